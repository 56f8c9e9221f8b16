"""Impact or not is decided exactly (issue 16): (vA1 − vB1)·n in rational
arithmetic of the given doubles, zero to within 4 round-offs of every given
component counts as no approach (docs/types/impact.md)."""

from __future__ import annotations

from fractions import Fraction

import pytest

from tests.conftest import solve_one_text


def _impact(vA1, vB1, n):
    text = f"type: impact\nmA: 1\nmB: 2\ne: 0.5\nvA1: {vA1}\nvB1: {vB1}\nn: {n}\n"
    return solve_one_text(text)["results"]


@pytest.mark.parametrize("n,vA1", [
    ('["cos(pi/4)", "sin(pi/4)", 0]', "[1, -1, 0]"),          # cos, sin differ by 1 ulp: +1.1e-16
    ('["sin(pi/4)", "cos(pi/4)", 0]', "[-1, 1, 0]"),
    ('["cos(pi/6)", "sin(pi/6)", 0]', '["-sin(pi/6)", "cos(pi/6)", 0]'),
    ('[3, 4, 0]', "[-0.8, 0.6, 0]"),                          # decimal tangent
    ('[1, 1, 1]', '["1/3", "1/3", "-2/3"]'),
])
def test_grazing_given_exactly_is_no_impact(n, vA1):
    r = _impact(vA1, "[0, 0, 0]", n)
    assert r["impact"] is False
    assert r["vA2"] == r["vB2"] or r["vB2"] == [0.0, 0.0, 0.0]


def test_tiny_real_approach_is_an_impact():
    """Beyond the band: an approach of 1e-14 |Δv| (exact doubles) is an impact."""
    r = _impact("[-0.79999999999999, 0.60000000000001, 0]", "[0, 0, 0]", "[3, 4, 0]")
    d = (Fraction(-0.79999999999999) * 3 + Fraction(0.60000000000001) * 4) / 5
    assert d > 0 and r["impact"] is True


def test_exactly_zero_and_head_on():
    assert _impact("[0, 1, 0]", "[0, 0, 0]", "[1, 0, 0]")["impact"] is False
    assert _impact("[1, 0, 0]", "[0, 0, 0]", "[1, 0, 0]")["impact"] is True
    assert _impact("[-1, 0, 0]", "[0, 0, 0]", "[1, 0, 0]")["impact"] is False


@pytest.mark.parametrize("a,b", [(2, 1), (3, 7), (5, 11), (1, 3), (17, 4)])
def test_phi_at_the_bound_is_admissible(a, b):
    """η = 0: φ₂ = θ = atan(b/a) exactly (28.50); φ given as that expression."""
    for phi in (f"atan({b}/{a})", f"acos({a}/sqrt({a * a + b * b}))", f"asin({b}/sqrt({a * a + b * b}))"):
        text = (f"type: impact\nmA: 1\nmB: 2\neta: 0\nphi: \"{phi}\"\nvA1: [{-a}, {b}, 0]\nvB1: [0, 0, 0]\n"
                "n: [-1, 0, 0]\n")
        r = solve_one_text(text)["results"]
        assert r["admissible"] is True and r["P3"] is True, (phi, r["phi2"])
    text = (f"type: impact\nmA: 1\nmB: 2\neta: 0\nphi: \"atan({b}/{a}) + 1e-13\"\nvA1: [{-a}, {b}, 0]\n"
            "vB1: [0, 0, 0]\nn: [-1, 0, 0]\n")
    assert solve_one_text(text)["results"]["admissible"] is False
