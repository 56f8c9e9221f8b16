"""``--units`` on a topic's views (:class:`~dyncli.result.Table`,
:class:`~dyncli.result.FrameTable`): a column (or a frame table's row) whose
label names its unit in brackets (``x̄ [m]``, ``ω [rad/s]``) is converted and
relabelled (``x̄ [mm]``); a view holding numbers whose unit it does not name
cannot be converted, and the terminal view says so in a note."""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

from dyncli.result import FrameTable, Table


def scale(x: Any, f: float) -> Any:
    """Every number in ``x`` (nested lists and mappings) times ``f``; other values unchanged."""
    if x is None or isinstance(x, (bool, str)):
        return x
    if isinstance(x, dict):
        return {k: scale(v, f) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [scale(v, f) for v in x]
    try:
        return float(x) * f
    except (TypeError, ValueError):
        return x

_UNIT = re.compile(r"^(?P<label>.*?)\s*\[(?P<unit>[^\[\]]+)\]$")


def _numeric(x: Any) -> bool:
    if isinstance(x, bool) or x is None or isinstance(x, str):
        return False
    if isinstance(x, (list, tuple)):
        return any(_numeric(v) for v in x)
    if isinstance(x, dict):
        return any(_numeric(v) for v in x.values())
    if isinstance(x, int):
        return False                  # a count or an index (#, mode, equilibrium): no unit
    return isinstance(x, float) or hasattr(x, "__float__")


def _relabel(label: Any, wanted: list[str]) -> tuple[Any, float | None, bool]:
    """(new label, factor or None, whether the label names a unit)."""
    from dyncli.units import display_factor

    m = _UNIT.match(label) if isinstance(label, str) else None
    if m is None:
        return label, None, False
    fac = display_factor(m.group("unit"), wanted)
    if fac is None:
        return label, None, True
    return f"{m.group('label')} [{fac[1]}]", fac[0], True


def convert_view(view, wanted: list[str] | None):
    """(the view in the ``--units`` wanted, True unless it holds numbers of
    unnamed units)."""

    if not wanted:
        return view, True
    title, f, named = _relabel(view.title, wanted)
    if named:                       # a title naming the unit of every number: "Ī [kg·m²]"
        if f is None:
            return view, True
        if isinstance(view, Table):
            return replace(view, title=title, rows=[[scale(c, f) if _numeric(c) else c for c in r]
                                                    for r in view.rows]), True
        return replace(view, title=title, rows=[(lb, [scale(c, f) if _numeric(c) else c for c in comps])
                                                for lb, comps in view.rows]), True
    ok = True
    if isinstance(view, Table):
        columns, rows = list(view.columns), [list(r) for r in view.rows]
        for j, head in enumerate(view.columns):
            new, f, named = _relabel(head, wanted)
            numbers = any(j < len(r) and _numeric(r[j]) for r in rows)
            ok = ok and (named or not numbers)
            if f is not None:
                columns[j] = new
                for r in rows:
                    if j < len(r):
                        r[j] = scale(r[j], f)
        return replace(view, columns=columns, rows=rows), ok
    if isinstance(view, FrameTable):
        frows = []
        for label, comps in view.rows:
            new, f, named = _relabel(label, wanted)
            ok = ok and (named or not _numeric(comps))
            frows.append((new, [scale(c, f) if not isinstance(c, str) else c for c in comps]) if f is not None
                         else (label, comps))
        return replace(view, rows=frows), ok
    return view, True
