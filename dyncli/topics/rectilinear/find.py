"""The queries of every motion in ``rectilinear`` (§11), and ``distance`` in every answer.

The type's own queries ({t}, {v}, {s}) keep their routes (closed form, quadratures, the ODE's
events).  ``when``, ``max``, ``min`` — and a ``{v: V}`` or ``{s: S}`` equal to the initial state,
which counts only when the motion reaches it again (from rest, ``{v: 0}`` is the next turning
point, not the release) — are answered by :mod:`dyncli.motion_find` on the motion the route
gives at any time (one batched run per search: :func:`solver.sample`), with the exact rates
(v of s, a of v) so that turning points are roots of v (Brent).  Where s and v are monotone is
decided exactly, never by a grid: the closed form's and the quadratures' own pieces
(:func:`turning_points`), and in the general case the ODE's steps both ways from t1, each cut at
the extremes of s and v inside its interpolant (:class:`.general.Dense`).  ``distance`` (∫|v| dt
since t1) is Σ|Δs| between the turning points.
"""

from __future__ import annotations

import math

from dyncli import motion_find as mf
from dyncli import rootfind
from dyncli.errors import InputError, NumericalError
from dyncli.expr import constant, resolve_params

#: the most turning points of a periodic case 4 listed for one search (then the motion repeats)
MAX_PIECES = 20_000
GENERIC = ("when", "max", "min")


def split(p) -> tuple[list[int], list[tuple[int, dict]]]:
    """(the indices of the queries the type's routes answer, (index, raw query) of the others)."""
    legacy, generic = [], []
    for i, q in enumerate(p.find):
        held = (q.kind == "v" and q.v == p.v1) or (q.kind == "s" and q.s == p.s1)
        if q.kind in GENERIC:
            generic.append((i, q.raw()))
        elif held:
            generic.append((i, {"when": {q.kind: q.target}}))
        else:
            legacy.append(i)
    return legacy, generic


class _Motion:
    """s, v, a at any time of one problem, by its own route (batched)."""

    def __init__(self, p, sample):
        self.p, self.sample = p, sample

    def batch(self, times: list[float]) -> list[dict]:
        memo = self.__dict__.setdefault("_memo", {})
        new = [float(t) for t in times if float(t) not in memo]
        if new:
            if len(memo) > 100_000:
                memo.clear()
            memo.update(zip(new, (self._entry(e) for e in self.sample(self.p, new))))
        return [memo[float(t)] for t in times]

    def state(self, t: float) -> dict:
        return self.batch([t])[0]

    @staticmethod
    def _entry(e: dict) -> dict:
        if not e or not e.get("reached"):
            raise NumericalError("the motion is not defined there")
        return {"s": e["s"], "v": e["v"], "a": e["a"]}

    def reachable_end(self, t_end: float) -> float:
        """t_end, or the last time before it the motion reaches (it ends early: a blow-up)."""
        try:
            self.state(t_end)
            return t_end
        except NumericalError:
            pass
        lo, hi = self.p.t1, t_end
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            try:
                self.state(mid)
                lo = mid
            except NumericalError:
                hi = mid
        return lo


def turning_points(p, res, lo: float, hi: float, motion, solve_one) -> tuple[list[float], list[float]]:
    """(the times in (lo, hi) where v changes sign, the other times the results are smooth and
    monotonic between) of the quadrature and closed-form routes: case 1 from (6.5a); case 3 —
    v is monotonic — the one zero of v by its route; case 4 from its route (the first turning
    point, then every half period: a swing between two turning points takes half the period,
    (6.12)); case 2: v is monotonic between the zeros of a(t) (an explicit function of t, found
    decided exactly by the signs of a at its critical points), so each piece holds at most one turning point.
    (The general case has its own: the extremes of its steps' interpolants, :class:`.general.Dense`.)"""
    t1, case = p.t1, res.results.get("case")
    if case == 1:
        a = p.a.value()
        t = t1 - p.v1 / a if a != 0 else math.inf
        return ([t] if lo < t < hi else []), []
    if case == 3:
        e = solve_one(p, {"v": 0.0}) if p.v1 != 0 else None
        return ([e["t"]] if e and e.get("reached") and lo < e["t"] < hi else []), []
    if case == 4:
        return _swings(p, res, lo, hi, solve_one), []
    knots = _zeros_of_a(p, lo, hi)          # case 2 (on any route: a(t) is known exactly)
    pts = [lo] + knots + [hi]
    V = [st["v"] for st in motion.batch(pts)]
    v = lambda t: motion.state(t)["v"]         # noqa: E731
    turns = [rootfind.root(v, a, b) for a, b, va, vb in zip(pts, pts[1:], V, V[1:]) if va * vb < 0]
    return sorted(turns + [a for a, va in zip(pts[1:-1], V[1:-1]) if va == 0]), knots


