"""rigid-energy with x/about (29.25), forces, couples and b (34.17-34.19) and a
prescribed motion (34.13-34.20); planar-moments with forces (32.6, 32.8).
Issue 21 item 6.  Independent routes: a point-mass model of the body for
H_O, the Newton–Euler equations (34.15) for the power, mpmath's numerical
derivative for Ṫ, and fixed-axis rotation about the pin for the bar."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.conftest import PROBLEMS, error_of, run_cli, solve_one_text, solve_path

RB = PROBLEMS / "rigid-bodies"
EPS = 2.3e-16


def _yaml_vec(v):
    return "[" + ", ".join(repr(float(x)) for x in v) + "]"


def test_rolling_disk_gallery():
    a, b = (rec["results"] for rec in solve_path(RB / "rolling-disk-energy.yaml"))
    m, R, v, g, beta = 2.0, 0.3, 1.5, 9.81, math.pi / 6
    assert a["T"] == pytest.approx(3.375, rel=4 * EPS)
    assert a["H_O"] == pytest.approx([0, 0, -1.5 * m * R * v], rel=4 * EPS, abs=1e-15)
    assert a["power_forces"] == pytest.approx([0.0, 0.0], abs=1e-14)      # the contact point is at rest
    assert a["power"] == pytest.approx(m * g * math.sin(beta) * v, rel=8 * EPS)
    acc = (2 / 3) * g * math.sin(beta)
    assert b["T_motion"] == pytest.approx([0, 0.75 * m * acc**2, 3 * m * acc**2], rel=8 * EPS)
    assert b["T_motion"][1] == pytest.approx(16.03935, rel=1e-12)
    assert b["T_rate"][1] == pytest.approx(m * g * math.sin(beta) * acc, rel=8 * EPS)   # = P (34.16)
    assert b["work"][2] == pytest.approx(m * g * math.sin(beta) * 0.5 * acc * 4, rel=8 * EPS)


def test_pinned_bar_gallery():
    (rec,) = solve_path(RB / "pinned-bar-forces.yaml")
    r = rec["results"]
    m, L, w, wd = 3.0, 1.2, 4.0, 2.0
    assert r["a_com"] == pytest.approx([-w * w * L / 2, wd * L / 2, 0], rel=4 * EPS)
    assert r["M_forces"] == pytest.approx([0, 0, -m * wd * L * L / 4], rel=8 * EPS, abs=1e-15)
    # second route: rotation about the fixed pin, I_pin = mL²/3 (31.7), the motor torque I_pin ω̇
    assert r["M_couple"] == pytest.approx([0, 0, m * L * L / 3 * wd], rel=8 * EPS, abs=1e-15)
    assert "32.6" in rec["equations"]


def _point_mass_body(I, m):
    """Six point masses m/6 at ±q_k e_k (e_k the principal axes of I) with the inertia I about their
    center: I_k = 2 Σ_{j≠k} μ q_j², so μ q_j² = (I1 + I2 + I3)/4 − I_j/2 (≥ 0 for a real body)."""
    lam, Q = np.linalg.eigh(I)
    mu = m / 6
    pts = []
    for k in range(3):
        q = math.sqrt(max(lam.sum() / 4 - lam[k] / 2, 0.0) / mu)
        pts += [Q[:, k] * q, -Q[:, k] * q]
    return pts, mu


@settings(max_examples=25, deadline=None)
@given(v=st.lists(st.floats(-5, 5), min_size=3, max_size=3), w=st.lists(st.floats(-5, 5), min_size=3, max_size=3),
       x=st.lists(st.floats(-3, 3), min_size=3, max_size=3), O=st.lists(st.floats(-3, 3), min_size=3, max_size=3),
       J=st.lists(st.floats(0.1, 1.0), min_size=3, max_size=3), ang=st.floats(-3, 3))
def test_H_O_against_a_point_mass_model(v, w, x, O, J, ang):
    c, s = math.cos(ang), math.sin(ang)
    Q = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])
    J = sorted(J)
    J[2] = min(J[2], J[0] + J[1])            # a real body (triangle inequality)
    I = Q @ np.diag(J) @ Q.T
    m = 3.0
    text = (f"type: rigid-energy\nm: {m}\nv: {_yaml_vec(v)}\nomega: {_yaml_vec(w)}\n"
            f"I: [{_yaml_vec(I[0])}, {_yaml_vec(I[1])}, {_yaml_vec(I[2])}]\nx: {_yaml_vec(x)}\nabout: {_yaml_vec(O)}\n")
    r = solve_one_text(text)["results"]
    xb, vb, wv, Ov = (np.array(a, dtype=float) for a in (x, v, w, O))
    pts, mu = _point_mass_body(I, m)
    H = sum(np.cross(xb + p - Ov, mu * (vb + np.cross(wv, p))) for p in pts)   # Σ xᵢ × mᵢ vᵢ (24.4a)
    scale = 1 + np.abs(xb - Ov).max() * m * np.abs(vb).max() + np.abs(I).max() * np.abs(wv).max()
    assert r["H_O"] == pytest.approx(H.tolist(), abs=1e-12 * scale)


@settings(max_examples=25, deadline=None)
@given(data=st.lists(st.floats(-4, 4), min_size=3 * 7, max_size=3 * 7))
def test_power_equals_the_newton_euler_rate_of_T(data):
    """(34.15): Ṫ = v̄·(ΣF + m b) + ω·(ΣM + Σ pᵢ × Fᵢ) for the accelerations of the Newton–Euler
    equations; (34.19) must give the same number."""
    v, w, x, F1, x1, M1, b = (np.array(data[3 * i:3 * i + 3]) for i in range(7))
    m = 2.0
    I = np.diag([0.3, 0.4, 0.5])
    text = (f"type: rigid-energy\nm: {m}\nv: {_yaml_vec(v)}\nomega: {_yaml_vec(w)}\n"
            "I: [[0.3, 0, 0], [0, 0.4, 0], [0, 0, 0.5]]\n"
            f"x: {_yaml_vec(x)}\nforces: [{{F: {_yaml_vec(F1)}, x: {_yaml_vec(x1)}}}]\nmoments: [{_yaml_vec(M1)}]\n"
            f"b: {_yaml_vec(b)}\n")
    r = solve_one_text(text)["results"]
    a = (F1 + m * b) / m                                   # m dv̄/dt = F (29.5)
    Mbar = M1 + np.cross(x1 - x, F1)                       # moment about the center of mass
    wdot = np.linalg.solve(I, Mbar - np.cross(w, I @ w))   # Euler's equations (29.22)
    Tdot = m * v @ a + w @ (I @ wdot)
    scale = 1 + np.abs(F1).max() * (np.abs(v).max() + np.abs(w).max() * np.abs(x1 - x).max()) \
        + np.abs(M1).max() * np.abs(w).max() + m * np.abs(b).max() * np.abs(v).max()
    assert r["power"] == pytest.approx(Tdot, abs=1e-13 * scale)


def test_motion_rate_against_numerical_derivative():
    text = ("type: rigid-energy\nm: 1.5\nI: [[0.2, 0.01, 0], [0.01, 0.3, 0.02], [0, 0.02, 0.4]]\n"
            "motion: {v: [\"sin(t)\", \"t**2\", 1], omega: [\"exp(-t)\", \"cos(3*t)\", \"t\"], at: [0.5, 1, 2.5]}\n")
    rec = solve_one_text(text)
    r = rec["results"]
    I = [[0.2, 0.01, 0], [0.01, 0.3, 0.02], [0, 0.02, 0.4]]
    with mp.workdps(30):
        def T(t):
            v = [mp.sin(t), t**2, 1]
            w = [mp.exp(-t), mp.cos(3 * t), t]
            return 0.75 * sum(c * c for c in v) + sum(w[i] * I[i][j] * w[j] for i in range(3) for j in range(3)) / 2
        for k, t in enumerate([0.5, 1, 2.5]):
            assert r["T_motion"][k] == pytest.approx(float(T(mp.mpf(t))), rel=1e-14)
            assert r["T_rate"][k] == pytest.approx(float(mp.diff(T, mp.mpf(t))), rel=1e-13)
            assert r["work"][k] == pytest.approx(float(T(mp.mpf(t)) - T(mp.mpf(0.5))), abs=1e-13)
    # v̄, ω default to the motion at its first time
    assert r["T"] == pytest.approx(r["T_motion"][0], rel=1e-15)


def test_extremes():
    base = "type: rigid-energy\nm: 2\nI: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"
    # ω = 0: a couple does no work; a force at the center of mass gives F·v̄
    r = solve_one_text(base + "v: [1, 0, 0]\nomega: [0, 0, 0]\nforces: [{F: [3, 4, 0]}]\nmoments: [[0, 0, 7]]\n")["results"]
    assert r["power_moments"] == [0.0] and r["power"] == 3.0 and r["power_body"] == 0.0
    # O at the center of mass: H_O = H̄
    r = solve_one_text(base + "v: [1, 2, 3]\nomega: [1, -1, 2]\nx: [4, 5, 6]\nabout: [4, 5, 6]\n")["results"]
    assert r["H_O"] == r["H"] and r["H_orbit"] == [0.0, 0.0, 0.0]
    # x without about: O is the origin
    r = solve_one_text(base + "v: [1, 0, 0]\nomega: [0, 0, 0]\nx: [0, 2, 0]\n")["results"]
    assert r["H_O"] == [0.0, 0.0, -4.0]
    # without the new fields nothing new is reported (the contract only adds)
    r = solve_one_text(base + "v: [1, 0, 0]\nomega: [0, 0, 0]\n")["results"]
    assert not {"H_O", "power", "T_motion"} & set(r)
    # a motion that is not differentiable at a requested time: exit 1 with one message
    rc, _, err = run_cli("solve", "-", input=base + "motion: {v: [\"sqrt(t)\", 0, 0], omega: [0, 0, 0], at: [0, 1]}\n")
    assert rc == 1 and "not finite" in err and "Traceback" not in err
    # planar-moments: forces summing to zero give ā = 0 and the couple is M̄ itself
    r = solve_one_text("type: planar-moments\nI13: 0\nI23: 0\nI33: 2\nomega: 1\nomega_dot: 3\nm: 1\n"
                       "forces: [{F: [1, 0, 0], x: [0, 1, 0]}, {F: [-1, 0, 0], x: [0, 1, 0]}]\n")["results"]
    assert r["a_com"] == [0.0, 0.0, 0.0] and r["M_couple"] == r["M"] == [0.0, 0.0, 6.0]


def test_planar_force_out_of_plane_warns():
    rec = solve_one_text("type: planar-moments\nI13: 0\nI23: 0\nI33: 2\nomega: 1\nm: 1\nforces: [{F: [0, 0, 1]}]\n")
    assert any("out of the plane" in w for w in rec["warnings"])


RE = "type: rigid-energy\nm: 1\nI: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"


@pytest.mark.parametrize("text,expected", [
    (RE + "omega: [0, 0, 1]\n", "v: required field is missing (or give a prescribed motion"),
    (RE + "v: [0, 0, 0]\nomega: [0, 0, 1]\nabout: [1, 0, 0]\n", "about: about (the point O for H_O) needs the position x"),
    (RE + "v: [0, 0, 0]\nomega: [0, 0, 1]\nforces: [{F: [1, 0, 0], x: [1, 0, 0]}]\n", "forces.0.x: a force's point of application x needs"),
    (RE + "v: [0, 0, 0]\nomega: [0, 0, 1]\nforces: [{F: [1, 0]}]\n", "forces.0.F"),
    (RE + "v: [0, 0, 0]\nomega: [0, 0, 1]\nforces: [{F: [1, 0, 0], at: [0, 0, 0]}]\n", "forces.0.at: unknown field"),
    (RE + "v: [0, 0, 0]\nomega: [0, 0, 1]\nmoments: [[1, 2]]\n", "moments.0"),
    (RE + "motion: {v: [t, 0, 0], omega: [0, 0, 0], at: []}\n", "motion.at"),
    (RE + "motion: {v: [t, 0, 0], omega: [0, 0, x], at: [0]}\n", "motion.omega"),
    (RE + "motion: {v: [t, 0, 0], omega: [0, 0, 0]}\n", "motion.at: required field is missing"),
    (RE + "v: [1e300, 0, 0]\nomega: [0, 0, 0]\nx: [0, 1e300, 0]\n", "H_O"),
    ("type: planar-moments\nI13: 0\nI23: 0\nI33: 1\nomega: 1\nforces: [{F: [1, 0, 0]}]\n", "m: forces need the mass m"),
    ("type: planar-moments\nI13: 0\nI23: 0\nI33: 1\nomega: 1\nm: 0\nforces: [{F: [1, 0, 0]}]\n", "m: must be > 0"),
])
def test_invalid(text, expected):
    msg = error_of(text)
    assert expected in msg, msg
    assert "Traceback" not in msg


def test_table_puts_each_time_of_the_motion_on_its_own_row():
    # v̄(t) and ω(t) were stacked in the results table without their times
    rc, out, err = run_cli("solve", str(PROBLEMS / "rigid-bodies/rolling-disk-energy.yaml"))
    assert rc == 0, err
    rows = [line.split() for line in out.splitlines() if "[3.27, 0, 0]" in line]
    assert len(rows) == 1 and rows[0][0] == "1"             # v̄ = a t at t = 1 s, a = (2/3) g sin 30°
