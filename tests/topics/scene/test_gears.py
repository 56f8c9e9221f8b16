"""Gears in mesh (``gear: [A, B]``): a gear train lifting a load, a planetary set driven by its
carrier and driven by a torque on its sun, the refusals.

References by hand: the pitch circles roll on each other, R_A ω_A + s R_B ω_B = D φ̇ (s = +1
external, −1 internal, φ the line of centres' angle); the angular accelerations from the power
balance Σ M ω = d/dt T with the speed ratios (a formulation without the tooth forces), the tooth
forces from each gear's moment equation (32.15) alone, in exact rationals (mpmath).  Exact
routes: 1e-12 of the quantity's scale; the ODE route at its default rtol: ODE_GLOBAL × 1e-10.
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL
from tests.topics.scene.test_refusals import refusal
from tests.topics.scene.test_start import near

G = mp.mpf("9.81")
ODE_TOL = ODE_GLOBAL * 1e-10

TRAIN = """
type: scene
params: {M: -20}
bodies:
  A: {shape: disk, mass: 2, radius: 0.1, x: [0, 0]}
  B: {shape: disk, mass: 8, radius: 0.2, x: [0.3, 0]}
  W: {shape: point, mass: 5, x: [0.45, -1]}
joints:
  pA: {pin: [A, [0, 0]]}
  pB: {pin: [B, [0.3, 0]]}
  mesh: {gear: [A, B]}
  rope: {cord: [{wound: B, radius: 0.15}, W]}
forces:
  - {torque: A, M: M, name: motor}
at: [0, 1]
"""


def solved(text: str) -> dict:
    rec = solve_one_text(text)
    assert rec.get("error") is None, rec.get("error")
    return rec["results"]


def test_a_gear_train_lifts_a_load():
    # a motor couple of 20 N·m (clockwise) on pinion A (R = 0.1) turns gear B (R = 0.2) the other
    # way, k = ω_A/ω_B = −2; B's drum (r = 0.15) winds up W.  Power: 20 |k| ω_B − m g r ω_B =
    # (Ī_A k² + Ī_B + m r²) α_B ω_B.  Tooth force on A along t = e2 (n̂ = e1 from A to B):
    # Ī_A α_A = M + R_A F.
    r = solved(TRAIN)
    assert r["route"] == "closed-form" and r["dof"] == 1
    IA, IB, m, rr = mp.mpf(2) * mp.mpf("0.1") ** 2 / 2, mp.mpf(8) * mp.mpf("0.2") ** 2 / 2, 5, mp.mpf("0.15")
    aB = (20 * 2 - m * G * rr) / (IA * 4 + IB + m * rr ** 2)
    aA = -2 * aB
    near(r["alpha"]["B"][0][2], aB, aB, "alpha_B")
    near(r["alpha"]["A"][0][2], aA, aB, "alpha_A")
    near(r["a"]["W"][0][1], aB * rr, aB * rr, "W goes up")
    near(r["reaction"]["rope"]["T"][0][0], m * (G + aB * rr), m * G, "rope tension")
    F = (IA * aA + 20) / mp.mpf("0.1")
    near(r["reaction"]["mesh"]["F"][0], F, F, "the tooth force on A")
    # A's pin carries the tooth force and A's weight: R = −F e2 + m_A g e2
    near(r["reaction"]["pA"]["R"][0][1], -F + 2 * G, F, "A's pin")


PLANETARY = """
type: scene
params: {Rs: 0.1, Rp: 0.05}
bodies:
  sun: {shape: disk, mass: 1, radius: Rs, x: [0, 0]}
  planet: {shape: disk, mass: 0.5, radius: Rp, x: [0.15, 0]}
  arm: {shape: rod, mass: 0.2, length: 0.3, x: [0, 0], angle: 0, points: {tip: [0.15, 0]}}
  ring: {shape: ring, mass: 3, radius: 0.2, x: [0, 0]}
