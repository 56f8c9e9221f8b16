"""The ``quadrature`` route of a scene: one degree of freedom with an energy integral (34.20).

Every load is conservative (gravity, springs, constant forces and couples: a potential each),
no joint dissipates (smooth contacts, rolling, cords, links) and nothing is driven, so along
the one independent coordinate s (a body's angle or coordinate)

    ½ M(s) ṡ² + V(s) = E,   M(s) = Nᵀ M N,   ṡ² = K(s) = 2 (E − V(s)) / M(s),

with N(s) the direction the joints allow (N_s = 1) and q(s) the assembled positions.  Time is
a quadrature with turning points (dyncli.energy_route); K' = 2 s̈ comes from the equations of
motion themselves (s̈ is even in ṡ), so a double root (a separatrix) is classified exactly.
The positions at each s are placed by Newton on the joints, continued from the nearest s
already placed.
"""

from __future__ import annotations

import bisect
import math

import numpy as np

from dyncli import cputime
from dyncli.errors import InputError, NumericalError

from . import motion

EPS = float(np.finfo(float).eps)


def applies(system) -> str | None:
    """None when the route applies (decided from the elements' kinds), else why not."""
    for e in system.elements:
        if e.kind == "drive":
            return "a drive prescribes a motion in time"
        if getattr(e, "mode", None) in ("slide", "slip") and getattr(e, "mu_k", None):
            return f"the joint {e.name!r} slides with friction"
        if getattr(e, "pegs", None):
            return f"the string {e.name!r} catches pegs (the length it swings on changes there)"
    for ld in system.loads:
        if ld.kind == "damper":
            return f"{ld.label} dissipates"
        if ld.kind in ("force", "torque") and not ld.constant:
            return f"{ld.label} depends on time"
        if ld.kind == "spring" and ld.one_sided:
            return f"{ld.label} is one-sided"
    return None


def _solve(A, b):
    """A square system by LU, a rectangular one (more rows: consistent) by least squares."""
    if A.shape[0] == A.shape[1]:
        return np.linalg.solve(A, b)
    return np.linalg.lstsq(A, b, rcond=None)[0]


class Manifold:
    """q(s): the positions the joints allow with the independent coordinate q_i = s."""

    def __init__(self, system, q0, i: int):
        self.s, self.i = system, i
        self.others = [k for k in range(system.n) if k != i]
        self.keys, self.qs = [float(q0[i])], [q0.copy()]
        self._dirs: dict[int, tuple] = {}
        self.step = 0.05 if system.names[i].startswith("angle.") else 0.02 * max(1.0, float(np.max(np.abs(q0))))

    def _newton(self, q, s_val, iters: int = 12, N=None, s_from: float = 0.0):
        """Newton on the joints with q_i = s_val, from q moved along the tangent N (when given)."""
        q = q + N * (s_val - s_from) if N is not None else q.copy()
        q[self.i] = s_val
        tol = 8 * EPS * max(1.0, float(np.max(np.abs(q))))
        for _ in range(iters):
            ph = self.s.phi(q, 0.0)
            if float(np.max(np.abs(ph), initial=0.0)) <= tol:
                return q
            J = self.s.jac(q)[:, self.others]
            q[self.others] -= _solve(J, ph)
        return None

    def _reach(self, q, s_from: float, s_val: float, depth: int = 0, N=None):
        """Newton from the placed q at s_from straight to s_val (predicted along the tangent N
        there, when given: one or two iterations); halving the way when it does not converge
        (the branch is kept)."""
        got = self._newton(q, s_val, N=N, s_from=s_from) if N is not None else None
        if got is None:
            got = self._newton(q, s_val)
        if got is not None:
            return got
        if depth > 30:
            name = self.s.names[self.i]
            raise InputError(f"the quadrature route follows the motion along {name}, and the joints cannot be placed "
                             f"at {name} = {s_val:.10g}: the path turns back along that coordinate there (a circle's "
                             "side, where x stops growing), or the mechanism locks; use method auto (the ODE route)",
                             "accuracy.method")
        mid = 0.5 * (s_from + s_val)
        q_mid = self._reach(q, s_from, mid, depth + 1)
        return self._reach(q_mid, mid, s_val, depth + 1)

    def q(self, s_val: float) -> np.ndarray:
        if (limit := cputime.over()) is not None:
            raise NumericalError(f"the energy quadrature placed the joints to {self.s.names[self.i]} = {s_val:.6g} only "
                                 f"within the CPU budget of {limit:g} s (accuracy.max_cpu): solve it by the ODE route "
                                 "(accuracy.method: auto), or raise accuracy.max_cpu")
        k = bisect.bisect_left(self.keys, s_val)
        near = min((j for j in (k - 1, k) if 0 <= j < len(self.keys)), key=lambda j: abs(self.keys[j] - s_val))
        if self.keys[near] == s_val:
            return self.qs[near]
        s_from, q = self.keys[near], self.qs[near]
        if abs(s_val - s_from) > self.step:         # continued in short steps: the branch is kept
            n = math.ceil(abs(s_val - s_from) / self.step)
            if n > 64:
                q = self._reach(q, s_from, s_val)
            else:
                for m in range(1, n + 1):
                    q = self._reach(q, s_from + (s_val - s_from) * (m - 1) / n, s_from + (s_val - s_from) * m / n)
        else:
            q = self._reach(q, s_from, s_val, N=self.direction(q))
        if len(self.keys) < 20000:
            k = bisect.bisect_left(self.keys, s_val)
            self.keys.insert(k, float(s_val))
            self.qs.insert(k, q)
        return q

    def direction(self, q) -> np.ndarray:
        """N at the placed q (N_i = 1), kept for each q placed (a state's speed and its velocities
        read it twice)."""
        got = self._dirs.get(id(q))
        if got is not None and got[0] is q:
            return got[1]
        J = self.s.jac(q)
        N = np.zeros(self.s.n)
        N[self.i] = 1.0
        if J.size:
            N[self.others] = _solve(J[:, self.others], -J[:, self.i])
        if len(self._dirs) > 40000:
            self._dirs.clear()
        self._dirs[id(q)] = (q, N)      # (q kept alive with it: its id is not reused)
        return N


