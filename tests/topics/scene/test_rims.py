"""Bodies striking bodies rim to rim (``stop: [A, B]`` / ``contact: [A, B]`` with two bodies):
two pendulum balls colliding, a rolling billiard ball striking one at rest, a cylinder resting on
two others (released: both contacts let go at one instant), and the refusals.

References, none from the code under test: the impact of two bodies along their line of centres
(28.7, 28.11: v_A' = (m_A − e m_B) v/(m_A + m_B), v_B' = m_A (1 + e) v/(m_A + m_B), the energy
lost ½ m_A m_B/(m_A + m_B) (1 − e²) v²); the pendulum's exact quarter period √(L/g) K(sin²(θ0/2))
(mpmath); slipping under kinetic friction to rolling at (2/7) v and (5/7) v (solid spheres);
the released stack's first accelerations from its free-body diagrams by hand.
"""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL, closed_form
from tests.topics.scene.test_refusals import refusal
from tests.topics.scene.test_start import near

G = 9.81
TOL = ODE_GLOBAL * 1e-10


@pytest.mark.parametrize("mA, mB, e", [(1.0, 2.0, 0.8), (2.0, 1.0, 0.5), (1.0, 1.0, 1.0), (1.0, 3.0, 0.0)])
def test_two_pendulum_balls_collide_at_the_bottom(mA, mB, e):
    # A swings down from 60° on L = 1 and strikes B hanging at rest: horizontal and central at
    # the bottom (the links vertical: no impulsive tension)
    rec = solve_one_text(f"""
type: scene
bodies:
  A: {{shape: sphere, mass: {mA}, radius: 0.05, x: ["-0.1 - sin(pi/3)", "1 - cos(pi/3)"], angle: 0}}
  B: {{shape: sphere, mass: {mB}, radius: 0.05, x: [0, 0], angle: 0}}
joints:
  a: {{link: [[-0.1, 1], A]}}
  b: {{link: [[0, 1], B]}}
  hit: {{stop: [A, B], e: {e}}}
at: [0, 0.7]
find: [{{event: impact, after: true}}]
""")
    r = rec["results"]
    v = math.sqrt(G)                                        # √(2 g L (1 − cos 60°))
    near(r["events"][0]["t"], mp.sqrt(1 / G) * mp.ellipk(mp.sin(mp.pi / 6) ** 2), 1.0, "the time of the impact", TOL)
    after = r["find"][0]["v"]
    near(after["A"][0], (mA - e * mB) * v / (mA + mB), v, "v_A after", TOL)
    near(after["B"][0], mA * (1 + e) * v / (mA + mB), v, "v_B after", TOL)
    imp = r["impacts"][0]
    near(imp["impulse"], mA * mB * (1 + e) * v / (mA + mB), mA * v, "the impulse", TOL)
    near(imp["energy_loss"], 0.5 * mA * mB / (mA + mB) * (1 - e * e) * v * v, mA * v * v, "the energy lost", TOL)
    near(imp["v_n_after"], e * v, v, "Newton's law on the normal speed", TOL)
    if e == 0:                                              # plastic: they swing on together, touching
        assert r["phases"][1]["joints"] == ["a", "b", "hit"]


