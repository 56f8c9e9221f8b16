"""Exact motion of the heavy symmetric top (notes §38) by Jacobi elliptic functions.

With u = cosθ, v = 1 − u, w = 1 + u (so sin²θ = v w), the integrals E, H_O·e3 and
ω3 give u̇² = f(u) = (α − βu)(1 − u²) − (b − cu)² (β = 2mgL/I11, c = I33 ω3/I11).
The cubic is formed about u0 = cosθ0 (x = u − u0, constant term (θ̇0 sinθ0)² exact):

    f = βx³ + F2 x² + F1 x + F0 = (1 − ξ3 x) Q(x),   Q = a2 x² + a1 x + F0,

where ξ3 = 1/x3 is the reciprocal of the root above the motion (u3 ≥ 1; ξ3 = 0 when
mgL = 0, so the torque-free top is the same formula), a1 = F1 + F0 ξ3, a2 = F2 + a1 ξ3 = −β x3
(the last form: no cancellation when u3 is next to u0, a top released near the vertical).
The roots x1 ≤ 0 ≤ x2 of Q bound the motion; the one near a pole is polished in v or w,
where it has full relative precision.  Δ = x2 − x1 is the nutation amplitude in u, and

    m = ξ3 Δ/(1 − ξ3 x1),  m1 = 1 − m = (1 − ξ3 x2)/(1 − ξ3 x1),  λ² = −a2 (1 − ξ3 x1)/4,

    v = v2 + Δ m1 sd²(τ),   w = w1 + Δ cd²(τ),   τ = λt + τ0   (τ = 0 at θ_min),

each written from its own root so that neither cancels near its pole.  The rates
follow from the integrals H_O·e3 and ω3 (partial fractions):

    ψ̇ = ½(B/v + B'/w),   φ̇ = ω3 (I11 − I33)/I11 − ½B/v + ½B'/w,
    B = b − c = (H·e3 − I33ω3)/I11,   B' = b + c,

and ψ, φ from ∫dτ/v and ∫dτ/w, elliptic integrals of the third kind written in
Carlson's symmetric forms (dyncli.elliptic's elliprf/elliprj/elliprc, no scipy): with s = sn τ,
c = cn τ, d = dn τ,

    v2 ∫dτ/v = F − (ν + m)/3 s³ R_J(c², d², 1, 1 + νs²),      ν = k/v2 (ν ≤ 1)
             = s R_C(c²d², (1+νs²)(1+ms²/ν)) + m/(3ν) s³ R_J(c², d², 1, 1 + ms²/ν)
               − m/3 s³ R_J(c², d², 1, 1 + νs²)                      (ν > 1, DLMF 19.7.8)
    w2 ∫dτ/w = F + (n' − m)/3 s³ R_J(c², d², 1, c² + (1 − n') s²),   n' = (m w1 + Δ)/w2,
             (n' − m = m1 Δ/w2 and 1 − n' = m1 w1/w2 formed as products),

k = Δ m1 − m v2 = Δ β(u3 − 1)/γ ≥ 0, F = s R_F(c², d², 1): every term positive where the
parameter is large.  τ is reduced modulo the period 2K; whole periods add 2n times the
complete integrals, so each requested time costs the same whatever t.  Where the axis
passes exactly through the vertical (B = 0 or B' = 0) the 3-1-3 angles jump by π
there (ψ ± π with φ ∓ π at θ = 0, φ ± π at θ = π), as the orientation requires.
"""

from __future__ import annotations

import math
import sys

from dyncli.backends import FLOAT_OPS, array_ops, ops_for
from dyncli.elliptic import ellipj, elliprc, elliprf, elliprj
from dyncli.rootfind import brent as _brent

EPS = sys.float_info.epsilon


def _polish(coef, x, lo, hi, iters=12):
    """Newton on the polynomial ``coef`` (highest first) from x, kept in [lo, hi]."""
    def ev(z):
        p = dp = 0.0
        for a in coef:
            dp = dp * z + p
            p = p * z + a
        return p, dp
    fx, d = ev(x)
    for _ in range(iters):
        if d == 0 or not math.isfinite(d):
            break
        xn = min(max(x - fx / d, lo), hi)
        fn, dn = ev(xn)
        if not abs(fn) < abs(fx):
            break
        x, fx, d = xn, fn, dn
    return x


