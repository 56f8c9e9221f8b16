"""Rectilinear motion (notes §6) — numeric core (pure functions, no input-model imports).

The case follows from the variables the acceleration ``a`` uses:

* case 1, ``a`` constant: closed form (6.5a,b) — no numpy, no scipy;
* case 2, ``a(t)``: quadrature (6.6a,b), ``s`` as one integral with the
  kernel (t - tau); v/s queries by root finding on the quadrature
  (module :mod:`.case2`);
* case 3, ``a(v)``: t(v) (6.8) and s(v) (6.10) by quadrature after the
  substitution that removes the logarithmic singularity at a terminal
  velocity; t-queries invert t(v) (module :mod:`.case3`);
* case 4, ``a(s)``: energy (6.14, 6.15) and t(s) (6.12) by quadrature with
  u^2 substitutions at the turning points; periodic motion through the time
  along the swing (module :mod:`.case4`);
* ``general`` (more than one variable): ODE (6.2c,e) with scipy's solve_ivp,
  turning-point and extremum events (module :mod:`.general`).

Every query is answered at the first time t >= t1 (``t`` queries may lie before
t1); ``reached: false`` with a warning when the state is never attained.
"""

from __future__ import annotations

import math
from dataclasses import replace

from dyncli.errors import InputError
from dyncli.result import Result, SolveOptions
from dyncli.topics.rectilinear.answers import Answers
from dyncli.topics.rectilinear.constants import EPS, fmt
from dyncli.topics.rectilinear.setup import QUERY_FIELDS, Accuracy, Query, Setup, Spring

EQUATIONS = {
    1: ["6.5a", "6.5b"],
    2: ["6.6a", "6.6b"],
    3: ["6.8", "6.10", "6.12", "6.6b"],
    4: ["6.14", "6.15", "6.12"],
    "general": ["6.2c", "6.2e"],
}


def case_of(a) -> int | str:
    used = set(a.variables)
    if not used:
        return 1
    if len(used) > 1:
        return "general"
    return {"t": 2, "v": 3, "s": 4}[used.pop()]


def _route(p, case) -> str:
    """The route: 'closed-form', 'quadrature' or an ODE method name."""
    m = p.accuracy.method
    if m == "auto":
        return "closed-form" if case == 1 else ("DOP853" if case == "general" else "quadrature")
    if m == "closed-form":
        if case != 1:
            raise InputError(
                f"closed-form applies only to case 1 (constant a); this a is case {case}: use auto, quadrature or an ODE method",
                "accuracy.method")
        return m
    if m == "quadrature":
        if case == "general":
            raise InputError("no quadrature route when a uses more than one of t, s, v (general case): use auto or an ODE method",
                             "accuracy.method")
        return m
    from dyncli.runner import scipy_method      # an ODE route (the runner's one method map)

    return scipy_method(m)


def _check_initial(p) -> None:
    try:
        a1 = p.a.value() if not p.a.variables else float(p.a(t=p.t1, s=p.s1, v=p.v1))
    except (TypeError, ValueError):  # pragma: no cover - defensive
        a1 = math.nan
    if not math.isfinite(a1):
        raise InputError(
            f"a = {p.a.text} is not finite at the initial state (t1 = {fmt(p.t1)}, s1 = {fmt(p.s1)}, v1 = {fmt(p.v1)}): "
            f"it evaluates to {a1!r}; start where a is defined (change t1, s1 or v1) or correct a", "a")


def _distinct(p, keep: list[int]):
    """(p with each distinct query of ``keep`` (indices into p.find) once, the index of each
    kept query among them): 20,000 copies of one query are solved once; warnings name each
    query by its place in the user's list."""
    where: dict[tuple, int] = {}
    index = [where.setdefault((p.find[i].kind, p.find[i].target), len(where)) for i in keep]
    firsts = [keep[index.index(k)] for k in range(len(where))]
    counts = [0] * len(where)
    for k in index:
        counts[k] += 1
    q = replace(p, find=tuple(p.find[i] for i in firsts),
                labels=tuple(f"find[{i}]" + (f" and {c - 1} identical quer{'y' if c == 2 else 'ies'}" if c > 1 else "")
                             for i, c in zip(firsts, counts)))
    return q, index


