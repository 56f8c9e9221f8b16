"""rigid-velocity `rotations` (issue 27): nested rotations, ω = Ω + ω_rel and
ω̇ = Ω̇ + δω_rel/δt + Ω × ω_rel.  References: the hand derivation of the gallery file (a disk on a
turning axle), and a second route: the body's rotation matrix as a product of elementary
rotations in t, differentiated by sympy, ω and ω̇ read from Ṙ Rᵀ (the skew matrix of ω) — never
the composition rule under test."""

from __future__ import annotations

import pytest

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

TOL = 1e-12


def close(a, b, tol=TOL):
    assert len(a) == len(b) and all(abs(x - y) <= tol * max(1.0, abs(y)) for x, y in zip(a, b)), (a, b)


def test_gallery_disk_on_a_turning_axle_by_hand():
    (rec,) = solve_path(PROBLEMS / "kinematics" / "disk-on-turning-axle.yaml")
    r = rec["results"]
    Om, spin, spin_dot, rad = 2.0, 10.0, 3.0, 0.2
    assert r["omega"] == [spin, 0.0, Om]
    assert r["alpha"] == [spin_dot, Om * spin, 0.0]            # Ω × ω_rel = 2 e3 × 10 e1 = 20 e2
    assert r["alpha_coupling"] == [0.0, Om * spin, 0.0]
    close(r["v"]["top"], [0.0, 0.5 * Om - spin * rad, 0.0])
    close(r["a"]["top"], [-0.5 * Om ** 2 + Om * spin * rad + Om * spin * rad, -spin_dot * rad, -spin ** 2 * rad])
    assert "11.7" in rec["equations"]


def _chain(rates, t0=0.37):
    """The rotations Rz(ψ) Ry(θ) Rx(φ) with each angle q0 + q1 t + q2 t²/2 (a gimbal: an outer
    ring about e3, an inner ring about the outer's e2, a rotor about the inner's e1).  Returns the
    `rotations` entries (each relative ω_k and δω_k/δt on the fixed basis at t0) and the reference
    (ω, ω̇) from the skew matrix Ṙ Rᵀ."""
    import sympy as sp

    t = sp.symbols("t")
    ang = [q0 + q1 * t + q2 * t ** 2 / 2 for q0, q1, q2 in rates]
    c, s = sp.cos, sp.sin
    Rz = sp.Matrix([[c(ang[0]), -s(ang[0]), 0], [s(ang[0]), c(ang[0]), 0], [0, 0, 1]])
    Ry = sp.Matrix([[c(ang[1]), 0, s(ang[1])], [0, 1, 0], [-s(ang[1]), 0, c(ang[1])]])
    Rx = sp.Matrix([[1, 0, 0], [0, c(ang[2]), -s(ang[2])], [0, s(ang[2]), c(ang[2])]])
    R = Rz * Ry * Rx
    S = R.diff(t) * R.T
    w = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])
    at = {t: t0}
    ref_w = [float(x.evalf(subs=at)) for x in w]
    ref_a = [float(x.evalf(subs=at)) for x in w.diff(t)]
    # each rotation's axis is fixed in the frame before: its relative rate seen there is q̈ × axis
    axes = [sp.Matrix([0, 0, 1]), Rz * sp.Matrix([0, 1, 0]), Rz * Ry * sp.Matrix([1, 0, 0])]
    entries = []
    for q, axis in zip(ang, axes):
        om = [float((q.diff(t) * x).evalf(subs=at)) for x in axis]
        od = [float((q.diff(t, 2) * x).evalf(subs=at)) for x in axis]
        entries.append((om, od))
    return entries, ref_w, ref_a


@pytest.mark.parametrize("rates", [
    [(0.3, 2.0, 0.0), (0.0, 0.0, 0.0), (1.0, 10.0, 3.0)],         # the disk on an axle (two levels)
    [(0.3, 2.0, -1.0), (0.7, -0.5, 0.4), (1.0, 50.0, 3.0)],        # a gimbal, every rate nonzero
    [(-2.0, 0.1, 5.0), (1.4, 3.0, -2.0), (0.0, -7.0, 0.0)],
])
def test_against_the_rotation_matrix_differentiated(rates):
    entries, ref_w, ref_a = _chain(rates)
    rot = "\n".join(f"  - {{omega: {om!r}, omega_dot: {od!r}}}" for om, od in entries)
    r = solve_one_text(f"type: rigid-velocity\nrotations:\n{rot}\npoints: {{P: [0.1, 0.2, 0.3]}}\n")["results"]
    close(r["omega"], ref_w)
    close(r["alpha"], ref_a)


def test_one_rotation_is_omega_and_alpha():
    a = solve_one_text("type: rigid-velocity\nvB: [1, 2, 0]\naB: [0, 1, 1]\nrotations: [{omega: [1, 2, 3], "
                       "omega_dot: [0.5, 0, -1]}]\npoints: {P: [0.3, -0.2, 1]}\n")["results"]
    b = solve_one_text("type: rigid-velocity\nvB: [1, 2, 0]\naB: [0, 1, 1]\nomega: [1, 2, 3]\n"
                       "alpha: [0.5, 0, -1]\npoints: {P: [0.3, -0.2, 1]}\n")["results"]
    assert a["v"] == b["v"] and a["a"] == b["a"] and a["alpha_coupling"] == [0.0, 0.0, 0.0]


@pytest.mark.parametrize("text,field,fix", [
    ("omega: [0, 0, 1]\nrotations: [{omega: [0, 0, 1]}]\n", "omega", "not both"),
    ("alpha: [0, 0, 1]\nrotations: [{omega: [0, 0, 1]}]\n", "alpha", "not both"),
    ("rolling: {contact: [0, -1, 0]}\nrotations: [{omega: [0, 0, 1]}]\n", "rolling", "not both"),
    ("rotations: []\n", "rotations", "the outermost first"),
    ("rotations: [{omega_dot: [0, 0, 1]}]\n", "rotations.0.omega", "required"),
    ("rotations: [{omega: [0, 0, 1], alpha: [0, 0, 1]}]\n", "rotations.0.alpha", "unknown field"),
])
def test_invalid_rotations(text, field, fix):
    msg = error_of("type: rigid-velocity\n" + text + "points: {P: [0, 1, 0]}\n")
    assert f" {field}:" in msg and fix in msg, msg
