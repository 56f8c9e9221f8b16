"""The torque-free closed form at long times: its phase λt + u0 is formed in doubles (λ to its
formula's last digits, the sum to one ulp), so beyond a phase of ~1e9 the reported ω loses its
digits.  The bound (dyncli.phase.rounded) must hold against the exact solution (the axisymmetric
body, 39.17, in mpmath at 50 digits from the decimal inputs), and a warning says so past 1e-6."""

from __future__ import annotations

import mpmath
import pytest

from dyncli.topics.euler import free
from tests.conftest import solve_one_text

AXI = """type: euler
I: [2, 2, 3]
omega0: [0.3, 5, 0.1]
at: [{at}]
"""


def _lost(rec):
    return [w for w in rec.get("warnings", []) if "phase" in w and "smaller t" in w]


@pytest.mark.parametrize("t", ["1", "1e4", "1e8", "1e10", "1e12", "1e14"])
def test_axisymmetric_bound_holds(t):
    body = free.exact([2.0, 2.0, 3.0], [0.3, 5.0, 0.1])
    got = body.omega(float(t))
    with mpmath.workdps(50):
        lam = (mpmath.mpf(3) - 2) / 2 * mpmath.mpf("0.1")            # (39.15)
        c, s = mpmath.cos(lam * mpmath.mpf(t)), mpmath.sin(lam * mpmath.mpf(t))
        w1, w2 = mpmath.mpf("0.3"), mpmath.mpf(5)
        ref = (float(w1 * c - w2 * s), float(w1 * s + w2 * c))          # (39.17)
    amp = float(mpmath.hypot(0.3, 5))
    err = max(abs(got[0] - ref[0]), abs(got[1] - ref[1])) / amp
    assert err <= body.phase_error(float(t)) + 1e-15, (t, err, body.phase_error(float(t)))


def test_moderate_times_are_not_warned():
    assert _lost(solve_one_text(AXI.format(at="0, 1, 1e3, 1e6"))) == []
    assert _lost(solve_one_text("type: euler\nI: [1, 2, 3]\nomega0: [0.3, 5, 0.1]\nat: [1, 1e3, 1e6]\n")) == []


def test_long_times_are_warned_once():
    warned = _lost(solve_one_text(AXI.format(at="1, 1e12")))
    assert len(warned) == 1 and warned[0].startswith("ω at t = 1e+12 s has a phase error up to")
    warned = _lost(solve_one_text("type: euler\nI: [1, 2, 3]\nomega0: [0.3, 5, 0.1]\nat: [1, 1e12, 1e16]\n"))
    assert len(warned) == 1 and warned[0].startswith("ω at t = 1e+16 s has no correct digits (digits lost at 2 of the 3")