def test_a_rolling_ball_strikes_a_resting_one_each_slips_then_rolls_at_two_and_five_sevenths():
    rec = solve_one_text("""
type: scene
surfaces:
  table: {through: [-2, 0], direction: [1, 0]}
bodies:
  cue: {shape: sphere, mass: 0.17, radius: 0.028, x: [-0.5, 0.028], angle: 0, v: [2, 0], omega: -71.42857142857143}
  ball: {shape: sphere, mass: 0.17, radius: 0.028, x: [0.1, 0.028], angle: 0}
joints:
  r1: {rolls: [cue, table], mu_s: 0.3, mu_k: 0.2}
  r2: {rolls: [ball, table], mu_s: 0.3, mu_k: 0.2}
  hit: {stop: [cue, ball], e: 0.9}
at: [0, 1.5]
""")
    r = rec["results"]
    v0, e, mu = 2.0, 0.9, 0.2
    va, vb = (1 - e) * v0 / 2, (1 + e) * v0 / 2             # equal masses
    # the cue ball keeps ω0 = v0/R: it is driven forward to (5 va + 2 v0)/7; the other to 5 vb/7
    ka, kb = (5 * va + 2 * v0) / 7, 5 * vb / 7
    t_hit = 0.544 / v0
    assert [(x["joint"], x["what"]) for x in r["events"]] == [("hit", "impact"), ("r1", "sticks"), ("r2", "sticks")] \
        or [(x["joint"], x["what"]) for x in r["events"]] == [("hit", "impact"), ("r2", "sticks"), ("r1", "sticks")]
    times = {x["joint"]: x["t"] for x in r["events"][1:]}
    assert times["r1"] == pytest.approx(t_hit + (ka - va) / (mu * G), rel=closed_form(1e3))
    assert times["r2"] == pytest.approx(t_hit + (vb - kb) / (mu * G), rel=closed_form(1e3))
    assert r["v"]["cue"][1][0] == pytest.approx(ka, rel=closed_form(100))
    assert r["v"]["ball"][1][0] == pytest.approx(kb, rel=closed_form(100))
    assert r["omega"]["ball"][1][2] == pytest.approx(-kb / 0.028, rel=closed_form(100))


def test_a_cylinder_on_two_others_pushes_them_apart_and_leaves_both_at_once():
    # three equal smooth cylinders (R = 0.1, m = 1), the top one on the two below at 60°: by
    # hand, N = m g/(2 cos 30° + tan 30° sin 30°·…): a_L = −N/2, a_T = √3 N − g with
    # ½(−a_L) + (√3/2) a_T = 0, so N = g/(√3 + 1/(2√3)) and the floor's 9.81 + (√3/2) N
    rec = solve_one_text("""
type: scene
surfaces:
  floor: {through: [-2, 0], direction: [1, 0]}
bodies:
  L: {shape: cylinder, mass: 1, radius: 0.1, x: [0, 0.1], angle: 0}
  T: {shape: cylinder, mass: 1, radius: 0.1, x: [0.1, "0.1 + 0.2*sin(pi/3)"], angle: 0}
  R: {shape: cylinder, mass: 1, radius: 0.1, x: [0.2, 0.1], angle: 0}
joints:
  fl: {stop: [L, floor], e: 0}
  fr: {stop: [R, floor], e: 0}
  tl: {contact: [T, L]}
  tr: {contact: [T, R]}
at: [0, 0.3]
""")
    r = rec["results"]
    N = G / (math.sqrt(3) + 1 / (2 * math.sqrt(3)))
    assert r["reaction"]["tl"]["N"][0] == pytest.approx(N, rel=closed_form(100))
    assert r["reaction"]["tr"]["N"][0] == pytest.approx(N, rel=closed_form(100))
    assert r["a"]["L"][0][0] == pytest.approx(-N / 2, rel=closed_form(100))
    assert r["reaction"]["fl"]["N"][0] == pytest.approx(G + math.sqrt(3) / 2 * N, rel=closed_form(100))
    # the top lets go of both at one instant (symmetric), and falls freely between them
    assert [(x["joint"], x["what"]) for x in r["events"]] == [("tl", "separates"), ("tr", "separates")]
    assert r["events"][0]["t"] == r["events"][1]["t"]
    assert r["x"]["T"][1][0] == pytest.approx(0.1, abs=1e-12)
    assert r["x"]["L"][1][0] == pytest.approx(0.2 - r["x"]["R"][1][0], abs=1e-12)


