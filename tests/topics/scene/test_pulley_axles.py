"""A massive pulley on a fixed axle whose cord runs to a body another joint guides (a block on a
table or an incline), and ends that reach their pulley along a segment kept straight.

* The axle's reaction carries the pull of *every* segment (before: a segment that turns with its
  block, elements.Turning, had no column for the disk's centre, so its tension was missing from
  the pin's reaction: [0, 34.335] N where the free-body diagram gives [9.81, 34.335] N).  The
  reference is the pulley's free-body diagram by hand and, as a second route, the momentum of
  the whole system (Σ m a = Σ external forces: the pin's reaction is what is left).
* ``--symbolic`` writes the same rows: the disk's angle and centre appear in the turning
  segment's length, so its tension turns the disk and pulls on the axle; the reduced equation
  gives the engine's acceleration away from the start.
* ``reaches`` for a hanging mass hoisted into its pulley and a yo-yo thrown up to the hand (a
  segment kept along its direction of t = 0: before, the end passed through its pulley with no
  event): the motion stops where the straight part is down to a millionth of the cord.
"""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_text

G = 9.81

TABLE = """
type: scene
surfaces:
  table: {through: [-3, 0], direction: [1, 0], length: 3}
bodies:
  pulley: {shape: disk, mass: M, radius: 0.1, x: [0, -0.1], angle: 0}
  A: {shape: point, mass: 2, x: [-1, 0]}
  B: {shape: point, mass: 3, x: [0.1, -1]}
joints:
  axle: {pin: [pulley, ground]}
  slide: {contact: [A, table]}
  rope: {cord: [A, pulley, B]}
at: [0, 0.3]
"""

INCLINE = """
type: scene
params: {beta: "30*deg", R: 0.1}
surfaces:
  slope: {through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}
bodies:
  pulley: {shape: disk, mass: 2, radius: R, x: ["3*cos(beta) + R*sin(beta)", "3*sin(beta) - R*cos(beta)"], angle: 0}
  A: {shape: point, mass: 2, x: ["cos(beta)", "sin(beta)"]}
  B: {shape: point, mass: 3, x: ["3*cos(beta) + R*sin(beta) + R", -1]}
joints:
  axle: {pin: [pulley, ground]}
  slide: {contact: [A, slope], mu_s: 0.15, mu_k: 0.1}
  rope: {cord: [A, pulley, B]}
at: [0, 0.5]
"""


def _results(text: str) -> dict:
    rec = solve_text(text)[0]
    assert not rec.get("error"), rec.get("error")
    return rec["results"]


@pytest.mark.parametrize("M", [2.0, 0.0])
def test_the_axle_of_a_pulley_at_a_tables_edge_carries_both_strands(M):
    """Block A (2 kg) on a smooth table, the cord level from A to the top of a uniform disk
    pulley (M, R = 0.1) pinned at its centre, down to B (3 kg).  By hand: a = m_B g/(m_A + m_B +
    M/2), T1 = m_A a (level, toward A), T2 = m_B (g − a); the pulley at rest: R = [T1, M g + T2].
    Second route: the whole system's momentum, Σ m a = R + N e2 − Σ m g e2 with N = m_A g."""
    r = _results(TABLE.replace("mass: M", f"mass: {M}"))
    a = 3 * G / (5 + M / 2)
    T1, T2 = 2 * a, 3 * (G - a)
    for i in range(2):
        R = r["reaction"]["axle"]["R"][i]
        assert R[0] == pytest.approx(T1, rel=1e-12) and R[1] == pytest.approx(M * G + T2, rel=1e-12)
        assert r["reaction"]["rope"]["T"][i] == pytest.approx([T1, T2], rel=1e-12)
        N = r["reaction"]["slide"]["N"][i]
        momentum = [2 * r["a"]["A"][i][0] + 3 * r["a"]["B"][i][0],
                    2 * r["a"]["A"][i][1] + 3 * r["a"]["B"][i][1]]      # the pulley's centre is at rest
        assert momentum[0] == pytest.approx(R[0], rel=1e-12)
        assert momentum[1] == pytest.approx(R[1] + N - (5 + M) * G, abs=1e-12 * (5 + M) * G)


