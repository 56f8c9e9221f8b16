"""precession (§38): stability of each steady precession and the frequency of
small nutation (issue 21 item 9).  The reference differentiates the reduced
nutation equation numerically in 40-digit arithmetic (mpmath.diff), not the
closed form ν² of the solver; a second check runs the ``top`` type (energy and
momentum integrals) with a small θ̇ perturbation: the nutation half-range is
ε/ν to first order."""

from __future__ import annotations

import math

import mpmath as mp
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

G = 9.81


def ref_nu2(m, L, I11, I33, theta0, p, Omega, g=G):
    """−f'(θ0) of θ̈ = f(θ) with h and ω3 held at the steady values (40 digits)."""
    with mp.workdps(40):
        m, L, I11, I33, th0, p, Om, g = (mp.mpf(x) for x in (m, L, I11, I33, theta0, p, Omega, g))
        w3 = p + Om * mp.cos(th0)
        h = I11 * Om * mp.sin(th0) ** 2 + I33 * w3 * mp.cos(th0)

        def f(th):
            psid = (h - I33 * w3 * mp.cos(th)) / (I11 * mp.sin(th) ** 2)
            return (I11 * psid**2 * mp.sin(th) * mp.cos(th) - I33 * w3 * psid * mp.sin(th)
                    + m * g * L * mp.sin(th)) / I11

        # a steady precession up to the rounding of the float root
        assert abs(f(th0)) < 1e-12 * (1 + Om**2 + abs(I33 * w3 * Om / I11) + abs(m * g * L / I11))
        return -mp.diff(f, th0)


TOP = dict(m=0.5, L=0.05, I11=0.006, I33=0.002)


def _prec(theta, p, **kw):
    d = dict(TOP, **kw)
    return "type: precession\n" + "".join(f"{k}: {v!r}\n" for k, v in d.items()) + f"theta: {theta!r}\np: {p!r}\n"


def test_gallery_precession_stability():
    a, b, c = (rec["results"] for rec in solve_path(PROBLEMS / "gyroscopic/precession-stability.yaml"))
    # header values (hand-derived from ν² = [(I33ω3 − 2I11Ω cosθ0)² + (I11Ω sinθ0)²]/I11²)
    assert a["stable_slow"] is True and a["stable_fast"] is True
    assert a["nutation_freq_slow"] == pytest.approx(65.7777, abs=1e-4)
    assert a["nutation_freq_fast"] == pytest.approx(114.5456, abs=1e-4)
    assert b["nutation_freq_slow"] == pytest.approx(65.6384, abs=1e-4)
    assert b["nutation_freq_fast"] == pytest.approx(98.9718, abs=1e-4)
    assert c["stable_slow"] is True and c["stable_fast"] is None and c["nutation_freq_fast"] is None
    assert c["nutation_freq_slow"] == pytest.approx(math.hypot(0.002 * 50 / 0.006, 2.4525), rel=1e-14)
    # the sleeping top: the classical form √((I33ω3)² − 4 I11 m g L)/I11, ω3 = p + Ω
    for Om, nu in ((b["Omega_slow"], b["nutation_freq_slow"]), (b["Omega_fast"], b["nutation_freq_fast"])):
        w3 = 200 + Om
        assert nu == pytest.approx(math.sqrt((0.002 * w3) ** 2 - 4 * 0.006 * 0.5 * G * 0.05) / 0.006, rel=1e-12)
    # against the numerical derivative of the nutation equation
    for Om, nu in ((a["Omega_slow"], a["nutation_freq_slow"]), (a["Omega_fast"], a["nutation_freq_fast"])):
        assert nu**2 == pytest.approx(float(ref_nu2(0.5, 0.05, 0.006, 0.002, math.pi / 6, 200, Om)), rel=1e-12)


@settings(max_examples=30, deadline=None)
# L subnormal (|m g L| < 2.2e-308: the roots of (38.22) lose their accuracy there) is outside the
# guaranteed range; subnormal spins are kept (see the examples)
@given(theta=st.floats(0.05, math.pi - 0.05), p=st.floats(-500, 500),
       L=st.floats(-0.2, 0.2, allow_subnormal=False),
       I33=st.floats(1e-4, 0.011))
