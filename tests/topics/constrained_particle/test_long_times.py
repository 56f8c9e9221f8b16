"""The energy route at long times: t is reduced modulo a period known to its quadratures'
estimates, so n periods on the time is off by n times that, and a velocity (or a position
oscillating about a point) by 2π·δt/period of its scale.  error_estimate must bound the true error
against the bead on a hoop released from rest (a pendulum, sin(q/2) = k cd(ωt | k²), in mpmath at
50 digits from the decimal inputs), and one warning says so past 1e-6."""

from __future__ import annotations

import mpmath
import pytest

from tests.conftest import solve_one_text

TEXT = """type: constrained-particle
m: 0.1
curve: {{x1: "0.5*sin(q)", x2: 0, x3: "-0.5*cos(q)"}}
q_range: [-pi, pi]
q0: 1
forces: [{{kind: gravity}}]
at: [{at}]
"""


def _q(t: str):
    with mpmath.workdps(50):
        k, w = mpmath.sin(mpmath.mpf(1) / 2), mpmath.sqrt(mpmath.mpf("9.81") / mpmath.mpf("0.5"))
        u = w * mpmath.mpf(t) + mpmath.ellipk(k * k)
        return 2 * mpmath.asin(k * mpmath.ellipfun("sn", u, m=k * k)), 2 * k * w * mpmath.ellipfun("cn", u, m=k * k)


def _lost(rec):
    return [w for w in rec.get("warnings", []) if "periods" in w and "smaller t" in w]


@pytest.mark.parametrize("t", ["1", "1e6", "1e10", "1e13"])
def test_estimate_bounds_the_error(t):
    rec = solve_one_text(TEXT.format(at=t))
    r = rec["results"]
    q, qd = _q(t)
    with mpmath.workdps(50):
        k, w = mpmath.sin(mpmath.mpf(1) / 2), mpmath.sqrt(mpmath.mpf("9.81") / mpmath.mpf("0.5"))
        err = float(max(abs(r["q"][0] - q), abs(r["q_dot"][0] - qd) / (2 * k * w)))   # (scales 1 and the top speed)
    assert err <= rec["error_estimate"], (t, err, rec["error_estimate"])
    assert (_lost(rec) != []) == (rec["error_estimate"] > 1e-10)       # (the default rtol, then 1e-6)


def test_long_times_are_warned_once():
    warned = _lost(solve_one_text(TEXT.format(at="1, 1e13, 1e16")))
    assert len(warned) == 1 and "t = 1e+16 s has no correct digits (digits lost at 2 of the 3" in warned[0]
