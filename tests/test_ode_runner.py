"""The numerical runner's one policy (dyncli/ode.py, docs/accuracy.md): the check-solve
divisor and fallback, the relative measure of error_estimate, the step budget on every
ODE route, and dense output through scipy's public API only."""

from __future__ import annotations

import math
import pathlib

import numpy as np
import pytest

from dyncli import ode
from dyncli.errors import NumericalError
from tests.conftest import solve_one_text, solve_text

ROOT = pathlib.Path(__file__).resolve().parents[1]


class _Res:
    def __init__(self):
        self.error_estimate = 0.0
        self.warnings = []

    def warn(self, msg):
        self.warnings.append(msg)


def test_check_solve_runs_at_the_one_divisor():
    seen = []
    res = _Res()
    out = ode.check_solve(res, lambda r, a: seen.append((r, a)) or "run", 1e-6, 1e-9)
    assert out == ("run", "tighter") and res.warnings == []
    assert seen == [(1e-6 / ode.CHECK_DIV, 1e-9 / ode.CHECK_DIV)]


def test_check_solve_over_budget_falls_back_to_the_one_looser_run():
    seen = []

    def run(r, a):
        seen.append((r, a))
        if len(seen) == 1:
            raise ode.OverBudget(1.0, 2e6, 1000, 0.5)
        return "looser run"

    res = _Res()
    assert ode.check_solve(res, run, 1e-6, 1e-9) == ("looser run", "looser")
    assert seen[1] == pytest.approx((1e-6 * ode.LOOSER_MUL, 1e-9 * ode.LOOSER_MUL))
    assert len(res.warnings) == 1 and "accuracy.max_steps" in res.warnings[0]
    # rtol of the looser run is capped; without the fallback the estimate is null
    seen.clear()
    ode.check_solve(_Res(), run, 1e-3, 1e-6)
    assert seen[1][0] == ode.LOOSER_CAP
    res = _Res()
    seen.clear()
    assert ode.check_solve(res, run, 1e-6, 1e-9, fallback=False) is None
    assert res.error_estimate is None and "error_estimate is null" in res.warnings[0]


def test_check_solve_other_failure_gives_a_null_estimate():
    def run(r, a):
        raise NumericalError("the integrator failed")

    res = _Res()
    assert ode.check_solve(res, run, 1e-6, 1e-9) is None
    assert res.error_estimate is None and "the integrator failed" in res.warnings[0]


def test_relative_difference_uses_each_quantitys_own_scale():
    x, x2 = np.array([100.0, -200.0]), np.array([100.0, -200.002])      # 1e-5 of 200
    v, v2 = np.array([0.001, 0.002]), np.array([0.001, 0.002 + 2e-9])   # 1e-6 of 0.002
    # the scale is the largest magnitude over both runs (200.002, 0.002000002)
    assert ode.relative_difference([(x, x2), (v, v2)]) == pytest.approx(0.002 / 200.002, rel=1e-9)
    assert ode.relative_difference([(v, v2)]) == pytest.approx(2e-9 / (0.002 + 2e-9), rel=1e-6)
    # a floor raises the scale; a quantity that vanishes in both runs counts 0; inf/NaN skipped
    assert ode.relative_difference([(v, v2)], [1.0]) == pytest.approx(2e-9, rel=1e-6)
    assert ode.relative_difference([(np.zeros(3), np.zeros(3))]) == 0.0
    assert ode.relative_difference([([1.0, math.inf], [1.0 + 1e-8, math.nan])]) == pytest.approx(1e-8, rel=1e-6)


def test_no_route_reads_scipys_private_dense_output():
    # dense output only through OdeSolver.dense_output() (ode.dense_output); dyncli's own stepper
    # (dyncli/dop853.py, scipy's DOP853 transcribed) is where its dense output is made
    for path in (ROOT / "dyncli").rglob("*.py"):
        if path.name == "dop853.py":
            continue
        text = path.read_text(encoding="utf-8")
        for private in ("Dop853DenseOutput", "RkDenseOutput", "._dense_output_impl", "d.F,", '"F", None'):
            assert private not in text, f"{path.relative_to(ROOT)} reads scipy's {private}"


def test_vibration_ode_route_respects_max_steps():
    text = "type: vibration\nm: 1\nk: 1\nzeta: 0.01\nx0: 1\nat: [0, 300]\n"
    ok = solve_one_text(text + "accuracy: {method: DOP853}\n")
    assert ok.get("error") is None and ok["method"] == "ode:DOP853"
    rec = solve_text(text + "accuracy: {method: DOP853, max_steps: 60}\n")[0]
    assert rec["exit_code"] == 1 and "max_steps" in rec["error"]


def test_particles_check_solve_over_budget_falls_back_to_a_conservative_estimate():
    # the main run (~57 steps) fits max_steps: 80, the check run at rtol/100 (~100) does not: the
    # looser check run bounds the error from above (it measures the looser run's error)
    text = ("type: particles\nparticles: [{m: 1, x: [0, 0, 0], v: [0, 1, 0]}, {m: 1, x: [1.5, 0, 0], v: [0, 1, 0]}]\n"
            "pairs: [{between: [0, 1], kind: spring, k: 4, L: 1}]\nat: [0, 1, 5]\n")
    full = solve_one_text(text)
    capped = solve_one_text(text + "accuracy: {max_steps: 80}\n")
    assert capped["results"]["x_motion"] == full["results"]["x_motion"]
    assert any("accuracy.max_steps" in w and "10·rtol" in w for w in capped["warnings"])
    assert capped["error_estimate"] >= full["error_estimate"] > 0
