"""precession (§38): roots checked against mpmath at 50 digits, limits, invalid input."""

from __future__ import annotations

import math
import sys
import subprocess

import mpmath as mp
import pytest
from hypothesis import given, settings, strategies as st

from tests.conftest import PROBLEMS, ROOT, error_of, solve_one_text, solve_path

MPMATH_DPS = 50
mp.mp.dps = 50


def ref_roots(m, L, I11, I33, theta, p, g=9.81):
    """Both roots of (38.22) in 50-digit arithmetic from the same float inputs."""
    m, L, I11, I33, theta, p, g = (mp.mpf(x) for x in (m, L, I11, I33, theta, p, g))
    a = (I11 - I33) * mp.cos(theta)
    b = I33 * p
    c = m * g * L
    if a == 0:
        return c / b, None
    # the textbook formula (38.23) in enough digits to survive its cancellation
    lost = 0 if a * c == 0 else int(mp.log10(b * b / abs(4 * a * c) + 1)) + 1
    with mp.workdps(60 + lost):
        d = b * b - 4 * a * c
        if d < 0:
            return None
        r1, r2 = (b - mp.sqrt(d)) / (2 * a), (b + mp.sqrt(d)) / (2 * a)
        return tuple(+x for x in sorted((r1, r2), key=abs))


def yaml_of(**kw):
    lines = ["type: precession"] + [f"{k}: {v!r}" if not isinstance(v, str) else f"{k}: \"{v}\"" for k, v in kw.items()]
    return "\n".join(lines) + "\n"


def close(x, ref, rtol):
    return abs(mp.mpf(x) - ref) <= rtol * abs(ref)


def test_example_fast_top():
    rec = solve_path(PROBLEMS / "gyroscopic" / "precession-fast-top.yaml")[0]
    r = rec["results"]
    slow, fast = ref_roots(0.5, 0.05, 0.006, 0.002, 30 * math.pi / 180, 200)
    assert r["exists"] is True
    assert close(r["Omega_slow"], slow, 1e-15) and close(r["Omega_fast"], fast, 1e-15)
    # (38.24) and (38.27) re-derived here
    a = 0.004 * math.cos(math.pi / 6)
    assert r["p_min"] == pytest.approx(2 * math.sqrt(a * 0.5 * 9.81 * 0.05) / 0.002, rel=1e-14)
    assert r["Omega_slow_approx"] == pytest.approx(0.5 * 9.81 * 0.05 / (0.002 * 200), rel=1e-15)
    assert r["Omega_fast_approx"] == pytest.approx(0.4 / a, rel=1e-15)
    # (38.20)
    s, c = 0.5, math.sqrt(3) / 2
    Om = float(slow)
    assert r["R_slow"] == pytest.approx([0, 0.5 * (9.81 * s + 0.05 * Om**2 * s * c), 0.5 * (9.81 * c - 0.05 * Om**2 * s * s)], rel=1e-14)
    assert rec["method"] == "closed-form"


def test_example_below_pmin():
    rec = solve_path(PROBLEMS / "gyroscopic" / "precession-below-pmin.yaml")[0]
    r = rec["results"]
    assert r["exists"] is False
    assert r["Omega_slow"] is None and r["Omega_fast"] is None and r["R_slow"] is None
    assert r["p_min"] == pytest.approx(29.147399903122307, rel=1e-14)
    assert any("p_min" in w for w in rec["warnings"])


def test_huge_spin_no_cancellation():
    r = solve_one_text(yaml_of(m=1.0, L=0.1, I11=0.01, I33=0.004, theta=0.7, p=1e8))["results"]
    slow, fast = ref_roots(1.0, 0.1, 0.01, 0.004, 0.7, 1e8)
    assert close(r["Omega_slow"], slow, 2e-16 * 4)
    assert close(r["Omega_fast"], fast, 2e-16 * 4)


def test_negative_spin():
    r = solve_one_text(yaml_of(m=1.0, L=0.1, I11=0.01, I33=0.004, theta=0.7, p=-300.0))["results"]
    slow, fast = ref_roots(1.0, 0.1, 0.01, 0.004, 0.7, -300.0)
    assert close(r["Omega_slow"], slow, 1e-15) and close(r["Omega_fast"], fast, 1e-15)
    assert r["Omega_slow"] < 0


