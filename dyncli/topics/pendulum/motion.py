"""θ(t), θ̇(t) of the pendulum by Jacobi's elliptic functions (dyncli.elliptic), in plain floats.

With ω₀ = √(g/l), k² = sin²(θ₀/2) + (θ̇₀/2ω₀)² (:func:`equations.modulus`):

* **swing** (k < 1, parameter m = k²): sin(θ/2) = k sn(ω₀t + u₀), so θ = 2 atan2(k sn, dn) and
  θ̇ = 2kω₀ cn; u₀ from sn u₀ = sin(θ₀/2)/k, cn u₀ = θ̇₀/(2kω₀), dn u₀ = |cos(θ₀/2)| by Carlson's
  R_F; period T = 4K(m)/ω₀, turning points where cn = 0;
* **rotation** (k > 1, m = 1/k²): θ/2 = am(kω₀t + v₀) (in the direction of θ̇₀), θ̇ = 2kω₀ dn;
  one turn in T = 2K(m)/(kω₀), am(τ) = nπ + atan2(sn r, cn r) for τ = 2Kn + r;
* **separatrix** (k = 1 within the inputs' rounding): θ = 2 atan(sinh(ω₀t + u₀)), θ̇ = 2ω₀ sech(ω₀t + u₀),
  θ → ±π as t → ∞ (no period); θ̇₀ = 0 there is the unstable equilibrium at the top.

sn, cn, dn of the phase reduced to |r| ≤ K come from :func:`dyncli.elliptic.ellipj_half` with
1 − m given exactly, so next to the separatrix (m₁ → 0) the small cn and dn keep their relative
precision.  The phase is reduced modulo its period in doubles (an error of ~ε·ω₀t), or, when
:meth:`Motion.long` is given a horizon beyond :data:`LONG` periods, in double-double from the
frequency at 40 digits (:class:`dyncli.phase.ReducedPhase`), so t = 10⁶ periods is as exact as
t = 1 period.
"""

from __future__ import annotations

import math

from dyncli.elliptic import ellipj_half, elliprf, legendre_F
from dyncli.phase import ReducedPhase, pair, rounded

from . import equations as eq

#: periods beyond which the phase is reduced in double-double
LONG = 64
#: |1 − k²| below which it is formed at 40 digits from the inputs (as binary numbers): in doubles
#: q = θ̇₀/2ωₙ carries ~ε, so 1 − k² = (c − q)(c + q) would carry ~ε/|1 − k²| relative
NEAR = 1e-3
TWO_PI = 2.0 * math.pi


def _near_separatrix(l: float, g: float, theta0: float, theta_dot0: float) -> tuple[float, float]:
    """(k², 1 − k²) at 40 digits from the inputs, rounded once."""
    import mpmath

    with mpmath.workdps(40):
        mp = mpmath.mp
        m1 = mp.cos(mp.mpf(theta0) / 2) ** 2 - mp.mpf(theta_dot0) ** 2 * mp.mpf(l) / (4 * mp.mpf(g))
        return float(1 - m1), float(m1)


