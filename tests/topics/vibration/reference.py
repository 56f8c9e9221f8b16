"""Independent 50-digit reference for (17.15a) with s = s0 sin(Ωt) (mpmath).

Derived from scratch, not from the solver's formulas: the general solution is
the particular solution Im(F e^{iΩt}/p(iΩ)) (or the secular solution at
undamped resonance) plus c1 e^{s1 t} + c2 e^{s2 t} with the characteristic
roots s1,2 = -ζω ± ω√(ζ²-1) (complex square root), or (c1 + c2 t)e^{-ωt} when
ζ = 1 exactly; c1, c2 are fitted to the initial conditions.
"""

from __future__ import annotations

import mpmath as mp

DPS = 50


def reference(times, *, m=None, k=None, omega_n=None, zeta, L=0.0, x0=None, v0=0.0, s0=0.0, Omega=0.0):
    """Return lists (x, v, w) as mpf at the given times (floats, exact)."""
    with mp.workdps(DPS):
        if omega_n is None:
            wn = mp.sqrt(mp.mpf(k) / mp.mpf(m))
        else:
            wn = mp.mpf(omega_n)
        z = mp.mpf(zeta)
        L = mp.mpf(L)
        x0 = L if x0 is None else mp.mpf(x0)
        v0 = mp.mpf(v0)
        s0 = mp.mpf(s0)
        Om = mp.mpf(Omega)
        F = s0 * Om ** 2
        # particular solution wp(t), wp'(t)
        p = wn ** 2 - Om ** 2 + 2j * z * wn * Om
        if p == 0:
            # ζ = 0, Ω = ωn: wp = a t cos(ωt), a = -F/(2ω)
            sec = -F / (2 * wn)

            def wp(t):
                return sec * t * mp.cos(wn * t), sec * (mp.cos(wn * t) - wn * t * mp.sin(wn * t))
        else:
            Z = F / p

            def wp(t):
                e = mp.expj(Om * t)
                return mp.im(Z * e), mp.im(1j * Om * Z * e)
        w0 = x0 - L
        wd0 = v0 - s0 * Om
        p0, pd0 = wp(mp.mpf(0))
        h0, hd0 = w0 - p0, wd0 - pd0
        if z == 1:
            c1 = h0
            c2 = hd0 + wn * h0

            def wh(t):
                e = mp.exp(-wn * t)
                return (c1 + c2 * t) * e, (c2 - wn * (c1 + c2 * t)) * e
        else:
            q = wn * mp.sqrt(mp.mpc(z ** 2 - 1))
            s1, s2 = -z * wn + q, -z * wn - q
            # c1 + c2 = h0, s1 c1 + s2 c2 = hd0
            c1 = (hd0 - s2 * h0) / (s1 - s2)
            c2 = h0 - c1

            def wh(t):
                e1, e2 = mp.exp(s1 * t), mp.exp(s2 * t)
                return mp.re(c1 * e1 + c2 * e2), mp.re(s1 * c1 * e1 + s2 * c2 * e2)

        xs, vs, ws = [], [], []
        for t in times:
            t = mp.mpf(t)
            hw, hwd = wh(t)
            pw, pwd = wp(t)
            w = hw + pw
            wd = hwd + pwd
            s = s0 * mp.sin(Om * t)
            sd = s0 * Om * mp.cos(Om * t)
            xs.append(w + s + L)
            vs.append(wd + sd)
            ws.append(w)
        return xs, vs, ws


def max_rel_err(got, ref, scale=None):
    """max |got - ref| / scale, scale = max |ref| over the run by default."""
    with mp.workdps(DPS):
        if scale is None:
            scale = max(abs(r) for r in ref)
        if scale == 0:
            scale = mp.mpf(1)
        return float(max(abs(mp.mpf(g) - r) for g, r in zip(got, ref)) / scale)
