"""A curve whose tangent dy/dq vanishes: inside the motion (a wire folded back on itself, where
q̇ would be infinite) the energy route steps aside and the ODE route reports the failure (exit 1,
never an internal error: fuzz seed 2433711); at the wire's ends (the cusps of a cycloid) the
energy route still answers — the tautochrone's period is 4π sqrt(R/g) whatever the release."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_one_text, solve_text

FOLDED = """type: constrained-particle
m: 0.1
curve: {x1: 3, x2: 0, x3: "-0.5*cos(q)"}
q_range: [-pi, pi]
q0: 1
forces: [{kind: gravity}]
at: [0, 0.5, 1, 2]
"""

CYCLOID = """type: constrained-particle
m: 1
curve: {{x1: "0.5*(q - sin(q))", x2: 0, x3: "0.5*(1 + cos(q))"}}
q_range: [0, 2*pi]
q0: {q0}
forces: [{{kind: gravity}}]
at: [0, 1]
"""


def test_a_fold_inside_the_motion_is_a_numerical_failure():
    rec = solve_text(FOLDED)[0]
    assert rec["exit_code"] == 1 and "internal error" not in rec["error"], rec["error"]


@pytest.mark.parametrize("q0", [0.5, 2, 3])
def test_cusps_at_the_ends_keep_the_energy_route(q0):
    rec = solve_one_text(CYCLOID.format(q0=q0))
    assert rec["method"].startswith("quadrature")
    assert rec["results"]["period"] == pytest.approx(4 * math.pi * math.sqrt(0.5 / 9.81), rel=1e-9)


@pytest.mark.parametrize("x3", [".inf", "-.inf", ".nan"])
def test_a_curve_that_is_not_finite_at_q0_is_refused(x3):
    """A component that is not a finite number where the bead starts (its derivatives may still
    be: a constant) is an input error naming the curve (exit 2; was exit 3 from the find queries'
    extremes of NaN values, fuzz seed 3037873)."""
    rec = solve_text("type: constrained-particle\nm: 0.1\n"
                     f"curve: {{x1: \"0.5*sin(q)\", x2: 0, x3: {x3}}}\nq0: 1\nforces: [{{kind: gravity}}]\n"
                     "at: [0, 1]\nfind: [{max: N.1}]\n", "bead.yaml")[0]
    assert rec["exit_code"] == 2, rec["error"]
    assert "curve" in rec["error"] and "q0" in rec["error"]
