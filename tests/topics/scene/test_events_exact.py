"""The first event of a phase in closed form, decided exactly (docs/types/scene.md): each watched
quantity's roots by the sign analysis of dyncli.rootfind.all_roots, never by a grid of samples.

A ball (m = 1 kg) on a vertical guide hangs from a spring (k = 100 N/m) released at its natural
length from rest: it oscillates between y = 0 and y = −2 d, d = m g/k = 0.0981 m, with ω = 10 rad/s
(the notes' free vibration, y = −d (1 − cos ω t)).  A floor at y_f = −0.1960038 m, 0.2 mm above
the lowest point, is reached for a few hundredths of each period only: first at
t* = arccos(1 + y_f/d)/ω (mpmath, 30 digits).  With e = 1 the motion is then periodic, of period
P = 2 t* (down to the floor, back up to y = 0): at t the ball is at phase τ = t mod P.  A scan of
64 samples over 40 s (the route's grid before this rule) saw no bounce at all: the ball went
through the floor with exit 0.  Also here: the closed form's stiffness probe, which must not move
the ball onto a spring's anchor.
"""

from __future__ import annotations

import mpmath as mp

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL

G = 9.81

SPRING_FLOOR = """
type: scene
params: {m: 1, k: 100}
surfaces:
  wall: {through: [0, 0], direction: [0, 1]}
  floor: {through: [0, -0.1960038], direction: [1, 0]}
bodies:
  ball: {shape: point, mass: m, x: [0, 0]}
joints:
  guide: {slider: [ball, wall]}
  bounce: {stop: [ball, floor], e: 1}
forces:
  - {spring: [[0, 3], ball], k: k, L: 3}
at: [0, 40]
"""


#: a ball on a vertical guide hanging from a spring anchored one rest length above it
HANGING = """
type: scene
params: {m: 1, k: 100}
surfaces:
  wall: {through: [0, 0], direction: [0, 1]}
bodies:
  ball: {shape: point, mass: m, x: [0, 0]}
joints:
  guide: {slider: [ball, wall]}
forces:
  - {spring: [[0, 1], ball], k: k, L: 1}
"""


#: a block entering a smooth loop of radius R at its bottom with the speed v0
LOOP = """
type: scene
params: {{m: 0.2, R: 0.5}}
surfaces:
  loop: {{curve: {{x1: "R*sin(q)", x2: "R - R*cos(q)"}}}}
bodies:
  block: {{shape: point, mass: m, v: ["{v0}", 0]}}
joints:
  track: {{contact: [block, loop], at: 0}}
"""


def _reference(t):
    with mp.workdps(30):
        d, w, yf = mp.mpf(G) / 100, mp.mpf(10), mp.mpf("-0.1960038")
        ts = mp.acos(1 + yf / d) / w
        P = 2 * ts
        tau = mp.fmod(mp.mpf(t), P)
        u = tau if tau <= ts else P - tau
        sign = 1 if tau <= ts else -1
        return ts, P, -d * (1 - mp.cos(w * u)), -sign * d * w * mp.sin(w * u)


def test_a_floor_reached_for_an_instant_each_period_is_struck_every_period():
    rec = solve_one_text(SPRING_FLOOR)
    assert rec.get("error") is None, rec.get("error")
    assert not rec["warnings"]
    r = rec["results"]
    ts, P, y, v = _reference(40)
    impacts = r["impacts"]
    assert len(impacts) == int(mp.floor((40 - ts) / P)) + 1
    assert all(p["route"] == "closed-form" for p in r["phases"])
    # each impact time is a root located to the double's resolution (the slope there is d ω sin)
    assert abs(impacts[0]["t"] - float(ts)) <= 1e-14
    for k in (1, 10, len(impacts) - 1):
        assert abs(impacts[k]["t"] - float(ts + k * P)) <= 1e-12 * 40
    # the state at t = 40 s after 65 bounces: rounding accumulated over the bounces only
    assert abs(r["x"]["ball"][1][1] - float(y)) <= 1e-11 * 0.2
    assert abs(r["v"]["ball"][1][1] - float(v)) <= 1e-10 * 1.0


def test_a_point_leaving_a_curve_is_not_read_as_impacts_in_the_rounding():
    """At the instant a block leaves a loop its gap is 0 and grows like (t − t*)³: within the first
    microseconds it is below the gap's rounding; the search takes the event as the gap passing
    below minus its rounding, so the flight is one phase (not thousands of impacts in the noise)."""
    rec = solve_one_text(LOOP.format(v0="sqrt(4*9.81*R)") + "at: [0, 0.4]\n")
    assert rec.get("error") is None, rec.get("error")
    r = rec["results"]
    assert [e["what"] for e in r["events"]] == ["separates"]
    assert [p["route"] for p in r["phases"]][-1] == "closed-form"


