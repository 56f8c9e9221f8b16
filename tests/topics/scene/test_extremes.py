"""Scenes at their extremes, against references derived by hand here (never from dyncli):

* an Atwood machine with a 1e6 mass ratio, and one whose pulley has negligible inertia;
* a block on an incline with μ_s exactly tan β (must stay at rest) and one part in 1e6 below it
  (must slide);
* a ladder released 1e-6 rad off the vertical (the wall lets go at cos φ = (2/3) cos φ0);
* a compound pendulum released from the horizontal (pin reaction at release and at the bottom);
* random Atwood machines and random slider-cranks (hypothesis).

Tolerances state what the route guarantees (tests/tolerances.py, docs/accuracy.md):

* closed form, statics, kinematics: a few ulp times the condition number of the computation
  (``closed_form(cond)``).  For the Atwood machine the condition number of the solve for the
  multipliers is about the mass ratio, so a small tension is good to ``closed_form(ratio)``
  relative to the largest force of the machine, m1 g;
* ODE: the motion within ODE_GLOBAL × rtol of its scale (the global error of a step-size
  controlled integrator over a short run); a reaction, solved from the state (λ(q, v)), within
  10 × that (the sensitivity of λ to (q, v) relative to its scale is O(1) in these scenes);
* quadrature (energy integral, 34.20): the state at an angle comes from the energy integral
  itself, so it is exact to rounding; the time is a quadrature good to its error bound.
"""

from __future__ import annotations

import math
import signal

import pytest
from hypothesis import HealthCheck, Phase, example, given, settings
from hypothesis import strategies as st

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL, closed_form

G = 9.81
EXACT = ("closed-form", "statics", "kinematics")


def rel(a: float, b: float, scale: float | None = None) -> float:
    s = abs(b) if scale is None else scale
    return abs(a - b) / s


def atwood_text(m1, m2, R, pulley: str, t=(0.0, 0.5, 1.0)) -> str:
    # A and B 10 m below the pulley: in 1 s neither comes up to it (g/2 = 4.9 m at most; an end
    # that reaches its pulley stops the motion, the event ``reaches``)
    return f"""\
type: scene
bodies:
  pulley: {{{pulley}, radius: {R!r}, x: [0, 0], angle: 0}}
  A: {{shape: point, mass: {m1!r}, x: [{-R!r}, -10]}}
  B: {{shape: point, mass: {m2!r}, x: [{R!r}, -10.5]}}
joints:
  axle: {{pin: [pulley, ground]}}
  rope: {{cord: [A, pulley, B]}}
at: {list(t)!r}
"""


def atwood_reference(m1, m2, I, R):
    """Hand closed form (16.7 for A and B, 32.15 for the disk, α = a/R): A's acceleration
    downward a, the two tensions, the axle reaction (upward, on the pulley), computed without
    cancellation: g − a = g (2 m2 + I/R²)/D, g + a = g (2 m1 + I/R²)/D."""
    J = I / R ** 2
    D = m1 + m2 + J
    a = G * (m1 - m2) / D
    T1 = m1 * G * (2 * m2 + J) / D
    T2 = m2 * G * (2 * m1 + J) / D
    return a, T1, T2


# --- Atwood machine, mass ratio 1e6 ---------------------------------------------------------------

