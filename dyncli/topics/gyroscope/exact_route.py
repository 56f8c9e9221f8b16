"""The gyroscope's exact route (accuracy.method auto or exact): θ(t) of
:mod:`dyncli.topics.gyroscope.elliptic` at the requested times, with its error estimate.

error_estimate (relative, docs/accuracy.md) bounds the round-off of the evaluation:

* the phase u = λt + u0 is formed in floating point, so θ and θ̇ carry a relative
  error of ~ε·(1 + λt + |u0|) (the condition number of the phase at time t; the dominant
  term at long times, e.g. 1e-9 at λt = 1e7), on the scale √(1 − m) of a negative parameter;
* the residual of the first integral (37.15b), |θ̇² − G(θ)| at the reported times,
  relative to the scale of θ̇² (it catches a wrong root or a lost digit in θ, θ̇);

the estimate is the larger of these (the phase term times a safety factor of 16, as
for the top).  Where the phase is reduced in double-double, the inputs' own rounding to doubles
(½ε each) still leaves λ/4K known to ~:data:`INPUTS_REL` relative: a phase error of that times
λt (:func:`dyncli.phase.rounded`), counted and warned beyond :data:`dyncli.phase.LOSS`, as for the top.
"""

from __future__ import annotations

import math
import sys

from dyncli.backends import ops_for
from dyncli.phase import rounded
from dyncli.topics.gyroscope.elliptic import GyroTheta

EPS = sys.float_info.epsilon
PHASE_FACTOR = 16.0
#: the phase is formed in double-double (40-digit λ and period) where its double round-off would exceed
#: min(rtol, this), as for the top
EXTENDED_ABOVE = 1e-12
#: the relative error of the frequency λ/4K from the inputs' rounding to doubles (as for the top)
INPUTS_REL = 4.0 * EPS


def theta_dot_sq(I1, I2, p, q, th0, thd0, th):
    """G(θ) of (37.15b) about the initial state: θ̇0² + a (s² − s0²) + b (s − s0) (θ a float or
    an array)."""
    a, b = (I1 - I2) * q * q / I2, 2.0 * I1 * p * q / I2
    s, s0 = ops_for(th).sin(th), math.sin(th0)
    return thd0 * thd0 + a * (s - s0) * (s + s0) + b * (s - s0)


class ExactRun:
    """θ, θ̇ at the requested times (lists of floats: no numpy) and the run's round-off estimate."""

    def __init__(self, I1, I2, p, q, th0, thd0, times, steady=False, rtol=None):
        self.g = g = GyroTheta(I1, I2, p, q, th0, thd0, steady=steady)
        t = [float(x) for x in times]
        self.finite = g.finite
        if not self.finite:
            return
        T = max(abs(x) for x in t) if t else 0.0
        self.extended = False
        if T > 0 and g.kind != "steady" and rtol is not None \
                and PHASE_FACTOR * EPS * (1.0 + g.lam * T) > min(rtol, EXTENDED_ABOVE) and math.isfinite(g.K):
            from dyncli.topics.gyroscope.phase import long_phase

            try:
                g.phase = long_phase((I1, I2, p, q, th0, thd0), g)
            except (ArithmeticError, ValueError):     # degenerate at 40 digits: the double phase stays
                g.phase = None
            self.extended = g.phase is not None
        states = [g.evaluate(x) for x in t]
        self.theta, self.theta_dot = [th for th, _ in states], [thd for _, thd in states]
        self.finite = all(math.isfinite(th) and math.isfinite(thd) for th, thd in states)
        if not self.finite:
            return
        a, b = abs(g.a), abs(g.b)
        scale = thd0 * thd0 + 2.0 * a + 2.0 * b + 1e-300          # range of θ̇² over a motion
        resid = [abs(thd * thd - theta_dot_sq(I1, I2, p, q, th0, thd0, th)) for th, thd in states]
        self.drift = max(resid) / scale if t else 0.0
        self.lam_T = g.lam * T
        # the phase reduced in double-double: as if λt were at most one period 4K (+ the offset u0);
        # for m < 0 the phase is scaled by √(1 − m) inside ellipj_any (next to a separatrix λ and u0
        # are tiny there and the rate is λ√(1 − m)), so the rounding is measured on that scale
        stretch = math.sqrt(g.m1) if getattr(g, "m", 0.0) < 0 else 1.0
        phase = 1.0 + stretch * ((4.0 * g.K if self.extended else self.lam_T) + abs(getattr(g, "u0", 0.0)))
        u0 = abs(getattr(g, "u0", 0.0))
        if g.kind == "steady":
            self.phase_errors = [0.0 for _ in t]
        elif self.extended:            # the inputs' rounding, on the same scale
            self.phase_errors = [rounded(stretch * g.lam, abs(x), stretch * u0, INPUTS_REL) if x else 0.0 for x in t]
        else:
            self.phase_errors = [PHASE_FACTOR * EPS * (1.0 + stretch * (g.lam * abs(x) + u0)) if x else 0.0 for x in t]
        self.error_estimate = max(self.drift, PHASE_FACTOR * EPS * phase, max(self.phase_errors)) if T > 0 else 0.0

    @property
    def period(self) -> float:
        return self.g.period

    def sample(self, ts):
        """θ at any times (for plots: an array, numpy)."""
        import numpy as np

        return self.g.evaluate(np.asarray(ts, dtype=float))[0]
