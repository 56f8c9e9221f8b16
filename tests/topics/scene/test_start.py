"""The phase a scene starts in: a slack cord, a rolling body that slips (docs/types/scene.md).

References by hand (constant accelerations, 16.7, 15.8, 28.7 with e = 0 for a cord jerked taut)
and, for an event time that is a root of a transcendental equation, mpmath's findroot at 30
digits on the hand-integrated motion.  Every phase here takes an exact route (closed-form):
tolerance 1e-12 of the quantity's scale; the ODE route (a load varying in time) ODE_GLOBAL × rtol.
"""

from __future__ import annotations

import mpmath as mp

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL
from tests.topics.scene.common import gallery
from tests.topics.scene.test_refusals import refusal

G = 9.81
EXACT = 1e-12
ODE_TOL = ODE_GLOBAL * 1e-10      # the ODE route at the default rtol (docs/accuracy.md)


def near(got, want, scale, what, tol=EXACT):
    assert got is not None, f"{what}: null"
    assert abs(float(got) - float(want)) <= tol * abs(float(scale)), f"{what}: {got!r} vs {float(want)!r}"


def _solve(text):
    rec = solve_one_text(text)
    assert rec.get("error") is None, rec.get("error")
    return rec["results"]


def test_cord_that_would_push_starts_slack_and_is_jerked_taut():
    # 1 kg hanging 1 m under a ground point on a cord of 1 m, lifted by F = 15 cos 2t: at t = 0
    # the cord would push (T = g − 15 < 0), so it starts slack; the mass then moves freely
    # along the cord's line: y = −1 + 3.75 (1 − cos 2t) − g t²/2 (it rises to y ≈ −0.27, never
    # a cord's length above the ceiling point), back to y = −1 (taut) at the root t2 of
    # 3.75 (1 − cos 2t) = g t²/2, where it is stopped (28.7, e = 0); then T = g − 15 cos 2t.
    r = _solve("""
type: scene
bodies:
  A: {shape: point, mass: 1, x: [0, -1]}
joints:
  rope: {cord: [[0, 0], A], length: 1}
forces:
  - {force: A, F: [0, "15*cos(2*t)"]}
at: [0, 0.5, 1.6, 2]
""")
    t2 = mp.findroot(lambda t: mp.mpf("3.75") * (1 - mp.cos(2 * t)) - G * t**2 / 2, 1.1)
    y = lambda t: -1 + mp.mpf("3.75") * (1 - mp.cos(2 * t)) - G * t**2 / 2
    v2 = mp.mpf("7.5") * mp.sin(2 * t2) - G * t2
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("rope", "taut")]
    assert r["phases"][0]["joints"] == [] and r["phases"][1]["joints"] == ["rope"]
    tol = ODE_TOL if r["phases"][0]["route"] == "ode" else EXACT
    near(r["events"][0]["t"], t2, t2, "taut t", tol)
    near(r["reaction"]["rope"]["T"][0][0], 0, 1, "T.0")
    near(r["x"]["A"][1][1], y(mp.mpf("0.5")), 1, "x.A.1", tol)
    near(r["impacts"][0]["impulse"], -v2, abs(v2), "impulse", tol)
    near(r["impacts"][0]["energy_loss"], v2**2 / 2, v2**2, "energy loss", tol)
    near(r["x"]["A"][2][1], -1, 1, "x.A.2 (taut)", tol)
    near(r["reaction"]["rope"]["T"][3][0], G - 15 * mp.cos(4), G, "T after", 10 * tol)


def test_slack_cord_gallery():
    r = gallery("slack-cord-jerk.yaml")["results"]
    mA, mB = 2, 1
    t1, vB = mp.sqrt(1 / mp.mpf(G)), mp.sqrt(mp.mpf(G))
    vp = mB * vB / (mA + mB)
    a = (mA - mB) * G / mp.mpf(mA + mB)
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("rope", "taut"), ("rest", "separates")]
    near(r["events"][0]["t"], t1, t1, "taut t")
    near(r["impacts"][0]["impulse"], mB * (vB - vp), vB, "impulse")
    near(r["impacts"][0]["energy_loss"], mB * vB**2 / 2 - (mA + mB) * vp**2 / 2, vB**2, "loss")
    near(r["reaction"]["rest"]["N"][1], mA * G, G, "N before")
    for k, t in ((2, mp.mpf("0.5")), (3, mp.mpf("0.8"))):
        tau = t - t1
        near(r["x"]["A"][k][1], -1.5 + vp * tau - a * tau**2 / 2, 1, f"x.A.{k}")
        near(r["v"]["B"][k][1], -(vp - a * tau), 1, f"v.B.{k}")
        near(r["reaction"]["rope"]["T"][k][1], 2 * mA * mB * G / (mA + mB), G, f"T.{k}")


def test_cord_longer_than_its_path_but_not_given_short():
    refusal("""
type: scene
bodies:
  A: {shape: point, mass: 1, x: [0, -1]}
joints:
  rope: {cord: [[0, 0], A], length: 0.5}
at: [0, 1]
""", "joints.rope.length", "shorter than its path")


