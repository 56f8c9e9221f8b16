"""An independent Kepler reference in mpmath (no dyncli import): the classical elements from the
state (eccentricity vector, perifocal frame), Kepler's equation solved by mpmath's findroot at
``DPS`` digits, and the state on the perifocal frame (Vallado, Algorithm 10 and 2)."""

from __future__ import annotations

import mpmath as mp

DPS = 30


def _v(x):
    return mp.matrix([mp.mpf(float(c)) for c in x])


def _cross(a, b):
    return mp.matrix([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def _dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def elements(mu, r, v):
    """dict of e, a (None parabola), p, r_p, r_a, period (None open), h, v_p, v_a at DPS digits."""
    with mp.workdps(DPS):
        mu, r, v = mp.mpf(float(mu)), _v(r), _v(v)
        R = mp.sqrt(_dot(r, r))
        h = _cross(r, v)
        H = mp.sqrt(_dot(h, h))
        ev = _cross(v, h) / mu - r / R
        e = mp.sqrt(_dot(ev, ev))
        eps = _dot(v, v) / 2 - mu / R
        p = H ** 2 / mu
        out = {"e": e, "p": p, "h": H, "r_p": p / (1 + e), "a": -mu / (2 * eps) if eps != 0 else None}
        out["r_a"] = p / (1 - e) if e < 1 else None
        out["period"] = 2 * mp.pi * mp.sqrt(out["a"] ** 3 / mu) if e < 1 else None
        out["v_p"] = H / out["r_p"]
        out["v_a"] = H / out["r_a"] if e < 1 else None
        return out


def state(mu, r, v, t):
    """(x, v) at time t as lists of floats (the particle starts at r, v at t = 0)."""
    with mp.workdps(DPS):
        mu, r, v, t = mp.mpf(float(mu)), _v(r), _v(v), mp.mpf(float(t))
        R = mp.sqrt(_dot(r, r))
        h = _cross(r, v)
        H = mp.sqrt(_dot(h, h))
        ev = _cross(v, h) / mu - r / R
        e = mp.sqrt(_dot(ev, ev))
        p = H ** 2 / mu
        W = h / H
        P = ev / e
        Q = _cross(W, P)
        nu0 = mp.atan2(_dot(r, Q), _dot(r, P))
        if e < 1:
            a = p / (1 - e ** 2)
            E0 = 2 * mp.atan(mp.sqrt((1 - e) / (1 + e)) * mp.tan(nu0 / 2))
            M = E0 - e * mp.sin(E0) + mp.sqrt(mu / a ** 3) * t
            E = mp.findroot(lambda E: E - e * mp.sin(E) - M, M + e * mp.sin(M) / (1 - e * mp.cos(M)) if e < 0.8 else mp.pi * mp.sign(mp.sin(M)) + 2 * mp.pi * mp.floor(M / (2 * mp.pi)) + mp.pi, tol=mp.mpf(10) ** (-DPS + 2))
            nu = 2 * mp.atan2(mp.sqrt(1 + e) * mp.sin(E / 2), mp.sqrt(1 - e) * mp.cos(E / 2))
        else:
            a = p / (e ** 2 - 1)
            H0 = 2 * mp.atanh(mp.sqrt((e - 1) / (e + 1)) * mp.tan(nu0 / 2))
            M = e * mp.sinh(H0) - H0 + mp.sqrt(mu / a ** 3) * t
            Hh = mp.findroot(lambda x: e * mp.sinh(x) - x - M, mp.asinh(M / e), tol=mp.mpf(10) ** (-DPS + 2))
            nu = 2 * mp.atan2(mp.sqrt(e + 1) * mp.sinh(Hh / 2), mp.sqrt(e - 1) * mp.cosh(Hh / 2))
        rr = p / (1 + e * mp.cos(nu))
        x = rr * (mp.cos(nu) * P + mp.sin(nu) * Q)
        vel = mp.sqrt(mu / p) * (-mp.sin(nu) * P + (e + mp.cos(nu)) * Q)
        return [float(c) for c in x], [float(c) for c in vel]
