"""Curved surfaces in scenes: the rows of a contact and of rolling on a curve against
differences (as the straight elements' tests), and the motions against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import ROOT, solve_one_text, solve_text
from tests.topics.scene.test_engine import _fd_check

ELLIPSE = """\
type: scene
title: curved rows
surfaces:
  rim: {curve: {x1: "2*sin(q)", x2: "1 - cos(q) + 0.3*q**2"}}
bodies:
  block: {shape: box, mass: 1, size: [0.2, 0.1], angle: 0.2}
  wheel: {shape: disk, mass: 2, radius: 0.15, angle: 0.1}
joints:
  c: {contact: [block.corner, rim], at: 0.2}
  r: {rolls: [wheel, rim], at: -0.6}
at: [0]
"""


def _scene(text: str):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver

    problems, diags = split_problems("t.yaml", text.encode(), ROOT)
    assert not diags
    validate(problems[0])
    return prepare.setup(solver._plan(problems[0].model))


def test_curved_rows_against_differences():
    """J by central differences of φ, γ by the second difference of φ along q + vτ + ½aτ²
    (J a = γ), at states off the curve too (the rows are exact functions of q, not only on it)."""
    text = ELLIPSE.replace("size: [0.2, 0.1],", "size: [0.2, 0.1], points: {corner: [0.1, -0.05]},")
    sc = _scene(text)
    rng = np.random.default_rng(3)
    for _ in range(6):
        q = sc.q0 + rng.normal(scale=0.02, size=sc.system.n)
        v = rng.normal(size=sc.system.n)
        _fd_check(sc.system, q, v)


def test_curved_contact_hessian_against_differences():
    from dyncli.topics.scene import curvature

    text = ELLIPSE.replace("size: [0.2, 0.1],", "size: [0.2, 0.1], points: {corner: [0.1, -0.05]},")
    s = _scene(text).system
    q = _scene(text).q0 + 0.01
    h = 1e-6
    for name, w in (("c", np.array([1.7])), ("r", np.array([0.8, -1.3]))):
        el = next(e for e in s.elements if e.name == name)
        H = el.hessian(q, w, s.n)
        for j in range(s.n):
            dq = np.zeros(s.n)
            dq[j] = h
            col = (el.jac(q + dq) - el.jac(q - dq)).T @ w / (2 * h)
            assert H[:, j] == pytest.approx(col, abs=1e-6), name
    assert curvature.rows_hessian(s, q, np.zeros(s.m)).shape == (s.n, s.n)


BOWL = """\
type: scene
title: bowl
surfaces:
  bowl: {curve: {x1: "%(x1)s", x2: "%(x2)s"}}
bodies:
  b: {shape: %(shape)s, mass: 0.7%(size)s}
joints:
  j: {%(joint)s: [b, bowl], at: %(at)s}
at: [0, 0.3]
linearize: true
"""


@pytest.mark.parametrize("shape, joint, I_over_mr2", [("point", "contact", 0.0), ("disk", "rolls", 0.5),
                                                      ("ring", "rolls", 1.0)])
@pytest.mark.parametrize("curve, rho", [(("1.3*sin(q)", "-1.3*cos(q)"), 1.3),          # a circle of radius 1.3
                                        (("q", "q**2/(2*0.8)"), 0.8)])                   # a parabola, ρ = 0.8 at its vertex
def test_small_oscillations_in_a_bowl(shape, joint, I_over_mr2, curve, rho):
    """ω² = g/((ρ − r)(1 + Ī/(m r²))) at the bottom (ρ the bowl's radius of curvature there; the
    centre's path is the offset curve, radius ρ − r), from `linearize: true` (the rows' Hessians)."""
    r = 0.1 if shape != "point" else 0.0
    text = BOWL % {"x1": curve[0], "x2": curve[1], "shape": shape, "size": f", radius: {r}" if r else "",
                   "joint": joint, "at": 0.2}
    rec = solve_one_text(text)
    eq = rec["results"]["equilibria"]
    stable = [e for e in eq if e["stable"]]
    assert len(stable) == 1
    want = math.sqrt(9.81 / ((rho - r) * (1 + I_over_mr2)))
    assert stable[0]["frequencies"][0] == pytest.approx(want, rel=1e-9)


@pytest.mark.parametrize("v0_sq", [4.5, 3.0])
def test_loop_separation_against_closed_form(v0_sq):
    """N = m (v0² − 2gR + 3gR cos φ)/R vanishes at cos φ* = (2gR − v0²)/(3gR); the time is the
    quadrature ∫ R dφ / v (mpmath at 30 digits)."""
    mpmath = pytest.importorskip("mpmath")
    R, g = 0.8, 9.81
    text = f"""\
