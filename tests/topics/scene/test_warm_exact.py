"""What a warm scene solve decides without a search, and the trajectory read on arrays.

* A closed-form phase whose joint forces are one constant (every made row linear, nothing
  driven, every load a constant force or couple: routes.constant_forces) has no crossing of a
  force watch off its band: the tensions of an Atwood machine are not searched, and the first
  event left (A landing on a floor, a gap: still searched) is the closed form's.  Reference:
  the notes' Atwood machine (16.7, 32.15), a = (m1 − m2) g / (m1 + m2 + M/2), y_A = −1 − a t²/2,
  the floor at y = −2 reached at t* = sqrt(2/a) (mpmath, 30 digits).
* The trajectory read on arrays (Trajectory.coordinates, .velocities, .increments) gives the
  numbers of one time at a time bit for bit (the results of a solve do not change with it).
"""

from __future__ import annotations

import mpmath as mp
import numpy as np

from tests.conftest import solve_one_text
from tests.topics.scene.common import DOUBLE_PENDULUM

G = 9.81

ATWOOD = """
type: scene
params: {{m1: 3, m2: 2, M: 1, R: 0.1}}
surfaces:
  floor: {{through: [0, -2], direction: [1, 0]}}
bodies:
  pulley: {{shape: disk, mass: M, radius: R, x: [0, 0], angle: 0}}
  A: {{shape: point, mass: m1, x: ["-R", -1]}}
  B: {{shape: point, mass: m2, x: [R, -1.5]}}
joints:
  axle: {{pin: [pulley, ground]}}
  rope: {{cord: [A, pulley, B]}}
  land: {{stop: [A, floor], e: 0}}
{forces}
at: [0, 0.5, 1]
t_end: 1.5
"""

DOUBLE = """
type: scene
params: {m1: 1, m2: 2, L1: 1, L2: 0.7, p1: "60*deg", p2: "20*deg"}
""" + DOUBLE_PENDULUM + """at: [0, 1.5]
"""


def _scene(text: str):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver
    from tests.conftest import ROOT

    problems, diags = split_problems("t.yaml", text.encode(), ROOT)
    assert not diags
    validate(problems[0])
    return prepare.setup(solver._plan(problems[0].model))


def _run(text: str, t_end: float):
    from dyncli.integrators import Accuracy
    from dyncli.topics.scene import routes

    scene = _scene(text)
    traj, route = routes.run(scene, t_end, Accuracy(1e-10, 1e-13, "auto", False, 50_000))
    return scene, traj, route


def _atwood_reference():
    with mp.workdps(30):
        m1, m2, M = mp.mpf(3), mp.mpf(2), mp.mpf(1)
        a = (m1 - m2) * mp.mpf(G) / (m1 + m2 + M / 2)
        return a, mp.sqrt(2 / a), m1 * (mp.mpf(G) - a), m2 * (mp.mpf(G) + a)


def test_the_tensions_of_a_constant_phase_are_decided_and_the_landing_is_the_closed_form():
    rec = solve_one_text(ATWOOD.format(forces=""))
    r = rec["results"]
    a, t_land, T1, T2 = _atwood_reference()
    assert r["route"] == "closed-form"
    first = r["events"][0]
    assert (first["joint"], first["what"]) == ("land", "impact")
    # the closed form is exact: the event to the rounding of the time (a few ulps through a)
    assert abs(first["t"] - float(t_land)) <= 1e-13 * float(t_land)
    assert abs(r["x"]["A"][1][1] - float(-1 - a / 8)) <= 1e-13
    T = r["reaction"]["rope"]["T"][1]
    assert abs(T[0] - float(T1)) <= 1e-12 * float(T1)
    assert abs(T[1] - float(T2)) <= 1e-12 * float(T2)


def test_the_forces_are_constant_by_structure_only():
    from dyncli.topics.scene import routes

    assert routes.constant_forces(_scene(ATWOOD.format(forces="")).system)
    constant = "forces:\n  - {force: B, F: [0, 5]}"
    assert routes.constant_forces(_scene(ATWOOD.format(forces=constant)).system)
    spring = "forces:\n  - {spring: [[0.1, -3], B], k: 10, L: 1}"
    assert not routes.constant_forces(_scene(ATWOOD.format(forces=spring)).system)
    in_time = "forces:\n  - {force: B, F: [0, \"5*t\"]}"
    assert not routes.constant_forces(_scene(ATWOOD.format(forces=in_time)).system)
    assert not routes.constant_forces(_scene(DOUBLE).system)       # links that turn: J changes


def test_a_constant_force_off_its_band_has_no_crossing_and_the_search_agrees():
    """The decision against today's search: the tension watches of the Atwood machine's first
    phase, searched by crossing.first_crossing on the closed form, have no crossing either."""
    from dyncli.topics.scene import crossing, motion

    scene, traj, _ = _run(ATWOOD.format(forces=""), 1.5)
    s, p = scene.system, traj.pieces[0]
    motion.set_modes(s, p.modes)
    q, v, _ = p.fn(p.t_a)
    tol = crossing.rounding(s, q, v, p.t_a, p.fn(p.t_b)[1])
    forces = [(j, what, g) for j, (_joint, what, g) in enumerate(motion.watches(s, q, v, p.t_a))
              if what in crossing.FORCES]
    assert len(forces) == 2                 # the cord's two runs (the floor's gap: an impact)
    for j, what, g in forces:
        assert abs(g) > 2 * tol[what]

        def column(ts, j=j):
            return np.array([motion.watches(s, *p.fn(float(t))[:2], float(t))[j][2] for t in np.atleast_1d(ts)])
        assert crossing.first_crossing(column, p.t_a, p.t_b, what, tol[what], True, 1) is None


