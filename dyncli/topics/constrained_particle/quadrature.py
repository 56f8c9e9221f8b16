"""The energy route of ``constrained-particle``: a fixed curve and forces of
the position only (notes §18-§20).

Along a fixed curve every force of the position only does work that depends
on q alone, W(q) = ∫ F(y(q))·y'(q) dq (19.4), so the energy equation (20.1)
integrates once: T = ½ m |y'|² q̇² = T1 + W(q) − W(q0) = K(q).  Turning
points are the roots of K; the time follows by quadrature,

    t(q) = ∫ dq / |q̇|,   |q̇| = sqrt(2 K(q) / (m |y'(q)|²)),

with Gauss–Jacobi rules whose weight (q − a)^(−½) absorbs the inverse
square root at a turning point a (K ≈ K'(a)(q − a)), so the rest of the
integrand is smooth and the rule converges exponentially.  q(t) is found by
brentq on t(q) within each leg between turning points (from the nearer end
in time); the motion is periodic between two turning points (the period is
reported), or a revolution of a closed curve, or a run to the end of the
wire.  W is a composite 8-point Gauss–Legendre sum on 1024 cells of
q_range.  ``error_estimate``: the positions recomputed with rules of half
the nodes (48 vs 96), the largest difference, and at least 100 ε of the
position scale |x| + |v| t (the rounding of the sums and the root finding).

Not used (the ODE route takes over under method auto) without q_range, on a
closed curve whose forces do net work around it, or when a turning point is
an equilibrium (an asymptotic approach that takes infinite time).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import NumericalError
from dyncli.result import Result, Series

N_CELLS = 1024


class _Skip(Exception):
    """The energy route does not apply; the message says why."""


class Energy:
    def __init__(self, p, model):
        self.p, self.model, self.curve, self.m = p, model, model.curve, model.m
        if p.q_range is None:
            raise _Skip("the energy route needs q_range (the ends of the wire)")
        self.lo, self.hi = (float(v) for v in p.q_range)
        self.L = self.hi - self.lo
        self.closed = model.closed
        xg, wg = np.polynomial.legendre.leggauss(8)
        self.xg, self.wg = xg, wg
        edges = np.linspace(self.lo, self.hi, N_CELLS + 1)
        self.edges, self.h = edges, edges[1] - edges[0]
        Qt, Qn = self._gen(self._cell_nodes(edges[:-1], edges[1:]))
        w = wg * (self.h / 2)
        self.cum = np.concatenate([[0.0], np.cumsum(Qt @ w)])
        self.cum_n = np.concatenate([[0.0], np.cumsum(Qn @ w)])
        self.scale = max(float(np.max(np.abs(self.cum))), 1e-300)
        x6, w6 = np.polynomial.legendre.leggauss(6)   # the cells must resolve the forces along the curve
        Q6 = self._gen((0.5 * (edges[:-1] + edges[1:]))[:, None] + (0.5 * self.h) * x6[None, :])[0]
        if np.max(np.abs(self.cum[1:] - np.cumsum(Q6 @ (w6 * self.h / 2)))) > 1e-9 * self.scale:
            raise _Skip(f"q_range is too long for the energy route's {N_CELLS} cells to resolve the curve")
        if self.closed and abs(self.cum[-1]) > 1e-10 * self.scale:
            raise _Skip("the forces do net work around the closed curve")
        self.q0, self.T0 = float(p.q0), 0.5 * self.m * self._g(np.array([p.q0]))[0] * float(p.q_dot0) ** 2

    def _cell_nodes(self, a, b):
        return (0.5 * (a + b))[:, None] + (0.5 * (b - a))[:, None] * self.xg[None, :]

    def _gen(self, q):
        """The generalised forces F·y' (total and of the non-potential terms) at q (any shape)."""
        shape = q.shape
        qf = q.ravel()
        x = self.curve.y(qf)
        Fc, Fn = self.model.forces(np.zeros_like(qf), x, np.zeros_like(x))
        y1 = self.curve.dy(qf)
        return (np.sum((Fc + Fn) * y1, axis=0).reshape(shape), np.sum(Fn * y1, axis=0).reshape(shape))

    def _g(self, q):
        y1 = self.curve.dy(np.ravel(q))
        return np.sum(y1 * y1, axis=0).reshape(np.shape(q))

    def W(self, q, which=0):
        """W(q) − W(lo) (which=0: all forces; 1: the non-potential ones), q anywhere
        (a closed curve is periodic)."""
        q = np.asarray(q, float)
        loops = np.floor((q - self.lo) / self.L) if self.closed else np.zeros_like(q)
        qq = q - loops * self.L
        i = np.clip(((qq - self.lo) // self.h).astype(int), 0, N_CELLS - 1)
        a = self.edges[i]
        nodes = self._cell_nodes(np.ravel(a), np.ravel(qq))
        G = self._gen(nodes)[which]
        part = (G @ self.wg) * (np.ravel(qq) - np.ravel(a)) / 2
        cum = self.cum if which == 0 else self.cum_n
        return (cum[i] + part.reshape(np.shape(q))) + loops * cum[-1]

    def K(self, q, ref=None):
        """Kinetic energy at q: from a turning point ref (K(ref) = 0), else from q0."""
        if ref is None:
            return self.T0 + self.W(q) - self.W(np.array(self.q0))
        return self.W(q) - self.W(np.array(ref))

    # -- turning points ---------------------------------------------------
    def next_turn(self, qs, d, ref):
        """The first turning point after qs in the direction d (None if none
        before the end of an open wire, or within one loop of a closed one)."""
        from dyncli.rootfind import brentq

        end = qs + d * self.L if self.closed else (self.hi if d > 0 else self.lo)
        if end == qs:                             # already at that end of the wire
            return None
        n = max(2, int(math.ceil(abs(end - qs) / self.h * 2)))
        qn = qs + (end - qs) * np.arange(1, n + 1) / n
        K = self.K(qn, ref)
        neg = np.flatnonzero(K <= 0)
        if not neg.size:
            return None
        j = int(neg[0])
        a = qs if j == 0 else float(qn[j - 1])
        if K[j] == 0:
            return float(qn[j])
        fa = float(self.K(np.array(a), ref))
        if fa <= 0:
            return a
        return float(brentq(lambda q: float(self.K(np.array(q), ref)), a, float(qn[j]), xtol=1e-15, rtol=1e-15))

    def check_turn(self, b):
        Qb = float(self._gen(np.array([b]))[0][0])
        if abs(Qb) <= 1e-9 * self.scale / self.L:
            raise _Skip(f"the turning point q = {b:.6g} is an equilibrium (an asymptotic approach)")

    # -- time along a leg ---------------------------------------------------
    def tau(self, qs, qe, turn_s, turn_e, n, ref):
        """∫ dq/|q̇| from qs to qe (either order); turn_* marks turning points."""
        from scipy.special import roots_jacobi

        if qs == qe:
            return 0.0
        al, be = (-0.5 if turn_s else 0.0), (-0.5 if turn_e else 0.0)
        x, w = roots_jacobi(n, be, al)          # weight (1 − x)^be (1 + x)^al on [−1, 1]
        q = qs + (qe - qs) * (x + 1) / 2
        K = np.maximum(self.K(q, ref), 0.0)
        qd = np.sqrt(2 * K / (self.m * self._g(q)))
        h = (1 - x) ** (-be) * (1 + x) ** (-al) / qd
        return float(abs(qe - qs) / 2 * (w @ h))

    def q_at(self, leg, target, n):
        """q on the leg (qs, qe, turn_s, turn_e, duration, ref) at the time
        ``target`` after its start."""
        from dyncli.rootfind import brentq

        qs, qe, ts, te, dur, ref = leg
        if target <= 0:
            return qs
        if target >= dur:
            return qe
        if target <= dur / 2:
            f = lambda q: self.tau(qs, q, ts, False, n, ref) - target  # noqa: E731
        else:
            f = lambda q: dur - target - self.tau(q, qe, False, te, n, ref)  # noqa: E731
        lo, hi = (qs, qe) if qs < qe else (qe, qs)
        return float(brentq(f, lo, hi, xtol=1e-15 * max(1.0, abs(lo), abs(hi)), rtol=1e-15))


def _plan(E: Energy, n: int):
    """The legs of the motion: (first legs, periodic legs or None, shift per period)."""
    p = E.p
    Q0 = float(E._gen(np.array([E.q0]))[0][0])
    if p.q_dot0 == 0 and abs(Q0) <= 1e-12 * E.scale / E.L:
        return "rest", None, None
    d = 1.0 if (p.q_dot0 > 0 or (p.q_dot0 == 0 and Q0 > 0)) else -1.0
    start_turn = p.q_dot0 == 0
    ref0 = E.q0 if start_turn else None
    b = E.next_turn(E.q0, d, ref0)
    if b is None:
        if E.closed:
            dur = E.tau(E.q0, E.q0 + d * E.L, start_turn, start_turn, n, ref0)
            return [], [(E.q0, E.q0 + d * E.L, start_turn, start_turn, dur, ref0)], d * E.L
        end = E.hi if d > 0 else E.lo
        return [(E.q0, end, start_turn, False, E.tau(E.q0, end, start_turn, False, n, ref0), ref0)], None, None
    E.check_turn(b)
    first = (E.q0, b, start_turn, True, E.tau(E.q0, b, start_turn, True, n, b), b)
    a = E.next_turn(b, -d, b)
    if a is None:
        end = E.lo if d > 0 else E.hi
        return [first, (b, end, True, False, E.tau(b, end, True, False, n, b), b)], None, None
    E.check_turn(a)
    dur = E.tau(b, a, True, True, n, b)
    return [first], [(b, a, True, True, dur, b), (a, b, True, True, dur, a)], 0.0


def motion(E: Energy, times, n: int):
    """q and q̇ at the times, and the period (or None); the legs planned once per Energy and n
    (the find queries ask for the motion at many single times)."""
    plans = E.__dict__.setdefault("_plans", {})
    if n not in plans:
        plans[n] = _plan(E, n)
    first, cycle, shift = plans[n]
    if first == "rest":
        return np.full(len(times), E.q0), np.zeros(len(times)), None, []
    qs, qds = [], []
    t_first = sum(leg[4] for leg in first)
    period = sum(leg[4] for leg in cycle) if cycle else None
    if period is not None and not period > 0:
        raise _Skip("the motion's turning points coincide")
    if cycle is None and t_first < max(times, default=0.0):
        end = first[-1][1]
        raise NumericalError(f"the particle reaches the end of the wire (q = {end:.6g}) at t = {t_first:.6g} s, "
                             f"before t_end = {max(times):g} s")
    for t in times:
        k, tt = 0, t
        legs, base = first, 0.0
        if cycle and (tt > t_first or not first):
            tt -= t_first
            nper = math.floor(tt / period)
            tt -= nper * period
            legs, base = cycle, nper * shift
        while k < len(legs) - 1 and tt > legs[k][4]:
            tt -= legs[k][4]
            k += 1
        leg = legs[k]
        q = E.q_at(leg, tt, n)
        K = max(float(E.K(np.array(q), leg[5])), 0.0)
        sgn = 1.0 if leg[1] > leg[0] else -1.0
        qs.append(q + base)
        qds.append(sgn * math.sqrt(2 * K / (E.m * float(E._g(np.array([q]))[0]))))
    turns = sorted({leg[1] for leg in (cycle or []) if leg[3]})
    return np.array(qs), np.array(qds), period, turns


def solve(p, model, times, fallback=True) -> Result | None:
    from .solver import SERIES, _equations, assemble

    try:
        E = Energy(p, model)
        q, qd, period, turns = motion(E, times, 96)
        q2, qd2, _, _ = motion(E, times, 48)
    except _Skip as exc:
        if fallback:
            return None
        raise NumericalError(f"method quadrature: {exc}; use method ode") from None
    n = len(times)
    Wn = E.W(q, 1) - E.W(np.array(E.q0), 1)
    Y = np.vstack([q, qd, np.zeros(n), Wn, np.zeros(n)])
    out = assemble(p, model, times, Y, [("slide", 1.0)] * n)
    x2 = model.curve.state(np.zeros(n), q2, qd2, np.zeros(n))[0]
    res = Result(out["results"], method="quadrature", equations=_equations(model) + ["19.4", "20.1"],
                 series=[Series("t", times, SERIES + ["distance"])])
    r = res.results
    x0 = model.curve.state(0.0, p.q0, p.q_dot0, 0.0)
    E1 = float(0.5 * model.m * np.sum(x0[1] ** 2) + model.potential(x0[0])[0])
    r["energy_residual"] = max((abs(e - E1 - w) for e, w in zip(r["E"], r["W_nc"])), default=0.0)
    r["period"] = period
    r["q_turn"] = [float(v) + 0.0 for v in turns]
    X, V = np.array(r["x"], float).T, np.array(r["v"], float).T
    # relative to the position scale |x| + |v| t (the runner's rule: relative, docs/accuracy.md), at least
    # the rounding floor of the sums and the root finding, 100 ε
    scale = float(np.max(np.abs(X)) + np.max(np.abs(V)) * max(times)) if n else 0.0
    diff = float(np.max(np.abs(X - x2))) / scale if n and scale > 0 else 0.0
    res.error_estimate = max(diff, 100 * np.finfo(float).eps) if n else 0.0
    if period and times and max(times) > 1e12 * period:
        res.warn(f"t = {max(times):.6g} s is more than 1e12 periods ({period:.6g} s): the phase of the motion there "
                 "is lost to rounding of t itself")
    return res
