"""Coulomb friction (19.27): stick/slip at v = 0 without chattering."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import solve_one_text


def close(a, b, rtol=1e-8, atol=1e-9):
    np.testing.assert_allclose(np.asarray(a, float), np.asarray(b, float), rtol=rtol, atol=atol)


def test_sticks_from_the_start():
    rec = solve_one_text("""
type: particle
m: 1
x0: [0.51, 0, 0]
forces:
  - {kind: spring, k: 100, L: 0.5}      # 1 N
  - {kind: friction, mu: 0.2, N: 9.81}  # 1.962 N
at: [0, 1, 2]
""")
    R = rec["results"]
    close(R["x"], [[0.51, 0, 0]] * 3)
    close(R["v"], [[0, 0, 0]] * 3)
    close(R["a"], [[0, 0, 0]] * 3)
    assert R["t_rest"] == 0
    assert R["energy_residual"] == 0


def test_slips_from_rest_then_slides():
    # uniform 5 N > mu N = 2 N: a = 3 m/s²
    rec = solve_one_text("""
type: particle
m: 1
forces:
  - {kind: uniform, F: [5, 0, 0]}
  - {kind: friction, mu: 0.5, N: 4}
at: [0, 1, 2]
""")
    R = rec["results"]
    for i, t in enumerate([0, 1, 2]):
        close(R["x"][i], [1.5 * t * t, 0, 0])
        close(R["v"][i], [3 * t, 0, 0])
        close(R["a"][i], [3, 0, 0])
        # W_nc = work of uniform + friction = (5 - 2) x
        assert R["W_nc"][i] == pytest.approx(3 * 1.5 * t * t, abs=1e-9)
    assert R["t_rest"] is None


def test_stops_and_slides_back():
    # moving +e1 at 2 m/s against a 5 N pull, mu N = 2 N:
    # a = -7 until t1 = 2/7, then a = -3 (friction now opposes the return)
    t1 = 2 / 7
    times = [0, 0.2, t1, 0.5, 1.0]
    rec = solve_one_text(f"""
type: particle
m: 1
v0: [2, 0, 0]
forces:
  - {{kind: uniform, F: [-5, 0, 0]}}
  - {{kind: friction, mu: 1, N: 2}}
at: {times}
""")
    R = rec["results"]
    x1 = 2 * t1 - 3.5 * t1 * t1
    for i, t in enumerate(times):
        if t <= t1:
            x, v = 2 * t - 3.5 * t * t, 2 - 7 * t
        else:
            x, v = x1 - 1.5 * (t - t1) ** 2, -3 * (t - t1)
        close(R["x"][i], [x, 0, 0], atol=1e-9)
        close(R["v"][i], [v, 0, 0], atol=1e-9)
    assert any("slips on" in w for w in rec["warnings"])


def test_time_dependent_force_breaks_free():
    # F = 4 t e1 against mu N = 2: stuck until t = 0.5, then v = 2 (t - 0.5)², x = (2/3)(t - 0.5)³
    rec = solve_one_text("""
type: particle
m: 1
forces:
  - {kind: custom, F: ["4*t", "0", "0"]}
  - {kind: friction, mu: 1, N: 2}
at: [0, 0.25, 0.5, 1.0, 1.5]
""")
    R = rec["results"]
    for i, t in enumerate([0, 0.25, 0.5, 1.0, 1.5]):
        s = max(t - 0.5, 0)
        close(R["x"][i], [2 / 3 * s ** 3, 0, 0], atol=1e-9)
        close(R["v"][i], [2 * s * s, 0, 0], atol=1e-9)
    assert any("breaks free at t = 0.5" in w for w in rec["warnings"])
    assert R["t_rest"] is None


def test_planar_motion_on_a_spring_stops_without_chattering():
    rec = solve_one_text("""
type: particle
m: 1
x0: [0.5, 0, 0]
v0: [0, 0.4, 0]
forces:
  - {kind: spring, k: 10}
  - {kind: friction, mu: 0.05, N: 9.81}
at: [0, 2, 6, 10]
""")
    R = rec["results"]
    t_rest = R["t_rest"]
    assert t_rest is not None and 2 < t_rest < 6
    x = np.array(R["x"][-1])
    # static condition at the final rest point
    assert 10 * np.linalg.norm(x) <= 0.05 * 9.81 * (1 + 1e-9)
    close(R["x"][2], R["x"][3])
    # E never increases: friction only dissipates
    assert all(b <= a + 1e-9 for a, b in zip(R["E"], R["E"][1:]))
    assert R["energy_residual"] < 1e-8


def test_marginal_static_condition_sticks():
    # spring force equal to mu N (up to rounding): the block stays put
    rec = solve_one_text("""
type: particle
m: 1
x0: [2.7561575312187742, 0, 0]
forces:
  - {kind: spring, k: 1, L: 2}
  - {kind: friction, mu: 1, N: 0.7561575312187742}
at: [1, 5]
""")
    R = rec["results"]
    assert R["t_rest"] == 0
    np.testing.assert_allclose(R["x"][-1], [2.7561575312187742, 0, 0])
