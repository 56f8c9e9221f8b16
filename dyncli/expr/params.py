"""The ``params`` mapping of a problem file: names checked, entries parsed and
evaluated in dependency order (cycles are an error)."""

from __future__ import annotations

import math
from typing import Any, Mapping

from dyncli.errors import InputError
from dyncli.expr.language import MAX_PARAMS, RESERVED, kind_of
from dyncli.expr.node import Expr
from dyncli.expr.parser import parse


def resolve_params(raw: Mapping[str, Any]) -> dict[str, float]:
    """Evaluate a ``params`` mapping; entries may refer to each other in any
    order (cycles are an error).  Raises InputError with path ``params.NAME``.
    The values of a mapping already resolved are remembered (:mod:`dyncli.docmemo`:
    the points of a sweep share their params)."""
    from dyncli.docmemo import recall

    if not raw:
        return {} if isinstance(raw, Mapping) else _resolve(raw)
    return dict(recall("params", raw, lambda: _resolve(raw)))


def _resolve(raw: Mapping[str, Any]) -> dict[str, float]:
    import keyword

    if not isinstance(raw, Mapping):
        raise InputError(f"params must be a mapping name: value, got {kind_of(raw)}", "params")
    names = list(raw)
    if len(names) > MAX_PARAMS:
        raise InputError(f"too many params ({len(names)}, at most {MAX_PARAMS})", "params")
    for n in names:
        if not isinstance(n, str) or not n.isidentifier() or not n.isascii() or keyword.iskeyword(n):
            raise InputError(f"parameter name {n!r} is not a valid name: use letters, digits and _, "
                             "starting with a letter (e.g. k_1)", f"params.{n}")
        if n in RESERVED:
            raise InputError(f"parameter name '{n}' is reserved (a constant or function): rename it (e.g. '{n}_1')",
                             f"params.{n}")
    parsed: dict[str, Expr] = {}
    for n in names:
        try:
            parsed[n] = parse(raw[n], variables=[m for m in names if m != n])
        except InputError as exc:
            from dyncli import units

            if isinstance(raw[n], str) and units.looks_like_quantity(raw[n]):
                try:  # a parameter with a unit: converted to SI base units
                    parsed[n] = Expr(raw[n], ("num", units.parse_quantity(raw[n])))
                    continue
                except units.UnitError as uexc:
                    raise InputError(str(uexc), f"params.{n}") from None
            raise InputError(exc.message, f"params.{n}") from None
    values: dict[str, float] = {}
    visiting: list[str] = []

    def value_of(n: str) -> float:
        if n in values:
            return values[n]
        if n in visiting:
            cyc = " -> ".join(visiting[visiting.index(n):] + [n])
            raise InputError(f"params refer to each other in a cycle: {cyc}; give one of them a value", f"params.{n}")
        visiting.append(n)
        e = parsed[n]
        deps = {d: value_of(d) for d in e.variables}
        visiting.pop()
        try:
            v = parse(e.text, (), deps).value() if deps else e.value()
        except InputError as exc:
            raise InputError(exc.message, f"params.{n}") from None
        if math.isnan(v):
            raise InputError("parameter is not a number", f"params.{n}")
        values[n] = v
        return v

    for n in names:
        try:
            value_of(n)
        except RecursionError:
            raise InputError("params refer to each other too deeply (a chain of hundreds of names)", f"params.{n}") from None
    return values
