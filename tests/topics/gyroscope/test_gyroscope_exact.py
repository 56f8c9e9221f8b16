"""gyroscope (§37) exact route: θ(t), θ̇(t) against mpmath references (30-digit Taylor
integration of (37.12), 40-digit quadrature of (37.15b) for long times; gyroscope_reference_data.py,
written by gen_gyroscope_reference.py), against the ODE route, and the elliptic solution's own
consistency at the extremes."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings, strategies as st

from tests.conftest import solve_one_text
from tests.topics.gyroscope.gyroscope_reference_data import CASES

EPS = 2.220446049250313e-16
# cases whose rows are far out in phase (λt ≳ 1e5): the phase u = λt + u0 rounded to a double
# carries ε·λt; there the reported error_estimate (16 ε (1 + λt)) is the bound tested
LONG = {"long", "long_circulating", "long_p_1e6"}


def text_of(I1, I2, p, q, th0, thd0, times, extra=""):
    return (f"type: gyroscope\nI1: {I1!r}\nI2: {I2!r}\np: {p!r}\nq: {q!r}\ntheta0: {th0!r}\n"
            f"theta_dot0: {thd0!r}\nat: {[float(t) for t in times]}\n{extra}")


def scales(I1, I2, p, q, th0, thd0):
    """θ: π (one swing); θ̇: √(θ̇0² + 2|a| + 2|b|), the size of θ̇ over the motion."""
    a, b = (I1 - I2) * q * q / I2, 2 * I1 * p * q / I2
    return math.pi, math.sqrt(thd0 * thd0 + 2 * abs(a) + 2 * abs(b))


@pytest.mark.parametrize("name", sorted(CASES))
def test_exact_route_matches_the_mpmath_reference(name):
    case = CASES[name]
    args, times = case["input"], case["times"]
    rec = solve_one_text(text_of(*args, times))
    assert rec["method"] == "exact"
    r = rec["results"]
    s_th, s_thd = scales(*args)
    err = max(max(abs(x - row[0]) for x, row in zip(r["theta"], case["rows"])) / s_th,
              max(abs(x - row[1]) for x, row in zip(r["theta_dot"], case["rows"])) / s_thd)
    est = rec["error_estimate"]
    if name in LONG:
        # round-off of the phase: bounded by the estimate, itself ~ε·λt
        assert err <= est <= 32 * EPS * (1 + max(times) * scales(*args)[1]), (err, est)
    else:
        assert err < 1e-12, (name, err)
        assert est < 1e-12
    for M in r["M"]:
        assert abs(M[2]) <= 1e-9 * s_thd * s_thd * args[1]        # (37.11): no moment about e''₃


@pytest.mark.parametrize("name", ["zero_to_pi", "pq_negative", "circulating", "band", "equal_moments",
                                  "prolate_rest"])
def test_ode_and_exact_routes_check_each_other(name):
    case = CASES[name]
    args = case["input"]
    times = case["times"] + [-t for t in case["times"]]        # backwards in time too
    ex = solve_one_text(text_of(*args, times))["results"]
    od = solve_one_text(text_of(*args, times, "accuracy: {method: DOP853, rtol: 1.0e-10, atol: 1.0e-12}\n"))
    assert od["method"] == "ode:DOP853"
    s_th, s_thd = scales(*args)
    # DOP853 at rtol 1e-10 over a few swings: global error within 100 rtol of the scales
    for key, s in (("theta", s_th), ("theta_dot", s_thd)):
        assert max(abs(x - y) for x, y in zip(ex[key], od["results"][key])) <= 100 * 1e-10 * s


def test_equilibrium_starts_stay_put_at_any_time():
    # θ0 = π/2 at rest (cos θ0 = 0) and the asin root of (37.12) (decided exactly by dyncli.exact)
    for th in ("pi/2", "asin(0.01*3/((0.03 - 0.01)*7))"):
        rec = solve_one_text(f"type: gyroscope\nI1: 0.01\nI2: 0.03\np: 3\nq: 7\ntheta0: \"{th}\"\nat: [0, 1e6]\n")
        assert rec["method"] == "exact"
        r = rec["results"]
        assert r["theta"][0] == r["theta"][1] and r["theta_dot"] == [0.0, 0.0]


def test_exact_method_for_q_zero_is_uniform_rotation():
    rec = solve_one_text(text_of(0.01, 0.006, 10.0, 0.0, 0.2, 0.5, [2.0, 1e6], "accuracy: {method: exact}\n"))
    assert rec["method"] == "exact"
    r = rec["results"]
    assert r["theta"][0] == pytest.approx(1.2, rel=4 * EPS)
    assert r["theta"][1] == pytest.approx(0.2 + 0.5e6, rel=1e-12)
    assert r["theta_dot"] == pytest.approx([0.5, 0.5], rel=4 * EPS)


def test_long_run_is_not_refused_and_samples_for_plots():
    rec = solve_one_text(text_of(0.01, 0.006, 100.0, 1.0, 0.3, 2.0, [1e6] * 3))
    assert rec["method"] == "exact" and len(set(rec["results"]["theta"])) == 1


def separatrix_distance(g):
    """The complementary parameter of the sn/cn/dn actually evaluated: m1 for 0 ≤ m < 1, and for
    m < 0 (through the imaginary-modulus transformation, parameter −m/m1) 1/m1 — the distance to
    the separatrix that conditions the solution (m1 itself is > 1 there)."""
    return g.m1 if g.m >= 0 else 1.0 / g.m1


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(th0=st.floats(-4, 4), thd0=st.floats(-30, 30), p=st.sampled_from([-1e6, -100.0, -1.0, 0.0, 0.3, 5.0, 1e6]),
       q=st.floats(-5, 5), ratio=st.floats(0.05, 1.99), t1=st.floats(0.0, 50.0), dt=st.floats(0.0, 50.0))
# a libration with m = −58114 (m1 = 58115: 1.7e-5 from the separatrix after the transformation), the
# axis passing 0.008 rad from the unstable −π/2 every swing: one ulp of the restart state moves θ(t1 + dt)
# by ~4e-10 (measured) — the restart's conditioning, which the tolerance took from m1 instead of 1/m1
@example(th0=-1.5625, thd0=0.0, p=1e6, q=1.0, ratio=1.0, t1=1.0, dt=1.0)
def test_elliptic_solution_is_consistent_at_the_extremes(th0, thd0, p, q, ratio, t1, dt):
    """The first integral (37.15b) holds at any time, and restarting from the state at t1 gives
    the same state at t1 + dt (different roots, centre and phase): a self-check of every branch
    (libration, band, circulation, m < 0) over fast and slow spins."""
    from dyncli.topics.gyroscope.elliptic import GyroTheta
    from dyncli.topics.gyroscope.exact_route import theta_dot_sq
    from dyncli.topics.gyroscope.solver import _balanced

    I2 = 0.006
    I1 = ratio * I2
    assume(abs(q) > 1e-3 and not (thd0 == 0 and _balanced(I1, I2, p, q, th0)))
    g = GyroTheta(I1, I2, p, q, th0, thd0)
    assume(g.finite and separatrix_distance(g) > 1e-6)       # the separatrix: conditioning ~1/m1
    th, thd = g.evaluate(np.array([t1, t1 + dt]))
    s_th, s_thd = scales(I1, I2, p, q, th0, thd0)
    assert np.all(np.abs(thd ** 2 - theta_dot_sq(I1, I2, p, q, th0, thd0, th)) <= 1e-12 * s_thd ** 2)
    g2 = GyroTheta(I1, I2, p, q, float(th[0]), float(thd[0]))
    assume(g2.finite and separatrix_distance(g2) > 1e-6)
    th2, thd2 = g2.evaluate(np.array([dt]))
    # the phase λ(t1 + dt) carries ε·λt; the restart's state ε-perturbed, amplified ~1/√m1 near the separatrix
    tol = 1e-12 * (1 + g.lam * (t1 + dt)) / math.sqrt(min(separatrix_distance(g), 1.0))
    assert abs(th2[0] - th[1]) <= tol * s_th and abs(thd2[0] - thd[1]) <= tol * s_thd


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(th0=st.floats(-4, 4), thd0=st.floats(-30, 30), p=st.sampled_from([-1e6, -100.0, -1.0, 0.0, 0.3, 5.0, 1e6]),
       q=st.floats(-5, 5), ratio=st.floats(0.05, 1.99), t=st.floats(0.0, 50.0))
def test_one_time_in_floats_is_the_array_path(th0, thd0, p, q, ratio, t):
    """θ, θ̇ at one float time (the requested times: math only, no numpy) and at an array of times
    (plots: numpy) are one algorithm on two backends whose sin/arcsin/arctan may differ by an ulp:
    ~2ε(1 + λt) in sn, cn, dn, amplified by at most ~1/m1 next to the separatrix; the bound allows
    8 times that, relative to the scales of θ and θ̇ (0.3 observed)."""
    from dyncli.topics.gyroscope.elliptic import GyroTheta

    I2 = 0.006
    I1 = ratio * I2
    g = GyroTheta(I1, I2, p, q, th0, thd0)
    m1 = getattr(g, "m1", 1.0)          # a steady state has none
    assume(g.finite and m1 > 1e-6)
    th, thd = g.evaluate(t)
    assert type(th) is float and type(thd) is float
    tha, thda = g.evaluate(np.array([t]))
    s_th, s_thd = scales(I1, I2, p, q, th0, thd0)
    tol = 8 * 2.0 ** -52 * (1 + g.lam * t) / min(m1, 1.0)
    assert abs(th - tha[0]) <= tol * s_th and abs(thd - thda[0]) <= tol * s_thd
