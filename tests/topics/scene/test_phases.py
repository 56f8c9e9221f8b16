"""Scenes past their events: phases, impacts, the accumulation rule (docs/types/scene.md).

Every reference is computed here, independently of dyncli: closed forms by hand (the notes'
28.7, 28.16, 33.2; the geometric series of a bouncing ball's flight times), and mpmath at 30
digits for the event times that are roots of transcendental equations (``mp.findroot`` on the
hand-integrated motion of each phase).  Tolerances: an exact route (closed-form, statics)
1e-12 relative to the quantity's scale; an ODE route ``ODE_GLOBAL`` × rtol of the state's scale,
the forces 10 × that (docs/accuracy.md).
"""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import PROBLEMS, run_cli, solve_one_text, solve_path
from tests.tolerances import ODE_GLOBAL

mp.mp.dps = 30
G = 9.81
RTOL = 1e-10                      # the default accuracy.rtol
ODE_TOL = ODE_GLOBAL * RTOL
EXACT = 1e-12


def near(got, want, tol, scale, what):
    assert got is not None, f"{what}: null"
    assert abs(float(got) - float(want)) <= tol * abs(float(scale)), f"{what}: {got!r} vs {float(want)!r}"


def _gallery(name):
    recs = solve_path(PROBLEMS / "scenes" / name)
    assert len(recs) == 1 and recs[0].get("error") is None
    return recs[0]


# ---------------------------------------------------------------------------------------------
# impacts: the bouncing ball (the geometric series) and the rod striking a ledge (33.2)

def test_bouncing_ball_impact_times_losses_and_rest():
    rec = _gallery("bouncing-ball.yaml")
    r = rec["results"]
    m, h, e = 0.5, mp.mpf(1), mp.mpf("0.8")
    t1 = mp.sqrt(2 * h / G)
    v1 = G * t1
    assert r["route"] == "closed-form"
    imps = r["impacts"]
    events = r["events"]
    assert [ev["what"] for ev in events] == ["impact"] * len(imps) + ["rests"]
    # the rule: bounces until the rebound speed is below sqrt(rtol) v1, then the series is summed
    k_last = len(imps) - 1
    assert e ** (k_last + 1) * v1 <= math.sqrt(RTOL) * v1 < e ** k_last * v1
    for k, im in enumerate(imps):
        tk = t1 + 2 * t1 * sum(e ** j for j in range(1, k + 1))
        vk = v1 * e ** k
        near(im["t"], tk, EXACT, tk, f"impacts.{k}.t")
        near(im["v_n_before"], -vk, EXACT, v1, f"impacts.{k}.v_n_before")
        if k < k_last:
            near(im["v_n_after"], e * vk, EXACT, v1, f"impacts.{k}.v_n_after")
            near(im["impulse"], (1 + e) * m * vk, EXACT, m * v1, f"impacts.{k}.impulse")
            # 28.16 with the floor's infinite mass: m* = m
            near(im["energy_loss"], (1 - e**2) * m * vk**2 / 2, EXACT, m * v1**2 / 2, f"impacts.{k}.energy_loss")
    # the last impact: rebound and rest in one (the plastic remainder of the series)
    near(imps[-1]["energy_loss"], m * (v1 * e**k_last) ** 2 / 2, EXACT, m * v1**2 / 2, "last energy loss")
    t_rest = t1 * (1 + e) / (1 - e)
    near(events[-1]["t"], t_rest, EXACT, t_rest, "rests t")
    # the energy balance holds across every impact (the losses count in W_nc)
    E0 = r["E"][0]
    for k, res in enumerate(r["energy_residual"]):
        near(res, 0, EXACT, E0, f"energy_residual.{k}")
    # after the rest: sliding at 0.3 m/s on the floor with N = m g
    near(r["x"]["ball"][4][1], 0, EXACT, 1, "x.ball.4.1")
    near(r["v"]["ball"][4][0], 0.3, EXACT, 1, "v.ball.4.0")
    near(r["reaction"]["bounce"]["N"][4], m * G, EXACT, m * G, "N after rest")
    # the third crossing of x2 = 0.5 m (down, up, down): on the way down of the first rebound
    q = r["find"][0]
    assert q["reached"] is True
    v2 = e * v1                                      # leaves the floor at t1 at e v1
    near(q["t"], t1 + (v2 + mp.sqrt(v2**2 - 2 * G * mp.mpf("0.5"))) / G, EXACT, 1, "find.0.t")


