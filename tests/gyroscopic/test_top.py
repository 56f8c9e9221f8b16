"""top (§38): steady precession kept, nutation bounds from an independent cubic
(mpmath), a second integrator in Euler angles (38.18), passage near the vertical
checked against a direction-cosine integration, invalid input."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import Phase, given, settings, strategies as st

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

M_, L_, I11, I33, G = 0.5, 0.05, 0.006, 0.002, 9.81


def cubic_bounds(m, L, i11, i33, th0, psid, thd, phid, g=9.81):
    """Turning points of u = cos θ: roots of (1−u²)(α − βu) − (a − bu)² (textbook form, mpmath)."""
    with mp.workdps(40):
        th0, psid, thd, phid, m, L, i11, i33, g = (mp.mpf(x) for x in (th0, psid, thd, phid, m, L, i11, i33, g))
        u0 = mp.cos(th0)
        w3 = psid * u0 + phid
        E = (mp.mpf(i11) * (thd**2 + psid**2 * mp.sin(th0) ** 2) + mp.mpf(i33) * w3**2) / 2 + m * g * L * u0
        Hz = mp.mpf(i11) * psid * mp.sin(th0) ** 2 + mp.mpf(i33) * w3 * u0
        al = (2 * E - i33 * w3**2) / i11
        be = 2 * mp.mpf(m) * g * L / i11
        a, b = Hz / i11, i33 * w3 / i11
        # f(u) = β u³ − (α + b²) u² + (2ab − β) u + (α − a²)
        coeffs = [be, -(al + b * b), 2 * a * b - be, al - a * a]
        while coeffs and abs(coeffs[0]) * 8 <= mp.mpf(10) ** -30 * sum(abs(x) for x in coeffs[1:]):
            coeffs = coeffs[1:]         # a negligible cubic term (L → 0)
        if len(coeffs) < 2:
            return float(th0), float(th0)          # f ≡ 0: the top does not move
        roots = mp.polyroots(coeffs, maxsteps=200, extraprec=200)
        real = sorted(mp.re(r) for r in roots if abs(mp.im(r)) < mp.mpf(10) ** -20)
        f = lambda u: (1 - u * u) * (al - be * u) - (a - b * u) ** 2
        pts = [mp.mpf(-1)] + [r for r in real if -1 < r < 1] + [mp.mpf(1)]
        for lo, hi in zip(pts, pts[1:]):
            if lo - mp.mpf(10) ** -25 <= u0 <= hi + mp.mpf(10) ** -25 and hi - lo > mp.mpf(10) ** -25 and f((lo + hi) / 2) > 0:
                return float(mp.acos(hi)), float(mp.acos(lo))
        return float(th0), float(th0)     # a double root at u0: steady precession


def euler_angle_reference(th0, psid, thd, phid, times, m=M_, L=L_, i11=I11, i33=I33, g=G):
    """(38.18) integrated directly in ψ, θ, φ (valid away from sin θ = 0)."""
    from scipy.integrate import solve_ivp

    mgL = m * g * L
    w3 = psid * math.cos(th0) + phid

    def f(t, y):
        ps, th, ph, pd, td, fd = y
        s, c = math.sin(th), math.cos(th)
        tdd = pd * pd * s * c - i33 / i11 * pd * s * w3 + mgL * s / i11
        pdd = (i33 * w3 * td - 2 * i11 * pd * td * c) / (i11 * s)
        fdd = -(pdd * c - pd * td * s)
        return [pd, td, fd, pdd, tdd, fdd]

    sol = solve_ivp(f, (0, max(times)), [0, th0, 0, psid, thd, phid], method="DOP853", rtol=1e-12, atol=1e-13,
                    t_eval=times)
    return sol.y.T


def test_steady_precession_kept():
    text = (PROBLEMS / "gyroscopic" / "top-steady.yaml").read_text()
    text = text.replace("at: [0, 5, 10]", "at: [0, 2.5, 5, 7.5, 10]\naccuracy: {rtol: 1.0e-12, atol: 1.0e-14}")
    r = solve_one_text(text)["results"]
    Om = 0.6164156212957234
    assert max(abs(t - math.pi / 6) for t in r["theta"]) < 2e-12
    assert r["theta_min"] == pytest.approx(math.pi / 6, abs=1e-12)
    assert r["theta_max"] == pytest.approx(math.pi / 6, abs=1e-12)
    for t, ps, ph in zip([0, 2.5, 5, 7.5, 10], r["psi"], r["phi"]):
        assert ps == pytest.approx(Om * t, abs=1e-9)
        assert ph == pytest.approx(200 * t, abs=1e-8)        # continuous, not wrapped
    s, c = 0.5, math.sqrt(3) / 2
    for R in r["R"]:                                           # (38.20)
        assert R == pytest.approx([0, M_ * (G * s + L_ * Om**2 * s * c), M_ * (G * c - L_ * Om**2 * s * s)], abs=1e-8)


def test_nutating_top_example():
    rec = solve_path(PROBLEMS / "gyroscopic" / "top-nutating.yaml")[0]
    r = rec["results"]
    tmin, tmax = cubic_bounds(M_, L_, I11, I33, math.pi / 6, 0.0, 0.0, 200.0)
    assert r["theta_min"] == pytest.approx(tmin, abs=1e-12)
    assert r["theta_max"] == pytest.approx(tmax, rel=1e-11)
    times = [0, 0.05, 0.1, 1, 2]
    ref = euler_angle_reference(math.pi / 6, 0.0, 0.0, 200.0, times)
    for key, col in (("psi", 0), ("theta", 1), ("phi", 2), ("psi_dot", 3), ("theta_dot", 4), ("phi_dot", 5)):
        assert np.max(np.abs(np.array(r[key]) - ref[:, col])) < 1e-7 * max(1.0, np.max(np.abs(ref[:, col]))), key
    assert all(tmin - 1e-9 <= t <= tmax + 1e-9 for t in r["theta"])
    assert r["drift"] < 1e-9


@pytest.mark.parametrize("offset", [0.0, 1e-3])
def test_passing_near_vertical_is_continuous_and_correct(offset):
    """H·e3 ≈ I33 ω3: the axis passes through (offset 0) or next to the vertical, where 3-1-3 breaks
    down; the quaternion route does not.  Compare the axis with a direction-cosine integration."""
    from scipy.integrate import solve_ivp

    th0, thd0, phid0 = 0.3, -3.0, 20.0
    k, c0, s0 = I33 / I11, math.cos(0.3), math.sin(0.3)
    psid0 = k * phid0 * (1 - c0) / (s0 * s0 - k * c0 * (1 - c0)) * (1 + offset)
    times = np.linspace(0, 1.0, 41)
    rec = solve_one_text(f"type: top\nm: {M_}\nL: {L_}\nI11: {I11}\nI33: {I33}\ntheta: {th0}\ntheta_dot: {thd0}\n"
                         f"phi_dot: {phid0}\npsi_dot: {psid0}\nat: {times.tolist()}\n")
    r = rec["results"]
    ps, th = np.array(r["psi"]), np.array(r["theta"])
    axis = np.stack([np.sin(ps) * np.sin(th), -np.cos(ps) * np.sin(th), np.cos(th)], axis=1)
    # reference: rotation matrix (9) + body ω (3)
    Ib = np.array([I11, I11, I33])
    mgL = M_ * G * L_

    def f(t, y):
        Rm = y[:9].reshape(3, 3)
        w = y[9:]
        n = Rm[2, :]
        Mb = mgL * np.array([n[1], -n[0], 0.0])
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([(Rm @ W).ravel(), (Mb - np.cross(w, Ib * w)) / Ib])

    s, c = math.sin(th0), math.cos(th0)
    R0 = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    w0 = np.array([thd0, psid0 * s, psid0 * c + phid0])
    sol = solve_ivp(f, (0, 1.0), np.concatenate([R0.ravel(), w0]), method="DOP853", rtol=1e-12, atol=1e-13, t_eval=times)
    ref_axis = sol.y[:9].T.reshape(-1, 3, 3)[:, :, 2]
    assert np.max(np.abs(axis - ref_axis)) < 1e-7
    assert np.min(np.abs(np.sin(th))) < 0.05                  # it did pass near the vertical
    if offset == 0:
        assert r["theta_min"] == pytest.approx(0.0, abs=1e-6)
    for key in ("psi", "phi"):
        assert np.max(np.abs(np.diff(r[key]))) < 3.2          # no 2π wrap jumps
    assert r["theta_min"] == pytest.approx(cubic_bounds(M_, L_, I11, I33, th0, psid0, thd0, phid0)[0], abs=1e-9)


def test_projected_method_and_estimate():
    base = f"type: top\nm: {M_}\nL: {L_}\nI11: {I11}\nI33: {I33}\ntheta: 0.5\nphi_dot: 50\nat: [3]\n"
    rec = solve_one_text(base + "accuracy: {method: projected, rtol: 1.0e-7, atol: 1.0e-9}\n")
    assert rec["method"] == "ode:projected-DOP853"
    assert rec["results"]["drift"] < 1e-13
    rec2 = solve_one_text(base + "accuracy: {rtol: 1.0e-7, atol: 1.0e-9, estimate: true}\n")
    assert 0 < rec2["error_estimate"] < 1e-3
    ref = euler_angle_reference(0.5, 0.0, 0.0, 50.0, [3.0])
    assert rec["results"]["theta"][0] == pytest.approx(ref[0, 1], abs=1e-4)


@settings(max_examples=30, deadline=None, phases=(Phase.explicit, Phase.reuse, Phase.generate))
@given(th0=st.floats(0.05, 3.0), psid=st.floats(-5, 5), thd=st.floats(-5, 5), phid=st.floats(-300, 300),
       L=st.floats(-0.1, 0.1))
def test_turning_points_against_textbook_cubic(th0, psid, thd, phid, L):
    from dyncli.topics.top import solver

    mgL = M_ * G * L
    w3 = psid * math.cos(th0) + phid
    got = solver.turning_points(I11, I33, mgL, th0, psid, thd, w3)
    ref = cubic_bounds(M_, L, I11, I33, th0, psid, thd, phid)
    assert got[0] <= th0 + 1e-12 and got[1] >= th0 - 1e-12
    for g_, r_ in zip(got, ref):
        assert g_ == pytest.approx(r_, abs=2e-6)


@pytest.mark.parametrize("text,field,msg", [
    ("type: top\nm: 1\nL: 0.1\nI11: 0.01\nI33: 0.004\n", None, "theta"),
    ("type: top\nm: 0\nL: 0.1\nI11: 0.01\nI33: 0.004\ntheta: 0.3\n", "m", "> 0"),
    ("type: top\nm: 1\nL: 0.1\nI11: 0.01\nI33: 0.03\ntheta: 0.3\n", None, "triangle"),
    ("type: top\nm: 1\nL: 0.1\nI11: 0.01\nI33: 0.004\ntheta: 0.3\naccuracy: {method: Euler}\n", None, "unknown method"),
    ("type: top\nm: 1\nL: 0.1\nI11: 0.01\nI33: 0.004\ntheta: 0.3\nat: [\"t\"]\n", "at", ""),
])
def test_invalid(text, field, msg):
    err = error_of(text)
    assert err.startswith("bad.yaml:")
    if field:
        line = [i + 1 for i, l in enumerate(text.splitlines()) if l.startswith(field + ":")][0]
        assert err.startswith(f"bad.yaml:{line}:")
    assert msg in err