def test_theta_half_pi_is_linear():
    rec = solve_one_text(yaml_of(m=1.0, L=0.1, I11=0.01, I33=0.004, theta="pi/2", p=100.0))
    r = rec["results"]
    assert r["Omega_fast"] is None and r["Omega_fast_approx"] is None and r["R_fast"] is None
    assert r["Omega_slow"] == pytest.approx(9.81 * 0.1 / (0.004 * 100), rel=1e-15)
    assert r["p_min"] == 0
    assert any("linear" in w for w in rec["warnings"])


def test_equal_inertia_is_linear():
    r = solve_one_text(yaml_of(m=1.0, L=0.1, I11=0.004, I33=0.004, theta=0.3, p=50.0))["results"]
    assert r["Omega_fast"] is None
    assert r["Omega_slow"] == pytest.approx(0.981 / 0.2, rel=1e-15)


def test_flat_top_no_pmin():
    # I11 < I33 (a disk-like top): (38.24) places no restriction, even at p = 0
    r = solve_one_text(yaml_of(m=1.0, L=0.02, I11=0.003, I33=0.005, theta=0.5, p=0.0))["results"]
    assert r["exists"] is True and r["p_min"] == 0
    slow, fast = ref_roots(1.0, 0.02, 0.003, 0.005, 0.5, 0.0)
    assert close(r["Omega_slow"], slow, 1e-15) and close(abs(r["Omega_fast"]), abs(fast), 1e-15)
    assert r["Omega_slow_approx"] is None


def test_vertical_top_trivial():
    rec = solve_one_text(yaml_of(m=1.0, L=0.1, I11=0.01, I33=0.004, theta=0.0, p=400.0))
    assert rec["results"]["exists"] is True
    assert any("trivial" in w for w in rec["warnings"])
    assert rec["results"]["R_slow"] == pytest.approx([0, 0, 9.81], abs=1e-12)


def test_inverse_problem_roundtrip():
    rec = solve_one_text(yaml_of(m=0.5, L=0.05, I11=0.006, I33=0.002, theta="30*deg", Omega=0.6164156212957234))
    r = rec["results"]
    assert r["p"] == pytest.approx(200.0, rel=1e-13)
    assert r["Omega_slow"] is None and r["Omega_fast"] is None
    Om, s, c = 0.6164156212957234, 0.5, math.sqrt(3) / 2
    assert r["R"] == pytest.approx([0, 0.5 * (9.81 * s + 0.05 * Om**2 * s * c), 0.5 * (9.81 * c - 0.05 * Om**2 * s * s)], rel=1e-14)


def test_inverse_zero_omega():
    r = solve_one_text(yaml_of(m=0.5, L=0.05, I11=0.006, I33=0.002, theta=0.5, Omega=0))["results"]
    assert r["exists"] is False and r["p"] is None


@settings(max_examples=150, deadline=None)
@given(
    I11=st.floats(1e-3, 10.0), ratio=st.floats(0.01, 1.99), theta=st.floats(0.01, 3.13),
    logp=st.floats(-2, 8), sign=st.sampled_from([-1.0, 1.0]),
    L=st.floats(-1.0, 1.0).filter(lambda x: x == 0 or abs(x) > 1e-250),  # no subnormal roots
    m=st.floats(0.01, 100.0),
)
def test_roots_match_mpmath(I11, ratio, theta, logp, sign, L, m):
    from dyncli.topics.precession import solver

    I33 = ratio * I11
    p = sign * 10.0**logp
    a, b, c = solver.coefficients(m, L, I11, I33, theta, p, 9.81)
    ref = ref_roots(m, L, I11, I33, theta, p)
    if solver.is_linear(a, I11, I33):
        slow = c / b
        assert close(slow, mp.mpf(m) * mp.mpf(9.81) * mp.mpf(L) / (mp.mpf(I33) * mp.mpf(p)), 1e-15) or L == 0
        return
    got = solver.roots(a, b, c)
    if ref is None:
        # only at the boundary may rounding decide existence
        d = mp.mpf(b) ** 2 - 4 * mp.mpf(a) * mp.mpf(c)
        assert got is None or abs(d) <= 1e-13 * mp.mpf(b) ** 2
        return
    if got is None:
        d = mp.mpf(b) ** 2 - 4 * mp.mpf(a) * mp.mpf(c)
        assert abs(d) <= 1e-13 * mp.mpf(b) ** 2
        return
    # conditioning: near p_min the roots are sensitive to rounding of a (cos θ)
    d = abs(mp.mpf(b) ** 2 - 4 * mp.mpf(a) * mp.mpf(c))
    kappa = 1 + (mp.mpf(b) ** 2 + 4 * abs(mp.mpf(a) * mp.mpf(c))) / max(d, mp.mpf(10) ** -300)
    tol = 1e-15 * float(mp.sqrt(kappa)) + 8e-16 * float(kappa) ** 0.5
    for g_, r_ in zip(got, ref):
        if r_ == 0:
            assert g_ == 0
        else:
            assert close(g_, r_, 4 * tol), (g_, r_, kappa)


