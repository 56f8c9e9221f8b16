"""A motion with no force at all is said so: a forgotten {kind: gravity} (a bead
on a turning hoop, a projectile) is the slip, a free particle the rare intent."""

from __future__ import annotations

import pytest

from tests.conftest import solve_one_text

HOOP = """type: constrained-particle
m: 0.1
curve: {x1: "0.5*sin(q)", x2: 0, x3: "-0.5*cos(q)"}
q_range: [-pi, pi]
q0: 0.3
at: [0, 1]
"""


def _no_force(rec) -> list[str]:
    return [w for w in rec["warnings"] if w.startswith("no forces")]


@pytest.mark.parametrize("turning", [True, False])
def test_hoop_without_forces_warns(turning):
    text = HOOP + ("rotation: {axis: [0, 0, 1], omega: 5}\n" if turning else "")
    (w,) = _no_force(solve_one_text(text))
    assert "{kind: gravity}" in w and "no gravity" in w
    assert ("turning curve" in w) == turning


def test_hoop_with_gravity_is_silent():
    rec = solve_one_text(HOOP + "rotation: {axis: [0, 0, 1], omega: 5}\nforces: [{kind: gravity}]\n")
    assert not _no_force(rec)


def test_particle_without_forces_warns_and_moves_straight():
    rec = solve_one_text("type: particle\nm: 1\nx0: [0, 0, 0]\nv0: [3, 0, 4]\nt_end: 2\nat: [2]\n")
    (w,) = _no_force(rec)
    assert "straight line" in w and "{kind: gravity}" in w
    assert rec["results"]["x"][0] == pytest.approx([6, 0, 8], rel=1e-12)


def test_particle_with_a_force_is_silent():
    rec = solve_one_text("type: particle\nm: 1\nx0: [0, 0, 0]\nv0: [3, 0, 4]\nforces: [{kind: gravity}]\nt_end: 2\nat: [2]\n")
    assert not _no_force(rec)