type: scene
surfaces:
  loop: {{curve: {{x1: "{R}*sin(q)", x2: "{R} - {R}*cos(q)"}}}}
bodies:
  block: {{shape: point, mass: 0.3, v: ["sqrt({v0_sq}*9.81*{R})", 0]}}
joints:
  track: {{contact: [block, loop], at: 0}}
at: [0, 2]
"""
    rec = solve_one_text(text)
    ev = rec["results"]["events"]
    assert ev[0]["what"] == "separates"
    c = (2 - v0_sq) / 3
    phi = math.acos(c)
    x = ev[0]["state"]["x"]["block"]
    assert x[0] == pytest.approx(R * math.sin(phi), abs=1e-8) and x[1] == pytest.approx(R - R * c, abs=1e-8)
    with mpmath.workdps(30):
        v0 = mpmath.sqrt(v0_sq * g * R)
        t = mpmath.quad(lambda p: R / mpmath.sqrt(v0 ** 2 - 2 * g * R * (1 - mpmath.cos(p))), [0, phi])
    assert ev[0]["t"] == pytest.approx(float(t), rel=1e-8)
    # then free flight (a parabola from the separation state) until it strikes the loop again
    ph = rec["results"]["phases"]
    assert ph[1]["joints"] == [] and ph[1]["route"] == "closed-form"
    if len(ev) > 1:
        assert ev[1]["what"] == "impact"
        xb = ev[1]["state"]["x"]["block"]
        assert math.hypot(xb[0], xb[1] - R) == pytest.approx(R, abs=1e-8)     # back on the circle


def test_rolling_in_a_bowl_period_and_no_slip():
    """A disk released at 40° in a circular bowl: the bottom at T/4 = sqrt(ℓ/g) K(sin²(φ0/2)),
    ℓ = 1.5 (R − r); the contact point at rest (v̄ = −ω r along t̂ at every requested time)."""
    mpmath = pytest.importorskip("mpmath")
    R, r, phi0 = 0.6, 0.08, math.radians(40)
    text = f"""\
type: scene
surfaces:
  bowl: {{curve: {{x1: "{R}*sin(q)", x2: "-{R}*cos(q)"}}}}
bodies:
  d: {{shape: disk, mass: 1.2, radius: {r}, angle: 0}}
joints:
  j: {{rolls: [d, bowl], at: {phi0}}}
