"""force-field: curl from exact derivatives, verdicts, potentials, work."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import solve_one_text


def test_curl_at_points_exact():
    # F = (x2 x3², -x1², sin(x1 x2)): curl = (x1 cos(x1 x2), 2 x2 x3 - x2 cos(x1 x2), -2 x1 - x3²)
    rec = solve_one_text("""
type: force-field
F: ["x2*x3**2", "-x1**2", "sin(x1*x2)"]
points: [[1, 2, 3], [-0.5, 0.25, 2]]
""")
    R = rec["results"]
    for pt, c in zip([[1, 2, 3], [-0.5, 0.25, 2]], R["curl"]):
        x1, x2, x3 = pt
        want = [x1 * math.cos(x1 * x2), 2 * x2 * x3 - x2 * math.cos(x1 * x2), -2 * x1 - x3 ** 2]
        np.testing.assert_allclose(c, want, rtol=1e-14, atol=1e-14)
    assert R["conservative"] is False
    assert R["conservative_method"].startswith("counterexample")
    assert R["work"] is None and rec["method"] == "closed-form"


def test_numeric_fallback_when_sympy_cannot_decide(monkeypatch):
    from dyncli.topics.force_field import symbolic_field

    monkeypatch.setattr(symbolic_field, "simplify_formula", lambda obj: obj)   # sympy "can't decide"
    rec = solve_one_text("""
type: force-field
F: ["x2*cos(x1)**2 + x2*sin(x1)**2", "x1", "0"]
path: {x1: t, x2: "2*t", x3: 0, t_span: [0, 1]}
""")
    R = rec["results"]
    assert R["conservative"] is True
    assert R["conservative_method"].startswith("numeric")
    assert any("numeric check" in w for w in rec["warnings"])
    assert R["work"] == pytest.approx(2.0, abs=1e-12)     # -V = x1 x2 from 0 to (1, 2)


def test_potential_with_a_non_elementary_function_still_checks_work():
    # V = -x2 x3 - sqrt(pi)/2 erf(x1): dyncli's language has no erf; evaluated by sympy
    rec = solve_one_text("""
type: force-field
F: ["exp(-x1**2)", "x3", "x2"]
path: {x1: "1 + t", x2: t, x3: "t**2", t_span: [0, 1]}
""")
    R = rec["results"]
    want = math.sqrt(math.pi) / 2 * (math.erf(2) - math.erf(1)) + 1.0
    assert R["work"] == pytest.approx(want, rel=1e-12)
    assert abs(R["work_check"]) < 1e-12
    assert "erf(x1)" in R["potential"]


def test_inverse_square_field_potential_without_V0():
    rec = solve_one_text("""
type: force-field
params: {k: 3}
F: ["-k*x1/(x1**2+x2**2+x3**2)**1.5", "-k*x2/(x1**2+x2**2+x3**2)**1.5", "-k*x3/(x1**2+x2**2+x3**2)**1.5"]
points: [[0, 0, 0], [1, 1, 1]]
path: {x1: "1 + t", x2: "2*t", x3: 0, t_span: [0, 1]}
""")
    R = rec["results"]
    assert R["conservative"] is True
    assert R["curl"][0] is None                    # singular at the origin
    np.testing.assert_allclose(R["curl"][1], [0, 0, 0], atol=1e-14)
    # V = -k/R (19.20b with V_inf = 0): work = V1 - V2 = -k (1/1 - 1/sqrt(8))
    assert R["work"] == pytest.approx(-3 * (1 - 1 / math.sqrt(8)), rel=1e-11)
    assert abs(R["work_check"]) < 1e-12
    assert any("singular at the origin" in w for w in rec["warnings"])


def test_closed_path_work_of_nonconservative_field():
    rec = solve_one_text("""
type: force-field
F: ["-x2 + x3", "x1", "0"]
path: {x1: "cos(t)", x2: "sin(t)", x3: 0, t_span: [0, "2*pi"]}
""")
    R = rec["results"]
    assert R["conservative"] is False
    assert R["work"] == pytest.approx(2 * math.pi, rel=1e-12)      # Stokes: 2 × area
    np.testing.assert_allclose(R["x_start"], R["x_end"], atol=1e-15)