BASE = """
type: scene
surfaces:
  floor: {through: [-2, 0], direction: [1, 0]}
bodies:
  A: {shape: sphere, mass: 1, radius: 0.1, x: XA, angle: 0}
  B: {shape: SHAPEB, mass: 2, RB, x: [0, 0.1], angle: 0}
  P: {shape: point, mass: 1, x: [3, 3]}
  Q: {shape: point, mass: 1, x: [4, 4]}
joints:
  f: {stop: [B, floor], e: 0}
  j: JOINT
at: [0]
"""


def base(joint="{stop: [A, B], e: 0.5}", xa="[0, 0.5]", shape="sphere", rb="radius: 0.1") -> str:
    return BASE.replace("JOINT", joint).replace("XA", xa).replace("SHAPEB", shape).replace("RB", rb)


@pytest.mark.parametrize("text, field, needles", [
    (base(joint="{contact: [A, B]}"), "joints.j", ("0.2 m apart", "R_A + R_B = 0.2 m", "make the joint a stop")),
    (base(xa="[0, 0.25]"), "joints.j", ("overlap by 0.05 m",)),
    (base(joint="{stop: [A, B], e: 0.5}", shape="box", rb="size: [0.2, 0.2]"), "joints.j.stop.1", ("has no radius",)),
    (base(joint="{stop: [P, Q], e: 0.5}"), "joints.j", ("two point masses",)),
    (base(joint="{stop: [A, A], e: 0.5}"), "joints.j", ("cannot touch itself",)),
    (base(joint="{stop: [A.center, B], e: 0.5}"), "joints.j.stop.0", ("names both bodies",)),
    (base(joint="{contact: [A, B]}", xa="[0, 0.5]", shape="ring", rb="radius: 0.6"), "joints.j",
     ("0.1 m apart", "R_B − R_A = 0.5 m")),
    (base(joint="{contact: [A, B], internal: true}"), "joints.j.internal", ("neither 'A' nor 'B' is a ring",)),
    (base(joint="{contact: [A, B]}", xa="[0, 0.1]", shape="ring", rb="radius: 0.1"), "joints.j", ("same radius",)),
    (base(joint="{link: [A, B], internal: true}"), "joints.j.internal", ("takes no internal",)),
])
def test_rim_refusals(text, field, needles):
    refusal(text, field, *needles)


def test_the_gallery_billiard_balls():
    from tests.topics.scene.common import gallery

    rec = gallery("billiard-balls.yaml")
    r = rec["results"]
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("hit", "impact"), ("roll_cue", "sticks"),
                                                              ("roll_ball", "sticks")]
    assert r["impacts"][0]["course"] == "smooth" and r["impacts"][0]["energy_loss"] == 0
    assert rec["warnings"] == []


