"""The terminal view (``--format table``).  Generic: scalars, vectors, tensors, lists over an
index (``Result.series``), mappings (one row per name), lists of records, and the views
(:class:`~dyncli.result.FrameTable`, :class:`~dyncli.result.Table`).

The tables are dyncli's own (:mod:`dyncli.render.plain`): laid out directly off a terminal
(rich is not imported), drawn by rich in one; ``NO_COLOR`` is honoured.  ``--units`` converts
every result with a unit, the fields of records and the views' columns that name their unit;
a view it cannot convert is named in a note.
"""

from __future__ import annotations

import math
import os
from typing import Any

from dyncli.numfmt import DEFAULT_DIGITS, fmt_num  # noqa: F401  (re-exported: one number format)
from dyncli.printable import printable
from dyncli.render.tableviews import convert_view, scale
from dyncli.result import Equations, FrameTable, Result, Table


def is_vector(x: Any) -> bool:
    return isinstance(x, (list, tuple)) and len(x) == 3 and all(_is_scalar_num(c) for c in x)


def is_tensor(x: Any) -> bool:
    return isinstance(x, (list, tuple)) and len(x) == 3 and all(is_vector(r) for r in x)


def _is_scalar_num(x: Any) -> bool:
    if isinstance(x, bool) or x is None:
        return x is None
    try:
        float(x)
        return not isinstance(x, (str, list, tuple, dict))
    except (TypeError, ValueError):
        return False


def fmt_value(x: Any, digits: int = DEFAULT_DIGITS) -> str:
    if hasattr(x, "tolist"):
        x = x.tolist()
    if is_tensor(x):
        return "\n".join("[" + ", ".join(fmt_num(c, digits) for c in row) + "]" for row in x)
    if is_vector(x):
        return "[" + ", ".join(fmt_num(c, digits) for c in x) + "]"
    if isinstance(x, dict):
        return ", ".join(f"{printable(k)}: {fmt_value(v, digits)}" for k, v in x.items())
    if isinstance(x, (list, tuple)):
        if not x:                       # (an empty list of records: a scene phase with no first integral)
            return "none"
        if len(x) > 12:
            return "[" + ", ".join(fmt_value(v, digits) for v in x[:5]) + f", … ({len(x)} values)]"
        return "[" + ", ".join(fmt_value(v, digits) for v in x) + "]"
    return fmt_num(x, digits)


def escape(text: str) -> str:
    """A label in a table (a name, a title, a user's key): one line
    (:func:`printable`).  dyncli's tables hold plain text (no markup)."""
    return printable(text)


def cell(text: str) -> str:
    """A value cell made by :func:`fmt_value` (printable already; a tensor
    keeps its row breaks)."""
    return text


def make_console(file=None, width: int | None = None):
    """Where a view prints (:class:`dyncli.render.plain.Out`): stdout by
    default (a terminal: rich, at its width; else plain text at
    :func:`dyncli.stdio.table_width`), or ``file`` at ``width`` (100 unless given)."""
    import sys

    from dyncli import stdio
    from dyncli.render.out import Out

    no_color = bool(os.environ.get("NO_COLOR"))
    if file is None:
        return Out(sys.stdout, stdio.table_width(), stdio.stdout_is_terminal(), getattr(sys.stdout, "encoding", None) or "utf-8",
                   no_color)
    return Out(file, width or stdio.DEFAULT_WIDTH, False, getattr(file, "encoding", None) or "utf-8", no_color)


def display_units(result: Result, wanted: list[str] | None) -> tuple[dict, dict]:
    """Apply ``--units`` preferences: returns (values, units) for display.
    A result with a unit is converted whole; the fields of a list of records
    or of a mapping (``find``'s ``t``, ``s``, ``v``) by their own units."""
    values = dict(result.results)
    units = dict(result.units)
    if not wanted:
        return values, units
    from dyncli.units import display_factor

    factors = {}
    for name, si in result.units.items():
        fac = display_factor(si, wanted)
        if fac is not None:
            factors[name] = fac[0]
            units[name] = fac[1]
    for name, val in values.items():
        if name in factors:
            values[name] = scale(val, factors[name])
        elif is_deferred(val):
            values[name] = _scale_fields(val, factors)
    return values, units


