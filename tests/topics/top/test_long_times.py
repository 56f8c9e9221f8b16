"""The exact top at long times: its phase is reduced in double-double from 40-digit constants of
the inputs as binary numbers, but the inputs are decimal numbers rounded to doubles, so λ/2K is
known to a few ε only and beyond λt ~ 1e9 the reported state loses its digits.  error_estimate
must bound the true error against the released top's exact solution (u = cos θ = u1 + (u2 − u1)
cd²(λt | m), in mpmath at 50 digits from the decimal inputs), and one warning says so past 1e-6."""

from __future__ import annotations

import mpmath
import pytest

from tests.conftest import solve_one_text

TEXT = """type: top
m: 0.5
L: 0.05
I11: 2.0e-3
I33: 1.0e-3
theta: 0.5
phi_dot: 100
at: [{at}]
"""


def _theta(t: str) -> float:
    with mpmath.workdps(50):
        m, L, A, C, g = (mpmath.mpf(x) for x in ("0.5", "0.05", "2.0e-3", "1.0e-3", "9.81"))
        u0, c = mpmath.cos(mpmath.mpf("0.5")), C * 100 / A
        be = 2 * m * g * L / A
        al, b = be * u0, c * u0                     # released: α − βu0 = 0, b − cu0 = 0
        u1, u2, u3 = sorted(mpmath.re(x) for x in mpmath.polyroots(
            [be, -al - c ** 2, -be + 2 * b * c, al - b ** 2], maxsteps=400, extraprec=400))
        lam, k2 = mpmath.sqrt(be * (u3 - u1)) / 2, (u2 - u1) / (u3 - u1)
        return mpmath.acos(u1 + (u2 - u1) * mpmath.ellipfun("cd", lam * mpmath.mpf(t), m=k2) ** 2)


def _lost(rec):
    return [w for w in rec.get("warnings", []) if "phase" in w and "smaller t" in w]


@pytest.mark.parametrize("t", ["1", "1e6", "1e10", "1e13"])
def test_estimate_bounds_the_error(t):
    rec = solve_one_text(TEXT.format(at=t))
    theta = rec["results"]["theta"][0]
    ref = _theta(t)
    err = float(abs(theta - ref) / ref)
    assert err <= rec["error_estimate"], (t, err, rec["error_estimate"])
    assert (_lost(rec) != []) == (rec["error_estimate"] > 1e-6)


def test_moderate_times_are_not_warned():
    rec = solve_one_text(TEXT.format(at="1, 100, 1e3"))
    assert _lost(rec) == [] and rec["error_estimate"] < 1e-10      # (the default rtol: not warned)


def test_long_times_are_warned_once():
    warned = _lost(solve_one_text(TEXT.format(at="1, 1e12, 1e16")))
    assert len(warned) == 1 and warned[0].startswith("the state at t = 1e+16 s has no correct digits (digits lost at 2 of the 3")


def test_a_find_answer_at_a_long_time_is_warned_and_counted():
    rec = solve_one_text(TEXT.format(at="1") + "find: [{t: 1e12}]\n")
    warned = _lost(rec)
    assert len(warned) == 1 and warned[0].startswith("the state at t = 1e+12 s has a phase error up to")
    assert rec["error_estimate"] > 1e-3
    rec = solve_one_text(TEXT.format(at="1") + "find: [{t: 1e3}]\n")
    assert _lost(rec) == [] and rec["error_estimate"] < 1e-10
    rec = solve_one_text("type: gyroscope\nI1: 0.01\nI2: 0.006\np: 100\nq: 1\ntheta0: 0\ntheta_dot0: 0\nat: [1]\n"
                         "find: [{t: 1e12}]\n")
    assert any(w.startswith("θ at t = 1e+12 s has a phase error") for w in rec["warnings"]), rec["warnings"]
