"""Power and work per force (notes §18-§20) and the cylindrical basis (§21-§22)
of ``particle``: the gallery files work-per-force.yaml and
central-force-cylindrical.yaml against closed forms, an independent sympy
route, the extremes and invalid input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

# an ODE at rtol 1e-10 (the default accuracy is tighter): a few 1e-9 relative
ODE_REL = 1e-8


def close(a, b, rel=ODE_REL, abs_=1e-9):
    np.testing.assert_allclose(np.asarray(a, float), np.asarray(b, float), rtol=rel, atol=abs_)


def recs(name):
    out = solve_path(PROBLEMS / "particle" / name)
    for r in out:
        assert r.get("error") is None, r.get("error")
    return out


# --- the gallery: work-per-force.yaml -----------------------------------------

def test_motor_lift_fig18_3_work_per_force():
    r = recs("work-per-force.yaml")[0]["results"]
    m, g, h, tau = 5.0, 9.81, 2.0, 4.0
    # t = tau/2: x3 = h/2, v3 = 2h/tau; motor power m g v3 (the sin term is 0)
    close(r["power"][1]["motor"], m * g * 1.0)
    close(r["power"][1]["gravity"], -m * g * 1.0)
    close(r["work"][1]["gravity"], -m * g * 1.0)
    close(r["work"][1]["motor"], m * g * 1.0 + 0.5 * m * 1.0 ** 2)
    # t = tau: rest to rest, U_motor = m g h = −U_gravity, total 0 (18.7)
    close(r["work"][2]["motor"], m * g * h, abs_=1e-8)
    close(r["work"][2]["gravity"], -m * g * h, abs_=1e-8)
    assert abs(sum(r["work"][2].values())) < 1e-8
    assert r["work_residual"] < 1e-8
    # the works of the non-potential forces add up to W_nc (20.3)
    close([w["motor"] for w in r["work"]], r["W_nc"])


def test_block_pushed_with_friction_closed_forms():
    r = recs("work-per-force.yaml")[1]["results"]
    m, P, muN = 2.0, 10.0, 0.25 * 19.62
    a = (P - muN) / m
    for i, t in enumerate([0.0, 1.0, 2.0]):
        v, x = a * t, a * t * t / 2
        close(r["power"][i]["push"], P * v, rel=1e-12, abs_=1e-12)
        close(r["power"][i]["friction"], -muN * v, rel=1e-12, abs_=1e-12)
        close(r["work"][i]["push"], P * x, rel=1e-12, abs_=1e-12)
        close(r["work"][i]["friction"], -muN * x, rel=1e-12, abs_=1e-12)
        assert r["work"][i]["gravity"] == 0 and r["work"][i]["normal"] == 0
        if t > 0:
            close(r["force_terms"][i]["friction"], [-muN, 0, 0], rel=1e-12)
        close(r["force_terms"][i]["normal"], [0, 0, 19.62], rel=0)


# --- an independent route: sympy's closed form of linear drag -----------------

def test_linear_drag_work_against_sympy():
    import sympy as sp

    t = sp.symbols("t", positive=True)
    m, c, g, u0, w0 = sp.Integer(2), sp.Rational(1, 2), sp.Rational(981, 100), sp.Integer(12), sp.Integer(9)
    k = c / m
    v1 = u0 * sp.exp(-k * t)                               # m v̇ = −c v − m g e3
    v3 = (w0 + g / k) * sp.exp(-k * t) - g / k
    x3 = sp.integrate(v3, (t, 0, t))
    U_drag = sp.integrate(-c * (v1 ** 2 + v3 ** 2), (t, 0, t))
    rec = solve_one_text("""
type: particle
m: 2
v0: [12, 0, 9]
forces: [{kind: gravity}, {kind: drag, c: 0.5, power: 1}]
at: [0, 0.7, 1.5, 3]
accuracy: {rtol: 1e-11, atol: 1e-12}
""")
    r = rec["results"]
    for i, tv in enumerate([0, 0.7, 1.5, 3]):
        ref_U = float(U_drag.subs(t, tv))
        ref_P = float((-c * (v1 ** 2 + v3 ** 2)).subs(t, tv))
        close(r["work"][i]["drag"], ref_U, rel=1e-9, abs_=1e-9)
        close(r["power"][i]["drag"], ref_P, rel=1e-9, abs_=1e-9)
        close(r["work"][i]["gravity"], float(-m * g * x3.subs(t, tv)), rel=1e-9, abs_=1e-9)


def test_sum_of_powers_is_T_dot():
    """(18.5): Σ P_i = m a·v at every time, for a mix of forces."""
    rec = solve_one_text("""
