"""Property tests of the inertia solver (hypothesis) and a sympy oracle for
composite bodies with 3-1-3 Euler orientations."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dyncli.topics.inertia.model import Inertia
from dyncli.topics.inertia.solver import solve
from tests.topics.inertia.oracles import rotation

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])

coord = st.floats(-2.0, 2.0, allow_nan=False)
angle = st.floats(-math.pi, math.pi, allow_nan=False)
pos = st.floats(0.05, 3.0, allow_nan=False)
vec = st.tuples(coord, coord, coord)
euler = st.tuples(angle, angle, angle)


@st.composite
def part(draw):
    shape = draw(st.sampled_from(["point", "rod", "box", "cylinder", "disk", "ring", "sphere", "shell"]))
    d = {"shape": shape, "mass": draw(pos), "at": list(draw(vec)), "orientation": {"euler313": list(draw(euler))}}
    if shape == "rod":
        d["length"] = draw(pos)
    elif shape == "box":
        d["size"] = [draw(pos), draw(pos), draw(pos)]
    elif shape == "cylinder":
        d["radius"], d["height"] = draw(pos), draw(pos)
    elif shape in ("disk", "ring", "sphere", "shell"):
        d["radius"] = draw(pos)
    return d


bodies = st.lists(part(), min_size=1, max_size=4)


def run(parts, about=None, basis=None):
    d = {"type": "inertia", "parts": parts}
    if about is not None:
        d["about"] = list(about)
    if basis is not None:
        d["basis"] = basis
    return solve(Inertia.model_validate(d, context={"params": {}}))


def scale_of(res):
    """Magnitude of the inertia involved (for absolute tolerances): the
    result itself and the transfer terms that built it."""
    r = res.results
    reach = float(np.dot(r["com"], r["com"]) + np.dot(r["p_bar"], r["p_bar"]))
    return float(np.max(np.abs(r["I_about"]))) + float(np.max(np.abs(r["I_com"]))) + r["mass"] * (1e-6 + reach)


@SETTINGS
@given(bodies, euler, vec)
def test_rotation_of_the_whole_body(parts, q, about):
    Q = rotation(*q)
    r1 = run(parts, about)
    turned = []
    for p in parts:
        p2 = dict(p)
        Rp = rotation(*p["orientation"]["euler313"])
        p2["orientation"] = {"matrix": (Q @ Rp).tolist()}
        p2["at"] = (Q @ np.array(p["at"])).tolist()
        turned.append(p2)
    r2 = run(turned, Q @ np.array(about))
    s = scale_of(r1)
    I1, I2 = np.array(r1.results["I_about"]), np.array(r2.results["I_about"])
    assert np.trace(I2) == pytest.approx(np.trace(I1), rel=1e-11, abs=1e-12 * s)
    np.testing.assert_allclose(r2.results["principal_moments"], r1.results["principal_moments"], rtol=1e-9, atol=1e-11 * s)
    np.testing.assert_allclose(I2, Q @ I1 @ Q.T, rtol=0, atol=1e-11 * s)


@SETTINGS
@given(bodies, vec)
def test_triangle_inequality_and_principal_frame(parts, about):
    res = run(parts, about).results
    lam = np.array(res["principal_moments"])
    s = max(1e-300, lam.max())
    assert lam[0] >= 0 and np.all(np.diff(lam) >= 0)
    assert lam[0] + lam[1] >= lam[2] - 1e-12 * s
    Q = np.array(res["principal_axes"])
    np.testing.assert_allclose(Q.T @ Q, np.eye(3), atol=1e-12)
    assert np.linalg.det(Q) == pytest.approx(1.0, abs=1e-12)
    I = np.array(res["I_about"])
    np.testing.assert_allclose(I @ Q, Q * lam, atol=1e-10 * s)
    np.testing.assert_allclose(res["radii_of_gyration"], np.sqrt(lam / res["mass"]), rtol=1e-12, atol=1e-15)


@SETTINGS
@given(bodies, vec, vec)
def test_transfer_round_trip(parts, b1, b2):
    r1 = run(parts, b1).results
    m = r1["mass"]
    com = np.array(r1["com"])

    def T(B):
        p = com - np.asarray(B)
        return m * (p @ p * np.eye(3) - np.outer(p, p))

    s = max(scale_of(run(parts, b1)), np.abs(T(b2)).max())
    I_com = np.array(r1["I_about"]) - T(b1)                     # B1 -> com
    np.testing.assert_allclose(I_com, r1["I_com"], atol=1e-11 * s)
    r2 = run(parts, b2).results
    np.testing.assert_allclose(I_com + T(b2), r2["I_about"], atol=1e-11 * s)  # com -> B2
    np.testing.assert_allclose(r1["p_bar"], com - np.asarray(b1), atol=1e-12 * (1 + np.abs(b1).max()))


@SETTINGS
@given(bodies, euler)
def test_change_of_basis_30_36(parts, q):
    Q = rotation(*q)
    r0 = run(parts).results
    r1 = run(parts, basis={"matrix": Q.tolist()}).results
    s = max(1e-300, np.abs(r0["I_com"]).max())
    np.testing.assert_allclose(r1["I_com"], Q.T @ np.array(r0["I_com"]) @ Q, atol=1e-11 * s)
    np.testing.assert_allclose(r1["com"], Q.T @ np.array(r0["com"]), atol=1e-12 * (1 + np.abs(r0["com"]).max()))
    np.testing.assert_allclose(r1["principal_moments"], r0["principal_moments"], rtol=1e-9, atol=1e-11 * s)


@settings(max_examples=40, deadline=None)
@given(euler, st.floats(1e-9, 1e-7), st.floats(0.5, 2.0))
def test_nearly_repeated_moments_are_flagged_and_accurate(q, rel, I1):
    Q = rotation(*q)
    D = np.diag([I1, I1 * (1 + rel), 1.5 * I1])
    parts = [{"shape": "tensor", "mass": 1.0, "inertia": D.tolist(), "orientation": {"matrix": Q.tolist()}}]
    res = run(parts)
    r = res.results
    assert r["principal_axes_unique"] is True
    assert r["principal_gap"] == pytest.approx(I1 * rel, rel=1e-5)
    assert any("nearly repeated" in w for w in res.warnings)
    I = np.array(r["I_about"])
    Qa = np.array(r["principal_axes"])
    lam = np.array(r["principal_moments"])
    np.testing.assert_allclose(I @ Qa, Qa * lam, atol=1e-13 * 1.5 * I1)
    np.testing.assert_allclose(lam, [I1, I1 * (1 + rel), 1.5 * I1], rtol=1e-13)
    # the well-separated axis is still accurate
    assert abs(abs(Qa[:, 2] @ Q[:, 2]) - 1) < 1e-12


@settings(max_examples=30, deadline=None)
@given(euler)
def test_repeated_moments_canonical_and_deterministic(q):
    Q = rotation(*q)
    D = np.diag([1.0, 1.0 + 1e-14, 2.0])
    parts = [{"shape": "tensor", "mass": 1.0, "inertia": D.tolist(), "orientation": {"matrix": Q.tolist()}}]
    a = run(parts)
    b = run(parts)
    assert a.results["principal_axes"] == b.results["principal_axes"]
    assert a.results["principal_axes_unique"] is False
    Qa = np.array(a.results["principal_axes"])
    # the eigenspace is the plane normal to Q e3
    np.testing.assert_allclose(Qa[:, :2].T @ Q[:, 2], [0, 0], atol=1e-12)
    assert abs(abs(Qa[:, 2] @ Q[:, 2]) - 1) < 1e-12


def test_composite_with_euler_angles_matches_sympy():
    import sympy as sp
    from sympy.physics.mechanics import Point, ReferenceFrame, RigidBody, inertia

    N = ReferenceFrame("N")
    psi, th, ph = sp.Rational(3, 10), sp.Rational(7, 10), sp.Rational(-1, 2)
    A = N.orientnew("A", "Body", [psi, th, ph], "313")       # sympy's own 3-1-3 body sequence
    O = Point("O")
    # part 1: box 0.4 x 0.2 x 0.1, m = 3, at (0.5, 0.1, -0.2), turned by (ψ, θ, φ)
    G1 = O.locatenew("G1", sp.Rational(1, 2) * N.x + sp.Rational(1, 10) * N.y - sp.Rational(1, 5) * N.z)
    a, b, c, m1 = sp.Rational(2, 5), sp.Rational(1, 5), sp.Rational(1, 10), 3
    box = RigidBody("box", G1, A, m1, (inertia(A, m1 * (b**2 + c**2) / 12, m1 * (a**2 + c**2) / 12, m1 * (a**2 + b**2) / 12), G1))
    # part 2: rod of length 1, m = 2, along N.z, at (-0.3, 0, 0.4)
    G2 = O.locatenew("G2", -sp.Rational(3, 10) * N.x + sp.Rational(2, 5) * N.z)
    rod = RigidBody("rod", G2, N, 2, (inertia(N, sp.Rational(2, 12), sp.Rational(2, 12), 0), G2))
    I_O = (box.parallel_axis(O) + rod.parallel_axis(O)).to_matrix(N)
    ref = np.array(I_O.evalf(30).tolist(), dtype=float)
    res = run([
        {"shape": "box", "mass": 3, "size": [0.4, 0.2, 0.1], "at": [0.5, 0.1, -0.2],
         "orientation": {"euler313": [0.3, 0.7, -0.5]}},
        {"shape": "rod", "mass": 2, "length": 1, "at": [-0.3, 0, 0.4]},
    ], about=(0, 0, 0)).results
    np.testing.assert_allclose(res["I_about"], ref, rtol=1e-13, atol=1e-15)


def test_axis_angle_equals_matrix_and_euler():
    # 90° about e3 == Euler (90°, 0, 0) == matrix with columns e2, -e1, e3
    base = {"shape": "box", "mass": 1, "size": [1, 2, 3], "at": [0.1, 0.2, 0.3]}
    forms = [{"axis": [0, 0, 5], "angle": math.pi / 2}, {"euler313": [math.pi / 2, 0, 0]},
             {"matrix": [[0, -1, 0], [1, 0, 0], [0, 0, 1]]}]
    outs = [run([dict(base, orientation=f)]).results["I_com"] for f in forms]
    for o in outs:
        np.testing.assert_allclose(o, np.diag([(9 + 1) / 12, (4 + 9) / 12, (1 + 4) / 12]), atol=1e-15)
