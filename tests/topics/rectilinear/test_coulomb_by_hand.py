"""Coulomb friction written by hand, sign(v), on the ODE route: recognised as the
jump it is and refused with what answers it (particle {kind: friction}), never
"raise accuracy.max_steps"; the quadrature of case 3 still answers the stop."""

from __future__ import annotations

import math

import pytest

from tests.conftest import error_of, solve_one_text

MU_G = 0.3 * 9.81


@pytest.mark.parametrize("a", ["-4*s - 0.3*9.81*sign(v)", "-0.3*9.81*sign(v) + 0*t", "cos(t) - 2*sign(-v)",
                               "-s - 0.5*sign(v)*abs(s)", "-s - sign(v*abs(v))"])
@pytest.mark.parametrize("method", ["auto", "DOP853", "Radau", "LSODA", "RK45"])
def test_general_route_refuses_sign_of_v(a, method):
    err = error_of(f"type: rectilinear\na: '{a}'\ns1: 1\nt_max: 5\naccuracy: {{method: {method}}}\nfind:\n  - {{t: 4}}\n")
    assert err.startswith("bad.yaml:2:1: a: sign(v) in"), err
    assert "type particle" in err and "{kind: friction" in err, err
    assert "max_steps" not in err and "more steps do not help" in err, err


def test_case3_on_an_ode_route_points_to_the_quadrature():
    err = error_of("type: rectilinear\na: '-2*sign(v)'\nv1: 4\naccuracy: {method: ode}\nfind:\n  - {t: 1}\n")
    assert "accuracy.method auto" in err and "case 3" in err, err


def test_case3_quadrature_answers_the_stop():
    rec = solve_one_text(f"type: rectilinear\na: '-{MU_G!r}*sign(v)'\nv1: 5\nfind:\n  - {{t: 3}}\n  - {{v: 0}}\n")
    t_stop, s_stop = 5 / MU_G, 25 / (2 * MU_G)          # uniform deceleration to rest, then at rest
    late, stop = rec["results"]["find"]
    assert late["s"] == pytest.approx(s_stop, rel=1e-12) and late["v"] == 0
    assert stop["t"] == pytest.approx(t_stop, rel=1e-12)


@pytest.mark.parametrize("a", ["-s - sign(t - 1)", "-s - sign(v - 1)", "-s - 0.1*abs(v)*v", "-s + 0*sign(1)*v"])
def test_other_expressions_are_not_refused(a):
    rec = solve_one_text(f"type: rectilinear\na: '{a}'\ns1: 1\nfind:\n  - {{t: 0.5}}\n")
    assert rec["results"]["find"][0]["reached"] is True


def test_the_refusal_points_to_what_answers_it():
    """The block on a spring with friction of the refused file, as the refusal says to write it:
    released at s = 1 from rest (k = 4, m = 1, mu N = 2.943 N) it swings half a period about the
    shifted equilibrium e = mu N / k and stops at 2e - 1 at t = pi/2, where the spring force
    (1.886 N) is below mu N: it sticks there."""
    rec = solve_one_text("""
type: particle
m: 1
x0: [1, 0, 0]
forces:
  - {kind: spring, k: 4, anchor: [0, 0, 0], L: 0}
  - {kind: friction, mu: 0.3, N: 9.81}
t_end: 4
at: [1, 4]
""")
    e = MU_G / 4
    x1 = e + (1 - e) * math.cos(2 * 1.0)
    assert rec["results"]["x"][0][0] == pytest.approx(x1, rel=1e-8)
    assert rec["results"]["x"][1][0] == pytest.approx(2 * e - 1, rel=1e-8)
    assert any("sticks" in w for w in rec["warnings"])
