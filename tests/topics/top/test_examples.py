"""Every example in problems/gyroscopic/top-*.yaml against independent references."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import PROBLEMS, solve_path
from tests.topics.top import reference as ref

M, L, A, C, G = 0.5, 0.05, 2.0e-3, 1.0e-3, 9.81
MGL = M * G * L
DIR = PROBLEMS / "gyroscopic"


def _steady(root):
    th, p = math.pi / 6, 150.0
    c = (A - C) * math.cos(th)
    # both roots of (38.22) with mpmath; the slow one is the smaller
    import mpmath as mp

    with mp.workdps(50):
        r = sorted((mp.polyroots([c, -C * p, MGL], extraprec=200)), key=abs)
    return th, p, float(r[0] if root == "slow" else r[1])


@pytest.mark.parametrize("index,root", [(0, "slow"), (1, "fast")])
def test_steady_precession_example(index, root):
    rec = solve_path(DIR / "top-steady-precession.yaml")[index]
    r = rec["results"]
    th, p, Om = _steady(root)
    t = np.array([[0, 1, 2, 5], [0, 0.05, 0.1]][index])
    assert r["theta_min"] == pytest.approx(th, abs=1e-12)
    assert r["theta_max"] == pytest.approx(th, abs=1e-12)
    assert np.max(np.abs(np.array(r["theta"]) - th)) < 1e-8
    assert np.allclose(r["psi"], Om * t, rtol=1e-8, atol=1e-9)
    assert np.allclose(r["phi"], p * t, rtol=1e-8, atol=1e-9)
    assert np.allclose(r["psi_dot"], Om, rtol=1e-8)
    # reaction of steady precession (38.20)
    R2 = M * (G * math.sin(th) + L * Om ** 2 * math.sin(th) * math.cos(th))
    R3 = M * (G * math.cos(th) - L * Om ** 2 * math.sin(th) ** 2)
    for R in r["R"]:
        assert R[0] == pytest.approx(0.0, abs=1e-7 * abs(R2))
        assert R[1] == pytest.approx(R2, rel=1e-8)
        assert R[2] == pytest.approx(R3, rel=1e-8)
    assert rec["error_estimate"] is not None and rec["error_estimate"] < 1e-6
    assert rec["method"] == "exact"      # auto: the elliptic solution


def test_nutating_example():
    rec = solve_path(DIR / "top-nutating.yaml")[0]
    r = rec["results"]
    times = [0, 0.05, 0.1, 0.2, 0.5, 1, 2]
    y0 = [0.0, 0.5, 0.0, 0.0, 0.0, 100.0]
    lo, hi = ref.bounds_mp(M, L, A, C, G, 0.5, 0.0, 0.0, 100.0)
    assert r["theta_min"] == pytest.approx(lo, abs=1e-13)
    assert r["theta_max"] == pytest.approx(hi, rel=1e-12)
    # second, independent integrator on the Euler-angle form of (38.18)
    Y = ref.euler_angle_ode(M, L, A, C, G, y0, times)
    for name, col in (("psi", 0), ("theta", 1), ("phi", 2), ("psi_dot", 3), ("theta_dot", 4), ("phi_dot", 5)):
        got = np.array(r[name], dtype=float)
        assert np.max(np.abs(got - Y[:, col])) < 1e-7 * max(1.0, np.max(np.abs(Y[:, col]))), name
    # reaction (38.16b-d) from the reference angles, rates and accelerations
    for R, (ps, th, ph, psd, thd, phd, psdd, thdd) in zip(r["R"], Y):
        s, c = math.sin(th), math.cos(th)
        Rref = [M * (L * psdd * s + 2 * L * psd * thd * c),
                M * (G * s - L * thdd + L * psd ** 2 * s * c),
                M * (G * c - L * thd ** 2 - L * psd ** 2 * s * s)]
        assert np.allclose(R, Rref, rtol=1e-7, atol=1e-7)
    assert all(lo - 1e-9 <= th <= hi + 1e-9 for th in r["theta"])
    assert r["drift"] < 1e-9


def test_near_vertical_example():
    rec = solve_path(DIR / "top-near-vertical.yaml")[0]
    r = rec["results"]
    times = [0, 0.02, 0.04, 0.06, 0.08, 0.1, 0.2, 0.5]
    args = (0.3, -2.0, 16.918, 50.0)
    lo, hi = ref.bounds_mp(M, L, A, C, G, *args)
    assert r["theta_min"] == pytest.approx(lo, rel=1e-7)   # 8.5e-6 rad: cosθ would lose it, the solver does not
    assert r["theta_max"] == pytest.approx(hi, rel=1e-12)
    assert any("8.5e-06 rad of the vertical" in w for w in rec["warnings"])
    # the reported angles give the same orientation as an independent direction-cosine integration
    Qs, ws = ref.dcm_ode(M, L, A, C, G, 0.0, 0.3, 0.0, 16.918, -2.0, 50.0, times)
    for k, (Q, w) in enumerate(zip(Qs, ws)):
        Qr = ref.euler313(r["psi"][k], r["theta"][k], r["phi"][k])
        assert np.max(np.abs(Qr - Q)) < 1e-7, k
    assert min(r["theta"]) >= lo - 1e-12


def test_near_vertical_continuous():
    """ψ + φ is smooth through the closest approach; ψ swings by about π there."""
    from tests.conftest import solve_one_text

    ts = [round(0.001 * k, 3) for k in range(0, 121)]
    rec = solve_one_text("type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\ntheta: 0.3\ntheta_dot: -2\n"
                         f"psi_dot: 16.918\nphi_dot: 50\nat: {ts}\n")
    r = rec["results"]
    psi, phi = np.array(r["psi"]), np.array(r["phi"])
    sig = psi + phi
    assert np.max(np.abs(np.diff(sig))) < 0.1            # smooth: ~|ψ̇ + φ̇|·1 ms
    jumps = np.abs(np.diff(psi))
    assert jumps.max() > 2.5                              # the swing past the pole...
    assert np.sum(jumps > 0.5) == 1                       # ...happens once, between two samples
    # orientation at every sample vs the direction-cosine reference
    Qs, _ = ref.dcm_ode(M, L, A, C, G, 0.0, 0.3, 0.0, 16.918, -2.0, 50.0, ts)
    for k in range(0, len(ts), 10):
        assert np.max(np.abs(ref.euler313(psi[k], r["theta"][k], phi[k]) - Qs[k])) < 1e-7


def test_sleeping_example():
    rec = solve_path(DIR / "top-near-vertical.yaml")[1]
    r = rec["results"]
    assert r["theta_min"] == 0.0 and r["theta_max"] == 0.0
    assert r["theta"] == [0.0, 0.0, 0.0]
    assert r["psi"] == [0.0, 0.0, 0.0]
    assert np.allclose(r["phi"], [0, 50, 100], rtol=1e-9)
    for R in r["R"]:
        assert np.allclose(R, [0, 0, M * G], atol=1e-12)
    assert r["psi_dot"] == [None, None, None]
    assert any("sleeping top" in w for w in rec["warnings"])
    assert not any("unstable" in w for w in rec["warnings"])   # I33²ω3² = 0.01 > 4 I11 mgL = 0.00196
