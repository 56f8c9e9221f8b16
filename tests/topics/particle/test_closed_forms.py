"""particle against closed forms and against a second, independent integrator."""

from __future__ import annotations

import math

import numpy as np
import pytest

import tests.tolerances as tol

from tests.conftest import solve_one_text


def close(a, b, rtol=1e-8, atol=1e-9):
    np.testing.assert_allclose(np.asarray(a, float), np.asarray(b, float), rtol=rtol, atol=atol)


def energy_ok(R, rtol=1e-10):
    scale = max(max(abs(v) for v in R["T"]), max(abs(v) for v in R["V"]), max(abs(v) for v in R["E"]), 1e-300)
    assert R["energy_residual"] <= 10 * rtol * scale, (R["energy_residual"], scale)


def test_projectile_without_drag():
    times = [0, 0.3, 1.1, 2.0, 2.5]
    rec = solve_one_text(f"""
type: particle
m: 3
g: 9.8
x0: [1, 2, 3]
v0: [4, -5, 12]
forces: [{{kind: gravity}}]
at: {times}
""")
    R = rec["results"]
    for i, t in enumerate(times):
        close(R["x"][i], [1 + 4 * t, 2 - 5 * t, 3 + 12 * t - 4.9 * t * t], rtol=1e-12, atol=1e-12)
        close(R["v"][i], [4, -5, 12 - 9.8 * t], rtol=1e-12, atol=1e-12)
        close(R["a"][i], [0, 0, -9.8])
        assert R["V"][i] == pytest.approx(3 * 9.8 * (3 + 12 * t - 4.9 * t * t), rel=1e-12)
        # H_O = m x × v
        x = np.array([1 + 4 * t, 2 - 5 * t, 3 + 12 * t - 4.9 * t * t])
        v = np.array([4, -5, 12 - 9.8 * t])
        close(R["H_O"][i], 3 * np.cross(x, v), rtol=1e-11, atol=1e-11)
    assert R["W_nc"] == [0.0] * 5
    energy_ok(R)
    assert rec["error_estimate"] < 1e-9


def test_undamped_spring_3d_isotropic():
    # L = 0: F = -k (x - anchor): x(t) = a + (x0 - a) cos wt + v0/w sin wt
    k, m = 40.0, 2.5
    w = math.sqrt(k / m)
    times = [0, 0.1, 0.7, 1.9, 5.0]
    rec = solve_one_text(f"""
type: particle
m: {m}
x0: [1, 0.5, -1]
v0: [0, 2, 1]
forces: [{{kind: spring, anchor: [0.2, 0, 0.1], k: {k}}}]
at: {times}
""")
    R = rec["results"]
    a, x0, v0 = np.array([0.2, 0, 0.1]), np.array([1, 0.5, -1.0]), np.array([0, 2, 1.0])
    E1 = 0.5 * m * v0 @ v0 + 0.5 * k * (x0 - a) @ (x0 - a)
    for i, t in enumerate(times):
        x = a + (x0 - a) * math.cos(w * t) + v0 / w * math.sin(w * t)
        v = -(x0 - a) * w * math.sin(w * t) + v0 * math.cos(w * t)
        close(R["x"][i], x, rtol=1e-9, atol=1e-9)
        close(R["v"][i], v, rtol=1e-9, atol=1e-9)
        assert R["E"][i] == pytest.approx(E1, rel=1e-10)
    energy_ok(R)


def test_undamped_spring_with_free_length_1d():
    # along e1, R = x1 > 0: x1 = L + A cos wt
    rec = solve_one_text("""
type: particle
m: 0.5
x0: [1.3, 0, 0]
forces: [{kind: spring, k: 18, L: 1}]
at: [0, 0.4, 1.0, 3.0]
""")
    R = rec["results"]
    w = 6.0
    for i, t in enumerate([0, 0.4, 1.0, 3.0]):
        close(R["x"][i], [1 + 0.3 * math.cos(w * t), 0, 0], rtol=1e-9, atol=1e-10)
        assert R["V"][i] == pytest.approx(9 * (0.3 * math.cos(w * t)) ** 2, rel=1e-8, abs=1e-12)
    energy_ok(R)


def test_circular_orbit_period():
    # circular speed sqrt(mu/r), period 2 pi sqrt(r³/mu), mu = g R0²
    g, R0, r = 9.81, 6.371e6, 8.0e6
    mu = g * R0 ** 2
    vc = math.sqrt(mu / r)
    P = 2 * math.pi * math.sqrt(r ** 3 / mu)
    rec = solve_one_text(f"""
type: particle
m: 500
x0: [0, {r}, 0]
v0: [0, 0, {vc}]
forces: [{{kind: inverse-square, R0: {R0}}}]
at: [0, {P / 3}, {P / 2}, {P}]
""")
    R = rec["results"]
    for i, f in enumerate([0, 1 / 3, 1 / 2, 1]):
        th = 2 * math.pi * f
        # an ODE route at the default rtol 1e-10: the documented envelope, 100 × rtol
        close(R["x"][i], [0, r * math.cos(th), r * math.sin(th)], rtol=0, atol=tol.ode(1e-10) * r)
        assert np.linalg.norm(R["v"][i]) == pytest.approx(vc, rel=tol.ode(1e-10))
        assert R["V"][i] == pytest.approx(-500 * mu / r, rel=tol.ode(1e-10))
        close(R["H_O"][i], [500 * r * vc, 0, 0], rtol=tol.ode(1e-10))
    energy_ok(R)
    assert not rec["warnings"]


