"""Tension, energy, the slack angle and the distance, against mpmath: the tension from the
reference state, the energy as ½ml²θ̇² + mgl(1 − cos θ) of it (a second formulation of 2mglk²),
the distance by quadrature of l|θ̇| split at the turning points."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from dyncli.topics.pendulum.motion import Motion
from tests.conftest import solve_one_text
from tests.topics.pendulum import reference as ref

EPS = 2.0 ** -52
MPMATH_DPS = 30


def _solve(extra: str) -> dict:
    return solve_one_text("type: pendulum\nl: 0.8\nm: 2\n" + extra)


@pytest.mark.parametrize("theta0,theta_dot0", [(2.0, 0.0), (0.3, 1.0), (0.0, 9.0)])
def test_tension_and_energy(theta0, theta_dot0):
    times = [0.0, 0.2, 0.9, 2.5]
    rec = _solve(f"theta0: {theta0!r}\ntheta_dot0: {theta_dot0!r}\nat: {times}\n")
    R = rec["results"]
    l, g, m = mp.mpf(0.8), mp.mpf(9.81), 2
    for t, T in zip(times, R["tension"]):
        th, thd = ref.elliptic(0.8, 9.81, theta0, theta_dot0, t) if t else (mp.mpf(theta0), mp.mpf(theta_dot0))
        Tref = m * (l * thd ** 2 + g * mp.cos(th))
        E = m * (l ** 2 * thd ** 2 / 2 + g * l * (1 - mp.cos(th)))
        scale = float(m * (l * thd ** 2 + g))
        assert abs(T - float(Tref)) <= 64 * EPS * scale, (t, T, Tref)
        assert R["E"] == pytest.approx(float(E), rel=16 * EPS)


def test_slack_angle_is_where_the_tension_vanishes():
    rec = _solve("theta0: 2.5\n")
    th = rec["results"]["theta_slack"]
    k2 = math.sin(1.25) ** 2
    with mp.workdps(30):      # tension at θ from the energy integral, l θ̇² = 4g(k² − sin²(θ/2))
        T = 4 * (k2 - mp.sin(mp.mpf(th) / 2) ** 2) + mp.cos(mp.mpf(th))
    assert abs(float(T)) <= 8 * EPS
    assert _solve("theta0: 1.0\n")["results"]["theta_slack"] is None          # k² < ½: stays taut
    assert _solve("theta0: 0\ntheta_dot0: 30\n")["results"]["theta_slack"] is None   # fast over the top


def _distance_reference(l, theta0, theta_dot0, t):
    """l∫|θ̇| dt by mpmath quadrature, split at the turning points (T/2 apart) and at t."""
    mo = Motion(l, 9.81, theta0, theta_dot0)
    knots = [0.0] + [tt for tt in mo_turns(mo, t)] + [t]
    with mp.workdps(20):
        f = lambda s: abs(ref.elliptic(l, 9.81, theta0, theta_dot0, s)[1])      # noqa: E731
        return float(l * sum(mp.quad(f, [a, b]) for a, b in zip(knots, knots[1:]) if b > a))


def mo_turns(mo, t_end):
    """The turning points of a swing from the mpmath phase: ω₀t + u₀ = K + 2Kj."""
    with mp.workdps(30):
        w, k2 = ref.modulus(mo.l, mo.g, mo.theta0, mo.theta_dot0)
        K = mp.ellipk(k2)
        k = mp.sqrt(k2)
        u0 = mp.ellipf(mp.atan2(mp.sin(mp.mpf(mo.theta0) / 2) / k, mp.mpf(mo.theta_dot0) / (2 * w * k)), k2)
        j = int(mp.floor((u0 - K) / (2 * K))) + 1
        out = []
        while True:
            tt = float((K + 2 * K * j - u0) / w)
            if tt > t_end:
                return out
            if tt > 0:
                out.append(tt)
            j += 1


@pytest.mark.parametrize("theta0,theta_dot0,t", [(2.0, 0.0, 3.1), (0.5, -1.0, 2.2), (0.1, 0.0, 0.4)])
def test_distance_of_a_swing(theta0, theta_dot0, t):
    rec = solve_one_text(f"type: pendulum\nl: 1.5\ntheta0: {theta0!r}\ntheta_dot0: {theta_dot0!r}\nat: [{t!r}]\n")
    d = rec["results"]["distance"][0]
    ref_d = _distance_reference(1.5, theta0, theta_dot0, t)
    assert d == pytest.approx(ref_d, rel=1e-13)


def test_distance_a_million_periods_later():
    """Every period adds 4θ_max exactly: at t = 10⁶ T (+ a quarter), 4·10⁶ l θ_max (+ l θ_max)."""
    T = float(ref.period(1.0, 9.81, 2.0))
    rec = solve_one_text(f"type: pendulum\nl: 1\ntheta0: 2\nat: [{1e6 * T!r}, {1e6 * T + T / 4!r}]\n")
    d = rec["results"]["distance"]
    assert d[0] == pytest.approx(4e6 * 2.0, rel=1e-14)
    assert d[1] == pytest.approx(4e6 * 2.0 + 2.0, rel=1e-14)


def test_distance_over_the_top_is_the_angle_turned():
    rec = solve_one_text("type: pendulum\nl: 2\ntheta0: 0\ntheta_dot0: -8\nat: [0.5, 3]\n")
    R = rec["results"]
    for t, d, th in zip([0.5, 3], R["distance"], R["theta"]):
        a, _ = ref.elliptic(2.0, 9.81, 0.0, -8.0, t)
        assert d == pytest.approx(2 * abs(float(a)), rel=1e-14) and th < 0