def _scale_fields(x: Any, factors: dict) -> Any:
    if isinstance(x, dict):
        return {k: scale(v, factors[k]) if k in factors else _scale_fields(v, factors) for k, v in x.items()}
    if isinstance(x, list):
        return [_scale_fields(v, factors) for v in x]
    return x


def render(console, lp, result: Result, digits: int = DEFAULT_DIGITS, units: list[str] | None = None) -> None:
    """The terminal view of one solved problem: a header (title, type, method, error estimate,
    equations), the table of scalar results, one table per series and per nested result, the
    frame views (δ/δt tables) and the warnings."""
    from dyncli.render.out import as_out
    from dyncli.render.plain import Text
    
    out = as_out(console)
    _print_header(out, lp, result)
    values, unit_names = display_units(result, units)
    in_series = {n for s in result.series if not s.frame_only for n in s.names} | \
        {s.index_result for s in result.series if s.index_result}
    in_series |= set(result.covered)
    deferred: list[tuple[str, Any]] = []
    scalars, n_rows = _results_table("; ".join(printable(n) for n in result.notes) or None), 0
    for name, val in values.items():
        if name in in_series:
            continue
        if hasattr(val, "tolist"):
            val = val.tolist()
        if is_deferred(val):
            deferred.append((name, val))
            continue
        cell, unit = relative(result, name, val, unit_names, digits) or (fmt_value(val, digits), unit_names.get(name, ""))
        scalars.add_row(escape(name), escape(result.symbols.get(name, "")), cell, escape(unit))
        n_rows += 1
    if n_rows:
        out.print(scalars)
    for s in result.series:
        if s.frame_only:
            continue
        for t in series_tables(s, values, unit_names, result.symbols, digits, out.width):
            out.print(t)
    for name, val in deferred:
        out.print(_nested_table(result.symbols.get(name, name), val, digits, unit_names))
    unconverted = []
    for view in result.views:
        view, converted = convert_view(view, units)
        out.print(render_view(view, digits))
        if not converted:
            unconverted.append(view.title)
    if unconverted:
        out.print(Text(f"--units: not applied to {'; '.join(printable(u) for u in unconverted)} "
                       "(units not named in the table: SI)", style="yellow"))
    for w in result.warnings:
        out.print(Text("warning: " + printable(w), style="yellow"))
    out.print("")


def relative(result: Result, name: str, val, unit_names: dict, digits: int) -> tuple[str, str] | None:
    """A result the tables show relative to its scale (``Result.scales``): the
    value and unit cells (``8.7e-11``, ``relative to 2.5e10 J``), or None."""
    scale = result.scales.get(name)
    raw = result.results.get(name)
    if not scale or not _is_scalar_num(raw) or raw is None or not math.isfinite(scale) or scale <= 0:
        return None
    unit = unit_names.get(name, "")
    shown = scale
    if unit and unit != result.units.get(name, ""):
        from dyncli.units import display_factor

        fac = display_factor(result.units.get(name, ""), [unit])
        shown = scale * fac[0] if fac else scale
    return fmt_num(float(raw) / scale, min(digits, 3)), f"relative to {fmt_num(shown, 3)} {unit}".rstrip()


def _print_header(out, lp, result: Result) -> None:
    from dyncli import registry
    from dyncli.render.plain import Text

    info = registry.TYPES.get(lp.type)
    section = f" ({info.sections})" if info else ""
    head = Text()
    head.append(printable(lp.title), style="bold")
    head.append(f"  ·  {lp.type}{section}", style="dim")
    out.print(head)
    out.print(Text("   ".join(meta_parts(result)), style="dim"))


def _results_table(title: str | None = None):
    from dyncli.render.plain import SIMPLE, Table

    t = Table(title=title, box=SIMPLE, header_style="bold", pad_edge=False)
    t.add_column("result", no_wrap=True)
    t.add_column("symbol", style="cyan", no_wrap=True)
    t.add_column("value", justify="left")
    t.add_column("unit", style="dim", no_wrap=True)
    return t