def test_bowling_ball_gallery():
    r = gallery("bowling-ball-skids.yaml")["results"]
    m, R, v0, mu = 7, mp.mpf("0.11"), 8, mp.mpf("0.1")
    t1 = 2 * v0 / (7 * mu * G)
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("r", "sticks")]
    near(r["events"][0]["t"], t1, t1, "sticks t")
    x1 = v0 * t1 - mu * G * t1**2 / 2
    near(r["events"][0]["state"]["x"]["ball"][0], x1, x1, "x1")
    near(r["v"]["ball"][1][0], v0 - mu * G, v0, "v at 1 s")
    near(r["omega"]["ball"][1][2], -5 * mu * G / (2 * R), v0 / R, "omega at 1 s")
    near(r["v"]["ball"][3][0], 5 * mp.mpf(v0) / 7, v0, "v rolling")
    near(r["x"]["ball"][3][0], x1 + 5 * mp.mpf(v0) / 7 * (3 - t1), x1, "x rolling")
    near(r["reaction"]["r"]["F"][0], -mu * m * G, m * G, "F slipping")
    near(r["W_nc"][3], -m * v0**2 / 7, m * v0**2, "W_nc")


def test_hoop_with_backspin_comes_back():
    # a ring (Ī = m R²) thrown at v0 = 3 m/s with backspin ω0 = 20 rad/s (R ω0 = 4 > v0): the
    # slip speed v0 + R ω0 − 2 μ g t reaches 0 at t1 = (v0 + R ω0)/(2 μ g); then it rolls back
    # at (v0 − R ω0)/2 = −0.5 m/s
    r = _solve("""
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  hoop: {shape: ring, mass: 0.5, radius: 0.2, x: [0, 0.2], v: [3, 0], omega: 20}
joints:
  r: {rolls: [hoop, floor], mu_s: 0.3, mu_k: 0.2}
at: [0, 1, 3]
""")
    mu, v0, w0, R = mp.mpf("0.2"), 3, 20, mp.mpf("0.2")
    t1 = (v0 + R * w0) / (2 * mu * G)
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("r", "sticks")]
    near(r["events"][0]["t"], t1, t1, "sticks t")
    near(r["v"]["hoop"][1][0], v0 - mu * G, v0, "v at 1 s")
    near(r["omega"]["hoop"][1][2], w0 - mu * G / R, w0, "omega at 1 s")
    x1 = v0 * t1 - mu * G * t1**2 / 2
    near(r["x"]["hoop"][2][0], x1 + (v0 - R * w0) / 2 * (3 - t1), x1, "x at 3 s")
    near(r["v"]["hoop"][2][0], (v0 - R * w0) / 2, v0, "v at 3 s")


def test_rolling_given_without_its_spin_still_rolls():
    # omega left out: the rolling row imposes it from the v given (kept): ω = −v/R = −4 rad/s
    # (15.8), and on a level floor nothing changes the rolling: x = 2 m at t = 1 s; no slip
    # (the mass-weighted projection of (v, 0), v = 4/3, moved the speed the file gave)
    r = _solve("""
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  d: {shape: disk, mass: 1, radius: 0.5, x: [0, 0.5], v: [2, 0]}
joints:
  r: {rolls: [d, floor], mu_s: 0.1}
at: [0, 1]
""")
    assert r["events"] == []
    near(r["omega"]["d"][0][2], mp.mpf(-4), 4, "omega")
    near(r["x"]["d"][1][0], mp.mpf(2), 2, "x")


def test_rolling_that_would_slip_at_start_slips():
    # a uniform disk on a 30° incline needs |F| = m g sin β / 3 = 1.635 N; μ_s = 0.1 gives only
    # μ_s m g cos β: it slips from t = 0 with μ_k = μ_s: a = g (sin β − μ cos β) down the slope,
    # α = −2 μ g cos β / R (it never rolls: μ < tan β / 3)
    r = _solve("""
type: scene
surfaces:
  slope: {through: [0, 0], direction: ["cos(30*deg)", "-sin(30*deg)"]}
bodies:
  wheel: {shape: disk, mass: 1, radius: 0.2, angle: 0}
joints:
  r: {rolls: [wheel, slope], at: 0, mu_s: 0.1}
at: [0, 1]
""")
    b, mu, R = mp.pi / 6, mp.mpf("0.1"), mp.mpf("0.2")
    a = G * (mp.sin(b) - mu * mp.cos(b))
    assert r["events"] == []
    near(r["a"]["wheel"][0][0], a * mp.cos(b), G, "a.0")
    near(r["a"]["wheel"][0][1], -a * mp.sin(b), G, "a.1")
    near(r["alpha"]["wheel"][0][2], -2 * mu * G * mp.cos(b) / R, G / R, "alpha")
    near(r["reaction"]["r"]["F"][1], -mu * G * mp.cos(b), G, "F")
    near(r["reaction"]["r"]["N"][1], G * mp.cos(b), G, "N")
    assert r["dof"] == 2, "slipping from the start: the centre along the slope and the spin (before: 1)"


WHEEL_AND_BLOCK = """
type: scene
surfaces:
  slope: {{through: [0, 0], direction: ["cos(30*deg)", "-sin(30*deg)"]}}
bodies:
  wheel: {{shape: disk, mass: 1, radius: 0.2, angle: 0}}
  block: {{shape: point, mass: 1, x: [2, "-2*tan(30*deg)"]}}
joints:
  r: {{rolls: [wheel, slope], at: 0, mu_s: {mu}}}
  b: {{contact: [block, slope], mu_s: 0.9, mu_k: 0.5}}
at: [0]
"""


def test_dof_counts_rolling_while_it_rolls_and_a_block_held_by_friction_as_free():
    # the block (μ_s = 0.9 > tan 30°) is held, yet it may slide: 1 degree of freedom; the wheel
    # rolls with μ_s = 0.5 (needs tan β / 3 = 0.19): 1; with μ_s = 0.1 it slips from t = 0: 2
    assert _solve(WHEEL_AND_BLOCK.format(mu=0.5))["dof"] == 2
    assert _solve(WHEEL_AND_BLOCK.format(mu=0.1))["dof"] == 3
