"""Oracle cases: rigid bodies in closed form (inertia, planar-moments, rigid-impulse,
rigid-energy, bearing-forces, spin-change, motor-bodies) at extreme scales and mass ratios:
a 1e-8 m cylinder whose principal moments differ by 1e-9, parts 1e8 m long beside 1e-9 kg
points, rates 1e8 rad/s on moments 1e-20 kg m², arms that start 1e-6 rad from the shaft, masses
1e9 and 1e-9 kg on one axis, a motor shaft 1e-9 rad from the plane."""

from __future__ import annotations

import mpmath as mp

from tests.oracle.common import case, closed, dot, norm, same, vclosed, vec, x


def _inertia():
    m, r = x(1e9), x(1e-8)
    h = x(float(mp.sqrt(3) * x(1e-8) * (1 + mp.mpf("1e-9"))))
    It, Ia = m * (3 * r ** 2 + h ** 2) / 12, m * r ** 2 / 2
    mom = sorted([It, It, Ia])
    sc = max(mom)
    cyl = case("tiny cylinder, moments 1e-9 apart", "inertia", {
        "parts": [{"shape": "cylinder", "mass": 1e9, "radius": 1e-8, "height": float(h),
                   "orientation": {"axis": [1, 1, 0], "angle": 0.3}}]},
        [closed(f"principal_moments.{i}", q, scale=sc, cond=8, reason="a symmetric eigenproblem: ε‖I‖")
         for i, q in enumerate(mom)] + [closed("mass", m)],
        "m = 1e9 kg, r = 1e-8 m, h = √3 r (1 + 1e-9), tilted: I_axial and I_transverse differ by 1e-9 relative")
    a, b, c = x(1e8), x(2e8), x(3e8)
    mp_, px = x(1e-9), x(1e8)
    M = 1 + mp_
    com = [mp_ * px / M, 0, 0]
    Ib = [1 * (b ** 2 + c ** 2) / 12 + 0, 1 * (a ** 2 + c ** 2) / 12 + mp_ * px ** 2, (a ** 2 + b ** 2) / 12 + mp_ * px ** 2]
    box = case("huge box beside a 1e-9 kg point", "inertia", {
        "parts": [{"shape": "box", "mass": 1, "size": [1e8, 2e8, 3e8], "at": [0, 0, 0]},
                  {"shape": "point", "mass": 1e-9, "at": [1e8, 0, 0]}], "about": [0, 0, 0]},
        [closed("mass", M), closed("com.0", com[0], cond=2)]
        + [closed(f"I_about.{i}.{i}", Ib[i], cond=4) for i in range(3)],
        "a 1 kg box 1e8 m across and a 1e-9 kg point at 1e8 m: mass ratio 1e9, moments ~1e16 kg m²")
    return [cyl, box]


def _planar():
    I13, I23, I33, w, wd = x(1e-20), x(-2e-20), x(5e-20), x(1e8), x(3e16)
    M = [I13 * wd - I23 * w ** 2, I23 * wd + I13 * w ** 2, I33 * wd]
    return [case("1e-20 kg m² at 1e8 rad/s", "planar-moments", {
        "I13": 1e-20, "I23": -2e-20, "I33": 5e-20, "omega": 1e8, "omega_dot": 3e16},
        [closed(f"M.{i}", M[i], scale=norm(M), cond=4) for i in range(3)] + vclosed("H", [I13 * w, I23 * w, I33 * w]),
        "products of inertia 1e-20 kg m², ω = 1e8 rad/s, ω̇ = 3e16 rad/s²: moments ~1e-4 N m")]


def _impulse():
    m, k, R, h = x(1e-9), x(1e-8), x(1e-9), x(3e-8)
    v, w = R / m, R * h / (m * k ** 2)
    return [case("1e-9 kg body, k = 1e-8 m", "rigid-impulse", {"m": 1e-9, "k": 1e-8, "R": 1e-9, "h": 3e-8, "s": 0},
                 [closed("v2.0", v), closed("omega2.2", w, cond=2), closed("percussion.1", k ** 2 / h, cond=2),
                  closed("T2", m * v ** 2 / 2 + m * k ** 2 * w ** 2 / 2, cond=4)],
                 "an impulse of 1e-9 N s 3e-8 m off a 1e-9 kg body: ω2 = 3e8 rad/s")]