joints:
  s_pin: {pin: [sun, [0, 0]]}
  a_pin: {pin: [arm, [0, 0]]}
  r_pin: {pin: [ring, [0, 0]]}
  p_pin: {pin: [planet, arm.tip]}
  hold: {drive: ring.angle, value: 0}
  sp: {gear: [sun, planet]}
  rp: {gear: [ring, planet], internal: true}
"""


def test_a_planetary_set_driven_by_its_carrier():
    # the ring held, the carrier turned at 2 rad/s for 4 s (past a whole turn): the planet rolls
    # inside the ring, ω_p = −(R_r − R_p)/R_p ω_c = −6, and on the sun, ω_s = (1 + R_r/R_s) ω_c = 6;
    # the angles stay continuous through the carrier's turns (θ_s = 6 t)
    r = solved(PLANETARY + "  turn: {drive: arm.angle, value: 2*t}\nat: [0, 1, 4]\n")
    assert r["route"] == "kinematics"
    for k, t in enumerate((0, 1, 4)):
        near(r["omega"]["sun"][k][2], 6, 6, "omega_sun")
        near(r["omega"]["planet"][k][2], -6, 6, "omega_planet")
        near(r["angle"]["sun"][k], 6 * t, 24, f"the sun's angle at {t} s")
        near(r["angle"]["planet"][k], -6 * t, 24, f"the planet's angle at {t} s")
        near(r["reaction"]["sp"]["F"][k], 0, 1, "no tooth force at a constant speed")


def test_a_planetary_set_driven_by_a_torque_on_its_sun():
    # g = 0, the ring held, 0.5 N·m on the sun: with ω_s = 3 ω_c, ω_p = −3 ω_c, v_p = 0.15 ω_c the
    # power balance 0.5 · 3 ω_c = I_eff α_c ω_c, I_eff = 9 Ī_s + 9 Ī_p + m_p 0.15² + Ī_arm;
    # the sun's moment equation gives its tooth force, the ring's (held, at rest) the holding couple
    r = solved(PLANETARY + "at: [0, 1]\ng: 0\nforces: [{torque: sun, M: 0.5}]\n")
    Is, Ip, Ia = mp.mpf("0.01") / 2, mp.mpf("0.5") * mp.mpf("0.0025") / 2, mp.mpf("0.2") * mp.mpf("0.09") / 12
    Ie = 9 * Is + 9 * Ip + mp.mpf("0.5") * mp.mpf("0.0225") + Ia
    ac = 3 * mp.mpf("0.5") / Ie
    for k in (0, 1):
        near(r["alpha"]["arm"][k][2], ac, ac, "alpha_carrier", ODE_TOL)
        near(r["alpha"]["sun"][k][2], 3 * ac, ac, "alpha_sun", ODE_TOL)
        near(r["alpha"]["planet"][k][2], -3 * ac, ac, "alpha_planet", ODE_TOL)
    F_sp = (Is * 3 * ac - mp.mpf("0.5")) / mp.mpf("0.1")
    near(r["reaction"]["sp"]["F"][0], F_sp, F_sp, "the sun's tooth force", ODE_TOL)
    near(r["drive"]["hold"][0], -mp.mpf("0.2") * r["reaction"]["rp"]["F"][0], 1, "the ring's holding couple")


@pytest.mark.parametrize("change,field,needle", [
    (("B: {shape: disk, mass: 8, radius: 0.2, x: [0.3, 0]}", "B: {shape: point, mass: 8, x: [0.3, 0]}"),
     "joints.mesh.gear.1", "needs a rigid body"),
    (("B: {shape: disk, mass: 8, radius: 0.2, x: [0.3, 0]}", "B: {shape: rod, mass: 8, length: 0.4, x: [0.3, 0]}"),
     "joints.mesh.radii", "give the pitch radii"),
    (("mesh: {gear: [A, B]}", "mesh: {gear: [A, B], radii: [0.1, 0.25]}"), "joints.mesh.gear", "do not mesh"),
    (("mesh: {gear: [A, B]}", "mesh: {gear: [A, B], internal: true}"), "joints.mesh.gear", "must exceed"),
    (("mesh: {gear: [A, B]}", "mesh: {gear: [A, B], radii: [0.1]}"), "joints.mesh.radii", "two pitch radii"),
    (("mesh: {gear: [A, B]}", "mesh: {gear: [A, A]}"), "joints.mesh.gear", "two different"),
    (("mesh: {gear: [A, B]}", "mesh: {gear: [A, B], mu: 0.3}"), "joints.mesh.mu", "takes no mu"),
    (("B: {shape: disk, mass: 8, radius: 0.2, x: [0.3, 0]}", "B: {shape: disk, mass: 8, radius: 0.2}"),
     "bodies.B.x", "give the centre"),
    (("  pB: {pin: [B, [0.3, 0]]}\n", ""), "joints.mesh.gear", "not held at their distance"),
])
def test_refusals(change, field, needle):
    text = TRAIN.replace(*change)
    assert text != TRAIN
    refusal(text, field, needle)


def test_the_gear_train_hoist_gallery_file():
    # problems/scenes/gear-train-hoist.yaml: the train above with M = 5 N·m; W risen 1 m at √(2/a)
    from tests.topics.scene.common import gallery

    r = gallery("gear-train-hoist.yaml")["results"]
    IA, IB, m, rr, M = mp.mpf("0.01"), mp.mpf("0.16"), 5, mp.mpf("0.15"), 5
    aB = (2 * M - m * G * rr) / (4 * IA + IB + m * rr ** 2)
    F = (IA * -2 * aB + M) / mp.mpf("0.1")
    near(r["alpha"]["B"][0][2], aB, aB, "alpha_B")
    near(r["reaction"]["mesh"]["F"][0], F, F, "the tooth force")
    near(r["reaction"]["pB"]["R"][0][1], 8 * G + m * (G + aB * rr) + F, F, "B's axle")
    near(r["find"][0]["t"], mp.sqrt(2 / (aB * rr)), 1, "W has risen 1 m")


RACK = """
type: scene
surfaces:
  guide: {through: [0, 0], direction: [1, 0]}
  teeth: {body: rack, through: [-1, 0.05], direction: [1, 0]}
