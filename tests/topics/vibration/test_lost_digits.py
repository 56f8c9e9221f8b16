"""A base-excited vibration whose absolute x, ẋ (or relative w) lose their digits — the base's
velocity Y·Ω cancelling in ṡ + ẇ, or the phase Ω·t held to one ulp — is warned about; the
examples are not, and the estimated rounding error bounds the true error (mpmath at 50 digits,
the exact solution of the ODE with the phase Ω·t computed from the decimal Ω and t)."""

from __future__ import annotations

import math

import mpmath
import pytest

from dyncli.topics.vibration import closed_form as cf
from tests.conftest import ROOT, solve_one_text, solve_text

CASE = """type: vibration
m: 1
k: 400
zeta: 0.025
L: 0.4
x0: 0.2
v0: {v0}
base: {{amplitude: 0.002, omega: {om}}}
at: [{at}]
"""


def _warnings(rec):
    return [w for w in rec.get("warnings", []) if "correct digits" in w or "rounding error" in w]


def test_fuzz_case_is_warned():
    rec = solve_one_text(CASE.format(v0="1.0e-300", om="3.0e+17", at="0, 0.1, 0.5, 1, 5, 20"))
    text = " ".join(_warnings(rec))
    assert "ẋ at t =" in text and "no correct digits" in text and "Y·Ω = 6e+14 m/s" in text
    assert "x at t =" in text and "w at t =" in text


@pytest.mark.parametrize("path", sorted((ROOT / "problems/vibration").glob("*.yaml")), ids=lambda p: p.name)
def test_examples_are_not_warned(path):
    for rec in solve_text(path.read_text()):
        assert _warnings(rec) == []


def _exact(om: str, t: str, v0: str):
    """(x, ẋ, w) of ẅ + 2ζωẇ + ω²w = YΩ² sin Ωt, w(0) = x0 − L, ẇ(0) = v0 − YΩ, x = w + Y sin Ωt + L."""
    with mpmath.workdps(50):
        wn, z, L, x0, Y = mpmath.mpf(20), mpmath.mpf("0.025"), mpmath.mpf("0.4"), mpmath.mpf("0.2"), mpmath.mpf("0.002")
        Om, tt, v = mpmath.mpf(om), mpmath.mpf(t), mpmath.mpf(v0)
        W = Y * Om**2 / (wn**2 - Om**2 + 2j * z * wn * Om)          # w_p = Im(W e^{iΩt})
        s1 = -z * wn + 1j * wn * mpmath.sqrt(1 - z * z)
        s2 = mpmath.conj(s1)
        a0 = x0 - L - W.imag                                        # homogeneous part's w(0), ẇ(0)
        b0 = (v - Y * Om) - (W * 1j * Om).imag
        c2 = (b0 - s1 * a0) / (s2 - s1)
        c1 = a0 - c2
        e = mpmath.exp(1j * Om * tt)
        w = (W * e).imag + (c1 * mpmath.exp(s1 * tt) + c2 * mpmath.exp(s2 * tt)).real
        wd = (W * 1j * Om * e).imag + (c1 * s1 * mpmath.exp(s1 * tt) + c2 * s2 * mpmath.exp(s2 * tt)).real
        return (float(w + Y * mpmath.sin(Om * tt) + L), float(wd + Y * Om * mpmath.cos(Om * tt)), float(w))


@pytest.mark.parametrize("om", ["2e4", "2e6", "2e8", "2e9"])          # r = 1e3 … 1e8
@pytest.mark.parametrize("t", ["0.1", "1", "7.3"])
def test_estimate_bounds_the_true_error(om, t):
    ref = _exact(om, t, "1")
    got = cf.response_at(float(t), omega_n=20.0, zeta=0.025, L=0.4, x0=0.2, v0=1.0, s0=0.002, Omega=float(om))
    errs, scales = cf.base_rounding(float(t), omega_n=20.0, zeta=0.025, L=0.4, x0=0.2, v0=1.0, s0=0.002,
                                    Omega=float(om), x=got[0], v=got[1], w=got[2])
    for q in range(3):
        # the estimate bounds the error (plus the last-digit rounding of the result itself)
        assert abs(got[q] - ref[q]) <= errs[q] + 4 * math.ulp(scales[q]), (q, got[q], ref[q], errs[q])


def test_large_ratio_at_moderate_phase_is_warned():
    # r = 1e8, Ω·t up to 2e9: ulp(Ω·t) ≈ 2.4e-7 rad times Y·Ω = 4e6 m/s is ≈ 1 m/s on ẋ (scale ≈ 4 m/s)
    rec = solve_one_text(CASE.format(v0="1", om="2e9", at="0.1, 1"))
    assert any(w.startswith("ẋ at t =") for w in _warnings(rec))
    # r = 1e3, Ω·t ≤ 2e4: digits kept, no warning
    rec = solve_one_text(CASE.format(v0="1", om="2e4", at="0.1, 1"))
    assert _warnings(rec) == []


# --- a free or force-excited vibration: the phases ω*·t and Ω·t alone -------------------------

