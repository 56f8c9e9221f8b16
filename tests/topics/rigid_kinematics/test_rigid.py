"""rigid-velocity, angular-velocity, screw, contact (§13-§15): references
re-derived here with numpy (13.8-13.20, 14.3-14.9, 15.8-15.9)."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

KIN = PROBLEMS / "kinematics"


def close(a, b, tol=1e-12):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert np.allclose(a, b, rtol=tol, atol=tol), (a, b)


def y(v) -> str:
    return json.dumps([float(c) for c in v])


num = st.floats(-5, 5, allow_nan=False, allow_infinity=False)
vec = st.lists(num, min_size=3, max_size=3).map(np.array)
SET = settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])


# ---------------------------------------------------------------------------
# rigid-velocity (13.8, 13.9)


def test_rolling_wheel_example():
    (rec,) = solve_path(KIN / "rolling-wheel-points.yaml")
    r = rec["results"]
    rr, vB, aB = 0.5, 2.0, 0.5
    w, al = vB / rr, aB / rr
    close(r["v"]["contact"], [0, 0, 0])                  # rolling: the contact point is at rest
    close(r["a"]["contact"], [0, rr * w * w, 0])        # ... and accelerates toward the center
    close(r["v"]["top"], [2 * vB, 0, 0])
    close(r["a"]["top"], [2 * aB, -rr * w * w, 0])
    close(r["v"]["front"], [vB, -w * rr, 0])
    close(r["a"]["front"], [aB - w * w * rr, -al * rr, 0])


@SET
@given(vB=vec, aB=vec, w=vec, al=vec, xA=vec, xC=vec)
def test_rigid_velocity_identities(vB, aB, w, al, xA, xC):
    rec = solve_one_text(f"type: rigid-velocity\nvB: {y(vB)}\naB: {y(aB)}\nomega: {y(w)}\nalpha: {y(al)}\n"
                         f"points: {{A: {y(xA)}, C: {y(xC)}}}\n")
    v, a = rec["results"]["v"], rec["results"]["a"]
    vA, vC = np.array(v["A"]), np.array(v["C"])
    scale = 1 + np.abs(np.concatenate([vB, w, xA, xC])).max() ** 2
    # (13.7): v_A/B·x_A/B = 0 and v_A/C·x_A/C = 0
    assert abs((vA - vB) @ xA) <= 1e-12 * scale ** 1.5
    assert abs((vA - vC) @ (xA - xC)) <= 1e-12 * scale ** 1.5
    close(a["A"], aB + np.cross(al, xA) + np.cross(w, np.cross(w, xA)), 1e-12 * scale ** 1.5)


# ---------------------------------------------------------------------------
# angular-velocity (13.13, 13.17, 13.20)


def omega_13_13(vA, vC, xC):
    return np.cross(vA, vC) / (vA @ xC)


def omega_13_17(vA, vC, xA, xC):
    N = np.cross(xA, xC)
    return (vC @ vC) / (vC @ N) * xA - (vA @ vA) / (vA @ N) * xC


def test_three_point_examples():
    recs = solve_path(KIN / "three-point-omega.yaml")
    r0, r1, r2 = (r["results"] for r in recs)
    w = np.array([1, -2, 0.5])
    close(r0["omega"], w)
    close(r0["omega"], omega_13_13(np.array([0, 0.5, 2]), np.array([-3, -1, 2]), np.array([0, 2, 1])))
    assert r0["rigid"] is True and r0["omega_in_plane"] is False
    assert "13.13" in recs[0]["equations"]
    close(r1["omega"], [2, 1, 0])
    close(r1["omega"], omega_13_17(np.array([0, 0, -1.0]), np.array([0, 0, 2.0]), np.array([1, 0, 0.0]),
                                   np.array([0, 1, 0.0])))
    assert r1["omega_in_plane"] is True and "13.17" in recs[1]["equations"]
    close(r2["omega_n"], [0, -1, 0])
    assert "omega" not in r2 and r2["rigid"] is True


@SET
@given(vB=vec, w=vec, xB=vec, xA=vec, xC=vec)
def test_recover_omega_from_three_points(vB, w, xB, xA, xC):
    N = np.cross(xA, xC)
    assume(np.linalg.norm(N) > 1e-2 * (1 + np.linalg.norm(xA) * np.linalg.norm(xC)))
    vA, vC = vB + np.cross(w, xA), vB + np.cross(w, xC)
    rec = solve_one_text("type: angular-velocity\npoints:\n"
                         f"  B: {{x: {y(xB)}, v: {y(vB)}}}\n"
                         f"  A: {{x: {y(xB + xA)}, v: {y(vA)}}}\n"
                         f"  C: {{x: {y(xB + xC)}, v: {y(vC)}}}\n")
    r = rec["results"]
    scale = (1 + np.abs(np.concatenate([w, xA, xC, vB])).max()) ** 4 / np.linalg.norm(N)
    assert np.allclose(r["omega"], w, atol=1e-11 * scale)
    assert r["rigid"] is True, rec["warnings"]
    D = (vA - vB) @ xC
    if abs(D) > 0.1 * np.linalg.norm(vA - vB) * np.linalg.norm(xC):
        assert np.allclose(r["omega"], omega_13_13(vA - vB, vC - vB, xC), atol=1e-10 * scale)


@SET
@given(vB=vec, w=vec, xA=vec)
def test_two_points_normal_component(vB, w, xA):
    L = np.linalg.norm(xA)
    assume(L > 1e-2)
    rec = solve_one_text("type: angular-velocity\npoints:\n"
                         f"  B: {{x: [0, 0, 0], v: {y(vB)}}}\n"
                         f"  A: {{x: {y(xA)}, v: {y(vB + np.cross(w, xA))}}}\n")
    e = xA / L
    scale = (1 + np.abs(np.concatenate([w, xA])).max()) ** 3 / L ** 2
    assert np.allclose(rec["results"]["omega_n"], w - (w @ e) * e, atol=1e-12 * scale)   # (13.20)


def test_not_rigid_warns():
    rec = solve_one_text("""
