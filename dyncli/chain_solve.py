"""Chained problems, when they are solved (:mod:`dyncli.chain` reads and checks the links when
the file is loaded): each chained parameter's value taken from its source's outcome, the problem
validated again with it.  Raises :class:`dyncli.chain.Failure` with the source's exit code."""

from __future__ import annotations

import json
from dataclasses import replace

from dyncli.chain import Failure, Link, items_of


def resolve(lp, solve):
    """A copy of the pending ``lp`` with each chained parameter's value, validated (its ``error``
    set when invalid); ``solve(source_lp)`` gives a source's outcome.  Raises :class:`Failure`."""
    from dyncli.loader import validate

    params = dict(lp.raw.get("params") or {})
    for ln in lp.chain.values():
        src = lp.sources.get(ln.source) or _from_doc(lp, ln.source)
        outcome = cached(src) or solve(src)
        params[ln.name] = _value(lp, ln, src, outcome)
    new = replace(lp, raw={**lp.raw, "params": params}, model=None, error=None, chain={}, sources={},
                  outcome=None)
    validate(new)
    return new


def cached(lp):
    """The outcome stored on ``lp`` by run.solve_one (None when not solved, or changed since)."""
    memo = lp.outcome
    return memo[1] if memo is not None and memo[0] is lp.raw else None


def _from_doc(lp, index: int):
    """The source problem as the file gives it, with this problem's changed params (a variant's or an
    answer file's values) applied where the source has the same names."""
    from dyncli.loader import LoadedProblem, validate

    raw = items_of(lp)[index]
    mine, original = lp.raw.get("params") or {}, (items_of(lp)[lp.index] or {}).get("params") or {}
    theirs = raw.get("params") if isinstance(raw, dict) else None
    if isinstance(theirs, dict) and isinstance(mine, dict) and isinstance(original, dict):
        changed = {k: v for k, v in mine.items() if k in theirs and _dumps(v) != _dumps(original.get(k))}
        if changed:
            raw = {**raw, "params": {**theirs, **changed}}
    title = raw.get("title") if isinstance(raw, dict) else None
    src = LoadedProblem(lp.file, index, raw.get("type") if isinstance(raw, dict) else None,
                        title if isinstance(title, str) and title else f"{lp.file} #{index + 1}", raw, lp.doc,
                        ("problems", index), base_dir=lp.base_dir)
    validate(src)
    return src


def _dumps(v) -> str:
    return json.dumps(v, sort_keys=True, default=str)


def _value(lp, ln: Link, src, outcome) -> float:
    from dyncli.frames import column_unit, flat

    where = f"params.{ln.name}"
    name = f"problem {ln.source} ({src.title})"
    if outcome.result is None:
        code = outcome.exit_code if outcome.exit_code in (1, 2) else 3
        raise Failure(code, str(lp.diagnostic(where, f"{name} was not solved (see its message), so its "
                                                     f"{ln.path} cannot be taken")))
    results = outcome.result.results
    values = flat(results, "", {})
    if ln.path not in values:
        inside = [k for k in values if k.startswith(ln.path + ".")]
        if inside:
            msg = (f"{name}'s {ln.path} holds {len(inside)} values, not one number: take one, e.g. "
                   + ", ".join(inside[:3]))
        else:
            from dyncli.expr import did_you_mean

            msg = f"{name} has no result {ln.path}{did_you_mean(ln.path, list(values))}"
        raise Failure(2, str(lp.diagnostic(f"{where}.result", msg)))
    v = values[ln.path]
    if v is None:
        raise Failure(2, str(lp.diagnostic(f"{where}.result", f"{name}'s {ln.path} is null (not defined; its "
                                                               "warnings say why): there is no value to take")))
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise Failure(2, str(lp.diagnostic(f"{where}.result", f"{name}'s {ln.path} is {v!r}, not a number")))
    if ln.unit is not None:
        units = {"t": "s", **outcome.result.units}          # a find entry's t (§11) is a time
        _check_unit(lp, ln, column_unit(units, ln.path), name)
    return float(v)


def _check_unit(lp, ln: Link, have: str, name: str) -> None:
    from dyncli.units import clean_unit, registry

    where = f"params.{ln.name}.unit"
    assert ln.unit is not None                      # (called when the link gives one)
    ureg = registry()
    try:
        given = ureg.Quantity(1.0, clean_unit(ln.unit))
    except Exception:  # noqa: BLE001 - pint's errors vary by version
        raise Failure(2, str(lp.diagnostic(where, f"unknown unit {ln.unit!r}"))) from None
    shown = have or "dimensionless"
    try:
        factor = float(given.to(clean_unit(have) if have else "dimensionless").magnitude)
    except Exception:  # noqa: BLE001 - a DimensionalityError: not the same kind of quantity
        raise Failure(2, str(lp.diagnostic(where, f"{name}'s {ln.path} is in {shown}, not {ln.unit}: a different "
                                                  "kind of quantity (take another result)"))) from None
    if abs(factor - 1.0) > 1e-12:
        raise Failure(2, str(lp.diagnostic(where, f"{name}'s {ln.path} is in {shown} and params hold SI values: "
                                                  f"write unit: {shown} (not {ln.unit})")))