type: particle
m: 1.5
x0: [1, 0.5, 2]
v0: [0.3, -1, 2]
forces:
  - {kind: gravity}
  - {kind: spring, anchor: [0, 0, 1], k: 7, L: 0.4}
  - {kind: drag, c: 0.2}
  - {kind: custom, F: ["sin(t)", "x1*v3", 0]}
at: [0, 0.5, 1.3, 2]
""")
    r = rec["results"]
    for i in range(4):
        a, v = np.array(r["a"][i]), np.array(r["v"][i])
        close(sum(r["power"][i].values()), 1.5 * a @ v, rel=1e-12, abs_=1e-11)
        close(np.sum([r["force_terms"][i][k] for k in r["force_terms"][i]], axis=0), 1.5 * a, rel=1e-12, abs_=1e-11)
    assert r["work_residual"] < 1e-7


# --- extremes -----------------------------------------------------------------

def test_no_forces_and_repeated_kinds():
    r = solve_one_text("type: particle\nm: 1\nv0: [1, 0, 0]\nt_end: 1\n")["results"]
    assert r["power"] == [{}, {}] and r["work"] == [{}, {}] and r["work_residual"] == 0
    r = solve_one_text("type: particle\nm: 1\nt_end: 1\nforces: [{kind: gravity}, {kind: gravity}]\n")["results"]
    assert set(r["work"][1]) == {"gravity", "gravity#2"}
    # two weights: a = −2g, x3(1) = −g, each does m g · g
    close(r["work"][1]["gravity"], 9.81 * 9.81, rel=1e-12)
    close(r["work"][1]["gravity#2"], 9.81 * 9.81, rel=1e-12)


def test_stuck_block_static_friction_is_the_reaction():
    """|other forces| = 3 N < μN = 4 N: the block never moves; the friction
    entry is the static reaction −F_other, power and work 0."""
    r = solve_one_text("""
type: particle
m: 1
forces: [{kind: uniform, F: [3, 0, 0]}, {kind: friction, mu: 0.4, N: 10}]
at: [0, 1]
""")["results"]
    for i in range(2):
        assert r["force_terms"][i]["friction"] == [-3.0, 0.0, 0.0]
        assert r["power"][i]["friction"] == 0 and r["work"][i]["friction"] == 0


def test_slipping_from_rest_friction_opposes_the_net_force():
    r = solve_one_text("""
