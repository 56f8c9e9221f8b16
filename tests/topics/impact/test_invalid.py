"""Invalid input for impact, particles and rigid-impulse: exit 2 with a
clear message located at the offending field (file:line:col: field: msg)."""

from __future__ import annotations

import pytest

from tests.conftest import error_of, run_cli

BASE = "type: impact\nmA: 1\nmB: 2\nvA1: [1, 0, 0]\nn: [1, 0, 0]\n"
OBLIQUE = "type: impact\nmA: 1\nmB: 2\nvA1: [1, 1, 0]\nn: [1, 0, 0]\n"


@pytest.mark.parametrize("text, where, words", [
    (BASE + "e: 1.5", "6:1: e:", "<= 1"),
    (BASE + "e: -0.1", "6:1: e:", ">= 0"),
    (BASE + "eta: 1.2", "6:1: eta:", "<= 1"),
    (BASE + "eta: -1", "6:1: eta:", ">= 0"),
    (BASE + "e: 0.5\neta: 0.5", "7:1: eta:", "not both"),
    (BASE, "e:", "give e"),
    (BASE + "e: 0.5\nphi: 0.1", "7:1: phi:", "requires eta"),
    (BASE + "phi: 0.1", "6:1: phi:", "requires eta"),
    (BASE + "eta: 0.5\nphi: 2", "7:1: phi:", "[-pi/2, pi/2]"),
    (BASE + "eta: 0.5\nphi: 0.1", "7:1: phi:", "parallel to n"),
    (BASE + "eta: 0.5\nphi: 0.1\nt: [0, 2, 0]", "8:1: t:", "unit vector"),
    (BASE + "eta: 0.5\nphi: 0.1\nt: [0.6, 0.8, 0]", "8:1: t:", "perpendicular to n"),
    (BASE + "eta: 0.5\nphi: 0.1\nt: [0, 0, 0]", "8:1: t:", "non-zero"),
    (OBLIQUE + "eta: 0.5\nphi: 0.1\nt: [0, 0, 1]", "8:1: t:", "plane of n"),
    (OBLIQUE + "eta: 0.5\nphi: 0.1\nt: [0, -1, 0]", "8:1: t:", "non-negative component"),
    (OBLIQUE + "e: 0.5\nt: [0, 1, 0]", "7:1: t:", "general model"),
    ("type: impact\nmA: 0\nmB: 2\nn: [1, 0, 0]\ne: 1", "2:1: mA:", "> 0"),
    ("type: impact\nmA: .inf\nmB: 2\nn: [1, 0, 0]\ne: 1", "2:1: mA:", "finite"),
    ("type: impact\nmA: 1\nmB: -2\nn: [1, 0, 0]\ne: 1", "3:1: mB:", "> 0"),
    ("type: impact\nmA: 1\nmB: .nan\nn: [1, 0, 0]\ne: 1", "3:1: mB:", "NaN"),
    ("type: impact\nmA: 1\nmB: 2\nn: [0, 0, 0]\ne: 1", "4:1: n:", "non-zero"),
    ("type: impact\nmA: 1\nmB: 2\ne: 1", "n:", "missing"),
    ("type: impact\nmA: 1\nmB: 2\nn: [1, 0]\ne: 1", "n:", "3 numbers"),
    ("type: impact\nmA: 1\nmB: 2\nn: [1, 0, 0]\ne: 1\nvA: [1, 0, 0]", "6:1: vA:", "did you mean"),
    ("type: impact\nmA: 1e308\nmB: 2\nvA1: [1e308, 0, 0]\nvB1: [-1e308, 0, 0]\nn: [1, 0, 0]\ne: 1", "vA1:", "too large"),
])
def test_impact_invalid(text, where, words):
    msg = error_of(text)
    assert msg.startswith("bad.yaml:"), msg
    assert where in msg, msg
    assert words in msg, msg
    assert "Traceback" not in msg


@pytest.mark.parametrize("text, where, words", [
    ("type: particles\nparticles: []", "2:1: particles:", "at least one particle"),
    ("type: particles\nparticles:\n  - {m: 1, x: [0, 0, 0]}\n  - {m: 0, x: [1, 0, 0]}", "4:6: particles.1.m:", "> 0"),
    ("type: particles\nparticles:\n  - {m: -1, x: [0, 0, 0]}", "particles.0.m:", "> 0"),
    ("type: particles\nparticles:\n  - {m: 1}", "particles.0.x:", "missing"),
    ("type: particles\nparticles:\n  - {m: 1, x: [0, 0]}", "particles.0.x:", "3 numbers"),
    ("type: particles\nparticles:\n  - {m: 1, x: [0, 0, 0], vel: [1, 0, 0]}", "particles.0.vel:", "unknown field"),
    ("type: particles\nparticles:\n  - {m: 1, x: [0, 0, 0]}\nabout: [1, 2]", "about:", "3 numbers"),
])
def test_particles_invalid(text, where, words):
    msg = error_of(text)
    assert where in msg and words in msg, msg


@pytest.mark.parametrize("text, where, words", [
    ("type: rigid-impulse\nm: 1\nk: 0\nR: 1\nh: 1", "3:1: k:", "> 0"),
    ("type: rigid-impulse\nm: -1\nk: 1\nR: 1\nh: 1", "2:1: m:", "> 0"),
    ("type: rigid-impulse\nm: 1\nk: 1\nR: 1", "h:", "missing"),
    ("type: rigid-impulse\nm: 1\nk: 1\nR: x\nh: 1", "4:1: R:", "x"),
])
def test_rigid_impulse_invalid(text, where, words):
    msg = error_of(text)
    assert where in msg and words in msg, msg


def test_cli_exit_2_and_one_line():
    rc, out, err = run_cli("solve", "-", input=BASE + "e: 2")
    assert rc == 2
    assert "e: must be <= 1" in err and "Traceback" not in err
