"""Every shape of the contract, placed and turned arbitrarily, against direct
integration of ρ[(p·p)1 − p⊗p] (Gauss rules written here, independent of the
tool's table of standard moments)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import solve_one_text
from tests.topics.inertia import oracles

AT = (0.3, -0.2, 0.5)
B = (-0.1, 0.4, 0.2)
PSI, THETA, PHI = 0.4, 1.1, -0.7


def R313(psi, theta, phi):
    """Columns = body axes e'_i in the starting basis: transpose of the
    product of the notes' matrices (38.6a-c), written out here."""
    def A(a):   # (38.6a)/(38.6c): rows are the new axes
        c, s = math.cos(a), math.sin(a)
        return np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])

    def Bm(t):  # (38.6b)
        c, s = math.cos(t), math.sin(t)
        return np.array([[1, 0, 0], [0, c, s], [0, -s, c]])

    return (A(phi) @ Bm(theta) @ A(psi)).T


R = R313(PSI, THETA, PHI)


def solve_part(part_yaml: str):
    text = f"""
type: inertia
parts:
  - {{{part_yaml}, at: [{AT[0]}, {AT[1]}, {AT[2]}], orientation: {{euler313: [{PSI}, {THETA}, {PHI}]}}}}
about: [{B[0]}, {B[1]}, {B[2]}]
"""
    return solve_one_text(text)["results"]


def about_B(points, weights):
    P = (R @ np.asarray(points).T).T + np.asarray(AT) - np.asarray(B)
    return oracles._about(P, np.asarray(weights))


def gl(n, a, b):
    return oracles._gl(n, a, b)


def check(res, m, I):
    assert res["mass"] == pytest.approx(m, rel=1e-13)
    np.testing.assert_allclose(res["I_about"], I, rtol=1e-11, atol=1e-14)
    np.testing.assert_allclose(res["com"], AT, rtol=1e-14)


def test_point():
    res = solve_part("shape: point, mass: 2.5")
    check(res, 2.5, about_B([[0, 0, 0]], [2.5])[2])
    np.testing.assert_allclose(res["I_com"], np.zeros((3, 3)), atol=0)


def test_rod_along_e3():
    L, m = 1.3, 2.0
    z, w = gl(6, -L / 2, L / 2)
    res = solve_part(f"shape: rod, mass: {m}, length: {L}")
    check(res, m, about_B(np.c_[0 * z, 0 * z, z], m / L * w)[2])


def test_box():
    m, size = 3.0, (0.5, 0.2, 0.9)
    rho = m / np.prod(size)
    res = solve_part(f"shape: box, mass: {m}, size: [{size[0]}, {size[1]}, {size[2]}]")
    check(res, m, oracles.box_cubature(rho, size, AT, R, B)[2])


def test_cylinder():
    m, r, h = 4.0, 0.15, 0.5
    res = solve_part(f"shape: cylinder, mass: {m}, radius: {r}, height: {h}")
    check(res, m, oracles.cylinder_cubature(m / (math.pi * r * r * h), r, h, AT, R, B)[2])


def test_disk():
    m, r = 1.5, 0.4
    rr, wr = gl(6, 0, r)
    th = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    RR, TH = np.meshgrid(rr, th, indexing="ij")
    W = (m / (math.pi * r * r)) * np.outer(wr * rr, np.full(th.size, 2 * np.pi / th.size))
    pts = np.c_[(RR * np.cos(TH)).ravel(), (RR * np.sin(TH)).ravel(), 0 * RR.ravel()]
    res = solve_part(f"shape: disk, mass: {m}, radius: {r}")
    check(res, m, about_B(pts, W.ravel())[2])


def test_ring():
    m, r = 0.7, 0.25
    th = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    pts = np.c_[r * np.cos(th), r * np.sin(th), 0 * th]
    res = solve_part(f"shape: ring, mass: {m}, radius: {r}")
    check(res, m, about_B(pts, np.full(th.size, m / th.size))[2])