class Motion:
    """One pendulum from θ(0) = θ₀, θ̇(0) = θ̇₀ (module docstring); ``regime`` is ``rest``,
    ``swing``, ``separatrix`` or ``rotating``; ``period`` None on the separatrix."""

    def __init__(self, l: float, g: float, theta0: float, theta_dot0: float):
        self.l, self.g, self.theta0, self.theta_dot0 = l, g, theta0, theta_dot0
        self.omega0 = w = eq.natural_frequency(l, g)
        self.k2, self.m1, self.tol = eq.modulus(theta0, theta_dot0, w)
        if abs(self.m1) < NEAR:
            self.k2, self.m1 = _near_separatrix(l, g, theta0, theta_dot0)
        self.sigma = 1.0 if theta_dot0 >= 0 else -1.0
        self.j0 = round(theta0 / TWO_PI)             # whole turns of θ₀ (a swing about 2πj₀)
        self.phase: ReducedPhase | None = None
        self.period: float | None
        if self.k2 == 0.0:
            self.regime, self.period = "rest", eq.small_angle_period(l, g)
        elif abs(self.m1) <= self.tol:
            self.regime, self.period = "separatrix", None
            self.top = theta_dot0 == 0.0             # balanced at the top: θ ≡ θ₀
            c = math.cos(0.5 * theta0 - math.pi * self.j0)
            self.u0 = math.inf if self.top else math.asinh(self.sigma * math.sin(0.5 * theta0 - math.pi * self.j0) / c)
        elif self.m1 > 0.0:
            self.regime = "swing"
            self._swing()
        else:
            self.regime = "rotating"
            self._rotation()

    # --- the constants of each regime ---------------------------------------------------------
    def _swing(self):
        k2, m1, w = self.k2, self.m1, self.omega0
        self.k = k = math.sqrt(k2)
        self.K = float(elliprf(0.0, m1, 1.0))
        half = 0.5 * self.theta0 - math.pi * self.j0         # about the bottom at 2πj₀
        sn, cn = math.sin(half) / k, self.theta_dot0 / (2.0 * w * k)
        d2 = math.cos(half) ** 2
        if cn >= 0.0:
            self.u0 = float(legendre_F(sn, cn, d2))
        else:                                        # F(φ) = ±2K − F(±π − φ) past a quarter
            self.u0 = math.copysign(2.0 * self.K, sn) - float(legendre_F(sn, -cn, d2))
        self.lam, self.P = w, 4.0 * self.K
        self.period = self.P / w
        self.theta_max = eq.amplitude(k, m1)

    def _rotation(self):
        k2, w = self.k2, self.omega0
        self.k = k = math.sqrt(k2)
        self.m, self.mr1 = 1.0 / k2, -self.m1 / k2
        self.K = float(elliprf(0.0, self.mr1, 1.0))
        half = 0.5 * self.sigma * self.theta0
        self.jr = round(half / math.pi)              # θ'/2 = jπ + φ, |φ| <= π/2
        phi = half - math.pi * self.jr
        s, c = math.sin(phi), math.cos(phi)
        self.u0 = float(legendre_F(s, c, c * c + self.mr1 * s * s))
        self.lam, self.P = k * w, 2.0 * self.K
        self.period = self.P / self.lam

    def long(self, horizon: float) -> None:
        """Reduce the phase in double-double when ``horizon`` spans more than :data:`LONG` periods."""
        if self.regime in ("swing", "rotating") and self.period is not None and horizon > LONG * self.period:
            import mpmath

            with mpmath.workdps(40):
                mp = mpmath.mp
                l, g, th, thd = (mp.mpf(x) for x in (self.l, self.g, self.theta0, self.theta_dot0))
                w = mp.sqrt(g / l)
                k2 = mp.sin(th / 2) ** 2 + (thd / (2 * w)) ** 2
                if self.regime == "swing":
                    lam, P = w, 4 * mp.ellipk(k2)
                else:
                    lam, P = mp.sqrt(k2) * w, 2 * mp.ellipk(1 / k2)
                if abs(P - self.P) <= 1e-9 * P:      # the same motion (else keep the double phase)
                    self.phase = ReducedPhase(pair(lam / P), pair(mp.mpf(self.u0) / P), float(P))

    def reduced(self, t: float) -> tuple[float, float]:
        """(n, r): the phase λt + u₀ = nP + r, |r| <= P/2."""
        if self.phase is not None:
            return self.phase.reduce(t)
        tau = self.lam * t + self.u0
        n = float(round(tau / self.P))
        return n, tau - n * self.P

    def phase_error(self, t: float) -> float:
        """The error of the phase λt + u₀ (the fraction of the motion's range θ(t) may be off by):
        however exactly it is reduced, λ/P is the inputs' (each rounded to a double, ½ε relative)
        through √(g/l) and K(k²), whose relative slope in k² is ~1/(2K·(1 − k²)) near the separatrix,
        so it is known to ~4ε·(1 + 1/(K·|1 − k²|)) relative (:func:`dyncli.phase.rounded`); a slope
        of θ, θ̇ in the phase of at most their scale makes it their error relative to that scale.
        0 at rest and on the separatrix (no period: θ settles)."""
        if self.regime not in ("swing", "rotating") or t == 0.0:
            return 0.0
        return rounded(self.lam, t, self.u0, 4.0 * 2.0 ** -52 * (1.0 + 1.0 / (self.K * abs(self.m1))))

    # --- the state ------------------------------------------------------------------------------
    def state(self, t: float) -> tuple[float, float]:
        """(θ, θ̇) at time t >= 0 (the inputs themselves at t = 0)."""
        if t == 0.0 or self.regime == "rest":
            return self.theta0, self.theta_dot0
        if self.regime == "separatrix":
            return self._separatrix(t)
        n, r = self.reduced(t)
        if self.regime == "swing":
            flip = abs(r) > self.K                   # sn(r) = sn(±2K − r), cn(r) = −cn(±2K − r)
            if flip:
                r = math.copysign(2.0 * self.K, r) - r
            sn, cn, dn = ellipj_half(r, self.k2, self.m1, self.K)
            cn = -cn if flip else cn
            return TWO_PI * self.j0 + 2.0 * math.atan2(self.k * sn, dn), 2.0 * self.k * self.omega0 * cn
        sn, cn, dn = ellipj_half(r, self.m, self.mr1, self.K)
        s = self.sigma
        return s * (TWO_PI * (self.jr + n) + 2.0 * math.atan2(sn, cn)), 2.0 * s * self.lam * dn

    def _separatrix(self, t: float) -> tuple[float, float]:
        if self.top:
            return self.theta0, 0.0
        u = self.omega0 * t + self.u0
        e = math.exp(-abs(u))                        # sech u = 2e/(1 + e²), no overflow
        th = 2.0 * math.atan(math.sinh(u)) if abs(u) < 700 else math.copysign(math.pi, u)
        return TWO_PI * self.j0 + self.sigma * th, self.sigma * 4.0 * self.omega0 * e / (1.0 + e * e)

    # --- the distance -----------------------------------------------------------------------
    def turned(self, t: float) -> float:
        """The angle swept since t = 0, ∫|θ̇| dt: |θ(t) − θ₀| but for a swing, where every
        turning point (phase ≡ K mod 2K) adds its 2θ_max, counted from the reduced phase."""
        th, _ = self.state(t)
        if self.regime != "swing" or t == 0.0:
            return abs(th - self.theta0)
        K, tm = self.K, self.theta_max
        n, r = self.reduced(t)
        j1 = math.floor((self.u0 - K) / (2.0 * K)) + 1          # the first turning point's index
        jt = 2.0 * n + math.floor((r - K) / (2.0 * K))          # the last one at or before t
        turns = jt - j1 + 1
        if turns <= 0:
            return abs(th - self.theta0)
        base = TWO_PI * self.j0
        first = base + (tm if j1 % 2 == 0 else -tm)
        last = base + (tm if jt % 2 == 0 else -tm)
        return abs(first - self.theta0) + 2.0 * tm * (turns - 1) + abs(th - last)