@example(theta=1.0, p=7.219315968444832e-262, L=0.0, I33=0.0078125)   # ν² below the double range
@example(theta=1.0, p=5e-324, L=0.0, I33=0.0078125)    # I33·ω3 underflows: the ratio I33/I11 first
def test_against_the_derivative_of_the_nutation_equation(theta, p, L, I33):
    r = solve_one_text(_prec(theta, p, L=L, I33=I33))["results"]
    for name in ("slow", "fast"):
        Om = r[f"Omega_{name}"]
        if Om is None:
            assert r[f"stable_{name}"] is None and r[f"nutation_freq_{name}"] is None
            continue
        nu2_mp = ref_nu2(0.5, L, 0.006, I33, theta, p, Om)
        nu2 = float(nu2_mp)
        # the root carries a few ulp of relative error; ν² depends on it with a condition number of
        # a few (|∂ν²/∂Ω|·|Ω|/ν²): 1e-9 relative, plus an absolute floor for ν² ≈ 0
        assert r[f"nutation_freq_{name}"] ** 2 == pytest.approx(nu2, rel=1e-9, abs=1e-9)
        assert r[f"stable_{name}"] is bool(nu2_mp > 0)   # the sign in 40 digits (ν² may underflow a double)


def test_small_perturbation_of_the_top_nutates_at_nu():
    """The top, started on the slow root with θ̇ = ε: θ stays within ε/ν of θ0 (second method)."""
    r = solve_one_text(_prec(math.pi / 6, 200))["results"]
    Om, nu = r["Omega_slow"], r["nutation_freq_slow"]
    eps = 1e-4
    top = ("type: top\nm: 0.5\nL: 0.05\nI11: 0.006\nI33: 0.002\ntheta: 0.5235987755982988\n"
           f"psi_dot: {Om!r}\nphi_dot: 200\ntheta_dot: {eps!r}\nat: [0]\n")
    t = solve_one_text(top)["results"]
    half = (t["theta_max"] - t["theta_min"]) / 2
    assert half == pytest.approx(eps / nu, rel=1e-3)   # first-order theory: relative error O(ε/(ν·θ-scale))


def test_extremes():
    # no gravity and no spin: the double root Ω = 0 — the linearised motion drifts (not stable)
    rec = solve_one_text(_prec(0.7, 0.0, L=0.0))
    r = rec["results"]
    assert r["Omega_slow"] == 0.0 and r["stable_slow"] is False and r["nutation_freq_slow"] == 0.0
    assert any("drift" in w for w in rec["warnings"])
    # below p_min: no precession, the stability fields are null
    r = solve_one_text(_prec(0.5, 5.0))["results"]
    assert r["exists"] is False and r["stable_slow"] is None and r["nutation_freq_fast"] is None
    # hanging top (L < 0), p = 0: a conical pendulum; both roots are stable
    r = solve_one_text(_prec(2.5, 0.0, L=0.05))["results"]
    assert r["stable_slow"] is True and r["stable_fast"] is True
    # huge spin: ν_slow → I33 p/I11 with no overflow
    r = solve_one_text(_prec(0.5, 1e150))["results"]
    assert r["nutation_freq_slow"] == pytest.approx(0.002 * 1e150 / 0.006, rel=1e-12)
    # Omega given: stable and nutation_freq for that precession, the root fields null
    r = solve_one_text("type: precession\nm: 0.5\nL: 0.05\nI11: 0.006\nI33: 0.002\ntheta: 0.5\nOmega: 1\n")["results"]
    assert r["stable"] is True and r["stable_slow"] is None
    assert r["nutation_freq"] ** 2 == pytest.approx(float(ref_nu2(0.5, 0.05, 0.006, 0.002, 0.5, r["p"], 1.0)), rel=1e-10)


def test_invalid_input_still_one_message():
    msg = error_of("type: precession\nm: 0.5\nL: 0.05\nI11: 0.006\nI33: 0.002\ntheta: 0.5\np: 1\nOmega: 1\n")
    assert "give exactly one of p" in msg and "Traceback" not in msg
    msg = error_of("type: precession\nm: 0.5\nL: 0.05\nI11: 0.006\nI33: 0.002\ntheta: 0.5\np: 1\nstable: true\n")
    assert "stable: unknown field" in msg