def _swings(p, res, lo, hi, solve_one) -> list[float]:
    T, t1 = res.results.get("period"), p.t1
    if p.v1 == 0:
        first = t1
    else:
        e = solve_one(p, {"v": 0.0})
        first = e["t"] if e and e.get("reached") else None
    if first is None or first >= hi:
        return []
    if not T:
        return [first] if lo < first < hi else []
    n = min(math.floor((hi - first) / (0.5 * T)), MAX_PIECES)
    k0 = max(0, math.ceil((lo - first) / (0.5 * T))) if lo > first else 0
    out = Swings(x for x in (first + 0.5 * T * k for k in range(k0, n + 1)) if lo < x < hi)
    out.first, out.half = first, 0.5 * T
    return out


class Swings(list):
    """The turning points of a periodic case 4 (as many as a search needs), with the first of
    them and the half period: the k-th lies at first + k·half, for the distance at any time."""

    first: float = 0.0
    half: float = 0.0


def _zeros_of_a(p, lo: float, hi: float) -> list[float]:
    """The sign changes of a(t) in (lo, hi), decided exactly (:class:`.case2_signs.SignTable`: the
    signs of a at its critical points, never by sampling)."""
    import numpy as np

    from dyncli.topics.rectilinear.case2_signs import SignTable, derivatives, irs

    dA, d2A = derivatives(p.a)
    roots, _, _ = SignTable(lambda x: p.a.evaluate(t=np.asarray(x, dtype=float)), dA, d2A, irs(p.a)).get(lo, hi)
    return [float(r) for r in roots]


def _breaks(t1: float, t_end: float, turns: list[float], knots: list[float]) -> list[float]:
    """The turning points and the knots (each piece monotonic in s and v), each piece cut in
    half."""
    pts = sorted({t1, t_end} | {x for x in turns + knots if t1 < x < t_end})
    return sorted(set(pts) | {0.5 * (a + b) for a, b in zip(pts, pts[1:])})


def _sampler(p, res, sample):
    """The motion at any times for the searches: case 2 one sweep of the span (not one quadrature
    from t1 per time), cases 3 and 4 the motion solved once (not one solve per try, issue 29)."""
    case, quad = res.results.get("case"), str(res.method).startswith("quadrature")
    if case == 2 and quad:
        from dyncli.topics.rectilinear.case2 import States

        return States(p, p.accuracy.rtol, p.accuracy.atol)
    if case in (3, 4) and quad:
        from dyncli.topics.rectilinear.solved import Solved

        return Solved(case, res.extra.get("solved"))
    return sample


