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

    from dyncli.dop853 import DOP853

    for name in runner.METHODS:
        assert runner.solver_class(name, scipy=True) is getattr(si, name)
        assert runner.solver_class(name) is (DOP853 if name == "DOP853" else getattr(si, name))
    for alias in ("auto", "ode", "exact", "projected"):
        assert runner.solver_class(alias) is DOP853 and runner.solver_class(alias, scipy=True) is si.DOP853
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


FORCED_EULER = """type: euler
I: [1, 2, 3]
omega0: [0.001, 5, 0.001]
M: ["0.1*sin(t)", "0", "0.05"]
at: [0, 1, 2, 3]
accuracy: {estimate: true, max_steps: 30}
"""


def test_euler_forced_check_solve_falls_back_as_documented():
    """A forced body whose reported run fits max_steps but whose check solve at rtol/100 does not:
    the one fallback of docs/accuracy.md (a solve at 10·rtol and a warning), not exit 1."""
    from tests.conftest import solve_one_text

    rec = solve_one_text(FORCED_EULER)
    assert any("exceeds the step budget" in w for w in rec["warnings"])
    assert 0 < rec["error_estimate"] < 1e-6
    free = solve_one_text(FORCED_EULER.replace(", max_steps: 30", ""))
    assert free["results"] == rec["results"]          # the answer itself does not change


def test_constrained_particle_runs_no_check_solve_without_estimate(monkeypatch):
    """constrained-particle's ODE route integrates once with estimate: false (the nominal
    estimate), twice with estimate: true."""
    from dyncli.topics.constrained_particle import dynamics
    from tests.conftest import solve_one_text

    calls = []
    real = dynamics.integrate
    monkeypatch.setattr(dynamics, "integrate", lambda *a, **k: calls.append(a[1]) or real(*a, **k))
    text = ("type: constrained-particle\nm: 0.1\ncurve: {x1: 'sin(q)', x2: 0, x3: '-cos(q)'}\n"
            "rotation: {axis: [0, 0, 1], omega: 6}\nq0: 0.3\nforces: [{kind: gravity}]\nat: [0, 1]\n")
    rec = solve_one_text(text + "accuracy: {method: ode}\n")     # (a closed hoop: the energy route by itself)
    assert len(calls) == 1 and rec["error_estimate"] > 0
    calls.clear()
    solve_one_text(text + "accuracy: {estimate: true, method: ode}\n")
    assert len(calls) == 2 and calls[1] == pytest.approx(calls[0] / ode.CHECK_DIV)


def test_march_locates_a_terminal_event_as_solve_ivp():
    """runner.march: the runner's own event driver finds the terminal event of scipy's
    solve_ivp (a pendulum's first stop, q̇ = 0 downwards) at the same time to rounding, and its
    interpolant reproduces the states."""
    import math

    import numpy as np
    from scipy.integrate import solve_ivp

    from dyncli import ode, runner

    def rhs(t, y):
        return [y[1], -9.81 / 0.5 * math.sin(y[0])]

    def stop(t, y):
        return y[1]
    stop.terminal, stop.direction = True, -1

    run = runner.march(rhs, 0.0, [0.0, 3.0], 10.0, method="DOP853", budget=ode.Budget(), rtol=1e-10,
                       atol=1e-12, events=[stop])
    ref = solve_ivp(rhs, (0.0, 10.0), [0.0, 3.0], method="DOP853", rtol=1e-10, atol=1e-12, events=[stop],
                    dense_output=True)
    assert run.status == 1 and run.event == 0
    assert abs(run.t_event - ref.t_events[0][0]) <= 1e-13
    assert abs(run.y_event[1]) <= 1e-12
    assert np.allclose(run.sol(np.linspace(0, run.t_event, 7)), ref.sol(np.linspace(0, run.t_event, 7)),
                       rtol=0, atol=1e-13)
    free = runner.march(rhs, 0.0, [0.0, 3.0], 1.0, method="DOP853", budget=ode.Budget(), rtol=1e-10, atol=1e-12)
    assert free.status == 0 and free.t[-1] == 1.0 and free.event is None
