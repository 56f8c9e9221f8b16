"""The quadrature runner (dyncli/quadrature.py): accuracy against closed-form integrals, its
error estimate against the true error, and the work budget (max_steps) shared with the ODE
routes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dyncli.ode import OverBudget
from dyncli.quadrature import gauss_kronrod
from tests.conftest import solve_text


@pytest.mark.parametrize("f,a,b,exact", [
    (np.exp, 0.0, 1.0, math.e - 1.0),
    (lambda t: 1.0 / (1.0 + t * t), 0.0, 10.0, math.atan(10.0)),
    (lambda t: np.abs(np.sin(t)), 0.0, 10.0, 7.0 + math.cos(10.0)),   # kinks at kπ
    (np.sqrt, 0.0, 1.0, 2.0 / 3.0),                                         # endpoint singularity of f'
])
def test_accuracy_and_honest_estimate(f, a, b, exact):
    I, err, ok = gauss_kronrod(f, a, b, 1e-12, 1e-14)
    assert ok
    true = abs(I - exact)
    # converged to rtol (plus rounding of the sum: 64 ε of the integral), and the estimate covers the error
    assert true <= 1e-12 * abs(exact) + 64 * np.finfo(float).eps * abs(exact)
    assert err >= 0.5 * true or true <= 4 * np.finfo(float).eps * abs(exact)


def test_budget_refuses():
    with pytest.raises(OverBudget) as exc:
        gauss_kronrod(lambda t: np.abs(np.sin(50 * t)), 0.0, 100.0, 1e-13, 1e-15, max_steps=20)
    assert "budget of 20" in str(exc.value) and "accuracy.max_steps" in str(exc.value)


def test_distance_respects_max_steps():
    import mpmath as mp

    text = ("type: kinematics\ncoordinates: cartesian\nposition: {x1: 't', x2: 'sin(20*t)', x3: 0}\n"
            "at: [0]\ndistance: [0, 5]\naccuracy: {max_steps: 3}\n")
    rec = solve_text(text)[0]
    assert rec["exit_code"] == 1 and "accuracy.max_steps" in rec["error"]
    rec = solve_text(text.replace("max_steps: 3", "max_steps: 5000"))[0]
    mp.mp.dps = 30
    ref = mp.quad(lambda t: mp.sqrt(1 + 400 * mp.cos(20 * t) ** 2), mp.linspace(0, 5, 101))
    assert rec.get("error") is None
    assert abs(rec["results"]["distance"] - float(ref)) <= 1e-10 * float(ref)
    assert rec["error_estimate"] >= 0.5 * abs(rec["results"]["distance"] - float(ref)) / float(ref)
