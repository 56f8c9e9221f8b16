"""Issue #28: relative equilibria of the bead on a hoop turning at ω² R/g = 1 + δ, just past (and
before) the bifurcation, decided exactly (never by sampling): for δ > 0 the bottom is unstable and
two stable equilibria sit at cos q* = g/(ω² R), q* ≈ ±√(2δ); for δ ≤ 0 the bottom alone (with the
top).  Reference: q* = acos(g/(ω² R)) in mpmath at 30 digits from the very doubles given."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import solve_one_text

R, G = 0.5, 9.81
EPS = 2.220446049250313e-16


def hoop(w):
    return (f"type: constrained-particle\nparams: {{R: 0.5}}\nm: 0.1\ncurve: {{x1: 'R*sin(q)', x2: 0, "
            f"x3: '-R*cos(q)'}}\nq_range: [-pi, pi]\nrotation: {{axis: [0, 0, 1], omega: {w!r}}}\n"
            "q0: 0.3\nforces: [{kind: gravity}]\nat: [0]\n")


@pytest.mark.parametrize("delta", [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12])
def test_just_past_the_bifurcation_the_two_stable_equilibria_are_found(delta):
    w = math.sqrt((1 + delta) * G / R)
    eq = solve_one_text(hoop(w))["results"]["equilibria"]
    with mp.workdps(30):
        qs = float(mp.acos(mp.mpf(G) / (mp.mpf(w) ** 2 * mp.mpf(R))))
    assert [e["stable"] for e in eq] == [False, True, False, True]
    top, left, bottom, right = (e["q"] for e in eq)
    assert top == pytest.approx(-math.pi, abs=1e-15) and bottom == 0.0
    # G = m R sin q (ω²R cos q − g): its terms cancel to 1 − cos q* ~ δ, so q* carries their rounding,
    # a few ε / (q* ω² R / g) (conditioning of the root, not of the method)
    tol = 8 * EPS / qs + 1e-15
    assert right == pytest.approx(qs, abs=tol) and left == pytest.approx(-qs, abs=tol)
    # small oscillations about q*: ω sin q* (the gallery's formula), from G' on a step below √δ
    for e in (eq[1], eq[3]):
        assert e["omega_small"] == pytest.approx(w * math.sin(qs), rel=max(1e-7, 32 * EPS / qs ** 2))


@pytest.mark.parametrize("delta", [-1e-2, -1e-6, -1e-12, 0.0])
def test_before_the_bifurcation_the_bottom_alone_is_stable(delta):
    w = math.sqrt((1 + delta) * G / R)
    eq = solve_one_text(hoop(w))["results"]["equilibria"]
    assert [(e["q"], e["stable"]) for e in eq] == [(pytest.approx(-math.pi, abs=1e-15), False), (0.0, True)]
    # the bottom's frequency sqrt(g/R − ω²) = sqrt(−δ g/R); 0 at the bifurcation (a cubic restoring force)
    # and where G'(0) ~ δ is below the difference's error (δ = −1e-12: reported 0, not a wrong number)
    om = eq[1]["omega_small"]
    assert om == pytest.approx(math.sqrt(max(-delta, 0.0) * G / R), rel=1e-6) or (om == 0 and abs(delta) < 1e-9)