@pytest.mark.parametrize("e", [0.3, 0.95])
def test_zeno_never_hangs_and_rests_at_the_series_sum(e):
    rec = solve_one_text(f"""
type: scene
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
bodies:
  ball: {{shape: point, mass: 2, x: [0, 0.2]}}
joints:
  bounce: {{stop: [ball, floor], e: {e}}}
at: [0, 100]
""")
    r = rec["results"]
    t1 = mp.sqrt(2 * mp.mpf("0.2") / G)
    rests = [ev for ev in r["events"] if ev["what"] == "rests"]
    assert len(rests) == 1
    near(rests[0]["t"], t1 * (1 + e) / (1 - e), EXACT, 1, "t_rest")
    assert r["x"]["ball"][1][1] == pytest.approx(0, abs=1e-12)
    assert not rec["warnings"]


def test_rod_striking_a_ledge_impulse_and_velocities():
    rec = _gallery("rod-strikes-ledge.yaml")
    r = rec["results"]
    m, L, h, e = 2, 1, mp.mpf("0.5"), mp.mpf("0.5")
    t = mp.sqrt(2 * h / G)
    v = G * t
    # 33.2 by hand: m (v̄⁺ + v) = P, (m L²/12) ω⁺ = (L/2) P, v̄⁺ + (L/2) ω⁺ = e v
    P = (1 + e) * v / (1 / mp.mpf(m) + (L / 2) ** 2 / (m * L**2 / mp.mpf(12)))
    vb, w = -v + P / m, (L / 2) * P / (m * L**2 / mp.mpf(12))
    im = r["impacts"][0]
    near(im["t"], t, EXACT, 1, "impacts.0.t")
    near(im["impulse"], P, EXACT, m * v, "impacts.0.impulse")
    near(im["energy_loss"], (1 - e**2) * (m / mp.mpf(4)) * v**2 / 2, EXACT, m * v**2, "impacts.0.energy_loss")
    near(im["v_n_after"], e * v, EXACT, v, "v_n_after")
    # at t = 0.4 s: free flight from the impact
    near(r["v"]["rod"][2][1], vb - G * (mp.mpf("0.4") - t), EXACT, v, "v.rod.2.1")
    near(r["omega"]["rod"][2][2], w, EXACT, w, "omega.rod.2")
    near(r["angle"]["rod"][2], w * (mp.mpf("0.4") - t), EXACT, 1, "angle.rod.2")
    assert [p["route"] for p in r["phases"]] == ["closed-form", "closed-form"]


def test_ladder_lands_on_the_floor_losing_its_vertical_energy():
    rec = _gallery("sliding-ladder-to-floor.yaml")
    r = rec["results"]
    m, L, th0 = 10, 5, mp.pi / 3
    E = m * G * L / 2 * mp.sin(th0)
    vx = mp.sqrt(G * L) * mp.sin(th0) ** mp.mpf(1.5) / 3          # (L/2) sin θ* |θ̇*|, sin θ* = (2/3) sin θ0
    ths = mp.asin(2 * mp.sin(th0) / 3)

    def thd(th):            # the floor-only phase: momentum along e1 and energy (34.20)
        return mp.sqrt((E - m * vx**2 / 2 - m * G * L / 2 * mp.sin(th))
                       / (m * L**2 / 8 * mp.cos(th) ** 2 + m * L**2 / 24))

    k = 3 * G / L
    ts = mp.quad(lambda th: 1 / mp.sqrt(k * (mp.sin(th0) - mp.sin(th))), [ths, th0])
    t_land = ts + mp.quad(lambda th: 1 / thd(th), [0, ths])
    assert [(p["joints"]) for p in r["phases"]] == [["at_floor", "at_wall"], ["at_floor"], ["at_floor", "lands"]]
    assert [(ev["joint"], ev["what"]) for ev in r["events"]] == [("at_wall", "separates"), ("lands", "impact")]
    near(r["events"][0]["t"], ts, 10 * ODE_TOL, 1, "separation time")
    near(r["events"][1]["t"], t_land, 10 * ODE_TOL, 1, "landing time")
    im = r["impacts"][0]
    near(im["v_n_before"], -L * thd(0), 10 * ODE_TOL, L * thd(0), "the top's speed onto the floor")
    near(im["energy_loss"], E - m * vx**2 / 2, 10 * ODE_TOL, E, "energy lost landing")
    for i in (3, 4):
        near(r["v"]["rod"][i][0], vx, ODE_TOL, vx, f"v.rod.{i}.0")
        near(r["v"]["rod"][i][1], 0, EXACT, vx, f"v.rod.{i}.1")
        near(r["reaction"]["at_floor"]["N"][i], m * G / 2, 10 * ODE_TOL, m * G, f"N at the foot {i}")
        near(r["reaction"]["lands"]["N"][i], m * G / 2, 10 * ODE_TOL, m * G, f"N at the top {i}")
        near(r["energy_residual"][i], 0, 10 * ODE_TOL, E, f"energy_residual.{i}")


