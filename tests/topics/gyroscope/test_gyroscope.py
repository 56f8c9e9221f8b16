"""gyroscope (§37): θ(t) against a quadrature of (37.15b) in mpmath, turning points, Table 37.1."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

I1, I2, P, Q = 0.01, 0.006, 100.0, 1.0


def t_of_theta(theta):
    """Time to reach θ from θ = 0 (37.14), by quadrature of (37.15b) in mpmath."""
    with mp.workdps(25):
        f = lambda th: 1 / mp.sqrt(((I1 - I2) * Q**2 * mp.sin(th) + 2 * I1 * P * Q) * mp.sin(th) / I2)
        return float(mp.quad(f, [0, theta]))


def test_example_between_0_and_pi():
    rec = solve_path(PROBLEMS / "gyroscopic" / "gyroscope-0-to-pi.yaml")[0]
    r = rec["results"]
    assert r["theta_min"] == 0.0
    assert r["theta_max"] == pytest.approx(math.pi, rel=1e-15)
    assert rec["method"] == "exact" and 0 < rec["error_estimate"] < 1e-13
    # θ at t = 0.1 s against the inverted quadrature (25 digits)
    th = mp.findroot(lambda x: t_of_theta(x) - 0.1, 0.8)
    assert r["theta"][2] == pytest.approx(float(th), abs=1e-13)
    for M in r["M"]:
        assert abs(M[2]) < 1e-12   # (37.11)


def test_quarter_turn_rate():
    T = t_of_theta(math.pi / 2)
    rec = solve_one_text(f"type: gyroscope\nI1: {I1}\nI2: {I2}\np: {P}\nq: {Q}\nat: [{T!r}, {2 * t_of_theta(math.pi)!r}]\n")
    r = rec["results"]
    assert r["theta"][0] == pytest.approx(math.pi / 2, abs=1e-8)
    assert r["theta_dot"][0] == pytest.approx(math.sqrt((I1 - I2 + 2 * I1 * P) / I2), rel=1e-8)
    # a full period: back at θ = 0 (37.17)
    assert r["theta"][1] == pytest.approx(0.0, abs=1e-6)
    # Table 37.1 moment e''₂ component at θ = π/2: −2 I2 q θ̇ + I1 (q + p) θ̇
    thd = r["theta_dot"][0]
    assert r["M"][0][1] == pytest.approx(-2 * I2 * Q * thd + I1 * (Q + P) * thd, rel=1e-8)
    assert r["M"][0][0] == pytest.approx(0.0, abs=1e-7)


def test_negative_pq_goes_to_minus_pi():
    r = solve_one_text("type: gyroscope\nI1: 0.01\nI2: 0.006\np: -100\nq: 1\nat: [0.1]\n")["results"]
    assert r["theta_min"] == pytest.approx(-math.pi) and r["theta_max"] == 0.0
    assert r["theta"][0] < 0


def test_circulates_null_bounds():
    rec = solve_one_text("type: gyroscope\nI1: 0.01\nI2: 0.006\np: 1\nq: 1\ntheta_dot0: 100\nat: [0.1]\n")
    assert rec["results"]["theta_min"] is None and rec["results"]["theta_max"] is None
    assert any("circulates" in w for w in rec["warnings"])


def test_q_zero_closed_form():
    rec = solve_one_text("type: gyroscope\nI1: 0.01\nI2: 0.006\np: 10\nq: 0\ntheta0: 0.2\ntheta_dot0: 0.5\nat: [2]\n")
    assert rec["method"] == "closed-form"
    assert rec["results"]["theta"][0] == pytest.approx(1.2, rel=1e-15)


def test_estimate_second_run():
    rec = solve_one_text("type: gyroscope\nI1: 0.01\nI2: 0.006\np: 100\nq: 1\nat: [0.3]\naccuracy: {rtol: 1.0e-6, estimate: true}\n")
    assert 0 < rec["error_estimate"] < 1e-4


@settings(max_examples=40, deadline=None)
@given(th0=st.floats(-3, 3), thd0=st.floats(-5, 5), p=st.floats(-50, 50), q=st.floats(-3, 3), ratio=st.floats(0.2, 1.99))
def test_turning_points_bound_the_motion(th0, thd0, p, q, ratio):
    from dyncli.topics.gyroscope import solver

    i2 = 0.01
    i1 = ratio * i2
    tmin, tmax, C = solver.turning_points(i1, i2, p, q, th0, thd0)
    if tmin is None:
        return
    assert tmin <= th0 + 1e-12 and th0 <= tmax + 1e-12
    # θ̇² >= 0 inside, = 0 at the bounds (37.13)
    for b in (tmin, tmax):
        G = C - (0.5 * (i2 - i1) * q * q * math.sin(b) ** 2 - i1 * p * q * math.sin(b))
        assert abs(G) <= 1e-9 * (abs(C) + i1 * abs(p * q) + i2 * q * q + 1e-12)
    xs = np.linspace(tmin, tmax, 101)[1:-1]
    G = C - (0.5 * (i2 - i1) * q * q * np.sin(xs) ** 2 - i1 * p * q * np.sin(xs))
    assert np.all(G >= -1e-9 * (abs(C) + i1 * abs(p * q) + i2 * q * q + 1e-12))


@pytest.mark.parametrize("text,field,msg", [
    ("type: gyroscope\nI1: -1\nI2: 1\np: 1\nq: 1\n", "I1", "> 0"),
    ("type: gyroscope\nI1: 3\nI2: 1\np: 1\nq: 1\n", None, "triangle"),
    ("type: gyroscope\nI1: 1\nI2: 1\np: 1\n", None, "q"),
    ("type: gyroscope\nI1: 1\nI2: 1\np: 1\nq: 1\naccuracy: {method: RK99}\n", None, "unknown method"),
])
def test_invalid(text, field, msg):
    err = error_of(text)
    assert err.startswith("bad.yaml:")
    if field:
        line = [i + 1 for i, l in enumerate(text.splitlines()) if l.startswith(field + ":")][0]
        assert err.startswith(f"bad.yaml:{line}:") and f"{field}:" in err
    assert msg in err


def test_magnitudes_beyond_doubles_are_reported_not_printed_as_inf():
    """C of (37.13) beyond a double: exit 2 naming theta_dot0; θ0 + θ̇0 t beyond a double (q = 0):
    exit 1 with a message (both printed inf or nan with exit 0 before)."""
    from tests.conftest import error_of, solve_text

    base = "type: gyroscope\nI1: 0.01\nI2: 0.006\np: 100\nq: 0\n"
    msg = error_of(base + "theta_dot0: 1e300\nat: [0, 1]\n")
    assert "theta_dot0" in msg and "beyond a double" in msg
    rec = solve_text(base + "theta_dot0: 1e150\nat: [0, 1e300]\n")[0]
    assert rec["exit_code"] == 1 and "beyond a double" in rec["error"]
