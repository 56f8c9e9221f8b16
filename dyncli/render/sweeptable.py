"""``--format table`` on a sweep: one wide table of rows per problem, one
row per sweep point (like ``--format csv``): the swept paths, then every
result flattened to dotted names (``x.0``, ``find.0.t``) with its unit in the
header, in ``--digits`` and ``--units``.  The table is at its natural width
(a row is a point: it is never split), laid out by dyncli's own tables.  A
point that failed has no row (its message is on stderr, as for every
format); the points' warnings go to stderr as with ``--format csv``."""

from __future__ import annotations

from typing import Any

from dyncli.numfmt import fmt_num
from dyncli.printable import printable


def _flat(value: Any, prefix: str, out: dict, digits: int) -> None:
    if hasattr(value, "tolist"):
        value = value.tolist()
    if isinstance(value, dict):
        for k, v in value.items():
            _flat(v, f"{prefix}.{k}" if prefix else str(k), out, digits)
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            _flat(v, f"{prefix}.{i}" if prefix else str(i), out, digits)
    else:
        out[prefix] = fmt_num(value, digits)


def _unit(units: dict, path: str) -> str:
    """The unit of a dotted column (:func:`dyncli.frames.column_unit`: the one rule of frames and
    grading — ``orbit.a`` is no acceleration, ``reaction.rope.T`` no energy)."""
    from dyncli.frames import column_unit

    return column_unit(units, path)


class SweepTable:
    """Collects a sweep's points (``write``) and prints one table per problem (``close``)."""

    def __init__(self, console, digits: int, units: list[str] | None):
        self.console, self.digits, self.units = console, digits, units
        self.groups: dict[tuple, list] = {}

    def write(self, lp, result) -> None:
        from dyncli.render.table import display_units

        values, unit_names = display_units(result, self.units)
        row: dict[str, str] = {}
        _flat(dict(getattr(lp, "swept", None) or {}), "", row, self.digits)
        swept = list(row)
        _flat(values, "", row, self.digits)
        key = (lp.file, lp.index)
        if key not in self.groups:
            self.groups[key] = [lp, result, swept, unit_names, []]
        self.groups[key][4].append(row)

    def close(self) -> None:
        from dyncli.render.plain import SIMPLE_HEAD, Table, Text
        from dyncli.render.table import meta_parts

        for lp, result, swept, unit_names, rows in self.groups.values():
            columns = list(dict.fromkeys(k for r in rows for k in r))
            head = Text()
            head.append(printable(lp.title), style="bold")
            head.append(f"  ·  {lp.type}  ·  sweep of {len(rows):,} points", style="dim")
            self.console.print(head)
            self.console.print(Text("   ".join(meta_parts(result)), style="dim"))
            t = Table(box=SIMPLE_HEAD, header_style="bold", pad_edge=False)
            for c in columns:
                unit = "" if c in swept else _unit(unit_names, c)
                t.add_column(printable(c) + (f" [{unit}]" if unit else ""), justify="right",
                             style="cyan" if c in swept else "")
            for r in rows:
                t.add_row(*[r.get(c, "") for c in columns])
            width, self.console.width = self.console.width, None
            try:
                self.console.print(t)
            finally:
                self.console.width = width
