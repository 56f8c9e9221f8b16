"""The `top`'s integrator next to the vertical (the ODE route's quaternion form; away from it
the route integrates the reduced equations of :mod:`dyncli.topics.top.reduced`): the motion
of the heavy symmetric top (notes §38, equations 38.18) with continuous Euler angles.

Numerical route (numpy; scipy imported lazily by the runner, :mod:`dyncli.runner`)
-----------------------------------------------------------------------
The 3-1-3 Euler angles are singular at θ = 0 and θ = π, so the motion is
integrated in a non-singular representation: the unit quaternion q of the
body basis e'_i (fixed ← body) and the body components w of ω, with Euler's
equations for the symmetric top about O,

    I11 ẇ1 = (I11 − I33) w2 w3 + mgL γ2,   I11 ẇ2 = (I33 − I11) w3 w1 − mgL γ1,
    I33 ẇ3 = 0 (38.18c),                   q̇ = ½ q ⊗ (0, w),

where γ = (sinθ sinφ, sinθ cosφ, cosθ) are the body components of e3 and
the gravity moment is M_O = L e'_3 × (−mg e3) (38.17).  This is (38.18)
written on the body basis.  With q = (cos(θ/2)cos(σ/2), sin(θ/2)cos(δ/2),
sin(θ/2)sin(δ/2), cos(θ/2)sin(σ/2)), σ = ψ + φ, δ = ψ − φ, the angles are
read back without loss of precision: θ = 2 atan2(|(q1,q2)|, |(q0,q3)|),
ψ ≡ atan2(q3,q0) + atan2(q2,q1), φ ≡ atan2(q3,q0) − atan2(q2,q1) (mod 2π).

The spin is taken out exactly: ω3 is constant (38.18c), so q = p ⊗ r(ω3 t) with r the
rotation by ω3 t about e'_3, and the spin-free frame p (same axis e'_3, no spin about it)
obeys, with v = (v1, v2) the components of ω⊥ on p,

    ṗ = ½ p ⊗ (0, v1, v2, 0),   I11 v̇1 = −I33 ω3 v2 + mgL γ2,   I11 v̇2 = I33 ω3 v1 − mgL γ1

(γ now on p).  This is what is integrated (state (p, v1, v2, ω3)); ψ and θ of q are those of p
and φ = φ_p + ω3 t, so the steps follow the nutation and precession, not the spin.  The
energy and H·e3 have the same form on p, and ω⊥, φ_p give the same rates and reaction as the
body components and φ (all are rotations about e'_3).

Continuous (unwrapped) ψ and φ are tracked along the trajectory: between two
points the horizontal projection of the axis e'_3 moves at most ℓ = Δt·W⊥
(W⊥ = bound of |ω⊥| from the energy integral); when ℓ < sinθ/2 at both ends
the projection stays at a distance ≥ (sinθa + sinθb − ℓ)/2 ≥ 3/4 min sinθ from the
vertical, so |Δψ| ≤ ℓ/(3/4 min sinθ) ≤ 2/3 rad, and it is read as a principal value,
otherwise the interval is bisected on the integrator's dense output.  The
spin φ follows from ψ and σ (or δ near θ = π), its branch from
Δφ ≈ ω3 Δt − cosθ̄ Δψ (error ≤ max|cosθ − cosθ̄| ∫|ψ̇|dt ≤ ℓ · 2/3 < 1/3 rad there;
the tracker follows φ_p of the spin-free frame, where ω3 = 0, and φ = φ_p + ω3 t).  Where the
axis passes (numerically) through the vertical, ψ and φ are individually
undefined; the tracker keeps them continuous and says so.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli import ode, runner
from dyncli.errors import NumericalError
from dyncli.topics.top.kinematics import S_TINY, Top, half_angles, wrap_angle

#: deepest bisection of one step when tracking ψ near the poles
MAX_DEPTH = 60
MAX_SPLITS = 256        # interpolant evaluations per step for the angle tracker



class _Tracker:
    """Continuous ψ, φ along the trajectory (see the module docstring)."""

    def __init__(self, psi, phi, q, W3, Wp):
        self.psi, self.phi = psi, phi
        self.ang = half_angles(q)
        self.W3, self.Wp = W3, Wp
        self.ambiguous: list[float] = []

    def _seg(self, ta, anga, psi_a, phi_a, tb, angb, dense, depth):
        sa, sb = anga[1], angb[1]
        ell = (tb - ta) * self.Wp
        smin = min(sa, sb)
        if (not (ell < 0.5 * smin) and smin >= S_TINY and depth < MAX_DEPTH and self._splits > 0
                and dense is not None and tb > ta):
            tm = 0.5 * (ta + tb)
            if ta < tm < tb:
                self._splits -= 1
                angm = half_angles(dense(tm))
                psi_m, phi_m = self._seg(ta, anga, psi_a, phi_a, tm, angm, dense, depth + 1)
                return self._seg(tm, angm, psi_m, phi_m, tb, angb, dense, depth + 1)
        _, _, cb, ab, bb = angb
        if sb < S_TINY:
            psi_b = psi_a              # ψ undefined at the pole: keep it, φ carries ψ ± φ
            if ell > 0 and sa >= S_TINY:
                self.ambiguous.append(tb)
        else:
            if not (ell < 0.5 * smin) and sa >= S_TINY:
                self.ambiguous.append(tb)
            psi_b = psi_a + wrap_angle(ab + bb - psi_a)
        pred = phi_a + self.W3 * (tb - ta) - (psi_b - psi_a) * 0.5 * (anga[2] + cb)
        phi_w = (2.0 * ab - psi_b) if cb >= 0 else (psi_b - 2.0 * bb)
        return psi_b, pred + wrap_angle(phi_w - pred)

    def advance(self, ta, tb, qb, dense):
        angb = half_angles(qb)
        # bisection is bounded per step: near the pole (sin θ/2 ~ 1e-9) the
        # halving would otherwise build a tree of ~ℓ/sin θ leaves; past the
        # bound the branch of ψ is marked ambiguous (a warning), not hunted
        self._splits = MAX_SPLITS
        self.psi, self.phi = self._seg(ta, self.ang, self.psi, self.phi, tb, angb, dense, 0)
        self.ang = angb
        return self.psi, self.phi, angb


def _unit(q):
    q = np.asarray(q, dtype=float)
    return q / math.sqrt(float(q @ q))


class Run:
    """One integration: states at the requested (sorted) times."""

    def __init__(self, n):
        self.psi = np.zeros(n)
        self.theta = np.zeros(n)
        self.phi = np.zeros(n)      # φ = φ_p + ω3 t
        self.phi_p = np.zeros(n)    # spin angle of the spin-free frame p
        self.w = np.zeros((n, 3))   # components of ω on p: (v1, v2, ω3)
        self.drift = (0.0, 0.0, 0.0)
        self.ambiguous: list[float] = []
        self.steps = 0
        self.nfev = 0


class _Recorder:
    """Drift of the invariants along the run and the states stored at the requested times."""

    def __init__(self, top: Top, y0, run: Run, tr: _Tracker):
        self.top, self.run, self.tr = top, run, tr
        self.E0, self.H0, self.W3 = top.invariants(y0[:4], y0[4:])
        self.dE = self.dH = self.dW = 0.0

    def __call__(self, k, t, y):
        E, H, w3 = self.top.invariants(y[:4], y[4:])
        self.dE, self.dH, self.dW = (max(self.dE, abs(E - self.E0)), max(self.dH, abs(H - self.H0)),
                                     max(self.dW, abs(w3 - self.W3)))
        if k is not None:
            run, tr = self.run, self.tr
            run.psi[k], run.phi_p[k], run.theta[k] = tr.psi, tr.phi, tr.ang[0]
            run.phi[k] = tr.phi + self.W3 * t
            run.w[k] = y[4:]


def integrate(top: Top, y0, psi0, phi0, times, *, rtol, atol, method, Wp, scales, max_steps=None,
              max_step=math.inf):
    """Integrate from y0 (quaternion + body ω at t = 0, where the spin-free frame p
    coincides with the body) to the sorted ``times``.

    Step budget :class:`dyncli.ode.Budget`: refused (NumericalError) as soon
    as it is clear that the run needs more than ``max_steps`` steps (default
    ``ode.MAX_STEPS``)."""
    budget = ode.Budget(max_steps)

    n = len(times)
    run = Run(n)
    Es, Hs, Ws = scales
    cls = runner.solver_class(method)          # the runner's one method map ("projected": DOP853)
    rtol = runner.floor_rtol(rtol)
    # the transverse rates ω⊥ get atol relative to their own bound, not to |ω| (the spin)
    atol_v = np.array([atol] * 4 + [atol * (Wp if Wp > 0 else Ws)] * 2 + [atol * Ws])
    # p has no spin about its axis: the tracker follows ψ and φ_p, φ = φ_p + ω3 t
    tr = _Tracker(psi0, phi0, y0[:4], 0.0, Wp * (1.0 + 1e-6) + 1e-300)
    record = _Recorder(top, y0, run, tr)

    k = 0
    while k < n and times[k] == 0.0:
        record(k, 0.0, y0)
        run.psi[k], run.phi[k], run.phi_p[k] = psi0, phi0, phi0
        k += 1
    T = times[-1] if n else 0.0
    if k < n:
        budget.leg(0.0, T)
        solver = cls(ode.finite(top.rhs_spinfree), 0.0, np.array(y0, dtype=float), T, rtol=rtol, atol=atol_v,
                     max_step=max_step)
        _steps(solver, run, tr, record, budget, times, k, method, math.sqrt(top.A) * Ws)
    run.drift = (record.dE / Es if Es > 0 else 0.0, record.dH / Hs if Hs > 0 else 0.0,
                 record.dW / Ws if Ws > 0 else 0.0)
    run.ambiguous = tr.ambiguous
    return run


def _steps(solver, run, tr, record, budget, times, k, method, S):
    """Step ``solver`` to the end, recording the requested times from index ``k`` on (dense
    output between steps; projection onto the invariants with accuracy.method projected)."""
    top, E0, H0, W3 = record.top, record.E0, record.H0, record.W3
    projected = method == "projected"
    n = len(times)
    t_prev = 0.0
    for _ in ode.steps(solver, budget, method):
        run.steps += 1
        tb = solver.t
        dense, dense_q = _dense(solver)
        while k < n and times[k] <= tb:
            tk = times[k]
            if tk == tb:
                yk = np.array(solver.y, dtype=float)
            else:
                yk = np.asarray(dense(tk), dtype=float)
            yk = top.project(yk, E0, H0, W3, S) if projected else _normq(yk)
            tr.advance(t_prev, tk, yk[:4], dense_q)
            t_prev = tk
            record(k, tk, yk)
            k += 1
        yb = top.project(solver.y, E0, H0, W3, S) if projected else _normq(solver.y)
        if tb > t_prev:
            tr.advance(t_prev, tb, yb[:4], dense_q)
            t_prev = tb
        if projected:
            solver.y = yb
            solver.f = solver.fun(solver.t, yb)
        record(None, tb, yb)
        if k >= n:
            break
    run.nfev = solver.nfev
    if k < n:  # pragma: no cover - the solver ends exactly at T
        raise NumericalError(f"the integrator stopped at t = {solver.t:.6g} s before t = {times[-1]:g} s")


def _dense(solver):
    """The step's dense output (built on first use) and its unit-quaternion part."""
    cache = []

    def dense(t):
        if not cache:
            cache.append(ode.dense_output(solver))
        return cache[0](t)

    def dense_q(t):
        """Unit quaternion part of the dense output (the tracker's bisection)."""
        return _unit(np.asarray(dense(t), dtype=float)[:4])

    return dense, dense_q


