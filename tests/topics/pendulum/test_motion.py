"""θ(t), θ̇(t) against mpmath (40 digits): its own elliptic functions (ellipf, ellipfun) and, as a
second formulation, a Taylor integration of θ̈ = −(g/l) sin θ (odefun) — swings from θ₀ → 0 to
1e-12 below the top, rotations, the separatrix, and t = 10⁶ periods."""

from __future__ import annotations

import math

import pytest

from dyncli.topics.pendulum.motion import Motion
from tests.conftest import solve_one_text
from tests.topics.pendulum import reference as ref

EPS = 2.0 ** -52


def tolerance(mo: Motion, theta: float, t: float = 0.0) -> float:
    """What the route guarantees for θ: the phase ω₀t + u₀ to ~ε of its reduced size on long
    runs (double-double: at most a period, 4K, plus u₀), to ~ε·λt on short ones (doubles), and
    sn, cn, dn to a few ε relative, times |dθ/dτ| <= 2; plus the rounding of an unwrapped θ."""
    K = getattr(mo, "K", 1.0)
    drift = 0.0 if mo.phase is not None or mo.regime in ("separatrix", "rest") else mo.lam * t
    return 16 * EPS * (4 * K + 1 + abs(theta) + drift)


def check(mo: Motion, l, g, theta0, theta_dot0, times, reference=ref.elliptic):
    for t in times:
        th, thd = mo.state(t)
        a, b = (float(x) for x in reference(l, g, theta0, theta_dot0, t))
        tol = tolerance(mo, a, t)
        assert abs(th - a) <= tol, (t, th, a, abs(th - a), tol)
        assert abs(thd - b) <= tol * mo.omega0 * max(1.0, math.sqrt(mo.k2)), (t, thd, b)


@pytest.mark.parametrize("theta0", [1e-8, 1e-3, 0.5, 2.0, -2.5])
def test_swing(theta0):
    mo = Motion(1.0, 9.81, theta0, 0.0)
    T = mo.period
    check(mo, 1.0, 9.81, theta0, 0.0, [0.1, 0.3 * T, T / 4, T / 2, 0.77 * T, T, 3.3 * T, 41.7])


@pytest.mark.parametrize("delta", [1e-1, 1e-3, 1e-6, 1e-9, 1e-12])
def test_swing_next_to_the_top(delta):
    theta0 = math.pi - delta
    mo = Motion(1.0, 9.81, theta0, 0.0)
    T = mo.period
    check(mo, 1.0, 9.81, theta0, 0.0, [0.1, 0.37 * T, T / 4, T / 2, 0.77 * T, 3.3 * T])


@pytest.mark.parametrize("theta0,theta_dot0", [(0.0, 3.0), (1.0, -2.0), (-0.3, 5.0), (3.0, 0.01)])
def test_swing_with_an_initial_rate(theta0, theta_dot0):
    mo = Motion(0.7, 9.81, theta0, theta_dot0)
    assert mo.regime == "swing"
    check(mo, 0.7, 9.81, theta0, theta_dot0, [0.05, 0.9, 2.3, 17.0])


@pytest.mark.parametrize("theta0,theta_dot0", [(0.0, 7.0), (1.0, -8.0), (3.0, 0.5), (0.0, 2 * math.sqrt(9.81) * (1 + 1e-12)),
                                               (0.0, -2 * math.sqrt(9.81) * (1 + 1e-9)), (-2.0, 100.0)])
def test_rotation(theta0, theta_dot0):
    mo = Motion(1.0, 9.81, theta0, theta_dot0)
    assert mo.regime == "rotating"
    check(mo, 1.0, 9.81, theta0, theta_dot0, [0.1, 0.5 * mo.period, 1.3, 9.0, 10.0, 3.7 * mo.period])


@pytest.mark.parametrize("theta0,theta_dot0", [(0.0, 4.0), (-1.0, 4.0 * math.cos(0.5))])
def test_separatrix(theta0, theta_dot0):
    """θ = 2 atan(sinh(ω₀t + u₀)) (exactly the separatrix for the first; the second within its rounding)."""
    mo = Motion(1.0, 4.0, theta0, theta_dot0)
    assert mo.regime == "separatrix"
    check(mo, 1.0, 4.0, theta0, theta_dot0, [0.1, 1.0, 3.0, 10.0, 1e3, 1e6], reference=ref.separatrix)


@pytest.mark.slow
def test_second_formulation_taylor_integration():
    """The same states from mpmath's Taylor ODE solver (no elliptic function) at 30 digits."""
    for l, th0, thd0, times in [(1.0, 2.0, 0.0, [0.4, 1.7]), (1.0, 0.0, 7.0, [0.3, 1.1]),
                                (1.0, math.pi - 1e-6, 0.0, [3.0])]:
        mo = Motion(l, 9.81, th0, thd0)
        for t, (a, b) in zip(times, ref.taylor(l, 9.81, th0, thd0, times)):
            th, thd = mo.state(t)
            assert abs(th - float(a)) <= tolerance(mo, float(a), t), (th0, thd0, t)
            assert abs(thd - float(b)) <= tolerance(mo, float(a), t) * mo.omega0 * 2, (th0, thd0, t)


@pytest.mark.parametrize("theta0,theta_dot0", [(2.0, 0.0), (math.pi - 1e-9, 0.0), (0.0, 7.0)])
def test_a_million_periods_later(theta0, theta_dot0):
    """At t = 10⁶ periods (the phase reduced in double-double) as exact as in the first period."""
    mo = Motion(1.0, 9.81, theta0, theta_dot0)
    T = float(ref.period(1.0, 9.81, theta0, theta_dot0))
    times = [1e6 * T, 1e6 * T + 0.3, 123456.7]
    mo.long(max(times))
    assert mo.phase is not None
    check(mo, 1.0, 9.81, theta0, theta_dot0, times)


def test_whole_turns_of_theta0_carry_through():
    """θ₀ = 2π + 0.5 swings about 2π: the same motion shifted by a turn, θ(0) = θ₀."""
    rec = solve_one_text("type: pendulum\nl: 1\ntheta0: 2*pi + 0.5\nat: [0, 0.7]\n")
    base = solve_one_text("type: pendulum\nl: 1\ntheta0: 0.5\nat: [0, 0.7]\n")
    th, th_base = rec["results"]["theta"], base["results"]["theta"]
    assert th[0] == 2 * math.pi + 0.5
    assert th[1] - 2 * math.pi == pytest.approx(th_base[1], abs=8 * EPS * 2 * math.pi)


def test_degrees_are_named():
    rec = solve_one_text("type: pendulum\nl: 1\ntheta0: 120\n")
    assert any("theta0" in w and "120*deg" in w for w in rec["warnings"])
    deg = solve_one_text("type: pendulum\nl: 1\ntheta0: 120*deg\n")
    assert deg["results"]["theta_max"] == pytest.approx(2 * math.pi / 3, rel=4 * EPS)