def is_deferred(val) -> bool:
    """Results drawn as their own table: a list of records, or a mapping (with more than one
    entry) of numbers, vectors and records, one row per name."""
    if isinstance(val, list) and val and all(isinstance(v, dict) for v in val):
        return True
    return (isinstance(val, dict) and len(val) > 1
            and all(isinstance(v, (list, tuple, dict)) or _is_scalar_num(v) for v in val.values())
            and any(isinstance(v, (list, tuple, dict)) for v in val.values()))


def meta_parts(result: Result) -> list[str]:
    """The header line's parts: method, error estimate (marked nominal when no second solve
    measured it), equations."""
    parts = [f"method: {result.method}"]
    if result.error_estimate is not None:
        nominal = " (nominal)" if str(result.extra.get("error_estimate_note", "")).startswith("nominal") else ""
        parts.append(f"error estimate: {fmt_num(result.error_estimate, 3)}{nominal}")
    if result.equations:
        parts.append("equations: " + ", ".join(f"({e})" for e in result.equations))
    return parts


def _nested_table(title: str, val, digits: int, unit_names: dict | None = None):
    """The table of a nested result: one row per record (a column per key,
    its unit in the header) or per entry."""
    from dyncli.render.plain import SIMPLE_HEAD, Table

    unit_names = unit_names or {}
    t = Table(title=escape(title), box=SIMPLE_HEAD, header_style="bold", pad_edge=False, split=True)
    if isinstance(val, list):
        keys: list[str] = []
        for rec in val:
            keys += [k for k in rec if k not in keys]
        t.add_column("#", justify="right", style="dim")
        for k in keys:
            unit = unit_names.get(k) if isinstance(k, str) else None
            t.add_column(escape(str(k) + (f" [{unit}]" if unit else "")), justify="right")
        for i, rec in enumerate(val):
            t.add_row(str(i), *[fmt_value(rec.get(k), digits) for k in keys])
    else:
        t.add_column("name")
        t.add_column("value")
        for k, v in val.items():
            t.add_row(escape(str(k)), fmt_value(v, digits))
    return t


#: a series longer than this shows its first and last SERIES_EDGE rows only
SERIES_MAX_ROWS = 60
SERIES_EDGE = 20


def shown_rows(n: int) -> tuple[list[int], int]:
    """Row indices a series table of ``n`` rows shows, and how many it omits:
    every row up to :data:`SERIES_MAX_ROWS`, else the first and last
    :data:`SERIES_EDGE` (laying out 1e5 rows would take minutes and help no
    reader; ``--format json`` holds every row)."""
    if n <= SERIES_MAX_ROWS:
        return list(range(n)), 0
    return list(range(SERIES_EDGE)) + list(range(n - SERIES_EDGE, n)), n - 2 * SERIES_EDGE


def omitted_note(omitted: int, total: int) -> str:
    return f"{omitted:,} rows not shown; --format json|csv holds all {total:,}"


def record_columns(vals) -> list[tuple[str, list]] | None:
    """A series column that holds records over the index, one column per key:
    a list of mappings (``force_terms``: force label -> value at each time)
    or a mapping of lists (``x_motion``: particle -> positions over time).
    None for a plain column."""
    if hasattr(vals, "tolist"):
        return None
    if isinstance(vals, list) and vals and all(isinstance(v, dict) for v in vals):
        keys = list(dict.fromkeys(k for v in vals for k in v))
        return [(str(k), [v.get(k) for v in vals]) for k in keys]
    if isinstance(vals, dict) and vals and all(isinstance(v, (list, tuple)) or hasattr(v, "tolist")
                                               for v in vals.values()):
        return [(str(k), v.tolist() if hasattr(v, "tolist") else list(v)) for k, v in vals.items()]
    return None


def series_columns(s, values: dict, unit_names: dict, symbols: dict) -> list[tuple[str, str | None, Any]]:
    """(label, unit, values over the index) of each column of a Series; a
    result holding records over the index gives a column per key, labelled
    by the key alone when it is the series' only result (the title names
    it), else ``symbol: key``."""
    out = []
    for name in s.names:
        sym = symbols.get(name, name)
        unit = unit_names.get(name) or None
        vals = values.get(name)
        parts = record_columns(vals)
        if parts is None:
            out.append((sym, unit, vals))
        else:
            out += [(_key_label(sym, k, len(s.names) == 1), unit, v) for k, v in parts]
    return out


