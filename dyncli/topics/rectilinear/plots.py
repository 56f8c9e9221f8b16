"""Plots of ``rectilinear`` problems (``dyncli solve --plot``): s(t) and
v(t), with the answered queries marked.

The curves come from the solver's own sampler (``result.extra["sample"]``:
one run of the problem's route with a grid of ``{t: T}`` queries, no error
estimate), so nothing here re-derives or re-solves the motion.

The time span follows the motion, not the farthest query: from t1 (or an
earlier {t: T} query) over the answered queries that cluster near it, and for
a periodic motion (case 4) at least two periods.  A query far beyond that
(t = 50 s for a spring of period 1.26 s; t = 100 s for a ball at terminal
speed) would squash the motion into a sliver: it is named in the title
instead.  The number of points adapts to the cost of the route (a coarse
pass measures it).
"""

from __future__ import annotations

from dyncli.errors import DyncliError
from dyncli.result import Line, Plot

POINTS = 301       # on a fine grid (more for a periodic motion, up to MAX_POINTS)
MAX_POINTS = 3000
PER_PERIOD = 40
COARSE = 31       # first pass, to measure the cost of a point
BUDGET = 1.0      # seconds for the fine pass
DEFAULT_SPAN = 10.0
FAR = 4.0         # a query farther than FAR x the span of the nearer ones is "far"
PERIODS = 2.0


def span(t1: float, times: list[float], period: float | None, t_max: float) -> tuple[float, float, list[float]]:
    """(lo, hi, far): the plotted time span and the query times left out.

    Query times are taken in order of their distance from t1; one is kept
    while it lies within FAR times the distance of the nearer kept ones (or
    within PERIODS periods of a periodic motion)."""
    base = PERIODS * period if period else 0.0
    kept, far = [], list[float]()
    reach = base
    for t in sorted(times, key=lambda x: abs(x - t1)):
        d = abs(t - t1)
        if far or (d > FAR * reach and d > base and reach > 0):
            far.append(t)
            continue
        kept.append(t)
        reach = max(reach, d)
    lo = min([t1] + [t for t in kept if t < t1])
    hi = max([t1] + [t for t in kept if t > t1])
    if period:
        hi = max(hi, lo + base)
    if hi <= lo:
        hi = lo + min(DEFAULT_SPAN, t_max)
    else:
        hi = hi + 0.1 * (hi - lo)
    return lo, hi, sorted(far)


def _sample_at(sample, ts):
    """[find entries] of the sampler at ``ts``; when the whole grid fails
    (e.g. the motion blows up before the end), the longest prefix of the
    grid that solves (found by bisection)."""
    try:
        return sample(ts)
    except DyncliError:
        pass
    good, lo, hi = [], 0, len(ts) - 1          # ts[:lo] known good, ts[:hi+1] known bad
    while lo < hi:
        mid = (lo + hi + 1) // 2
        try:
            good = sample(ts[:mid])
            lo = mid
        except DyncliError:
            hi = mid - 1
    return good


def _grid(sample, lo, hi, period, marks):
    """[(t, s, v)] from the sampler on a grid of times in [lo, hi] (plus the
    answered query times ``marks``, so the markers sit on the curves).

    The wanted number of points is POINTS, or PER_PERIOD per period of a
    periodic motion (case 4), at most MAX_POINTS; it is cut to what the
    measured cost of a point allows in BUDGET seconds, so a slow route still
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
    found = _sample_at(sample, times(COARSE))
    per_point = (time.perf_counter() - t0) / COARSE
    n = int(min(wanted, BUDGET / per_point)) if per_point > 0 else wanted
    if n > 2 * COARSE and len(found) >= COARSE:
        found = _sample_at(sample, times(n))
    return [(q["t"], q["s"], q["v"]) for q in found if q.get("reached") and q.get("s") is not None]


def plots(problem, result) -> list[Plot]:
    sample = result.extra.get("sample")
    if sample is None:
        return []
    queries = result.results.get("find") or []
    answered = [q for q in queries if q.get("reached") and q.get("t") is not None]
    period = result.results.get("period")
    lo, hi, far = span(problem.t1, [q["t"] for q in answered], period, problem.t_max)
    pts = _grid(sample, lo, hi, period, [q["t"] for q in answered])
    t = [x[0] for x in pts]
    case = result.results.get("case")
    where = f"case {case}" if isinstance(case, int) else str(case)
    note = ""
    if far:
        shown = ", ".join(f"{x:.4g}" for x in far[:3]) + (", …" if len(far) > 3 else "")
        note = f"\nquery at t = {shown} s far beyond the motion shown: see the table"
    out = []
    for key, sym, unit, name in (("s", "s", "m", "position"), ("v", "v", "m/s", "velocity")):
        col = 1 if key == "s" else 2
        lines = [Line(t, [x[col] for x in pts], f"{sym}(t)", style="-" if key == "s" else "--")]
        qs = [(q["t"], q[key]) for q in answered if q.get(key) is not None and lo <= q["t"] <= hi]
        if qs:
            lines.append(Line([a for a, _ in qs], [b for _, b in qs], "answered queries (find)", style="", marker="o"))
        vl = [(problem.t1, "t₁ (initial state)")] if lo < problem.t1 else []
        out.append(Plot(f"{name} {sym}(t), rectilinear motion ({where}, §6){note}", "t [s]",
                        f"{sym}, {name} [{unit}]", lines, vlines=vl))
    return out
