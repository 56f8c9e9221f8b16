"""The top's exact (elliptic) route against independent references.

* tests/topics/top/exact_reference_data.py: 60-digit mpmath evaluation of the elliptic solution with
  mpmath quadrature for ψ, φ (tests/topics/top/gen_exact_reference.py, a separate implementation);
* the ODE route (method DOP853) of the same problem: each route checks the other;
* the `euler` type for a top without gravity (torque-free body about O);
* the notes' integrals E, H_O·e3 and ω3.

Tolerances: the elliptic route is a closed form evaluated in doubles; its error is a few
hundred ulp (the Carlson integrals, the AGM) times the phase condition number 1 + λt, which is
what its error_estimate states (16 ε (1 + λt + periods)).  1e-12 relative to each quantity's
scale holds for every case with λt ≤ ~1e3; the t = 1e6 s case is held to its error_estimate.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.conftest import solve_one_text, solve_text
from tests.topics.top import reference as ref
from tests.topics.top.exact_reference_data import CASES

NAMES = ("psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot")


def _text(case, times=None, extra=""):
    m, L, A, C, ps, th, ph, psd, thd, phd = case["input"]
    at = case["times"] if times is None else times
    return (f"type: top\nm: {m!r}\nL: {L!r}\nI11: {A!r}\nI33: {C!r}\npsi: {ps!r}\ntheta: {th!r}\nphi: {ph!r}\n"
            f"psi_dot: {psd!r}\ntheta_dot: {thd!r}\nphi_dot: {phd!r}\nat: {at}\n{extra}")


def _errors(rec, rows, wp=0.0):
    """Largest error of each reported quantity relative to its scale over the run (θ̇, ψ̇: at least
    ``wp``, the transverse-rate scale |ω⊥|max the ODE route measures them against)."""
    r = rec["results"]
    out = {}
    for k, name in enumerate(NAMES):
        want = np.array([row[k] for row in rows])
        got = np.array(r[name], dtype=float)
        scale = max(np.max(np.abs(want)), wp if name in ("psi_dot", "theta_dot") else 0.0)
        out[name] = float(np.max(np.abs(got - want)) / scale)
    want = np.array([row[6] for row in rows])
    out["R"] = float(np.max(np.abs(np.array(r["R"]) - want)) / np.max(np.abs(want)))
    return out


@pytest.mark.parametrize("name", [n for n in CASES if n != "long"])
def test_exact_route_matches_the_60_digit_reference(name):
    case = CASES[name]
    rec = solve_one_text(_text(case))
    assert rec["method"] == "exact"
    err = _errors(rec, case["rows"])
    # the phase condition number: λ ≈ ½√(c² + 4β) (c = I33ω3/I11, β = 2mgL/I11) within a factor 2
    m, L, A, C, _, th, _, psd, _, phd = case["input"]
    lam_T = 0.5 * math.hypot(C * (psd * math.cos(th) + phd) / A, math.sqrt(8 * m * 9.81 * L / A)) * max(case["times"])
    assert max(err.values()) <= 1e-12 * max(1.0, lam_T / 1e3), (lam_T, err)
    assert rec["error_estimate"] >= max(err.values()), (rec["error_estimate"], err)
    r = rec["results"]
    assert r["theta_min"] == pytest.approx(case["theta_min"], rel=1e-13)
    assert r["theta_max"] == pytest.approx(case["theta_max"], rel=1e-13)
    assert r["drift"] < 1e-13


def test_exact_route_at_one_million_seconds():
    case = CASES["long"]
    rec = solve_one_text(_text(case))
    err = _errors(rec, case["rows"])
    # the phase λt ~ 1.5e7 rad is formed in doubles: ~ε λt, which error_estimate states
    assert max(err.values()) <= rec["error_estimate"] <= 1e-7, (rec["error_estimate"], err)


@pytest.mark.slow      # the ODE route: ~530 nutation periods, a run and its check solve (~3 s CPU)
def test_issue_top_rates_on_both_routes():
    # m 0.5, L 0.04, I11 1.2e-3, I33 4e-4, θ 1, φ̇ 5000, rtol 1e-8: θ̇(2 s) = 0.0089363826 (elliptic)
    case = CASES["spin5000"]
    for method in ("auto", "DOP853"):
        rec = solve_one_text(_text(case, extra=f"accuracy: {{rtol: 1.0e-8, method: {method}, estimate: true}}\n"))
        err = _errors(rec, case["rows"])          # θ̇ relative to its own largest value at the times
        if method == "auto":
            assert max(err.values()) <= 1e-8, (method, err)
            assert rec["results"]["theta_dot"][-1] == pytest.approx(0.0089363826, abs=5e-11)    # 8 digits quoted
        # the ODE's global error grows with the ~530 nutation periods (~600 rtol here): the check solve says so
        assert rec["error_estimate"] >= 0.9 * max(err.values()), (method, rec["error_estimate"], err)


@pytest.mark.parametrize("estimate", [False, True])
def test_ode_and_exact_routes_check_each_other(estimate):
    case = CASES["nutating"]
    ex = solve_one_text(_text(case))
    ode = solve_one_text(_text(case, extra=f"accuracy: {{rtol: 1.0e-10, method: DOP853, estimate: {str(estimate).lower()}}}\n"))
    assert ode["method"] == "ode:DOP853"
    rows = [[ex["results"][n][i] for n in NAMES] + [ex["results"]["R"][i]] for i in range(len(case["times"]))]
    err = max(_errors(ode, rows).values())
    if estimate:        # the check solve at rtol/100: its own error is ~1/60 of the reported run's
        assert 0.9 * err <= ode["error_estimate"] <= 1.5 * err, (ode["error_estimate"], err)
    else:               # one solve over ~11 nutation periods: within the stated 10 x rtol of the nominal estimate
        assert err <= ode["error_estimate"] and err <= 10 * 1e-10, (ode["error_estimate"], err)


def test_sleeping_top():
    rec = solve_one_text("type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\npsi: 0.4\nphi: 0.1\nphi_dot: 200\n"
                         "at: [0, 1, 1000000]\n")
    r = rec["results"]
    assert rec["method"] == "exact"
    assert r["theta"] == [0.0, 0.0, 0.0] and r["psi"] == [0.4, 0.4, 0.4]
    assert r["phi"] == pytest.approx([0.1, 200.1, 0.1 + 2e8], rel=1e-15)
    assert r["psi_dot"] == [None] * 3 and r["theta_dot"] == [0.0] * 3
    assert r["theta_min"] == 0.0 and r["theta_max"] == 0.0
    assert any("sleeping top" in w for w in rec["warnings"])
    # R = mg e3 on e'' (no acceleration of the center of mass)
    assert np.allclose(r["R"], [[0.0, 0.0, 0.5 * 9.81]] * 3, rtol=1e-15, atol=1e-15)


def test_steady_precession_has_zero_nutation_amplitude():
    A, C, m, L, th, p = 2.0e-3, 1.0e-3, 0.5, 0.05, 0.7, 60.0
    Om = ref.slow_root_mp(m, L, A, C, 9.81, th, p)
    rec = solve_one_text(f"type: top\nm: {m}\nL: {L}\nI11: {A}\nI33: {C}\ntheta: {th}\npsi_dot: {Om!r}\n"
                         f"phi_dot: {p}\nat: [1, 1000, 1000000]\n")
    r = rec["results"]
    # ψ̇ = Ω rounded to a double: the nutation amplitude is round-off (the roots of the cubic merge)
    assert np.max(np.abs(np.array(r["theta"]) - th)) <= 4e-16
    assert np.max(np.abs(r["theta_dot"])) <= 1e-15 * Om
    assert r["psi"] == pytest.approx([Om, 1e3 * Om, 1e6 * Om], rel=1e-13)
    assert r["theta_min"] == pytest.approx(th, abs=4e-16) and r["theta_max"] == pytest.approx(th, abs=4e-16)


def test_torque_free_limit_agrees_with_euler():
    # g = 0: the top is a torque-free axisymmetric body about O; body ω from the Euler angles
    A, C, th, thd, psd, phd, ph = 2.0e-3, 1.0e-3, 0.8, 0.6, 3.0, 25.0, 0.3
    ts = [0.1, 0.7, 2.0]
    rec = solve_one_text(f"type: top\nm: 0.5\nL: 0.05\nI11: {A}\nI33: {C}\ng: 0\ntheta: {th}\ntheta_dot: {thd}\n"
                         f"psi_dot: {psd}\nphi: {ph}\nphi_dot: {phd}\nat: {ts}\n")
    r = rec["results"]

    def body(th_, thd_, psd_, phd_, ph_):
        o1, o2, o3 = thd_, psd_ * math.sin(th_), psd_ * math.cos(th_) + phd_
        return [o1 * math.cos(ph_) + o2 * math.sin(ph_), -o1 * math.sin(ph_) + o2 * math.cos(ph_), o3]

    w0 = body(th, thd, psd, phd, ph)
    eu = solve_one_text(f"type: euler\nI: [{A}, {A}, {C}]\nomega0: {w0}\nat: {ts}\n")
    for i in range(len(ts)):
        w = body(r["theta"][i], r["theta_dot"][i], r["psi_dot"][i], r["phi_dot"][i], r["phi"][i])
        assert np.allclose(w, eu["results"]["omega"][i], rtol=0, atol=1e-12 * np.linalg.norm(w0))


@pytest.mark.parametrize("I33,phd", [(3.14159, 50.0), (2.0e-9, 3.0e5), (1.0e-3, 1.0e6), (1.0e-3, -1.0e6)])
def test_extreme_tops_keep_the_integrals_at_any_time(I33, phd):
    # strongly oblate (the ODE route refuses it at t = 0.5 s), nearly a rod spinning fast, 1e6 rad/s either way
    m, L, A, g = 0.5, 0.05, 2.0e-3, 9.81
    th, thd, psd = 0.3, -2.0, 16.918
    rec = solve_one_text(f"type: top\nm: {m}\nL: {L}\nI11: {A}\nI33: {I33}\ntheta: {th}\ntheta_dot: {thd}\n"
                         f"psi_dot: {psd}\nphi_dot: {phd}\nat: [0.5, 1000, 1000000]\n")
    r = rec["results"]
    E0, H0, W0 = ref.invariants(A, I33, m * g * L, th, thd, psd, phd)
    w2 = thd ** 2 + psd ** 2
    Es, Hs = 0.5 * A * w2 + 0.5 * I33 * W0 ** 2 + m * g * L, A * math.sqrt(w2) + abs(I33 * W0)
    for k in range(3):
        E, H, W = ref.invariants(A, I33, m * g * L, r["theta"][k], r["theta_dot"][k], r["psi_dot"][k], r["phi_dot"][k])
        assert abs(E - E0) <= 1e-12 * Es and abs(H - H0) <= 1e-12 * Hs
        assert r["theta_min"] - 1e-15 <= r["theta"][k] <= r["theta_max"] + 1e-15
    assert 0 < rec["error_estimate"] < 1.0      # ε·λt: up to ~1e-4 at λt ~ 1e11 rad (oblate, t = 1e6 s)


def test_pendulum_through_the_bottom_jumps_by_pi():
    # no spin, released at θ = π with θ̇: the axis passes through θ = π every swing (B' = 0)
    txt = "type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\ntheta: 3.141592653589793\ntheta_dot: 1.0\n"
    ts = [0.1, 0.4, 0.9, 1.7]
    ex = solve_one_text(txt + f"at: {ts}\n")
    ode = solve_one_text(txt + f"at: {ts}\naccuracy: {{rtol: 1.0e-11, method: DOP853}}\n")
    for n in ("theta", "theta_dot"):
        assert np.allclose(ex["results"][n], ode["results"][n], rtol=0, atol=1e-8), n
    # the orientation: ψ − φ (θ next to π) agrees modulo 2π
    d = [(a - b) - (c - e) for a, b, c, e in zip(ex["results"]["psi"], ex["results"]["phi"],
                                                 ode["results"]["psi"], ode["results"]["phi"])]
    assert all(abs(math.remainder(x, 2 * math.pi)) < 1e-7 for x in d)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(th=st.floats(0.05, math.pi - 0.05), thd=st.floats(-5, 5), psd=st.floats(-10, 10),
       phd=st.floats(-300, 300), ratio=st.floats(0.05, 1.95))
def test_random_tops_exact_and_ode_agree(th, thd, psd, phd, ratio):
    # each route checks the other: the ODE (DOP853, rtol 1e-9, check solve) within its own error_estimate of the exact
    # route, every quantity relative to its scale (ψ̇, φ̇ only away from the vertical, where they are defined)
    A, C = 2.0e-3, ratio * 1.0e-3
    txt = (f"type: top\nm: 0.5\nL: 0.05\nI11: {A}\nI33: {C!r}\ntheta: {th!r}\ntheta_dot: {thd!r}\n"
           f"psi_dot: {psd!r}\nphi_dot: {phd!r}\nat: [0.05, 0.13, 0.2]\n")
    ex = solve_one_text(txt)
    ode = solve_one_text(txt + "accuracy: {rtol: 1.0e-9, method: DOP853, estimate: true}\n")
    re_, ro = ex["results"], ode["results"]
    if min(re_["theta_min"], math.pi - re_["theta_max"]) < 1e-2:
        return          # ψ, φ individually ill-conditioned next to the vertical (the docs say so)
    tol = ode["error_estimate"] + ex["error_estimate"]
    wp = ref.wperp_max(0.5, 0.05, A, 9.81, th, thd, psd, re_["theta_max"])   # the ODE's scale of θ̇, ψ̇
    for name in NAMES + ("R",):
        a, b = np.array(re_[name], dtype=float), np.array(ro[name], dtype=float)
        scale = max(np.max(np.abs(a)), wp if name in ("psi_dot", "theta_dot") else 0.0)
        assert np.max(np.abs(a - b)) <= 3 * tol * scale + 1e-300, (name, tol)


# rates of 1e-30 rad/s and more (smaller ones square to energies near the underflow of doubles)
RATE = st.floats(-100, 100).filter(lambda x: x == 0 or abs(x) >= 1e-30)


@settings(max_examples=300, deadline=None)
@given(A=st.floats(1e-4, 1.0), ratio=st.floats(1e-6, 2.0), mgL=st.one_of(st.just(0.0), st.floats(1e-8, 10.0)),
       th=st.one_of(st.sampled_from([0.0, math.pi, 1e-9, math.pi - 1e-9]), st.floats(1e-12, math.pi - 1e-12)),
       thd=st.one_of(st.just(0.0), RATE), psd=st.one_of(st.just(0.0), RATE),
       phd=st.one_of(st.just(0.0), st.floats(-1e6, 1e6).filter(lambda x: x == 0 or abs(x) >= 1e-30)),
       t=st.floats(0.0, 1e6))
def test_elliptic_solution_keeps_the_integrals_at_the_extremes(A, ratio, mgL, th, thd, psd, phd, t):
    # the elliptic solution itself (no CLI), over oblate/prolate, fast/slow, poles, torque-free, any t:
    # finite, θ within its bounds, E and H_O·e3 kept to 1e-9 of their scales (the phase may be ~ε λt off,
    # the integrals are not)
    from dyncli.topics.top.elliptic import ExactTop

    C = ratio * A
    ex = ExactTop(A, C, mgL, 0.1, th, 0.2, psd, thd, phd)
    psi, theta, phi, psid, thdot, phid, S = (float(x[0]) for x in ex.evaluate(np.array([t])))
    if not all(math.isfinite(x) for x in (psi, theta, phi, thdot, S)):
        # beyond doubles (1 − m underflows): the solver falls back to the ODE route (tested above); only
        # next to a pole and the separatrix
        assert min(ex.nut.v2, ex.nut.w1) < 1e-100 or ex.nut.m1 < 1e-100
        return
    n = ex.nut
    assert n.theta_min - 1e-12 <= theta <= n.theta_max + 1e-12 or ex.steady
    E0, H0, W0 = ref.invariants(A, C, mgL, th, thd, psd, phd)
    w2 = thd ** 2 + (psd * math.sin(th)) ** 2 + 4 * mgL / A
    Es, Hs = 0.5 * A * w2 + 0.5 * C * W0 ** 2 + mgL, A * math.sqrt(w2) + abs(C * W0)
    E = 0.5 * A * (thdot ** 2 + S ** 2) + 0.5 * C * W0 ** 2 + mgL * math.cos(theta)
    H = A * S * math.sin(theta) + C * W0 * math.cos(theta)
    assert abs(E - E0) <= 1e-9 * Es + 1e-300 and abs(H - H0) <= 1e-9 * Hs + 1e-300     # (subnormal scales)


def test_beyond_doubles_falls_back_to_the_ode_route():
    # released 2e-154 rad from an unstable vertical: 1 − m ~ 1e-308 is subnormal, K and the Carlson
    # integrals are not representable (down to ~1e-153 rad they are: dyncli.elliptic rescales them)
    txt = ("type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\ntheta: 2.0e-154\nphi_dot: 20\n"
           "at: [0.5]\n")
    rec = solve_one_text(txt)
    assert rec["method"] == "ode:DOP853" and any("not representable" in w for w in rec["warnings"])
    rec = solve_text(txt + "accuracy: {method: exact}\n")[0]
    assert rec["exit_code"] == 1 and "accuracy.method DOP853" in rec["error"]


def test_a_top_whose_nutation_roots_do_not_separate_is_not_representable():
    """θ0 = 7.9e-31 rad with ω3 = 0 (and I33 = 0, below what a problem file admits): the cubic's
    root search cannot converge in doubles; the exact run says 'not representable' (the solver
    then takes the ODE route, or refuses under method: exact) instead of an internal error."""
    from types import SimpleNamespace

    from dyncli.topics.top.exact_route import ExactRun

    run = ExactRun(SimpleNamespace(A=1.0, C=0.0, mgL=1.0), 0.0, 7.888609052210118e-31, 0.0, 1.0, 1.0, -1.0,
                   [0.1])
    assert run.finite is False


def test_nutation_roots_of_a_top_1e_73_rad_from_the_vertical():
    """Issue #28: θ0 = 2.75e-73 with a1 cancelling to 0 made a2·F0 underflow (q = 0: a
    ZeroDivisionError in the roots of Q).  The roots x = u − u0 of f(x) = βx³ + F2x² + F1x + F0
    bounding the motion against mpmath (60 digits, the cubic formed from the same inputs)."""
    import mpmath as mp

    from dyncli.topics.top.elliptic import Nutation

    A, C, mgL, th, thd, psid, w3 = (2.1576085370698745, 4.315217074139749, 9.51164030999553, 2.75e-73,
                                    -2.5568523488869783e-44, -2.3665084547986442e-20, 0.0)
    n = Nutation(A, C, mgL, th, thd, psid, w3)
    assert n.finite
    with mp.workdps(60):
        s0, u0 = mp.sin(mp.mpf(th)), mp.cos(mp.mpf(th))
        K = mp.mpf(thd) ** 2 + (mp.mpf(psid) * s0) ** 2
        P, beta, c = mp.mpf(psid) * s0 * s0, 2 * mp.mpf(mgL) / mp.mpf(A), mp.mpf(C) * w3 / mp.mpf(A)
        F = [beta, 2 * beta * u0 - K - c * c, -beta * s0 * s0 - 2 * u0 * K + 2 * c * P, (mp.mpf(thd) * s0) ** 2]
        f = lambda x: ((F[0] * x + F[1]) * x + F[2]) * x + F[3]    # noqa: E731
        # the two roots next to x = 0 (u0): x1 < 0 < x2, sign changes of f bracket them
        x2 = mp.findroot(f, (mp.mpf(0), mp.mpf(n.x2) * 2), solver="anderson") if n.x2 > 0 else mp.mpf(0)
        x1 = mp.findroot(f, (mp.mpf(n.x1) * 2, mp.mpf(0)), solver="anderson") if n.x1 < 0 else mp.mpf(0)
    assert n.x1 == pytest.approx(float(x1), rel=1e-12) and n.x2 == pytest.approx(float(x2), rel=1e-12)
