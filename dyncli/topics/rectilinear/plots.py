"""Plots of ``rectilinear`` problems (``dyncli solve --plot``): s(t) and
v(t), with the answered queries marked.

The curves come from the topic's own solver: the problem is solved again with
a grid of ``{t: T}`` queries (one solve, whatever the case: closed form,
quadrature or ODE), so nothing here re-derives the motion.  The time span
runs from t1 to a little past the last answered query (10 s when there is
none, never beyond t1 + t_max).
"""

from __future__ import annotations

from dyncli.errors import DyncliError
from dyncli.result import Line, Plot

POINTS = 301
DEFAULT_SPAN = 10.0


def _span(p, answered) -> tuple[float, float]:
    lo = p.t1
    times = [q["t"] for q in answered]
    hi = max(times) if times else lo
    lo = min([lo] + times)
    if hi <= lo:
        hi = lo + min(DEFAULT_SPAN, p.t_max)
    else:
        hi = hi + 0.1 * (hi - lo)
    return lo, hi


def _grid(p, lo, hi):
    """[(t, s, v)] from the solver at POINTS times in [lo, hi] (the points it
    cannot reach, e.g. after a blow-up, are left out)."""
    from dyncli.topics.rectilinear.model import Query
    from dyncli.topics.rectilinear.solver import solve

    ts = [lo + (hi - lo) * i / (POINTS - 1) for i in range(POINTS)]
    try:
        found = solve(p.model_copy(update={"find": [Query(t=t) for t in ts]})).results["find"]
    except DyncliError:
        # e.g. the motion blows up before hi: keep the part the solver reaches
        found = []
        for t in ts:
            try:
                q = solve(p.model_copy(update={"find": [Query(t=t)]})).results["find"][0]
            except DyncliError:
                break
            found.append(q)
    return [(q["t"], q["s"], q["v"]) for q in found if q.get("reached") and q["s"] is not None]


def plots(problem, result) -> list[Plot]:
    queries = result.results.get("find") or []
    answered = [q for q in queries if q.get("reached") and q.get("t") is not None]
    lo, hi = _span(problem, answered)
    pts = _grid(problem, lo, hi)
    t = [x[0] for x in pts]
    case = result.results.get("case")
    where = f"case {case}" if isinstance(case, int) else str(case)
    out = []
    for key, sym, unit, name in (("s", "s", "m", "position"), ("v", "v", "m/s", "velocity")):
        col = 1 if key == "s" else 2
        lines = [Line(t, [x[col] for x in pts], f"{sym}(t)", style="-" if key == "s" else "--")]
        qs = [(q["t"], q[key]) for q in answered if q.get(key) is not None]
        if qs:
            lines.append(Line([a for a, _ in qs], [b for _, b in qs], "answered queries (find)", style="", marker="o"))
        vl = [(problem.t1, "t₁ (initial state)")] if lo < problem.t1 else []
        out.append(Plot(f"{name} {sym}(t), rectilinear motion ({where}, §6)", "t [s]",
                        f"{sym}, {name} [{unit}]", lines, vlines=vl))
    return out