type: angular-velocity
points:
  B: {x: [0, 0, 0], v: [0, 0, 0]}
  A: {x: [1, 0, 0], v: [1, 1, 0]}
  C: {x: [0, 1, 0], v: [0, 0, 1]}
""")
    assert rec["results"]["rigid"] is False
    # dd/dt of |x_A/B| is 1; the largest relative speed is |v_A/C| = √3
    assert rec["results"]["rigid_residual"] == pytest.approx(1 / np.sqrt(3))
    assert any("not those of a rigid body" in w and "B-A" in w for w in rec["warnings"])


def test_collinear_points_rejected():
    msg = error_of("""type: angular-velocity
points:
  B: {x: [0, 0, 0], v: [0, 0, 0]}
  A: {x: [1, 1, 0], v: [0, 0, 1]}
  C: {x: [2, 2, 0], v: [0, 0, 2]}
""")
    assert msg.startswith("bad.yaml:5:") and "collinear" in msg and "along that line" in msg


def test_angular_velocity_bad_counts_and_coincident():
    msg = error_of("type: angular-velocity\npoints:\n  B: {x: [0, 0, 0], v: [0, 0, 0]}\n")
    assert "two points" in msg and "got 1" in msg
    msg = error_of("type: angular-velocity\npoints:\n  B: {x: [0, 0, 0], v: [0, 0, 0]}\n"
                   "  A: {x: [0, 0, 0], v: [1, 0, 0]}\n")
    assert "same position" in msg and "bad.yaml:4:" in msg
    msg = error_of("type: angular-velocity\npoints:\n  B: {x: [0, 0, 0]}\n  A: {x: [1, 0, 0], v: [1, 0, 0]}\n")
    assert "points.B.v" in msg and "required" in msg


# ---------------------------------------------------------------------------
# screw (14.3-14.9)


def test_screw_examples():
    gen, planar = (r["results"] for r in solve_path(KIN / "screw-axis.yaml"))
    close(gen["e_omega"], [1 / 3, 2 / 3, 2 / 3])
    close(gen["advance_speed"], 5 / 3)
    close(gen["xD"], [1 + 2 / 9, 1 + 5 / 9, -6 / 9])
    close(gen["pitch"], 5 / 9)
    assert gen["instant_center"] is None
    close(planar["instant_center"], [1, 2, 0])
    close(planar["pitch"], 0.0)


@SET
@given(w=vec, vB=vec, xB=vec)
def test_screw_axis_properties(w, vB, xB):
    assume(np.linalg.norm(w) > 1e-3)
    rec = solve_one_text(f"type: screw\nomega: {y(w)}\nvB: {y(vB)}\nxB: {y(xB)}\n")
    r = rec["results"]
    xD = np.array(r["xD"])
    vD = vB + np.cross(w, xD - xB)                     # (14.5)
    scale = (1 + np.abs(np.concatenate([w, vB, xB])).max()) ** 2 / np.linalg.norm(w)
    e = w / np.linalg.norm(w)
    # every point of the axis moves along it with the advance speed (14.4)
    assert np.allclose(vD, r["advance_speed"] * e, atol=1e-11 * scale)
    # D is the point of the axis nearest B: x_D/B ⟂ ω (14.7)
    assert abs((xD - xB) @ w) <= 1e-11 * scale * np.linalg.norm(w)
    assert r["advance_speed"] == pytest.approx(vB @ e, abs=1e-12 * scale)


@SET
@given(wz=num, vx=num, vy=num, xB=vec)
def test_planar_instant_center_is_at_rest(wz, vx, vy, xB):
    assume(abs(wz) > 1e-3)
    rec = solve_one_text(f"type: screw\nomega: [0, 0, {wz!r}]\nvB: [{vx!r}, {vy!r}, 0]\nxB: {y(xB)}\n")
    c = np.array(rec["results"]["instant_center"])
    vC = np.array([vx, vy, 0]) + np.cross([0, 0, wz], c - xB)
    assert np.allclose(vC, 0, atol=1e-11 * (1 + abs(vx) + abs(vy)) * (1 + 1 / abs(wz)))
    assert np.linalg.norm(c - xB) == pytest.approx(np.hypot(vx, vy) / abs(wz), rel=1e-12, abs=1e-12)


def test_pure_translation():
    rec = solve_one_text("type: screw\nomega: [0, 0, 0]\nvB: [3, 0, 4]\n")
    r = rec["results"]
    assert r["pure_translation"] is True and r["advance_speed"] == 5.0
    assert r["e_omega"] is None and r["xD"] is None and r["pitch"] is None and r["instant_center"] is None
    assert any("pure translation" in w for w in rec["warnings"])


def test_screw_invalid():
    msg = error_of("type: screw\nomega: [0, 0]\nvB: [1, 0, 0]\n")
    assert msg.startswith("bad.yaml:2:") and "omega" in msg
    msg = error_of("type: screw\nomega: [0, 0, 1]\n")
    assert "vB" in msg and "required" in msg


# ---------------------------------------------------------------------------
# contact (15.8, 15.9)


def test_rolling_disk_examples():
    recs = solve_path(KIN / "rolling-disk.yaml")
    roll, slip, sep = (r["results"] for r in recs)
    r_, v = 0.5, 2.0
    for res, w in ((roll, 4.0), (slip, 5.0)):
        close(res["v_rel"], [w * r_ - v, 0, 0])                     # (15.9b)
        close(res["approach"], 0.0)
    assert roll["rolling"] is True and roll["state"] == "rolling" and roll["slip_speed"] == 0.0
    assert slip["rolling"] is False and slip["state"] == "slipping"
    close(slip["slip"], [0.5, 0, 0]) and close(slip["slip_speed"], 0.5)
    assert sep["state"] == "separating" and sep["approach"] == pytest.approx(-1.0)


@SET
@given(v1=vec, w1=vec, r1=vec, v2=vec, w2=vec, r2=vec, n=vec)
def test_contact_decomposition(v1, w1, r1, v2, w2, r2, n):
    assume(np.linalg.norm(n) > 1e-3)
    rec = solve_one_text(f"type: contact\nbody1: {{v: {y(v1)}, omega: {y(w1)}, r: {y(r1)}}}\n"
                         f"body2: {{v: {y(v2)}, omega: {y(w2)}, r: {y(r2)}}}\nn: {y(n)}\n")
    r = rec["results"]
    vrel = v1 + np.cross(w1, r1) - v2 - np.cross(w2, r2)
    nh = n / np.linalg.norm(n)
    scale = 1 + np.abs(np.concatenate([v1, w1, r1, v2, w2, r2])).max() ** 2
    assert np.allclose(r["v_rel"], vrel, atol=1e-12 * scale)
    assert r["approach"] == pytest.approx(vrel @ nh, abs=1e-12 * scale)
    assert abs(np.array(r["slip"]) @ nh) <= 1e-12 * scale
    assert np.allclose(np.array(r["slip"]) + r["approach"] * nh, vrel, atol=1e-12 * scale)
    assert r["state"] in ("rolling", "slipping", "separating", "approaching")
    assert r["rolling"] == (r["state"] == "rolling")
    if r["state"] == "separating":
        assert r["approach"] < 0


def test_contact_invalid():
    msg = error_of("type: contact\nbody1: {v: [0, 0, 0]}\nbody2: {}\nn: [0, 0, 0]\n")
    assert msg.startswith("bad.yaml:4:") and "non-zero" in msg
    msg = error_of("type: contact\nbody1: {velocity: [0, 0, 0]}\nbody2: {}\nn: [0, 1, 0]\n")
    assert "unknown field 'velocity'" in msg


# ---------------------------------------------------------------------------
# extremes


@settings(max_examples=60, deadline=None)
@given(w=vec, vB=vec, xA=vec, xC=vec, k=st.integers(-8, 8), j=st.integers(-8, 8))
def test_omega_scale_invariance(w, vB, xA, xC, k, j):
    """Positions scaled by 10^k and velocities by 10^j: ω scales by 10^(j-k)
    and the data stay rigid (no absolute tolerances hidden anywhere)."""
    N = np.cross(xA, xC)
    assume(np.linalg.norm(N) > 1e-2 * (1 + np.linalg.norm(xA) * np.linalg.norm(xC)))
    assume(np.linalg.norm(w) > 1e-3)
    L, V = 10.0 ** k, 10.0 ** j
    vA, vC = vB + np.cross(w, xA), vB + np.cross(w, xC)
    rec = solve_one_text("type: angular-velocity\npoints:\n"
                         f"  B: {{x: [0, 0, 0], v: {y(V * vB)}}}\n"
                         f"  A: {{x: {y(L * xA)}, v: {y(V * vA)}}}\n"
                         f"  C: {{x: {y(L * xC)}, v: {y(V * vC)}}}\n")
    scale = (1 + np.abs(np.concatenate([w, xA, xC, vB])).max()) ** 4 / np.linalg.norm(N)
    assert np.allclose(np.array(rec["results"]["omega"]) * L / V, w, atol=1e-10 * scale)
    assert rec["results"]["rigid"] is True


def test_screw_overflow_is_null():
    rec = solve_one_text("type: screw\nomega: [1e-200, 0, 0]\nvB: [0, 1e200, 0]\n")
    r = rec["results"]
    assert r["xD"] is None and r["instant_center"] is None
    assert r["e_omega"] == [1.0, 0.0, 0.0] and r["advance_speed"] == 0.0
    assert any("overflows" in w for w in rec["warnings"])


def test_contact_tolerance_is_relative():
    # ω r = v with large magnitudes and decimals: still rolling
    rec = solve_one_text("type: contact\nbody1: {v: [-3e5, 0, 0], omega: [0, 0, '3e5/0.7'], r: [0, -0.7, 0]}\n"
                         "body2: {}\nn: [0, -1, 0]\n")
    assert rec["results"]["state"] == "rolling"
    rec = solve_one_text("type: contact\nbody1: {v: [-3e-5, 0, 0], omega: [0, 0, 1e-5], r: [0, -0.7, 0]}\n"
                         "body2: {}\nn: [0, -1, 0]\n")
    assert rec["results"]["state"] == "slipping"


def test_closed_forms_import_neither_sympy_nor_scipy():
    import subprocess
    import sys

    from tests.conftest import ROOT

    code = ("import sys; from tests.conftest import solve_path, PROBLEMS; "
            "[solve_path(PROBLEMS / 'kinematics' / f) for f in ('three-point-omega.yaml', 'screw-axis.yaml', "
            "'rolling-disk.yaml', 'rolling-wheel-points.yaml')]; "
            "print('sympy' in sys.modules, 'scipy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         env={"PYTHONPATH": str(ROOT), "PATH": ""})
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["False", "False"]