def _xi3(beta, F2, F1, F0, v0, D, B):
    """ξ3 = 1/x3, x3 the largest root of βx³ + F2x² + F1x + F0 (0 when β = 0).

    R(ξ) = F0ξ³ + F1ξ² + F2ξ + β has the roots 1/x; R(0) = β > 0 and R(1/v0) = f(1)/v0³ ≤ 0
    (f(1) = −(b − c)²), and x2 ≤ v0 ≤ x3, so ξ3 is the one root in (0, 1/v0]: bracketed."""
    if beta == 0.0:
        return 0.0

    def R(z):
        return ((F0 * z + F1) * z + F2) * z + beta

    # ξ ≤ 1e60: x3 ≥ v0 is below 1e-60 only for a top within 1e-30 rad of a marginally stable vertical
    hi = min(1.0 / v0, 1e60) if v0 > 0 else 1.0
    # R(1/v0) = −B²/v0³: at rounding level, u = 1 is (numerically) a root
    at_root = v0 > 0 and abs(R(hi)) <= 64 * EPS * (abs(F0) * hi * hi * hi + abs(F1) * hi * hi + abs(F2) * hi + beta)
    if (B == 0.0 or at_root) and v0 > 0 and D > 0:
        # b = c: u = 1 (x = v0) is a root, and with D = α − β > 0 it is the top of the motion (u2 = 1):
        # x1, x3 are the roots of f(x)/(x − v0) = βx² + p1 x + p0, p0 = −F0/v0 (no cancellation)
        p1, p0 = F2 + beta * v0, -F0 / v0
        disc = math.sqrt(max(p1 * p1 - 4.0 * beta * p0, 0.0))
        qq = -0.5 * (p1 + math.copysign(disc, p1))
        roots = [qq / beta] + ([p0 / qq] if qq != 0 else [])
        x3 = max(roots)
        return 1.0 / x3 if x3 > v0 else hi
    if (B == 0.0 or at_root) and v0 > 0:         # u = 1 is u3 (D ≤ 0)
        return hi
    while R(hi) > 0 and math.isfinite(hi) and v0 == 0:      # θ0 = 0: widen until the sign changes
        hi *= 2.0
    if not math.isfinite(hi) or R(hi) > 0:                  # round-off at a root
        hi = 1.0 / v0 if v0 > 0 else math.inf
        return hi if math.isfinite(hi) else 0.0
    return _brent(R, 0.0, hi, xtol=1e-300, rtol=4 * EPS, maxiter=400)