def test_atwood_mass_ratio_1e6():
    m1, m2, M, R = 1e6, 1.0, 2.0, 0.1
    I = M * R ** 2 / 2
    rec = solve_one_text(atwood_text(m1, m2, R, f"shape: disk, mass: {M!r}"))
    r = rec["results"]
    assert r["route"] in EXACT, r["route"]
    a, T1, T2 = atwood_reference(m1, m2, I, R)
    # the accelerations: the effective-mass formula, a few ulp (cond ~ 1)
    for k in range(3):
        assert rel(r["a"]["A"][k][1], -a) <= 1e-12, (r["a"]["A"][k], -a)
        assert rel(r["a"]["B"][k][1], a) <= 1e-12, (r["a"]["B"][k], a)
        assert rel(r["alpha"]["pulley"][k][2], a / R) <= 1e-12
    # positions from rest: x2 = x2(0) ∓ a t²/2
    for k, t in enumerate((0.0, 0.5, 1.0)):
        assert rel(r["x"]["A"][k][1], -10 - a * t * t / 2, 1.0) <= 1e-12
        assert rel(r["x"]["B"][k][1], -10.5 + a * t * t / 2, 1.0) <= 1e-12
    # the tensions: T1 ~ m1 g to a few ulp; T2 ~ 2 g is 1e-6 of the machine's force scale,
    # so it is good to closed_form(m1/m2) relative to m1 g (the condition of the multiplier solve)
    scale = m1 * G
    for k in range(3):
        T = r["reaction"]["rope"]["T"][k]
        assert rel(T[0], T1) <= 1e-12, (T, T1)
        assert rel(T[1], T2, scale) <= closed_form(m1 / m2), (T, T2)
        Rax = r["reaction"]["axle"]["R"][k]
        assert rel(Rax[1], M * G + T1 + T2) <= 1e-12, (Rax, M * G + T1 + T2)
        assert abs(Rax[0]) <= 1e-12 * scale


# --- pulley of negligible inertia --------------------------------------------------------------------

def test_atwood_pulley_of_negligible_inertia():
    m1, m2, I, R = 3.0, 2.0, 1e-12, 0.1
    rec = solve_one_text(atwood_text(m1, m2, R, f"mass: 1e-9, I: {I!r}"))
    r = rec["results"]
    a, T1, T2 = atwood_reference(m1, m2, I, R)
    # T1 − T2 = I a / R² = 1.96e-10 N: equal tensions to 1e-9 relative, and each to the closed form
    for k in range(3):
        T = r["reaction"]["rope"]["T"][k]
        assert abs(T[0] - T[1]) <= 1e-9 * T1, T
        assert rel(T[0], T1) <= 1e-12, (T, T1)
        assert rel(T[1], T2) <= 1e-12, (T, T2)
        assert rel(r["a"]["A"][k][1], -a) <= 1e-12


# --- friction exactly at the limit -------------------------------------------------------------------

def incline_text(mu: str) -> str:
    return f"""\
type: scene
params: {{beta: "30*deg"}}
surfaces:
  slope: {{through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}}
bodies:
  A: {{shape: point, mass: 2, x: ["cos(beta)", "sin(beta)"]}}
joints:
  c: {{contact: [A, slope], {mu}}}
at: [0, 0.5, 1]
"""


def test_incline_mu_s_exactly_tan_beta_stays_at_rest():
    """μ_s = tan β: the static test |F| = m g sin β ≤ μ_s m g cos β holds with equality, so the
    block stays at rest (the decision must be exact at the boundary, not by a rounded product),
    with friction F = m g sin β up the slope (+d̂) and N = m g cos β at every time."""
    m, b = 2.0, math.radians(30)
    rec = solve_one_text(incline_text('mu_s: "tan(30*deg)", mu_k: 0.1'))
    r = rec["results"]
    assert not r["events"], r["events"]
    for k in range(3):
        assert r["x"]["A"][k][:2] == pytest.approx([math.cos(b), math.sin(b)], abs=1e-15)
        assert r["v"]["A"][k][:2] == pytest.approx([0, 0], abs=1e-15)
        assert rel(r["reaction"]["c"]["F"][k], m * G * math.sin(b)) <= closed_form(4)
        assert rel(r["reaction"]["c"]["N"][k], m * G * math.cos(b)) <= closed_form(4)