bodies:
  pinion: {shape: disk, mass: 1, radius: 0.05, x: [0, 0.1]}
  rack: {shape: box, mass: 4, size: [2, 0.1], x: [0, 0], angle: 0}
joints:
  axle: {pin: [pinion, [0, 0.1]]}
  way: {slider: [rack, guide]}
  mesh: {gear: [pinion, teeth]}
forces:
  - {torque: pinion, M: -2}
at: [0, 1]
"""


def test_a_pinion_drives_a_rack():
    # a couple M = −2 N·m on a pinned pinion (R = 0.05) meshing with a rack (4 kg) on a smooth
    # guide: the rack moves at v = R ω along d̂ (the pinion above it), (Ī + m R²) α = M; the tooth
    # force on the pinion along d̂ from Ī α = M + R F (its pitch point R below the centre), on the
    # rack −F: m a = −F; the guide's couple holds the rack's angle against F at its top face
    r = solved(RACK)
    assert r["route"] == "closed-form"
    I, m, R, M = mp.mpf("0.00125"), 4, mp.mpf("0.05"), -2
    alpha = M / (I + m * R ** 2)
    F = (I * alpha - M) / R
    near(r["alpha"]["pinion"][0][2], alpha, alpha, "alpha")
    near(r["a"]["rack"][0][0], R * alpha, R * alpha, "the rack's acceleration")
    near(r["reaction"]["mesh"]["F"][0], F, F, "the tooth force on the pinion")
    near(m * r["a"]["rack"][0][0], -F, F, "the rack's equation")
    near(r["reaction"]["way"]["M"][0][2], -mp.mpf("0.05") * F, F, "the guide's couple on the rack")


def test_a_pinion_rolls_down_a_fixed_rack():
    # a carriage (3 kg, a point) on a smooth track down β = 30° carries a pinion (1 kg, R = 0.1)
    # meshing with a fixed rack parallel to the track: a = m g sin β / (m + Ī/R²), m = 4 kg, and
    # the tooth force F = (Ī/R²) a up the slope
    r = solved("""
