"""inertia with ``omega``: ω on the body axes and on ``basis`` (notes §35,
35.3-35.7; issue 21 item 7).  References: the notes' (35.11)-(35.12) by hand,
and sympy with exact rotations (a second, exact route)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

EPS = 2.3e-16


def test_gallery_omega_two_bases():
    (rec,) = solve_path(PROBLEMS / "inertia/omega-two-bases.yaml")
    r = rec["results"]
    c, s = math.sqrt(3) / 2, 0.5
    assert r["omega_body"] == [2.0, -1.0, 5.0]
    assert r["omega_basis"] == pytest.approx([2 * c + s, 2 * s - c, 5.0], rel=8 * EPS)
    for row, want in zip(r["A"], [[c, -s, 0], [s, c, 0], [0, 0, 1]]):
        assert row == pytest.approx(want, abs=4 * EPS)
    I1, I2, I3 = 0.05, 0.1, 0.13
    assert r["I_com"][0] == pytest.approx([I1 * c * c + I2 * s * s, (I1 - I2) * s * c, 0], rel=1e-14, abs=1e-17)
    assert r["H_com_body"] == pytest.approx([0.1, -0.1, 0.65], rel=1e-14)
    assert r["H_com"] == pytest.approx([0.1 * c + 0.05, 0.05 - 0.1 * c, 0.65], rel=1e-14)
    assert r["H_about"] == r["H_com"]          # no `about`: B is the center of mass
    assert "35.6" in rec["equations"]


def _sympy_reference(axis, angle, omega, box, mass, about):
    """Exact ω'', H̄'' and I_B'' ω'' with sympy (Rodrigues rotation from exact rationals)."""
    import sympy as sp

    k = sp.Matrix([sp.Rational(a) for a in axis])
    k = k / sp.sqrt(k.dot(k))
    th = sp.Rational(angle)
    K = sp.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    R = sp.eye(3) + sp.sin(th) * K + (1 - sp.cos(th)) * K * K
    A = R.T
    a, b, cc = (sp.Rational(x) for x in box)
    m = sp.Rational(mass)
    I = sp.diag(m * (b**2 + cc**2) / 12, m * (a**2 + cc**2) / 12, m * (a**2 + b**2) / 12)
    p = -sp.Matrix([sp.Rational(x) for x in about])          # center of mass (origin) from B
    IB = I + m * (p.dot(p) * sp.eye(3) - p * p.T)
    w = sp.Matrix([sp.Rational(x) for x in omega])
    w2 = A * w
    return ([float(x) for x in w2], [float(x) for x in (A * I * A.T) * w2], [float(x) for x in (A * IB * A.T) * w2])


@settings(max_examples=15, deadline=None)
@given(axis=st.lists(st.integers(-3, 3), min_size=3, max_size=3).filter(any),
       angle=st.fractions(-3, 3, max_denominator=8),
       omega=st.lists(st.integers(-20, 20), min_size=3, max_size=3),
       about=st.lists(st.integers(-2, 2), min_size=3, max_size=3))
def test_against_sympy(axis, angle, omega, about):
    text = (f"type: inertia\nparts:\n  - {{shape: box, mass: 3, size: [0.5, 0.25, 1]}}\n"
            f"basis: {{axis: {axis}, angle: {float(angle)!r}}}\nomega: {omega}\nabout: {about}\n")
    r = solve_one_text(text)["results"]
    w2, H2, HB = _sympy_reference(axis, str(angle), omega, ("1/2", "1/4", "1"), 3, about)
    # products of a rotation (entries rounded to an ulp) with data of size ≤ 20·|I|: a few ulp of the scale
    sw = max(1.0, max(abs(x) for x in omega))
    assert r["omega_basis"] == pytest.approx(w2, abs=16 * EPS * sw)
    # H'' = A I Aᵀ ω'': its round-off scales with |I|·|ω| (H itself can be smaller by cancellation)
    w_len = math.sqrt(sum(x * x for x in omega))
    sH = max(1e-3, max(abs(x) for x in HB), max(abs(x) for x in H2),
             w_len * max(abs(x) for row in r["I_com"] for x in row))
    sHB = max(sH, w_len * max(abs(x) for row in r["I_about"] for x in row))
    assert r["H_com"] == pytest.approx(H2, abs=64 * EPS * sH)
    assert r["H_about"] == pytest.approx(HB, abs=64 * EPS * sHB)
    # invariants: |ω''| = |ω'|, ω''·H̄'' = ω'·H̄' (2T̄)
    assert math.hypot(*r["omega_basis"]) == pytest.approx(math.hypot(*omega), rel=8 * EPS, abs=1e-300)
    dot2 = sum(a * b for a, b in zip(r["omega_basis"], r["H_com"]))
    dot1 = sum(a * b for a, b in zip(r["omega_body"], r["H_com_body"]))
    assert dot2 == pytest.approx(dot1, rel=1e-13, abs=1e-13 * sH * sw)


def test_extremes():
    # no basis: A = 1 and the components agree; zero ω gives zero H
    r = solve_one_text("type: inertia\nparts: [{shape: sphere, mass: 2, radius: 0.5}]\nomega: [0, 0, 0]\n")["results"]
    assert r["A"] == [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    assert r["omega_basis"] == r["omega_body"] == [0.0, 0.0, 0.0] and r["H_com"] == [0.0, 0.0, 0.0]
    # a point mass: Ī = 0, so H̄ = 0 for any ω; about a point 1 m away, H_about = m p̄ × (ω × p̄)... = I_B ω
    r = solve_one_text("type: inertia\nparts: [{shape: point, mass: 2}]\nabout: [1, 0, 0]\nomega: [0, 0, 3]\n")["results"]
    assert r["H_com"] == [0.0, 0.0, 0.0] and r["H_about"] == [0.0, 0.0, 6.0]
    # without omega the new results are absent (the contract only adds)
    r = solve_one_text("type: inertia\nparts: [{shape: point, mass: 2}]\n")["results"]
    assert "omega_basis" not in r


@pytest.mark.parametrize("tail,expected", [
    ("omega: [1, 2]\n", "omega: "),
    ("omega: [1, .nan, 2]\n", "omega"),
    ("omega: [1, 2, x]\n", "omega"),
    ("omega: [1e300, 0, 0]\n", "omega: the angular momentum I ω overflows"),
])
def test_invalid(tail, expected):
    msg = error_of("type: inertia\nparts: [{shape: sphere, mass: 1e10, radius: 1e5}]\n" + tail)
    assert expected in msg and "Traceback" not in msg
