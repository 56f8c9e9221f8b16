"""Independent references for the pendulum, in mpmath at 40 digits (never the code under test).

* :func:`elliptic` — the closed form in mpmath's own elliptic functions: K by ``mp.ellipk``, the
  phase u₀ by ``mp.ellipf`` and θ, θ̇ by ``mp.ellipfun`` (sn, cn, dn), from the inputs as exact
  binary numbers;
* :func:`taylor` — a second formulation: θ̈ = −(g/l) sin θ integrated by ``mp.odefun`` (a Taylor
  series method to the working precision), no elliptic function at all.
"""

from __future__ import annotations

import mpmath as mp

DPS = 40


def modulus(l, g, theta0, theta_dot0):
    """(ω₀, k²) at DPS digits."""
    with mp.workdps(DPS):
        w = mp.sqrt(mp.mpf(g) / mp.mpf(l))
        k2 = mp.sin(mp.mpf(theta0) / 2) ** 2 + (mp.mpf(theta_dot0) / (2 * w)) ** 2
        return w, k2


def period(l, g, theta0, theta_dot0=0.0):
    """The exact period (swing: 4K(k²)/ω₀; over the top: one turn, 2K(1/k²)/(kω₀))."""
    with mp.workdps(DPS):
        w, k2 = modulus(l, g, theta0, theta_dot0)
        if k2 < 1:
            return 4 * mp.ellipk(k2) / w
        return 2 * mp.ellipk(1 / k2) / (mp.sqrt(k2) * w)


def elliptic(l, g, theta0, theta_dot0, t):
    """(θ, θ̇) at time t by mpmath's elliptic functions (swing or rotation; θ₀ in (−π, π])."""
    with mp.workdps(DPS):
        w, k2 = modulus(l, g, theta0, theta_dot0)
        th0, thd0, t = mp.mpf(theta0), mp.mpf(theta_dot0), mp.mpf(t)
        if k2 < 1:
            k = mp.sqrt(k2)
            phi0 = mp.atan2(mp.sin(th0 / 2) / k, thd0 / (2 * w * k))   # am(u₀): sn, cn of u₀
            u = w * t + mp.ellipf(phi0, k2)
            sn, cn = mp.ellipfun("sn", u, m=k2), mp.ellipfun("cn", u, m=k2)
            return 2 * mp.asin(k * sn), 2 * k * w * cn
        k = mp.sqrt(k2)
        s = 1 if thd0 > 0 else -1
        m = 1 / k2
        u = k * w * t + mp.ellipf(s * th0 / 2, m)
        # am(u) = atan2(sn, cn) + nπ, n from u = 2Kn + r
        K = mp.ellipk(m)
        n = mp.nint(u / (2 * K))
        r = u - 2 * K * n
        am = n * mp.pi + mp.atan2(mp.ellipfun("sn", r, m=m), mp.ellipfun("cn", r, m=m))
        return s * 2 * am, s * 2 * k * w * mp.ellipfun("dn", u, m=m)


def separatrix(l, g, theta0, theta_dot0, t):
    """(θ, θ̇) on the separatrix: θ = 2 atan(sinh(ω₀t + u₀)), θ̇ = 2ω₀ sech(...) (θ̇₀ > 0)."""
    with mp.workdps(DPS):
        w = mp.sqrt(mp.mpf(g) / mp.mpf(l))
        u = w * mp.mpf(t) + mp.asinh(mp.tan(mp.mpf(theta0) / 2))
        return 2 * mp.atan(mp.sinh(u)), 2 * w * mp.sech(u)


def taylor(l, g, theta0, theta_dot0, times):
    """(θ, θ̇) at each time by mpmath's Taylor ODE solver (30 digits)."""
    with mp.workdps(30):
        w2 = mp.mpf(g) / mp.mpf(l)
        f = mp.odefun(lambda t, y: [y[1], -w2 * mp.sin(y[0])], 0, [mp.mpf(theta0), mp.mpf(theta_dot0)])
        return [tuple(f(mp.mpf(t))) for t in times]