def answer(p, res, generic, items, sample, solve_one) -> None:
    """Fill ``items`` (the answers in the user's order) for the generic queries, then add
    ``distance`` to every reached answer."""
    params = resolve_params(p.params)
    const = lambda text: constant(text, params)      # noqa: E731
    sample = _sampler(p, res, sample)
    t1 = p.t1
    asked = [q.t for q in p.find if q.kind == "t"]
    t_end = max(asked) if asked and max(asked) > t1 else t1 + p.t_max     # the largest requested time, else t_max
    raw = [x for _, x in generic]
    reached = [e["t"] for e in items if e and e.get("reached")]
    t_end = mf.search_end(t_end, raw, const) if generic else max(reached + [t1])
    dense = None
    lo = min(reached + [t1])
    if res.results.get("case") == "general" and (t_end > t1 or lo < t1):    # one run each way, every step's interpolant
        from dyncli.topics.rectilinear.general import Dense

        sample = dense = Dense(p, str(res.method).split(":")[-1], p.accuracy.rtol, p.accuracy.atol, t_end, lo,
                               res.extra.pop("marches", ()))
    motion = _Motion(p, sample)
    if generic:
        t_end = dense.end if dense is not None else motion.reachable_end(t_end)
    hi = max(reached + [t1, t_end])
    if dense is not None:       # the general case: s and v monotone between the steps' extremes
        cuts = [b for b in dense.extremes if dense.start <= b <= max(dense.end, t1)]
        motion.batch(cuts)      # the states at every cut in one pass over the steps (the turns' signs)
        turns = mf.turns(lambda t: motion.state(t)["v"], cuts, 1)
        knots = [b for b in cuts if t1 < b < t_end]
    else:
        try:
            turns, knots = turning_points(p, res, lo, hi, motion, solve_one) if hi > lo else ([], [])
        except NumericalError as exc:               # no search needs them: only the distance is lost
            if generic:
                raise
            res.warn(f"distance not computed: the turning points between t = {lo:.10g} and {hi:.10g} s: {exc}")
            _distances(p, res, items, None, motion)
            return
    if generic:
        odo = _Odometer(p, turns, motion)

        def batch(ts: list[float]) -> list[dict]:
            return [dict(st, distance=odo.at(t, st["s"])) for t, st in zip(ts, motion.batch(ts))]

        sm: mf.StateMotion
        sm = mf.StateMotion(lambda t: batch([t])[0], t1, t_end, _breaks(t1, t_end, turns, knots),
                            rtol=p.accuracy.rtol if res.method != "closed-form" else 0.0,
                            rates={"s": "v", "v": "a", "distance": lambda t, _: abs(sm.value("v", t))}, batch=batch,
                            subdivide=1 if dense is not None else None)
        try:
            found = mf.answer_find(raw, sm, const, None, full=motion.state)
        except InputError as e:                     # find.k of the generic queries: the user's index
            head, k, rest = (e.path or "").split(".", 2) + [""] * (2 - (e.path or "").count("."))
            raise InputError(e.message, ".".join(x for x in (head, str(generic[int(k)][0]), rest) if x)) \
                if head == "find" and k.isdigit() else e
        for (i, _), a in zip(generic, found):
            if not a["reached"]:
                res.warn(f"find[{i}]: not reached between t1 = {t1:g} and t = {t_end:.10g} s"
                         + (" (t1 + t_max)" if t_end >= t1 + p.t_max else ""))
                a.update({"s": None, "v": None, "a": None})
            items[i] = a
    _distances(p, res, items, turns, motion)


def _distances(p, res, items, turns, motion) -> None:
    """``distance`` in every answer; null with a warning where a state between t1 and t is one
    the route cannot give."""
    for e in items:
        if e is not None:
            try:
                e["distance"] = _distance(p, e, turns, motion) if e.get("reached") else None
            except NumericalError as exc:
                e["distance"] = None
                res.warn(f"distance at t = {e['t']:.10g} s not computed: {exc}")


class _Odometer:
    """∫|v| dt from t1 to a later time: the distances at the turning points accumulated as far
    as asked (s at the turns fetched in growing batches), then |s(t) − s(last turn)| (the
    motion is monotonic between turns)."""

    def __init__(self, p, turns: list[float], motion):
        self.turns, self.motion = [x for x in sorted(turns) if x > p.t1], motion
        self.knots, self.s, self.cum = [p.t1], [p.s1], [0.0]

    def at(self, t: float, s: float) -> float:
        import bisect

        while len(self.knots) <= len(self.turns) and self.knots[-1] < t:     # the turns before t, in batches
            new = self.turns[len(self.knots) - 1:2 * len(self.knots) + 16]
            for x, st in zip(new, self.motion.batch(new)):
                self.knots.append(x)
                self.cum.append(self.cum[-1] + abs(st["s"] - self.s[-1]))
                self.s.append(st["s"])
        j = max(bisect.bisect_left(self.knots, t) - 1, 0)
        return self.cum[j] + abs(s - self.s[j]) + 0.0


def _distance(p, e: dict, turns: list[float] | None, motion) -> float | None:
    """∫|v| dt between t1 and the answer's time: Σ|Δs| between the turning points (a periodic
    swing: from its first two turning points, whatever the number of swings)."""
    if turns is None:
        return None
    if isinstance(turns, Swings) and turns.half > 0 and e["t"] > turns.first >= p.t1:
        f, h = turns.first, turns.half
        k = math.floor((e["t"] - f) / h)                  # turning points after the first, up to t
        s1, s2 = motion.state(f)["s"], motion.state(f + h)["s"]
        last = s1 if k % 2 == 0 else s2
        return abs(s1 - p.s1) + k * abs(s2 - s1) + abs(e["s"] - last) + 0.0
    a, b = sorted((p.t1, e["t"]))
    knots = [a] + [x for x in turns if a < x < b] + [b]
    s = {t: motion.state(t)["s"] for t in knots[1:-1]}
    s[a], s[b] = (p.s1, e["s"]) if a == p.t1 else (e["s"], p.s1)
    return sum(abs(s[y] - s[x]) for x, y in zip(knots, knots[1:])) + 0.0
