"""The ODE route's two forms (docs/types/top.md): the reduced equations away from the vertical,
the quaternion form next to it, each against the 60-digit elliptic references
(tests/topics/top/exact_reference_data.py, a separate implementation), with the runner's estimates."""

from __future__ import annotations

import math

import pytest

from dyncli.topics.top import reduced
from dyncli.topics.top.kinematics import Top, turning_points
from tests.conftest import solve_one_text
from tests.topics.top.exact_reference_data import CASES
from tests.topics.top.test_exact import _errors, _text

G = 9.81


def _usable(name, rtol=1e-10):
    m, L, A, C, _, th, _, psd, thd, phd = CASES[name]["input"]
    top = Top(m, L, A, C, G)
    w3 = psd * math.cos(th) + phd
    lo, hi, wp2 = turning_points(A, C, top.mgL, th, thd, psd, w3)
    b = psd * math.sin(th) ** 2 + C / A * w3 * math.cos(th)
    Wfast = abs(C * w3 / A) + math.sqrt(4 * top.mgL / A)
    return reduced.usable(top, lo, hi, w3, b, math.sqrt(wp2), Wfast, rtol)


def test_the_form_follows_the_distance_from_the_vertical():
    assert _usable("nutating") and _usable("oblate") and _usable("spin5000")
    # θ ~ 1e-6 rad: 1/sin²θ is singular there, the quaternion form integrates
    assert not _usable("near_vertical_stable") and not _usable("near_vertical_falls")
    # spin 5000 rad/s: ψ̇ = (b − c cosθ)/sin²θ with c/ψ̇ ~ 1e4 keeps rtol 1e-8, not rtol 2.3e-14
    assert not _usable("spin5000", rtol=2.3e-14)


@pytest.mark.parametrize("name,rtol", [("nutating", 1e-6), ("nutating", 1e-10), ("near_vertical_stable", 1e-6),
                                       ("near_vertical_stable", 1e-10), ("near_vertical_falls", 1e-6),
                                       ("oblate", 1e-10)])
def test_check_solve_measures_the_error_of_both_forms(name, rtol):
    case = CASES[name]
    rec = solve_one_text(_text(case, extra=f"accuracy: {{rtol: {rtol}, method: DOP853, estimate: true}}\n"))
    err = max(_errors(rec, case["rows"]).values())    # every quantity relative to its own scale at the times
    # the check solve at rtol/100 (its error ~1/60 of the reported run's): 0.98-1.02 times the error
    assert 0.9 * err <= rec["error_estimate"] <= 1.5 * err, (rec["error_estimate"], err)


def test_step_cap_keeps_a_loose_run_within_a_few_rtol():
    # without the cap (h·W ≈ 1.4) DOP853's error estimator fell short: 35 x rtol at rtol 1e-6
    case = CASES["nutating"]
    for rtol in (1e-5, 1e-6):
        rec = solve_one_text(_text(case, extra=f"accuracy: {{rtol: {rtol}, method: DOP853}}\n"))
        assert max(_errors(rec, case["rows"]).values()) <= 3 * rtol
        assert rec["error_estimate"] >= max(_errors(rec, case["rows"]).values())   # one solve: the nominal bound


def test_steady_precession_estimate_is_not_inflated_by_theta_dot():
    # θ̇ ≡ 0: its computed values are the integrator's error (its tolerance is rtol |ω⊥|max / 10 per
    # step), counted relative to |ω⊥|max / 10: a few rtol, not the O(1) of a relative error of zero
    m, L, A, C, th, p = 0.5, 0.05, 2.0e-3, 1.0e-3, math.pi / 6, 150.0
    om = 2 * m * G * L / (C * p + math.sqrt((C * p) ** 2 - 4 * m * G * L * (A - C) * math.cos(th)))
    rec = solve_one_text(f"type: top\nm: {m}\nL: {L}\nI11: {A}\nI33: {C}\ntheta: {th!r}\npsi_dot: {om!r}\n"
                         f"phi_dot: {p}\nat: [1, 2, 5]\naccuracy: {{rtol: 1.0e-8, method: DOP853, estimate: true}}\n")
    r = rec["results"]
    err = max(max(abs(a - om * t) for a, t in zip(r["psi"], (1, 2, 5))) / (5 * om),
              max(abs(a - th) for a in r["theta"]) / th,
              max(abs(a - p * t) for a, t in zip(r["phi"], (1, 2, 5))) / (5 * p))
    assert err <= rec["error_estimate"] <= 10 * 1e-8
