"""Independent reference for two-particle impact (notes §28), in mpmath at 50
digits, written straight from the notes' equations:

* smooth: normal components from (28.10), tangential components kept (28.12),
  impulse (28.13); for mB = inf the limits of (28.10);
* general: t from (28.40), f from (28.41), impulse (28.24, 28.26), velocities
  (28.30a,b), theta (28.40) and the bounds phi1, phi2 from (28.50) as printed
  (arccos form).

Float inputs are converted exactly (mpf(float)), so the reference is the exact
answer for the very numbers the solver receives.
"""

from __future__ import annotations

import math

from mpmath import mp, mpf

mp.dps = 50


def _v(x):
    return [mpf(c) for c in x]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(a):
    return mp.sqrt(dot(a, a))


def impact(mA, mB, vA1, vB1, n, e=None, eta=None, phi=0.0, t=None):
    inf = math.isinf(mB)
    mA = mpf(mA)
    mB = None if inf else mpf(mB)
    vA1, vB1, n = _v(vA1), _v(vB1), _v(n)
    nn = norm(n)
    n = [c / nn for c in n]
    dv1 = [x - y for x, y in zip(vA1, vB1)]
    a = dot(dv1, n)
    m_star = mA if inf else mA * mB / (mA + mB)                   # (28.14)
    out = {"m_star": m_star, "approach_speed": a, "impact": a > 0}
    if a <= 0:
        out.update(vA2=vA1, vB2=vB1, impulse=[mpf(0)] * 3, energy_loss=mpf(0))
        return out
    if e is not None:
        e = mpf(e)
        vA1n, vB1n = dot(vA1, n), dot(vB1, n)
        if inf:
            vA2n = -e * vA1n + (1 + e) * vB1n
            vB2n = vB1n
        else:
            M = mA + mB
            vA2n = (mA - e * mB) / M * vA1n + mB * (1 + e) / M * vB1n        # (28.10)
            vB2n = mA * (1 + e) / M * vA1n + (mB - e * mA) / M * vB1n
        vA2 = [x + (vA2n - vA1n) * c for x, c in zip(vA1, n)]             # (28.12)
        vB2 = [x + (vB2n - vB1n) * c for x, c in zip(vB1, n)]
        impulse = [-m_star * (1 + e) * a * c for c in n]                  # (28.13)
        loss = (1 - e * e) * m_star * a * a / 2                           # (28.16)
        out.update(vA2=vA2, vB2=vB2, impulse=impulse, energy_loss=loss,
                   separation_speed=vB2n - vA2n)
    else:
        eta, phi = mpf(eta), mpf(phi)
        w = [x - a * c for x, c in zip(dv1, n)]
        if t is None:
            tt = [c / norm(w) for c in w]
        else:
            tt = _v(t)
            tt = [x - dot(tt, n) * c for x, c in zip(tt, n)]
            tn = norm(tt)
            tt = [c / tn for c in tt]
        f = [-(mp.cos(phi) * x + mp.sin(phi) * y) for x, y in zip(n, tt)]  # (28.41)
        mag = m_star * (1 + eta) * (-dot(f, dv1))                          # (28.26)
        impulse = [mag * c for c in f]
        vA2 = [x + c / mA for x, c in zip(vA1, impulse)]                   # (28.30a)
        vB2 = vB1 if inf else [x - c / mB for x, c in zip(vB1, impulse)]   # (28.30b)
        dv2 = [x - y for x, y in zip(vA2, vB2)]
        loss = m_star * (1 - eta * eta) * dot(f, dv1) ** 2 / 2             # (28.32)
        theta = mp.atan2(dot(dv1, tt), a)                                  # (28.40)
        phi1, phi2 = bounds_28_50(theta, eta)
        out.update(vA2=vA2, vB2=vB2, impulse=impulse, energy_loss=loss,
                   separation_speed=-dot(dv2, n), theta=theta, phi1=phi1, phi2=phi2, t=tt,
                   P1=dot(impulse, [-x for x in dv1]) > 0, P2=-dot(impulse, n) > 0,
                   P3=-dot(dv2, n) >= 0, P4=loss >= 0)
    if not inf:
        out["T1"] = (mA * dot(vA1, vA1) + mB * dot(vB1, vB1)) / 2
        out["T2"] = (mA * dot(out["vA2"], out["vA2"]) + mB * dot(out["vB2"], out["vB2"])) / 2
        out["G1"] = [mA * x + mB * y for x, y in zip(vA1, vB1)]
    return out


def bounds_28_50(theta, eta):
    """(28.50a,b) as printed.  The arccos argument approaches 1 (eta -> 0,
    theta -> 0), where arccos loses half the digits, so evaluate at 120
    digits (and clamp the argument to [-1, 1])."""
    with mp.workdps(120):
        theta, eta = mpf(theta), mpf(eta)
        rho = (1 - eta) / (1 + eta)
        c2, s = mp.cos(theta) ** 2, mp.sin(theta)
        root = mp.sqrt(1 - rho * rho * c2)
        clamp = lambda x: min(mpf(1), max(mpf(-1), x))  # noqa: E731
        phi1 = -mp.acos(clamp(rho * c2 + root * s)) / 2                    # (28.50a)
        phi2 = mp.acos(clamp(rho * c2 - root * s)) / 2                     # (28.50b)
    return +phi1, +phi2