class Nutation:
    """Roots of the nutation cubic and the constants of the elliptic solution."""

    def __init__(self, A, C, mgL, theta0, theta_dot0, psi_dot0, omega3):
        s0 = math.sin(theta0)
        self.v0 = v0 = 2.0 * math.sin(theta0 / 2) ** 2
        self.w0 = w0 = 2.0 * math.cos(theta0 / 2) ** 2
        u0 = math.cos(theta0)
        K = theta_dot0 ** 2 + (psi_dot0 * s0) ** 2       # α − βu0 = |ω⊥|²
        P = psi_dot0 * s0 * s0                           # b − c u0
        self.beta = beta = 2.0 * mgL / A
        self.c = c = C * omega3 / A
        F0 = (theta_dot0 * s0) ** 2
        F1 = -beta * s0 * s0 - 2.0 * u0 * K + 2.0 * c * P
        F2 = 2.0 * beta * u0 - K - c * c
        self.P = P
        self.B, self.Bp = P - c * v0, P + c * w0
        self.D, self.Dp = K - beta * v0, K + beta * w0
        self.finite = all(math.isfinite(z) for z in (F0, F1, F2, self.B, self.Bp, self.D, self.Dp))
        if not self.finite:
            return
        xi = _xi3(beta, F2, F1, F0, v0, self.D, self.B)
        a1 = F1 + F0 * xi
        # F2 + a1 ξ3 = −β/ξ3 (ξ3 is a root of F0ξ³ + F1ξ² + F2ξ + β): the sum cancels when x3 is small
        a2 = -beta / xi if xi > 0 else F2 + a1 * xi
        if F0 == 0.0:
            r = -a1 / a2 if a2 != 0 else 0.0
            x1, x2 = (r, 0.0) if r < 0 else (0.0, r)
        else:
            # the discriminant a1² − 4 a2 F0 scaled by its size (a2 F0 underflows for a top within
            # ~1e-73 rad of the vertical, where a1 may cancel to 0: q would be 0, F0/q a ZeroDivisionError)
            sa = 2.0 * math.sqrt(abs(a2)) * math.sqrt(F0)
            sc = max(abs(a1), sa)
            disc = sc * math.sqrt(max((a1 / sc) ** 2 - math.copysign(1.0, a2) * (sa / sc) ** 2, 0.0)) if sc > 0 else 0.0
            q = -0.5 * (a1 + math.copysign(disc, a1))
            ra, rb = q / a2, F0 / q
            x1, x2 = min(ra, rb, 0.0), max(ra, rb, 0.0)
        x2, x1 = min(x2, v0), max(x1, -w0)
        self.x1, self.x2 = x1, x2          # relative precision: the phase at t = 0
        v2, w1 = v0 - x2, w0 + x1
        B, Bp, D, Dp = self.B, self.Bp, self.D, self.Dp
        # polish a root near a pole in v or w only where v0 − x2 (w0 + x1) cancelled: Newton there
        # would spoil a near-double root (a steady precession) that the quadratic gives to rounding
        if v2 < 0.01 * v0 and x2 != 0.0:       # g(v) = f(1 − v), relative precision near θ = 0
            v2 = _polish([-beta, 2 * beta - D - c * c, 2 * D - 2 * B * c, -B * B], v2, 0.0, v0)
            x2 = v0 - v2
        if w1 < 0.01 * w0 and x1 != 0.0:       # h(w) = f(w − 1), near θ = π
            w1 = _polish([beta, -(Dp + 2 * beta + c * c), 2 * Dp + 2 * Bp * c, -Bp * Bp], w1, 0.0, w0)
            x1 = w1 - w0
        self.v2, self.w1 = v2, w1
        self.delta = delta = x2 - x1
        self.v1, self.w2 = v0 - x1, w0 + x2
        den = 1.0 - xi * x1
        self.m = xi * delta / den
        self.m1 = (1.0 - xi * x2) / den
        self.gamma = -a2 * den
        self.lam = 0.5 * math.sqrt(max(self.gamma, 0.0))
        # β(u3 − 1) ≥ 0: from the product of the roots of g where v2 > 0
        bu3 = (B / self.v1) * (B / v2) if v2 > 0 else -a2 * (1.0 - xi * v0)
        self.k = delta * bu3 / self.gamma if self.gamma > 0 else 0.0
        self.kp = self.m * w1 + delta

    @staticmethod
    def _theta(v, w):
        """θ from v = 1 − cosθ or w = 1 + cosθ, whichever is smaller (full precision)."""
        if v <= w:
            return 2.0 * math.asin(math.sqrt(min(v, 2.0) / 2.0))
        return math.pi - 2.0 * math.asin(math.sqrt(min(w, 2.0) / 2.0))

    @property
    def theta_min(self):
        return self._theta(self.v2, self.w2)

    @property
    def theta_max(self):
        return self._theta(self.v1, self.w1)


def _legendre_F(s, c, d2):
    return s * elliprf(c * c, d2, 1.0)


def _integrals(nu, np_m, one_np, m, s, c, d2):
    """Jv = v2 ∫dτ/v, Jw = w2 ∫dτ/w over [0, τ] and Jd = Jw − Jv (module docstring),
    each as a sum of positive terms where the parameter is large."""
    s2, c2, s3 = s * s, c * c, s * s * s
    F = _legendre_F(s, c, d2)
    tw = (np_m / 3.0) * s3 * elliprj(c2, d2, 1.0, c2 + one_np * s2)
    Jw = F + tw
    if nu <= 1.0:
        tv = ((nu + m) / 3.0) * s3 * elliprj(c2, d2, 1.0, 1.0 + nu * s2)
        return F - tv, Jw, tw + tv
    Jv = s * elliprc(c2 * d2, (1.0 + nu * s2) * (1.0 + m * s2 / nu))
    if m != 0.0:
        Jv = Jv + (m / (3.0 * nu)) * s3 * elliprj(c2, d2, 1.0, 1.0 + m * s2 / nu) \
            - (m / 3.0) * s3 * elliprj(c2, d2, 1.0, 1.0 + nu * s2)
    return Jv, Jw, Jw - Jv


