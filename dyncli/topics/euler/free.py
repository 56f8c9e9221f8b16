"""Exact motion of the torque-free rigid body, no scipy: ω at one time in plain floats (math,
no numpy import), or at an array of times with numpy (the same formulas on either backend,
:data:`dyncli.backends.FLOAT_OPS` or numpy).

* Axisymmetric body (two equal principal moments): (39.14)-(39.22).
* Asymmetric body: Jacobi elliptic functions.  With the moments sorted so
  that B is the intermediate one and the "polar" axis C the one about which
  ω circulates (sign of H² − 2TB), Euler's equations are solved by

      ω_A = a cn(u),  ω_B = b sn(u),  ω_C = σ c dn(u),   u = u₀ + λ t,

  with a², b², c², λ², m = k² and m₁ = 1 − m formed from the differences
  H² − 2T·I_i written as sums of the initial ω² (no cancellation), so the
  solution stays accurate near the separatrix (spin about the intermediate
  axis).  u₀ = F(φ0 | m) comes from Carlson's R_F of cn(u₀)², dn(u₀)² (the initial
  data, accurate next to the separatrix; the addition theorems from sn, cn, dn of λt
  lost ~1e6 ε there to a difference of nearly equal terms).  sn, cn, dn of u₀ + λt come from the
  arithmetic-geometric mean in terms of m₁ directly (:mod:`dyncli.elliptic`,
  argument reduced modulo 4K); dn = √(m₁ + m cn²) avoids the 0/0 of the usual
  dn formula near u = K.
"""

from __future__ import annotations

import math

from dyncli.backends import FLOAT_OPS, ops_for
from dyncli.elliptic import ellipj, ellipK, elliprf
from dyncli.phase import rounded

EQUAL_TOL = 1e-13


def _parity(perm) -> int:
    p = list(perm)
    s = 1
    for i in range(3):
        for j in range(i + 1, 3):
            if p[i] > p[j]:
                s = -s
    return s


def _separatrix(A, B, C, wA, wC) -> bool:
    """H² = 2TB (the separatrix) decided exactly from the given doubles, to
    within 4 round-offs of each (dyncli.exact): |A(A−B)wA² + C(C−B)wC²| is at
    most what those can change, rel·Σ |I|w²(3|I−B| + |I| + |B|)."""
    from dyncli.exact import INPUT_ROUNDING, fr, sign_within

    terms = [(fr(A), fr(wA)), (fr(C), fr(wC))]
    b = fr(B)
    value = sum(i * (i - b) * w * w for i, w in terms)
    bound = fr(INPUT_ROUNDING) * sum(abs(i) * w * w * (3 * abs(i - b) + abs(i) + abs(b)) for i, w in terms)
    return sign_within(value, bound) == 0


