"""The notes' own formulas (§17), evaluated in mpmath at 50 digits, for
checking the solver's scalar results independently of its (different,
cancellation-free) formulation."""

from __future__ import annotations

import mpmath as mp

DPS = 50


def free_A_phi(w0, v0, omega_n, zeta):
    """(17.12)/(17.22c-e)/(17.24c-e): A, phi or (None, None) when the form does
    not exist (critical, or the overdamped equations have no solution with A ≥ 0)."""
    with mp.workdps(DPS):
        w0, v0, wn, z = (mp.mpf(a) for a in (w0, v0, omega_n, zeta))
        if z == 1:
            return None, None
        if z < 1:
            ws = wn * mp.sqrt(1 - z ** 2)
            A = mp.sqrt(w0 ** 2 + (v0 / ws + z * wn / ws * w0) ** 2)
            if A == 0:
                return mp.mpf(0), None
            # sin φ = w0/A, cos φ = (v0 + ζωw0)/(Aω*)
            return A, mp.atan2(w0 / A, (v0 + z * wn * w0) / (A * ws))
        ws = wn * mp.sqrt(z ** 2 - 1)
        A2 = (v0 / ws + z * wn / ws * w0) ** 2 - w0 ** 2
        if A2 <= 0:
            return None, None
        A = mp.sqrt(A2)
        cosh_phi = (v0 + z * wn * w0) / (A * ws)
        if cosh_phi < 1:
            return None, None
        return A, mp.asinh(w0 / A)


def amplification(r, zeta):
    """(17.30b-d), (17.33), (17.34b) as printed in the notes: G, phi, g, Phi."""
    with mp.workdps(DPS):
        r, z = mp.mpf(r), mp.mpf(zeta)
        if r == 0:
            return mp.mpf(0), mp.mpf(0), mp.mpf(1), mp.mpf(0)
        G = 1 / mp.sqrt((1 / r ** 2 - 1) ** 2 + (2 * z / r) ** 2)
        sphi = -(2 * z / r) * G
        cphi = (1 / r ** 2 - 1) * G
        phi = mp.atan2(sphi, cphi)
        g = mp.sqrt((1 + 4 * z ** 2 * r ** 2) / ((1 - r ** 2) ** 2 + 4 * z ** 2 * r ** 2))
        Phi = mp.atan2(G * sphi, 1 + G * cphi)   # (17.33)
        return G, phi, g, Phi


def peak(fn, lo, hi):
    """Location and value of the maximum of the unimodal fn on [lo, hi], found
    numerically by golden-section search (independent of any peak formula;
    the location is good to ~1e-25, the value to ~1e-50)."""
    with mp.workdps(DPS):
        a, b = mp.mpf(lo), mp.mpf(hi)
        q = (mp.sqrt(5) - 1) / 2
        c, d = b - q * (b - a), a + q * (b - a)
        fc, fd = fn(c), fn(d)
        for _ in range(260):
            if fc > fd:
                b, d, fd = d, c, fc
                c = b - q * (b - a)
                fc = fn(c)
            else:
                a, c, fc = c, d, fd
                d = a + q * (b - a)
                fd = fn(d)
        rp = (a + b) / 2
        return rp, fn(rp)


def G_of(zeta):
    z = mp.mpf(zeta)
    return lambda r: 1 / mp.sqrt((1 / r ** 2 - 1) ** 2 + (2 * z / r) ** 2)


def g_of(zeta):
    z = mp.mpf(zeta)
    return lambda r: mp.sqrt((1 + 4 * z ** 2 * r ** 2) / ((1 - r ** 2) ** 2 + 4 * z ** 2 * r ** 2))