def test_a_spring_anchored_one_rest_length_above_is_a_closed_form():
    """The closed form's stiffness is probed along the motion: a probe of the scene's size would
    put the ball on the spring's anchor (1 m above, rest length 1 m) and was refused ("the ends of
    the spring coincide"); y = −d (1 − cos ω t), d = m g/k, ω = √(k/m) (the notes' free vibration)."""
    rec = solve_one_text(HANGING + "at: [0, 0.3, 1]\n")
    assert rec.get("error") is None, rec.get("error")
    r = rec["results"]
    assert [p["route"] for p in r["phases"]] == ["closed-form"]
    d = mp.mpf(G) / 100
    for k, t in enumerate((0, mp.mpf("0.3"), 1)):
        assert abs(r["x"]["ball"][k][1] - float(-d * (1 - mp.cos(10 * t)))) <= 1e-14


def test_a_contact_force_that_dips_below_zero_inside_one_ode_step_separates():
    """A block enters a smooth loop (R = 0.5 m) with v0² = 5 g R (1 − 10⁻⁴), a hair below what
    going round needs: N = m (v0² − 2 g R + 3 g R cos φ)/R (16.7, 34.20) is negative only within
    0.018 rad of the top, a few ms, inside one step of the ODE route; the steps' ends both read
    N > 0 and the block was taken round the loop at every rtol.  The screen of each step's
    interpolant sees the dip: the block leaves where cos φ* = (2 g R − v0²)/(3 g R), at
    t* = ∫ R dφ / v (mpmath).  The position there is sensitive to the state by 1/sin φ* (N's
    slope is small at the top): tolerance ODE_GLOBAL · rtol · R / sin φ*."""
    rec = solve_one_text(LOOP.format(v0="sqrt(5*9.81*R*(1 - 1e-4))") + "at: [0, 0.5]\naccuracy: {rtol: 1.0e-6}\n")
    assert rec.get("error") is None, rec.get("error")
    ev = rec["results"]["events"][0]
    assert ev["what"] == "separates"
    with mp.workdps(30):
        R, g = mp.mpf("0.5"), mp.mpf(G)
        v0sq = 5 * g * R * (1 - mp.mpf("1e-4"))
        phi = mp.acos((2 * g * R - v0sq) / (3 * g * R))
        t = mp.quad(lambda p: R / mp.sqrt(v0sq - 2 * g * R * (1 - mp.cos(p))), [0, phi])
        tol = ODE_GLOBAL * 1e-6 * float(R / mp.sin(phi))
        assert abs(ev["t"] - float(t)) <= tol / float(mp.sqrt(v0sq - 2 * g * R * (1 - mp.cos(phi))))
        assert abs(ev["state"]["x"]["block"][0] - float(R * mp.sin(phi))) <= tol
        assert abs(ev["state"]["x"]["block"][1] - float(R - R * mp.cos(phi))) <= tol


def test_find_on_a_closed_form_phase_of_many_periods():
    """A scene's find reads its motion piece by piece; a closed-form phase is one piece however
    many periods it spans, and the search read four points of it: the 7th crossing of a level
    near the lowest point was "not reached" and the least v.ball.1 was t = 0.  Each piece is now
    cut at the exact extremes of the result searched.  y = −d (1 − cos ω t), v = −d ω sin ω t
    (the notes' free vibration): the crossings of y = Y are ±arccos(1 + Y/d)/ω + k 2π/ω, the least
    v first at ω t = π/2 (an extreme's time: to the square root of the rounding at worst)."""
    rec = solve_one_text(HANGING + """at: [0, 20]
find:
  - {when: {x.ball.1: -0.196199}, occurrence: 7}
  - {min: v.ball.1}
""")
    assert rec.get("error") is None, rec.get("error")
    assert not rec["warnings"]
    got = rec["results"]["find"]
    with mp.workdps(30):
        d, w = mp.mpf(G) / 100, mp.mpf(10)
        a = mp.acos(1 + mp.mpf("-0.196199") / d) / w
        P = 2 * mp.pi / w
        crossings = sorted([a + k * P for k in range(10)] + [P - a + k * P for k in range(10)])
        assert abs(got[0]["t"] - float(crossings[6])) <= 1e-12
        assert abs(got[1]["t"] - float(mp.pi / 20)) <= 1e-8
