"""Oracle cases: the spring-mass-damper at its boundaries — ζ = 1 ± 1e-12 and exactly 1,
resonance r = 1 ± 1e-9 undamped and r = 1 with ζ = 1e-9, and scales m = 1e-8 kg, k = 1e8 N/m
(ωₙ = 1e8 rad/s, times 1e-8 … 1e-6 s).  The reference response is the exact solution of
m ÿ + c ẏ + k y = f(t) (y = x − L) from the characteristic roots and the complex amplitude of
the forcing, in mpmath at 60 digits (a degenerate case is perturbed by 1e-40: the response is
continuous there)."""

from __future__ import annotations

import mpmath as mp

from tests.oracle.common import case, closed, same, x


def response(m, k, c, y0, v0, force=None, base=None):
    """(y(t), ẏ(t)) functions: force = (F0, ω) for F0 sin ωt; base = (s0, ω) for s = s0 sin ωt."""
    with mp.workdps(60):
        wn2, zw = k / m, c / (2 * m)
        disc = zw ** 2 - wn2
        if disc == 0:
            disc = mp.mpf("1e-40") * wn2
        sq = mp.sqrt(mp.mpc(disc))
        r1, r2 = -zw + sq, -zw - sq
        Z = mp.mpc(0)              # complex amplitude of the particular solution y_p = Im(Z e^{iωt})
        w = mp.mpf(0)
        if force or base:
            amp, w = force if force else base
            rhs = amp / m if force else (k + 1j * c * w) * amp / m
            den = wn2 - w ** 2 + 2j * zw * w
            if den == 0:
                den = mp.mpf("1e-40") * wn2
            Z = rhs / den
        yp0, vp0 = (Z).imag, (1j * w * Z).imag
        A = ((v0 - vp0) - r2 * (y0 - yp0)) / (r1 - r2)
        B = (y0 - yp0) - A

    def y(t):
        with mp.workdps(60):
            return (A * mp.exp(r1 * t) + B * mp.exp(r2 * t)).real + (Z * mp.exp(1j * w * t)).imag

    def v(t):
        with mp.workdps(60):
            return (A * r1 * mp.exp(r1 * t) + B * r2 * mp.exp(r2 * t)).real + (1j * w * Z * mp.exp(1j * w * t)).imag
    return y, v


def _states(y, v, times, wn, L=0, extra=""):
    """x and v at the times: closed form, the phase ωₙt rounded in doubles: cond 16(1 + ωₙ t)."""
    ys = [y(t) for t in times]
    vs = [v(t) for t in times]
    ysc, vsc = max(abs(q) for q in ys), max(abs(q) for q in vs)
    out = []
    for i, t in enumerate(times):
        cond = 16 * (1 + wn * t)
        out += [closed(f"x.{i}", L + ys[i], scale=ysc + abs(L), cond=cond, reason="phase ωₙt rounded" + extra),
                closed(f"v.{i}", vs[i], scale=vsc, cond=cond, reason="phase ωₙt rounded" + extra)]
    return out


def _near_critical():
    out = []
    for name, zeta, regime in (("zeta = 1 + 1e-12", 1 + 1e-12, "overdamped"),
                               ("zeta = 1 - 1e-12", 1 - 1e-12, "underdamped"),
                               ("c = 2 sqrt(km) exactly", None, "critical")):
        c = 2 * x(zeta) if zeta else x(2)
        y, v = response(x(1), x(1), c, x(1), x(0))
        times = [x(0.5), x(5), x(30)]
        doc = {"m": 1, "k": 1, "L": 0, "x0": 1, "v0": 0, "at": [0.5, 5, 30]}
        doc.update({"zeta": zeta} if zeta else {"c": 2})
        out.append(case(name, "vibration", doc, _states(y, v, times, 1),
                        f"free, m = k = 1, x0 = 1: {regime} next to (or at) ζ = 1; the response is smooth in ζ",
                        same_=[same("regime", regime)]))
    return out


def _resonance():
    w = x(1 + 1e-9)
    y, v = response(x(1), x(1), x(0), x(0), x(0), force=(x(1), w))
    times = [x(10), x(1000)]
    G = 1 / abs(1 - w ** 2)
    checks = _states(y, v, times, 1) + [closed("magnification", G, cond=2 / abs(1 - w ** 2),
                                               reason="G = 1/|1 − r²| has condition 2r²/|1 − r²| = 1e9 in r")]
    undamped = case("undamped, r = 1 + 1e-9", "vibration", {
        "m": 1, "k": 1, "L": 0, "x0": 0, "v0": 0, "force": {"amplitude": 1, "omega": 1 + 1e-9}, "at": [10, 1000]},
        checks, "F = sin((1 + 1e-9) t) from rest: the response t/2 growth is smooth in r, G = 5e8",
        same_=[same("regime", "undamped")])
    zeta = x(1e-9)
    y2, v2 = response(x(1), x(1), 2 * zeta, x(0), x(0), base=(x(1e-3), x(1)))
    times2 = [x(100), x(1e4)]
    Gb = mp.sqrt(1 + (2 * zeta) ** 2) / (2 * zeta)
    damped = case("base at r = 1, zeta = 1e-9", "vibration", {
        "m": 1, "k": 1, "L": 0, "zeta": 1e-9, "x0": 0, "v0": 0, "base": {"amplitude": 1e-3, "omega": 1},
        "at": [100, 1e4]}, _states(y2, v2, times2, 1) + [closed("G", Gb, cond=2)],
        "base excitation at resonance with ζ = 1e-9: amplitude 5e5 × s0 reached after ~1e9 s; x(t) grows as t/2",
        same_=[same("regime", "underdamped")])
    return [undamped, damped]


def _scale():
    m, k, c, L = x(1e-8), x(1e8), x(0.02), x(1e-8)
    y, v = response(m, k, c, x(1e-8), x(0))
    times = [x(1e-8), x(1e-7), x(1e-6)]
    return [case("m = 1e-8 kg, k = 1e8 N/m", "vibration", {
        "m": 1e-8, "k": 1e8, "c": 0.02, "L": 1e-8, "x0": 2e-8, "v0": 0, "at": [1e-8, 1e-7, 1e-6]},
        _states(y, v, times, 1e8, L=L) + [closed("omega_n", mp.sqrt(k / m)), closed("zeta", c / (2 * mp.sqrt(k * m)))],
        "ωₙ = 1e8 rad/s, ζ = 0.01, displacement 1e-8 m over 1e-8 … 1e-6 s",
        same_=[same("regime", "underdamped")])]


def cases():
    return _near_critical() + _resonance() + _scale()
