"""The gallery example problems/particle/pendulum.yaml against mpmath (40 digits)."""

from __future__ import annotations

import math

import pytest

from tests.conftest import PROBLEMS, solve_path
from tests.topics.pendulum import reference as ref

EPS = 2.0 ** -52


def test_pendulum_example():
    swing, over, sep = solve_path(PROBLEMS / "particle" / "pendulum.yaml")
    R = swing["results"]
    theta0 = 120 * math.pi / 180
    assert R["period"] == pytest.approx(float(ref.period(1.0, 9.81, theta0)), rel=16 * EPS)
    assert R["period_ratio"] == pytest.approx(float(ref.period(1.0, 9.81, theta0)) / (2 * math.pi / math.sqrt(9.81)),
                                              rel=16 * EPS)
    for t, th, thd in zip([0.5, 1, 2.75409, 100], R["theta"][1:], R["theta_dot"][1:]):
        a, b = ref.elliptic(1.0, 9.81, theta0, 0.0, t)
        assert th == pytest.approx(float(a), abs=1e-13) and thd == pytest.approx(float(b), abs=1e-12)
    f = R["find"]
    assert f[0]["tension"] == pytest.approx(9.81 * 4, rel=8 * EPS)            # mg(3 − 2 cos 120°) at the bottom
    assert f[1]["tension"] == pytest.approx(-9.81 / 2, rel=8 * EPS)           # mg cos 120° at the ends
    assert over["results"]["regime"] == "rotating"
    assert over["results"]["period"] == pytest.approx(float(ref.period(1.0, 9.81, 0.0, 7.0)), rel=16 * EPS)
    S = sep["results"]
    assert S["regime"] == "separatrix" and S["period"] is None
    for t, th in zip([1, 10], S["theta"][1:]):
        assert th == pytest.approx(float(ref.separatrix(1.0, 4.0, 0.0, 4.0, t)[0]), abs=4 * EPS)