def _sphere_points(r_nodes, r_weights, n=8):
    ct, wct = gl(n, -1, 1)                       # cos(polar angle)
    ph = np.linspace(0, 2 * np.pi, 2 * n, endpoint=False)
    pts, ws = [], []
    for rr, wr in zip(r_nodes, r_weights):
        for c, wc in zip(ct, wct):
            s = math.sqrt(1 - c * c)
            for p in ph:
                pts.append([rr * s * math.cos(p), rr * s * math.sin(p), rr * c])
                ws.append(wr * wc * 2 * np.pi / ph.size)
    return np.array(pts), np.array(ws)


def test_sphere():
    m, r = 5.0, 0.3
    rr, wr = gl(6, 0, r)
    pts, w = _sphere_points(rr, wr * rr * rr)
    res = solve_part(f"shape: sphere, mass: {m}, radius: {r}")
    check(res, m, about_B(pts, w * m / (4 / 3 * math.pi * r**3))[2])


def test_shell():
    m, r = 2.0, 0.3
    pts, w = _sphere_points([r], [r * r])
    res = solve_part(f"shape: shell, mass: {m}, radius: {r}")
    check(res, m, about_B(pts, w * m / (4 * math.pi * r * r))[2])


def test_tensor_part_turned():
    Ip = np.array([[0.3, -0.05, 0.02], [-0.05, 0.4, 0.01], [0.02, 0.01, 0.5]])
    rows = ", ".join("[" + ", ".join(repr(float(x)) for x in r) + "]" for r in Ip)
    res = solve_part(f"shape: tensor, mass: 2, inertia: [{rows}]")
    p = np.asarray(AT) - np.asarray(B)
    ref = R @ Ip @ R.T + 2 * (p @ p * np.eye(3) - np.outer(p, p))
    check(res, 2.0, ref)


def test_sphere_all_repeated_reports_identity():
    rec = solve_one_text("type: inertia\nparts: [{shape: sphere, mass: 2, radius: 0.5}]\n")
    res = rec["results"]
    np.testing.assert_allclose(res["principal_moments"], [0.2, 0.2, 0.2], rtol=1e-15)
    np.testing.assert_array_equal(res["principal_axes"], np.eye(3))
    assert res["principal_axes_unique"] is False
    assert "every direction is principal" in res["principal_axes_note"]


def test_single_point_mass_is_degenerate():
    rec = solve_one_text("type: inertia\nparts: [{shape: point, mass: 2, at: [1, 2, 3]}]\n")
    res = rec["results"]
    assert res["I_com"] == [[0.0] * 3] * 3
    assert res["principal_moments"] == [0.0, 0.0, 0.0]
    assert res["radii_of_gyration"] == [0.0, 0.0, 0.0]
    np.testing.assert_array_equal(res["principal_axes"], np.eye(3))
    assert any("all principal moments are zero" in w for w in rec["warnings"])


def test_collinear_points_have_a_zero_moment():
    rec = solve_one_text("""
type: inertia
parts:
  - {shape: point, mass: 1, at: [0, 0, 0]}
  - {shape: point, mass: 2, at: [1, 2, 2]}
  - {shape: point, mass: 3, at: [-2, -4, -4]}
about: [3, 6, 6]
""")
    res = rec["results"]
    assert res["principal_moments"][0] == 0.0
    assert res["radii_of_gyration"][0] == 0.0
    np.testing.assert_allclose(np.abs(np.array(res["principal_axes"])[:, 0]), [1 / 3, 2 / 3, 2 / 3], atol=1e-14)
    # about a point on the line, the other two moments are equal: Σ m d²
    d2 = sum(mm * (np.linalg.norm(np.array(x) - [3, 6, 6]) ** 2) for mm, x in [(1, (0, 0, 0)), (2, (1, 2, 2)), (3, (-2, -4, -4))])
    np.testing.assert_allclose(res["principal_moments"][1:], [d2, d2], rtol=1e-13)
