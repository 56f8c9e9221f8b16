"""Oracle cases: systems of particles and bodies — impact and particles at mass ratios 1e±9 and
speeds 1e-8 … 1e8 m/s, an Atwood machine (scene, closed form) at a mass ratio of 1e9 and at
balance to 1e-9."""

from __future__ import annotations

import mpmath as mp

from tests.oracle.common import EPS, absolute, case, closed, cross, dot, norm, same, vclosed, vec, x


def _impact_case(name, mA, mB, vA, vB, n, e, note):
    MA, MB, VA, VB, E = x(mA), x(mB), vec([x(c) for c in vA]), vec([x(c) for c in vB]), x(e)
    N = vec([x(c) for c in n])
    N = [c / norm(N) for c in N]
    ms = MA * MB / (MA + MB)
    u = dot([VA[i] - VB[i] for i in range(3)], N)
    P = (1 + E) * ms * u
    vA2 = [VA[i] - P / MA * N[i] for i in range(3)]
    vB2 = [VB[i] + P / MB * N[i] for i in range(3)]
    T1 = (MA * dot(VA, VA) + MB * dot(VB, VB)) / 2
    loss = ms * (1 - E ** 2) * u ** 2 / 2
    sc = max(norm(VA), norm(VB))
    checks = (vclosed("vA2", vA2, scale=sc, cond=8) + vclosed("vB2", vB2, scale=sc, cond=8)
              + [closed("m_star", ms, cond=2), closed("approach_speed", u, scale=sc, cond=4),
                 absolute("energy_loss", loss, 32 * EPS * T1, "a difference of kinetic energies: 32 ε T1")])
    doc = {"mA": mA, "mB": mB, "vA1": vA, "vB1": vB, "n": n, "e": e}
    return case(name, "impact", doc, checks, note, same_=[same("impact", True)])


def _impact():
    return [_impact_case("elastic, mass ratio 1e9", 1e9, 1, [1, 0, 0], [0, 0, 0], [1, 0, 0], 1,
                         "a 1e9 kg body hits 1 kg at 1 m/s: B leaves at 2 m/s, A loses 2e-9 m/s, no energy lost"),
            _impact_case("oblique, mass ratio 1e-18, e = 0.5", 1e-9, 1e9, [1e8, 0, 0], [0, 1e-8, 0], [3, 4, 0], 0.5,
                         "a 1e-9 kg particle at 1e8 m/s on a 1e9 kg body at 1e-8 m/s: a wall, to rounding")]


def _particles():
    ps = [(x(1e9), vec([x(1e8), 0, 0]), vec([0, x(1e-8), 0])),
          (x(1e-9), vec([0, x(1e-8), 0]), vec([x(1e8), 0, 0])),
          (x(1), vec([x(1), x(2), x(3)]), vec([x(3), x(2), x(1)]))]
    M = sum(m for m, _, _ in ps)
    xc = [sum(m * p[i] for m, p, _ in ps) / M for i in range(3)]
    vc = [sum(m * v[i] for m, _, v in ps) / M for i in range(3)]
    G = [M * c for c in vc]
    HO = [sum(m * cross(p, v)[i] for m, p, v in ps) for i in range(3)]
    Hc = [sum(m * cross([p[j] - xc[j] for j in range(3)], [v[j] - vc[j] for j in range(3)])[i] for m, p, v in ps)
          for i in range(3)]
    T = sum(m * dot(v, v) for m, _, v in ps) / 2
    Tc = M * dot(vc, vc) / 2
    hs = sum(m * norm(p) * norm(v) for m, p, v in ps)            # the scale of the terms of H
    checks = (vclosed("com", xc, cond=4) + vclosed("v_com", vc, cond=4) + vclosed("G", G, cond=4)
              + vclosed("H_O", HO, scale=hs, cond=4)
              + vclosed("H_com", Hc, scale=hs, cond=16, reason="H_O − x̄ × G: terms of Σ m|x||v|")
              + [closed("T", T, cond=2), closed("T_com", Tc, scale=T, cond=4), closed("T_rel", T - Tc, scale=T, cond=8)])
    return [case("masses 1e9, 1e-9 and 1 kg", "particles", {"particles": [
        {"m": 1e9, "x": [1e8, 0, 0], "v": [0, 1e-8, 0]}, {"m": 1e-9, "x": [0, 1e-8, 0], "v": [1e8, 0, 0]},
        {"m": 1, "x": [1, 2, 3], "v": [3, 2, 1]}]}, checks,
        "a 1e9 kg particle 1e8 m out at 1e-8 m/s, a 1e-9 kg one at 1e8 m/s, and 1 kg: every term of H and T ~ 1-10")]


def _atwood(name, m1, m2, note):
    M, g = x(1), x(9.81)
    A, B = x(m1), x(m2)
    a = g * (A - B) / (A + B + M / 2)            # A falls (disk pulley: I = M R²/2)
    T1, T2 = A * (g - a), B * (g + a)
    times = [x(0), x(0.5), x(1)]
    checks = []
    for i, t in enumerate(times):
        checks += [closed(f"x.A.{i}.1", -10 - a * t ** 2 / 2, scale=10 + abs(a) * t ** 2 / 2, cond=8),
                   closed(f"v.B.{i}.1", a * t, scale=g * t + 1e-300, cond=8)]
    Fs = T1 + T2 + M * g
    checks += [closed("reaction.rope.T.0.0", T1, cond=8), closed("reaction.rope.T.0.1", T2, scale=T1, cond=8),
               closed("reaction.axle.R.0.1", Fs, cond=8)]
    doc = {"params": {"M": 1, "R": 0.1}, "bodies": {
        "pulley": {"shape": "disk", "mass": "M", "radius": "R", "x": [0, 0], "angle": 0},
        # 10 m below the pulley: in 1 s neither comes up to it (an end that reaches its pulley stops
        # the motion, the event `reaches`)
        "A": {"shape": "point", "mass": m1, "x": ["-R", -10]}, "B": {"shape": "point", "mass": m2, "x": ["R", -10.5]}},
        "joints": {"axle": {"pin": ["pulley", "ground"]}, "rope": {"cord": ["A", "pulley", "B"]}},
        "at": [0, 0.5, 1]}
    return case(name, "scene", doc, checks, note, same_=[same("route", "closed-form")])


def cases():
    return (_impact() + _particles()
            + [_atwood("Atwood, mass ratio 1e9", 1e9, 1, "A = 1e9 kg against B = 1 kg: a = g to 1e-9, T2 = 2 m g"),
               _atwood("Atwood, balanced to 1e-9", 1 + 1e-9, 1,
                       "A = 1 + 1e-9 kg against 1 kg: a = 3.9e-9 m/s², x moves 2e-9 m in 1 s")])


assert mp
