"""A cord over a fixed pulley whose end segment turns with its end: a rod raised by a cable over
a pulley, a block on a table tied over a pulley above its level, a collar pulled up a rod
(docs/types/scene.md, cords).  Only a hanging point mass is guided along its segment (the
textbook's Atwood machine); any other end — a point of a rigid body, or a mass that another
joint holds — drags its segment round with it, the cord's length ℓ + ρ α kept exactly (ℓ the
straight part from the tangent point, α the arc the tangent point runs over).

Reference (a second formulation, written here only): one coordinate s, the end point P(s) on the
path the other joints allow, the cord's part from the pulley f(s) = √(|P − C|² − ρ²) + ρ α_T(s)
with α_T the tangent point's angle about C (its branch read off the drawing: over the top), the
hanging mass lowered by f(s) − f(s0); Lagrange's equation of T(s, ṡ) − V(s) differentiated by
sympy and integrated by scipy's DOP853 at rtol 1e-12 — never the engine.  The engine runs at its
default rtol 1e-10: agreement to ODE_GLOBAL × 1e-10 of each quantity's scale.
"""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL
from tests.topics.scene.common import TABLE_PULLEY
from tests.topics.scene.test_start import near

sp = pytest.importorskip("sympy")

G = 9.81
TOL = ODE_GLOBAL * 1e-10


#: a uniform rod (2 kg, 1 m) hinged at the origin at 30°, its end tied by a cable over a pulley
#: (the third %s) to a 3 kg weight hanging on the far side; the first %s more bodies, the second more joints
ROD_CABLE = """
type: scene
bodies:
  rod: {shape: rod, mass: 2, length: 1, angle: "30*deg", x: ["0.5*cos(30*deg)", "0.5*sin(30*deg)"]}
  W: {shape: point, mass: 3, x: [2.1, 0.5]}
%s
joints:
  hinge: {pin: [rod.end1, ground]}
%s
  rope: {cord: [rod.end2, %s, W]}
"""


def lagrange(s, P, C, rho, over, body_T, body_V, mW, s0, times, spin=0):
    """(s, ṡ, y_W − y_W0, the tension) at ``times`` from rest at s0: P (sympy pair in s), the pulley
    (C, ρ), ``over`` = ±1 the side the cord leaves the pulley toward P (+1: the tangent point at
    the angle of P − C less arccos(ρ/|P − C|)), body_T = its kinetic coefficient (T = ½ body_T ṡ²),
    body_V its potential; the counterweight mW hangs from the pulley's other side; ``spin`` the
    pulley's Ī/ρ² when it is a disk on a fixed axle (the cord does not slip on it: it turns at
    the counterweight's speed over ρ)."""
    from scipy.integrate import solve_ivp

    dx, dy = P[0] - C[0], P[1] - C[1]
    d = sp.sqrt(dx ** 2 + dy ** 2)
    f = sp.sqrt(d ** 2 - rho ** 2) + rho * (sp.atan2(dy, dx) - over * sp.acos(rho / d)) * over
    y = f - f.subs(s, s0)                           # the counterweight falls as the cord's part shortens
    yp, ypp = sp.diff(y, s), sp.diff(y, s, 2)
    a_T = body_T + (mW + spin) * yp ** 2
    sd = sp.Symbol("sd")
    acc = -(sp.diff(body_V + mW * G * y, s) + (sp.diff(body_T, s) / 2 + (mW + spin) * yp * ypp) * sd ** 2) / a_T
    fa = sp.lambdify((s, sd), acc, "math")
    fy, fyp, fypp = (sp.lambdify(s, e, "math") for e in (y, yp, ypp))
    sol = solve_ivp(lambda t, z: [z[1], fa(z[0], z[1])], (0, max(times)), [s0, 0.0], method="DOP853",
                    rtol=1e-12, atol=1e-14, dense_output=True)
    out = []
    for t in times:
        sv, sdv = sol.sol(t)
        sdd = fa(sv, sdv)
        ydd = fypp(sv) * sdv ** 2 + fyp(sv) * sdd
        out.append((sv, sdv, fy(sv), mW * (G + ydd)))
    return out


