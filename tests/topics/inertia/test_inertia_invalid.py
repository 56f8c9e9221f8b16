"""Invalid input for the five types of this topic: exit 2, with the field,
the line and a clear message."""

from __future__ import annotations

import pytest

from tests.conftest import error_of, run_cli, solve_one_text

BOX = "  - shape: box\n    mass: 1\n    size: [1, 1, 1]\n"


@pytest.mark.parametrize("matrix, where, words", [
    ("[[1, 0.1, 0], [0, 1, 0], [0, 0, 1]]", "bad.yaml:6:5: parts.0.orientation", "not orthonormal"),
    ("[[0.7071, -0.7071, 0], [0.7071, 0.7071, 0], [0, 0, 1]]", "bad.yaml:6:5: parts.0.orientation", "not orthonormal"),
    ("[[0, 1, 0], [1, 0, 0], [0, 0, 1]]", "bad.yaml:6:5: parts.0.orientation", "determinant -1"),
    ("[[-1, 0, 0], [0, -1, 0], [0, 0, -1]]", "bad.yaml:6:5: parts.0.orientation", "reflection"),
])
def test_matrix_must_be_a_proper_rotation(matrix, where, words):
    msg = error_of(f"type: inertia\nparts:\n{BOX}    orientation:\n      matrix: {matrix}\n")
    assert msg.startswith(where), msg
    assert words in msg


def test_exact_matrix_entries_accepted():
    rec = solve_one_text("type: inertia\nparts:\n" + BOX
                         + '    orientation: {matrix: [["sqrt(2)/2", "-sqrt(2)/2", 0], ["sqrt(2)/2", "sqrt(2)/2", 0], [0, 0, 1]]}\n')
    assert rec["results"]["mass"] == 1.0


def test_basis_is_validated_too():
    msg = error_of("type: inertia\nparts: [{shape: point, mass: 1}]\nbasis: {matrix: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}\n")
    assert msg.startswith("bad.yaml:3:1: basis:") and "determinant -1" in msg


def test_negative_mass():
    msg = error_of("type: inertia\nparts:\n  - {shape: sphere, mass: -2, radius: 1}\n")
    assert msg == "bad.yaml:3:21: parts.0.mass: must be > 0, got -2"


def test_hole_heavier_than_body():
    msg = error_of("type: inertia\nparts:\n  - {shape: box, mass: 1, size: [1, 1, 1]}\n"
                   "  - {shape: box, mass: 2, size: [1, 1, 1], hole: true}\n")
    assert msg.startswith("bad.yaml:4:5: parts.1:")
    assert "remaining mass -1 kg is not positive" in msg


def test_hole_with_negative_definite_remainder():
    msg = error_of("type: inertia\nparts:\n  - {shape: box, mass: 10, size: [0.1, 0.1, 0.1]}\n"
                   "  - {shape: ring, mass: 1, radius: 2, hole: true}\n")
    assert msg.startswith("bad.yaml:4:5: parts.1:")
    assert "not positive-semidefinite" in msg and "smallest principal moment" in msg


def test_hole_outside_the_body_breaks_triangle_inequality():
    msg = error_of("type: inertia\nparts:\n  - {shape: box, mass: 10, size: [1, 1, 1]}\n"
                   "  - {shape: point, mass: 0.8, at: [1.2, 0, 0], hole: true}\n")
    assert msg.startswith("bad.yaml:4:5: parts.1:")
    assert "triangle inequality" in msg and "outside" in msg


def test_hole_inside_is_fine():
    rec = solve_one_text("type: inertia\nparts:\n  - {shape: box, mass: 10, size: [1, 1, 1]}\n"
                         "  - {shape: box, mass: 1.25, size: [0.5, 0.5, 0.5], at: [0.2, 0, 0], hole: true}\n")
    assert rec["results"]["mass"] == 8.75


def test_tensor_part_not_positive_semidefinite():
    msg = error_of("type: inertia\nparts:\n  - {shape: tensor, mass: 1, inertia: [[1, 0, 0], [0, -1, 0], [0, 0, 1]]}\n")
    assert msg.startswith("bad.yaml:3:30: parts.0.inertia: not positive-semidefinite")


def test_tensor_part_triangle_violation_warns():
    rec = solve_one_text("type: inertia\nparts:\n  - {shape: tensor, mass: 1, inertia: [[1, 0, 0], [0, 1, 0], [0, 0, 3]]}\n")
    assert any("triangle inequality" in w for w in rec["warnings"])


