"""euler (§39): exact torque-free solutions against mpmath odefun and a tight
second integrator; the coin (39.10); applied moments; projection; invalid input."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path


def mp_reference(I, w0, times, dps=20):
    """Euler's equations (39.5) with M = 0 by mpmath's Taylor-series odefun."""
    with mp.workdps(dps):
        Im = [mp.mpf(x) for x in I]

        def f(t, w):
            return [(Im[1] - Im[2]) * w[1] * w[2] / Im[0], (Im[2] - Im[0]) * w[2] * w[0] / Im[1],
                    (Im[0] - Im[1]) * w[0] * w[1] / Im[2]]

        sol = mp.odefun(f, 0, [mp.mpf(x) for x in w0])
        return np.array([[float(c) for c in sol(t)] for t in times])


def scipy_reference(I, w0, times, M=None):
    from scipy.integrate import solve_ivp

    I = np.asarray(I, float)

    def f(t, w):
        m = np.zeros(3) if M is None else M(t)
        return (m - np.cross(w, I * w)) / I

    s = solve_ivp(f, (0, max(times)), w0, method="DOP853", rtol=1e-13, atol=1e-14, t_eval=times)
    return s.y.T


def test_intermediate_axis_against_mpmath():
    rec = solve_path(PROBLEMS / "gyroscopic" / "euler-intermediate-axis.yaml")[0]
    r = rec["results"]
    assert rec["method"] == "closed-form"
    W = np.array(r["omega"])
    ref = mp_reference([1, 2, 3], [0.001, 5, 0.001], [0, 1, 2, 3, 4])
    assert np.max(np.abs(W[:5] - ref)) < 1e-11
    assert W[4][1] < -4 and W[6][1] < -4.99                 # the flip
    assert r["H"] == pytest.approx(math.sqrt(1e-6 + 100 + 9e-6), rel=1e-15)
    assert r["T"] == pytest.approx(0.5 * (1e-6 + 50 + 3e-6), rel=1e-15)
    assert r["drift"] < 1e-14


def test_coin_example():
    rec = solve_path(PROBLEMS / "gyroscopic" / "euler-flipping-coin.yaml")[0]
    r = rec["results"]
    m, R, h = 0.005, 0.012, 0.002
    I1 = m * R**2 / 4 + m * h**2 / 12
    I3 = m * R**2 / 2
    lam = (I3 - I1) / I1 * 3
    assert r["I"] == pytest.approx([I1, I1, I3], rel=1e-14)
    assert r["lambda"] == pytest.approx(lam, rel=1e-14)
    assert r["psi_dot"] == pytest.approx(math.sqrt(40**2 + (I3 / I1 * 3) ** 2), rel=1e-14)
    assert r["theta"] == pytest.approx(math.acos((I3 / I1 * 3) / math.sqrt(40**2 + (I3 / I1 * 3) ** 2)), rel=1e-13)
    for t, w in zip([0, 0.5, 1], r["omega"]):
        assert w == pytest.approx([40 * math.cos(lam * t), 40 * math.sin(lam * t), 3], abs=1e-13)
    # H = I1 λ (39.22)
    assert r["H"] == pytest.approx(I1 * math.sqrt(40**2 + (I3 / I1 * 3) ** 2), rel=1e-14)


def test_symmetry_axis_not_third():
    r = solve_one_text("type: euler\nI: [3, 2, 2]\nomega0: [1, 0.5, 0.2]\nat: [0.7]\n")["results"]
    assert r["symmetry_axis"] == 1
    lam = (3 - 2) / 2 * 1.0
    ref = scipy_reference([3, 2, 2], [1, 0.5, 0.2], [0.7])
    assert r["omega"][0] == pytest.approx(ref[0].tolist(), abs=1e-10)
    assert r["lambda"] == pytest.approx(lam)


@settings(max_examples=25, deadline=None)
@given(I=st.lists(st.floats(1.0, 3.0), min_size=3, max_size=3), w=st.lists(st.floats(-3, 3), min_size=3, max_size=3))
def test_asymmetric_against_second_integrator(I, w):
    from dyncli.topics.euler import free

    if max(I) > I[0] + I[1] + I[2] - max(I) or np.linalg.norm(w) < 1e-3:
        return
    if min(abs(I[0] - I[1]), abs(I[1] - I[2]), abs(I[0] - I[2])) < 1e-6:
        return
    times = np.linspace(0, 5, 6)
    got = free.exact(I, w).omega(times)
    ref = scipy_reference(I, w, times)
    assert np.max(np.abs(got - ref)) <= 1e-8 * np.linalg.norm(w)


@settings(max_examples=40, deadline=None)
@given(eps=st.floats(1e-12, 1e-2), d1=st.floats(-1, 1), d3=st.floats(-1, 1), perm=st.permutations([1.0, 2.0, 3.5]))
def test_near_separatrix_conserves(eps, d1, d3, perm):
    """Spin about the intermediate axis: the exact solution keeps |H| and T to rounding."""
    from dyncli.topics.euler import free

    I = np.array(perm)
    j = int(np.argsort(I)[1])
    w0 = np.zeros(3)
    w0[j] = 4.0
    w0[(j + 1) % 3] = eps * d1
    w0[(j + 2) % 3] = eps * d3
    ex = free.exact(I, w0)
    W = ex.omega(np.linspace(0, 200, 50))
    H = np.linalg.norm(I * W, axis=1)
    T = 0.5 * np.sum(I * W * W, axis=1)
    H0, T0 = np.linalg.norm(I * w0), 0.5 * np.sum(I * w0 * w0)
    assert np.max(np.abs(H - H0)) <= 2e-14 * H0
    assert np.max(np.abs(T - T0)) <= 2e-14 * T0


def test_ellipj_against_scipy_and_mpmath():
    from scipy.special import ellipj as sj

    from dyncli.topics.euler.free import ellipj

    u = np.linspace(-30, 30, 61)
    for m in (0.1, 0.5, 0.99, 1 - 1e-6):
        got = ellipj(u, m, 1 - m)
        ref = sj(u, m)
        for g, r_ in zip(got, ref[:3]):
            assert np.max(np.abs(g - r_)) < 1e-13
    # m1 = 1e-12, beyond what m alone can carry: mpmath with m1 exact
    with mp.workdps(40):
        m1 = mp.mpf("1e-12")
        for x in (0.5, 5.0, 14.0):
            got = ellipj(np.array([x]), float(1 - m1), 1e-12)
            for g, name in zip(got, ("sn", "cn", "dn")):
                assert abs(float(g[0]) - float(mp.ellipfun(name, x, m=1 - m1))) < 1e-14


def test_applied_moment_axisymmetric_closed_form():
    """M = [0, 0, M3] on an axisymmetric body: ω3 = ω03 + M3 t/I3 and ω1,2 rotate by
    ∫λ dt = (I3 − I1)/I1 (ω03 t + M3 t²/(2 I3)) — a closed form re-derived here."""
    I1, I3, M3, w03 = 2.0, 3.0, 0.5, 1.5
    rec = solve_one_text(f"type: euler\nI: [{I1}, {I1}, {I3}]\nomega0: [1, 0, {w03}]\nM: [0, 0, {M3}]\nat: [0, 1, 4]\n")
    assert rec["method"] == "ode:DOP853"
    for t, w in zip([0, 1, 4], rec["results"]["omega"]):
        ph = (I3 - I1) / I1 * (w03 * t + M3 * t * t / (2 * I3))
        assert w == pytest.approx([math.cos(ph), math.sin(ph), w03 + M3 * t / I3], abs=1e-9)
    assert rec["results"]["drift"] < 1e-9
    assert rec["results"]["T_t"][2] == pytest.approx(0.5 * (I1 + I3 * (w03 + 4 * M3 / I3) ** 2), rel=1e-9)


def test_time_dependent_moment_against_second_integrator():
    rec = solve_one_text("type: euler\nI: [1, 2, 3]\nomega0: [1, 2, 0.5]\nM: [\"0.3*sin(2*t)\", 0, \"-0.1*t\"]\nat: [1, 3]\n")
    ref = scipy_reference([1, 2, 3], [1, 2, 0.5], [1, 3], M=lambda t: np.array([0.3 * math.sin(2 * t), 0, -0.1 * t]))
    assert np.max(np.abs(np.array(rec["results"]["omega"]) - ref)) < 1e-8


def test_projected_conserves_invariants():
    rec = solve_one_text("type: euler\nI: [1, 2, 3]\nomega0: [1, 0.3, 2]\nat: [200]\naccuracy: {method: projected, rtol: 1.0e-6, atol: 1.0e-9}\n")
    assert rec["method"] == "ode:projected-DOP853"
    r = rec["results"]
    assert r["drift"] <= 1e-14
    w = np.array(r["omega"][0])
    I = np.array([1, 2, 3.0])
    w0 = np.array([1, 0.3, 2])
    assert np.linalg.norm(I * w) == pytest.approx(np.linalg.norm(I * w0), rel=1e-14)


def test_ode_route_error_estimate_is_actual_error():
    rec = solve_one_text("type: euler\nI: [1, 2, 3]\nomega0: [1, 0.3, 2]\nat: [10]\naccuracy: {method: RK45, rtol: 1.0e-8}\n")
    from dyncli.topics.euler import free

    ex = free.exact([1, 2, 3], [1, 0.3, 2]).omega(np.array([10.0]))[0]
    err = np.max(np.abs(np.array(rec["results"]["omega"][0]) - ex)) / np.linalg.norm([1, 0.3, 2])
    assert rec["error_estimate"] == pytest.approx(err, rel=1e-6, abs=1e-15)


def test_estimate_second_run():
    rec = solve_one_text("type: euler\nI: [1, 2, 3]\nomega0: [1, 0.3, 2]\nM: [0.1, 0, 0]\nat: [5]\naccuracy: {rtol: 1.0e-6, estimate: true}\n")
    assert 0 < rec["error_estimate"] < 1e-4


def test_rotation_about_principal_axis_and_zero():
    r = solve_one_text("type: euler\nI: [1, 2, 3]\nomega0: [0, 5, 0]\nat: [100]\n")["results"]
    assert r["omega"][0] == [0.0, 5.0, 0.0]           # unstable equilibrium, exactly
    r = solve_one_text("type: euler\nI: [1, 2, 3]\nomega0: [0, 0, 0]\nat: [1]\n")["results"]
    assert r["omega"][0] == [0.0, 0.0, 0.0]


@pytest.mark.parametrize("text,field,msg", [
    ("type: euler\nomega0: [1, 2, 3]\n", None, "exactly one of I"),
    ("type: euler\nI: [1, 1, 3]\nomega0: [1, 2, 3]\n", None, "triangle"),
    ("type: euler\nI: [1, -1, 1]\nomega0: [1, 2, 3]\n", None, "> 0"),
    ("type: euler\ncoin: {m: 1, R: 0.1}\nomega0: [1, 2, 3]\n", None, "h"),
    ("type: euler\nI: [1, 2, 3]\nomega0: [1, 2]\n", "omega0", "3"),
    ("type: euler\nI: [1, 2, 3]\nomega0: [1, 2, 3]\nM: [\"x\", 0, 0]\n", "M", "x"),
    ("type: euler\nI: [1, 2, 3]\nomega0: [1, 2, 3]\nM: [1, 0, 0]\naccuracy: {method: projected}\n", None, "torque-free"),
    ("type: euler\nI: [1, 2, 3]\nomega0: [1, 2, 3]\nM: [1, 0, 0]\naccuracy: {method: closed-form}\n", None, "torque-free"),
])
def test_invalid(text, field, msg):
    err = error_of(text)
    assert err.startswith("bad.yaml:")
    if field:
        line = [i + 1 for i, l in enumerate(text.splitlines()) if l.startswith(field + ":")][0]
        assert err.startswith(f"bad.yaml:{line}:")
    assert msg in err


@settings(max_examples=40, deadline=None)
@given(I=st.lists(st.floats(1.0, 3.0), min_size=3, max_size=3), w=st.lists(st.floats(-3, 3), min_size=3, max_size=3),
       t=st.floats(-50.0, 50.0))
def test_omega_at_one_time_in_floats_is_the_array_path(I, w, t):
    """ω at one float time (the solver's requested times: math only) and at an array of times (the
    plots: numpy) are one algorithm on two backends, whose sin/arcsin may differ by an ulp: the
    Jacobi functions then differ by ~2ε(1 + |λt|) and the addition theorems amplify that by at most
    ~1/m1 (their denominator 1 − m s0² sn² ≥ m1); the bound allows 8 times that (0.4 observed)."""
    from dyncli.topics.euler import free

    if max(I) > I[0] + I[1] + I[2] - max(I) or np.linalg.norm(w) == 0.0:
        return
    ex = free.exact(I, w)
    one = ex.omega(t)
    assert isinstance(one, tuple) and all(type(x) is float for x in one)
    arr = ex.omega(np.array([t]))[0]
    m1 = min(getattr(ex, "m1", 1.0), 1.0)
    if m1 < 1e-6:
        return                           # next to the separatrix: conditioning ~1/m1 (tested above)
    tol = 8 * 2.0 ** -52 * (1 + abs(ex.lam * t)) * np.linalg.norm(w) / m1
    assert np.max(np.abs(np.array(one) - arr)) <= tol