def test_a_rod_raised_by_a_cable_over_a_pulley():
    """A uniform rod (2 kg, 1 m) hinged at the origin, at 30°, its end tied by a cable over a
    pulley (centre (2, 1.5), radius 0.1) to a 3 kg weight hanging on the far side: the cable's
    segment to the rod turns as the rod does.  Before, it kept its direction of t = 0 (0.49143
    rad at 0.3 s against 0.49638 here, without a warning)."""
    rec = solve_one_text(ROD_CABLE % ("", "", "{pulley: [2, 1.5], radius: 0.1}") + "at: [0, 0.3, 0.6]\n")
    assert rec.get("error") is None and rec["warnings"] == [], (rec.get("error"), rec["warnings"])
    r = rec["results"]
    th = sp.Symbol("th")
    ref = lagrange(th, (sp.cos(th), sp.sin(th)), (2, sp.Rational(3, 2)), sp.Rational(1, 10), 1,
                   sp.Rational(2, 3), 2 * G * sp.sin(th) / 2, 3, math.pi / 6, [0, 0.3, 0.6])
    for k, (sv, sdv, yw, T) in enumerate(ref):
        near(r["angle"]["rod"][k], sv, 1, f"θ at t[{k}]", TOL)
        near(r["omega"]["rod"][k][2], sdv, 1, f"ω at t[{k}]", TOL)
        near(r["x"]["W"][k][1], 0.5 + yw, 1, f"the weight's height at t[{k}]", TOL)
        near(r["reaction"]["rope"]["T"][k][0], T, 30, f"the tension at t[{k}]", TOL)


def test_a_rod_raised_by_a_cable_over_a_massive_pulley_on_a_fixed_axle():
    """The same rod and weight over a disk pulley (1 kg, radius 0.1) pinned on a fixed axle: the
    segment to the rod turns with it, the cord does not slip on the disk (its length from the
    tangent point to the disk's material point less the disk's turn), so the weight rises R φ and
    the disk's Ī/R² adds to the weight's inertia; the two tensions differ by Ī φ̈/R.  Before, this
    segment kept its direction of t = 0 without a warning."""
    rec = solve_one_text(ROD_CABLE % ("  P: {shape: disk, mass: 1, radius: 0.1, x: [2, 1.5], angle: 0}",
                                      "  axle: {pin: [P, ground]}", "P") + "at: [0, 0.3, 0.6]\n")
    assert rec.get("error") is None and rec["warnings"] == [], (rec.get("error"), rec["warnings"])
    r = rec["results"]
    th = sp.Symbol("th")
    ref = lagrange(th, (sp.cos(th), sp.sin(th)), (2, sp.Rational(3, 2)), sp.Rational(1, 10), 1,
                   sp.Rational(2, 3), 2 * G * sp.sin(th) / 2, 3, math.pi / 6, [0, 0.3, 0.6], spin=sp.Rational(1, 2))
    for k, (sv, _sdv, yw, T) in enumerate(ref):
        near(r["angle"]["rod"][k], sv, 1, f"θ at t[{k}]", TOL)
        near(r["x"]["W"][k][1], 0.5 + yw, 1, f"the weight's height at t[{k}]", TOL)
        near(r["angle"]["P"][k], yw / 0.1, 1, f"the disk's turn at t[{k}]", TOL)
        near(r["reaction"]["rope"]["T"][k][1], T, 30, f"the weight's tension at t[{k}]", TOL)
        phidd = r["alpha"]["P"][k][2]
        near(abs(r["reaction"]["rope"]["T"][k][0] - T), 0.005 * abs(phidd) / 0.1, 30, f"the disk's torque at t[{k}]",
             TOL)


def test_a_block_on_a_table_tied_over_a_pulley_above_its_level():
    """A (2 kg) on a smooth table at x = −2, tied over a pulley of radius 0.1 at (0, 0.1) to B (1 kg)
    hanging 0.1 to its right: the segment to A steepens as A nears the pulley (5.72° at the start),
    the cord's pull on A grows a vertical part and the table's N drops."""
    rec = solve_one_text(TABLE_PULLEY % ("-2", "0.1", "[0, 0.5, 1]"))
    assert rec.get("error") is None and rec["warnings"] == [], (rec.get("error"), rec["warnings"])
    r = rec["results"]
    x = sp.Symbol("x")
    ref = lagrange(x, (x, sp.Integer(0)), (0, sp.Rational(1, 10)), sp.Rational(1, 10), 1, sp.Integer(2),
                   sp.Integer(0), 1, -2.0, [0, 0.5, 1])
    for k, (sv, sdv, yb, T) in enumerate(ref):
        near(r["x"]["A"][k][0], sv, 2, f"x_A at t[{k}]", TOL)
        near(r["v"]["A"][k][0], sdv, 2, f"v_A at t[{k}]", TOL)
        near(r["x"]["B"][k][1], -1 + yb, 2, f"y_B at t[{k}]", TOL)
        near(r["reaction"]["rope"]["T"][k][0], T, G, f"the tension at t[{k}]", TOL)
        # the table: N = m_A g − T sin φ, φ the segment's angle above A's path (tangent to the pulley)
        d = math.hypot(sv, 0.1)
        phi = math.atan2(0.1, -sv) + math.asin(0.1 / d)
        near(r["reaction"]["on"]["N"][k], 2 * G - T * math.sin(phi), G, f"N at t[{k}]", TOL)
    assert r["route"] == "ode"