# ---------------------------------------------------------------------------------------------
# stick, slip, slack, taut: event times that are roots (mpmath at 30 digits)

def test_block_slides_sticks_and_slides_back_under_a_periodic_push():
    rec = _gallery("stick-slip-periodic.yaml")
    r = rec["results"]
    m, F0, w, mus, muk = 1, 4, 2 * mp.pi, mp.mpf("0.35"), mp.mpf("0.3")
    t1 = mp.asin(mus * m * G / F0) / w
    v = lambda t: F0 / (m * w) * (mp.cos(w * t1) - mp.cos(w * t)) - muk * G * (t - t1)   # noqa: E731
    t2 = mp.findroot(v, mp.mpf("0.49"))
    assert abs(F0 * mp.sin(w * t2)) <= mus * m * G                  # the static test holds there
    want = [(t1, "slips"), (t2, "sticks"), (t1 + mp.mpf(1) / 2, "slips"), (t2 + mp.mpf(1) / 2, "sticks")]
    got = [(ev["t"], ev["what"]) for ev in r["events"]][:4]
    for (tg, wg), (tw, ww) in zip(got, want):
        assert wg == ww
        near(tg, tw, ODE_TOL, 1, f"{ww} at {float(tw)}")
    assert [p["route"] for p in r["phases"]][:3] == ["statics", "ode", "statics"]
    # sliding: F = −μ_k N; held: F = −push
    near(r["reaction"]["rough"]["F"][1], -muk * m * G, EXACT, m * G, "kinetic friction")
    near(r["reaction"]["rough"]["F"][2], -F0 * mp.sin(w / 2), EXACT, F0, "static friction")
    near(r["x"]["A"][4][0], 0, ODE_TOL, 0.1, "back at x = 0 after one period")


def test_cord_goes_slack_and_is_jerked_taut():
    rec = _gallery("cord-jerked-taut.yaml")
    r = rec["results"]
    m = 1
    t1 = mp.asin(mp.mpf("0.8")) / mp.pi
    vB1 = mp.mpf(2.5) * G / 2 * (1 - mp.cos(mp.pi * t1)) / mp.pi

    def gap(t):             # s(t) − s(t1), s = y_A + y_B, in free flight from t1
        return (mp.mpf(2.5) * G * ((t - t1) * mp.cos(mp.pi * t1) / mp.pi - (mp.sin(mp.pi * t) - mp.sin(mp.pi * t1))
                                   / mp.pi**2) - G * (t - t1) ** 2)

    t2 = mp.findroot(gap, mp.mpf("1.1"))
    vA = -vB1 - G * (t2 - t1)
    vB = vB1 + mp.mpf(2.5) * G * (mp.cos(mp.pi * t1) - mp.cos(mp.pi * t2)) / mp.pi - G * (t2 - t1)
    assert [(ev["what"]) for ev in r["events"]] == ["slack", "taut"]
    near(r["events"][0]["t"], t1, ODE_TOL, 1, "slack")
    near(r["events"][1]["t"], t2, ODE_TOL, 1, "taut")
    im = r["impacts"][0]
    assert (im["joint"], im["e"]) == ("rope", 0.0)
    # equal impulses P up on A and B (through the pulley), v_A⁺ + v_B⁺ = 0
    P = -m * (vA + vB) / 2
    near(im["impulse"], P, 10 * ODE_TOL, m * abs(vA), "impulsive tension")
    near(im["energy_loss"], m * (vA + vB) ** 2 / 4, 10 * ODE_TOL, m * vA**2, "energy lost")
    near(im["v_n_before"], vA + vB, 10 * ODE_TOL, abs(vA), "the cord's rate before")
    # the slack phase has no cord row: T = 0 there; taut again after
    assert r["reaction"]["rope"]["T"][2] == [0.0, 0.0] and r["phases"][1]["joints"] == []
    near(r["reaction"]["rope"]["T"][4][0], m * G * (1 + mp.mpf(1.25)), 10 * ODE_TOL, m * G, "T after")