def test_incline_mu_one_part_in_1e6_below_slides():
    """μ = tan β (1 − 1e-6): it slides down with a = g (sin β − μ cos β) = g sin β · 1e-6."""
    m, b = 2.0, math.radians(30)
    rec = solve_one_text(incline_text('mu: "tan(30*deg)*(1 - 1e-6)"'))
    r = rec["results"]
    a = G * math.sin(b) * 1e-6             # = g cos β (tan β − μ), down the slope
    for k, t in enumerate((0.0, 0.5, 1.0)):
        s = -a * t * t / 2                   # along d̂ (up the slope) from the start
        x = [math.cos(b) * (1 + s), math.sin(b) * (1 + s)]
        # the displacement is 1e-6 of the position: 1e-12 absolute resolves it to 1e-6 of itself
        assert r["x"]["A"][k][0] == pytest.approx(x[0], abs=1e-12)
        assert r["x"]["A"][k][1] == pytest.approx(x[1], abs=1e-12)
        assert r["a"]["A"][k][0] == pytest.approx(-a * math.cos(b), rel=1e-6)
        # kinetic friction μ N up the slope
        assert rel(r["reaction"]["c"]["F"][k], m * G * math.cos(b) * math.tan(b) * (1 - 1e-6)) <= 1e-12
    assert r["v"]["A"][2][0] < 0


# --- ladder released 1e-6 rad off the vertical -------------------------------------------------------

def test_ladder_from_near_vertical_separates_at_two_thirds():
    """Smooth wall and floor (sliding-ladder.yaml), φ0 = 1e-6 rad from the vertical.  Energy and
    momentum (29.5, 34.20) give N_wall = (3mg/4) sin φ (3 cos φ − 2 cos φ0), zero at
    cos φ* = (2/3) cos φ0.  The event is located on the state, so cos φ* carries the state's error:
    ODE_GLOBAL × rtol = 1e-8 at rtol 1e-10 on an ODE route; rounding on a quadrature."""
    phi0 = 1e-6
    text = f"""\
type: scene
params: {{m: 10, L: 5, phi0: {phi0!r}}}
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
  wall: {{through: [0, 0], direction: [0, -1]}}
bodies:
  rod: {{shape: rod, mass: m, length: L, angle: "pi/2 + phi0", x: ["L/2*sin(phi0)", "L/2*cos(phi0)"]}}
joints:
  at_floor: {{contact: [rod.end1, floor]}}
  at_wall: {{contact: [rod.end2, wall]}}
at: [0, 5]
t_end: 20
accuracy: {{rtol: 1e-10}}
"""
    rec = solve_one_text(text)
    r = rec["results"]
    ev = r["events"]
    assert len(ev) == 1, ev
    assert ev[0]["joint"] == "at_wall" and ev[0]["what"] == "separates", ev[0]
    psi = ev[0]["state"]["angle"]["rod"]            # rod angle = π/2 + φ
    phi = psi - math.pi / 2
    tol = ODE_GLOBAL * 1e-10
    assert abs(math.cos(phi) - 2 / 3 * math.cos(phi0)) <= tol, (math.cos(phi), 2 / 3 * math.cos(phi0))
    # at separation the floor carries m g / 4 (N_f = mg − (3mg/4)(...) with sin θ* = (2/3) sin θ0)
    # exactly: N_f = mg[1 − (3/4)(cos²θ + 2 sinθ sinθ0 − 2 sin²θ)], θ the angle from the floor
    th0 = math.pi / 2 - phi0
    th = math.asin(2 / 3 * math.sin(th0))
    Nf = 10 * G * (1 - 0.75 * (math.cos(th) ** 2 + 2 * math.sin(th) * math.sin(th0) - 2 * math.sin(th) ** 2))
    assert abs(ev[0]["state"]["reaction"]["at_floor"]["N"] - Nf) <= 10 * tol * 10 * G


# --- compound pendulum from the horizontal -----------------------------------------------------------