def _normq(y):
    y = np.array(y, dtype=float)
    y[:4] /= math.sqrt(float(y[:4] @ y[:4]))
    return y


def dense_run(top: Top, y0, psi0, phi0, T, *, rtol, atol, method, Wp, scales, max_steps=None, max_step=math.inf):
    """The quaternion form's motion from 0 to T as one run's dense output, for the ``find`` search:
    (the steps' ends, ``states(ts)``, the reported ψ, θ, φ, ψ̇, θ̇, φ̇, R at any times of [0, T] as
    lists).  The run is :func:`integrate`'s (the same stepper, tolerances, cap and projection);
    each step keeps its interpolant and the tracker's ψ, φ_p at its start, and a time inside it is
    read as :func:`integrate` reads a requested time: the state from the interpolant (normalised or
    projected), ψ and φ_p carried from the step's start by the tracker (bisected on the step's
    interpolant where the axis moves far beside the vertical) — so every result is a smooth
    function of the step's polynomial between two ends."""
    from dyncli.topics.top.derived import rates, reaction

    budget = ode.Budget(max_steps)
    Es, Hs, Ws = scales
    cls = runner.solver_class(method)
    rtol = runner.floor_rtol(rtol)
    atol_v = np.array([atol] * 4 + [atol * (Wp if Wp > 0 else Ws)] * 2 + [atol * Ws])
    Wt = Wp * (1.0 + 1e-6) + 1e-300
    tr = _Tracker(psi0, phi0, y0[:4], 0.0, Wt)
    E0, H0, W3 = top.invariants(y0[:4], y0[4:])
    S = math.sqrt(top.A) * Ws
    projected = method == "projected"

    def settle(y):
        return top.project(y, E0, H0, W3, S) if projected else _normq(y)

    budget.leg(0.0, T)
    solver = cls(ode.finite(top.rhs_spinfree), 0.0, np.array(y0, dtype=float), T, rtol=rtol, atol=atol_v,
                 max_step=max_step)
    steps, t_prev = [], 0.0
    for _ in ode.steps(solver, budget, method):
        tb = float(solver.t)
        interp = ode.dense_output(solver)
        dense_q = (lambda t, d=interp: _unit(np.asarray(d(t), dtype=float)[:4]))
        yb = settle(solver.y)
        steps.append((t_prev, interp, dense_q, tr.psi, tr.phi, tr.ang))
        tr.advance(t_prev, tb, yb[:4], dense_q)
        t_prev = tb
        if projected:
            solver.y = yb
            solver.f = solver.fun(solver.t, yb)
    ends = np.array([0.0] + [s[0] for s in steps[1:]] + [t_prev])
    y0 = np.array(y0, dtype=float)

    def states(ts) -> dict:
        ts = np.asarray(ts, dtype=float).reshape(-1)
        n = ts.size
        psi, theta, phi_p = np.empty(n), np.empty(n), np.empty(n)
        w = np.empty((n, 3))
        k = np.clip(np.searchsorted(ends, ts, side="left") - 1, 0, len(steps) - 1)
        scratch = _Tracker(psi0, phi0, y0[:4], 0.0, Wt)
        for j in np.unique(k).tolist():
            sel = np.flatnonzero(k == j)
            ta, interp, dense_q, psi_a, phi_a, ang_a = steps[j]
            Y = np.asarray(interp(ts[sel]), dtype=float).reshape(len(y0), -1)
            for i, col in zip(sel.tolist(), Y.T):
                if ts[i] == 0.0:                # the initial state as given
                    y, psi[i], phi_p[i] = y0, psi0, phi0
                    theta[i] = half_angles(y0[:4])[0]
                else:
                    y = settle(col)
                    ang = half_angles(y[:4])
                    scratch._splits = MAX_SPLITS
                    psi[i], phi_p[i] = scratch._seg(ta, ang_a, psi_a, phi_a, float(ts[i]), ang, dense_q, 0)
                    theta[i] = ang[0]
                w[i] = y[4:]
        psd, thd, phd, _ = rates(top, theta, phi_p, w)
        R = reaction(top, theta, phi_p, w)
        out = {k_: (np.asarray(a, dtype=float) + 0.0).tolist() for k_, a in
               (("psi", psi), ("theta", theta), ("phi", phi_p + W3 * ts), ("psi_dot", psd), ("theta_dot", thd),
                ("phi_dot", phd))}
        out["R"] = (np.asarray(R, dtype=float) + 0.0).tolist()
        return out
    return ends.tolist(), states