at: [0.1, 0.3, 0.5]
find: [{{when: {{x.d.0: 0}}}}]
"""
    rec = solve_one_text(text)
    ell = 1.5 * (R - r)
    with mpmath.workdps(30):
        quarter = mpmath.sqrt(ell / 9.81) * mpmath.ellipk(mpmath.sin(phi0 / 2) ** 2)
    assert rec["results"]["find"][0]["t"] == pytest.approx(float(quarter), rel=1e-8)
    res = rec["results"]
    for k in range(3):
        x, v, w = res["x"]["d"][k], res["v"]["d"][k], res["omega"]["d"][k][2]
        phi = math.atan2(x[0], -x[1])
        tangent = (math.cos(phi), math.sin(phi))
        assert v[0] * tangent[0] + v[1] * tangent[1] == pytest.approx(-w * r, abs=1e-8)
        assert math.hypot(*x[:2]) == pytest.approx(R - r, abs=1e-10)


def test_gallery_ball_in_bowl():
    """problems/scenes/ball-in-bowl.yaml against its closed forms (a pendulum of length 1.5 (R − r))."""
    mpmath = pytest.importorskip("mpmath")
    from tests.topics.scene.common import gallery

    res = gallery("ball-in-bowl.yaml")["results"]
    m, r, R, phi0, g = 0.5, 0.05, 0.5, math.pi / 6, 9.81
    ell = 1.5 * (R - r)
    assert res["equilibria"][0]["frequencies"][0] == pytest.approx(math.sqrt(g / ell), rel=1e-9)
    with mpmath.workdps(30):
        quarter = float(mpmath.sqrt(ell / g) * mpmath.ellipk(mpmath.sin(phi0 / 2) ** 2))
    f = res["find"][0]
    assert f["t"] == pytest.approx(quarter, rel=1e-8)
    assert f["reaction"]["roll"]["N"] == pytest.approx(m * g * (1 + 4 / 3 * (1 - math.cos(phi0))), rel=1e-7)
    assert res["reaction"]["roll"]["F"][0] == pytest.approx(m * g * math.sin(phi0) / 3, rel=1e-9)


def test_gallery_loop_the_loop():
    """problems/scenes/loop-the-loop.yaml: N = 0 at cos φ* = −2/3, v² = 2gR/3 there."""
    from tests.topics.scene.common import gallery

    res = gallery("loop-the-loop.yaml")["results"]
    R, g = 0.5, 9.81
    ev = res["events"][0]
    assert ev["what"] == "separates" and ev["joint"] == "track"
    x, v = ev["state"]["x"]["block"], ev["state"]["v"]["block"]
    assert x[1] == pytest.approx(R + 2 * R / 3, abs=1e-8)
    assert v[0] ** 2 + v[1] ** 2 == pytest.approx(2 * g * R / 3, rel=1e-7)
    dt = 0.4 - ev["t"]                                 # then a projectile from the separation state
    assert res["x"]["block"][2][:2] == pytest.approx([x[0] + v[0] * dt, x[1] + v[1] * dt - g * dt * dt / 2], abs=1e-9)


def test_leaves_at_the_end_of_a_curve():
    """A block shot along a quarter-pipe (q_range ends at the top of the quarter circle) leaves it
    there: the event `leaves` at q = π/2, with v² = v0² − 2 g R (energy)."""
    R, v0 = 0.5, 4.0
    text = f"""\
type: scene
surfaces:
  pipe: {{curve: {{x1: "{R}*sin(q)", x2: "{R} - {R}*cos(q)"}}, q_range: [-0.1, "pi/2"]}}
bodies:
  block: {{shape: point, mass: 1, v: [{v0}, 0]}}
joints:
  c: {{contact: [block, pipe], at: 0}}
at: [0, 1]
"""
    rec = solve_one_text(text)
    ev = rec["results"]["events"][0]
    assert ev["what"] == "leaves"
    x, v = ev["state"]["x"]["block"], ev["state"]["v"]["block"]
    assert x[0] == pytest.approx(R, abs=1e-8) and x[1] == pytest.approx(R, abs=1e-8)
    assert v[1] == pytest.approx(math.sqrt(v0 ** 2 - 2 * 9.81 * R), rel=1e-7)


NEEDLE = """\
type: scene
title: a bead on the tip of a needle of the curve
surfaces:
  ground: {curve: {x1: "q", x2: "0.5*exp(-((q - 3.001)/0.0003)**2)"}}
bodies:
  bead: {shape: point, mass: 1, x: [3.001, 0.5]}
joints:
  c: {contact: [bead, ground]}
