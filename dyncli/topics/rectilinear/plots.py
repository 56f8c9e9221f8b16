"""Plots of ``rectilinear`` problems (``dyncli solve --plot``): s(t) and
v(t), with the answered queries marked.

The curves come from the topic's own solver: the problem is solved again with
a grid of ``{t: T}`` queries (one solve, whatever the case: closed form,
quadrature or ODE), so nothing here re-derives the motion.  The time span
runs from t1 (or an earlier {t: T} query) to a little past the last answered
query (10 s, or t_max if shorter, when there is none).  The number of
points adapts to the cost of the solver's route (a coarse pass measures it).
"""

from __future__ import annotations

from dyncli.errors import DyncliError
from dyncli.result import Line, Plot

POINTS = 301       # on a fine grid (more for a periodic motion, up to MAX_POINTS)
MAX_POINTS = 3000
PER_PERIOD = 40
COARSE = 31       # first pass, to measure the cost of a point
BUDGET = 3.0      # seconds for the fine pass
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


def _solve_at(p, ts):
    """[find entries] of the solver for {t: T} queries at ``ts``; when the
    whole grid fails (e.g. the motion blows up before the end), the longest
    prefix of the grid that solves (found by bisection)."""
    from dyncli.topics.rectilinear.model import Query
    from dyncli.topics.rectilinear.solver import solve

    def run(times):
        return solve(p.model_copy(update={"find": [Query(t=t) for t in times]})).results["find"]

    try:
        return run(ts)
    except DyncliError:
        pass
    good, lo, hi = [], 0, len(ts) - 1          # ts[:lo] known good, ts[:hi+1] known bad
    while lo < hi:
        mid = (lo + hi + 1) // 2
        try:
            good = run(ts[:mid])
            lo = mid
        except DyncliError:
            hi = mid - 1
    return good


def _grid(p, lo, hi, period, marks):
    """[(t, s, v)] from the solver on a grid of times in [lo, hi] (plus the
    answered query times ``marks``, so the markers sit on the curves).

    The wanted number of points is POINTS, or PER_PERIOD per period of a
    periodic motion (case 4), at most MAX_POINTS; it is cut to what the
    measured cost of a point allows in BUDGET seconds (two small passes
    measure the solver's fixed and per-point cost), so a slow route still
    plots quickly."""
    import time

    def times(n):
        grid = [lo + (hi - lo) * i / (n - 1) for i in range(n)]
        return sorted(set(grid + [t for t in marks if lo <= t <= hi]))

    wanted = POINTS
    if period:
        wanted = max(wanted, int(PER_PERIOD * (hi - lo) / period) + 1)
    wanted = min(wanted, MAX_POINTS)
    t0 = time.perf_counter()
    _solve_at(p, times(2))
    t1 = time.perf_counter()
    found = _solve_at(p, times(COARSE))
    t2 = time.perf_counter()
    per_point = max((t2 - t1) - (t1 - t0), 0.0) / (COARSE - 2) or (t2 - t1) / COARSE
    n = int(min(wanted, BUDGET / per_point)) if per_point > 0 else wanted
    if n > 2 * COARSE and len(found) >= COARSE:
        found = _solve_at(p, times(n))
    return [(q["t"], q["s"], q["v"]) for q in found if q.get("reached") and q.get("s") is not None]


def plots(problem, result) -> list[Plot]:
    queries = result.results.get("find") or []
    answered = [q for q in queries if q.get("reached") and q.get("t") is not None]
    lo, hi = _span(problem, answered)
    pts = _grid(problem, lo, hi, result.results.get("period"), [q["t"] for q in answered])
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