@settings(max_examples=60, deadline=None)
@given(eps=st.floats(1e-15, 1e-6), I11=st.floats(0.01, 1.0), ratio=st.floats(0.1, 1.9))
def test_near_linear(eps, I11, ratio):
    """(I11 − I33) cos θ → 0: the slow root tends continuously to the linear root."""
    from dyncli.topics.precession import solver

    I33 = ratio * I11
    theta = math.pi / 2 - eps
    a, b, c = solver.coefficients(1.0, 0.1, I11, I33, theta, 50.0, 9.81)
    lin = c / b
    if solver.is_linear(a, I11, I33):
        return
    slow, fast = solver.roots(a, b, c)
    ref = ref_roots(1.0, 0.1, I11, I33, theta, 50.0)
    assert close(slow, ref[0], 1e-14)
    assert abs(slow - lin) <= 1e-5 * abs(lin) + abs(a) * lin * lin / b * 2
    assert close(fast, ref[1], 1e-14)


@settings(max_examples=60, deadline=None)
@given(rel=st.floats(1e-12, 1e-2), theta=st.floats(0.05, 1.5))
def test_near_pmin(rel, theta):
    """p → p_min+: both roots merge towards I33 p/(2a); no complex result above p_min (up to rounding)."""
    from dyncli.topics.precession import solver

    m, L, I11, I33 = 1.0, 0.1, 0.01, 0.004
    a, _, c = solver.coefficients(m, L, I11, I33, theta, 0.0, 9.81)
    pm = solver.p_min(a, c, I33)
    p = pm * (1 + rel)
    got = solver.roots(a, I33 * p, c)
    assert got is not None
    slow, fast = got
    mid = I33 * p / (2 * a)
    assert 0 < slow <= mid * (1 + 1e-12) and fast >= mid * (1 - 1e-12)
    assert slow * fast == pytest.approx(c / a, rel=1e-13)   # Vieta
    assert slow + fast == pytest.approx(I33 * p / a, rel=1e-13)


@pytest.mark.parametrize("text,field,msg", [
    ("type: precession\nm: 1\nL: 0.1\nI11: 0.01\nI33: 0.004\ntheta: 0.5\n", None, "exactly one of p"),
    ("type: precession\nm: 1\nL: 0.1\nI11: 0.01\nI33: 0.004\ntheta: 0.5\np: 1\nOmega: 2\n", None, "both"),
    ("type: precession\nm: -1\nL: 0.1\nI11: 0.01\nI33: 0.004\ntheta: 0.5\np: 1\n", "m", "> 0"),
    ("type: precession\nm: 1\nL: 0.1\nI11: 0.01\nI33: 0.03\ntheta: 0.5\np: 1\n", None, "triangle"),
    ("type: precession\nm: 1\nL: 0.1\nI11: 0.01\nI33: 0.004\ntheta: 0.5\np: 1\nspin: 3\n", "spin", ""),
])
def test_invalid(text, field, msg):
    err = error_of(text)
    assert err.startswith("bad.yaml:")
    if field:
        assert f"{field}:" in err
        line = [i + 1 for i, l in enumerate(text.splitlines()) if l.startswith(field + ":")][0]
        assert err.startswith(f"bad.yaml:{line}:")
    assert msg in err


def test_no_scipy_import():
    code = ("import sys; from tests.conftest import solve_path, PROBLEMS; "
            "solve_path(PROBLEMS/'gyroscopic'/'precession-fast-top.yaml'); "
            "print('scipy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert out.stdout.strip() == "False", out.stderr
