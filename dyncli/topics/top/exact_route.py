"""The `top`'s exact route (accuracy.method auto or exact): the elliptic solution of
:mod:`dyncli.topics.top.elliptic` evaluated at the requested times, with its
error estimate.

error_estimate (relative, docs/accuracy.md) bounds the round-off of the evaluation:

* the phase τ = λt + τ0 is formed in floating point, so every quantity carries a
  relative error of ~ε·(1 + λt) (the condition number of the phase at time t; the
  dominant term at long times, e.g. 4e-9 at λt = 1e7);
* the residuals of the energy and H_O·e3 integrals at the reported times, relative to
  their scales (they catch a wrong root or a lost digit in θ, θ̇, ψ̇ sinθ);

the estimate is the largest of these (the phase term times a safety factor of 16).  Where the
phase is reduced in double-double (40-digit λ and period from the inputs as binary numbers), the
inputs themselves are still decimal numbers rounded to doubles (½ε each): λ/2K is known to
~:data:`INPUTS_REL` relative, a phase error of that times λt (:func:`dyncli.phase.rounded`), counted
in the estimate and warned beyond :data:`dyncli.phase.LOSS` (docs/accuracy.md, long times).
"""

from __future__ import annotations

import math

from dyncli.backends import FLOAT_OPS
from dyncli.errors import NumericalError
from dyncli.phase import LOSS, rounded
from dyncli.topics.top.derived import reaction_on
from dyncli.topics.top.elliptic import EPS, ExactTop
from dyncli.topics.top.kinematics import Controls

#: safety factor on the phase round-off term ε (1 + λ t + periods)
PHASE_FACTOR = 16.0
#: the phase is formed in double-double (40-digit λ and period) where its double round-off would exceed
#: min(rtol, this): the exact top keeps ~1e-13 of scale at any t
EXTENDED_ABOVE = 1e-12
#: at most this many requested times are evaluated one by one in plain floats (no numpy import; each
#: costs ~50 µs, mostly three Carlson integrals), more as arrays (~0.7 ms for numpy's calls + ~8 µs a time)
FLOAT_TIMES = 16
#: the relative error of the frequency λ/2K from the inputs' rounding to doubles (½ε each, through
#: the products mgL/A, Cω3/A, the nutation cubic's roots and K(m); measured ≤ 1.5ε in the tests)
INPUTS_REL = 4.0 * EPS


