"""The exact gyroscope's phase at long times (issue 28): λ and the period 4K of θ(t) at 40
digits (mpmath, imported here only, on the exact route's long runs), from the input numbers
themselves, for :class:`dyncli.phase.ReducedPhase`.

In doubles the phase u = λt + u0 carries ε·λt (λ is known to ε relative; so are a and b,
products of the inputs): 1e-9 of the motion at λt = 1e7.  Here a, b, c0 and the biquadratic's
coefficients A0, A4, A2 about the centre the double solution chose (:mod:`dyncli.topics.gyroscope.elliptic`)
are formed at 40 digits, and with its roots

    libration     λ = √(A0/x1),       m = A4 x1²/A0          (x1 the root the motion reaches),
    band          λ = √(−A4 x_hi),    m = (x_hi − x_lo)/x_hi,
    circulation   λ = 2 (A0 A4)^¼,    m = ½ − A2/(4√(A0 A4)),

K = K(m) (m < 0 too), so the frequency σλ/4K is a double-double pair; the offset u0 comes
from the double solution (it does not grow with t).  None when the constants do not agree with
the double solution's: the caller keeps the double phase and says what it costs.
"""

from __future__ import annotations

from dyncli.phase import ReducedPhase, pair

#: digits of the evaluation (the double-double pair needs 32)
DPS = 40


def _coefficients(mp, inputs, bsign):
    """(A0, A4, A2) of P(x) = A4 x² + A2 x + A0 about the double solution's centre, at DPS digits."""
    I1, I2, p, q, th0, thd0 = (mp.mpf(x) for x in inputs)
    a, b = (I1 - I2) * q * q / I2, 2 * I1 * p * q / I2
    s0 = mp.sin(th0)
    c0 = thd0 * thd0 - a * s0 * s0 - b * s0        # G(θ) = a sin²θ + b sinθ + c0
    bc = bsign * b                                 # G about the centre: a cos²χ + bc cos χ + c0
    return (a + bc + c0) / 4, (a - bc + c0) / 4, (c0 - a) / 2


def _nearest_root(mp, A4, A2, A0, near):
    """The root of A4 x² + A2 x + A0 nearest ``near`` and the other one (None if complex)."""
    if A4 == 0:
        return (-A0 / A2, None) if A2 != 0 else (None, None)
    d = A2 * A2 - 4 * A4 * A0
    if d < 0:
        return None, None
    r = [(-A2 + s * mp.sqrt(d)) / (2 * A4) for s in (1, -1)]
    r.sort(key=lambda x: abs(x - near))
    return r[0], r[1]


def long_phase(inputs, g) -> ReducedPhase | None:
    """The double-double phase of the motion ``g`` (a GyroTheta) from (I1, I2, p, q, θ0, θ̇0), or None."""
    import mpmath

    mp = mpmath.mp
    with mpmath.workdps(DPS):
        A0, A4, A2 = _coefficients(mp, inputs, g.bsign)
        sigma = 1
        if g.kind == "libration":
            x1, _ = _nearest_root(mp, A4, A2, A0, mp.mpf(g.z1) ** 2)
            if x1 is None or not x1 > 0:
                return None
            lam, m = mp.sqrt(A0 / x1), A4 * x1 * x1 / A0
        elif g.kind == "band":
            xh, xl = _nearest_root(mp, A4, A2, A0, mp.mpf(g.zh) ** 2)
            if xh is None or xl is None or not xh > 0:
                return None
            lam, m = mp.sqrt(-A4 * xh), (xh - xl) / xh
        elif g.kind == "circulation":
            gg = mp.sqrt(A0 * A4)
            lam, m, sigma = 2 * mp.sqrt(gg), mp.mpf(1) / 2 - A2 / (4 * gg), g.sigma
        else:
            return None
        if not (mp.isfinite(lam) and m < 1):
            return None
        P = 4 * mp.ellipk(m)
        if not (abs(lam - g.lam) <= 1e-6 * lam and abs(m - g.m) <= 1e-6 * max(abs(m), 1e-3)):
            return None
        return ReducedPhase(pair(sigma * lam / P), pair(mp.mpf(g.u0) / P), float(P))