def test_the_trajectory_read_on_arrays_is_one_time_at_a_time_bit_for_bit():
    scene, traj, route = _run(DOUBLE, 1.5)
    assert route == "ode"
    n = scene.system.n
    ts = np.linspace(0.0, 1.5, 97)
    Y = traj.coordinates(ts)
    for k, t in enumerate(ts):
        p = traj.piece(float(t))
        y = np.asarray(p.batch(min(max(float(t), p.t_a), p.t_b)), dtype=float)
        assert np.array_equal(Y[:, k], y[:2 * n])
    inc = traj.increments(2 * n)
    for j, p in enumerate(traj.pieces):
        if p.t_b > p.t_a:
            assert inc[j] == float(p.batch(p.t_b)[2 * n]) - float(p.batch(p.t_a)[2 * n])

    scene, traj, route = _run(ATWOOD.format(forces=""), 1.5)
    ts = np.linspace(0.0, 1.5, 41)
    V = traj.velocities(ts)
    for k, t in enumerate(ts):
        p = traj.piece(float(t))
        assert np.array_equal(V[k], p.fn(min(max(float(t), p.t_a), p.t_b))[1])


# ----------------------------------------------------------------------------- gaps as quadratics

BALL = """
type: scene
params: {{m: 0.5, h: 1.5}}
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
bodies:
  ball: {{shape: point, mass: m, x: [0, h], v: [0.3, {v0}]}}
joints:
  bounce: {{stop: [ball, floor], e: 0.5}}
at: [0, 0.5]
t_end: 3
"""


def _landing(h, v0):
    """The first landing of a ball thrown up at v0 from h: h + v0 t − g t²/2 = 0 (mpmath)."""
    with mp.workdps(30):
        g, h, v0 = mp.mpf(G), mp.mpf(h), mp.mpf(v0)
        return (v0 + mp.sqrt(v0 * v0 + 2 * g * h)) / g


def test_a_flight_over_a_line_is_decided_from_its_quadratic(monkeypatch):
    """The gap of a point over a line without ends, in free flight, is a quadratic in t: its
    crossing is decided from the quadratic (no all_roots search), located by Brent on the gap
    itself to the rounding of the time; the second landing after a bounce (e = 0.5) too."""
    from dyncli.topics.scene import crossing

    searched = []
    real = crossing.first_crossing
    monkeypatch.setattr(crossing, "first_crossing", lambda *a, **k: searched.append(a[3]) or real(*a, **k))
    for v0 in (0.0, 2.0, -1.0):
        r = solve_one_text(BALL.format(v0=v0))["results"]
        t1 = _landing(1.5, v0)
        ev = r["events"]
        assert (ev[0]["joint"], ev[0]["what"]) == ("bounce", "impact")
        assert abs(ev[0]["t"] - float(t1)) <= 8 * 2.2e-16 * float(t1)
        with mp.workdps(30):        # up again at half the landing speed: the next flight 2 (v/2)/g
            v1 = mp.mpf(G) * t1 - mp.mpf(v0)
            t2 = t1 + v1 / mp.mpf(G)
        assert abs(ev[1]["t"] - float(t2)) <= 1e-13 * float(t2)
    assert "impact" not in searched


def test_the_quadratic_decision_answers_only_what_it_can_tell():
    """crossing.quadratic_crossing on quadratics given exactly: a clear miss is None, a clear
    crossing is g's own root (mpmath), a graze of the band or a start below it is UNDECIDED."""
    from dyncli.topics.scene import crossing

    tol = 1e-12

    def err(a, b):
        return 1e-14

    def quad(c0, c1, c2):
        return lambda ts: c0 + c1 * np.asarray(ts) + c2 * np.asarray(ts) ** 2

    assert crossing.quadratic_crossing(quad(1.0, -0.5, 0.2), 0.0, 3.0, tol, err) is None
    got = crossing.quadratic_crossing(quad(1.0, 0.5, -4.905), 0.0, 3.0, tol, err)
    with mp.workdps(30):
        root = (mp.mpf(0.5) + mp.sqrt(mp.mpf(0.25) + 4 * mp.mpf(4.905))) / (2 * mp.mpf(4.905))
    assert abs(got - float(root)) <= 4 * 2.2e-16 * float(root)
    # a dip to −tol/2 at t = 1: inside the band by more than the error, not an event
    assert crossing.quadratic_crossing(quad(1.0 - 0.5 * tol, -2.0, 1.0), 0.0, 3.0, tol, err) is None
    # a graze of −tol itself (within the quadratic's error): too close to call
    for d in (0.0, 1e-14, -1e-14):
        assert crossing.quadratic_crossing(quad(1.0 - tol + d, -2.0, 1.0), 0.0, 3.0, tol, err) == crossing.UNDECIDED
    assert crossing.quadratic_crossing(quad(-2 * tol, -1.0, 0.0), 0.0, 3.0, tol, err) == crossing.UNDECIDED
    assert crossing.quadratic_crossing(quad(1.0, -1.0, 0.0), 0.0, 3.0, tol, lambda a, b: tol) == crossing.UNDECIDED
