"""A scene's closed-form vibration at long times: its phase ω*·t is formed in doubles from ωₙ²
assembled from the inputs (a few ε relative), so beyond ~1e9 rad it loses its digits; one warning
says so once the phase error exceeds 1e-6 of the oscillation.  Against the exact motion of a disk
rolling (no friction watched) on an incline held by a spring, s = δ(1 − cos ωₙt), ωₙ = √(2k/3m)
(mpmath, 50 digits from the decimal inputs): unwarned reported angles are within 1e-6 of the
oscillation, and a time at which they are not is warned."""

from __future__ import annotations

import mpmath
import pytest

from tests.conftest import solve_one_text

TEXT = """type: scene
params: {{m: 2, R: 0.2, k: 250, L0: 0.5, beta: "30*deg", s0: 2}}
surfaces:
  slope: {{through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}}
bodies:
  disk: {{shape: disk, mass: m, radius: R, angle: 0}}
joints:
  roll: {{rolls: [disk, slope], at: s0}}
forces:
  - spring: [disk, ["(s0 + L0)*cos(beta) - R*sin(beta)", "(s0 + L0)*sin(beta) + R*cos(beta)"]]
    k: k
    L: L0
    name: spring
at: [{at}]
"""


def _lost(rec):
    return [w for w in rec.get("warnings", []) if "vibration" in w and "smaller t" in w]


def _angle(t: str):
    with mpmath.workdps(50):
        m, R, k, g = (mpmath.mpf(x) for x in ("2", "0.2", "250", "9.81"))
        delta, wn = m * g / 2 / k, mpmath.sqrt(2 * k / (3 * m))          # sin 30° = ½
        return delta / R * (1 - mpmath.cos(wn * mpmath.mpf(t))), 2 * delta / R


@pytest.mark.parametrize("t", ["1", "1e6", "1e10", "1e13"])
def test_unwarned_times_are_accurate(t):
    rec = solve_one_text(TEXT.format(at=t))
    assert rec["method"] == "closed-form"
    ref, scale = _angle(t)
    err = float(abs(rec["results"]["angle"]["disk"][0] - ref) / scale)
    assert err <= 1e-6 or _lost(rec), (t, err)
    assert bool(_lost(rec)) == (float(t) >= 1e10), rec["warnings"]


def test_huge_times_have_no_correct_digits():
    warned = _lost(solve_one_text(TEXT.format(at="1, 1e16")))
    assert len(warned) == 1 and warned[0].startswith("the vibration at t = 1e+16 s has no correct digits")