class ExactRun:
    """Lists of plain floats at the requested times (same order as ``times``) and the run's figures."""

    def __init__(self, top, psi0, theta0, phi0, psi_dot0, theta_dot0, phi_dot0, times, rtol=None):
        A, C, mgL = top.A, top.C, top.mgL
        try:
            self.ex = ex = ExactTop(A, C, mgL, psi0, theta0, phi0, psi_dot0, theta_dot0, phi_dot0)
        except RuntimeError:     # the nutation cubic's root search did not converge (a degenerate top
            self.finite = False  # ~1e-30 rad from the vertical): the caller takes the ODE route
            return
        self.finite = ex.nut.finite
        if not self.finite:
            return
        self.times = t = [float(x) for x in times]
        self.extended = False
        if t and not ex.steady and rtol is not None:
            self._long_phase(top, (theta0, theta_dot0, psi_dot0, phi_dot0), max(abs(x) for x in t), rtol)
        if len(t) <= FLOAT_TIMES:      # one by one in plain floats: no numpy import (most of a cold start)
            cols = list(zip(*(ex.evaluate(x) for x in t))) if t else [[]] * 7
        else:                          # many times: the arrays (numpy), the same algorithm
            cols = [a.tolist() for a in ex.evaluate(_array(t))]
        (self.psi, self.theta, self.phi, self.psi_dot, self.theta_dot, self.phi_dot, self.S) = map(list, cols)
        # a parameter beyond doubles (1 − m underflowing next to the separatrix, θ0 within ~1e-153 rad
        # of an unstable vertical): not representable here; the caller falls back to the ODE route
        self.finite = all(math.isfinite(x) for a in (self.psi, self.theta, self.phi, self.theta_dot, self.S)
                          for x in a)
        if not self.finite:
            return
        self.w = [(td, S, ex.omega3) for td, S in zip(self.theta_dot, self.S)]     # body ω on e'' (φ = 0)
        self._bounds(theta0)
        self.passes = [] if ex.steady else self._passages(t)
        self._residuals(top, t)

    def _long_phase(self, top, state, T, rtol):
        """The phase in double-double (:mod:`dyncli.topics.top.phase`) where the double phase's
        round-off, PHASE_FACTOR·ε(1 + λT + periods), would exceed min(rtol, EXTENDED_ABOVE)."""
        ex = self.ex
        lam_T = ex.nut.lam * T
        if not PHASE_FACTOR * EPS * (1.0 + lam_T + lam_T / (2.0 * ex.K)) > min(rtol, EXTENDED_ABOVE):
            return
        from dyncli.topics.top.phase import long_phase

        mgl = (top.m, top.g, top.L) if all(hasattr(top, k) for k in ("m", "g", "L")) else (top.mgL, 1.0, 1.0)
        try:
            ex.phase = long_phase((*mgl, top.A, top.C, *state), ex.nut, ex.tau0)
        except (ArithmeticError, ValueError):     # a degenerate motion at 40 digits: the double phase stays
            ex.phase = None
        self.extended = ex.phase is not None

    def _bounds(self, theta0):
        n, ex = self.ex.nut, self.ex
        self.theta_min = n.theta_min if not ex.sleeping else theta0
        self.theta_max = n.theta_max if not ex.sleeping else theta0

    def _passages(self, t):
        """First time in the run at which the axis passes exactly through the vertical."""
        ex, n = self.ex, self.ex.nut
        P = 2.0 * ex.K
        out = []
        for at_pole, off in ((n.v2 == 0.0 and n.B == 0.0, 0.0), (n.w1 == 0.0 and n.Bp == 0.0, ex.K)):
            if at_pole and len(t):
                tau_p = off + P * (math.floor((ex.tau0 - off) / P) + 1.0)
                tp = (tau_p - ex.tau0) / n.lam
                if tp <= max(t):
                    out.append(tp)
        return sorted(out)

    def _residuals(self, top, t):
        """drift and error_estimate (module docstring), in plain floats."""
        A, C, mgL = top.A, top.C, top.mgL
        ex, n = self.ex, self.ex.nut
        W3 = ex.omega3
        # E and H_O·e3 of the initial state from the constants of the solution (α = D + β, b)
        self.E0 = E0 = 0.5 * A * (n.D + n.beta) + 0.5 * C * W3 * W3
        self.H0 = H0 = 0.5 * A * (n.B + n.Bp)
        T = max(t) if t else 0.0
        dE = dH = 0.0
        if t:
            spin = 0.5 * C * W3 * W3
            dEs, dHs = [], []
            for th, (w1, w2, _) in zip(self.theta, self.w):
                u, s = math.cos(th), math.sin(th)
                dEs.append(abs(0.5 * A * (w1 * w1 + w2 * w2) + spin + mgL * u - E0))
                dHs.append(abs(A * w2 * s + C * W3 * u - H0))
            wmax = max(max(abs(w1), abs(w2)) for w1, w2, _ in self.w)
            Es = 0.5 * A * wmax * wmax + spin + mgL
            Hs = A * wmax + abs(C * W3) + 1e-300
            dE = max(dEs) / Es if Es > 0 else 0.0
            dH = max(dHs) / Hs
        self.drift = max(dE, dH)
        lam = 0.0 if ex.steady else n.lam
        periods = 0.0 if ex.steady else lam * T / (2.0 * ex.K)
        self.lam_T = lam * T
        self.phase_errors = [self.phase_error(abs(x)) for x in t]
        if self.extended:       # the phase reduced in double-double: as if λt were at most one period
            phase = max(PHASE_FACTOR * EPS * (1.0 + 2.0 * ex.K + abs(ex.tau0)), max(self.phase_errors))
        else:
            phase = PHASE_FACTOR * EPS * (1.0 + lam * T + periods)
        # at t = 0 only, the reported state is the input itself
        self.error_estimate = max(dE, dH, phase) if T > 0 else 0.0


    def phase_error(self, t: float) -> float:
        """The phase's error at time t (a fraction of each quantity's scale): the inputs' rounding,
        INPUTS_REL·λt + ulp (double-double), or PHASE_FACTOR·ε(1 + λt + periods) (double phase)."""
        ex = self.ex
        if ex.steady or t == 0.0:
            return 0.0
        lam = ex.nut.lam
        if self.extended:
            return rounded(lam, t, ex.tau0, INPUTS_REL)
        return PHASE_FACTOR * EPS * (1.0 + lam * t + lam * t / (2.0 * ex.K))


