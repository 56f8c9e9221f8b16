"""The top integrator: steady precession kept, bounds vs the sampled trajectory,
conservation, the accuracy methods, error estimates and Table 38.1."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import solve_one_text
from tests.topics.top import reference as ref

M, L, A, C, G = 0.5, 0.05, 2.0e-3, 1.0e-3, 9.81
HEAD = "type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\n"


@pytest.mark.parametrize("method", ["auto", "projected"])
def test_steady_precession_kept_10s(method):
    th, p = 0.7, 60.0
    Om = ref.slow_root_mp(M, L, A, C, G, th, p)      # slow root of (38.22), 50 digits
    ts = [float(k) for k in range(11)]
    rec = solve_one_text(HEAD + f"theta: {th}\npsi_dot: {Om!r}\nphi_dot: {p}\nat: {ts}\n"
                         f"accuracy: {{rtol: 1.0e-13, atol: 1.0e-15, method: {method}}}\n")
    r = rec["results"]
    assert np.max(np.abs(np.array(r["theta"]) - th)) < 2e-12
    assert np.max(np.abs(np.array(r["theta_dot"]))) < 1e-10
    assert np.allclose(r["psi"], Om * np.array(ts), rtol=1e-11, atol=1e-11)
    assert r["theta_min"] == pytest.approx(th, abs=1e-13) and r["theta_max"] == pytest.approx(th, abs=1e-13)
    if method == "projected":
        assert rec["method"] == "ode:DOP853+projection"
        assert r["drift"] < 1e-14


def _sampled(th, thd, psd, phd, T=1.0, n=2001, extra=""):
    ts = [round(T * k / (n - 1), 12) for k in range(n)]
    rec = solve_one_text(HEAD + f"theta: {th}\ntheta_dot: {thd}\npsi_dot: {psd}\nphi_dot: {phd}\nat: {ts}\n" + extra)
    return rec, np.array(rec["results"]["theta"])


@pytest.mark.parametrize("state", [
    (0.5, 0.0, 0.0, 100.0),       # released with spin: θ0 is the upper bound
    (1.2, 1.5, -2.0, 40.0),       # general
    (2.5, -0.5, 3.0, 30.0),       # below the horizontal
    (1.0, 0.0, 0.0, 0.0),         # no spin: a spherical pendulum swinging through θ = π
])
def test_bounds_vs_sampled_extremes(state):
    rec, theta = _sampled(*state)
    r = rec["results"]
    lo, hi = ref.bounds_mp(M, L, A, C, G, *state)
    assert r["theta_min"] == pytest.approx(lo, abs=1e-12)
    assert r["theta_max"] == pytest.approx(hi, abs=1e-12)
    # the sampled trajectory stays inside and reaches both bounds (sampling at 0.5 ms)
    assert theta.min() >= lo - 1e-9 and theta.max() <= hi + 1e-9
    assert theta.min() - lo < 2e-3 * (hi - lo) + 1e-12
    assert hi - theta.max() < 2e-3 * (hi - lo) + 1e-12


def _energy(r, k):
    th, thd, psd, phd = r["theta"][k], r["theta_dot"][k], r["psi_dot"][k], r["phi_dot"][k]
    return ref.invariants(A, C, M * G * L, th, thd, psd, phd)


@pytest.mark.parametrize("method", ["auto", "DOP853", "RK45", "Radau", "LSODA", "projected"])
def test_methods_conserve_and_agree(method):
    state = (1.2, 1.5, -2.0, 40.0)
    ts = [0, 0.1, 0.3]
    rec = solve_one_text(HEAD + f"theta: 1.2\ntheta_dot: 1.5\npsi_dot: -2\nphi_dot: 40\nat: {ts}\n"
                         f"accuracy: {{rtol: 1.0e-9, atol: 1.0e-11, method: {method}}}\n")
    r = rec["results"]
    Y = ref.euler_angle_ode(M, L, A, C, G, [0.0, 1.2, 0.0, -2.0, 1.5, 40.0], ts)
    for name, col in (("psi", 0), ("theta", 1), ("phi", 2)):
        assert np.max(np.abs(np.array(r[name]) - Y[:, col])) < 2e-6, name
    E0 = ref.invariants(A, C, M * G * L, state[0], state[1], state[2], state[3])
    for k in range(len(ts)):
        E = _energy(r, k)
        assert E[0] == pytest.approx(E0[0], rel=1e-6)
        assert E[1] == pytest.approx(E0[1], rel=1e-6, abs=1e-9)
        assert E[2] == pytest.approx(E0[2], rel=1e-9)
    assert 0 <= r["drift"] < 1e-6
    assert rec["error_estimate"] is not None and 0 < rec["error_estimate"] < 1e-4
    want = {"auto": "exact", "projected": "ode:DOP853+projection"}.get(method, f"ode:{method}")
    assert rec["method"] == want


def test_projection_conserves_long_run():
    txt = HEAD + "theta: 1.2\ntheta_dot: 1.5\npsi_dot: -2\nphi_dot: 40\nat: [20]\n"
    plain = solve_one_text(txt + "accuracy: {rtol: 1.0e-6, atol: 1.0e-8, method: DOP853}\n")["results"]["drift"]
    proj = solve_one_text(txt + "accuracy: {rtol: 1.0e-6, atol: 1.0e-8, method: projected}\n")["results"]["drift"]
    assert proj < 1e-14
    assert plain > 100 * proj


def test_error_estimate_default_and_tight():
    txt = HEAD + "theta: 0.5\nphi_dot: 100\nat: [0, 0.5, 1]\n"
    default = solve_one_text(txt + "accuracy: {rtol: 1.0e-7, method: DOP853}\n")
    tight = solve_one_text(txt + "accuracy: {rtol: 1.0e-7, estimate: true, method: DOP853}\n")
    Y = ref.euler_angle_ode(M, L, A, C, G, [0.0, 0.5, 0.0, 0.0, 0.0, 100.0], [0, 0.5, 1])

    def err(rec):      # each quantity relative to its own scale at the times (the estimate's contract, §9)
        return max(np.max(np.abs(np.array(rec["results"][n]) - Y[:, c])) / np.max(np.abs(Y[:, c]))
                   for n, c in (("psi", 0), ("theta", 1), ("phi", 2), ("psi_dot", 3), ("theta_dot", 4), ("phi_dot", 5)))
    # the check solve at rtol/100 has ~1/60 of the reported run's error (DOP853: error ~ tol^(7/8)), so their
    # difference is 0.98-1.02 times the error (R is covered too; here ψ̇, θ̇ dominate)
    assert 0.9 * err(tight) <= tight["error_estimate"] <= 1.5 * err(tight)
    # one solve by default: the nominal estimate (rtol x the steps, or the energy's drift when larger) bounds
    # the error of this two-nutation-period run
    assert err(default) <= default["error_estimate"] and default["error_estimate"] >= max(1e-7, default["results"]["drift"])
    assert "nominal" in default["error_estimate_note"] if "error_estimate_note" in default else True
    none = solve_one_text(HEAD + "theta: 0.5\nphi_dot: 100\nat: [0]\n")
    assert none["error_estimate"] == 0.0


def test_unsorted_and_repeated_times():
    rec = solve_one_text(HEAD + "theta: 0.5\nphi_dot: 100\nat: [1, 0.5, 1, 0]\n")
    r = rec["results"]
    assert r["theta"][0] == r["theta"][2] and r["psi"][3] == 0.0 and r["theta"][3] == 0.5
    Y = ref.euler_angle_ode(M, L, A, C, G, [0.0, 0.5, 0.0, 0.0, 0.0, 100.0], [0.5, 1])
    assert r["phi"][1] == pytest.approx(Y[0, 2], rel=1e-9)
    assert r["phi"][0] == pytest.approx(Y[1, 2], rel=1e-9)


def test_theta_outside_range_is_normalised():
    rec = solve_one_text(HEAD + "theta: -0.5\ntheta_dot: 0.3\nphi_dot: 100\nat: [0, 0.2]\n")
    r = rec["results"]
    assert r["theta"][0] == 0.5 and r["psi"][0] == pytest.approx(math.pi) and r["phi"][0] == pytest.approx(math.pi)
    assert r["theta_dot"][0] == pytest.approx(-0.3)
    assert any("outside [0, π]" in w for w in rec["warnings"])


def test_table_38_1_view():
    from dyncli.loader import split_problems, validate
    from dyncli.run import solve_one

    text = HEAD + "theta: 1.2\ntheta_dot: 1.5\npsi_dot: -2\nphi_dot: 40\nat: [0.1, 0.3]\n"
    (lp,), diags = split_problems("t.yaml", text.encode(), None)
    validate(lp)
    out = solve_one(lp)
    res = out.result
    (tab,) = [v for v in res.views if v.title.startswith("Table 38.1")]
    rows = dict(tab.rows)
    assert tab.basis == ("e''₁", "e''₂", "e''₃")
    r = res.results
    th = r["theta"][0]
    # Ḣ = M_O = mgL sinθ e''1 (38.17c); R = mg e3 + m ā (38.16a)
    assert np.allclose(rows["Ḣ_O"], [M * G * L * math.sin(th), 0, 0], atol=1e-9)
    a = np.array(rows["ā"])
    R = M * G * np.array([0, math.sin(th), math.cos(th)]) + M * a
    assert np.allclose(R, r["R"][0], rtol=1e-9, atol=1e-9)
    assert np.allclose(rows["v̄"], np.cross(rows["Ω"], rows["x̄"]))
    assert rows["x̄"] == [0.0, 0.0, L]
    # second independent check of Ω and H from the Euler-angle reference
    Y = ref.euler_angle_ode(M, L, A, C, G, [0.0, 1.2, 0.0, -2.0, 1.5, 40.0], [0.1])
    ps, th_, ph, psd, thd, phd, psdd, thdd = Y[0]
    assert np.allclose(rows["Ω"], [thd, psd * math.sin(th_), psd * math.cos(th_)], rtol=1e-7)
    assert np.allclose(rows["H_O"], [A * thd, A * psd * math.sin(th_), C * (psd * math.cos(th_) + phd)], rtol=1e-7)
    assert np.allclose(rows["δH_O/δt"][:1], [A * thdd], rtol=1e-6)


_RELEASED = {}


@pytest.mark.parametrize("estimate", [False, True])
@pytest.mark.parametrize("rtol", [1e-6, 1e-8, 1e-10])
def test_error_estimate_is_honest_against_the_elliptic_solution(rtol, estimate):
    # released at rest in θ, ψ with spin: θ(t) by Jacobi sn², ψ, φ by quadrature (mpmath, tests/topics/top/reference.py)
    ts = [0.1, 0.5]
    if not _RELEASED:
        _RELEASED["ref"] = np.array(ref.released_top_mp(M, L, A, C, G, 0.5, 100.0, ts, rates=True))
    est = "true" if estimate else "false"
    rec = solve_one_text(HEAD + f"theta: 0.5\nphi_dot: 100\nat: {ts}\n"
                         f"accuracy: {{rtol: {rtol}, method: DOP853, estimate: {est}}}\n")
    r = rec["results"]
    Y = _RELEASED["ref"]
    # every reported quantity relative to its scale over the requested times (docs/accuracy.md)
    err = max(np.max(np.abs(np.array(r[n]) - Y[:, j])) / np.max(np.abs(Y[:, j]))
              for j, n in enumerate(("psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot")))
    assert err > 1e-13
    if estimate:       # the check solve at rtol/100 measures the error (its own is ~1/60 of it)
        assert 0.9 <= rec["error_estimate"] / err <= 1.5, (rec["error_estimate"], err)
    else:              # one solve: the nominal estimate (rtol x the steps) bounds the error; ~2 periods: within 3 rtol
        assert err <= rec["error_estimate"] and rec["error_estimate"] >= rtol, (rec["error_estimate"], err)
        assert err <= 3 * rtol, err


def test_error_estimate_falls_back_to_a_looser_run_over_budget():
    # the main run (~270 steps) fits max_steps: 300, the check solve at rtol/100 (~500) does not
    rec = solve_one_text(HEAD + "theta: 0.5\nphi_dot: 100\nat: [0, 2]\n"
                         "accuracy: {max_steps: 300, method: DOP853, estimate: true}\n")
    assert rec["error_estimate"] > 0
    assert any("10·rtol" in w and "accuracy.max_steps" in w for w in rec["warnings"])


def test_bounds_with_a_subnormal_gravity_moment():
    # mgL = 2.5e-318: the cubic's leading coefficient overflows numpy.roots' companion matrix; the
    # root it belongs to is far outside u ∈ [-1, 1], so the bounds are those of the torque-free body
    rec = solve_one_text("type: top\nm: 5.0e-17\nL: 5.0e-302\nI11: 0.002\nI33: 1.0e-153\ntheta: 0.3\n"
                         "theta_dot: -2\npsi_dot: 16.918\nphi_dot: 5.0e-149\nat: [0, 0.1]\n")
    lo, hi = ref.bounds_mp(5e-17, 5e-302, 0.002, 1e-153, 9.81, 0.3, -2, 16.918, 5e-149)
    assert rec["results"]["theta_min"] == pytest.approx(lo, rel=1e-10)
    assert rec["results"]["theta_max"] == pytest.approx(hi, rel=1e-10)
