"""The example files of problems/inertia against independent routes:
sympy.physics.mechanics (inertia of point masses, parallel_axis), direct
cubature of ρ[(p·p)1 − p⊗p] over the shape, and the notes' closed forms
re-derived here."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import PROBLEMS, solve_path
from tests.topics.inertia import oracles

INERTIA = PROBLEMS / "inertia"


def one(name):
    recs = solve_path(INERTIA / name)
    assert all(r.get("error") is None for r in recs), recs
    return recs


def close(a, b, rtol=1e-10, atol=1e-14):
    np.testing.assert_allclose(np.asarray(a, float), np.asarray(b, float), rtol=rtol, atol=atol)


def check_principal(res):
    """Principal moments ascending, axes right-handed orthonormal, and
    I_about = Q diag(λ) Qᵀ."""
    lam = np.array(res["principal_moments"])
    Q = np.array(res["principal_axes"])
    I = np.array(res["I_about"])
    assert np.all(np.diff(lam) >= 0)
    close(Q.T @ Q, np.eye(3), atol=1e-12)
    assert np.linalg.det(Q) == pytest.approx(1.0, abs=1e-12)
    scale = max(1e-300, np.abs(lam).max())
    close(Q @ np.diag(lam) @ Q.T / scale, I / scale, atol=1e-12)


def test_dumbbell_fig_30_3_sympy():
    import sympy as sp
    from sympy.physics.mechanics import ReferenceFrame, inertia_of_point_mass

    (rec,) = one("dumbbell-fig30-3.yaml")
    res = rec["results"]
    M, L, a = sp.symbols("M L alpha", positive=True)
    N = ReferenceFrame("N")
    I = (inertia_of_point_mass(M, L * sp.sin(a) * N.x + L * sp.cos(a) * N.y, N)
         + inertia_of_point_mass(M, -L * sp.sin(a) * N.x - L * sp.cos(a) * N.y, N)).to_matrix(N)
    # (30.39d) as printed: I'12 = −M L² sin 2α
    assert sp.simplify(I[0, 1] + M * L**2 * sp.sin(2 * a)) == 0
    assert sp.simplify(I[0, 0] - 2 * M * L**2 * sp.cos(a) ** 2) == 0
    vals = {M: 2, L: sp.Rational(1, 2), a: sp.pi / 6}
    ref = np.array(I.subs(vals).evalf(30).tolist(), dtype=float)
    close(res["I_about"], ref, atol=1e-15)
    close(res["I_com"], ref, atol=1e-15)
    # (30.44): principal values 0, 2ML², 2ML²; the zero one along the masses
    close(res["principal_moments"], [0.0, 1.0, 1.0], atol=1e-15)
    close(np.array(res["principal_axes"])[:, 0], [0.5, math.sqrt(3) / 2, 0.0], atol=1e-15)
    assert res["principal_axes_unique"] is False
    assert "any orthonormal basis" in res["principal_axes_note"]
    assert res["radii_of_gyration"][0] == 0.0
    assert any("zero" in w for w in rec["warnings"])
    check_principal(res)


def test_box_about_corner_hand_and_sympy_parallel_axis():
    import sympy as sp
    from sympy.physics.mechanics import Point, ReferenceFrame, RigidBody, inertia

    (rec,) = one("box-about-corner.yaml")
    res = rec["results"]
    a, b, c, m = 0.4, 0.3, 0.2, 6.0
    hand = [[m * (b * b + c * c) / 3, -m * a * b / 4, -m * a * c / 4],
            [-m * a * b / 4, m * (a * a + c * c) / 3, -m * b * c / 4],
            [-m * a * c / 4, -m * b * c / 4, m * (a * a + b * b) / 3]]
    close(res["I_about"], hand)
    N = ReferenceFrame("N")
    O = Point("O")
    G = O.locatenew("G", sp.Rational(1, 5) * N.x + sp.Rational(3, 20) * N.y + sp.Rational(1, 10) * N.z)
    A_, B_, C_ = sp.Rational(2, 5), sp.Rational(3, 10), sp.Rational(1, 5)
    body = RigidBody("box", G, N, 6, (inertia(N, 6 * (B_**2 + C_**2) / 12, 6 * (A_**2 + C_**2) / 12, 6 * (A_**2 + B_**2) / 12), G))
    ref = np.array(body.parallel_axis(O).to_matrix(N).tolist(), dtype=float)
    close(res["I_about"], ref)
    close(res["com"], [0.2, 0.15, 0.1])
    # the same by cubature
    mm, com, I = oracles.box_cubature(m / (a * b * c), (a, b, c), (a / 2, b / 2, c / 2), np.eye(3), (0, 0, 0))
    close(res["I_about"], I)
    close(res["I_transfer"], np.array(res["I_about"]) - np.array(res["I_com"]), atol=1e-15)
    check_principal(res)


def test_plate_with_hole_direct_integration():
    (rec,) = one("plate-with-hole.yaml")
    res = rec["results"]
    m, com, I_O = oracles.plate_minus_disk(7800, 0.6, 0.4, 0.01, 0.15, 0.05, 0.1)
    assert res["mass"] == pytest.approx(m, rel=1e-12)
    assert res["mass"] == pytest.approx(7800 * 0.01 * (0.24 - math.pi * 0.01), rel=1e-14)
    close(res["com"], com, rtol=1e-10, atol=1e-14)
    I_com = I_O - m * (com @ com * np.eye(3) - np.outer(com, com))
    close(res["I_com"], I_com, rtol=1e-9, atol=1e-13)
    check_principal(res)


def test_plate_about_defaults_to_com():
    (rec,) = one("plate-with-hole.yaml")
    res = rec["results"]
    # `about` is absent: I_about equals I_com (contract), not the inertia about the origin
    close(res["I_about"], res["I_com"], rtol=0, atol=0)
    close(res["p_bar"], [0, 0, 0], atol=0)


def test_l_bracket_polygon_integration():
    (rec,) = one("l-shaped.yaml")
    res = rec["results"]
    verts = [(0, 0), (0.5, 0), (0.5, 0.1), (0.1, 0.1), (0.1, 0.5), (0, 0.5)]
    m, com, I_O = oracles.polygon_prism(2700, verts, 0.02)
    assert res["mass"] == pytest.approx(m, rel=1e-12)
    close(res["com"], com, rtol=1e-12)
    close(res["I_about"], I_O, rtol=1e-11, atol=1e-15)
    # symmetric about the diagonal: principal axes along (1, ±1, 0)/√2
    Q = np.array(res["principal_axes"])
    assert abs(abs(Q[0, 0]) - math.sqrt(0.5)) < 1e-12 and abs(abs(Q[1, 0]) - math.sqrt(0.5)) < 1e-12
    check_principal(res)


def test_tilted_cylinder_cubature_and_own_basis():
    recs = one("tilted-cylinder.yaml")
    res, res2 = recs[0]["results"], recs[1]["results"]
    m, r, h = 5.0, 0.1, 0.6
    b = math.radians(30)
    R = np.array([[1, 0, 0], [0, math.cos(b), -math.sin(b)], [0, math.sin(b), math.cos(b)]])  # columns: cylinder axes
    _, _, I = oracles.cylinder_cubature(m / (math.pi * r * r * h), r, h, (0, 0, 0), R, (0, 0, 0))
    close(res["I_com"], I, rtol=1e-12, atol=1e-15)
    It, Ia = m * (3 * r * r + h * h) / 12, m * r * r / 2
    assert res["I_com"][1][2] == pytest.approx((It - Ia) * math.sin(b) * math.cos(b), rel=1e-13)
    close(res["principal_moments"], [Ia, It, It], rtol=1e-13)
    ax1 = np.array(res["principal_axes"])[:, 0]
    close(np.abs(ax1), [0, 0.5, math.sqrt(3) / 2], atol=1e-14)
    check_principal(res)
    # on the cylinder's own axes the tensor is diagonal (30.36)
    close(res2["I_com"], np.diag([It, It, Ia]), rtol=1e-13, atol=1e-15)
    close(res2["principal_axes"], [[0, 1, 0], [0, 0, 1], [1, 0, 0]], atol=1e-14)


def test_coin_39_10():
    (rec,) = one("coin.yaml")
    res = rec["results"]
    m, R, h = 0.01, 0.012, 0.002
    I1 = 0.5 * m * R * R * (0.5 + h * h / (6 * R * R))
    I3 = 0.5 * m * R * R
    close(res["I_com"], np.diag([I1, I1, I3]), rtol=1e-14)
    close(res["principal_moments"], [I1, I1, I3], rtol=1e-14)
    close(res["principal_axes"], np.eye(3), atol=0)
    close(res["radii_of_gyration"], [math.sqrt(I1 / m), math.sqrt(I1 / m), math.sqrt(I3 / m)], rtol=1e-14)
    assert res["principal_axes_unique"] is False
    assert any("equal" in w for w in rec["warnings"])