type: scene
params: {b: 30*deg}
surfaces:
  track: {through: ["-0.1*sin(b)", "0.1*cos(b)"], direction: ["cos(b)", "sin(b)"]}
  teeth: {through: [0, 0], direction: ["cos(b)", "sin(b)"]}
bodies:
  cart: {shape: point, mass: 3, x: ["-0.1*sin(b)", "0.1*cos(b)"]}
  pinion: {shape: disk, mass: 1, radius: 0.1, x: ["-0.1*sin(b)", "0.1*cos(b)"]}
joints:
  axle: {pin: [pinion, cart]}
  way: {slider: [cart, track]}
  mesh: {gear: [pinion, teeth]}
at: [0, 1]
""")
    a = 4 * G * mp.sin(mp.pi / 6) / (4 + mp.mpf("0.5"))
    near(mp.hypot(*r["a"]["cart"][0][:2]), a, a, "a")
    near(r["reaction"]["mesh"]["F"][0], mp.mpf("0.5") * a, a, "the tooth force")


@pytest.mark.parametrize("change,field,needle", [
    (("  way: {slider: [rack, guide]}\n", ""), "joints.mesh.gear", "not held at its distance from the rack"),
    (("x: [0, 0.1]}", "x: [0, 0.12]}"), "joints.mesh.gear", "does not mesh with the rack"),
    (("mesh: {gear: [pinion, teeth]}", "mesh: {gear: [pinion, teeth], radii: [0.05, 0.1]}"), "joints.mesh.radii",
     "one pitch radius"),
    (("mesh: {gear: [pinion, teeth]}", "mesh: {gear: [pinion, teeth], internal: true}"), "joints.mesh.internal",
     "a rack is straight"),
    (("mesh: {gear: [pinion, teeth]}", "mesh: {gear: [rack, teeth]}"), "joints.mesh.gear.0", "its own rack"),
])
def test_rack_refusals(change, field, needle):
    text = RACK.replace(*change)
    assert text != RACK
    refusal(text.replace("  axle: {pin: [pinion, [0, 0.1]]}", "  axle: {pin: [pinion, [0, 0.12]]}")
            if "0.12" in change[1] else text, field, needle)


def test_a_geared_pendulum_has_both_equilibria():
    # W (5 kg) fixed 0.15 below B's axle; B (Ī_B = 0.16) meshes with A (Ī_A = 0.01, ω_A = −2 ω_B):
    # ω² = m g r / (Ī_B + m r² + 4 Ī_A) hanging, its negative inverted — the equilibrium search
    # walks on until B (the slower wheel) has turned by π
    r = solved("""
type: scene
bodies:
  A: {shape: disk, mass: 2, radius: 0.1, x: [0, 0]}
  B: {shape: disk, mass: 8, radius: 0.2, x: [0.3, 0], angle: 0, points: {P: [0, -0.15]}}
  W: {shape: point, mass: 5, x: [0.3, -0.15]}
joints:
  pA: {pin: [A, [0, 0]]}
  pB: {pin: [B, [0.3, 0]]}
  mesh: {gear: [A, B]}
  fix: {pin: [W, B.P]}
at: [0]
linearize: true
""")
    w2 = 5 * G * mp.mpf("0.15") / (mp.mpf("0.16") + 5 * mp.mpf("0.0225") + 4 * mp.mpf("0.01"))
    eq = r["equilibria"]
    assert [e["stability"] for e in eq] == ["stable", "unstable"]
    near(eq[0]["omega2"][0], w2, w2, "hanging", 1e-9)
    near(eq[1]["omega2"][0], -w2, w2, "inverted", 1e-9)