def test_compound_pendulum_pin_reactions():
    """A uniform rod (m, L) pinned at end1, released from rest horizontal.  At release
    (32.15 about the pin) α = 3g/(2L), so the centre accelerates down at α L/2 = 3g/4 and the pin
    pushes up with R = m g − m (3g/4) = m g/4, no horizontal part.  At the bottom (energy,
    34.20) ω² = 3g/L, α = 0: R = m g + m ω² L/2 = 5 m g/2 upward."""
    m, L = 2.0, 1.5
    text = f"""\
type: scene
bodies:
  bar: {{shape: rod, mass: {m}, length: {L}, x: [{L / 2}, 0], angle: 0}}
joints:
  pin: {{pin: [bar.end1, [0, 0]]}}
at: [0]
t_end: 2
find: [{{when: {{angle.bar: "-pi/2"}}}}]
"""
    rec = solve_one_text(text)
    r = rec["results"]
    route = r["route"]
    R0 = r["reaction"]["pin"]["R"][0]
    assert rel(R0[1], m * G / 4) <= closed_form(4), R0
    assert abs(R0[0]) <= closed_form(4) * m * G, R0
    f = r["find"][0]
    assert f["reached"], f
    # quarter period of the 90° swing of a compound pendulum, reference not needed here: only the state
    assert rel(f["angle"]["bar"], -math.pi / 2) <= closed_form(4)
    # the state at the bottom: ω² = 3g/L; on a quadrature route exact to rounding, on an ODE
    # route ODE_GLOBAL × rtol (default 1e-10) of its scale, the reaction 10 × that
    state_tol = closed_form(16) if route == "quadrature" else ODE_GLOBAL * 1e-10
    assert rel(abs(f["omega"]["bar"][2]), math.sqrt(3 * G / L)) <= state_tol, (route, f["omega"]["bar"])
    Rb = f["reaction"]["pin"]["R"]
    assert rel(Rb[1], 5 * m * G / 2) <= 10 * state_tol, (route, Rb)
    assert abs(Rb[0]) <= 10 * state_tol * m * G, (route, Rb)


# --- random Atwood machines --------------------------------------------------------------------------

masses = st.floats(1e-3, 1e3)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(m1=masses, m2=masses, M=masses, R=st.floats(0.01, 1.0), ring=st.booleans())
def test_random_atwood_against_closed_form(m1, m2, M, R, ring):
    """a = g (m1 − m2)/(m1 + m2 + I/R²), I = M R²/2 (disk) or M R² (ring); the tensions
    T1 = m1 g (2 m2 + I/R²)/D, T2 = m2 g (2 m1 + I/R²)/D.  A closed form: 1e-11 relative to the
    scale of each quantity (g for the acceleration — it may be ~0 —, m1 g and m2 g for the
    tensions; the multiplier solve has condition ≲ max mass / min mass ≤ 1e6, and 1e-11 ≥
    closed_form(1e6) would not hold, so the tensions are held to their own mass's scale times
    the mass ratio's ulps)."""
    I = M * R ** 2 * (1.0 if ring else 0.5)
    shape = "ring" if ring else "disk"
    rec = solve_one_text(atwood_text(m1, m2, R, f"shape: {shape}, mass: {M!r}"))
    r = rec["results"]
    assert r["route"] in EXACT, r["route"]
    a, T1, T2 = atwood_reference(m1, m2, I, R)
    cond = max(m1, m2, M) / min(m1, m2, M)
    ttol = max(1e-11, closed_form(cond))
    for k, t in enumerate((0.0, 0.5, 1.0)):
        assert rel(r["a"]["A"][k][1], -a, G) <= 1e-11, (r["a"]["A"][k], -a)
        assert rel(r["a"]["B"][k][1], a, G) <= 1e-11, (r["a"]["B"][k], a)
        assert rel(r["x"]["A"][k][1], -10 - a * t * t / 2, G) <= 1e-11
        T = r["reaction"]["rope"]["T"][k]
        assert rel(T[0], T1, max(m1, m2) * G) <= ttol, (T, T1, T2)
        assert rel(T[1], T2, max(m1, m2) * G) <= ttol, (T, T1, T2)


# --- random slider-cranks ----------------------------------------------------------------------------

class _Hung(BaseException):
    """Raised by the alarm: a BaseException so that the engine's own error handling lets it through."""