def nutation_period(ex: ExactTop) -> float:
    """Period of θ(t) [s] (inf for a steady motion)."""
    return math.inf if ex.steady else 2.0 * ex.K / ex.nut.lam


def route(res, top, acc: Controls, psi0, th0, phi0, psd0, th_dot0, phi_dot0, times):
    """The elliptic solution at ``times``, or None when it is not representable in doubles
    (then the caller takes the ODE route; accuracy.method exact refuses instead)."""
    ex = ExactRun(top, psi0, th0, phi0, psd0, th_dot0, phi_dot0, times, rtol=acc.rtol)
    if not ex.finite:
        msg = ("the elliptic solution of this top is not representable in doubles (its elliptic parameter "
               "1 − m underflows, or the roots of its nutation cubic are not separable: a top released "
               "within ~1e-30 rad of the vertical)")
        if acc.method == "exact":
            raise NumericalError(msg + ": use accuracy.method DOP853")
        res.warn(msg + "; solved by the ODE route (DOP853)")
        return None
    R = [reaction_on(FLOAT_OPS, top, th, 0.0, *w) for th, w in zip(ex.theta, ex.w)]
    res.method = "exact"
    res.extra["sample"] = lambda ts: ex.ex.evaluate(_array(ts))[:2]      # (ψ, θ), for plots
    res.error_estimate = float(ex.error_estimate) if len(times) else None
    res.extra["error_estimate_note"] = (
        "round-off of the elliptic solution: the larger of ε·16(1 + λt + periods) (the phase λt + τ0 "
        "formed in floating point; in double-double, 4ε·λt: the inputs' rounding to doubles) and the residuals of the energy and H_O·e3 integrals at the reported times, "
        "each relative to its scale")
    lost = max(ex.phase_errors, default=0.0) > LOSS
    if lost:
        from dyncli.phase import warn_lost

        warn_lost(res, ex.times, ex.phase_errors, "the state")
    if not lost and ex.times and max(abs(x) for x in ex.times) > 0 and ex.error_estimate > acc.rtol:
        from dyncli import runner       # (numpy: only when there is something to say)

        runner.warn_unmet(res, acc.rtol, res.error_estimate,
                          what=f"error_estimate (the elliptic solution's round-off over λt = {ex.lam_T:.3g} rad)")
    th_min = min(ex.theta_min, th0)
    th_max = max(ex.theta_max, th0)
    res.results.update(theta_min=th_min + 0.0, theta_max=th_max + 0.0)
    if ex.passes:
        res.warn(f"the axis passes exactly through the vertical at t = {ex.passes[0]:.6g} s (and once every "
                 "nutation period): there ψ and φ are individually undefined and the 3-1-3 angles jump by π "
                 "(ψ + π with φ ∓ π); the orientation is continuous")
    return ex.psi, ex.theta, ex.phi, ex.psi_dot, ex.theta_dot, ex.phi_dot, ex.S, R, ex.drift, []


def _array(ts):
    """Times as an array (numpy, imported here: the plots' dense sampling)."""
    import numpy as np

    return np.asarray(ts, dtype=float)
