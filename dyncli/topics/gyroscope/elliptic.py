"""Exact θ(t) of the gyroscope (notes §37) by Jacobi elliptic functions.

The first integral (37.15b) reads θ̇² = G(θ) = a s² + b s + c0 with s = sin θ,
a = (Ī₁ − Ī₂) q²/Ī₂, b = 2 Ī₁ p q/Ī₂.  G is even about θ = ±π/2, so about a centre
θc = ±π/2 (χ = θ − θc, s = ±cos χ) the half-angle variable z = tan(χ/2) obeys a
biquadratic (no odd powers):

    ż² = P(z²),   P(x) = A4 x² + A2 x + A0,
    A0 = G(θc)/4,  A4 = G(θc + π)/4,  A2 = (c0 − a)/2,

each of A0, A4 formed from the initial state without cancellation (G(θc) =
θ̇0² + a sin²χ0 ± 2b sin²(χ0/2)).  The centre is the one with |χ0| ≤ π/2, switched
when the motion reaches z = ∞ but not z = 0.  With x0 = z0² the motion is one of

* libration through the centre (|z| ≤ z1, x1 the root of P above x0):
  z = z1 sn(λt + u0 | m),  m = A4 x1²/A0,  λ² = A0/x1;
* a band between two roots x_lo < x_hi of the same sign of z (θ never at ±π/2):
  z = ±z_hi dn(λt + u0 | m),  m1 = 1 − m = x_lo/x_hi,  λ² = −A4 x_hi;
* circulation (P > 0 for all x ≥ 0, no turning point): with β = (A0/A4)^¼,
  z = β tan(φ/2), φ = am(σλt + u0 | m), λ = 2 (A0 A4)^¼, m = ½ − A2/(4√(A0A4)),
  so χ = φ + 2 atan2((β − 1) sin φ, (1 + β) + (1 − β) cos φ): whole revolutions come
  from the whole periods 4K of φ.

m < 0 (a gyroscope spinning against the turntable, a circulation with real roots)
goes through the imaginary-modulus transformation to parameter −m/(1 − m) ∈ [0, 1).
sn, cn, dn come from the AGM of dyncli.elliptic with 1 − m given exactly
(next to the separatrix, m → 1), the phase u0 from Carlson's R_F (dyncli.elliptic: no scipy
on this route).  The argument is reduced modulo the period, so each requested time costs the
same whatever t.  One time is evaluated in plain floats (no numpy import), an array of times
(plots) with numpy: the same formulas on either backend.
"""

from __future__ import annotations

import math

from dyncli.backends import FLOAT_OPS, ops_for
from dyncli.elliptic import ellipj
from dyncli.elliptic import elliprf as _rf

#: π/2 − fl(π/2), the part of π/2 a double cannot hold
_HALF_PI_LO = 6.123233995736766e-17


def ellipj_any(u, m: float, m1: float):
    """sn, cn, dn for any parameter m < 1 (m1 = 1 − m exact); m < 0 by DLMF 22.17."""
    if m >= 0.0:
        return ellipj(u, m, m1)
    mu, mu1 = -m / m1, 1.0 / m1
    r = math.sqrt(m1)
    s, c, d = ellipj(u * r, mu, mu1)
    return s / (d * r), c / d, 1.0 / d


def quarter_period(m1: float) -> float:
    """K(m) = R_F(0, 1 − m, 1)."""
    return math.inf if m1 == 0.0 else _rf(0.0, m1, 1.0)


def quadratic_roots(A4, A2, A0):
    """Real roots of A4 x² + A2 x + A0 (stable formula), ascending."""
    if A4 == 0.0:
        return [] if A2 == 0.0 else [-A0 / A2]
    d = A2 * A2 - 4.0 * A4 * A0
    if d < 0.0:
        return []
    q = -0.5 * (A2 + math.copysign(math.sqrt(d), A2))
    if q == 0.0:
        return [0.0, 0.0]
    return sorted([q / A4, A0 / q])


