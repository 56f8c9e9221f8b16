"""The pendulum at long times: however exactly its phase is reduced (double-double), its rate λ/P
is the inputs', each rounded to a double, so beyond a phase of ~1e9 the reported θ loses its
digits.  The bound (Motion.phase_error) must hold against the exact swing released from rest
(sin(θ/2) = k cd(ω₀t, k²), in mpmath at 50 digits from the decimal inputs), and one warning
says so past 1e-6 of the motion's range."""

from __future__ import annotations

import math

import mpmath
import pytest

from dyncli.topics.pendulum.motion import Motion
from tests.conftest import solve_one_text

TEXT = """type: pendulum
l: 1.3
g: 9.81
theta0: 2.1
at: [{at}]
"""


def _lost(rec):
    return [w for w in rec.get("warnings", []) if "phase" in w and "smaller t" in w]


@pytest.mark.parametrize("t", ["1", "1e6", "1e10", "1e13"])
def test_bound_holds(t):
    mo = Motion(1.3, 9.81, 2.1, 0.0)
    mo.long(float(t))
    th, thd = mo.state(float(t))
    with mpmath.workdps(50):
        g, l, th0 = mpmath.mpf("9.81"), mpmath.mpf("1.3"), mpmath.mpf("2.1")
        w, k = mpmath.sqrt(g / l), mpmath.sin(th0 / 2)
        u = w * mpmath.mpf(t)
        ref = 2 * mpmath.asin(k * mpmath.ellipfun("sn", u + mpmath.ellipk(k * k), m=k * k))
        ref_d = 2 * k * w * mpmath.ellipfun("cn", u + mpmath.ellipk(k * k), m=k * k)
        scale, scale_d = float(th0), float(2 * k * w)
    err = max(abs(th - float(ref)) / scale, abs(thd - float(ref_d)) / scale_d)
    assert err <= mo.phase_error(float(t)) + 1e-15, (t, err, mo.phase_error(float(t)))


def test_moderate_times_are_not_warned():
    assert _lost(solve_one_text(TEXT.format(at="0, 1, 1e3, 1e6"))) == []


def test_long_times_are_warned_once():
    warned = _lost(solve_one_text(TEXT.format(at="1, 1e13, 1e16")))
    assert len(warned) == 1 and warned[0].startswith("θ at t = 1e+16 s has no correct digits (digits lost at 2 of the 3")
    warned = _lost(solve_one_text(TEXT.format(at="1") + "find: [{t: 1e16}]\n"))
    assert len(warned) == 1 and warned[0].startswith("θ at t = 1e+16 s has no correct digits")
    assert math.isfinite(Motion(1.3, 9.81, 2.1, 0.0).phase_error(1e16))