@pytest.mark.parametrize("seed", range(12))
def test_an_oblique_impact_of_two_free_bodies_keeps_momentum_and_the_tangential_speeds(seed):
    # g = 0, two bodies (a ball, a disk or a point against a ball or a disk) meeting off-centre:
    # total momentum kept (both components), each tangential speed along the contact kept (smooth
    # rims), Newton's law on the normal speed, T kept for e = 1 — at the masses, radii, offsets
    # and speeds drawn by a seeded generator (the extremes of mass ratio 50 and grazing offsets)
    import random

    rnd = random.Random(seed)
    mA, mB = rnd.choice([0.1, 1.0, 5.0]), rnd.choice([0.1, 1.0, 5.0])
    RA, RB = rnd.uniform(0.01, 0.3), rnd.uniform(0.01, 0.3)
    shapeA = ("sphere", "disk", "point")[seed % 3]
    RAe = 0.0 if shapeA == "point" else RA
    off = rnd.uniform(-0.95, 0.95) * (RAe + RB)
    w = rnd.uniform(-1, 1)                                     # the same sideways speed: they meet
    vA, vB = (rnd.uniform(0.5, 5), w), (rnd.uniform(-5, -0.5), w)
    e = (0.0, 0.5, 1.0)[seed % 3 - 1]
    radius = "" if shapeA == "point" else f"radius: {RA}, angle: 0, "
    rec = solve_one_text(f"""
type: scene
g: 0
bodies:
  A: {{shape: {shapeA}, mass: {mA}, {radius}x: [-1, 0], v: [{vA[0]}, {vA[1]}]}}
  B: {{shape: disk, mass: {mB}, radius: {RB}, angle: 0, x: [1, {off}], v: [{vB[0]}, {vB[1]}]}}
joints:
  hit: {{stop: [A, B], e: {e}}}
t_end: 3
at: [0]
find: [{{event: impact, after: true}}]
""")
    f = rec["results"]["find"][0]
    assert f["reached"]
    a, b = f["v"]["A"], f["v"]["B"]
    xa, xb = f["x"]["A"], f["x"]["B"]
    d = math.hypot(xb[0] - xa[0], xb[1] - xa[1])
    n = ((xb[0] - xa[0]) / d, (xb[1] - xa[1]) / d)
    tol = closed_form(100) * 5 * max(mA, mB)
    for k in (0, 1):
        assert mA * a[k] + mB * b[k] == pytest.approx(mA * vA[k] + mB * vB[k], abs=tol)
    assert d == pytest.approx(RAe + RB, rel=1e-9)               # where the rims meet (the located event)
    dv0 = (vB[0] - vA[0]) * n[0] + (vB[1] - vA[1]) * n[1]
    dv1 = (b[0] - a[0]) * n[0] + (b[1] - a[1]) * n[1]
    assert dv1 == pytest.approx(-e * dv0, abs=tol)
    for (u, w) in ((vA, a), (vB, b)):
        assert w[1] * n[0] - w[0] * n[1] == pytest.approx(u[1] * n[0] - u[0] * n[1], abs=tol)
    if e == 1:
        T = lambda p, q: 0.5 * mA * (p[0] ** 2 + p[1] ** 2) + 0.5 * mB * (q[0] ** 2 + q[1] ** 2)  # noqa: E731
        assert T(a, b) == pytest.approx(T(vA, vB), rel=closed_form(100))


@pytest.mark.parametrize("shape, radius, internal", [("point", 0.0, True), ("sphere", 0.1, None)])
def test_a_marble_inside_a_fixed_hoop_presses_on_it_and_rises_to_v2_over_2g(shape, radius, internal):
    # smooth: the marble's centre runs on a circle of radius ρ = 1 − r inside the hoop (pinned and
    # held), N = m g + m v0²/ρ at the bottom, up to v0²/(2g) above it (the energy integral); a point
    # on the ring itself is told inside by internal: true, a ball within it is inside by position
    m, v0, rho = 0.1, 2.0, 1.0 - radius
    body = "shape: point" if shape == "point" else f"shape: sphere, radius: {radius}, angle: 0"
    flag = ", internal: true" if internal else ""
    rec = solve_one_text(f"""
type: scene
bodies:
  hoop: {{shape: ring, mass: 2, radius: 1, x: [0, 1], angle: 0}}
  m: {{{body}, mass: {m}, x: [0, {radius}], v: [{v0}, 0]}}
joints:
  fix: {{pin: [hoop, [0, 1]]}}
  hold: {{drive: hoop.angle, value: 0}}
  in: {{contact: [m, hoop]{flag}}}
at: [0]
find: [{{max: x.m.1, within: [0, 3]}}]
t_end: 3
""")
    r = rec["results"]
    assert r["reaction"]["in"]["N"][0] == pytest.approx(m * G + m * v0 ** 2 / rho, rel=closed_form(100))
    near(r["find"][0]["x"]["m"][1], radius + v0 ** 2 / (2 * G), 1.0, "the height it rises to", TOL)