@pytest.mark.parametrize("part, words", [
    ("{shape: cylinder, mass: 1, height: 2}", "shape 'cylinder' needs 'radius'"),
    ("{shape: box, mass: 1, size: [1, 1, 1], radius: 2}", "'radius' does not apply to shape 'box' (it takes 'size')"),
    ("{shape: point, mass: 1, length: 2}", "it takes no dimensions"),
    ("{shape: box, mass: 1, size: [1, -1, 1]}", "non-negative edge lengths"),
    ("{shape: point, mass: 1, orientation: {axis: [1, 0, 0]}}", "needs an 'angle'"),
    ("{shape: point, mass: 1, orientation: {angle: 1}}", "needs an 'axis'"),
    ("{shape: point, mass: 1, orientation: {axis: [0, 0, 0], angle: 1}}", "non-zero"),
    ("{shape: point, mass: 1, orientation: {euler313: [0, 0, 0], matrix: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}}", "exactly one of"),
    ("{shape: cube, mass: 1}", "must be 'point', 'rod', 'box'"),
    ("{shape: box, mass: 1, sise: [1, 1, 1]}", "did you mean 'size'"),
])
def test_part_fields(part, words):
    msg = error_of(f"type: inertia\nparts:\n  - {part}\n")
    assert msg.startswith("bad.yaml:3:"), msg
    assert words in msg, msg


def test_no_parts():
    assert error_of("type: inertia\nparts: []\n").startswith("bad.yaml:2:1: parts:")


def test_rigid_energy_invalid_tensor():
    base = "type: rigid-energy\nm: 1\nv: [0, 0, 0]\nomega: [1, 0, 0]\n"
    msg = error_of(base + "I: [[1, 0, 0], [0, -1, 0], [0, 0, 1]]\n")
    assert msg.startswith("bad.yaml:5:1: I: not positive-semidefinite")
    msg = error_of(base + "I: [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]\n")
    assert msg.startswith("bad.yaml:5:1: I: must be symmetric")
    assert error_of(base.replace("m: 1", "m: 0") + "I: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]\n").startswith("bad.yaml:2:1: m: must be > 0")


def test_planar_moments_invalid():
    msg = error_of("type: planar-moments\nI13: 0\nI23: 0\nI33: -1\nomega: 1\n")
    assert msg == "bad.yaml:4:1: I33: must be >= 0, got -1"
    assert "required field is missing" in error_of("type: planar-moments\nI13: 0\nI23: 0\nI33: 1\n")


def test_spin_change_invalid():
    msg = error_of("type: spin-change\naxis: [0, 0, 1]\nomega0: 2\nmasses:\n  - {m: 1, before: [1, 0, 0], after: [0, 0, 3]}\n")
    assert msg.startswith("bad.yaml:4:1: masses:") and "I_after = 0" in msg
    assert error_of("type: spin-change\naxis: [0, 0, 0]\nomega0: 2\nmasses: []\n").startswith("bad.yaml:2:1: axis: must be a non-zero vector")
    assert error_of("type: spin-change\naxis: [0, 0, 1]\nomega0: 2\nmasses:\n  - {m: -1, before: [1, 0, 0], after: [1, 0, 0]}\n").startswith("bad.yaml:5:6: masses.0.m: must be > 0")


def test_spin_change_all_on_axis_at_rest_is_null_not_error():
    rec = solve_one_text("type: spin-change\naxis: [0, 0, 1]\nomega0: 0\nmasses:\n  - {m: 1, before: [1, 0, 0], after: [0, 0, 3]}\n")
    assert rec["results"]["omega"] is None
    assert any("undefined" in w for w in rec["warnings"])


def test_motor_bodies_invalid():
    base = "type: motor-bodies\nIA1: 0\nIA2: 0\nmA: 0\nL: 0\nIB2: 0\nalpha: 0.3\np: 10\n"
    msg = error_of(base)
    assert msg.startswith("bad.yaml:6:1: IB2:") and "no inertia about the fixed axis" in msg
    assert error_of(base.replace("mA: 0", "mA: -1")) == "bad.yaml:4:1: mA: must be >= 0, got -1"


def test_cli_exit_code_and_no_traceback():
    rc, out, err = run_cli("solve", "-", input="type: inertia\nparts:\n  - {shape: sphere, mass: 1, radius: 1}\n"
                                               "  - {shape: sphere, mass: 2, radius: 1, hole: true}\n")
    assert rc == 2
    assert "Traceback" not in err and "parts.1" in err