at: [0]
"""


def test_first_foot_on_the_tip_of_a_needle():
    """Without ``at`` the contact's first foot is the nearest point of the curve, from the roots
    of (r − y)·y′ (then Newton), not from the best of a table of samples: a needle 3e-4 wide
    (between two samples of a 4001-point table over [−10, 10], whose best sample started Newton
    on its flank, where it left the curve: "no nearest point", exit 1) holds the bead at its tip,
    where by hand y = (3.001, 0.5), the tangent is horizontal and N = m g."""
    rec = solve_one_text(NEEDLE)
    r = rec["results"]
    assert r["x"]["bead"][0][:2] == pytest.approx([3.001, 0.5], abs=1e-12)
    assert r["reaction"]["c"]["N"][0] == pytest.approx(9.81, rel=1e-12)


CAN_IN_TRACK = """
type: scene
params: {R: 1, r: 0.1}
surfaces:
  track: {curve: {x1: "R*sin(q)", x2: "-R*cos(q)"}}
bodies:
  can: {shape: cylinder, mass: 2, radius: r}
joints:
  roll: {rolls: [can, track], at: "60*deg"}
"""


def test_a_disk_placed_by_at_on_a_curve_is_held_there_not_a_second_branch():
    """A cylinder rolling inside a full circular track, placed by `at` with its angle left out:
    its centre is where `at` puts it (held, as on a line), its angle the rolling row's reference —
    no warning that the joints "close two ways" (before: angle.can = 0 or 3.10927, the second a
    disk on the far side of the track), and N at the start is m g cos 60° (at rest)."""
    import math

    rec = solve_one_text(CAN_IN_TRACK + "at: [0]\n")
    assert rec["warnings"] == [], rec["warnings"]
    r = rec["results"]
    assert r["x"]["can"][0][:2] == pytest.approx([0.9 * math.sin(math.pi / 3), -0.9 * math.cos(math.pi / 3)],
                                                 rel=1e-12)
    assert r["reaction"]["roll"]["N"][0] == pytest.approx(2 * 9.81 * math.cos(math.pi / 3), rel=1e-12)


#: a particle at the top of a smooth dome (R = 1) launched at 4 m/s > √(gR); the file's other
#: surfaces follow (YAML keys may come in any order: `surfaces` is completed below)
LAUNCH = """
type: scene
params: {R: 1}
bodies:
  P: {shape: point, mass: 1, x: [0, R], v: [4, 0]}
at: [0, 0.3]
surfaces:
  dome: {curve: {x1: "-R*cos(q)", x2: "R*sin(q)"}, q_range: [0, "pi"]}"""


def test_a_point_on_a_dome_by_its_formula_launched_faster_than_sqrt_gr_flies_off():
    """A particle at the top of a smooth dome (R = 1, x: [0, R]: on the curve to 4e-33 m, its own
    formula's rounding) launched at 4 m/s > √(gR) as a `stop`: it flies off at once and lands on
    the floor at t = √(2R/g), x = 4 t.  Before, the 4e-33 m was "on the wrong side" (the gap
    told from 0 against the multipliers' scale, 0 here, not the scene's size)."""
    import math

    rec = solve_one_text(LAUNCH + """
  floor: {through: [-5, 0], direction: [1, 0]}
joints:
  on_dome: {stop: [P, dome], e: 0}
  on_floor: {stop: [P, floor], e: 0}
t_end: 1
find: [{event: impact}]
""")
    f = rec["results"]["find"][0]
    t = math.sqrt(2 / 9.81)
    assert f["t"] == pytest.approx(t, rel=1e-9)
    assert f["x"]["P"][:2] == pytest.approx([4 * t, 0.0], rel=1e-9, abs=1e-9)


def test_a_contact_launched_off_a_dome_points_to_a_stop():
    """The same particle as a `contact` would have to pull at t = 0 (N = m g − m v²/R < 0): refused,
    and since at rest it would push, the message says why (launched faster than the bend lets it
    follow) and what to write: a stop."""
    rec = solve_text(LAUNCH + """
joints:
  on_dome: {contact: [P, dome]}
""")[0]
    err = str(rec.get("error"))
    assert "N = -6.19 N" in err and "launched faster" in err and "stop: [P, dome], e: 0" in err, err
