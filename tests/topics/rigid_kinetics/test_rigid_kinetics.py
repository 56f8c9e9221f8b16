"""planar-moments, rigid-energy, spin-change and motor-bodies against
independent routes: sympy differentiation of H in the fixed frame, a
point-mass model of the body, distances computed with cross products, and
the full angular-momentum vector of the motor system assembled in 3-D."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.conftest import PROBLEMS, run_cli, solve_one_text, solve_path
from tests.topics.inertia.oracles import rotation

RB = PROBLEMS / "rigid-bodies"


def results(name):
    (rec,) = solve_path(RB / name)
    assert rec.get("error") is None, rec
    return rec


# ---------------------------------------------------------------- planar-moments

@functools.lru_cache(maxsize=1)
def _planar_symbolic():
    """M̄ = dH̄/dt derived by sympy in the FIXED frame, then put on e'_i,
    with symbols (I13, I23, I33, ω, ω̇)."""
    import sympy as sp

    t = sp.Symbol("t")
    I13, I23, I33, w, wd = sp.symbols("I13 I23 I33 w wd")
    th = sp.Function("theta")(t)
    Q = sp.Matrix([[sp.cos(th), -sp.sin(th), 0], [sp.sin(th), sp.cos(th), 0], [0, 0, 1]])  # columns e'_i
    Ib = sp.Matrix([[0, 0, I13], [0, 0, I23], [I13, I23, I33]])  # Ī'11, Ī'22, Ī'12 do not matter
    H_fixed = Q * Ib * sp.Matrix([0, 0, th.diff(t)])
    M_body = (Q.T * H_fixed.diff(t)).subs(th.diff(t, 2), wd).subs(th.diff(t), w)
    return M_body.applyfunc(sp.simplify), (I13, I23, I33, w, wd)


def planar_reference(I13, I23, I33, w, wd):
    M, syms = _planar_symbolic()
    vals = dict(zip(syms, (I13, I23, I33, w, wd)))
    return [float(x.subs(vals)) for x in M]


def test_wobbling_disk_example():
    rec = results("wobbling-disk.yaml")
    m, R, b = 2.0, 0.1, math.radians(5)
    # the disk's Ī'_{ij} from the inertia type (an independent route to the I's)
    inert = solve_one_text(f"type: inertia\nparts: [{{shape: disk, mass: {m}, radius: {R}, orientation: {{axis: [1, 0, 0], angle: {b!r}}}}}]\n")["results"]["I_com"]
    I13, I23, I33 = inert[0][2], inert[1][2], inert[2][2]
    ref = planar_reference(I13, I23, I33, 100.0, 0.0)
    np.testing.assert_allclose(rec["results"]["M"], ref, rtol=1e-12, atol=1e-12)
    assert rec["results"]["M"][0] == pytest.approx(0.25 * m * R * R * math.sin(b) * math.cos(b) * 1e4, rel=1e-13)
    assert rec["results"]["purely_planar"] is False


@settings(max_examples=25, deadline=None)
@given(st.floats(-1, 1), st.floats(-1, 1), st.floats(0, 2), st.floats(-50, 50), st.floats(-20, 20))
def test_planar_moments_vs_fixed_frame_derivative(I13, I23, I33, w, wd):
    rec = solve_one_text(f"type: planar-moments\nI13: {I13!r}\nI23: {I23!r}\nI33: {I33!r}\nomega: {w!r}\nomega_dot: {wd!r}\n")
    ref = planar_reference(I13, I23, I33, w, wd)
    np.testing.assert_allclose(rec["results"]["M"], ref, rtol=1e-12, atol=1e-12 * (1 + w * w + abs(wd)))


def test_purely_planar_32_15():
    rec = solve_one_text("type: planar-moments\nI13: 0\nI23: 0\nI33: 2\nomega: 5\nomega_dot: 3\n")
    assert rec["results"]["M"] == [0.0, 0.0, 6.0]
    assert rec["results"]["purely_planar"] is True
    assert "32.15" in rec["equations"]


@pytest.mark.parametrize("F, x", [("[1e308, 0, 0]", "[0, 0, 0]"), ("[1e308, 0, 0]", "[0, 1e300, 0]")])
def test_planar_forces_whose_sum_or_moment_overflows_exit_2(F, x):
    """Σ Fᵢ or Σ pᵢ × Fᵢ beyond ~1e308: one line naming the forces, never an internal error."""
    doc = f"type: planar-moments\nI13: 0\nI23: 0\nI33: 1\nomega: 1\nm: 1\nforces:\n- {{F: {F}, x: {x}}}\n- {{F: {F}, x: [0, 0, 0]}}\n"
    code, out, err = run_cli("solve", "-", input=doc)
    assert code == 2, (out, err)
    assert "forces (their resultant or moment) overflows a double" in err and "Traceback" not in err


# ---------------------------------------------------------------- rigid-energy

def particle_model(m, I):
    """Six point masses m/6 at ±d_k along the principal axes of the second
    moment J = ½tr(I)1 − I: same mass, center of mass and inertia tensor."""
    I = np.asarray(I, float)
    J = 0.5 * np.trace(I) * np.eye(3) - I
    lam, V = np.linalg.eigh(J)
    pts = []
    for k in range(3):
        d = math.sqrt(max(lam[k], 0.0) * 3.0 / m)
        pts += [d * V[:, k], -d * V[:, k]]
    return np.array(pts), np.full(6, m / 6.0)


def energy_reference(m, v, w, I):
    pts, ms = particle_model(m, I)
    v, w = np.asarray(v, float), np.asarray(w, float)
    vel = v + np.cross(w, pts)
    T = 0.5 * float(np.sum(ms * np.sum(vel * vel, axis=1)))
    H = np.sum(ms[:, None] * np.cross(pts, np.cross(w, pts)), axis=0)
    return T, H


def test_tumbling_body_example():
    rec = results("tumbling-body.yaml")
    r = rec["results"]
    I = [[0.5, -0.1, 0.05], [-0.1, 0.8, 0], [0.05, 0, 1.1]]
    T, H = energy_reference(6, [1, 2, 0], [3, -1, 2], I)
    assert r["T"] == pytest.approx(T, rel=1e-13)
    assert r["T_trans"] == pytest.approx(15.0, rel=1e-15)
    assert r["T_rot"] == pytest.approx(T - 15.0, rel=1e-12)
    np.testing.assert_allclose(r["H"], H, rtol=1e-12)
    np.testing.assert_allclose(r["H"], [1.7, -1.1, 2.35], rtol=1e-14)


@settings(max_examples=40, deadline=None)
@given(st.tuples(*[st.floats(-3, 3)] * 3), st.tuples(*[st.floats(-3, 3)] * 3),
       st.tuples(*[st.floats(0.1, 2)] * 3), st.tuples(*[st.floats(-math.pi, math.pi)] * 3), st.floats(0.1, 10))
def test_rigid_energy_vs_point_mass_model(v, w, J, q, m):
    # a physical, non-diagonal I: J (second moments) positive, turned by q
    Q = rotation(*q)
    Jt = Q @ np.diag(J) @ Q.T
    I = np.trace(Jt) * np.eye(3) - Jt
    I = 0.5 * (I + I.T)
    rows = ", ".join("[" + ", ".join(repr(float(x)) for x in row) + "]" for row in I)
    rec = solve_one_text(f"type: rigid-energy\nm: {m!r}\nv: {list(map(float, v))}\nomega: {list(map(float, w))}\nI: [{rows}]\n")
    T, H = energy_reference(m, v, w, I)
    scale = 1 + 0.5 * m * np.dot(v, v) + np.trace(I) * np.dot(w, w)
    assert rec["results"]["T"] == pytest.approx(T, abs=1e-12 * scale)
    np.testing.assert_allclose(rec["results"]["H"], H, atol=1e-12 * scale)
    assert rec["results"]["T_rot"] >= 0


# ---------------------------------------------------------------- spin-change

def axial(x, e):
    e = np.asarray(e, float) / np.linalg.norm(e)
    c = np.cross(e, x)
    return float(c @ c)


def test_spinning_arms_36_22():
    r = results("spinning-arms.yaml")["results"]
    a0, a, w0, m, L = math.radians(60), math.radians(30), 2.0, 1.0, 0.5
    assert r["omega"] == pytest.approx((math.sin(a0) / math.sin(a)) ** 2 * w0, rel=1e-14)
    assert r["omega"] == pytest.approx(6.0, rel=1e-14)
    assert r["I_before"] == pytest.approx(2 * m * L * L * math.sin(a0) ** 2, rel=1e-14)
    assert r["I_after"] == pytest.approx(2 * m * L * L * math.sin(a) ** 2, rel=1e-14)
    # (36.21): H_O = 2 m ω L² sin²α e'2 is the same before and after
    assert r["I_after"] * r["omega"] == pytest.approx(2 * m * w0 * L * L * math.sin(a0) ** 2, rel=1e-14)


def test_spin_change_general_example():
    r = results("spin-change-general.yaml")["results"]
    e = [1, 1, 1]
    before = [(1, (1, 0, 0)), (2, (0, 0.5, -0.5)), (0.5, (0, 0, 0))]
    after = [(1, (0.5, 0, 0)), (2, (1, 1, 1)), (0.5, (0, 0, 1))]
    Ib = 0.8 + sum(m * axial(np.array(x, float), e) for m, x in before)
    Ia = 0.8 + sum(m * axial(np.array(x, float), e) for m, x in after)
    assert r["I_before"] == pytest.approx(Ib, rel=1e-14)
    assert r["I_after"] == pytest.approx(Ia, rel=1e-14)
    assert r["I_before"] == pytest.approx(0.8 + 2 / 3 + 1.0, rel=1e-14)
    assert r["I_after"] == pytest.approx(1.3, rel=1e-14)
    assert r["omega"] == pytest.approx(3 * Ib / Ia, rel=1e-14)
    assert r["work"] == pytest.approx(0.5 * Ia * r["omega"] ** 2 - 0.5 * Ib * 9, rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(0.1, 5), st.tuples(*[st.floats(-2, 2)] * 3), st.tuples(*[st.floats(-2, 2)] * 3)),
                min_size=1, max_size=4),
       st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda e: np.linalg.norm(e) > 0.1),
       st.floats(-10, 10), st.floats(0.05, 2))
def test_spin_change_conserves_axial_momentum(masses, e, w0, I0):
    items = "\n".join(f"  - {{m: {m!r}, before: {list(map(float, b))}, after: {list(map(float, a))}}}" for m, b, a in masses)
    rec = solve_one_text(f"type: spin-change\naxis: {list(map(float, e))}\nomega0: {w0!r}\nI0: {I0!r}\nmasses:\n{items}\n")
    r = rec["results"]
    Ib = I0 + sum(m * axial(np.array(b), e) for m, b, a in masses)
    Ia = I0 + sum(m * axial(np.array(a), e) for m, b, a in masses)
    assert r["I_before"] == pytest.approx(Ib, rel=1e-12)
    assert r["I_after"] == pytest.approx(Ia, rel=1e-12)
    assert r["I_after"] * r["omega"] == pytest.approx(Ib * w0, rel=1e-12, abs=1e-300)


# ---------------------------------------------------------------- motor-bodies

def motor_reference(IA1, IA2, mA, L, IB2, alpha, p, IB1=0.37):
    """Assemble H_O (36.34) as 3-D vectors on e''_i (= identity here) and
    solve H_O·e''2 = 0 (36.31) for Ω: H is affine in Ω."""
    e1 = np.array([math.cos(alpha), math.sin(alpha), 0.0])      # shaft e'''1 (36.24a)
    e2 = np.array([0.0, 1.0, 0.0])                              # fixed axis e''2

    def H(Om):
        Omega = Om * e2
        xA = L * e1
        vA = np.cross(Omega, xA)
        IA = IA2 * np.eye(3) + (IA1 - IA2) * np.outer(e1, e1)   # (36.32) on e''
        wA = Omega + p * e1                                     # (36.25)
        IB = np.diag([IB1, IB2, IB1])                           # (36.33)
        return np.cross(xA, mA * vA) + IA @ wA + IB @ Omega

    h0, h1 = H(0.0) @ e2, H(1.0) @ e2
    return -h0 / (h1 - h0)


def test_motor_disks_example():
    r = results("motor-disks.yaml")["results"]
    ref = motor_reference(0.01, 0.005, 2, 0.3, 0.1, math.radians(30), 100)
    assert r["Omega"] == pytest.approx(ref, rel=1e-13)
    assert r["Omega"] == pytest.approx(-2.0725388601036263, rel=1e-12)
    assert r["Omega"] < 0  # opposite to p for 0 < α < π/2 (notes after 36.40)


@settings(max_examples=40, deadline=None)
@given(st.floats(0, 2), st.floats(0.01, 2), st.floats(0, 5), st.floats(0, 2), st.floats(0.01, 3),
       st.floats(-math.pi, math.pi), st.floats(-500, 500))
def test_motor_bodies_vs_vector_assembly(IA1, IA2, mA, L, IB2, alpha, p):
    rec = solve_one_text(f"type: motor-bodies\nIA1: {IA1!r}\nIA2: {IA2!r}\nmA: {mA!r}\nL: {L!r}\nIB2: {IB2!r}\nalpha: {alpha!r}\np: {p!r}\n")
    ref = motor_reference(IA1, IA2, mA, L, IB2, alpha, p)
    assert rec["results"]["Omega"] == pytest.approx(ref, rel=1e-10, abs=1e-12 * (1 + abs(p)))


def test_templates_solve():
    for name in ("inertia", "planar-moments", "rigid-energy", "spin-change", "motor-bodies"):
        rc, out, err = run_cli("new", name)
        assert rc == 0, err
        rec = solve_one_text(out)
        assert rec["type"] == name


def test_table_views_show_transfer_and_principal_columns():
    rc, out, err = run_cli("solve", str(PROBLEMS / "inertia" / "box-about-corner.yaml"))
    assert rc == 0, err
    assert "transfer theorem (31.7)" in out
    assert "principal moments and directions (columns)" in out
    assert "+Δ" in out and "=I_B" in out