def test_check_solve_covers_the_event_times():
    text = (PROBLEMS / "scenes" / "cord-jerked-taut.yaml").read_text()
    loose = solve_one_text(text.replace("type: scene", "type: scene\naccuracy: {rtol: 1.0e-6, estimate: true}"))
    t1 = mp.asin(mp.mpf("0.8")) / mp.pi
    err = abs(loose["results"]["events"][0]["t"] - t1) / t1
    assert loose["error_estimate"] is not None and err <= loose["error_estimate"]


def test_rolling_disk_slips_and_rolls_again():
    """A disk (m, R, Ī = mR²/2) on a rough floor pushed at its centre by A sin ωt: rolling needs
    friction −F/3, so it slips where A sin ωt = 3 μ_s m g; slipping, the contact point's speed
    u = v + Rω obeys u̇ = F/m − 3 μ_k g (friction −μ_k m g at the contact: I α = −R μ_k m g), so
    it rolls again where u returns to 0 (a root) if the static test holds there."""
    rec = solve_one_text("""
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  D: {shape: disk, mass: 1, radius: 0.5, x: [0, 0.5], angle: 0}
joints:
  roll: {rolls: [D, floor], mu_s: 0.3, mu_k: 0.2}
forces:
  - {force: D, F: ["10*sin(2*t)", 0]}
at: [0, 0.8, 2]
""")
    r = rec["results"]
    A, w, mus, muk = 10, 2, mp.mpf("0.3"), mp.mpf("0.2")
    ts = mp.asin(3 * mus * G / A) / w
    u = lambda t: A / w * (mp.cos(w * ts) - mp.cos(w * t)) - 3 * muk * G * (t - ts)     # noqa: E731
    tr = mp.findroot(u, mp.mpf("1.75"))
    assert abs(A * mp.sin(w * tr)) / 3 <= mus * G
    ev = [(e["what"], e["t"]) for e in r["events"]][:2]
    assert [x for x, _ in ev] == ["slips", "sticks"]
    near(ev[0][1], ts, ODE_TOL, 1, "slips")
    near(ev[1][1], tr, ODE_TOL, 1, "rolls again")
    # slipping at t = 0.8: F = −μ_k N, α = −2 μ_k g / R
    near(r["reaction"]["roll"]["F"][1], -muk * G, EXACT, G, "kinetic friction while slipping")
    near(r["alpha"]["D"][1][2], -2 * muk * G / mp.mpf("0.5"), 10 * ODE_TOL, G, "alpha while slipping")
    assert r["reaction"]["roll"]["slip_margin"][1] is None


def test_a_stop_needs_its_restitution():
    code, out, err = run_cli("solve", "-", input="""
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  ball: {shape: point, mass: 1, x: [0, 1]}
joints:
  bounce: {stop: [ball, floor]}
at: [0, 1]
""")
    assert code == 2 and "joints.bounce.e" in err and "coefficient of restitution" in err and "Traceback" not in err


