"""particles (24.12, 25.7, 27.8) and rigid-impulse (33.5-33.10): exact
rational references, property tests and edge cases."""

from __future__ import annotations

import math
from fractions import Fraction as Fr

from hypothesis import given, settings, strategies as st

from tests.conftest import solve_one_text
from tests.topics.impact.util import EPS, assert_close

coord = st.floats(-10, 10, allow_nan=False).map(lambda x: round(x, 3))
vec = st.tuples(coord, coord, coord)
mass = st.floats(-2, 2).map(lambda x: 10.0 ** x)


def run_particles(parts, about=(0.0, 0.0, 0.0)):
    from dyncli.topics.particle_systems.model import Particles
    from dyncli.topics.particle_systems.solver import solve

    p = Particles.model_validate({"type": "particles", "about": list(about),
                                  "particles": [{"m": m, "x": list(x), "v": list(v)} for m, x, v in parts]})
    res = solve(p)
    return res.results, res.warnings


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def exact(parts, about):
    P = [(Fr(m), [Fr(c) for c in x], [Fr(c) for c in v]) for m, x, v in parts]
    O = [Fr(c) for c in about]
    M = sum(m for m, _, _ in P)
    xb = [sum(m * x[i] for m, x, _ in P) / M for i in range(3)]
    vb = [sum(m * v[i] for m, _, v in P) / M for i in range(3)]
    G = [sum(m * v[i] for m, _, v in P) for i in range(3)]
    HO = [sum(cross([x[j] - O[j] for j in range(3)], [m * c for c in v])[i] for m, x, v in P) for i in range(3)]
    Hc = [sum(cross([x[j] - xb[j] for j in range(3)], [m * (v[j] - vb[j]) for j in range(3)])[i] for m, x, v in P)
          for i in range(3)]
    T = sum(m * sum(c * c for c in v) for m, _, v in P) / 2
    Tc = M * sum(c * c for c in vb) / 2
    Tr = sum(m * sum((v[j] - vb[j]) ** 2 for j in range(3)) for m, _, v in P) / 2
    return dict(mass=M, com=xb, v_com=vb, G=G, H_O=HO, H_com=Hc, T=T, T_com=Tc, T_rel=Tr)


@settings(max_examples=80, deadline=None)
@given(parts=st.lists(st.tuples(mass, vec, vec), min_size=1, max_size=8), about=vec)
def test_particles_against_exact(parts, about):
    r, _ = run_particles(parts, about)
    R = exact(parts, about)
    xs = max(max(abs(c) for _, x, _ in parts for c in x), max(abs(c) for c in about), 1.0)
    vs = max(max(abs(c) for _, _, v in parts for c in v), 1e-300)
    M = float(R["mass"])
    assert_close(r["mass"], R["mass"], rel=4 * EPS)
    assert_close(r["com"], R["com"], rel=0, abs_=8 * EPS * xs, what="com")
    assert_close(r["v_com"], R["v_com"], rel=0, abs_=8 * EPS * vs, what="v_com")
    assert_close(r["G"], R["G"], rel=0, abs_=8 * EPS * M * vs, what="G")
    assert_close(r["H_O"], R["H_O"], rel=0, abs_=32 * EPS * M * vs * xs, what="H_O")
    assert_close(r["H_com"], R["H_com"], rel=0, abs_=64 * EPS * M * vs * xs, what="H_com")
    for k in ("T", "T_com", "T_rel"):
        assert_close(r[k], R[k], rel=0, abs_=32 * EPS * M * vs * vs, what=k)
    assert r["T_rel"] >= 0
    # (27.8) and (25.7)
    assert abs(r["T"] - r["T_com"] - r["T_rel"]) <= 32 * EPS * M * vs * vs
    via = cross([r["com"][i] - about[i] for i in range(3)], [M * c for c in r["v_com"]])
    assert_close(r["H_O"], [via[i] + r["H_com"][i] for i in range(3)], rel=0, abs_=64 * EPS * M * vs * xs)