def test_a_segment_pulled_straight_at_its_pulley_keeps_the_closed_form():
    """The block's pulley at its own level: the segment runs along the block's path, so it keeps
    its direction as it shortens (affine along the motion) and the closed form stays:
    a = m_B g/(m_A + m_B)."""
    rec = solve_one_text(TABLE_PULLEY % ("-2", "-0.1", "[0, 1]"))
    r = rec["results"]
    assert r["route"] == "closed-form", r["route"]
    near(r["a"]["A"][1][0], G / 3, G, "a", 1e-13)


def test_the_end_reaching_its_pulley_stops_the_solve_with_the_reason():
    from tests.conftest import solve_text

    (rec,) = solve_text("""
type: scene
surfaces:
  table: {through: [-5, 0], direction: [1, 0]}
bodies:
  A: {shape: point, mass: 2, x: [-0.5, 0]}
  B: {shape: point, mass: 5, x: [0.1, -1]}
joints:
  on: {contact: [A, table]}
  rope: {cord: [A, {pulley: [0, 0.3], radius: 0.1}, B]}
t_end: 3
at: [0, 3]
""")
    assert "a cord's end reached its pulley at [0, 0.3]" in (rec.get("error") or ""), rec.get("error")


def test_the_collar_pulled_up_a_rod_gallery_file():
    """problems/scenes/collar-pulled-up-rod.yaml against its energy integral (mpmath, 30 digits):
    ½ (m + M ((H − y)/ℓ)²) ẏ² = g (M (ℓ0 − ℓ) − m y): the time to 0.6 m and the top by quadrature
    of dt = dy/ẏ, the speed there, the top where ẏ = 0, the fastest point where d(ẏ²)/dy = 0."""
    import mpmath as mp

    from tests.topics.scene.common import gallery

    r = gallery("collar-pulled-up-rod.yaml")["results"]
    with mp.workdps(30):
        g, m, M, b, H = mp.mpf("9.81"), 2, 3, mp.mpf("0.8"), mp.mpf("1.2")

        def ell(y):
            return mp.sqrt(b ** 2 + (H - y) ** 2)

        def v2(y):
            return 2 * g * (M * (ell(0) - ell(y)) - m * y) / (m + M * ((H - y) / ell(y)) ** 2)
        y1 = mp.mpf("0.6")
        t1 = mp.re(mp.quad(lambda y: 1 / mp.sqrt(v2(y)), [0, y1 / 2, y1]))
        top = mp.findroot(lambda y: M * (ell(0) - ell(y)) - m * y, 0.9)
        t_top = mp.re(mp.quad(lambda y: 1 / mp.sqrt(v2(y)), [0, top / 2, top]))
        fast = mp.findroot(lambda y: mp.diff(v2, y), 0.5)
    f0, f1, f2 = r["find"]
    near(f0["t"], t1, 1, "the time to 0.6 m", TOL)
    near(f0["v"]["collar"][1], mp.sqrt(v2(y1)), 1, "the speed at 0.6 m", TOL)
    near(f1["x"]["collar"][1], top, 1, "the top", TOL)
    near(f1["t"], t_top, 1, "the time to the top", TOL)
    near(f2["x"]["collar"][1], fast, 1, "where it is fastest", TOL)
    near(f2["v"]["collar"][1], mp.sqrt(v2(fast)), 1, "its top speed", TOL)


def test_a_segment_from_a_moving_disk_to_a_turning_point_is_told():
    """A moving pulley (a disk hanging in the cord's loop) is followed with its segments
    parallel; the segment from it to the rod's end keeps its direction of t = 0 — exact only while
    the end moves along it — and a warning says so; over a light fixed pulley the segment turns
    and nothing is said."""
    disk = solve_one_text("""
type: scene
bodies:
  rod: {shape: rod, mass: 2, length: 1, angle: "30*deg", x: ["0.5*cos(30*deg)", "0.5*sin(30*deg)"]}
  P: {shape: disk, mass: 1, radius: 0.1, x: ["cos(30*deg) + 0.1", -1], angle: 0}
joints:
  hinge: {pin: [rod.end1, ground]}
  rope: {cord: [rod.end2, P, ["cos(30*deg) + 0.2", 1]]}
at: [0, 0.3]
""")
    assert any("keeps its segment to rod.end2 at its direction of t = 0" in w for w in disk["warnings"]), disk["warnings"]
    text = ROD_CABLE + "at: [0, 0.3]\n"
    light = solve_one_text(text % ("", "", "{pulley: [2, 1.5], radius: 0.1}"))
    assert light["warnings"] == [], light["warnings"]
    # a rod hung from a string (no pulley): the string turns with its end by itself
    hung = solve_one_text("""
type: scene
bodies:
  rod: {shape: rod, mass: 2, length: 1, angle: "-60*deg", x: ["0.3 + 0.5*cos(60*deg)", "-1 - 0.5*sin(60*deg)"]}
joints:
  s: {cord: [[0, 0], rod.end1]}
at: [0, 0.3]
""")
    assert hung["warnings"] == [], hung["warnings"]