def solve_within(text: str, seconds: int = 20) -> dict:
    """``solve_one_text`` that fails (instead of hanging the suite) when the solve takes longer
    than ``seconds`` — a kinematics solve of a few times takes well under a second."""
    def _alarm(*_):
        raise _Hung()

    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(seconds)
    try:
        return solve_one_text(text)
    except _Hung:
        raise AssertionError(f"the solve did not finish within {seconds} s") from None
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def slider_crank(r: float, l: float, w: float, th0: float, times: list[float]) -> str:
    """Crank (length r) pinned at the origin, driven at θ = θ0 + ω t; a connecting rod of length
    l, its end pinned to a block sliding on the e1 axis; every position given at t = 0 from the
    triangle (hand geometry), so assembly has nothing to place."""
    bx, by = r * math.cos(th0), r * math.sin(th0)
    cx = slider_x(r, l, th0)
    rod_angle = math.atan2(-by, cx - bx)
    return f"""\
type: scene
g: 0
surfaces:
  track: {{through: [0, 0], direction: [1, 0]}}
bodies:
  crank: {{shape: rod, mass: 1, length: {r!r}, x: [{bx / 2!r}, {by / 2!r}], angle: {th0!r}}}
  rod: {{shape: rod, mass: 1, length: {l!r}, x: [{(bx + cx) / 2!r}, {by / 2!r}], angle: {rod_angle!r}}}
  block: {{shape: point, mass: 1, x: [{cx!r}, 0]}}
joints:
  axle: {{pin: [crank.end1, [0, 0]]}}
  wrist: {{pin: [crank.end2, rod.end1]}}
  gudgeon: {{pin: [rod.end2, block]}}
  guide: {{slider: [block, track]}}
  motor: {{drive: crank.angle, value: "{th0!r} + {w!r}*t"}}
at: {times!r}
"""


def slider_x(r: float, l: float, th: float) -> float:
    """The block's position: x = r cos θ + sqrt(l² − r² sin² θ) (the triangle of crank, rod, axis)."""
    return r * math.cos(th) + math.sqrt(l * l - (r * math.sin(th)) ** 2)


def check_slider_crank(res: dict, r: float, l: float, w: float, th0: float, times: list[float]) -> None:
    assert res["route"] == "kinematics", res["route"]
    assert res["dof"] == 0
    for k, t in enumerate(times):
        th = th0 + w * t
        assert rel(res["x"]["block"][k][0], slider_x(r, l, th), r + l) <= 1e-12, (t, res["x"]["block"][k])
        assert abs(res["x"]["block"][k][1]) <= 1e-12 * (r + l)
        assert rel(res["angle"]["crank"][k], th, abs(th) + 1) <= 1e-12


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow],
          phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(r=st.floats(0.05, 1.0), ratio=st.floats(0.1, 0.9), w=st.floats(0.5, 10.0),
       th0=st.floats(0.0, 2 * math.pi))
@example(r=0.6845889744294165, ratio=0.6845889744294165, w=6.035537161679154, th0=0.0)  # found: > 20 s
def test_random_slider_crank_position(r, ratio, w, th0):
    """Random crank length, r/l in [0.1, 0.9], crank speed and phase; reported every 0.05 s (the
    crank turns at most 0.5 rad between reports).  Kinematics (Newton on the joints to
    convergence): rounding, 1e-12 relative to r + l (the condition of the position problem is
    ≤ l/sqrt(l² − r²) ≤ 1/sqrt(1 − 0.81) ≈ 2.3)."""
    l = r / ratio
    times = [round(0.05 * i, 2) for i in range(27)]
    check_slider_crank(solve_within(slider_crank(r, l, w, th0, times))["results"], r, l, w, th0, times)


def test_slider_crank_large_turn_between_reported_times():
    """The same mechanism reported at times far apart: the crank turns 4.8 rad between the last
    two.  The positions at a time do not depend on which other times are reported, so the
    kinematics route must reach them all the same (found by the random test with sparse times:
    the solve never finished)."""
    r, ratio, w, th0 = 0.08279953864377451, 0.29419197883445414, 8.075340351765878, 2.6032116329654382
    l = r / ratio
    times = [0.0, 0.3, 0.7, 1.3]
    check_slider_crank(solve_within(slider_crank(r, l, w, th0, times))["results"], r, l, w, th0, times)