def _key_label(sym: str, key: str, alone: bool) -> str:
    """``x_i(t)``, key ``2`` -> ``x_2(t)``; else the key (``gravity``) when the
    result is alone in its series, ``Fᵢ: gravity`` beside others."""
    if "_i" in sym:
        return sym.replace("_i", "_" + key, 1)
    return key if alone else f"{sym}: {key}"


def series_tables(s, values: dict, unit_names: dict, symbols: dict, digits: int, width: int | None) -> list:
    """One or more tables for a Series: columns are packed greedily so each
    table fits ``width`` (None: one table; the index column repeats in
    each); cells never wrap in the middle of a number.  A long series shows
    its head and tail (:func:`shown_rows`) with a ``⋮`` row between them,
    and a note after the last table."""
    from dyncli.render.plain import SIMPLE_HEAD, Table, Text, cell_len

    n = len(s.index)
    rows, omitted = shown_rows(n)
    gap = SERIES_EDGE if omitted else -1          # position of the ⋮ row
    marks = s.index_marks or {}
    idx_cells = [fmt_num(s.index[i], digits) + (f" {marks[i]}" if i in marks else "") for i in rows]
    idx_w = max([cell_len(escape(s.index_name))] + [len(c) for c in idx_cells])
    cols = []
    for label, unit, vals in series_columns(s, values, unit_names, symbols):
        head = escape(label + (f" [{unit}]" if unit else ""))
        cells = [fmt_value(vals[i], digits) if vals is not None and i < len(vals) else "" for i in rows]
        w = max([cell_len(head)] + [cell_len(ln) for c in cells for ln in c.split("\n")])
        cols.append((head, cells, w))
    groups: list[list] = []
    cur: list = []
    used = idx_w + 2
    for c in cols:
        if cur and width is not None and used + c[2] + 3 > width:
            groups.append(cur)
            cur, used = [], idx_w + 2
        cur.append(c)
        used += c[2] + 3
    if cur:
        groups.append(cur)
    tables: list = []
    for gi, group in enumerate(groups):
        title = s.title if gi == 0 else (f"{s.title} (continued)" if s.title else None)
        t = Table(title=escape(title) if title else None, box=SIMPLE_HEAD, header_style="bold", pad_edge=False)
        t.add_column(escape(s.index_name), justify="right", no_wrap=True)
        for head, _, _ in group:
            t.add_column(head, justify="right", no_wrap=True)
        for k, ic in enumerate(idx_cells):
            if k == gap:
                t.add_row("⋮", *["⋮" for _ in group])
            t.add_row(ic, *[cells[k] for _, cells, _ in group])
        tables.append(t)
    if omitted:
        tables.append(Text(omitted_note(omitted, n), style="dim"))
    return tables


def render_view(view, digits: int = DEFAULT_DIGITS):
    from dyncli.render.plain import SIMPLE_HEAD, SQUARE
    from dyncli.render.plain import Table as PTable

    def e(x):
        return escape(x) if isinstance(x, str) else x

    if isinstance(view, FrameTable):
        t = PTable(title=e(view.title), caption=e(view.note), box=SQUARE, header_style="bold", show_lines=True)
        t.add_column("", style="cyan")
        for b in view.basis:
            t.add_column(e(b), justify="right")
        for label, comps in view.rows:
            t.add_row(e(label), *[e(c) if isinstance(c, str) else fmt_num(c, digits) for c in comps])
        return t
    if isinstance(view, Equations):
        t = PTable(title=e(view.title), caption=e(view.note), box=SIMPLE_HEAD, header_style="bold")
        t.add_column("", style="cyan")
        t.add_column("equation", justify="left", overflow="fold")
        for label, text, _tex in view.rows:
            t.add_row(e(label), e(text))
        return t
    if isinstance(view, Table):
        t = PTable(title=e(view.title), caption=e(view.note), box=SIMPLE_HEAD, header_style="bold", split=True)
        for c in view.columns:
            t.add_column(e(c), justify="right")
        for row in view.rows:
            t.add_row(*[fmt_value(c, digits) for c in row])
        return t
    raise TypeError(view)  # pragma: no cover
