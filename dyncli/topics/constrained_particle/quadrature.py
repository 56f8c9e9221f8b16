"""The energy route of ``constrained-particle``: a fixed curve and forces of the position only
(notes §18-§20).  The energy integral and its turning points: turning.py (decided exactly).

The time follows by quadrature, t = ∫ dq/|q̇|, |q̇| = sqrt(2K(q)/M(q)), M = m|y'|², piece by
piece in a variable x ≥ 0 that makes the integrand smooth: q = a + σx² from a turning point a
(K ≈ Q(a)(q − a): dt = 2 sqrt(M u/(2K)) dx, the inverse square root absorbed exactly, K formed
from a itself so that it keeps its relative precision however close a lies to a barrier's top),
else q = q0 + σx; an oscillation is split at the midpoint of its turning points.  Each piece is
integrated by adaptive Gauss–Kronrod (dyncli.quadrature) to rtol 1e-13, which follows the
near-separatrix structure (a time growing like the log of the distance to the top).  q(t): Brent
on x within a piece.  The state at t = 0 is the input itself.

``error_estimate``: the time error (the quadratures' estimates, per period times the periods run,
plus the sensitivity of the time to the turning points' rounding next to a barrier's top) times
the largest speed, relative to the position scale |x| + |v| t, at least 100 ε; for a periodic
motion at least 2π·δt/period with δt = n·(the cycle's time error) + ulp(t) after n whole periods
(the error of the velocity, and of a position oscillating about a point, relative to its scale),
warned beyond rtol and, as lost digits, beyond :data:`dyncli.phase.LOSS` (docs/accuracy.md,
long times).  Not used (the ODE
route takes over under method auto) without q_range, on a closed curve whose forces do net work
around it, or when the energy equals a barrier's top to rounding (refused: undecided).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import NumericalError
from dyncli.quadrature import gauss_kronrod
from dyncli.result import Result, Series

from .report import SERIES, assemble, equation_numbers
from .turning import Energy, Skip

RTOL = 1e-13            # above Gauss–Kronrod's rounding floor (50 ε ∫|f|)
_EPS = float(np.finfo(float).eps)
REFUSE = 1e-3              # an error estimate above this is refused (exit 1), not reported
_TABLE = 8                  # table points per piece (Brent inverts between two of them)


class Piece:
    """q = anchor + σx² ('turn', K(anchor) = 0) or anchor + σx ('line', K from ref), 0 ≤ x ≤ X."""

    def __init__(self, E, kind, anchor, sig, X, ref=None):
        self.E, self.kind, self.a, self.sig, self.X = E, kind, anchor, sig, X
        self.ref = (anchor, 0.0) if kind == "turn" else ref
        barrier = E.nearest_crit(anchor) if kind == "turn" else None
        # next to a barrier's top c, Q(q) itself carries the rounding of q: relative ~ulp(q)/|q − c|
        self.rtol = RTOL if barrier is None or barrier == anchor else \
            min(max(RTOL, 4 * math.ulp(max(abs(anchor), 1.0)) / abs(barrier - anchor)), 1e-2)
        if kind == "line":      # over a barrier's top: K there against its rounding
            for c in E.crit_between(anchor, anchor + sig * X):
                k, e = E.K(c, [self.ref])
                self.rtol = min(max(self.rtol, 4 * e / k if k > 0 else 1e-2), 1e-2)
        self.c = abs(float(E.Q(np.array([anchor]))[0])) if kind == "turn" else 0.0
        self.err = 0.0
        self.xs = [X * j / _TABLE for j in range(_TABLE + 1)]
        self.ts = [0.0]
        self.dense: list = []           # each table interval's antiderivative (quadrature.Antiderivative)
        for x0, x1 in zip(self.xs[:-1], self.xs[1:]):
            self.ts.append(self.ts[-1] + self._quad(x0, x1))

    def q(self, x):
        return self.a + self.sig * (x * x if self.kind == "turn" else x)

    def x_of(self, q):
        u = abs(q - self.a)
        return math.sqrt(u) if self.kind == "turn" else u

    def _K(self, x):
        q = self.q(np.asarray(x, float))
        return q, self.E.K_from(q, self.ref)

    def _g(self, x):
        """dt/dx (smooth: the turning point's inverse square root taken out exactly)."""
        q, K = self._K(x)
        M = self.E.M(q)
        if self.kind == "turn":
            u = np.abs(q - self.a)             # (the rounded q: K/u → |Q(a)| as u → 0)
            r = np.where(u > 0, K / np.where(u > 0, u, 1.0), self.c)
            bad = ~(r > 0)
            g = 2.0 * np.sqrt(M / (2.0 * np.where(bad, 1.0, r)))
        else:
            bad = ~(K > 0)
            g = np.sqrt(M / (2.0 * np.where(bad, 1.0, K)))
        if np.any(bad):
            raise NumericalError(f"the kinetic energy is not positive at q = {float(np.ravel(q)[np.ravel(bad)][0]):.9g} "
                                 "inside the motion (a turning point the analysis did not find): please report this")
        return g

    def _quad(self, x0, x1):
        """A table interval's time, its error in ``err``, and its antiderivative kept (the
        quadrature's dense output: the time at any x between, and its inverse, with no new
        quadrature)."""
        I, err, ok, F = gauss_kronrod(self._g, x0, x1, self.rtol, 0.0, what="the time integrand 1/|q̇|", dense=True)
        self.err += err + (0.0 if ok else abs(I))
        self.dense.append(F)
        return I

    def _k(self, x) -> int:
        return min(max(int(np.searchsorted(self.xs, x, side="right")) - 1, 0), _TABLE - 1)

    def tau(self, x):
        """The time from x = 0 to x."""
        k = self._k(x)
        return self.ts[k] + (self.dense[k](x) if x != self.xs[k] else 0.0)

    def x_at(self, target):
        """x where τ(x) = target (0 ≤ target ≤ τ(X))."""
        if target <= 0:
            return 0.0
        if target >= self.ts[-1]:
            return self.X
        k = max(int(np.searchsorted(self.ts, target, side="left")) - 1, 0)
        return self.dense[k].inverse(target - self.ts[k])

    def speed(self, x):
        """|q̇| at x: √(2K/M); near a turning point, where q = a + σx² has lost x² to the rounding
        of q (the relative error ulp(q)/x² above the quadrature's rtol), 2x / (dt/dx) from the time
        integrand's interpolant instead — so that the rate crosses zero at the turning point's time
        (its root read from √K's rounding was 5e-9 of the period off)."""
        if self.kind == "turn" and 0.0 < x <= self.X and math.ulp(max(abs(self.a), 1.0)) > self.rtol * x * x:
            return 2.0 * x / self.dense[self._k(x)].f(x)
        q, K = self._K(np.array([x]))
        return math.sqrt(max(float(K[0]), 0.0) / (0.5 * float(self.E.M(q)[0])))


class Seg:
    """A piece run from x0 to x1."""

    def __init__(self, piece, x0, x1):
        self.p, self.x0, self.x1 = piece, x0, x1
        self.t0 = piece.tau(x0) if x0 not in (0.0, piece.X) else (0.0 if x0 == 0.0 else piece.ts[-1])
        t1 = piece.tau(x1) if x1 not in (0.0, piece.X) else (0.0 if x1 == 0.0 else piece.ts[-1])
        self.dur, self.dir = abs(t1 - self.t0), (1.0 if x1 >= x0 else -1.0)

    def state(self, tt):
        x = self.p.x_at(self.t0 + self.dir * min(max(tt, 0.0), self.dur))
        return float(self.p.q(x)), self.p.speed(x) * self.p.sig * self.dir


def _oscillation(E, a, b, d, start, ca, cb):
    """Turning points a (behind) and b (ahead in the direction d), the barriers' tops ca, cb
    beyond them (or None): (first legs, cycle)."""
    mid = 0.5 * (a + b)
    A = Piece(E, "turn", a, d, math.sqrt(abs(mid - a)))
    B = Piece(E, "turn", b, -d, math.sqrt(abs(b - mid)))
    cycle = [Seg(B, 0.0, B.X), Seg(A, A.X, 0.0), Seg(A, 0.0, A.X), Seg(B, B.X, 0.0)]   # from b
    if d * (mid - start) >= 0:
        first = [Seg(A, A.x_of(start), A.X), cycle[3]]
    else:
        first = [Seg(B, B.x_of(start), 0.0)]
    return first, cycle


def plan(E):
    """(first legs, cycle or None, shift of q per cycle, turning points, time sensitivity per
    cycle), or None at rest."""
    p, q0 = E.p, E.q0
    rest = p.q_dot0 == 0
    if rest and (E.Q0 == 0 or any(abs(q0 - c) <= 2 * math.ulp(q0) for c in E.crit_between(q0 - 1, q0 + 1) + E.crit)):
        return None                            # released at an equilibrium
    d = math.copysign(1.0, p.q_dot0 if not rest else E.Q0)
    refs = [(q0, E.T0)]
    ahead = E.next_turn(q0, d, refs)
    if ahead is None:
        wall = None if E.closed else (E.hi if d > 0 else E.lo)
        if wall is None:                        # a revolution of the closed curve
            P = Piece(E, "line", q0, d, E.L, ref=(q0, E.T0))
            return [], [Seg(P, 0.0, P.X)], d * E.L, [], 0.0
        kind, X = ("turn", math.sqrt(abs(wall - q0))) if rest else ("line", abs(wall - q0))
        P = Piece(E, kind, q0, d, X, ref=(q0, E.T0))
        return [Seg(P, 0.0, P.X)], None, 0.0, [], 0.0
    b, cb = ahead
    if b == q0:
        raise Skip("the start is itself a turning point at an equilibrium")
    behind = (q0, E.nearest_crit(q0)) if rest else E.next_turn(q0, -d, refs)
    if behind is None:
        if E.closed:
            raise Skip("no turning point behind the start on the closed curve (rounding): undecided")
        wall = E.lo if d > 0 else E.hi
        P = Piece(E, "turn", b, -d, math.sqrt(abs(wall - b)))
        return [Seg(P, P.x_of(q0), 0.0), Seg(P, 0.0, P.X)], None, 0.0, [b], 0.0
    a, ca = behind
    first, cycle = _oscillation(E, a, b, d, q0, ca, cb)
    sens = 2 * (E.sensitivity(a, ca) + E.sensitivity(b, cb))
    return first, cycle, 0.0, sorted([a, b]), sens


def motion(E, times):
    """q, q̇ at the times, the period (or None), the turning points and the time error at the
    latest time; the legs planned once per Energy (the find queries ask for many single times)."""
    if "_plan" not in E.__dict__:
        E._plan = plan(E)
    pl = E._plan
    if pl is None:
        return np.full(len(times), E.q0), np.zeros(len(times)), None, [], 0.0, [0.0] * len(times)
    first, cycle, shift, turns, sens = pl
    t_first = sum(s.dur for s in first)
    period = sum(s.dur for s in cycle) if cycle else None
    if period is not None and not period > 0:
        raise Skip("the motion's turning points coincide")
    if cycle is None and t_first < max(times, default=0.0):
        end = first[-1].p.q(first[-1].x1)
        raise NumericalError(f"the particle reaches the end of the wire (q = {end:.6g}) at t = {t_first:.6g} s, "
                             f"before t_end = {max(times):g} s")
    pieces = {id(s.p): s.p for s in first + (cycle or [])}.values()
    err_cycle = sum(pc.err for pc in pieces) + sens
    qs, qds, dt, dts = [], [], 0.0, []          # dts: the time's error from the whole periods run
    for t in times:
        if t == 0:                             # the input itself
            qs.append(E.q0)
            qds.append(float(E.p.q_dot0))
            dts.append(0.0)
            continue
        legs, tt, base = first, t, 0.0
        if cycle and (tt > t_first or not first):
            tt -= t_first
            nper = math.floor(tt / period)
            tt -= nper * period
            legs, base = cycle, nper * shift
            dt = max(dt, err_cycle * (nper + 2))
            dts.append(err_cycle * nper + math.ulp(t))      # (the periods run: within one, the estimate above)
        else:
            dt = max(dt, err_cycle)
            dts.append(math.ulp(t))
        k = 0
        while k < len(legs) - 1 and tt > legs[k].dur:
            tt -= legs[k].dur
            k += 1
        q, qd = legs[k].state(tt)
        qs.append(q + base)
        qds.append(qd)
    return np.array(qs), np.array(qds), period, turns, dt, dts


def results_at(p, model, E, ts, q, qd, carried_s: bool = False) -> dict:
    """The reported results at the times ``ts`` with q, q̇ there: the curve turned by φ = ω t (a
    turning curve's), W̄ from the table, and W_N — 0 on a fixed curve — on a turning one the work
    the curve does, ω ΔH₃ (N's power is ω k·(y × N), N ⊥ the relative velocity; the other forces,
    symmetric about the axis, have no moment about it), so that the energy balance checks the
    Jacobi integral.  ``carried_s``: a zero row for s (the caller's own arc length)."""
    n = len(ts)
    w = model.curve.omega_const if model.curve.rotating else 0.0
    Wn = E.W(q, 1) - E.W(np.array(E.q0), 1)
    rows = [q, qd, w * np.asarray(ts, float), Wn, np.zeros(n)] + ([np.zeros(n)] if carried_s else [])
    r = assemble(p, model, ts, np.vstack(rows), [("slide", 1.0)] * n)["results"]
    if w:
        k = model.curve.k
        x0, v0 = (np.asarray(c, float)[:, 0] for c in model.curve.state(0.0, p.q0, p.q_dot0, 0.0)[:2])
        H0 = float(model.m * np.dot(np.cross(x0, v0), k))
        H = model.m * np.cross(np.asarray(r["x"], float), np.asarray(r["v"], float)) @ k
        r["W_N"] = [float(w * (h - H0)) + 0.0 for h in H]
    return r


def initial_energy(p, model) -> float:
    """T + V at t = 0 (the fixed frame's)."""
    x0 = model.curve.state(0.0, p.q0, p.q_dot0, 0.0)
    return float(0.5 * model.m * np.sum(x0[1] ** 2) + model.potential(x0[0])[0])


def solve(p, model, times, fallback=True) -> Result | None:
    try:
        E = Energy(p, model)
        q, qd, period, turns, dt, dts = motion(E, times)
    except Skip as exc:
        if fallback:
            return None
        raise NumericalError(f"method quadrature: {exc}; use method ode") from None
    res = Result(results_at(p, model, E, times, q, qd), method="quadrature",
                 equations=equation_numbers(model) + ["19.4", "20.1"],
                 series=[Series("t", times, SERIES + ["distance"])])
    r = res.results
    E1 = initial_energy(p, model)       # (on a turning curve the balance is the Jacobi integral's, E − ω H_k)
    r["energy_residual"] = max((abs(e - E1 - w - wn) for e, w, wn in zip(r["E"], r["W_nc"], r["W_N"])), default=0.0)
    r["period"] = period
    r["q_turn"] = [float(v) + 0.0 for v in turns]
    _estimate(res, p, E, times, dt, period)
    if period:
        _long_times(res, p, times, dts, period)
    return res


def _long_times(res, p, times, dts, period):
    """The periodic motion's phase error 2π·δt/period at each time: counted in error_estimate and
    warned beyond :data:`dyncli.phase.LOSS` (the period known to its quadratures' estimates), or
    beyond rtol when the estimate was within it before."""
    from dyncli.phase import LOSS, warn_lost

    phases = [2.0 * math.pi * d / period for d in dts]
    before, worst = res.error_estimate or 0.0, max(phases, default=0.0)
    res.error_estimate = max(before, worst)
    why = (f"the period {period:.9g} s is known to its quadratures' estimates, so n periods on the time is "
           "n times as uncertain (counted in error_estimate)")
    rtol = float(p.accuracy.rtol)
    if worst > LOSS:
        warn_lost(res, [float(t) for t in times], phases, "the state", why)
    elif worst > rtol >= before:
        res.warn(f"error estimate {worst:.2g} > rtol {rtol:g}: {why}; ask for a smaller t")


def _estimate(res, p, E, times, dt, period):
    """error_estimate: the time error times the largest speed, relative to |x| + |v| t."""
    r, n = res.results, len(times)
    X, V = np.array(r["x"], float).T, np.array(r["v"], float).T
    vmax = float(np.max(np.linalg.norm(V, axis=0))) if n else 0.0
    vmax = max(vmax, math.sqrt(2 * (E.T0 + E.scale) / E.m))     # the speed bound of the energy
    scale = float(np.max(np.abs(X)) + vmax * max(times)) if n else 0.0
    est = vmax * dt / scale if scale > 0 else 0.0
    res.error_estimate = max(est, 100 * _EPS) if n else 0.0
    rtol = float(p.accuracy.rtol)
    if res.error_estimate > REFUSE:
        raise NumericalError(f"the energy route's error estimate is {res.error_estimate:.2g} (> {REFUSE:g}): the motion "
                             "passes so close to a barrier's top (an unstable equilibrium) that its timing is not "
                             "determined in double precision (it depends on the last digits of q0 and of the turning "
                             "points); start further from the separatrix (e.g. 1e-10 of q_range from the top or more)")
    if res.error_estimate > rtol:
        res.warn(f"error estimate {res.error_estimate:.2g} > rtol {rtol:g}: the motion passes close to a barrier's "
                 "top (an unstable equilibrium), where its timing depends on the last digits of q0 and of the turning "
                 "points; move the start further from the separatrix for a better-determined answer")