def test_a_ball_rolling_inside_a_fixed_hoop_rises_seven_tenths_of_v2_over_g():
    # rough (μ = 1: it rolls, |F| ≤ μ N all the way up): the energy of rolling, ½ m v² (1 + 2/5),
    # takes it up (7/10) v0²/g; N = m g + m v0²/ρ at the bottom, F = 0 there
    m, v0, r, rho = 0.1, 1.0, 0.1, 0.9
    rec = solve_one_text(f"""
type: scene
bodies:
  hoop: {{shape: ring, mass: 2, radius: 1, x: [0, 1], angle: 0}}
  ball: {{shape: sphere, radius: {r}, mass: {m}, x: [0, {r}], angle: 0, v: [{v0}, 0], omega: {-v0 / r}}}
joints:
  fix: {{pin: [hoop, [0, 1]]}}
  hold: {{drive: hoop.angle, value: 0}}
  in: {{contact: [ball, hoop], mu: 1}}
at: [0]
find: [{{max: x.ball.1, within: [0, 2]}}]
t_end: 2
""")
    r_ = rec["results"]
    assert r_["events"] == []                                  # it never slips
    assert r_["reaction"]["in"]["N"][0] == pytest.approx(m * G + m * v0 ** 2 / rho, rel=closed_form(100))
    assert abs(r_["reaction"]["in"]["F"][0]) <= closed_form(100) * m * G
    near(r_["find"][0]["x"]["ball"][1], r + 0.7 * v0 ** 2 / G, 1.0, "the height it rolls up to", TOL)


@pytest.mark.parametrize("seed", range(8))
def test_a_rough_oblique_impact_of_two_spinning_balls_keeps_both_momenta_and_never_gains_energy(seed):
    # g = 0, two spinning balls meeting off-centre with friction (Routh's method on the rims'
    # slip): the impulses between them are equal and opposite at one point, so the linear
    # momentum and the angular momentum about the origin are kept; T does not grow
    import random

    rnd = random.Random(100 + seed)
    mA, mB = rnd.choice([0.1, 1.0, 5.0]), rnd.choice([0.1, 1.0, 5.0])
    RA, RB = rnd.uniform(0.02, 0.3), rnd.uniform(0.02, 0.3)
    off, w = rnd.uniform(-0.9, 0.9) * (RA + RB), rnd.uniform(-1, 1)
    vA, vB = (rnd.uniform(0.5, 5), w), (rnd.uniform(-5, -0.5), w)
    wA, wB = rnd.uniform(-20, 20), rnd.uniform(-20, 20)
    e, mu = (0.0, 0.5, 1.0)[seed % 3], (0.1, 0.3, 1.0)[seed % 3 - 1]
    rec = solve_one_text(f"""
type: scene
g: 0
bodies:
  A: {{shape: sphere, mass: {mA}, radius: {RA}, angle: 0, x: [-1, 0], v: [{vA[0]}, {vA[1]}], omega: {wA}}}
  B: {{shape: sphere, mass: {mB}, radius: {RB}, angle: 0, x: [1, {off}], v: [{vB[0]}, {vB[1]}], omega: {wB}}}
joints:
  hit: {{stop: [A, B], e: {e}, mu: {mu}}}
t_end: 3
at: [0]
find: [{{event: impact, after: true}}]
""")
    r = rec["results"]
    before, after = r["events"][0]["state"], r["find"][0]
    parts = (("A", mA, 0.4 * mA * RA ** 2), ("B", mB, 0.4 * mB * RB ** 2))

    def L(st):
        return sum(I * st["omega"][k][2] + m * (st["x"][k][0] * st["v"][k][1] - st["x"][k][1] * st["v"][k][0])
                   for k, m, I in parts)

    def T(st):
        return sum(0.5 * m * (st["v"][k][0] ** 2 + st["v"][k][1] ** 2) + 0.5 * I * st["omega"][k][2] ** 2
                   for k, m, I in parts)

    tol = closed_form(100) * 5 * max(mA, mB)
    assert L(after) == pytest.approx(L(before), abs=tol)
    for c in (0, 1):
        assert sum(m * after["v"][k][c] for k, m, _ in parts) == pytest.approx(
            sum(m * before["v"][k][c] for k, m, _ in parts), abs=tol)
    assert T(after) <= T(before) * (1 + closed_form(100))