type: particle
m: 1
forces: [{kind: uniform, F: [0, 5, 0]}, {kind: friction, mu: 0.2, N: 10}]
at: [0, 1]
""")["results"]
    assert r["force_terms"][0]["friction"] == [0.0, -2.0, 0.0]
    close(r["work"][1]["friction"], -2.0 * 1.5, rel=1e-12)   # a = 3, x = 1.5


# --- the cylindrical basis: central-force-cylindrical.yaml ----------------------

def test_central_force_cylindrical_gallery():
    r = recs("central-force-cylindrical.yaml")[0]["results"]
    assert r["r2_theta_dot"] == pytest.approx([3.0] * 4, rel=1e-10)
    assert r["x3_dot"] == pytest.approx([0.5] * 4, rel=1e-12)
    assert r["drift_r2_theta_dot"] < 1e-9 and r["drift_x3_dot"] < 1e-12
    assert r["drift_H_O"] > 1          # H_O is not conserved (22.9)
    i = 2                              # t = pi/4
    close(r["r"][i], 1.5, rel=1e-10)
    close(r["theta"][i], math.pi / 2, abs_=1e-10)
    close(r["x_cyl"][i], [1.5, 0, math.pi / 8], abs_=1e-10)
    close(r["v_cyl"][i], [0, 2, 0.5], abs_=1e-10)
    close(r["a_cyl"][i], [-6, 0, 0], abs_=1e-9)
    close(r["F_cyl"][i], [-12, 0, 0], abs_=1e-9)
    close(r["H_O_cyl"][i], [-math.pi / 2, -1.5, 6], abs_=1e-9)
    close(r["work"][i]["radial"], -5.0, abs_=1e-9)
    close(r["theta"][3], math.pi, abs_=1e-10)       # continuous, not wrapped


def test_cylindrical_components_against_sympy_22_6():
    """A second route: r(t), θ(t) of the closed-form motion differentiated by
    sympy and put into (22.6b,d) and the corrected (22.10b)."""
    import sympy as sp

    t = sp.symbols("t")
    m, w = 2, 2
    x1, x2, x3 = sp.cos(w * t), sp.Rational(3, 2) * sp.sin(w * t), t / 2
    r, th = sp.sqrt(x1 ** 2 + x2 ** 2), sp.atan2(x2, x1)
    rd, thd = sp.diff(r, t), sp.diff(th, t)
    v = [rd, r * thd, sp.diff(x3, t)]
    a = [sp.diff(r, t, 2) - r * thd ** 2, 2 * rd * thd + r * sp.diff(th, t, 2), sp.diff(x3, t, 2)]
    H = [-m * r * thd * x3, m * (x3 * rd - r * sp.diff(x3, t)), m * r ** 2 * thd]
    res = recs("central-force-cylindrical.yaml")[0]["results"]
    for i, tv in enumerate([0, math.pi / 8, math.pi / 4]):
        sub = {t: tv}
        close(res["v_cyl"][i], [float(e.subs(sub)) for e in v], rel=1e-9, abs_=1e-10)
        close(res["a_cyl"][i], [float(e.subs(sub)) for e in a], rel=1e-9, abs_=1e-9)
        close(res["H_O_cyl"][i], [float(e.subs(sub)) for e in H], rel=1e-9, abs_=1e-9)


def test_inverse_square_orbit_conserves_H_O():
    text = (PROBLEMS / "particle" / "satellite-inverse-square.yaml").read_text().replace("at:", "basis: cylindrical\nat:")
    r = solve_one_text(text)["results"]
    H0 = np.linalg.norm(r["H_O"][0])
    assert r["drift_H_O"] < 1e-9 * H0          # rtol 1e-10 (default): ~1e-10 relative
    assert r["drift_r2_theta_dot"] < 1e-9 * 4.9e10
    assert r["drift_x3_dot"] > 1e3             # an inclined orbit: F3 ≠ 0
    assert r["theta"][-1] == pytest.approx(2 * math.pi, abs=1e-8)


def test_cylindrical_on_the_axis_and_through_it():
    rec = solve_one_text("type: particle\nm: 1\nv0: [0, 0, 1]\nbasis: cylindrical\nt_end: 1\n")
    r = rec["results"]
    assert r["r"] == [0.0, 0.0] and r["theta"] == [0.0, 0.0]
    assert r["v_cyl"][1] == [0.0, 0.0, 1.0] and r["drift_H_O"] == 0
    assert any("e3 axis" in w for w in rec["warnings"])
    r = solve_one_text("type: particle\nm: 1\nx0: [1, 0, 0]\nv0: [-1, 0, 0]\nbasis: cylindrical\nat: [0, 1, 2]\n")["results"]
    assert r["r2_theta_dot"] == [0.0, 0.0, 0.0]
    close(r["x_cyl"][2], [1, 0, 0], abs_=1e-12)     # on the far side: θ = π, r = 1


def test_default_basis_adds_no_cylindrical_results():
    r = solve_one_text("type: particle\nm: 1\nt_end: 1\n")["results"]
    assert "x_cyl" not in r and "r2_theta_dot" not in r


@pytest.mark.parametrize("extra, message", [
    ("basis: spherical", "basis"),
    ("basis: 3", "basis"),
])
def test_invalid_basis(extra, message):
    msg = error_of("type: particle\nm: 1\nt_end: 1\n" + extra + "\n")
    assert msg.startswith("bad.yaml:4:"), msg
    assert message in msg and "cylindrical" in msg, msg