def test_particles_single_and_rigid_translation():
    r, _ = run_particles([(2.0, (1.0, 2.0, 3.0), (0.5, 0.0, 0.0))])
    assert r["com"] == [1.0, 2.0, 3.0] and r["v_com"] == [0.5, 0.0, 0.0]
    assert r["H_com"] == [0.0, 0.0, 0.0] and r["T_rel"] == 0.0 and r["T"] == r["T_com"] == 0.25
    # a rigid translation: no relative motion, T_rel exactly 0
    r, _ = run_particles([(1.0, (0, 0, 0), (0.1, 0.2, 0.3)), (3.0, (1, 1, 1), (0.1, 0.2, 0.3))])
    assert r["T_rel"] == 0.0 and r["H_com"] == [0.0, 0.0, 0.0]


def test_particles_huge_masses():
    r, w = run_particles([(1e300, (1.0, 0, 0), (0, 1.0, 0)), (1e300, (-1.0, 0, 0), (0, -1.0, 0))])
    assert r["mass"] == 2e300 and r["com"] == [0.0, 0.0, 0.0] and r["v_com"] == [0.0, 0.0, 0.0]
    assert_close(r["H_O"], [0, 0, 2e300])
    assert_close(r["T"], 1e300)


def test_particles_about_zero_default_and_yaml():
    rec = solve_one_text("type: particles\nabout: 0\nparticles:\n  - {m: 1, x: [1, 0, 0], v: [0, 1, 0]}\n")
    assert rec["results"]["H_O"] == [0.0, 0.0, 1.0]
    rec = solve_one_text("type: particles\nparticles:\n  - {m: 1, x: [1, 0, 0]}\n")
    assert rec["results"]["T"] == 0.0 and rec["results"]["G"] == [0.0, 0.0, 0.0]


# ---------------------------------------------------------------- rigid-impulse

def run_rigid(**kw):
    from dyncli.topics.rigid_impulse.model import RigidImpulse
    from dyncli.topics.rigid_impulse.solver import solve

    res = solve(RigidImpulse.model_validate({"type": "rigid-impulse", **kw}))
    return res.results, res.warnings


@settings(max_examples=80, deadline=None)
@given(m=mass, k=mass, R=st.floats(-100, 100).map(lambda x: round(x, 2)), h=coord, s=coord)
def test_rigid_impulse_exact(m, k, R, h, s):
    r, w = run_rigid(m=m, k=k, R=R, h=h, s=s)
    M, K, RR, H, S = map(Fr, (m, k, R, h, s))
    I = M * K * K
    assert_close(r["v2"], [RR / M, 0, 0], rel=2 * EPS)                    # (33.5)
    assert_close(r["omega2"], [0, 0, H * RR / I], rel=4 * EPS)            # (33.8)
    # M̂ = x1 × R̂ with x1 = -s e1 - h e2 (33.4, 33.7)
    assert cross([-S, -H, 0], [RR, 0, 0]) == [0, 0, H * RR]
    if h == 0:
        assert r["percussion"] is None and any("h = 0" in x for x in w)
    else:
        assert_close(r["percussion"], [0, K * K / H, 0], rel=4 * EPS)     # (33.10)
        # the percussion point has zero velocity (33.9)
        v = [r["v2"][0] - r["omega2"][2] * r["percussion"][1], r["omega2"][2] * r["percussion"][0]]
        assert abs(v[0]) <= 8 * EPS * abs(r["v2"][0]) + 1e-300 and v[1] == 0
    assert_close(r["v_point"], [RR / M + H * RR / I * H, -H * RR / I * S, 0], rel=8 * EPS, abs_=1e-300)
    assert_close(r["T2"], RR * RR / M / 2 + I * (H * RR / I) ** 2 / 2, rel=8 * EPS, abs_=1e-300)


def test_rigid_impulse_h_zero():
    r, w = run_rigid(m=2.0, k=0.5, R=4.0, h=0.0)
    assert r["v2"] == [2.0, 0.0, 0.0] and r["omega2"] == [0.0, 0.0, 0.0]
    assert r["percussion"] is None
    assert any("center of percussion" in x for x in w)


def test_rigid_impulse_sign_convention():
    # h > 0: application point below the center (−h e'_2), spin counterclockwise
    # (+e'_3), percussion point above (+k²/h e'_2); h < 0 mirrors it
    r, _ = run_rigid(m=1.0, k=1.0, R=1.0, h=0.5)
    assert r["omega2"][2] > 0 and r["percussion"][1] == 2.0
    r, _ = run_rigid(m=1.0, k=1.0, R=1.0, h=-0.5)
    assert r["omega2"][2] < 0 and r["percussion"][1] == -2.0