def test_rough_impact_slides_with_coulomb_friction_of_the_impulse():
    """A ball landing on a rough stop (μ = 0.2, e = 0.5) with 3 m/s sideways: the normal impulse
    is (1 + e) m v_n; holding the sideways speed would need 3m > μ N̂, so the friction impulse is
    −μ N̂ and the sideways speed after is 3 − μ (1 + e) v_n; the energy lost is T⁻ − T⁺."""
    text = """
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  ball: {shape: point, mass: 1, x: [0, 1], v: [3, 0]}
joints:
  bounce: {stop: [ball, floor], e: 0.5, mu: 0.2}
at: [0, 0.5]
"""
    r = solve_one_text(text)["results"]
    vn = mp.sqrt(2 * G)
    im = r["impacts"][0]
    near(im["impulse"], mp.mpf(1.5) * vn, EXACT, vn, "normal impulse")
    near(im["impulse_F"], -mp.mpf(0.2) * mp.mpf(1.5) * vn, EXACT, vn, "friction impulse")
    vt = 3 - mp.mpf(0.2) * mp.mpf(1.5) * vn
    near(r["v"]["ball"][1][0], vt, EXACT, 3, "sideways speed after")
    near(im["energy_loss"], (9 + vn**2 - vt**2 - (vn / 2) ** 2) / 2, EXACT, vn**2, "energy lost")
    near(r["energy_residual"][1], 0, EXACT, vn**2, "energy balance")
    bad = text.replace("x: [0, 1]", "x: [0, -1]")
    code, _, err = run_cli("solve", "-", input=bad)
    assert code == 2 and "wrong side of the surface 'floor'" in err and "joints.bounce" in err


def test_the_cap_on_phases_stops_the_motion_with_a_warning(monkeypatch):
    from dyncli.topics.scene import phases

    monkeypatch.setattr(phases, "MAX_PHASES", 5)
    rec = solve_one_text("""
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  ball: {shape: point, mass: 1, x: [0, 1]}
joints:
  bounce: {stop: [ball, floor], e: 0.9}
at: [0, 0.5, 10]
""")
    r = rec["results"]
    assert len(r["phases"]) == 5 and len(r["impacts"]) == 4
    assert r["x"]["ball"][1] is not None and r["x"]["ball"][2] is None
    assert any("5 phases" in w and "stops there" in w for w in rec["warnings"])


#: a bob on a light link released 45° from the vertical, striking a wall 30° on the other side
#: (``rough``: the stop's friction, e.g. ", mu: 0.3"; tests/topics/scene/test_rough_impacts.py)
BOB_AT_WALL = """
type: scene
surfaces:
  wall: {{through: [0.5, 0], direction: [0, 1]}}
bodies:
  bob: {{shape: point, mass: 1, x: ["-sqrt(0.5)", "-sqrt(0.5)"]}}
joints:
  arm: {{link: [[0, 0], bob], length: 1}}
  hit: {{stop: [bob, wall], e: 0.7{rough}}}
at: [0, 1]
"""


def test_pendulum_strikes_a_wall():
    """A bob (m = 1 kg) on a light link (L = 1 m) released 45° from the vertical strikes a wall at
    x1 = 0.5 m (30° on the other side; a stop, e = 0.7).  Energy (34.20): v² = 2 g L (cos 30° −
    cos 45°); time: t = ∫ dφ / sqrt((2g/L)(cos φ − cos φ0)) from −45° to 30° (mpmath quadrature).
    The link keeps the bob on its circle, so the velocity is tangent and the wall's impulse and
    the link's impulsive tension together reverse only its normal part with e: the bob leaves at
    e v along the circle, and the loss is (1 − e²) ½ m v² (28.16 with the circle's m* = m)."""
    rec = solve_one_text(BOB_AT_WALL.format(rough=""))
    r = rec["results"]
    phi0, phi1, e = mp.pi / 4, mp.pi / 6, mp.mpf("0.7")
    v = mp.sqrt(2 * G * (mp.cos(phi1) - mp.cos(phi0)))
    t = mp.quad(lambda p: 1 / mp.sqrt(2 * G * (mp.cos(p) - mp.cos(phi0))), [-phi0, 0, phi1])
    im = r["impacts"][0]
    near(im["t"], t, ODE_TOL, 1, "impact time")
    near(im["energy_loss"], (1 - e**2) * v**2 / 2, 10 * ODE_TOL, v**2, "energy loss")
    near(im["v_n_after"], -e * im["v_n_before"], EXACT, v, "restitution")
    st_after = math.hypot(*r["events"][0]["state"]["v"]["bob"][:2])
    near(st_after, v, ODE_TOL, v, "speed just before")
