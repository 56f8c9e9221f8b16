"""The exact top's phase at long times (issue 28): λ and the nutation period 2K of the
elliptic solution at 40 digits (mpmath, imported here only, on the exact route's long runs),
from the input numbers themselves, for :class:`dyncli.phase.ReducedPhase`.

In doubles the phase τ = λt + τ0 carries ε·λt (λ is known to ε relative; so are mgL and ω3,
products of the inputs): 1e-9 of the motion at λt = 1e7.  Here, with u = cosθ, x = u − u0 and
every product of the inputs formed at 40 digits, the cubic βx³ + F2x² + F1x + F0 of
:mod:`dyncli.topics.top.elliptic` has the roots x1 ≤ 0 ≤ x2 ≤ x3 (mpmath.polyroots), and

    m = (x2 − x1)/(x3 − x1),   λ = ½√(β(x3 − x1)),   K = K(m)        (β > 0),
    m = 0,                     λ = ½√(−F2),          K = π/2         (β = 0: a quadratic),

so the frequency λ/2K is a double-double pair.  The offset τ0 comes from the double solution
(it does not grow with t).  None when the roots do not agree with the double solution's (a
degenerate top): the caller keeps the double phase and says what it costs.
"""

from __future__ import annotations

from dyncli.phase import ReducedPhase, pair

#: digits of the evaluation (the double-double pair needs 32; the rest is headroom for close roots)
DPS = 40


def _cubic(mp, inputs):
    """(β, F2, F1, F0) at DPS digits from (m, g, L, I11, I33, θ0, θ̇0, ψ̇0, φ̇0) (mgL for m, g, L
    when only the product is known: then (mgL, 1, 1))."""
    m, g, L, A, C, th, thd, psd, phd = (mp.mpf(x) for x in inputs)
    s0, u0 = mp.sin(th), mp.cos(th)
    w3 = psd * u0 + phd
    beta, c = 2 * m * g * L / A, C * w3 / A
    Kp = thd * thd + (psd * s0) ** 2           # α − βu0
    P = psd * s0 * s0                          # b − c u0
    F0 = (thd * s0) ** 2
    F1 = -beta * s0 * s0 - 2 * u0 * Kp + 2 * c * P
    F2 = 2 * beta * u0 - Kp - c * c
    return beta, F2, F1, F0


def long_phase(inputs, nut, tau0: float) -> ReducedPhase | None:
    """The double-double phase of the motion (module docstring), or None."""
    import mpmath

    mp = mpmath.mp
    with mpmath.workdps(DPS):
        beta, F2, F1, F0 = _cubic(mp, inputs)
        if beta > 0:
            try:
                roots = mp.polyroots([beta, F2, F1, F0], maxsteps=200, extraprec=2 * DPS * 4, error=False)
            except mp.NoConvergence:        # (coefficients 1e300 apart: the double phase stays)
                return None
            x1, x2, x3 = sorted(mp.re(r) for r in roots)
            if not all(abs(mp.im(r)) <= mp.mpf(10) ** (-DPS // 2) * (1 + abs(r)) for r in roots):
                return None
            x1, x2 = min(x1, 0), max(x2, 0)
            m = (x2 - x1) / (x3 - x1)
            lam = mp.sqrt(beta * (x3 - x1)) / 2
            K = mp.ellipk(m)
        elif F2 < 0:
            m, lam, K = mp.zero, mp.sqrt(-F2) / 2, mp.pi / 2
        else:
            return None
        P = 2 * K
        # agreement with the double solution (the same motion, the same branch of roots)
        if not (abs(lam - nut.lam) <= 1e-6 * lam and abs(m - nut.m) <= 1e-6 * max(m, 1e-3)):
            return None
        return ReducedPhase(pair(lam / P), pair(mp.mpf(tau0) / P), float(P))