class Asymmetric:
    """Exact ω(t) of a torque-free body with three distinct principal moments."""

    def __init__(self, I, w0):
        I = [float(x) for x in I]
        w0 = [float(x) for x in w0]
        self.I, self.w0 = I, w0
        iA, iB, iC = sorted(range(3), key=lambda k: I[k])
        A, B, C = I[iA], I[iB], I[iC]
        wA, wC = w0[iA], w0[iC]
        DB = A * (A - B) * wA * wA + C * (C - B) * wC * wC      # H² − 2TB
        on_separatrix = _separatrix(A, B, C, wA, wC)
        if on_separatrix:
            DB = 0.0
        perm = (iA, iB, iC) if DB >= 0 else (iC, iB, iA)      # polar axis last
        self.perm = perm
        s = _parity(perm)
        self.sign = s
        A, B, C = (I[k] for k in perm)
        wA, wB, wC = (s * w0[k] for k in perm)
        DA = B * (B - A) * wB * wB + C * (C - A) * wC * wC      # H² − 2TA  (signed)
        DC = A * (C - A) * wA * wA + B * (C - B) * wB * wB      # 2TC − H²  (signed)
        DB = 0.0 if on_separatrix else A * (A - B) * wA * wA + C * (C - B) * wC * wC   # H² − 2TB (signed)
        self.constant = (wA == 0.0 and wB == 0.0) or DC == 0.0 or DA == 0.0 or (DB == 0.0 and wA == 0.0 and wC == 0.0)
        self.separatrix = DB == 0.0
        if self.constant:
            self.m = 0.0
            self.m1 = 1.0
            self.lam = 0.0
            return
        a = math.sqrt(DC / (A * (C - A)))
        b = math.sqrt(DC / (B * (C - B)))
        c = math.sqrt(DA / (C * (C - A)))
        lam = math.sqrt((C - B) * DA / (A * B * C))
        m = (B - A) * DC / ((C - B) * DA)
        m1 = (C - A) * DB / ((C - B) * DA)
        m, m1 = min(max(m, 0.0), 1.0), min(max(m1, 0.0), 1.0)
        if on_separatrix:
            m, m1 = 1.0, 0.0
        sigma = 1.0 if wC >= 0 else -1.0
        self.lam = sigma * math.copysign(1.0, C - B) * lam
        self.a, self.b, self.c, self.sigma = a, b, c, sigma
        self.m, self.m1 = m, m1
        s0 = min(max(wB / b, -1.0), 1.0)
        c0 = min(max(wA / a, -1.0), 1.0)
        d0 = min(max(sigma * wC / c, 0.0), 1.0)
        self.s0, self.c0, self.d0 = s0, c0, d0
        # u0 = F(am⁻¹ s0 | m) from cn(u0)², dn(u0)² as given (Carlson: no cancellation next to the
        # separatrix, where s0 → 1 and the addition theorems lose ~1e6 ε to the difference
        # c0 cv − s0 sv d0 dv of nearly equal terms); cn(u0) < 0 on the far half of the period
        self.u0 = 0.0
        if m1 > 0.0 and not on_separatrix:
            u0 = s0 * elliprf(c0 * c0, d0 * d0, 1.0)
            self.u0 = math.copysign(2.0 * ellipK(m, m1), s0) - u0 if c0 < 0 else u0

    def phase_error(self, t: float) -> float:
        """The error of ω(t) relative to its amplitudes from its phase λt + u0 formed in doubles
        (:func:`dyncli.phase.rounded`); 0 for constant ω and on the separatrix (tanh, sech settle)."""
        if self.constant or self.m1 == 0.0:
            return 0.0
        return rounded(self.lam, t, self.u0)

    @property
    def period(self) -> float | None:
        """Period of ω(t) (4K/|λ|); None on the separatrix or for constant ω."""
        if self.constant:
            return None
        if self.m1 == 0.0:
            return None
        return 4.0 * ellipK(self.m, self.m1) / abs(self.lam)

    def omega(self, t):
        """ω at t (body components): a float gives a tuple of 3 floats (no numpy), an array
        (shape S) an array of shape S + (3,)."""
        xp = ops_for(t)
        t = float(t) if xp is FLOAT_OPS else xp.asarray(t, dtype=float)
        if self.constant:
            return _assemble(xp, t, dict(enumerate(self.w0)))
        try:
            comps = self._components(xp, t)
        except ZeroDivisionError:      # plain floats, constants beyond doubles: nan, as numpy gives
            comps = (math.nan, math.nan, math.nan)
        s = self.sign
        return _assemble(xp, t, {k: s * comp for comp, k in zip(comps, self.perm)})

    def _components(self, xp, t):
        """(ω_A, ω_B, ω_C) at t, on the backend xp (floats or numpy)."""
        m = self.m
        s0, c0 = self.s0, self.c0
        if self.m1 == 0.0:
            # on the separatrix: sn = tanh, cn = dn = sech; u0 from sinh u0 = s0/|c0|
            # (cn >= 0 here, so a negative c0 uses the symmetry (ω_A, ω_C) -> (−ω_A, −ω_C), t -> t)
            flip = -1.0 if c0 < 0 else 1.0
            u0 = math.asinh(s0 / abs(c0)) if c0 != 0 else math.copysign(math.inf, s0)
            u = u0 + flip * self.lam * t
            with xp.errstate(over="ignore"):
                sn, cn = xp.tanh(u), 1.0 / xp.cosh(u)
            cn, dn = flip * cn, cn
        else:
            sn, cn, dn = ellipj(self.lam * t + self.u0, m, self.m1)
        return self.a * cn, self.b * sn, self.sigma * self.c * dn


def _assemble(xp, t, comps):
    """ω from its components by body axis ({0: ω₁, 1: ω₂, 2: ω₃}): a tuple for a float t, else
    an array of shape t.shape + (3,)."""
    if xp is FLOAT_OPS:
        return tuple(float(comps[k]) for k in range(3))
    out = xp.empty(t.shape + (3,))
    for k in range(3):
        out[..., k] = comps[k]
    return out


class Axisymmetric:
    """(39.14)-(39.22): the symmetry axis is the body axis ``k`` (0-based)."""

    def __init__(self, I, w0, k):
        self.k = k
        self.i1 = (k + 1) % 3
        self.i2 = (k + 2) % 3
        I1 = 0.5 * (I[self.i1] + I[self.i2])
        I3 = I[k]
        self.I1, self.I3 = I1, I3
        w01, w02, w03 = w0[self.i1], w0[self.i2], w0[k]
        self.w = (w01, w02, w03)
        self.lam = (I3 - I1) / I1 * w03                     # (39.15)
        lam_vec = (w01, w02, I3 / I1 * w03)                 # (39.18)
        self.alpha = 1.0 if w03 >= 0 else -1.0              # (39.20); ω03 = 0 takes α = 1
        self.psi_dot = self.alpha * math.hypot(*lam_vec)    # (39.20); hypot: no overflow of the squares
        self.theta = math.atan2(math.hypot(w01, w02), abs(lam_vec[2]))   # (39.21)

    def phase_error(self, t: float) -> float:
        """As :meth:`Asymmetric.phase_error`, of the precession phase λt."""
        return rounded(self.lam, t)

    def omega(self, t):
        """ω at t, as :meth:`Asymmetric.omega`."""
        xp = ops_for(t)
        t = float(t) if xp is FLOAT_OPS else xp.asarray(t, dtype=float)
        w01, w02, w03 = self.w
        c, s = xp.cos(self.lam * t), xp.sin(self.lam * t)
        return _assemble(xp, t, {self.i1: w01 * c - w02 * s,          # (39.17a)
                                 self.i2: w01 * s + w02 * c,          # (39.17b)
                                 self.k: w03})                        # (39.12)


def symmetry_axis(I) -> int | None:
    """Index of the symmetry axis of an axisymmetric body (2 for a sphere), else None."""
    scale = max(I)
    eq = [abs(I[(i + 1) % 3] - I[(i + 2) % 3]) <= EQUAL_TOL * scale for i in range(3)]
    if all(eq):
        return 2
    for k in range(3):
        if eq[k]:
            return k
    return None


def exact(I, w0):
    k = symmetry_axis(I)
    return Axisymmetric(I, w0, k) if k is not None else Asymmetric(I, w0)
