"""``dyncli.sweep(...).to_xarray()`` (docs/api.md): a sweep's results as an
xarray Dataset on the grid of the swept values, the results over time with
one more dimension ``t``.

One dimension per swept path (its values in sweep order as the coordinate),
plus ``t`` for results reported over the times of ``at``; one variable per
flattened result (the names of ``to_frame()``: ``x``, ``vA2.0``,
``work.gravity``), each with ``attrs["units"]``.  xarray is an optional
extra (``pip install 'dyncli[frames]'``), imported only here.
"""

from __future__ import annotations

import math
from typing import Any

from dyncli.errors import InputError
from dyncli.frames import column_unit, element_at, field_unit, flat, need


def _one_problem(sols: list, problem: int | None) -> list:
    indices = sorted({s.index for s in sols})
    if problem is None and len(indices) > 1:
        raise InputError(f"to_xarray: the sweep holds problems {indices}: pick one with "
                         f"to_xarray(problem={indices[0]})")
    if problem is not None and problem not in indices:
        raise InputError(f"to_xarray: no problem {problem} in the sweep; its problems are {indices}")
    return [s for s in sols if problem is None or s.index == problem]


def _time_names(sol) -> list[str]:
    """The results that are lists over ``t`` (the series over time)."""
    return [n for s in sol._result.series if s.index_name == "t" for n in s.names if n in sol.results]


def dataset(sols: list, problem: int | None = None):
    """The Dataset of one problem's sweep points (the solutions of ``dyncli.sweep``)."""
    xr = need("xarray", "to_xarray()")
    np = need("numpy", "to_xarray()")
    sols = _one_problem(sols, problem)
    if not sols:
        raise InputError("to_xarray: the sweep has no points")
    paths = list(sols[0].swept)
    coords = {p: list(dict.fromkeys(s.swept[p] for s in sols)) for p in paths}
    shape = tuple(len(coords[p]) for p in paths)
    if math.prod(shape) != len(sols):
        raise InputError(f"to_xarray: the {len(sols)} points are not a grid of {' x '.join(map(str, shape))} values")
    over_t = _time_names(sols[0])
    times: Any = sols[0].results.get("t") if over_t else None      # read only when over_t
    if over_t and any(list(s.results.get("t", [])) != list(times) for s in sols):
        raise InputError("to_xarray: the points report different times (a swept 'at'); use to_frame(long=True)")
    cols: dict[str, list] = {}
    for k, s in enumerate(sols):
        rest = {n: v for n, v in s.results.items() if n not in over_t and not (over_t and n == "t")}
        for c, v in flat(rest, "", {}).items():
            cols.setdefault(c, [None] * len(sols))[k] = v
    data = {c: (paths, _array(np, v).reshape(shape)) for c, v in cols.items()
            if c not in coords}                 # a result that is a swept input: its coordinate
    for c, v in _series_columns(sols, over_t, len(times or ())).items():
        data[c] = (paths + ["t"], _array(np, [x for row in v for x in row]).reshape(shape + (len(times),)))
    units = {**sols[0]._result.units, **sols[0].units}
    ds = xr.Dataset({c: xr.Variable(d, a, attrs={"units": units[c] if c in units else column_unit(units, c)})
                     for c, (d, a) in data.items()},
                    coords={**{p: (p, coords[p], {"units": field_unit(sols[0].type, p)}) for p in paths},
                            **({"t": ("t", list(times), {"units": "s"})} if over_t else {})})
    ds.attrs["title"], ds.attrs["type"] = sols[0].title, sols[0].type
    return ds


def _series_columns(sols: list, names: list[str], nt: int) -> dict[str, list]:
    """Flattened column -> per point, the list of its values over the times."""
    cols: dict[str, list] = {}
    for k, s in enumerate(sols):
        for i in range(nt):
            for c, v in flat({n: element_at(s.results[n], i) for n in names}, "", {}).items():
                cols.setdefault(c, [[None] * nt for _ in sols])[k][i] = v
    return cols


def _array(np, values: list):
    """Numbers as floats (None as NaN); anything else an object array."""
    if all(v is None or (isinstance(v, (int, float)) and not isinstance(v, bool)) for v in values):
        return np.array([math.nan if v is None else float(v) for v in values])
    return np.array(values, dtype=object)
