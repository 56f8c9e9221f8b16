"""The `top`'s ODE route away from the vertical: the reduced equations (notes §38) in the
3-1-3 Euler angles.

With the two momentum integrals p_ψ = H_O·e3 = I11 ψ̇ sin²θ + I33 ω3 cosθ and ω3 = ψ̇ cosθ + φ̇
(38.18b, 38.18c) held exactly, the motion is the state (θ, θ̇, ψ, φ) with

    ψ̇ = (b − c cosθ)/sin²θ,   φ̇ = ω3 − ψ̇ cosθ,
    θ̈ = sinθ (ψ̇ (ψ̇ cosθ − c) + mgL/I11)                 (38.18a)

(b = p_ψ/I11, c = I33 ω3/I11): four states, the right-hand side in plain floats, the
angles continuous by construction (no unwrapping) and ψ̇, φ̇ from the integrals.  It is
used when the axis stays away from the vertical over the whole nutation (the turning
points are known beforehand: :func:`usable`); next to θ = 0 or π, where 1/sin²θ is
singular, the route integrates the spin-free quaternion form
(:mod:`dyncli.topics.top.integrator`) instead.

Step size: DOP853's (and RK45's) error estimator is only asymptotically right; with steps
of h ≈ 1-1.5 rad of the nutation (h·W ≈ 1, W the fastest rate) it underestimates, and the
error of the nutating top of tests/topics/top at rtol 1e-6 was 35x rtol where rtol 1e-5 gave 3x.  The step is capped at
h ≤ 1/W whenever the axis nutates (θ_max > θ_min), which keeps the global error within a
few rtol at loose tolerances; in steady precession (a fixed point of 38.18a) the cap is
not needed and not applied.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli import ode, runner
from dyncli.topics.top.derived import reaction
from dyncli.topics.top.kinematics import EPS, Top

#: the transverse rates θ̇, ψ̇ count relative to at least FLOOR |ω⊥|max (the error_estimate), and
#: their tolerances are no tighter than that: in steady precession θ̇ ≡ 0 and its computed values
#: are the integrator's own error, ~0.01 rtol |ω⊥|max, no scale of their own
FLOOR = 0.1
#: the axis at least this far from the vertical (sinθ over the nutation) for the reduced form
S_MIN = 0.05


def usable(top: Top, th_min: float, th_max: float, omega3: float, b: float, Wp: float, Wfast: float,
           rtol: float) -> bool:
    """Whether the reduced form suits this motion: sinθ ≥ S_MIN over [θ_min, θ_max], the
    largest precession rate |ψ̇| ≤ |ω⊥|max/sinθ no faster than the fastest rate W of the
    quaternion form (else that form needs fewer steps), and ψ̇ = (b − c cosθ)/sin²θ not
    losing more than rtol/10 of its scale to the cancellation of b against c cosθ."""
    s_min = min(math.sin(th_min), math.sin(th_max))
    if not s_min >= S_MIN:
        return False
    c = top.C * omega3 / top.A
    psd_max = Wp / s_min
    if psd_max > max(Wfast, 1e-300):
        return False
    cond = (abs(b) + abs(c)) / (s_min * s_min) * EPS
    return cond <= 0.1 * rtol * psd_max or cond == 0.0


class Reduced:
    """The reduced equations of one top from its initial state (ψ0, θ0, φ0, ψ̇0, θ̇0, φ̇0),
    θ integrated as x = θ − θc about the centre θc of the nutation [θ_min, θ_max]."""

    def __init__(self, top: Top, state, bounds, Wp: float):
        psi0, th0, phi0, psd0, thd0, phd0 = state
        self.top, self.Wp = top, Wp
        s0, c0 = math.sin(th0), math.cos(th0)
        self.w3 = psd0 * c0 + phd0
        self.b = psd0 * s0 * s0 + top.kc * self.w3 * c0          # p_ψ / I11
        self.c = top.kc * self.w3
        self.tc = 0.5 * (bounds[0] + bounds[1])
        self.y0 = [th0 - self.tc, thd0, psi0, phi0]
        self.th0 = th0
        self.E0 = self._energy(th0, thd0)
        s_min = max(min(math.sin(bounds[0]), math.sin(bounds[1])), 1e-300)
        #: the change of θ that moves ψ̇ = (b − c cosθ)/sin²θ by its scale |ψ̇|max ≤ |ω⊥|max/sinθ_min
        #: (|∂ψ̇/∂θ| ≤ (|c| + 2|ψ̇|max)/sinθ_min): a fast top's ψ̇ is c/ψ̇ ~ 1e4 times more sensitive
        self.X = min(bounds[1], Wp / (abs(self.c) + 2.0 * Wp / s_min)) if Wp > 0 else bounds[1]

    def tolerances(self, rtol, atol):
        """(rtol, atol of each state): scipy's test |e| ≤ atol + rtol |y| on x = θ − θc is relative
        to the nutation amplitude, not to θ (a top nutating by 1e-4 rad about θ = 1 would get
        θ̇, ψ̇ errors ~1e4 rtol); atol of x and θ̇ no tighter than FLOOR rtol times their scales X and
        |ω⊥|max (the scales the error_estimate counts them against: steady precession's x and θ̇
        are the integrator's own error, which an atol below that chases with ever smaller steps)."""
        rtol = runner.floor_rtol(rtol)
        return rtol, [max(atol, FLOOR * rtol * self.X), max(atol, FLOOR * rtol * self.Wp), atol, atol]

    def rhs(self, t, y):
        """(θ̇, θ̈, ψ̇, φ̇): (38.18) with the momentum integrals, plain floats; a rate that is
        not finite raises :class:`dyncli.ode.NonFiniteRate` here (what ``ode.finite`` does, without
        a second call per evaluation)."""
        x, thd, _, _ = y.tolist()
        s, c = math.sin(x + self.tc), math.cos(x + self.tc)
        psd = (self.b - self.c * c) / (s * s)
        thdd = s * (psd * (psd * c - self.c) + self.top.kg)
        if not (math.isfinite(thdd) and math.isfinite(psd)):
            raise ode.NonFiniteRate(t, y)
        return [thd, thdd, psd, self.w3 - psd * c]

    def _energy(self, th, thd):
        """(E − ½ I33 ω3²)/I11 = ½(θ̇² + ψ̇² sin²θ) + (mgL/I11) cosθ.  On the
        vertical (sinθ = 0: a top started upright) S = ψ̇ sinθ = (b − c cosθ)/sinθ
        is 0/0; its value there is ψ̇0 sinθ0 = 0 (b − c cosθ = ψ̇0 sin²θ0)."""
        s, c = math.sin(th), math.cos(th)
        num = self.b - self.c * c
        S = num / s if s != 0 else (0.0 if num == 0 else math.inf)
        return 0.5 * (thd * thd + S * S) + self.top.kg * c

    def run(self, times, *, rtol, atol, method, max_step, max_steps):
        """ψ, θ, φ, ψ̇, θ̇, φ̇, S = ψ̇ sinθ, R at the sorted ``times`` (t ≥ 0) and the energy's
        largest change at them, over I11 (the caller scales it)."""
        budget = ode.Budget(max_steps)
        ts = np.asarray(times, dtype=float)
        T = float(ts[-1])
        budget.leg(0.0, T)
        rtol, atol = self.tolerances(rtol, atol)
        # the rhs checks its own rates (check_finite=False: one Python call less per evaluation)
        sol = runner.solve_ivp(self.rhs, (0.0, T), self.y0, method=method, budget=budget, check_finite=False,
                               t_eval=ts, rtol=rtol, atol=atol, max_step=max_step)
        self.steps = budget.n          # accepted steps of the last run (the nominal error estimate)
        if sol.status != 0 or sol.y.shape[1] != len(ts):
            from dyncli.errors import NumericalError

            raise NumericalError(f"the integrator ({method}) failed at t = {sol.t[-1] if len(sol.t) else 0.0:.6g} s: "
                                 f"{sol.message}")
        x, thd, psi, phi = sol.y
        th = x + self.tc
        zero = ts == 0.0                      # the initial state as given
        th[zero] = self.th0
        thd[zero], psi[zero], phi[zero] = self.y0[1:]
        return self.motion(psi, th, phi, thd), self.drift(th, thd)

    def dense(self, T, *, rtol, atol, method, max_step, max_steps):
        """One run from 0 to T with every step's interpolant: (the steps' ends, ``states(ts)``, the
        results ψ, θ, φ, ψ̇, θ̇, φ̇, R at any times of [0, T] as lists, each a smooth function of the
        step's polynomial between two step ends) — the ``find`` search's motion."""
        budget = ode.Budget(max_steps)
        budget.leg(0.0, T)
        rtol, atol = self.tolerances(rtol, atol)
        sol = runner.solve_ivp(self.rhs, (0.0, T), self.y0, method=method, budget=budget, check_finite=False,
                               dense_output=True, rtol=rtol, atol=atol, max_step=max_step)
        if sol.status != 0:
            from dyncli.errors import NumericalError

            raise NumericalError(f"the integrator ({method}) failed at t = {sol.t[-1]:.6g} s: {sol.message}")
        dense = sol.sol

        def states(ts) -> dict:
            ts = np.asarray(ts, dtype=float).reshape(-1)
            x, thd, psi, phi = np.asarray(dense(ts), dtype=float).reshape(4, -1)
            th = x + self.tc
            zero = ts == 0.0                  # the initial state as given
            th[zero] = self.th0
            thd[zero], psi[zero], phi[zero] = self.y0[1:]
            psi, th, phi, psd, thd, phd, _, R = self.motion(psi, th, phi, thd)
            out = {k: (np.asarray(a, dtype=float) + 0.0).tolist() for k, a in
                   (("psi", psi), ("theta", th), ("phi", phi), ("psi_dot", psd), ("theta_dot", thd), ("phi_dot", phd))}
            out["R"] = (np.asarray(R, dtype=float) + 0.0).tolist()
            return out
        return [float(t) for t in sol.t], states

    def motion(self, psi, th, phi, thd):
        s, c = np.sin(th), np.cos(th)
        psd = (self.b - self.c * c) / (s * s)
        S = psd * s
        w = np.column_stack([thd, S, np.full_like(th, self.w3)])       # ω on e'' (φ = 0)
        R = reaction(self.top, th, np.zeros_like(th), w)
        return psi, th, phi, psd, thd, self.w3 - psd * c, S, R

    def drift(self, th, thd) -> float:
        if not len(th):
            return 0.0
        return max(abs(self._energy(a, b) - self.E0) for a, b in zip(th.tolist(), thd.tolist()))