def plain(p) -> Setup:
    """The validated problem as plain numbers (setup.py): everything below this module reads only it."""
    a = p.accuracy
    return Setup(a=p.a, t1=p.t1, s1=p.s1, v1=p.v1, find=tuple(Query(**{n: getattr(q, n) for n in QUERY_FIELDS}) for q in p.find),
                 t_max=p.t_max, m=p.m, springs=tuple(Spring(sp.k, sp.anchor, sp.L, sp.one_sided) for sp in p.springs),
                 params=p.params, accuracy=Accuracy(a.rtol, a.atol, a.method, a.estimate, a.max_steps, a.max_cpu))


def solve(p, options: SolveOptions | None = None) -> Result:
    """The type's own queries by its route; the queries of every motion (§11) and ``distance``
    by :mod:`.find` on that route's motion."""
    return solve_setup(plain(p))


def solve_setup(p: Setup) -> Result:
    """:func:`solve` of a problem given in plain numbers (setup.py)."""
    from dyncli.topics.rectilinear import find

    if p.springs:                     # the springs' acceleration joins a (springs.py); the input stays as given
        from dyncli.topics.rectilinear.springs import with_springs

        if p.m is None:               # (a Setup built by hand: the input model asks for m already)
            raise InputError("springs need the body's mass m (their acceleration is the force over m): give m", "m")
        p = replace(p, a=with_springs(p.a, p.springs, float(p.m)))
    legacy, generic = find.split(p)
    q, index = _distinct(p, legacy)
    res = _solve(q)
    got = res.results["find"]
    items: list = [None] * len(p.find)
    for i, k in zip(legacy, index):
        items[i] = dict(got[k])
    if p.find:
        find.answer(p, res, generic, items, sample, _solve_one)
    res.extra.pop("marches", None)    # the route's recorded steps (general.Record) are not kept with the result
    res.results["find"] = items
    return res


def _solve(p) -> Result:
    case = case_of(p.a)
    route = _route(p, case)
    _check_initial(p)
    res = Result({"case": case, "find": []})
    if route == "closed-form":
        res.method = "closed-form"
        res.equations = list(EQUATIONS[1])
        ans = Answers(p, res)
        a = p.a.value()
        for i, q in enumerate(p.find):
            _case1(p, a, i, q, ans)
        res.results["find"] = ans.items
        res.extra["sample"] = lambda times: sample(p, times)
        return res

    from dyncli.topics.rectilinear import coulomb

    if route != "quadrature" and coulomb.by_hand(p.a):
        raise coulomb.refuse(p.a, case)

    def run(rtol, atol):
        return _run(p, case, route, rtol, atol)

    import numpy as np

    from dyncli import ode

    rtol, atol = p.accuracy.rtol, p.accuracy.atol
    with np.errstate(all="ignore"):
        res, ans = run(rtol, atol)
    res.results["find"] = ans.items
    bound = ans.relative_error()
    if route == "quadrature":
        # the quadratures' propagated error bounds, each relative to its answer's scale
        res.error_estimate = bound
    if p.accuracy.estimate:
        # the runner's check solve (ode.check_solve: rtol/CHECK_DIV and its one fallback, also
        # when the quadratures' work meter refuses the tighter run: work.OverWork is an OverBudget)
        with np.errstate(all="ignore"):
            check = ode.check_solve(res, run, rtol, atol)
        if check is not None:
            res.error_estimate = max(_difference(p, ans.items, check[0][1].items), bound)
    elif route != "quadrature":
        ode.nominal_estimate(res, rtol, steps=res.extra.get("nsteps", 1))
    res.extra["sample"] = lambda times: sample(p, times)
    return res


def _run(p, case, route: str, rtol: float, atol: float):
    """One run of the quadrature or ODE route: (Result, Answers)."""
    res_ = Result({"case": case, "find": []})
    ans_ = Answers(p, res_)
    if route == "quadrature":
        if case in (1, 2):
            from dyncli.topics.rectilinear import case2 as mod
        elif case == 3:
            from dyncli.topics.rectilinear import case3 as mod  # type: ignore[no-redef]  # one of three modules with solve()
        else:
            from dyncli.topics.rectilinear import case4 as mod  # type: ignore[no-redef]  # (as above)
        res_.method = mod.solve(p, ans_, rtol, atol)
        if res_.extra.get("solved") is not None and res_.extra["solved"].rtol != p.accuracy.rtol:
            res_.extra.pop("solved")    # (a check run at another rtol: not the motion reported)
        res_.equations = list(EQUATIONS[2 if case == 1 else case])
    else:
        from dyncli.topics.rectilinear import general

        res_.method = general.solve(p, ans_, route, rtol, atol)
        res_.equations = list(EQUATIONS["general"])
    return res_, ans_


