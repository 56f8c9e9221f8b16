"""Where a scene can rest: the equilibria of its reduced system, each a converged root (docs/types/scene.md).

At rest the joints hold the loads: f(q) + Jᵀλ = 0 with φ(q) = 0 — the generalized forces
Zᵀf of the reduced system vanish (Z spanning the null space of J).  Each equilibrium is a root
of that square system in (q, λ), found by Newton's method with its analytic Jacobian

    [ −∇²V + Σ λ_k ∇²φ_k   Jᵀ ]
    [ J                    0  ]      (curvature.py),

started from the given configuration and from the points where the generalized force along a
path on the mechanism vanishes: each free coordinate is followed on the joints' manifold (a step
of 0.1 rad, or 0.1 of the scene's size, by tangent continuation, half a turn either way), and on
each step p(τ) = onto(q_k + τ (q_{k+1} − q_k)) every root and touch of g(τ) = t(τ)·f(p(τ)) is
decided by all_roots (the sign analysis of g's resolved Chebyshev interpolant, g evaluated at
all its nodes at once), never by the signs at the step's ends: two or three equilibria within
one step are each a start.  A step whose interpolant stays clear of zero is decided by its
coefficients alone (:func:`away_from_zero`).  With one degree of freedom the steps are decided
together over *stretches* (:meth:`Search.stretch_roots`): where the walk is a graph over the
chord of a run of steps, the path is the section of the joints by the planes normal to that
chord, and one all_roots (cells halved where g needs it) decides the same zeros as a cell of
degree 12 on every step, at a fraction of the evaluations.  With more degrees of freedom each
step keeps its own cell; what is shared is the arithmetic: :func:`find` works in *rounds* — Newton
runs from every start queued at once (:meth:`Search.rests_from`: one iteration a row, stacked F,
Jacobians from curvature.rest_hessians and least-squares steps by one stacked SVD, each row
stopped on its own), the results are read in the queue's order (the same equilibria in the same
order as one start at a time), and the paths from the round's new equilibria are walked together
(:meth:`Search.walks`: a step of every path in one stacked Gauss–Newton), their steps' first cells
evaluated in one call, the steps whose first cell is not resolved evaluated on both halves in one
more, and the clear-of-zero test applied to all of them at once (:func:`clear_of_zero`).  A scene
with an element on a curve (whose point's foot is searched from the last one asked) keeps one
path and one start at a time.  An equilibrium beyond half a turn from every start can still be
missed (said in the docs).
Equilibria that differ by whole turns of an angle, or along a neutral direction of a continuum
of equilibria, are one.  A one-sided joint that would pull (or a rolling body that would slip)
at an equilibrium is not a rest configuration: that equilibrium is dropped with a warning.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import NumericalError
from dyncli.rootfind import all_roots, lstsq_many, newton_system, newton_systems

from . import assembly, curvature

EPS = float(np.finfo(float).eps)
STEP = 0.1              # path step along a free coordinate (rad, or a fraction of the scene's size)
REACH = math.pi         # how far each path runs either way (same units)
FAR = 3                 # ... and on, until each angle moving along it has turned by π, at most FAR × REACH
MAX_FOUND = 24
EVERY = 5              # every fifth point of a path starts a Newton iteration too
MAX_WALKED = 8         # equilibria whose own paths are followed too
DEG = 12                # the degree of g's interpolant on one step (all_roots' starting cell)
BUDGET = 64            # cells per step before the rest of it is left undecided (a start at each)
STRETCH_COS = 0.9      # one degree of freedom: a stretch's tangents within 26° of its chord


class Search:
    def __init__(self, system, q0):
        self.s = system
        self.n = system.n
        self.L = assembly.length_scale(q0, system)
        self.angles = np.array([nm.startswith("angle.") for nm in system.names])
        self.scale = np.where(self.angles, 1.0, self.L)
        self.dof = system.n - assembly.rank(system.jac(q0)) if system.m else system.n
        f = self.forces(q0)
        self.F0 = max(float(np.max(np.abs(f), initial=0.0)), float(np.max(np.abs(system.grav), initial=0.0)), 1e-300)
        self.floor = 1e-10 * self.F0 * max(1.0, self.L)      # all_roots' resolution of the force along a path
        # many paths and Newton starts at once, unless an element on a curve keeps the foot of its
        # point from the last position asked (its next foot is searched from there: one at a time)
        self.stacked = not any(hasattr(e, "hessian") for e in system.elements)

    def forces(self, q) -> np.ndarray:
        return self.s.applied(q, np.zeros(self.n), 0.0)[0]

    def forces_many(self, Q) -> np.ndarray:
        """:meth:`forces` at the configurations Q (k, n): gravity alone for all rows at once, with
        loads row by row."""
        if not self.s.loads:
            return np.broadcast_to(self.s.grav, np.shape(Q))
        return np.array([self.forces(q) for q in Q]).reshape(np.shape(Q))

    def multipliers(self, q) -> np.ndarray:
        J = self.s.jac(q)
        if J.shape[0] == 0:
            return np.zeros(0)
        return np.linalg.lstsq(J.T, -self.forces(q), rcond=None)[0]

    def multipliers_many(self, Q, J=None) -> np.ndarray:
        """:meth:`multipliers` at every row of Q (k, n) at once (J: the rows' Jacobians, if known)."""
        if not self.s.m:
            return np.zeros((len(Q), 0))
        if J is None:
            J = self.s.jac_many(self.s.stack(Q))
        return lstsq_many(np.swapaxes(J, 1, 2), -self.forces_many(Q), rcond=EPS * max(self.n, self.s.m))

    def same_sides(self, qa, qb) -> bool:
        """No spring or damper passed through zero length from qa to qb (its direction, undefined
        there, would flip: the model ends where its two ends meet)."""
        for ld in self.s.loads:
            if ld.kind in ("spring", "damper"):
                da, db = ld.P.pos(qa) - ld.Q.pos(qa), ld.P.pos(qb) - ld.Q.pos(qb)
                if float(da @ db) <= 0:
                    return False
        return True

    # ------------------------------------------------------------------ Newton on (q, λ)
    def rests_from(self, starts) -> list:
        """The equilibrium Newton's method reaches from each start, (q, λ) or None: one Newton
        iteration a start, all run together (rootfind.newton_systems: the rows' F, Jacobians and
        least-squares steps stacked, each row stopped on its own), then each result checked."""
        s, n, m = self.s, self.n, self.s.m
        if len(starts) <= 1:
            return [self.rest_from(q) for q in starts]

        def F(Y):
            Q, L = Y[:, :n], Y[:, n:]
            X = s.stack(Q)
            out = np.empty_like(Y)
            out[:, :n] = self.forces_many(Q)
            if m:
                out[:, :n] += np.einsum("kri,kr->ki", s.jac_many(X), L)
                out[:, n:] = s.phi_many(X, s.at_times(np.zeros(len(Y))))
            return out

        def jac(Y):
            Q, L = Y[:, :n], Y[:, n:]
            A = np.zeros((len(Y), n + m, n + m))
            A[:, :n, :n] = curvature.rest_hessians(s, Q, L)
            if m:
                J = s.jac_many(s.stack(Q))
                A[:, :n, n:] = np.swapaxes(J, 1, 2)
                A[:, n:, :n] = J
            return A

        Q0 = np.array(starts, dtype=float)
        Y0 = np.concatenate([Q0, self.multipliers_many(Q0)], axis=1)
        scale = np.concatenate([self.scale, np.full(m, 1e3 * self.F0 * max(1.0, self.L))])
        Y, conv = newton_systems(F, jac, Y0, scale=scale, tol=1e-13)
        out: list = [None] * len(starts)
        k = np.nonzero(conv)[0]
        if not k.size:
            return out
        Q = Y[k, :n]
        X = s.stack(Q)
        on = np.max(np.abs(s.phi_many(X, s.at_times(np.zeros(len(k))))), axis=1, initial=0.0) <= 1e-10 * self.L
        J = s.jac_many(X) if m else np.zeros((len(k), 0, n))
        lam = self.multipliers_many(Q, J)
        held = np.max(np.abs(self.forces_many(Q) + np.einsum("kri,kr->ki", J, lam)), axis=1, initial=0.0) <= 1e-9 * self.F0
        for j, kk in enumerate(k.tolist()):
            if on[j] and held[j] and self.same_sides(starts[kk], Q[j]):
                out[kk] = (Q[j].copy(), lam[j].copy())
        return out

    def rest_from(self, q_start):
        """:meth:`rests_from` from one start (its F and Jacobian in the one-state forms)."""
        s, n, m = self.s, self.n, self.s.m

        def F(y):
            q, lam = y[:n], y[n:]
            return np.concatenate([self.forces(q) + s.jac(q).T @ lam, s.phi(q, 0.0)])

        def jac(y):
            q, lam = y[:n], y[n:]
            J = s.jac(q)
            A = np.zeros((n + m, n + m))
            A[:n, :n] = -curvature.potential_hessian(s, q) + curvature.rows_hessian(s, q, lam)
            A[:n, n:] = J.T
            A[n:, :n] = J
            return A

        try:
            y0 = np.concatenate([q_start, self.multipliers(q_start)])
            scale = np.concatenate([self.scale, np.full(m, 1e3 * self.F0 * max(1.0, self.L))])
            y, ok = newton_system(F, jac, y0, scale=scale, tol=1e-13)
            return self._checked(q_start, y[:n]) if ok else None
        except NumericalError:          # Newton led off a curve's ends (no foot there): no rest from here
            return None

    def _checked(self, q_start, q):
        """(q, λ) when Newton's point q is on the joints, reached without a spring or damper passing
        through zero length, and its loads held by the joints (λ by least squares); else None."""
        s = self.s
        if float(np.max(np.abs(s.phi(q, 0.0)), initial=0.0)) > 1e-10 * self.L or not self.same_sides(q_start, q):
            return None
        lam = self.multipliers(q)
        if float(np.max(np.abs(self.forces(q) + s.jac(q).T @ lam), initial=0.0)) > 1e-9 * self.F0:
            return None
        return q, lam

    # ------------------------------------------------------------------ paths on the manifold
    def _onto(self, q):
        """q placed on the joints by minimum-norm Gauss–Newton (the branch nearest q); None where it
        does not converge, or leaves a curve (a point whose foot is beyond the curve's ends: a bowl
        with q_range walked past its rim is off its joint, not an error)."""
        try:
            return self._onto_newton(q)
        except NumericalError:
            return None

    def _onto_newton(self, q):
        for _ in range(30):
            ph = self.s.phi(q, 0.0)
            if float(np.max(np.abs(ph), initial=0.0)) <= 1e-13 * self.L:
                return q
            Js = self.s.jac(q) * self.scale
            q = q - Js.T @ _row_solve(Js, ph) * self.scale
        return None

    def _tangent(self, q, t):
        J = self.s.jac(q) * self.scale
        ts = t / self.scale
        if J.shape[0]:
            ts = ts - J.T @ _row_solve(J, J @ ts)
        nrm = float(np.linalg.norm(ts))
        return None if nrm < 1e-12 else ts / nrm * self.scale

    def _onto_many(self, Q):
        """:meth:`_onto` of every row of Q (k, n) at once: (the points, placed or not)."""
        s, sc = self.s, self.scale
        Q = np.array(Q, dtype=float)
        act = np.arange(len(Q) if s.m else 0)
        if s.m:
            td = s.at_times(np.zeros(len(Q)))
            for _ in range(30):
                ph = s.phi_many(s.stack(Q[act]), [x[act] for x in td])
                done = np.max(np.abs(ph), axis=1) <= 1e-13 * self.L
                act, ph = act[~done], ph[~done]
                if not act.size:
                    break
                Js = s.jac_many(s.stack(Q[act])) * sc
                Q[act] -= (np.swapaxes(Js, 1, 2) @ _row_solve_many(Js, ph)[:, :, None])[:, :, 0] * sc
        ok = np.ones(len(Q), dtype=bool)
        ok[act] = False
        return Q, ok

    def _tangents(self, Q, T) -> np.ndarray:
        """:meth:`_tangent` at every row of Q along the row of T at once (NaN rows where it vanishes)."""
        ts = T / self.scale
        if self.s.m:
            J = self.s.jac_many(self.s.stack(Q)) * self.scale
            ts = ts - (np.swapaxes(J, 1, 2) @ _row_solve_many(J, (J @ ts[:, :, None])[:, :, 0])[:, :, None])[:, :, 0]
        nrm = np.linalg.norm(ts, axis=1)
        with np.errstate(all="ignore"):
            return np.where((nrm >= 1e-12)[:, None], ts / nrm[:, None] * self.scale, np.nan)

    def path_starts(self, q0, t0) -> list:
        """Points of the path from q0 along t0 (both ways) where the force along it vanishes
        (:meth:`walks` of this one path)."""
        return self.walks([(q0, t0)])[0]

    def walks(self, froms) -> list[list]:
        """For each (q0, t0) of ``froms``, the points of the path from q0 along t0 (both ways) where
        the force along it vanishes: every root and touch of g on every step, decided by
        :meth:`step_roots`, and every fifth point of the path.  All the paths are walked together,
        a step of each at once (:meth:`_onto_many`, :meth:`_tangents`: each row's own
        Gauss–Newton and projection, a path stopping on its own), and g at every step's first
        Chebyshev nodes is then evaluated in one stacked call for all of them (:meth:`first_cells`:
        the same values, one call instead of one a step)."""
        ways = [(q0, sign * t0) for q0, t0 in froms for sign in (1.0, -1.0)]
        walks: list[tuple[list, list]] = [([], []) for _ in ways]
        roots: list[list] = []
        for group in ([range(len(ways))] if self.stacked else [[w] for w in range(len(ways))]):
            self._walk(ways, walks, list(group))
            roots += self.walks_roots([walks[w] for w in group])
        out = []
        for k in range(len(froms)):
            got = []
            for w in (2 * k, 2 * k + 1):
                got += roots[w]
                got += [qb for j, (_qa, qb) in enumerate(walks[w][0]) if j % EVERY == EVERY - 1]   # starts on the path itself
            out.append([x for x in got if x is not None])
        return out

    def _moving_angles(self, t) -> np.ndarray:
        """The angles a path's tangent t turns at a rate of at least a tenth of its fastest one's."""
        rates = np.where(self.angles, np.abs(t), 0.0)
        top = float(np.max(rates, initial=0.0))
        return (rates >= 0.1 * top) & (rates > 0) if top > 0 else np.zeros(self.n, dtype=bool)

    def _walk(self, ways, walks, group) -> None:
        """The ways (q0, t0) of ``group`` walked together, their steps and tangents into ``walks``."""
        qs, ts, live = [], [], []
        for w in group:
            q0, t0 = ways[w]
            t = self._tangent(q0, t0)
            if t is not None:
                qs.append(q0.copy())
                ts.append(t)
                live.append(w)
                walks[w][1].append(t)
        # a path runs REACH either way, and on until every angle moving along it has turned by π
        # (a geared pendulum's slower wheel, whose angle is a part of the path's length only), at
        # most FAR × REACH
        start = {w: ways[w][0] for w in group}
        moving = {w: self._moving_angles(t) for w, t in zip(live, ts)}
        base = int(REACH / STEP)
        for k in range(FAR * base):
            if k >= base:
                on = [j for j, w in enumerate(live) if np.any(np.abs(qs[j][moving[w]] - start[w][moving[w]]) < math.pi)]
                qs, ts, live = [qs[j] for j in on], [ts[j] for j in on], [live[j] for j in on]
            if not live:
                break
            if len(live) == 1:                  # one path (an element on a curve): the plain forms
                q1 = self._onto(qs[0] + STEP * ts[0])
                t1 = None if q1 is None else self._tangent(q1, ts[0])
                Q, ok = np.array([qs[0] if q1 is None else q1]), np.array([q1 is not None])
                T = np.array([np.full(self.n, np.nan) if t1 is None else t1])
            else:
                Q, ok = self._onto_many(np.array(qs) + STEP * np.array(ts))
                T = self._tangents(Q, np.array(ts))
            nq, nt, nl = [], [], []
            for j, w in enumerate(live):
                if not ok[j] or not np.isfinite(T[j, 0]) or not self.same_sides(qs[j], Q[j]):
                    continue
                walks[w][0].append((qs[j], Q[j]))
                walks[w][1].append(T[j])
                nq.append(Q[j])
                nt.append(T[j])
                nl.append(w)
            qs, ts, live = nq, nt, nl

    def walk_roots(self, steps, tans) -> list:
        """:meth:`walks_roots` of one walk."""
        return self.walks_roots([(steps, tans)])[0]

    def walks_roots(self, walks) -> list[list]:
        """The roots and touches of the force along each walk (steps, tangents): with one degree of
        freedom over stretches of many steps at once (:meth:`stretch_roots`), else step by step.
        The steps of all the walks decided one by one are evaluated together (:meth:`cell_values`
        at their first cells and ends, then at both halves of the first cells not resolved) and
        decided clear of zero all at once (:func:`clear_of_zero`); the others go to
        :meth:`step_roots` with their values known."""
        outs: list[list] = []
        single: list[tuple[int, int]] = []
        for w, (steps, tans) in enumerate(walks):
            out: list = []
            i = 0
            pts = [steps[0][0]] + [qb for _qa, qb in steps] if steps else []
            while i < len(steps):
                j = self.stretch_end(pts, tans, i) if self.dof == 1 and self.s.m == self.n - 1 else i + 1
                got = self.stretch_roots(pts[i:j + 1]) if j > i + 1 else None
                if got is None:
                    single += [(w, k) for k in range(i, j)]
                else:
                    out += got
                i = j
            outs.append(out)
        steps = [walks[w][0][k] for w, k in single]
        V, evaluated = self.cell_values(steps, FIRST)
        clear, unresolved = clear_of_zero(V[:, :DEG + 1], self.floor)
        todo = np.nonzero(unresolved)[0]
        halves: dict[int, np.ndarray] = {}
        if todo.size:               # a first cell not resolved: both its halves, for all such steps at once
            V2, got2 = self.cell_values([steps[j] for j in todo], SECOND)
            clear[todo] = got2 & clear_of_zero(V2[:, :DEG + 1], self.floor)[0] & \
                clear_of_zero(V2[:, DEG + 1:2 * DEG + 2], self.floor)[0]
            halves = {int(j): V2[i] for i, j in enumerate(todo) if got2[i]}
        for j in np.nonzero(~clear)[0].tolist():
            w, k = single[j]
            known = dict(zip(FIRST.tolist(), V[j].tolist())) if evaluated[j] else {}
            if j in halves:
                known.update(zip(SECOND.tolist(), halves[j].tolist()))
            qa, qb = walks[w][0][k]
            outs[w] += self.step_roots(qa, qb, known)
        return outs

    def stretch_end(self, pts, tans, i: int) -> int:
        """The last walk point j such that the path from point i to j is a graph over the chord
        d = q_j − q_i: every walk point's tangent within 26° of d (STRETCH_COS, the scaled
        metric), each step advancing along d — the section by the planes normal to d then meets
        it once (the closer to straight, the fewer cells all_roots needs)."""
        j = len(pts) - 1
        while j > i + 1:
            d = (pts[j] - pts[i]) / self.scale
            d = d / max(float(np.linalg.norm(d)), 1e-300)
            ok = all(float(tans[k] / self.scale @ d) >= STRETCH_COS for k in range(i, j + 1))
            if ok:
                return j
            j = i + 1 + (j - i - 1) // 2
        return i + 1

    def stretch_roots(self, pts) -> list | None:
        """With one degree of freedom, the roots and touches of the force along the path over a
        stretch of walk points q_0 … q_N (a graph over d = q_N − q_0, :meth:`stretch_end`): the
        path p(τ) is the point of the joints on the plane w·(p − q_0) = τ w·d (w = d in the scaled
        metric), τ in [0, 1], and g(τ) = t·f(p(τ)) as on a step (t along d, projected on the
        joints' tangent) — the same function of the configuration as step by step, one all_roots
        (cells halved where not resolved) over the whole stretch instead of a cell of degree 12
        on each step.  None when a plane's point cannot be found or a part is not resolved
        (all_roots' ``bad``: the steps decide then, each with its own cells)."""
        P = np.array(pts)
        d = P[-1] - P[0]
        w = d / self.scale ** 2
        taus = (P - P[0]) @ w / float(w @ d)
        if not np.all(np.diff(taus) > 0):
            return None

        def section(T):
            T = np.atleast_1d(np.asarray(T, dtype=float))
            return self.on_planes(np.column_stack([np.interp(T, taus, P[:, c]) for c in range(self.n)]), T, P[0], d, w)

        def g(T):
            Q, ok = section(T)
            return self.forces_along(Q, d, ok)

        floor = 1e-10 * self.F0 * max(1.0, self.L)
        roots, touches, bad = all_roots(g, 0.0, 1.0, cells=1, deg=DEG, floor=floor, budget=BUDGET * len(pts))
        if bad:                         # a plane's point not found, or not resolved: step by step
            return None
        xs = roots + touches
        if not xs:
            return []
        Q, ok = section(np.array(xs))
        return [Q[k].copy() if ok[k] else self._onto(P[0] + x * d) for k, x in enumerate(xs)]

    def on_planes(self, Q, T, q0, d, w):
        """Newton from Q (k, n) on the joints' rows and the plane w·(p − q0) = τ w·d of each row's
        τ (stacked); (the points, converged or not)."""
        s = self.s
        Q = np.array(Q, dtype=float)
        td = s.at_times(np.zeros(len(Q)))
        wd = float(w @ d)
        act = np.arange(len(Q))
        for _ in range(30):
            X = s.stack(Q[act])
            F = np.concatenate([s.phi_many(X, [x[act] for x in td]),
                                (((Q[act] - q0) @ w - T[act] * wd) / float(np.linalg.norm(w)))[:, None]], axis=1)
            done = np.max(np.abs(F), axis=1) <= 1e-13 * self.L
            act, F = act[~done], F[~done]
            if not act.size:
                break
            A = np.concatenate([s.jac_many(s.stack(Q[act])),
                                np.broadcast_to(w / float(np.linalg.norm(w)), (act.size, 1, self.n))], axis=1)
            try:
                Q[act] -= np.linalg.solve(A, F[:, :, None])[:, :, 0]
            except np.linalg.LinAlgError:
                break
        ok = np.ones(len(Q), dtype=bool)
        ok[act] = False
        return Q, ok & np.all(np.isfinite(Q), axis=1)

    def first_cells(self, steps) -> list:
        """g at the DEG + 1 Chebyshev nodes of all_roots' first cell [0, 1] of every step and at
        its ends (where all_roots reads the signs) by :meth:`cell_values`, as {τ: g} per step ({}
        for a step whose rows' matrices are singular: its own call falls back to least squares)."""
        V, got = self.cell_values(steps, FIRST)
        return [dict(zip(FIRST.tolist(), V[j].tolist())) if got[j] else {} for j in range(len(steps))]

    def cell_values(self, steps, taus) -> tuple[np.ndarray, np.ndarray]:
        """g at the points τ of ``taus`` of every step (qa, qb), in one stacked :meth:`along` (each
        row's Gauss–Newton and solves its own: the values of one call a step): (the values, a row a
        step; which steps were evaluated).  Where a row's matrix is singular the steps are halved
        until the steps with such a row are alone (those are left to their own calls, which fall
        back to least squares)."""
        V = np.full((len(steps), len(taus)), np.nan)
        got = np.zeros(len(steps), dtype=bool)

        def run(lo: int, hi: int) -> None:
            Q = np.concatenate([steps[j][0] + taus[:, None] * (steps[j][1] - steps[j][0]) for j in range(lo, hi)])
            D = np.repeat(np.array([steps[j][1] - steps[j][0] for j in range(lo, hi)]), len(taus), axis=0)
            try:
                vals = self.along(Q, D)
            except (np.linalg.LinAlgError, NumericalError):  # (a point off a curve's ends: no foot)
                if hi - lo > 1:
                    run(lo, (lo + hi) // 2)
                    run((lo + hi) // 2, hi)
                return
            V[lo:hi] = vals.reshape(hi - lo, len(taus))
            got[lo:hi] = True

        if steps:
            run(0, len(steps))
        return V, got

    def clear(self, known) -> bool:
        """The force along a step has no root and no touch, decided from its values ``known`` at the
        nodes of all_roots' first cell [0, 1], or of both its halves (:func:`away_from_zero`)."""
        vals = [known.get(x, math.nan) for x in NODES.tolist()]
        if away_from_zero(vals, self.floor):
            return True
        return all(x in known for x in HALVES.tolist()) and all(
            away_from_zero([known[x] for x in half.tolist()], self.floor) for half in (HALVES[:DEG + 1], HALVES[DEG + 1:]))

    def step_roots(self, qa, qb, known=None) -> list:
        """The points of the step p(τ) = onto(qa + τ (qb − qa)), τ in [0, 1], where the force along
        it, g(τ) = t(τ)·f(p(τ)) (t the chord's direction projected on the joints' tangent at p),
        has a root or a touch: all_roots' sign analysis of g's Chebyshev interpolant (one cell of
        degree DEG, halved where not resolved to ``floor``), never the signs at the ends alone.
        A part of the step where g cannot be evaluated (off the joints) starts Newton at its middle.
        ``known``: {τ: g(τ)} already evaluated (:meth:`first_cells`)."""
        d = qb - qa
        known = known or {}

        def point(x):
            p = self._onto(qa + x * d)
            t = None if p is None else self._tangent(p, d)
            return math.nan if t is None else float(t @ self.forces(p))

        def one(x):
            try:
                return point(x)
            except (np.linalg.LinAlgError, NumericalError):   # joints not finite there, or off a curve's
                return math.nan                                # ends: not on them (as along gives)

        def fresh(taus):
            if len(taus) <= 2:                  # Brent's points, a cell's critical points: the plain forms
                return np.array([one(float(x)) for x in taus])
            try:
                return self.along(qa + taus[:, None] * d, d)
            except np.linalg.LinAlgError:       # dependent rows somewhere: one point at a time (least squares)
                return np.array([point(float(x)) for x in taus])

        def g(taus):
            taus = np.atleast_1d(np.asarray(taus, dtype=float))
            out = np.array([known.get(x, math.nan) for x in taus.tolist()])
            new = np.array([x not in known for x in taus.tolist()], dtype=bool)
            if np.any(new):
                out[new] = fresh(taus[new])
            return out

        floor = self.floor
        if self.clear(known):
            return []
        roots, touches, bad = all_roots(g, 0.0, 1.0, cells=1, deg=DEG, floor=floor, budget=BUDGET)
        return [self._onto(qa + x * d) for x in roots + touches + bad]

    def along(self, Q, d) -> np.ndarray:
        """g at the chord points Q (k, n), all at once: each placed on the joints by the minimum-norm
        Gauss–Newton of :meth:`_onto` (stacked), then t·f with t the chord direction d (one for
        all, or one a row) projected on the joints' tangent there (NaN where a point does not
        reach the joints, or leads off a curve's ends: those points one at a time)."""
        try:
            return self._along(Q, d)
        except NumericalError:
            Q = np.atleast_2d(np.asarray(Q, dtype=float))
            D = np.broadcast_to(np.asarray(d, dtype=float), Q.shape)
            out = np.full(len(Q), np.nan)
            for i in range(len(Q)):
                try:
                    out[i] = self._along(Q[i:i + 1], D[i:i + 1])[0]
                except NumericalError:
                    pass
            return out

    def _along(self, Q, d) -> np.ndarray:
        s, sc = self.s, self.scale
        Q = np.array(Q, dtype=float)
        ok = np.ones(len(Q), dtype=bool)
        if s.m:
            td = s.at_times(np.zeros(len(Q)))
            act = np.arange(len(Q))
            for _ in range(30):
                X = s.stack(Q[act])
                ph = s.phi_many(X, [x[act] for x in td])
                done = np.max(np.abs(ph), axis=1) <= 1e-13 * self.L
                act, ph = act[~done], ph[~done]
                if not act.size:
                    break
                Js = s.jac_many(s.stack(Q[act])) * sc
                Q[act] -= (np.swapaxes(Js, 1, 2) @ np.linalg.solve(Js @ np.swapaxes(Js, 1, 2), ph[:, :, None]))[:, :, 0] * sc
            ok[act] = False
        return self.forces_along(Q, d, ok)

    def forces_along(self, Q, d, ok) -> np.ndarray:
        """t·f at the points Q of the joints (rows), t the direction d (one for all, or one a row)
        projected on the joints' tangent there (NaN where not ``ok`` or the projection vanishes)."""
        s, sc = self.s, self.scale
        if s.m:
            Js = s.jac_many(s.stack(Q)) * sc
            ts = np.broadcast_to(np.asarray(d) / sc, Q.shape)[:, :, None]
            T = (ts - np.swapaxes(Js, 1, 2) @ np.linalg.solve(Js @ np.swapaxes(Js, 1, 2), Js @ ts))[:, :, 0]
        else:
            T = np.broadcast_to(np.asarray(d) / sc, Q.shape)
        nrm = np.linalg.norm(T, axis=1)
        ok &= np.all(np.isfinite(Q), axis=1) & (nrm >= 1e-12)
        out = np.full(len(Q), np.nan)
        k = np.nonzero(ok)[0]
        out[k] = np.einsum("ki,ki->k", T[k] / nrm[k, None] * sc, self.forces_many(Q[k]))
        return out


NODES = 0.5 + 0.5 * np.polynomial.chebyshev.chebpts1(DEG + 1)    # all_roots' first cell [0, 1]
#: the nodes of its two halves [0, ½] and [½, 1] (all_roots' m + h x of each, the same doubles)
HALVES = np.concatenate([0.25 + 0.25 * np.polynomial.chebyshev.chebpts1(DEG + 1),
                         0.75 + 0.25 * np.polynomial.chebyshev.chebpts1(DEG + 1)])
FIRST = np.concatenate([NODES, [0.0, 1.0]])     # a step's first evaluation: the first cell and the ends
SECOND = np.concatenate([HALVES, [0.5]])        # a first cell not resolved: its halves and their common end
#: (c = COEF @ g(NODES): the Chebyshev coefficients of g's interpolant on [0, 1], all_roots' own)
COEF = np.polynomial.chebyshev.chebvander(2 * NODES - 1, DEG).T * np.r_[1.0, np.full(DEG, 2.0)][:, None] / (DEG + 1)


def _resolution(y, c, floor: float) -> float:
    """all_roots' resolution of an interpolant with coefficients c of the values y."""
    return max(1e-13 * float(np.max(np.abs(c))), 16 * EPS * float(np.max(np.abs(y))), floor)


def clear_of_zero(Y, floor: float) -> tuple[np.ndarray, np.ndarray]:
    """:func:`away_from_zero` of each row of Y (k, DEG + 1: g at a cell's nodes), all at once; and
    which rows are finite but not resolved (all_roots would halve that cell)."""
    fin = np.all(np.isfinite(Y), axis=1)
    Y = np.where(fin[:, None], Y, 0.0)
    C = Y @ COEF.T
    tol = np.maximum(np.maximum(1e-13 * np.max(np.abs(C), axis=1), 16 * EPS * np.max(np.abs(Y), axis=1)), floor)
    resolved = np.max(np.abs(C[:, -3:]), axis=1) <= tol
    clear = fin & resolved & (np.abs(C[:, 0]) - np.sum(np.abs(C[:, 1:]), axis=1) > 4 * tol)
    return clear, fin & ~resolved


def away_from_zero(ys, floor: float) -> bool:
    """True when g, known at the DEG + 1 NODES of a step, has no root and no touch on it, decided
    from its interpolant p = Σ c_k T_k alone: p resolved (all_roots' own test: the last three
    coefficients at the rounding of g, or below ``floor``) and |p| ≥ |c₀| − Σ_{k≥1} |c_k| (|T_k| ≤ 1)
    more than four times that resolution — then g keeps p's sign on the whole step and is nowhere
    within its rounding of 0: all_roots, which decides the same interpolant by g's signs at p's
    critical points, would find nothing there (its critical points and their values not needed)."""
    y = np.asarray(ys, dtype=float)
    if not np.all(np.isfinite(y)):
        return False
    c = COEF @ y
    tol = _resolution(y, c, floor)
    if float(np.max(np.abs(c[-3:]))) > tol:
        return False
    return abs(float(c[0])) - float(np.sum(np.abs(c[1:]))) > 4 * tol


def _row_solve(J, r) -> np.ndarray:
    """(J Jᵀ)⁻¹ r: J Jᵀ's LU (a quarter of a least-squares solve's cost), least squares where J's
    rows are dependent (redundant joints, a singular configuration).  Not finite: LinAlgError,
    as least squares would raise (after LAPACK printed to stdout)."""
    JJ = J @ J.T
    if not (np.all(np.isfinite(JJ)) and np.all(np.isfinite(r))):
        raise np.linalg.LinAlgError("the joints' equations are not finite on the way to an equilibrium")
    try:
        x = np.linalg.solve(JJ, r)
        if np.all(np.isfinite(x)):
            return x
    except np.linalg.LinAlgError:
        pass
    return np.linalg.lstsq(JJ, r, rcond=None)[0]


def _row_solve_many(J, R) -> np.ndarray:
    """:func:`_row_solve` of every row of the stacks J (k, m, n) and R (k, m) at once (one stacked
    LU); row by row (least squares, or LinAlgError, as there) when a matrix is singular or not finite."""
    JJ = J @ np.swapaxes(J, 1, 2)
    if np.all(np.isfinite(JJ)) and np.all(np.isfinite(R)):
        try:
            x = np.linalg.solve(JJ, R[:, :, None])[:, :, 0]
            if np.all(np.isfinite(x)):
                return x
        except np.linalg.LinAlgError:
            pass
    return np.array([_row_solve(J[k], R[k]) for k in range(len(J))]).reshape(R.shape)


def null_basis(J, n: int, indep: list[int]) -> np.ndarray:
    """Z with Z[indep] = I and J Z = 0 (the independent coordinates' own directions)."""
    dep = [k for k in range(n) if k not in indep]
    Z = np.zeros((n, len(indep)))
    Z[indep, range(len(indep))] = 1.0
    if dep and J.shape[0]:
        Z[dep] = -np.linalg.solve(J[:, dep], J[:, indep])
    return Z


def neutral_dirs(system, q, lam) -> np.ndarray:
    """The directions in q along which the reduced stiffness vanishes (a continuum of rest)."""
    n = system.n
    J = system.jac(q)
    if J.shape[0]:
        _, sv, Vt = np.linalg.svd(J)
        r = assembly.rank(J)
        Z = Vt[r:].T
    else:
        Z = np.eye(n)
    Hv = Z.T @ curvature.potential_hessian(system, q) @ Z
    Hc = Z.T @ curvature.rows_hessian(system, q, lam) @ Z
    K = Hv - Hc
    K = 0.5 * (K + K.T)
    w, U = np.linalg.eigh(K)
    tol = 1e-8 * max(float(np.linalg.norm(Hv, 2)) if Hv.size else 0.0,
                     float(np.linalg.norm(Hc, 2)) if Hc.size else 0.0, 1e-300)
    return Z @ U[:, np.abs(w) <= tol]


def _same(a, b, search, dirs) -> bool:
    """Whether b is the equilibrium a: the same configuration (angles by whole turns), or a moved
    along its neutral directions ``dirs`` (a continuum of rest).  A continuum that turns an angle
    as it moves (a wheel rolling along a floor) may reach b after more than a half turn: its
    step is then read from the other coordinates and the angles compared by whole turns."""
    d = (b - a) / search.scale
    wrapped = _turns(d, search.angles)
    if float(np.max(np.abs(wrapped), initial=0.0)) <= 1e-7:
        return True
    if not dirs.shape[1]:
        return False
    D = dirs / search.scale[:, None]
    c = np.linalg.lstsq(D, wrapped, rcond=None)[0]
    if float(np.max(np.abs(D @ c - wrapped), initial=0.0)) <= 1e-7:
        return True
    lengths = ~search.angles
    if not lengths.any() or assembly.rank(D[lengths]) < D.shape[1]:
        return False
    c = np.linalg.lstsq(D[lengths], d[lengths], rcond=None)[0]
    return float(np.max(np.abs(_turns(D @ c - d, search.angles)), initial=0.0)) <= 1e-7


def _turns(d, angles) -> np.ndarray:
    """d with its angle components by whole turns into [−π, π)."""
    return np.where(angles, (d + math.pi) % (2 * math.pi) - math.pi, d)


def _walks(S, froms) -> list[list]:
    """The starts of the paths along each free coordinate from each (q, its independent
    coordinates) of ``froms``: one list a configuration."""
    ways, cut = [], [0]
    for q, indep in froms:
        Z = null_basis(S.s.jac(q), S.n, indep)
        ways += [(q, Z[:, k]) for k in range(Z.shape[1])]
        cut.append(len(ways))
    got = S.walks(ways) if ways else []
    return [[x for w in range(a, b) for x in got[w]] for a, b in zip(cut[:-1], cut[1:])]


def _near_start(q, q0, angles) -> np.ndarray:
    """Each angle moved by whole turns to the value nearest the initial configuration's."""
    q = q.copy()
    q[angles] = q[angles] - 2 * math.pi * np.round((q[angles] - q0[angles]) / (2 * math.pi))
    return q


def find(system, q0, coords_idx: list[int], warn) -> list[tuple[np.ndarray, np.ndarray]]:
    """Every equilibrium reached: [(q, λ)], the one reached from the initial configuration first.

    The starts are taken in order (the initial configuration, the points of its paths, then the
    points of the paths from each new equilibrium), in rounds: Newton runs from all the starts
    queued at once (:meth:`Search.rests_from`), their results are read in the queue's order, and
    the paths from the round's new equilibria are walked together — the same equilibria, in the
    same order, as one start at a time."""
    S = Search(system, q0)
    starts = [q0] + _walks(S, [(q0, coords_idx)])[0]
    found: list[tuple[np.ndarray, np.ndarray, np.ndarray]] = []
    dropped: list[str] = []
    walked, i, full = 0, 0, False
    tried: set[bytes] = set()           # a start already run (the same doubles: the same result)
    while i < len(starts) and not full:
        batch: list[np.ndarray] = []
        new: list[tuple[np.ndarray, list[int]]] = []
        while i < len(starts) and (S.stacked or not batch):
            start, i = starts[i], i + 1
            if (key := np.asarray(start, dtype=float).tobytes()) not in tried:
                tried.add(key)
                batch.append(start)
        for start, got in zip(batch, S.rests_from(batch)):
            if got is None:
                continue
            q, lam = got
            q = _near_start(q, q0, S.angles)
            if any(_same(q, f[0], S, f[2]) for f in found):
                continue
            bad = _pulls(system, q, lam)
            found.append((q, lam, neutral_dirs(system, q, lam)))
            if bad:
                pos = ", ".join(f"{nm} = {x:.6g}" for nm, x in zip(system.names, q))
                dropped.append(f"at {pos}: {bad}")
            if walked < MAX_WALKED:           # the paths from each new equilibrium reach the others
                walked += 1
                new.append((q, assembly.independent(system.jac(q), system.n)))
            if len(found) >= MAX_FOUND:
                warn(f"the equilibrium search stopped after {MAX_FOUND} equilibria")
                full = True
                break
        if not full:
            starts += [x for got in _walks(S, new) for x in got]
    if len(dropped) == len(found) and not any("rests on its peg" in d for d in dropped):
        warn("no rest configuration found: the loads cannot be held by the joints at rest anywhere the search "
             "reached (from the given configuration and along each free coordinate)")
    if dropped:
        warn("equilibria that are not rest configurations (a one-sided joint would not hold, a body would be "
             "through a surface, or a string would rest on a peg) are left out: "
             + "; ".join(dict.fromkeys(dropped)))
    return [(q, lam) for q, lam, d in found if not _pulls(system, q, lam)]


def _pulls(system, q, lam) -> str | None:
    """Why a one-sided joint does not hold at this equilibrium (None when every one holds)."""
    v = np.zeros(system.n)
    for e in system.elements:
        if e.kind in ("contact", "rolls") and not getattr(e.surface, "curved", False) \
                and not getattr(e.surface, "carried", False):       # (a carried line moves: its own gap holds)
            body = e.P.body if e.kind == "contact" else e.body_point.body
            if body is not None:
                i = body.index
                side = float(np.array(e.surface.n) @ (np.array([q[i[0]], q[i[1]]]) - np.array(e.surface.origin)))
                if side < -1e-9 * assembly.length_scale(q, system):
                    return f"{body.name!r} would be through the surface {e.surface.name!r} (its centre on the far side)"
    for i, e in enumerate(system.elements):
        for k, p in enumerate(getattr(e, "pegs", ())):
            B, A = e.ends()
            off, place = e._offset(A, B, p, q)
            if 0 < place < 1 and abs(off) <= e._radius(k) + 1e-9 * assembly.length_scale(q, system):
                return (f"the string {e.name!r} rests on its peg at [{p.p[0]:g}, {p.p[1]:g}] (small swings turn about "
                        "the peg one way and about the string's end the other: not one linear system)")
        for what, g in e.watch(system.lam_of(lam, i), q, v, 0.0):
            if what in ("sticks", "wraps", "unwraps", "reaches", "turns"):   # (a peg's side, a cord's reach: geometry)
                continue
            if g < -1e-9 * max(1.0, float(np.max(np.abs(lam), initial=0.0))):
                return f"the joint {e.name!r} {what}"
    return None
