"""Tables of solutions for notebooks (docs/api.md): ``Solution.to_frame()``
and ``dyncli.sweep(...).to_frame()`` give a pandas DataFrame,
``dyncli.sweep(...).to_xarray()`` an xarray Dataset of the results over
time x sweep.

pandas and xarray are optional extras (``pip install 'dyncli[frames]'``),
imported only here and only when a frame is asked for.

Columns are the results flattened to dotted names as in ``--format csv``:
a vector ``vA2`` is ``vA2.0``, ``vA2.1``, ``vA2.2``; a mapping ``work``
of forces is ``work.gravity``, ``work.motor``; a ``find`` entry
``find.0.t``.  ``df.attrs["units"]`` maps every column to its SI unit
("" for dimensionless numbers, strings and flags): the unit of the result
the column belongs to (the declarations, ``Solution.units``), the field's
unit for a swept path.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import lru_cache
from typing import Any

EXTRA = "frames"


def need(module: str, what: str):
    """Import an optional extra's ``module`` or raise ImportError naming the extra."""
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise ImportError(f"{what} needs {module}, which dyncli installs only with the optional extra "
                          f"'{EXTRA}': pip install 'dyncli[{EXTRA}]' (or pip install {module})") from exc


def flat(value: Any, prefix: str, out: dict) -> dict:
    """``out[dotted name] = value`` for every leaf of ``value`` (numbers,
    strings, booleans and None kept as they are; arrays as lists)."""
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        value = value.tolist()
    if isinstance(value, Mapping):
        for k, v in value.items():
            flat(v, f"{prefix}.{k}" if prefix else str(k), out)
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            flat(v, f"{prefix}.{i}" if prefix else str(i), out)
    else:
        out[prefix] = value
    return out


#: results that hold the type's own results (``find.0.x``, ``events.0.state.x``), or hold them
#: under names of the problem's own, skipped (``point.BODY.POINT.a``)
_HOLDERS = {"find": 0, "events": 0, "point": 2}


def column_unit(units: Mapping[str, str], column: str) -> str:
    """The SI unit of a flattened column (or an answer path: the one policy of grading and frames),
    read from its start: a result with a unit holds it all the way down (``reaction.rope.T.0`` is
    a tension, N — not the kinetic energy ``T``; ``x.V.2.1`` a position), a result that holds
    the type's results is looked into (``find.0.t`` -> the unit of ``t``,
    ``events.0.state.reaction.axle.R``, ``point.bar.end2.a``); any other record without a unit of
    its own has none to give ("": ``orbit.a`` is a semi-major axis, not the acceleration ``a``)."""
    parts = [p for p in column.split(".") if not p.isdigit()]
    i = 0
    while i < len(parts):
        name = parts[i]
        if units.get(name):
            return units[name]
        if name in _HOLDERS:
            i += 1 + _HOLDERS[name]
        elif name == "state" and i > 0:      # (an event's state: the results at its instant)
            i += 1
        else:
            return ""
    return ""


def _over_index(result) -> list[tuple[str, list, list[str]]]:
    """(index name, index values, result names) of the series, those over the
    same index merged."""
    groups: dict = {}
    for s in result.series:
        index = s.index.tolist() if hasattr(s.index, "tolist") else list(s.index)
        key = (s.index_name, repr(index))
        groups.setdefault(key, (s.index_name, index, []))[2].extend(
            n for n in s.names if n in result.results)
    return list(groups.values())


def element_at(value: Any, i: int) -> Any:
    """Element ``i`` of a list over the index (or of each list of a mapping of them)."""
    if hasattr(value, "tolist"):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return value[i] if i < len(value) else None
    if isinstance(value, Mapping):
        return {k: element_at(v, i) for k, v in value.items()}
    return value


def rows(sol, long: bool) -> list[dict]:
    """The rows of one solution: the swept values then the flattened
    results; with ``long``, one row per index value (time) of its series."""
    head = flat(sol.swept, "", {})
    results = sol.results                       # with "t" when the results are over time
    groups = _over_index(sol._result) if long else []
    if not groups:
        return [flat(results, "", head)]
    in_series = {n for _, _, names in groups for n in names} | {index_name for index_name, _, _ in groups}
    in_series |= {s.index_result for s in sol._result.series if s.index_result}
    rest = flat({k: v for k, v in results.items() if k not in in_series}, "", {})
    out = []
    for index_name, index, names in groups:
        for i, iv in enumerate(index):
            row = flat(iv, index_name, dict(head))
            for n in names:
                flat(element_at(results[n], i), n, row)
            row.update(rest)
            out.append(row)
    return out


@lru_cache(maxsize=64)
def _schema(type_name: str) -> dict:
    from dyncli.registry import model_class

    return model_class(type_name).model_json_schema()


@lru_cache(maxsize=512)
def field_unit(type_name: str | None, path: str) -> str:
    """The SI unit of an input field at a dotted ``path`` ("" when it has
    none: a ``params`` name, a dimensionless field)."""
    try:
        schema = _schema(type_name)
    except Exception:  # noqa: BLE001 - an unknown type: no unit to give
        return ""
    defs, nodes = schema.get("$defs", {}), [schema]
    for part in path.split("."):
        nodes = [n for node in nodes for n in _step(_alternatives(node, defs), part)]
    units = {_unit(n) for node in nodes for n in _alternatives(node, defs)} - {""}
    return units.pop() if len(units) == 1 else ""       # one unit whichever variant (a force's kind) it is


def _step(nodes: list[dict], part: str) -> list[dict]:
    out = []
    for node in nodes:
        if part.isdigit() and _unit(node):
            out.append({"x-unit": _unit(node)})      # a component of a vector field
        elif part.isdigit() and isinstance(node.get("items"), dict):
            out.append(node["items"])
        elif part.isdigit() and int(part) < len(node.get("prefixItems", ())):
            out.append(node["prefixItems"][int(part)])
        elif part in node.get("properties", {}):
            out.append(node["properties"][part])
    return out


def _alternatives(node: dict, defs: dict, depth: int = 0) -> list[dict]:
    """``node`` with its ``$ref`` resolved, or each variant of an ``anyOf``/``oneOf``."""
    if depth > 8:
        return []
    if "$ref" in node:
        return _alternatives(defs.get(node["$ref"].split("/")[-1], {}), defs, depth + 1)
    if _unit(node) or "properties" in node:
        return [node]
    variants = node.get("anyOf") or node.get("oneOf")
    if variants:
        return [a for v in variants for a in _alternatives(v, defs, depth + 1)]
    return [node]


def _unit(node: dict) -> str:
    from dyncli.units import si_unit

    return node.get("x-unit") or si_unit(node.get("x-dimension"))


def frame(sols: list, long: bool):
    """A DataFrame of ``sols`` (one row per solution, or per solution and
    time with ``long``), with ``attrs["units"]``."""
    pd = need("pandas", "to_frame()")
    several = len({(s.file, s.index) for s in sols}) > 1
    table, units = [], {}
    for s in sols:
        for row in rows(s, long):
            table.append({"problem": s.index, **row} if several else row)
        units.update({k: field_unit(s.type, k) for k in s.swept})
        units.update({**s._result.units, **s.units})    # with the parts of records (find.0.t)
    columns: dict[str, None] = {}
    for row in table:
        columns.update(dict.fromkeys(row))
    df = pd.DataFrame(table, columns=list(columns))
    df.attrs["units"] = {c: ("" if c == "problem" else
                             units[c] if c in units else column_unit(units, c)) for c in columns}
    return df