def _solve_one(p, raw: dict) -> dict | None:
    """The answer of one of the type's own queries (``{"v": 0.0}``) by the problem's route."""
    return _solve(replace(p, find=(Query(**raw),), labels=None)).results["find"][0]


def sample(p, times) -> list[dict]:
    """The motion at ``times`` (the ``find`` entries of ``{t: T}`` queries),
    for plots: one run of the problem's own route at its tolerances, with no
    second run for an error estimate.  Raises like :func:`solve` when a time
    cannot be reached (e.g. the motion blows up before it)."""
    import numpy as np

    q = replace(p, find=tuple(Query(t=float(t)) for t in times), labels=None)
    case = case_of(q.a)
    route = _route(q, case)
    if route == "closed-form":
        return _solve(q).results["find"]
    with np.errstate(all="ignore"):
        _, ans = _run(q, case, route, q.accuracy.rtol, q.accuracy.atol)
    return ans.items


def _difference(p, a: list, b: list) -> float:
    """ode.relative_difference over the answers reached in both runs: t (as the time elapsed
    since t1), s, v and a, each relative to its own scale (s, v, a: at least atol)."""
    both = [(x, y) for x, y in zip(a, b) if x is not None and y is not None and x["reached"] and y["reached"]]
    if not both:
        return 0.0
    from dyncli import ode

    shift = {"t": p.t1, "s": 0.0, "v": 0.0, "a": 0.0}
    pairs = [([x[k] - shift[k] for x, _ in both], [y[k] - shift[k] for _, y in both]) for k in shift]
    floor = p.accuracy.atol
    return ode.relative_difference(pairs, [0.0, floor, floor, floor])


# ---------------------------------------------------------------------------
# case 1: constant acceleration (6.5a,b)


def _case1(p, a: float, i: int, q, ans: Answers) -> None:
    t1, s1, v1 = p.t1, p.s1, p.v1
    if q.kind == "t":
        tau = q.t - t1
    elif q.kind == "v":
        dv = q.v - v1
        if dv == 0:
            tau = 0.0
        elif a == 0:
            ans.unreached(i, f"a = 0: the velocity stays v1 = {fmt(v1)}")
            return
        else:
            tau = dv / a
            if tau < 0:
                ans.unreached(i, f"the velocity moves away from it (v1 = {fmt(v1)}, a = {fmt(a)})")
                return
    else:
        tau = _case1_position(s1, v1, a, q.s, i, ans)
        if tau is None:
            return
    if q.kind != "t" and ans.beyond_t_max(i, t1 + tau):
        return
    ans.reached(i, t1 + tau, s1 + v1 * tau + 0.5 * a * tau * tau, v1 + a * tau, a=a)


def _case1_position(s1: float, v1: float, a: float, S: float, i: int, ans: Answers):
    """Smallest tau >= 0 with s1 + v1 tau + a tau^2 / 2 = S, or None."""
    d = S - s1
    if d == 0:
        return 0.0
    if a == 0:
        if v1 == 0:
            ans.unreached(i, f"the body stays at rest at s1 = {fmt(s1)}")
            return None
        tau = d / v1
        if tau < 0:
            ans.unreached(i, f"the body moves away from it (v1 = {fmt(v1)}, a = 0)")
            return None
        return tau
    disc = v1 * v1 + 2 * a * d
    if disc < 0 and disc >= -8 * EPS * (v1 * v1 + abs(2 * a * d)):
        disc = 0.0  # the target is the turning point, up to rounding
    if disc < 0:
        ans.unreached(i, f"it lies beyond the turning point s = {fmt(s1 - v1 * v1 / (2 * a))}")
        return None
    r = math.sqrt(disc)
    qq = -0.5 * (v1 + math.copysign(r, v1))  # a/2 tau^2 + v1 tau - d = 0, stable roots
    roots = [2.0 * qq / a]              # not qq / (0.5 a): a/2 underflows to 0 for a = 5e-324
    if qq != 0:
        roots.append(-d / qq)
    pos = [x for x in roots if x > 0 and math.isfinite(x)]
    if not pos:
        ans.unreached(i, f"the body moves away from it for t >= t1 (v1 = {fmt(v1)}, a = {fmt(a)})")
        return None
    return min(pos)