FREE = """type: vibration
m: 1
k: 3
{damping}
L: 0.5
x0: 0.6
v0: 0.2
{force}
at: [{at}]
"""


def _free_exact(t: str, zeta: str = "0", f0: str = "0", om: str = "1"):
    """(x, ẋ, w) of ẅ + 2ζωₙẇ + ωₙ²w = f0 sin Ωt, ωₙ = √3 from the decimal k, w(0) = 0.1, ẇ(0) = 0.2."""
    with mpmath.workdps(60):
        wn, z, tt = mpmath.sqrt(3), mpmath.mpf(zeta), mpmath.mpf(t)
        F, Om = mpmath.mpf(f0), mpmath.mpf(om)
        W = F / (wn**2 - Om**2 + 2j * z * wn * Om)                    # w_p = Im(W e^{iΩt})
        s1 = -z * wn + 1j * wn * mpmath.sqrt(1 - z * z)
        s2 = mpmath.conj(s1)
        a0 = mpmath.mpf("0.1") - W.imag
        b0 = mpmath.mpf("0.2") - (W * 1j * Om).imag
        c2 = (b0 - s1 * a0) / (s2 - s1)
        c1 = a0 - c2
        e = mpmath.exp(1j * Om * tt)
        w = (W * e).imag + (c1 * mpmath.exp(s1 * tt) + c2 * mpmath.exp(s2 * tt)).real
        wd = (W * 1j * Om * e).imag + (c1 * s1 * mpmath.exp(s1 * tt) + c2 * s2 * mpmath.exp(s2 * tt)).real
        return float(w + mpmath.mpf("0.5")), float(wd), float(w)


@pytest.mark.parametrize("t", ["1", "1e6", "3e9", "1e12", "1e15"])
@pytest.mark.parametrize("zeta", ["0", "1e-14", "1e-11"])
def test_free_phase_bound_holds(t, zeta):
    from dyncli.topics.vibration import forced

    wn = math.sqrt(3.0)
    got = forced.response_at(float(t), m=1.0, omega_n=wn, zeta=float(zeta), L=0.5, x0=0.6, v0=0.2, F0=0.0, Om=0.0)
    ref = _free_exact(t, zeta)
    errs, scales = cf.phase_rounding(float(t), omega_n=wn, zeta=float(zeta), L=0.5, w0=0.1, wd0=0.2)
    for q in range(3):
        # the phase bound plus the rounding of the result itself (a few ulps of its scale)
        assert abs(got[q] - ref[q]) <= errs[q] + 8 * math.ulp(scales[q]), (q, got[q], ref[q], errs[q])


@pytest.mark.parametrize("t", ["2", "1e6", "1e10", "1e13"])
def test_forced_phase_bound_holds(t):
    from dyncli.topics.vibration import forced

    wn = math.sqrt(3.0)
    got = forced.response_at(float(t), m=1.0, omega_n=wn, zeta=0.0, L=0.5, x0=0.6, v0=0.2, F0=0.7, Om=0.9)
    ref = _free_exact(t, "0", "0.7", "0.9")
    errs, scales = cf.phase_rounding(float(t), omega_n=wn, zeta=0.0, L=0.5, w0=0.1, wd0=0.2, f0=0.7, Omega=0.9)
    for q in range(3):
        assert abs(got[q] - ref[q]) <= errs[q] + 8 * math.ulp(scales[q]), (q, got[q], ref[q], errs[q])


def test_free_vibration_at_huge_times_is_warned_once():
    rec = solve_one_text(FREE.format(damping="", force="", at="0, 1e3, 1e15, 1e17"))
    warned = _warnings(rec)
    assert len(warned) == 1, warned
    assert warned[0].startswith("x, ẋ and w at t = 1e+17 s have no correct digits (digits lost at 2 of the 4")
    assert "phase ω*·t" in warned[0] and "smaller t" in warned[0]


@pytest.mark.parametrize("damping, force, at", [
    ("", "", "1, 1e6, 1e8"),                                       # ωₙt ≤ 1.7e8: ulp 3e-8 rad
    ("zeta: 0.01", "", "1, 1e12, 1e17"),                           # decayed to nothing long before
    ("", "force: {amplitude: 0.7, omega: 0.9}", "1, 1e6, 1e8"),
])
def test_moderate_phases_and_decayed_motions_are_not_warned(damping, force, at):
    assert _warnings(solve_one_text(FREE.format(damping=damping, force=force, at=at))) == []


def test_forced_vibration_at_huge_times_is_warned():
    rec = solve_one_text(FREE.format(damping="zeta: 0.01", force="force: {amplitude: 0.7, omega: 0.9}",
                                     at="1, 1e16"))
    warned = _warnings(rec)
    # Ω·t = 9e15 rad is held to ±1 rad: the steady oscillation (0.32 m) is lost, x's offset L is not
    assert [w.split(" at ")[0] for w in warned] == ["x", "ẋ", "w"]
    assert all("phase ω*·t or Ω·t" in w and "t = 1e+16 s" in w for w in warned)
