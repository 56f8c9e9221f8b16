"""The terminal view's tables as plain data, for the Markdown, LaTeX and
HTML renderers (``--format markdown|latex``, a solution's notebook view).

:func:`build` lays out a solved problem the way :mod:`dyncli.render.table`
draws it: a heading, a line with the method and equations, the scalar
results (result, symbol, value, unit), one table per series (a row per
time, the index first), the lists of records and mappings, the views, and
the warnings.  The cells are the same strings (same digits, same units).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from dyncli.render.table import display_units, fmt_num, fmt_value, is_deferred, meta_parts, relative, series_columns
from dyncli.render.tableviews import convert_view
from dyncli.result import Equations, FrameTable, Result, Table


@dataclass
class Grid:
    title: str | None
    columns: list[str]
    rows: list[list[str]]
    align: list[str]                     # "l" / "r" per column
    units: list[str | None] = field(default_factory=list)   # a column's unit (series headers)
    unit_column: int | None = None       # index of a column of unit names (the scalar table)
    note: str | None = None
    tex: list[str] | None = None         # LaTeX of the last column per row (formulas: --symbolic)


@dataclass
class View:
    title: str
    kind: str          # "vibration (§17)"
    meta: list[str]    # "method: closed-form", "error estimate: 1e-10", "equations: (17.5b), ..."
    grids: list[Grid]
    warnings: list[str]


def build(lp, result: Result, digits: int = 6, units: list[str] | None = None) -> View:
    from dyncli import registry

    info = registry.TYPES.get(lp.type)
    kind = f"{lp.type} ({info.sections})" if info else str(lp.type)
    meta = meta_parts(result)
    values, unit_names = display_units(result, units)
    values = {k: (v.tolist() if hasattr(v, "tolist") else v) for k, v in values.items()}
    in_series = {n for s in result.series if not s.frame_only for n in s.names} | \
        {s.index_result for s in result.series if s.index_result}
    in_series |= set(result.covered)
    rows, deferred = [], []
    for name, val in values.items():
        if name in in_series:
            continue
        if is_deferred(val):
            deferred.append((name, val))
        else:
            cell, unit = relative(result, name, val, unit_names, digits) or (fmt_value(val, digits),
                                                                             unit_names.get(name, ""))
            rows.append([name, result.symbols.get(name, ""), cell, unit])
    grids = [Grid("; ".join(result.notes) or None, ["result", "symbol", "value", "unit"], rows, ["l", "l", "l", "l"], unit_column=3)] if rows else []
    grids += [_series(s, values, unit_names, result.symbols, digits) for s in result.series if not s.frame_only]
    grids += [_deferred(result.symbols.get(n, n), v, digits, unit_names) for n, v in deferred]
    grids += [_view(convert_view(v, units)[0], digits) for v in result.views]
    title = lp.title + swept_label(getattr(lp, "swept", None), digits)
    return View(title, kind, meta, grids, list(result.warnings))


def swept_label(swept: dict | None, digits: int = 6) -> str:
    """`` [k=100, zeta=0.1]`` for a sweep point's title ("" without a sweep)."""
    if not swept:
        return ""
    return " [" + ", ".join(f"{k}={fmt_value(v, digits)}" for k, v in swept.items()) + "]"


def _series(s, values: dict, unit_names: dict, symbols: dict, digits: int) -> Grid:
    cols, data = [s.index_name], []
    units: list[str | None] = [None]
    for label, unit, vals in series_columns(s, values, unit_names, symbols):
        cols.append(label)
        units.append(unit)
        data.append(vals)
    rows = []
    marks = s.index_marks or {}
    for i, iv in enumerate(s.index):
        rows.append([fmt_num(iv, digits) + (f" {marks[i]}" if i in marks else "")]
                    + [fmt_value(v[i], digits) if v is not None and i < len(v) else "" for v in data])
    return Grid(s.title, cols, rows, ["r"] * len(cols), units)


def _deferred(title: str, val, digits: int, unit_names: dict) -> Grid:
    if isinstance(val, list):
        keys: list[str] = []
        for rec in val:
            keys += [k for k in rec if k not in keys]
        rows = [[str(i)] + [fmt_value(rec.get(k), digits) for k in keys] for i, rec in enumerate(val)]
        units = [None] + [(unit_names.get(k) or None) if isinstance(k, str) else None for k in keys]
        return Grid(title, ["#"] + [str(k) for k in keys], rows, ["r"] * (len(keys) + 1), units)
    return Grid(title, ["name", "value"], [[str(k), fmt_value(v, digits)] for k, v in val.items()], ["l", "l"])


def _view(view, digits: int) -> Grid:
    if isinstance(view, FrameTable):
        rows = [[label] + [c if isinstance(c, str) else fmt_num(c, digits) for c in comps] for label, comps in view.rows]
        return Grid(view.title, ["", *view.basis], rows, ["l", "r", "r", "r"], note=view.note)
    if isinstance(view, Equations):
        return Grid(view.title, ["", "equation"], [[label, text] for label, text, _ in view.rows], ["l", "l"],
                    note=view.note, tex=[tex for _, _, tex in view.rows])
    if isinstance(view, Table):
        rows = [[fmt_value(c, digits) for c in row] for row in view.rows]
        return Grid(view.title, list(view.columns), rows, ["r"] * len(view.columns), note=view.note)
    raise TypeError(view)  # pragma: no cover