def test_inverse_square_default_g_and_below_surface_warning():
    rec = solve_one_text("""
type: particle
g: 2
m: 1
x0: [1.5, 0, 0]
v0: [0, 0.1, 0]
forces: [{kind: inverse-square, R0: 1.5}]
t_end: 0.5
""")
    R = rec["results"]
    close(R["a"][0], [-2, 0, 0])
    assert any("inside R0" in w for w in rec["warnings"])


MIXED = """
type: particle
m: 1.7
x0: [0.3, -0.2, 0.5]
v0: [1.0, 0.4, -0.3]
forces:
  - {kind: gravity}
  - {kind: uniform, F: [0.5, 0, 0]}
  - {kind: spring, anchor: [0, 0, 1], k: 30, L: 0.4}
  - {kind: damper, c: 0.2}
  - {kind: drag, c: 0.05, power: 2}
  - {kind: drag, c: 0.1, power: 1}
  - {kind: custom, F: ["0.3*sin(2*t)", "-0.2*x1*v3", "0.1*cos(t)*x2"]}
at: [0, 0.5, 1.3, 2.0]
accuracy: {method: METHOD}
"""


def _mixed_rhs(t, y):
    m, g = 1.7, 9.81
    x, v = y[0:3], y[3:6]
    r = x - np.array([0, 0, 1.0])
    R = np.linalg.norm(r)
    s = np.linalg.norm(v)
    Fc = np.array([0, 0, -m * g]) - 30 * (R - 0.4) * r / R
    Fnc = (np.array([0.5, 0, 0]) - 0.2 * v - 0.05 * s * v - 0.1 * v
           + np.array([0.3 * math.sin(2 * t), -0.2 * x[0] * v[2], 0.1 * math.cos(t) * x[1]]))
    return np.concatenate([v, (Fc + Fnc) / m, [Fnc @ v]])


@pytest.fixture(scope="module")
def radau_reference():
    from scipy.integrate import solve_ivp

    y0 = np.array([0.3, -0.2, 0.5, 1.0, 0.4, -0.3, 0.0])
    sol = solve_ivp(_mixed_rhs, (0, 2.0), y0, method="Radau", rtol=1e-13, atol=1e-14,
                    t_eval=[0, 0.5, 1.3, 2.0])
    return sol.y


@pytest.mark.parametrize("method", ["auto", "RK45", "Radau", "LSODA"])
def test_mixed_forces_against_radau_reference(method, radau_reference):
    rec = solve_one_text(MIXED.replace("METHOD", method))
    R = rec["results"]
    want = "DOP853" if method == "auto" else method
    assert rec["method"] == f"ode:{want}"
    tol = 1e-8 if method in ("auto", "Radau") else 1e-6
    for i in range(4):
        close(R["x"][i], radau_reference[0:3, i], rtol=tol, atol=tol)
        close(R["v"][i], radau_reference[3:6, i], rtol=tol, atol=tol)
        assert R["W_nc"][i] == pytest.approx(radau_reference[6, i], rel=tol, abs=tol)
    assert rec["error_estimate"] is not None and rec["error_estimate"] >= 0
    assert R["energy_residual"] < 1e-6


def test_error_estimate_tighter_solve():
    text = MIXED.replace("METHOD", "auto").replace("accuracy: {method: auto}",
                                                   "accuracy: {method: auto, rtol: 1e-6, atol: 1e-8, estimate: true}")
    rec = solve_one_text(text)
    from scipy.integrate import solve_ivp

    y0 = np.array([0.3, -0.2, 0.5, 1.0, 0.4, -0.3, 0.0])
    ref = solve_ivp(_mixed_rhs, (0, 2.0), y0, method="Radau", rtol=1e-13, atol=1e-14, t_eval=[2.0]).y
    true_err = float(np.max(np.abs(np.array(rec["results"]["x"][-1]) - ref[0:3, 0])))
    est = rec["error_estimate"]
    assert true_err <= 10 * est + 1e-12
    assert est <= 100 * true_err + 1e-9


def test_t_end_inferred_and_default_times():
    rec = solve_one_text("""
type: particle
m: 1
v0: [1, 0, 0]
at: [2, 1]
""")
    close(rec["results"]["x"], [[2, 0, 0], [1, 0, 0]])     # requested order kept
    rec = solve_one_text("""
type: particle
m: 1
v0: [1, 0, 0]
t_end: 3
""")
    close(rec["results"]["x"], [[0, 0, 0], [3, 0, 0]])      # default at: [0, t_end]


def test_t_end_zero_reports_initial_state():
    rec = solve_one_text("""
type: particle
m: 2
v0: [1, 0, 0]
forces: [{kind: gravity}]
at: [0]
""")
    R = rec["results"]
    close(R["x"], [[0, 0, 0]])
    close(R["a"], [[0, 0, -9.81]])
    assert R["energy_residual"] == 0