class ExactTop:
    """The elliptic solution from one initial state (angles, rates at t = 0)."""

    def __init__(self, A, C, mgL, psi0, theta0, phi0, psi_dot0, theta_dot0, phi_dot0):
        self.A, self.C, self.mgL = A, C, mgL
        self.omega3 = W3 = psi_dot0 * math.cos(theta0) + phi_dot0
        # at a pole θ̇0 must point into [0, π]: the same motion with ψ + π (and φ ∓ π)
        if theta0 == 0.0 and theta_dot0 < 0:
            psi0, phi0, theta_dot0 = psi0 + math.pi, phi0 - math.pi, -theta_dot0
        elif theta0 == math.pi and theta_dot0 > 0:
            psi0, phi0, theta_dot0 = psi0 + math.pi, phi0 + math.pi, -theta_dot0
        self.psi0, self.phi0, self.theta0 = psi0, phi0, theta0
        self.initial = (psi0, theta0, phi0, psi_dot0, theta_dot0, phi_dot0, psi_dot0 * math.sin(theta0))
        self.nut = n = Nutation(A, C, mgL, theta0, theta_dot0, psi_dot0, W3)
        self.phase = None                        # the double-double phase of a long run (reduced())
        self.spin_free = W3 * (A - C) / A
        if not n.finite:
            return
        self.sleeping = (n.v0 == 0.0 or n.w0 == 0.0) and theta_dot0 == 0.0
        self.steady = n.delta == 0.0 or self.sleeping or not n.lam > 0
        if self.steady:
            return
        self._constants(theta_dot0)

    def _constants(self, theta_dot0):
        n = self.nut
        m1 = n.m1
        self.K = float(elliprf(0.0, m1, 1.0))
        # phase at t = 0, from the nearer turning point
        # (sn²: cn² = rv : m1 rw at τ0, rv + rw = 1, from the roots of Q about u0)
        rv, rw = min(max(n.x2 / n.delta, 0.0), 1.0), min(max(-n.x1 / n.delta, 0.0), 1.0)
        if rv <= 0.5:
            h = math.hypot(math.sqrt(rv), math.sqrt(m1 * rw))
            sn, cn = math.sqrt(rv) / h, math.sqrt(m1 * rw) / h
            tau0 = float(_legendre_F(sn, cn, cn * cn + m1 * sn * sn))
        else:       # from the lower turning point: cd²(τ0) = sn²(K − τ0) = rw
            sn, cn = math.sqrt(rw), math.sqrt(rv)
            tau0 = self.K - float(_legendre_F(sn, cn, cn * cn + m1 * sn * sn))
        self.tau0 = math.copysign(tau0, theta_dot0) if theta_dot0 != 0 else tau0
        self.nu = n.k / n.v2 if n.v2 > 0 else math.inf
        self.np_m = m1 * n.delta / n.w2        # n' − m, without cancellation
        self.one_np = m1 * n.w1 / n.w2
        self.Jc = self._J(1.0, 0.0, m1)          # the complete integrals (τ = K), plain floats
        self._J0 = None                          # the integrals at τ0: when first evaluated (numpy)

    @property
    def J0(self):
        if self._J0 is None:
            P = 2.0 * self.K
            n0 = FLOAT_OPS.round(self.tau0 / P)
            self._J0 = self._at_phase(FLOAT_OPS, self.tau0 - n0 * P, n0)[1]
        return self._J0

    def reduced(self, xp, t):
        """(n, r) with τ = λt + τ0 = n·2K + r, |r| ≤ K: by :attr:`phase` (a double-double
        :class:`dyncli.phase.ReducedPhase`, set by the caller for long runs) when set, else in doubles
        (an absolute error of ~ε·λt)."""
        if self.phase is not None:
            return self.phase.reduce(t)
        P = 2.0 * self.K
        tau = self.nut.lam * t + self.tau0
        n = xp.round(tau / P)
        return n, tau - n * P

    def _J(self, s, c, d2):
        if self.nu == math.inf:          # v2 = 0: the B/v term is absent (B = 0)
            nu = 1.0
        else:
            nu = self.nu
        return _integrals(nu, self.np_m, self.one_np, self.nut.m, s, c, d2)

    def _at_phase(self, xp, r, nper):
        """(sn, cn, dn) at τ = nper·2K + r (|r| ≤ K) and (Jv, Jw, Jd) from τ = 0, whole periods included
        (sn, cn, dn by the AGM in m1 = 1 − m given exactly, accurate next to the separatrix); on backend xp."""
        K, m1 = self.K, self.nut.m1
        a = xp.abs(r)
        far = a > 0.5 * K
        # past K/2 from the reflection ρ = K − |r|: sn = cd ρ, cn = √m1 sd ρ, dn = √m1 nd ρ, so cn and
        # dn keep their relative precision where they are small (next to the separatrix, m1 → 0)
        s1, c1, d1 = ellipj(xp.where(far, K - a, a), self.nut.m, m1)
        d1 = xp.where(d1 != 0, d1, math.nan)     # dn = 0 only at m1 = 0 (sech underflowing): not representable
        q = math.sqrt(m1)
        sn = xp.sign(r) * xp.where(far, c1 / d1, s1)
        cn = xp.where(far, q * s1 / d1, c1)
        dn = xp.where(far, q / d1, d1)
        J = self._J(sn, cn, dn * dn)
        with xp.errstate(invalid="ignore"):     # ∫dτ/w is infinite (unused) when w1 = 0 (a pole passage)
            return (sn, cn, dn), tuple(j + 2.0 * nper * jc for j, jc in zip(J, self.Jc))

    def evaluate(self, t):
        """psi, theta, phi, psi_dot, theta_dot, phi_dot, S (= ψ̇ sinθ) at times t (the initial state
        itself at t = 0): plain floats for one float time (no numpy), arrays for an array."""
        xp = ops_for(t)
        pole = math.sin(self.theta0) == 0.0
        if xp is FLOAT_OPS:
            t = float(t)
            try:
                out = self._steady(xp, t) if self.steady else self._moving(xp, t)
            except (ZeroDivisionError, OverflowError):      # a degenerate parameter: numpy's inf/nan
                return tuple(float(a[0]) for a in self.evaluate(array_ops().array([t])))
            if t == 0:
                out = [o if pole and k in (3, 5) else x for k, (o, x) in enumerate(zip(out, self.initial))]
            return tuple(float(o) for o in out)
        t = xp.asarray(t, dtype=float)
        out = [xp.array(a, dtype=float) for a in (self._steady(xp, t) if self.steady else self._moving(xp, t))]
        at0 = t == 0
        if xp.any(at0):
            for k, x in enumerate(self.initial):
                if not (pole and k in (3, 5)):
                    out[k][at0] = x
        return tuple(out)

    def _moving(self, xp, t):
        n = self.nut
        nper, r = self.reduced(xp, t)
        (sn, cn, dn), J = self._at_phase(xp, r, nper)
        d2 = dn * dn
        s2, c2 = sn * sn, cn * cn
        tv, tw = n.delta * n.m1 * s2 / d2, n.delta * c2 / d2     # v − v2, w − w1 (sum Δ)
        v, w = n.v2 + tv, n.w1 + tw
        theta = xp.where(v <= w, 2.0 * xp.arcsin(xp.sqrt(xp.minimum(v, 2.0) / 2.0)),
                         xp.pi - 2.0 * xp.arcsin(xp.sqrt(xp.minimum(w, 2.0) / 2.0)))
        with xp.errstate(divide="ignore", invalid="ignore"):
            # exactly at a pole passed through (v2 = 0 or w1 = 0) θ̇ is the incoming rate
            # (a nutation whose range underflowed to 0, Δ = 0: the rate's limit is inf, not an error)
            qv0 = -_inv_sqrt(n.delta * n.m1) if n.v2 == 0.0 else 0.0
            qw0 = _inv_sqrt(n.delta) if n.w1 == 0.0 else 0.0
            ev = xp.where(s2 > 0, n.v2 * d2 / xp.where(s2 > 0, s2, 1.0), math.inf) if n.v2 > 0 else 0.0
            ew = xp.where(c2 > 0, n.w1 * d2 / xp.where(c2 > 0, c2, 1.0), math.inf) if n.w1 > 0 else 0.0
            qv = xp.where(sn == 0, qv0, xp.sign(sn) / xp.sqrt(ev + n.delta * n.m1))
            qw = xp.where(cn == 0, qw0, xp.sign(cn) / xp.sqrt(ew + n.delta))
        theta_dot = 2.0 * n.lam * n.delta * n.m1 * qv * qw / dn
        dJv, dJw, dJd = ((j - j0) / (2.0 * n.lam) for j, j0 in zip(J, self.J0))
        # ∫dt/v, ∫dt/w (×½): ψ̇ = ½(B/v + B'/w), φ̇ = ω3(1 − I33/I11) − ½B/v + ½B'/w
        # B ≠ 0 keeps v ≥ v2 > 0 (f(1) = −B²); a B so small that v2 underflows to 0 is no term
        hv = n.B * dJv / n.v2 if n.B != 0 and n.v2 > 0 else xp.zeros_like(t)
        hw = n.Bp * dJw / n.w2 if n.Bp != 0 and n.w1 > 0 else xp.zeros_like(t)
        phi = self.phi0 + self.spin_free * t - hv + hw
        if n.v2 > 0 and n.w1 > 0:
            # ψ = ψ0 + (b − c u2)∫dt/(vw) + c/2 ∫(w2/w − v2/v)dt: no cancellation of B/v against B'/w
            # when both are large (a fast top, I33ω3/I11 ≫ ψ̇)
            psi = self.psi0 + (n.P - n.c * n.x2) * (dJv / n.v2 + dJw / n.w2) + n.c * dJd
        else:
            psi = self.psi0 + hv + hw
        # passages exactly through a pole: the 3-1-3 angles jump by π there
        P = 2.0 * self.K
        if n.v2 == 0.0 and n.B == 0.0:          # ⌊τ/P⌋ = nper + ⌊r/P⌋
            j = nper + xp.floor(r / P) - math.floor(self.tau0 / P)
            psi, phi = psi + math.pi * j, phi - math.pi * j
        if n.w1 == 0.0 and n.Bp == 0.0:
            j = nper + xp.floor((r - self.K) / P) - math.floor((self.tau0 - self.K) / P)
            psi, phi = psi + math.pi * j, phi + math.pi * j
        # x = u − u0 from the nearer turning point (x2 and x1 have full relative precision)
        x = xp.where(tv <= tw, n.x2 - tv, n.x1 + tw)
        return self._rates(xp, psi, theta, phi, theta_dot, v, w, x)

    def _rates(self, xp, psi, theta, phi, theta_dot, v, w, x):
        """ψ̇ = (b − cu)/(vw) = (P − c x)/(vw) or ½(B/v + B'/w), whichever has the smaller
        round-off there (the first for a fast top, the second next to a pole); φ̇, ψ̇ sinθ.
        Each division by v, w or vw is kept to where that is positive (the others are unused)."""
        n = self.nut
        vp, wp, vw = v > 0, w > 0, v * w
        v1, w1, vw1 = xp.where(vp, v, 1.0), xp.where(wp, w, 1.0), xp.where(vw > 0, vw, 1.0)
        with xp.errstate(divide="ignore", invalid="ignore"):
            bv = xp.where(vp, n.B / v1, 0.0) if n.B != 0 else xp.zeros_like(v)
            bw = xp.where(wp, n.Bp / w1, 0.0) if n.Bp != 0 else xp.zeros_like(w)
            num = n.P - n.c * x
            use_direct = (vw > 0) & ((abs(n.P) + xp.abs(n.c * x)) / vw1 < xp.abs(bv) + xp.abs(bw))
            psi_dot = xp.where(use_direct, num / vw1, 0.5 * (bv + bw))
            S = xp.where(use_direct, num / xp.sqrt(vw1),
                         0.5 * (xp.where(vp, n.B * xp.sqrt(w / v1), 0.0) if n.B != 0 else 0.0)
                         + 0.5 * (xp.where(wp, n.Bp * xp.sqrt(v / w1), 0.0) if n.Bp != 0 else 0.0))
        pole = (v == 0) | (w == 0)
        psi_dot = xp.where(pole, math.nan, psi_dot)
        phi_dot = xp.where(pole, math.nan, self.spin_free - 0.5 * bv + 0.5 * bw)
        if xp is not FLOAT_OPS:
            S = xp.broadcast_to(S, xp.shape(theta)).astype(float)
        return psi, theta, phi, psi_dot, theta_dot, phi_dot, S

    def _steady(self, xp, t):
        """Constant θ (steady precession, a sleeping top): ψ̇, φ̇ constant."""
        n = self.nut
        one, zero = xp.ones_like(t), 0 * t
        v, w, theta = n.v0 * one, n.w0 * one, self.theta0 * one
        psi, theta, phi, psi_dot, theta_dot, phi_dot, S = self._rates(xp, zero, theta, zero, zero, v, w, zero)
        if n.v0 == 0.0 or n.w0 == 0.0:      # sleeping: ψ held, φ carries ψ ± φ (ω3 about the vertical)
            return self.psi0 + zero, theta, self.phi0 + self.omega3 * t, psi_dot, theta_dot, phi_dot, S
        if xp is FLOAT_OPS:
            pd, fd = psi_dot, phi_dot
        else:
            pd, fd = float(psi_dot[0]) if len(t) else 0.0, float(phi_dot[0]) if len(t) else 0.0
        return self.psi0 + pd * t, theta, self.phi0 + fd * t, psi_dot, theta_dot, phi_dot, S


def _inv_sqrt(x: float) -> float:
    """1/√x in plain floats, inf at x = 0 (as numpy's division gives it)."""
    return 1.0 / math.sqrt(x) if x > 0 else math.inf

