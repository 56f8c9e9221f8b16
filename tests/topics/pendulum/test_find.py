"""`find` (§11) on the pendulum: turning points and extremes as roots of the exact rates, against
the period and quarter period from mpmath's K."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_one_text
from tests.topics.pendulum import reference as ref

EPS = 2.0 ** -52


def _find(extra: str, queries: str) -> dict:
    return solve_one_text("type: pendulum\nl: 1\nm: 1\n" + extra + f"find: {queries}\n")


def test_turning_point_and_bottom_of_a_swing():
    T = float(ref.period(1.0, 9.81, 2.0))
    rec = _find("theta0: 2\nt_end: 10\n", "[{min: theta}, {max: theta_dot}, {when: {theta: 0}, occurrence: 3}, {max: tension}]")
    f = rec["results"]["find"]
    assert f[0]["t"] == pytest.approx(T / 2, rel=8 * EPS) and f[0]["theta"] == pytest.approx(-2.0, rel=8 * EPS)
    assert abs(f[0]["theta_dot"]) <= 1e-14
    assert f[1]["t"] == pytest.approx(3 * T / 4, rel=8 * EPS)                  # fastest at the bottom, moving up
    assert f[2]["t"] == pytest.approx(T / 4 + T, rel=8 * EPS)                  # the third pass of the bottom
    assert f[3]["t"] == pytest.approx(T / 4, rel=8 * EPS)
    assert f[3]["tension"] == pytest.approx(9.81 * (3 - 2 * math.cos(2.0)), rel=8 * EPS)


def test_over_the_top_reaches_the_top_at_half_a_turn():
    T = float(ref.period(1.0, 9.81, 0.0, 7.0))
    rec = _find("theta0: 0\ntheta_dot0: 7\nt_end: 6\n", "[{when: {theta: pi}}, {when: {theta: 4*pi}}, {min: theta_dot, within: [0, 2]}]")
    f = rec["results"]["find"]
    assert f[0]["t"] == pytest.approx(T / 2, rel=8 * EPS)
    assert f[1]["t"] == pytest.approx(2 * T, rel=8 * EPS)
    assert f[2]["theta"] == pytest.approx(math.pi, rel=1e-12)                 # slowest at the top


def test_separatrix_never_reaches_the_top():
    rec = solve_one_text("type: pendulum\nl: 1\ng: 4\ntheta0: 0\ntheta_dot0: 4\nt_end: 10\nfind: [{when: {theta: pi}}, {when: {theta: 3}}]\n")
    f = rec["results"]["find"]
    assert f[0]["reached"] is False and any("find.0: not reached" in w for w in rec["warnings"])
    assert f[1]["t"] == pytest.approx(math.asinh(math.tan(1.5)) / 2, rel=8 * EPS)     # 2 atan(sinh 2t) = 3


def test_a_tension_whose_rate_overflows_is_still_found():
    """m g = 1e300 with ω₀ = 1e100: the tension (at most m g (3 − 2 cos θ₀) at the bottom) is a
    double though its rate −3 m g θ̇ sin θ is not; the mass is accepted and the extremes found (the
    largest at the bottom, a quarter period K/ω₀ in; the least at the release)."""
    rec = solve_one_text("type: pendulum\nl: 1e-100\ng: 1e100\nm: 1e200\ntheta0: 1\n"
                         "find: [{max: tension}, {min: tension}]\n")
    f = rec["results"]["find"]
    T = float(ref.period(1e-100, 1e100, 1.0))
    assert f[0]["t"] == pytest.approx(T / 4, rel=1e-12)
    assert f[0]["tension"] == pytest.approx(1e300 * (3 - 2 * math.cos(1.0)), rel=8 * EPS)
    assert f[1]["t"] == 0.0 and f[1]["tension"] == pytest.approx(1e300 * math.cos(1.0), rel=8 * EPS)