def test_the_axle_of_a_pulley_atop_a_rough_incline():
    """Block A (2 kg) on a rough 30° incline (μ_s 0.15, μ_k 0.1) tied parallel to the slope over a
    uniform disk (2 kg, R = 0.1) pinned at the top to B (3 kg) hanging.  It slides up (the static
    test needs (m_B − m_A sin β) g = 19.62 N > μ_s N): s̈ = (m_B g − m_A g sin β − μ_k N)/(m_A + m_B
    + M/2), T1 = m_A (s̈ + g sin β) + μ_k N, T2 = m_B (g − s̈); the pulley at rest:
    R = [T1 cos β, M g + T1 sin β + T2]."""
    r = _results(INCLINE)
    b = math.radians(30)
    N = 2 * G * math.cos(b)
    sdd = (3 * G - 2 * G * math.sin(b) - 0.1 * N) / 6
    T1, T2 = 2 * (sdd + G * math.sin(b)) + 0.1 * N, 3 * (G - sdd)
    assert r["a"]["B"][0][1] == pytest.approx(-sdd, rel=1e-12)
    assert r["reaction"]["rope"]["T"][0] == pytest.approx([T1, T2], rel=1e-12)
    assert r["reaction"]["axle"]["R"][0][:2] == pytest.approx([T1 * math.cos(b), 2 * G + T1 * math.sin(b) + T2],
                                                              rel=1e-12)


def test_symbolic_rows_turn_the_pulley_under_a_turning_segment():
    """The pulley's moment balance has both tensions, and the reduced equation in the pulley's
    angle gives the engine's acceleration at a state away from the start (A moved, moving)."""
    from tests.topics.scene.test_symbolic import _reduced_matches_engine_away_from_start

    _reduced_matches_engine_away_from_start(TABLE.replace("mass: M", "mass: 2"), {"x.A.0": -0.6},
                                            {"x.A.0": 1.5})


def test_symbolic_pulley_balance_names_both_tensions(tmp_path):
    from tests.conftest import run_cli

    f = tmp_path / "t.yaml"
    f.write_text(TABLE.replace("mass: M", "mass: 2"))
    code, out, err = run_cli("solve", str(f), "--symbolic")
    assert code == 0, err
    line = next(x for x in out.splitlines() if "Ī_pulley θ̈_pulley =" in x)
    assert "T_rope,1" in line and "T_rope,2" in line, line


HOIST = """
type: scene
bodies:
  A: {shape: point, mass: 1, x: [-0.1, -0.5]}
  B: {shape: point, mass: 3, x: [0.1, -1.5]}
joints:
  rope: {cord: [A, {pulley: [0, 0], radius: 0.1}, B]}
at: [0, 0.4, 1.0]
find:
  - {event: reaches}
"""

YOYO = """
type: scene
bodies:
  yoyo: {shape: disk, mass: 0.2, radius: 0.05, x: [0.01, -0.5], v: [0, 1]}
joints:
  string: {cord: [[0, 0], {wound: yoyo, radius: 0.01}]}
at: [0, 0.9]
t_end: 1
find:
  - {event: reaches}
"""


def test_a_hanging_mass_hoisted_into_its_pulley_stops_there():
    """A (1 kg) and B (3 kg) over a light pulley (radius 0.1), A 0.5 m below its tangent point:
    a = (3 − 1) g/4 from rest, A's straight part 0.5 − a t²/2 is down to 1e-6 of the cord's
    straight length (2 m) at t = √(2 (0.5 − 2e-6)/a); the results after it are null, warned."""
    rec = solve_text(HOIST)[0]
    r = rec["results"]
    a = 2 * G / 4
    t = math.sqrt(2 * (0.5 - 2e-6) / a)
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("rope", "reaches")]
    assert r["events"][0]["t"] == pytest.approx(t, rel=1e-12)
    assert r["find"][0]["t"] == pytest.approx(t, rel=1e-12)
    assert r["x"]["A"][1][1] == pytest.approx(-0.5 + a * 0.4 ** 2 / 2, rel=1e-12)
    assert r["x"]["A"][2] is None
    assert any("no straight part left" in w for w in rec["warnings"])


def test_a_yoyo_thrown_up_to_the_hand_stops_there():
    """A yo-yo (uniform disk m, R = 0.05, hub r = 0.01) on a string from the hand, 0.5 m below it,
    thrown up at 1 m/s: a = −g/(1 + R²/(2 r²)); the string's straight part 0.5 − (t + a t²/2) is
    down to 1e-6 of its length (0.5 m) where t + a t²/2 = 0.5 − 5e-7."""
    r = _results(YOYO)
    a = -G / (1 + 0.05 ** 2 / (2 * 0.01 ** 2))
    d = 0.5 - 5e-7
    t = (-1 + math.sqrt(1 + 2 * a * d)) / a
    assert r["a"]["yoyo"][0][1] == pytest.approx(a, rel=1e-12)
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("string", "reaches")]
    assert r["events"][0]["t"] == pytest.approx(t, rel=1e-12)
