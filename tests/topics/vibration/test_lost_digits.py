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