def _energy():
    m, v, w = x(1e9), vec([x(1e-8), 0, x(2e-8)]), vec([x(1e8), x(-2e8), x(3e8)])
    I = [[x(4e-20), x(-1e-20), 0], [x(-1e-20), x(5e-20), x(1e-21)], [0, x(1e-21), x(6e-20)]]
    H = [sum(I[i][j] * w[j] for j in range(3)) for i in range(3)]
    Tr = dot(w, H) / 2
    Tt = m * dot(v, v) / 2
    return [case("heavy, slow and spinning", "rigid-energy", {
        "m": 1e9, "v": [1e-8, 0, 2e-8], "omega": [1e8, -2e8, 3e8],
        "I": [[4e-20, -1e-20, 0], [-1e-20, 5e-20, 1e-21], [0, 1e-21, 6e-20]]},
        [closed("T", Tr + Tt, cond=4), closed("T_rot", Tr, cond=4), closed("T_trans", Tt)] + vclosed("H", H, cond=4),
        "m = 1e9 kg at 1e-8 m/s (T = 2.5e-7 J) spinning at 1e8 rad/s on moments of 1e-20 kg m² (T_rot ~ 4e-3 J)")]


def _bearing():
    m, L, w0, a0, ad = x(1), x(0.5), x(1), x(1e-6), x(0.5)
    times = [x(0), x(1e-6), x(1)]
    I = lambda t: 2 * m * L ** 2 * mp.sin(a0 + ad * t) ** 2       # noqa: E731
    om = lambda t: w0 * I(0) / I(t)                                # noqa: E731
    checks = []
    for i, t in enumerate(times):
        al = a0 + ad * t
        checks += [closed(f"omega.{i}", om(t), cond=8, reason="ω0 sin²α0/sin²α"),
                   closed(f"omega_dot.{i}", -om(t) * 2 * ad * mp.cot(al), cond=8),
                   closed(f"F.{i}.1", -2 * m * L * mp.cos(al) * ad ** 2, cond=4),
                   closed(f"I_axis.{i}", I(t), cond=4),
                   closed(f"T.{i}", I(t) * om(t) ** 2 / 2 + m * L ** 2 * ad ** 2, cond=4)]
    return [case("arms opening from 1e-6 rad off the shaft", "bearing-forces", {
        "masses": [{"m": 1, "L": 0.5, "alpha": "-(1e-6 + 0.5*t)"}, {"m": 1, "L": 0.5, "alpha": "1e-6 + 0.5*t"}],
        "omega0": 1, "at": [0, 1e-6, 1]}, checks,
        "two arms at ±α, α = 1e-6 + 0.5 t rad, on a free shaft at ω0 = 1 rad/s: I_axis grows 2.3e11-fold, ω falls")]


def _spin():
    I0, w0 = x(1), x(2)
    big, small = x(1e9), x(1e-9)
    Ib = I0 + big * x(1e-8) ** 2 + small * x(1e8) ** 2
    Ia = I0 + big * x(2e-8) ** 2 + small * x(1e4) ** 2
    w = w0 * Ib / Ia
    return [case("masses 1e9 and 1e-9 kg", "spin-change", {
        "axis": [0, 1, 0], "omega0": 2, "I0": 1,
        "masses": [{"m": 1e9, "before": [1e-8, 0, 0], "after": [2e-8, 0, 0]},
                   {"m": 1e-9, "before": [0, 0, 1e8], "after": [0, 0, 1e4]}]},
        [closed("I_before", Ib, cond=2), closed("I_after", Ia, cond=2), closed("omega", w, cond=4),
         closed("T_after", Ia * w ** 2 / 2, cond=8), closed("work", Ia * w ** 2 / 2 - Ib * w0 ** 2 / 2, cond=8)],
        "a 1e9 kg mass 1e-8 m from the axis and a 1e-9 kg mass pulled in from 1e8 m: ω grows 9.1e6-fold")]


def _motor():
    IA1, IA2, mA, L, IB2, al, p = x(0.01), x(0.005), x(2), x(0.3), x(0.1), x(1e-9), x(1e8)
    Iax = IB2 + mA * L ** 2 * mp.cos(al) ** 2 + IA1 * mp.sin(al) ** 2 + IA2 * mp.cos(al) ** 2
    Om = -IA1 * p * mp.sin(al) / Iax
    return [case("motor shaft 1e-9 rad from the plane, p = 1e8", "motor-bodies", {
        "IA1": 0.01, "IA2": 0.005, "mA": 2, "L": 0.3, "IB2": 0.1, "alpha": 1e-9, "p": 1e8},
        [closed("Omega", Om, cond=4), closed("I_axis", Iax, cond=2),
         closed("omega_A.0", p + Om * mp.sin(al), cond=2), closed("omega_A.1", Om * mp.cos(al), cond=4)],
        "α = 1e-9 rad, p = 1e8 rad/s: the turntable turns at Ω = −3.5e-3 rad/s")]


def cases():
    return _inertia() + _planar() + _impulse() + _energy() + _bearing() + _spin() + _motor()


assert same
