"""The exact period against mpmath's complete elliptic integral (40 digits), from θ₀ → 0 (the
small-angle limit) to 1e-12 rad below the top, over the top, and its absence on the separatrix."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from dyncli.topics.pendulum.motion import Motion
from tests.conftest import solve_one_text
from tests.topics.pendulum import reference as ref

EPS = 2.0 ** -52
#: K by Carlson's R_F is good to a few ε (tests/foundation/test_elliptic.py); T = 4K/ω₀ adds the
#: rounding of √(g/l), one division and, next to the top, the conditioning of K in 1 − k²
#: (dK/K = d(1 − k²)/(2(1 − k²)K), 1 − k² itself to an ε)
PERIOD_RTOL = 16 * EPS


@pytest.mark.parametrize("theta0", [1e-12, 1e-6, 1e-3, 0.1, 0.5, 1.0, 2.0, 3.0])
def test_swing_period(theta0):
    mo = Motion(1.0, 9.81, theta0, 0.0)
    assert mo.regime == "swing"
    assert mo.period == pytest.approx(float(ref.period(1.0, 9.81, theta0)), rel=PERIOD_RTOL)


@pytest.mark.parametrize("delta", [1e-1, 1e-3, 1e-6, 1e-9, 1e-12])
def test_period_next_to_the_top(delta):
    """Released from rest δ below the top: T = 4K/ω₀, K ≈ ln(8/δ) grows without bound."""
    theta0 = math.pi - delta
    mo = Motion(2.0, 9.81, theta0, 0.0)
    assert mo.regime == "swing"
    assert mo.period == pytest.approx(float(ref.period(2.0, 9.81, theta0)), rel=PERIOD_RTOL)
    with mp.workdps(40):      # the asymptotic form K = ln(8/δ) + O(δ² ln δ), a second formulation
        K = float(mp.log(8 / (mp.pi - mp.mpf(theta0))))
    assert mo.period * math.sqrt(9.81 / 2.0) / 4 == pytest.approx(K, rel=delta ** 2 + 16 * EPS)


@pytest.mark.parametrize("theta0", [1e-8, 1e-4, 1e-2])
def test_small_angle_limit(theta0):
    """T/T₀ = 1 + θ₀²/16 + 11θ₀⁴/3072 + ... (the series of 2K(k²)/π in k = sin(θ₀/2))."""
    rec = solve_one_text(f"type: pendulum\nl: 0.5\ntheta0: {theta0!r}\n")
    R = rec["results"]
    assert R["period_small"] == pytest.approx(2 * math.pi * math.sqrt(0.5 / 9.81), rel=4 * EPS)
    series = 1 + theta0 ** 2 / 16 + 11 * theta0 ** 4 / 3072
    assert R["period_ratio"] == pytest.approx(series, rel=4 * EPS + theta0 ** 6)
    assert R["theta_max"] == pytest.approx(theta0, rel=4 * EPS)


@pytest.mark.parametrize("theta_dot0", [6.3, 7.0, 20.0, 1e3])
def test_rotation_period_is_one_turn(theta_dot0):
    mo = Motion(1.0, 9.81, 0.0, theta_dot0)
    assert mo.regime == "rotating"
    assert mo.period == pytest.approx(float(ref.period(1.0, 9.81, 0.0, theta_dot0)), rel=PERIOD_RTOL)
    # a second formulation: the time of one turn is ∫dθ/θ̇ over 2π (energy integral), by quadrature
    with mp.workdps(30):
        w2 = mp.mpf(9.81)
        E = mp.mpf(theta_dot0) ** 2
        T = mp.quad(lambda th: 1 / mp.sqrt(E - 4 * w2 * mp.sin(th / 2) ** 2), [0, mp.pi, 2 * mp.pi])
    assert mo.period == pytest.approx(float(T), rel=1e-14)


def test_the_separatrix_has_no_period():
    rec = solve_one_text("type: pendulum\nl: 1\ng: 4\ntheta0: 0\ntheta_dot0: 4\n")
    R = rec["results"]
    assert R["regime"] == "separatrix" and R["k"] == 1.0
    assert R["period"] is None and R["period_ratio"] is None
    assert any("separatrix" in w for w in rec["warnings"])


def test_within_the_inputs_rounding_of_the_separatrix_is_said():
    """θ₀ = π/2 and θ̇₀ = √(2g/l): 1 − k² = cos²(π/4) − ½ is a rounding error, not a motion."""
    rec = solve_one_text("type: pendulum\nl: 1\ntheta0: pi/2\ntheta_dot0: sqrt(2*9.81)\n")
    assert rec["results"]["regime"] == "separatrix"
    assert any("within the inputs' rounding" in w for w in rec["warnings"])


def test_balanced_at_the_top_stays_there():
    rec = solve_one_text("type: pendulum\nl: 1\ntheta0: pi\nat: [0, 1, 1000]\n")
    R = rec["results"]
    assert R["regime"] == "separatrix"
    assert R["theta"] == [math.pi] * 3 and R["theta_dot"] == [0.0] * 3
    assert any("unstable equilibrium" in w for w in rec["warnings"])


def test_at_rest_at_the_bottom():
    R = solve_one_text("type: pendulum\nl: 1\ntheta0: 0\nat: [0, 5]\n")["results"]
    assert R["regime"] == "rest" and R["period_ratio"] == 1.0 and R["theta"] == [0.0, 0.0]
