"""The ``find`` queries and ``distance`` of a particle on a curve (§11).

The motion is the route's own at any time: the energy quadrature's q(t) (the legs between
turning points, periodic when the motion is) or the ODE's dense output, each assembled into the
reported results as at an ``at`` time.  Breaks: the ODE's steps and phase ends, each step cut at
the exact extremes of every result searched (:func:`dyncli.motion_find.exact_breaks`: monotone
between two cuts); on the quadrature route its legs (turning points and midpoints) and an eighth
of the period, each leg cut at the exact extremes of every result searched in the leg's
quadrature variable (:func:`quadrature_cuts`: monotone between two cuts; beyond MAX_PIECES legs,
sampled, with a warning).  Rates: q̇ of q,
ṡ of s, v of x, a of v, so turning points are roots of the rate (Brent).  ``distance`` is the
arc length travelled, Σ|Δs| between the turning points of s (the roots of ṡ).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli import motion_find as mf
from dyncli.expr import constant, resolve_params
from dyncli.queries import SUBDIVIDE

PIECES, PER_PERIOD, MAX_PIECES = 64, 8, 20_000


def _entries(r: dict, n: int, keys) -> list[dict]:
    return [{k: r[k][j] for k in keys} for j in range(n)]


def quadrature_states(p, model):
    """states(ts) on the energy-quadrature route (the same legs and nodes as its answers)."""
    from . import quadrature

    E = quadrature.Energy(p, model)

    def legs(t_end: float, turning: bool = False) -> list[float]:
        """The ends of the route's legs up to t_end: the turning points and the legs' middles
        (``turning``: the turning points only, every one to t_end)."""
        quadrature.motion(E, [0.0])
        pl = E._plan
        if pl is None:
            return []
        first, cycle = pl[0], pl[1]
        out, t, cap = [], 0.0, (4 if turning else MAX_PIECES)   # turning: the first few (then periodic)
        for s in first:
            t += s.dur
            out.append((t, s.x1 == 0.0 and s.p.kind == "turn"))
        while cycle and t < t_end and len(out) < cap:
            for s in cycle:
                t += s.dur
                out.append((t, s.x1 == 0.0 and s.p.kind == "turn"))
        return [x for x, turn in out if 0.0 < x < t_end and (turn or not turning)]

    def states(ts):
        ts = [float(t) for t in ts]
        q, qd = quadrature.motion(E, ts)[:2]
        return quadrature.results_at(p, model, E, ts, q, qd)
    states.legs = legs
    states.energy = E
    return states


def quadrature_cuts(p, model, E, t_end: float, warn) -> "dict[str, list[float]] | None":
    """The exact extremes, as times in (0, t_end), of every result the ``find`` queries search on
    the energy-quadrature route — decided exactly, never by samples.  Each leg of the route runs one
    piece of the quadrature monotonically in its variable x (q = a + σx² from a turning point a,
    else q = a + σx): the reported results are smooth functions of x there (the turning point's
    square root taken out exactly: q̇ = ±√(2K/M) is smooth in x), so their extremes along the leg
    are the roots of their rate in x, found by :func:`dyncli.rootfind.smooth_extremes` on the leg's
    x interval (the Chebyshev interpolant resolved to rounding, the real roots of its derivative);
    each is taken to time by the piece's own quadrature τ(x).  The legs' cuts repeat with the period.
    ``{path: cuts}`` (the legs' starts among them), or None when no query searches, the
    motion is at rest, or a result is not resolved (a warning then says the search reads samples)."""
    from dyncli import rootfind

    from . import quadrature

    asked = mf.searched_paths(p.find)
    if not asked or not t_end > 0:
        return None
    quadrature.motion(E, [0.0])
    plan = E._plan
    if plan is None:
        return None
    first, cycle = plan[0], plan[1]
    # nondecreasing along a leg (q, s: the leg runs q one way; distance): no cut of their own
    rest = sorted(a for a in asked if a not in ("q", "s", "distance"))
    table: dict[str, list[float]] = {a: [] for a in asked}

    def leg_values(seg, paths):
        pc, d = seg.p, seg.dir

        def values(xs):
            xs = np.asarray(xs, dtype=float).reshape(-1)
            q, K = pc._K(xs)
            qd = np.sqrt(np.maximum(K, 0.0) / (0.5 * E.M(q))) * pc.sig * d
            # (at φ = 0: the results searched do not turn with the curve, solver.TURNING)
            got = quadrature.results_at(p, model, E, np.zeros(xs.size), q, qd, carried_s=True)
            return mf.series_values(lambda ts: got)(paths, xs)
        return values

    def cuts_of(seg) -> dict[str, list[float]] | None:
        """The cuts of one leg as times from the leg's start."""
        lo, hi = sorted((seg.x0, seg.x1))
        if not hi > lo or not rest:
            return {a: [] for a in rest}
        try:
            got, ok = rootfind.smooth_extremes(leg_values(seg, rest), [lo + (hi - lo) * k / 4 for k in range(5)])
        except KeyError:
            return None
        if not ok:
            return None
        grid = [lo + (hi - lo) * k / 4 for k in range(1, 4)]    # (the inner breaks given: cuts of every result)
        out = {}
        for a, xs in zip(rest, got):
            ts = [seg.dir * (seg.p.tau(x) - seg.t0) for x in sorted(set(xs) | set(grid))]
            out[a] = sorted(t for t in ts if 0.0 < t < seg.dur)
        return out

    legs: list = []
    t = 0.0
    for seg in first:
        legs.append((t, seg))
        t += seg.dur
    per = sum(sg.dur for sg in cycle) if cycle else 0.0
    n_cycles = math.ceil((t_end - t) / per) if cycle and per > 0 and t_end > t else 0
    if len(first) + n_cycles * len(cycle or []) > MAX_PIECES:
        warn(f"find: {', '.join(rest)} searched on samples: the motion runs {n_cycles} periods, more legs than "
             f"the exact cuts cover ({MAX_PIECES}); narrow the search with within")
        return None
    memo: dict[int, dict[str, list[float]] | None] = {}
    for k in range(n_cycles):
        for seg in cycle or []:
            legs.append((t, seg))
            t += seg.dur
    for start, seg in legs:
        if start >= t_end:
            break
        if id(seg) not in memo:
            memo[id(seg)] = cuts_of(seg)
        got = memo[id(seg)]
        if got is None:
            warn(f"find: {', '.join(rest)} could not be followed as a smooth function along a leg of the "
                 "quadrature: its crossings are searched on samples, where a level crossed and crossed back "
                 "between two is not seen")
            return None
        for a in table:                 # the leg's start (a turning point or a leg's middle) and its cuts
            table[a] += [start] + [start + c for c in got.get(a, ()) if start + c < t_end]
    return table


def ode_states(p, model, phases):
    from . import dynamics
    from .report import assemble

    def states(ts):
        ts = [float(t) for t in ts]
        Y, modes = dynamics.states_at(phases, ts)
        return assemble(p, model, ts, Y, modes)["results"]
    return states


def ode_turns(phases) -> list[float]:
    """The turning points of s on the ODE route: the roots of q̇ (ṡ = |τ| q̇ with |τ| > 0) inside
    every step of a sliding phase, decided exactly: q̇ is a component of the step's dense output,
    a polynomial, monotone between its critical points (:func:`dyncli.rootfind.polynomial_extremes`),
    so the signs at the step's ends and at those points bracket every root (Brent) — a q̇ that
    changes sign twice inside one step is two turns, not none; and the start of every later phase
    (a stop, a stick or a slip: a turn at most, never a missed one).  A step whose q̇ keeps one
    strict sign by its Bernstein coefficients (:func:`dyncli.dop853.one_sign`, all steps at once)
    has no root and is not looked into."""
    from dyncli import rootfind
    from dyncli.dop853 import one_sign

    eps = float(np.finfo(float).eps)
    out = []
    for i, ph in enumerate(phases):
        if i:
            out.append(float(ph.t0))
        if ph.mode[0] == "stick" or not ph.t1 > ph.t0:
            continue
        sol = ph.sol
        signed = one_sign(sol.interpolants, 1)
        pieces = [(f, float(a), min(float(b), float(ph.t1)))
                  for f, a, b, skip in zip(sol.interpolants, sol.ts[:-1], sol.ts[1:], signed)
                  if min(float(b), float(ph.t1)) > float(a) and not skip]
        rows = [(lambda t, f=f: np.asarray(f(t))[1:2], a, b) for f, a, b in pieces]     # q̇'s row only
        for (f, a, b), crit in zip(pieces, rootfind.polynomial_extremes(rows)):
            T = [a] + crit[0] + [b]
            R = [float(r) for r in np.asarray(f(np.array(T)), dtype=float)[1]]
            for k in range(len(T) - 1):
                if R[k] == 0.0 and (k > 0 or a > float(ph.t0)):
                    out.append(T[k])
                elif R[k] * R[k + 1] < 0:
                    qd = f.component(1) if hasattr(f, "component") else (lambda t, f=f: float(np.asarray(f(t))[1]))
                    out.append(rootfind.brent(qd, T[k], T[k + 1], 1e-300, 4 * eps, 2000))
    return sorted(set(out))


def ode_arc(model, phases, q0: float, known):
    """s at any times on the ODE route: the arc length carried in the state (its 6th row), read
    from the dense output (``known``: the (t, s) pairs already reported)."""
    from . import dynamics

    memo = {float(t): s for t, s in known}

    def s_of(ts) -> list[float]:
        new = sorted({float(t) for t in ts} - memo.keys())
        if new:
            memo.update(zip(new, (dynamics.states_at(phases, new)[0][5] + 0.0).tolist()))
        return [memo[float(t)] for t in ts]
    return s_of


def ode_breaks(phases) -> list[float]:
    """The steps' ends and the phases' ends (a stop, a stick, a slip: the state is smooth between two)."""
    out = set()
    for ph in phases:
        out |= {float(t) for t in ph.steps_t} | {float(ph.t0), float(ph.t1)}
    return sorted(out)


def uniform_breaks(t_end: float, period) -> list[float]:
    n = PIECES
    if period and math.isfinite(period) and period > 0:
        n = max(PER_PERIOD, math.ceil(t_end / period * PER_PERIOD))
    n = min(n, MAX_PIECES)
    return [t_end * k / n for k in range(n + 1)]


def report(p, res, states, breaks, keys, subdivide=None, turn_times=None, s_of=None, smooth=False,
           cuts=None) -> None:
    """``distance`` at the times of ``at`` and the ``find`` answers (``subdivide``: 1 when the
    breaks are the ODE's steps; ``turn_times``: the turning points when the route knows them;
    ``s_of``: s at a list of times, cheaper than the whole state; ``smooth``: the results are
    smooth functions of time between two breaks — an ODE's steps and phase ends —, so that each
    step is cut at the exact extremes of every result searched, :func:`dyncli.motion_find.exact_breaks`,
    and the search takes it as monotone between two cuts; ``cuts``: ``{path: times}``, the exact
    extremes of each result searched the route decides itself, :func:`quadrature_cuts`, so that the
    search takes each result as monotone between two of the breaks and its cuts)."""
    t_end = float(p.t_end)
    B = sorted({0.0, t_end} | {b for b in breaks if 0.0 < b < t_end})

    memo: dict[float, dict] = {}

    def batch(ts) -> list[dict]:
        new = [float(t) for t in ts if float(t) not in memo]
        if new:
            if len(memo) > 50_000:
                memo.clear()
            memo.update(zip(new, _entries(states(new), len(new), keys)))
        return [memo[float(t)] for t in ts]

    turns = turn_times if turn_times is not None else ([] if t_end <= 0 else _turns(batch, B, subdivide))
    period = res.results.get("period")
    s_at = (lambda t: s_of([t])[0]) if s_of is not None else (lambda t: batch([t])[0]["s"])
    distance = _odometer(s_at, turns,
                         0.5 * period if turn_times is not None and isinstance(period, float) and period > 0 else None)

    if s_of is not None:            # every s the distances need, in one call
        s_of([0.0] + [float(t) for t in turns if t > 0] + [float(t) for t in p.at])
    res.results["distance"] = [distance(float(t)) for t in p.at]
    if not p.find:
        return
    params = resolve_params(p.params)
    const = lambda text: constant(text, params)      # noqa: E731

    def full(t: float) -> dict:
        return dict(batch([t])[0], distance=distance(t))

    # distance is Σ|Δs| between the turning points of s: nondecreasing, no cut of its own
    own = (mf.exact_breaks(p.find, B, mf.series_values(states), lambda path: [] if path == "distance" else None,
                           warn=res.warn)
           if smooth and t_end > 0 else None)
    quad = subdivide is None            # the energy route (its motion repeats exactly)
    if cuts is not None:                # the route's own exact extremes (the quadrature's legs)
        table = {path: sorted(set(B).union(c for c in cut if 0.0 < c < t_end)) for path, cut in cuts.items()}
        own, subdivide = (lambda path: table.get(path, B)), 1
    motion: mf.StateMotion
    motion = mf.StateMotion(full, 0.0, t_end, B, rtol=float(p.accuracy.rtol), subdivide=subdivide,
                            rates={"q": "q_dot", "s": "s_dot", "x": "v", "v": "a",
                                   "distance": lambda t, _: abs(motion.flat(t)["s_dot"])},
                            batch=lambda ts: [dict(e, distance=distance(float(t))) for t, e in zip(ts, batch(ts))],
                            breaks_for=own, monotone=own is not None)
    motion.cuts_approximate = own is not None   # (critical points of interpolants: a rate's root replaces them)
    period = res.results.get("period")
    if quad and isinstance(period, float) and period > 0:
        motion.period = period                       # the energy route's motion repeats exactly
    mf.attach(res, p.find, mf.answer_find(p.find, motion, const, res.warn, full=full))


def _turns(batch, B, subdivide=None) -> list[float]:
    sm = mf.StateMotion(lambda t: batch([t])[0], B[0], B[-1], B, batch=batch, subdivide=subdivide)
    sm.prefetch()
    return mf.turns(lambda t: sm.value("s_dot", t), B, subdivide or SUBDIVIDE)


def _odometer(s, turns: list[float], half: float | None):
    """distance(t): Σ|Δs| between the turning points.  ``half``: the motion oscillates between
    two turning points, the k-th at turns[0] + (k − 1)·half (a swing and its return take equal
    times), s there alternating between its first two values: the distance at any t from those
    two, whatever the number of swings (no list of them)."""
    import math

    turns = sorted(turns)
    s0 = s(0.0)
    if half is not None and len(turns) >= 2:
        t1, s1, s2 = turns[0], s(turns[0]), s(turns[1])

        def periodic(t: float) -> float:
            if t <= t1:
                return abs(s(t) - s0) + 0.0
            k = math.floor((t - t1) / half) + 1          # turning points at or before t
            last = s1 if k % 2 else s2
            return abs(s1 - s0) + (k - 1) * abs(s2 - s1) + abs(s(t) - last) + 0.0
        return periodic
    return lambda t: mf.turning_length(s, turns, [t])[0]