class Work:
    """W(s) = ∫_{s0}^{s} Q(σ) dσ = V(s0) − V(s), Q = Nᵀ f the generalized force of the loads:
    an 8-point Gauss–Legendre sum over cells of the manifold's step from s0 (each cell's sum
    kept), so that E − V(s) = T0 + W(s) carries no cancellation near s0 — a release close to an
    unstable equilibrium, where V(s) − V(s0) is far below V's own rounding."""

    def __init__(self, man, system, s0: float):
        self.man, self.s, self.s0, self.h = man, system, s0, man.step
        self.x, self.w = np.polynomial.legendre.leggauss(8)
        self.cells: dict[int, tuple[float, np.ndarray, float, float]] = {}   # ∫, antiderivative, centre, half-width
        self.sums: dict[int, list[float]] = {1: [0.0], -1: [0.0]}   # Σ of the first k whole cells, each side

    def Q(self, x: float) -> float:
        q = self.man.q(x)
        f, _ = self.s.applied(q, np.zeros(self.s.n), 0.0)
        return float(self.man.direction(q) @ f)

    def _cell(self, key: int):
        """The cell's Legendre series of Q (from its 8 Gauss nodes): ∫ over the whole cell and
        the coefficients of the antiderivative for a part of it."""
        got = self.cells.get(key)
        if got is None:
            sign = 1.0 if key > 0 else -1.0
            a = self.s0 + sign * (abs(key) - 1) * self.h
            b = a + sign * self.h
            c, r = 0.5 * (a + b), 0.5 * (b - a)
            vals = np.array([self.Q(c + r * xk) for xk in self.x])
            coef = np.polynomial.legendre.legfit(self.x, vals, 7)
            anti = np.polynomial.legendre.legint(coef, lbnd=-1.0)
            got = self.cells[key] = (float(r * np.dot(self.w, vals)), anti, c, r)
        return got

    def __call__(self, x: float) -> float:
        d = x - self.s0
        if d == 0:
            return 0.0
        sign = 1 if d > 0 else -1
        k_full = int(abs(d) // self.h)
        sums = self.sums[sign]
        while len(sums) <= k_full:      # (the same sum in the same order as cell by cell)
            sums.append(sums[-1] + self._cell(sign * len(sums))[0])
        total = sums[k_full]
        if abs(d) > k_full * self.h:
            _, anti, c, r = self._cell(sign * (k_full + 1))
            total += r * float(np.polynomial.legendre.legval((x - c) / r, anti))
        return total


class _Turn:
    """A motion along an angle that goes a whole turn from its start without a turning point,
    on joints that repeat after a whole turn (a pendulum whirling over the top), goes round for
    ever along them: the quadrature of the energy integral between turning points has none to
    find (the march would follow the angle out to 10³¹ rad, placing the joints and summing the
    work over every turn).  Refused (accuracy.method), once the march has passed a whole turn
    (K > 0 all the way, decided by its own root search), where the positions a turn on equal
    those of the start (every angle a whole number of turns on, every other coordinate the same,
    to 1e-9 of the scene's size)."""

    def __init__(self, man, system, i: int, q0):
        self.man, self.s, self.i, self.q0 = man, system, i, np.asarray(q0, float)
        self.periodic: bool | None = None

    def check(self, x: float) -> None:
        s0 = float(self.q0[self.i])
        if abs(x - s0) <= 2 * math.pi:
            return
        if self.periodic is None:
            q1 = self.man.q(s0 + math.copysign(2 * math.pi, x - s0))
            d = q1 - self.q0
            angles = np.array([nm.startswith("angle.") for nm in self.s.names])
            d = np.where(angles, (d + math.pi) % (2 * math.pi) - math.pi, d)
            scale = max(1.0, float(np.max(np.abs(self.q0[~angles]), initial=0.0)))
            self.periodic = bool(np.max(np.abs(d)) <= 1e-9 * scale)
        if self.periodic:
            raise InputError(f"the quadrature route needs turning points, and along its joints this motion goes "
                             f"round: {self.s.names[self.i]} passes a whole turn from its start with none, on joints "
                             "that repeat every turn (a rotation); use method auto (the ODE route, which also finds "
                             "the events on the way)", "accuracy.method")


def run(scene, traj, t_end: float, acc) -> object:
    """The trajectory by the energy quadrature (the caller decided that it applies: one degree
    of freedom, :func:`applies`)."""
    from dyncli.energy_route import EnergyMotion

    s = scene.system
    i = s.names.index(scene.coords[0])
    man = Manifold(s, scene.q0, i)
    N0 = man.direction(scene.q0)
    sd0 = float(scene.v0[i])
    M0 = float(N0 @ (s.mass * N0))
    T0 = 0.5 * M0 * sd0 * sd0
    W = Work(man, s, float(scene.q0[i]))

    turn = _Turn(man, s, i, scene.q0) if s.names[i].startswith("angle.") else None

    def K(x: float) -> float:
        if turn is not None:
            turn.check(float(x))
        q = man.q(float(x))
        N = man.direction(q)
        return 2.0 * (T0 + W(float(x))) / float(N @ (s.mass * N))

    def K_prime(x: float) -> float:          # ½ K' = s̈ on the motion (even in ṡ)
        q = man.q(float(x))
        N = man.direction(q)
        k = max(K(x), 0.0)
        a, _, _ = s.solve(q, N * math.sqrt(k), 0.0)
        return 2.0 * float(a[i])

    em = EnergyMotion(K, float(scene.q0[i]), sd0, K_prime=K_prime, rtol=acc.rtol, max_steps=acc.max_steps)
    breaks = sorted({0.0, t_end, *[b for b in em.breaks(t_end) if 0 < b < t_end]})

    seen: dict[float, tuple] = {}

    def fn(t):
        got = seen.get(t)
        if got is None:
            x, xd = em.state(float(t))
            q = man.q(x)
            got = (q, man.direction(q) * xd, 0.0)
            if len(seen) < 100_000:
                seen[t] = got
        return got

    modes = motion.modes_of(s)
    for a, b in zip(breaks[:-1], breaks[1:]):
        traj.add(motion.Piece(a, b, fn, modes))
    if len(breaks) == 1:
        traj.add(motion.Piece(0.0, 0.0, fn, modes))
    traj.method = "quadrature"
    traj.energy, traj.energy_index = em, i
    for w in em.warnings:
        scene.warnings.append(w)
    return traj
