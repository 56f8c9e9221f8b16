"""The runner contract (dyncli/runner.py): the one method map, the one rtol floor, and a
:class:`Route` that states only its problem (y0, rhs, times) and gets the policy of
docs/accuracy.md — the nominal estimate, the check solve at rtol/100 and its one fallback."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dyncli import ode, runner
from dyncli.result import Result


class Oscillator(runner.Route):
    """x'' = -x from (1, 0): x = cos t."""

    times = np.linspace(0.0, 6.0, 7)

    def initial_state(self):
        return [1.0, 0.0]

    def rhs(self, t, y):
        return [y[1], -y[0]]


def test_one_method_map_and_floor():
    from scipy import integrate as si

    for name in runner.METHODS:
        assert runner.solver_class(name) is getattr(si, name)
    for alias in ("auto", "ode", "exact", "projected"):
        assert runner.solver_class(alias) is si.DOP853
    with pytest.raises(ValueError):
        runner.solver_class("Euler")
    assert ode.RTOL_FLOOR == runner.RTOL_FLOOR == 100 * np.finfo(float).eps * 1.0001
    assert runner.floor_rtol(1e-20) == runner.RTOL_FLOOR and runner.floor_rtol(1e-6) == 1e-6
    assert ode.tighter(1e-14, 1e-20)[0] == runner.RTOL_FLOOR


def test_route_nominal_estimate_without_check_solve():
    r = Oscillator(rtol=1e-8, atol=1e-10)
    res = Result({})
    Y = r.run(res)
    assert np.max(np.abs(Y[:, 0] - np.cos(Oscillator.times))) < 1e-6
    assert res.error_estimate == pytest.approx(1e-8 * r.nsteps)
    assert "nominal" in res.extra["error_estimate_note"]


def test_route_check_solve_measures_the_error():
    r = Oscillator(rtol=1e-6, atol=1e-8, estimate=True)
    res = Result({})
    Y = r.run(res)
    err = float(np.max(np.abs(Y[:, 0] - np.cos(Oscillator.times))))
    assert err <= res.error_estimate * 1.5 and res.error_estimate < 100 * err
    assert "rtol/100" in res.extra["error_estimate_note"] and not res.warnings


def test_route_check_solve_over_budget_falls_back():
    r = Oscillator(rtol=1e-6, atol=1e-8, estimate=True, max_steps=10)
    res = Result({})
    r.run(res)                       # the reported run fits 10 steps, the check at rtol/100 does not
    assert "10·rtol" in res.extra["error_estimate_note"]
    assert any("exceeds the step budget" in w for w in res.warnings)
    assert math.isfinite(res.error_estimate)