class GyroTheta:
    """θ(t), θ̇(t) of (37.12) from θ(0) = θ0, θ̇(0) = θ̇0 (module docstring)."""

    def __init__(self, I1, I2, p, q, theta0, theta_dot0, steady=False):
        self.a = a = (I1 - I2) * q * q / I2
        self.b = b = 2.0 * I1 * p * q / I2
        self.theta0, self.theta_dot0 = theta0, theta_dot0
        self.steady = steady
        self.lam = 0.0
        self.K = math.inf
        self.phase = None           # the double-double phase of a long run (set by the caller; reduced())
        self.kind = "steady"
        self.finite = True
        if steady:
            return
        # the centre ±π/2 nearer θ0 (|χ0| ≤ π/2), χ0 reduced to (−π, π]
        sgn = 1.0 if math.sin(theta0) >= 0 else -1.0
        try:
            self._setup(sgn, False, theta0, theta_dot0)
            if self.kind == "far":          # through z = ∞ only: the other centre
                self._setup(sgn, True, theta0, theta_dot0)
        except (ValueError, ZeroDivisionError, OverflowError):     # beyond doubles: the caller integrates
            self.kind = "far"
        if self.kind == "steady":
            return
        self.finite = self.kind != "far" and all(math.isfinite(x) for x in (self.lam, self.u0, self.m, self.m1))

    def _setup(self, sgn, flip, theta0, thd0):
        """Coefficients about the centre θc = sgn·π/2 (flip: about the opposite one, the
        trigonometric values still taken from χ about the nearer centre, |χn| ≤ π/2)."""
        # θ0 − θc with θc the true ±π/2: the subtraction of the double π/2 is exact next to it, and
        # the rest of π/2 (_HALF_PI_LO) is added after, so that a start 1e-6 rad from the centre keeps
        # its relative precision (the timing along a separatrix depends on it; issue 28's oracle)
        chin = math.remainder(theta0 - sgn * math.pi / 2, 2 * math.pi) - sgn * _HALF_PI_LO
        sc, hs, hc = math.sin(chin), math.sin(chin / 2), math.cos(chin / 2)
        a, b, cc, chi0 = self.a, sgn * self.b, math.cos(chin), chin
        self.bsign = -sgn if flip else sgn      # G about the centre: a cos²χ + bsign·b cos χ + c0
        if flip:        # χ = χn ∓ π: sin χ = −sin χn, sin(χ/2)² = cos(χn/2)², cos χ = −cos χn, b → −b
            chi0 = chin - math.copysign(math.pi, chin)
            b, sc, hs, hc, cc = -b, -sc, hc, hs, -cc
            self.z0 = z0 = -hs / hc
        else:
            self.z0 = z0 = hs / hc
        self.offset = theta0 - chi0            # θ = offset + χ (offset = θc + 2πk)
        self.A0 = A0 = 0.25 * (thd0 * thd0 + a * sc * sc + 2.0 * b * hs * hs)
        self.A4 = A4 = 0.25 * (thd0 * thd0 + a * sc * sc - 2.0 * b * hc * hc)
        c0 = thd0 * thd0 - a * cc * cc - b * cc
        self.A2 = A2 = 0.5 * (c0 - a)
        self.x0 = x0 = z0 * z0
        self.zd0 = zd0 = 0.5 * thd0 * (1.0 + x0)        # ż(0)
        P0 = zd0 * zd0
        # P about x0: P(x0 + d) = A4 d² + P1 d + P0 with P1 = P'(x0) from θ̈0 (37.12) and θ̇0, so the roots
        # come as offsets d from x0 with their own relative precision (a small swing off ±π/2)
        P1 = -(a * cc + 0.5 * b) + 0.5 * thd0 * thd0 * (1.0 + x0)
        ds = quadratic_roots(A4, P1, P0)          # P0 = 0 (θ̇0 = 0): d = 0 and −P1/A4 exactly
        below = [d for d in ds if d <= 0.0 and x0 + d >= 0.0 and not (d == 0.0 and P1 < 0)]
        above = [d for d in ds if d >= 0.0 and not (d == 0.0 and P1 > 0)]
        d_lo = max(below) if below else None
        d_hi = min(above) if above and math.isfinite(min(above)) else None
        if d_lo is not None and d_lo == d_hi:       # a double root at x0: an equilibrium within rounding
            self.kind = "steady"
        elif d_lo is None and d_hi is None:
            self._circulation(A0, A4, A2, chi0, thd0)
        elif d_lo is None:
            self._libration(A0, A4, x0, d_hi, z0, zd0)
        elif d_hi is None:
            self.kind = "far"
        else:
            self._band(A4, x0, -d_lo, d_hi, z0, zd0)

    def _libration(self, A0, A4, x0, r_hi, z0, zd0):
        self.kind = "libration"
        x1 = x0 + r_hi
        self.z1 = z1 = math.sqrt(x1)
        m = A4 * x1 * x1 / A0
        self.m, self.m1 = m, (2.0 * A0 + self.A2 * x1) / A0     # 1 − m: A4 x1² = −A2 x1 − A0
        if not 0.0 <= self.m1:
            self.m1 = 0.0
        self.lam = math.sqrt(A0 / x1)
        self.K = quarter_period(self.m1)
        S = max(-1.0, min(1.0, z0 / z1))
        cn = math.copysign(math.sqrt(r_hi / x1), zd0 if zd0 != 0.0 else 1.0)     # cn² = (x1 − x0)/x1
        v = S * _rf(cn * cn, 1.0 - m * S * S, 1.0)
        self.u0 = v if cn >= 0.0 else 2.0 * self.K - v

    def _band(self, A4, x0, r_lo, r_hi, z0, zd0):
        self.kind = "band"
        self.sz = 1.0 if z0 > 0 else -1.0
        x_hi = x0 + r_hi
        self.zh = math.sqrt(x_hi)
        D = r_hi + r_lo
        self.m, self.m1 = D / x_hi, (x0 - r_lo) / x_hi
        self.lam = math.sqrt(-A4 * x_hi)
        self.K = quarter_period(self.m1)
        sn2, cn2 = r_hi / D, r_lo / D
        v = math.sqrt(sn2) * _rf(cn2, x0 / x_hi, 1.0)
        self.u0 = v if zd0 * self.sz <= 0.0 else -v

    def _circulation(self, A0, A4, A2, chi0, thd0):
        if A4 <= 0.0:           # the far equilibrium reached asymptotically: from the other centre
            self.kind = "far"
            return
        self.kind = "circulation"
        g = math.sqrt(A0 * A4)
        self.beta = math.sqrt(math.sqrt(A0 / A4))
        self.m, self.m1 = 0.5 - A2 / (4.0 * g), 0.5 + A2 / (4.0 * g)
        self.lam = 2.0 * math.sqrt(g)
        self.sigma = 1.0 if thd0 > 0 else -1.0
        self.K = quarter_period(self.m1) if self.m1 > 0 else math.inf
        phi0 = 2.0 * math.atan(self.z0 / self.beta)
        s, c = math.sin(phi0), math.cos(phi0)
        v = s * _rf(c * c, 1.0 - self.m * s * s, 1.0)
        self.u0 = v if c >= 0.0 else math.copysign(2.0 * self.K, phi0) - v

    @property
    def period(self) -> float:
        """Period of θ(t) (of a full revolution when θ circulates) [s]; inf when steady."""
        if self.kind == "steady" or self.lam == 0.0:
            return math.inf
        n = 2.0 if self.kind == "band" else 4.0
        return n * self.K / self.lam

    def evaluate(self, t):
        """θ(t), θ̇(t): floats for a float t (no numpy), else arrays (the initial state itself
        at t = 0)."""
        xp = ops_for(t)
        t = float(t) if xp is FLOAT_OPS else xp.asarray(t, dtype=float)
        if self.kind == "steady":
            if xp is FLOAT_OPS:
                return self.theta0, 0.0
            return xp.full_like(t, self.theta0), xp.zeros_like(t)
        if self.kind == "circulation":
            th, thd = self._eval_circ(xp, t)
        else:
            u = self.phase.reduce(t)[1] if self.phase is not None else self.lam * t + self.u0
            sn, cn, dn = ellipj_any(u, self.m, self.m1)
            if self.kind == "libration":
                z = self.z1 * sn
                zd = self.z1 * self.lam * cn * dn
            else:
                z = self.sz * self.zh * dn
                zd = -self.sz * self.zh * self.lam * self.m * sn * cn
            th = self.offset + 2.0 * xp.arctan(z)
            thd = 2.0 * zd / (1.0 + z * z)
        at0 = t == 0
        return xp.where(at0, self.theta0, th), xp.where(at0, self.theta_dot0, thd)

    def _eval_circ(self, xp, t):
        if self.phase is not None:      # u = σλt + u0 = n·4K + u (double-double: long runs)
            n, u = self.phase.reduce(t)
        else:
            u = self.sigma * self.lam * t + self.u0
            n = xp.round(u / (4.0 * self.K)) if math.isfinite(self.K) else 0.0
        sn, cn, dn = ellipj_any(u, self.m, self.m1)
        phi = 2.0 * math.pi * n + xp.arctan2(sn, cn)
        bt = self.beta
        chi = phi + 2.0 * xp.arctan2((bt - 1.0) * sn, (1.0 + bt) + (1.0 - bt) * cn)
        dchi = 2.0 * bt / ((1.0 + bt * bt) + (1.0 - bt * bt) * cn)
        return self.offset + chi, dchi * self.sigma * self.lam * dn
