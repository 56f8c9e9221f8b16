"""Case 4 at long times: a periodic motion is reduced modulo its period, which its quadratures know
only to their error estimate, so n periods shift a reported state by n times that.  The shift is
counted in error_estimate (which must bound the true error: the exact harmonic motion in mpmath at
50 digits, ω from the decimal k/m) and warned about once it moves the phase by more than 1e-6 rad."""

from __future__ import annotations

import mpmath
import pytest

from tests.conftest import solve_one_text

SPRING = """type: rectilinear
params: {{k: 100, m: 3}}
a: "-k/m*s"
s1: 0.1
v1: 1
find: [{queries}]
"""


def _exact(t: str) -> tuple[float, float]:
    with mpmath.workdps(50):
        w, T = mpmath.sqrt(mpmath.mpf(100) / 3), mpmath.mpf(t)
        return (float(mpmath.mpf("0.1") * mpmath.cos(w * T) + mpmath.sin(w * T) / w),
                float(-mpmath.mpf("0.1") * w * mpmath.sin(w * T) + mpmath.cos(w * T)))


def _long(rec):
    return [w for w in rec.get("warnings", []) if "periods after t1" in w]


@pytest.mark.parametrize("t", ["1", "50", "1e4", "1e6", "1e8", "1e10", "1e12"])
def test_error_estimate_bounds_the_true_error(t):
    rec = solve_one_text(SPRING.format(queries=f"{{t: {t}}}"))
    got = rec["results"]["find"][0]
    s, v = _exact(t)
    amp_s, amp_v = 0.2236, 1.292                       # the motion's scales: √(s1² + (v1/ω)²), ω·that
    err = max(abs(got["s"] - s) / amp_s, abs(got["v"] - v) / amp_v)
    assert err <= rec["error_estimate"] + 1e-14, (t, err, rec["error_estimate"])


def test_short_times_are_not_warned_long_ones_are():
    assert _long(solve_one_text(SPRING.format(queries="{t: 1}, {t: 50}, {t: 1e4}"))) == []
    warned = _long(solve_one_text(SPRING.format(queries="{t: 1}, {t: 1e12}, {t: 1e16}")))
    assert len(warned) == 1 and warned[0].startswith("the state at t ≈ 1e+16 s (9.19e+15 periods after t1) has no "
                                                     "correct digits")
    assert "counted in error_estimate" in warned[0] and "earlier time" in warned[0]
