"""Rectilinear motion (notes §6) — numeric core (no pydantic).

Case 1 (a constant): closed form (6.5).  Cases 2-4 and general: TODO.
"""

from __future__ import annotations

import math

from dyncli.errors import InputError
from dyncli.result import Result, SolveOptions

SYMBOLS = {"case": "case"}


def case_of(a) -> int | str:
    used = set(a.variables)
    if not used:
        return 1
    if len(used) > 1:
        return "general"
    return {"t": 2, "v": 3, "s": 4}[used.pop()]


def solve(p, options: SolveOptions | None = None) -> Result:
    case = case_of(p.a)
    if case != 1:
        raise InputError("only case 1 is implemented so far", "a")
    a = p.a.value()
    res = Result({"case": 1, "find": []}, method="closed-form", equations=["6.5a", "6.5b"], symbols=SYMBOLS)
    for q in p.find:
        res.results["find"].append(_case1(p, a, q, res))
    return res


def _case1(p, a, q, res):
    t1, s1, v1 = p.t1, p.s1, p.v1
    if q.kind == "t":
        t = q.t
    elif q.kind == "v":
        if a == 0:
            t = t1 if q.v == v1 else None
        else:
            t = t1 + (q.v - v1) / a
            if t < t1:
                t = None
    else:
        # s1 + v1 tau + a/2 tau^2 = S  -> smallest tau >= 0
        d = q.s - s1
        if a == 0:
            t = t1 + d / v1 if v1 != 0 and d / v1 >= 0 else (t1 if d == 0 else None)
        else:
            disc = v1 * v1 + 2 * a * d
            if disc < 0:
                t = None
            else:
                r = math.sqrt(disc)
                q_ = -0.5 * (v1 + math.copysign(r, v1)) if v1 != 0 else -0.5 * r
                roots = [x for x in ((q_ / (0.5 * a)) if a else math.inf, (d / q_) if q_ else math.inf) if x >= 0 and math.isfinite(x)]
                t = t1 + min(roots) if roots else None
    if t is None or (q.kind != "t" and t - t1 > p.t_max):
        res.warn(f"query {q.kind} = {q.target:g} is never reached")
        return {"t": None, "s": None, "v": None, "a": None, "reached": False}
    tau = t - t1
    return {"t": t, "s": s1 + v1 * tau + 0.5 * a * tau * tau, "v": v1 + a * tau, "a": a, "reached": True}
