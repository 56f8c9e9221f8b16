"""Invalid particle / force-field input: exit 2 with file:line:col, field and message."""

from __future__ import annotations

import pytest

from tests.conftest import error_of, run_cli

BASE = "type: particle\nm: 1\nt_end: 1\n"


@pytest.mark.parametrize("extra, where, message", [
    ("forces: [{kind: sprin, k: 1}]", "4:10: forces.0", "did you mean 'spring'"),
    ("forces: [{kind: spring, k: -1}]", "4:25: forces.0.k", "must be > 0"),
    ("forces: [{kind: spring, k: 1, kk: 2}]", "4:31: forces.0.kk", "unknown field 'kk' (did you mean 'k'?)"),
    ("forces: [{kind: drag, c: 1, power: 3}]", "forces.0.power", "power must be 1 (linear drag) or 2"),
    ("forces: [{kind: inverse-square, R0: 0}]", "forces.0.R0", "must be > 0"),
    ("forces: [{kind: inverse-square, R0: 1}]", "forces.0.center", "x0 is at the centre"),
    ("forces: [{kind: spring, k: 1, L: 0.5}]", "forces.0.anchor", "spring's anchor"),
    ("forces: [{kind: friction, mu: -0.1, N: 1}]", "forces.0.mu", "must be >= 0"),
    ("forces: [{kind: friction, mu: 0.1}]", "forces.0.N", "required field is missing"),
    ("forces: [{kind: custom, F: [x, 0, 0]}]", "forces.0.F", "unknown name 'x'"),
    ("forces: [{kind: custom, F: [\"v1^2\", 0, 0]}]", "forces.0.F", "use ** for powers"),
    ("forces: [{kind: custom, F: [1, 0]}]", "forces.0.F", "list of 3"),
    ("forces: [{k: 1}]", "forces.0", "a force needs 'kind'"),
    ("forces: [gravity]", "forces.0", "a force is a mapping with 'kind'"),
    ("forces: [{kind: gravity, g: 3}]", "forces.0.g", "unknown field 'g'"),
    ("at: [0.5, 2]", "4:11: at.1", "outside [0, t_end = 1]"),
    ("at: [-1]", "at.0", "outside [0, t_end"),
    ("x0: [1, 2]", "x0", "got 2 entries"),
    ("accuracy: {method: Euler}", "accuracy.method", "choose one of: auto, exact, ode, DOP853, RK45, Radau, LSODA"),
])
def test_invalid_particle(extra, where, message):
    msg = error_of(BASE + extra + "\n")
    assert msg.startswith("bad.yaml:"), msg
    assert where in msg, msg
    assert message in msg, msg


def test_mass_must_be_positive():
    msg = error_of("type: particle\nm: 0\nt_end: 1\n")
    assert msg.startswith("bad.yaml:2:1: m: must be > 0"), msg


def test_t_end_must_be_positive_or_inferred():
    assert "t_end: must be > 0" in error_of("type: particle\nm: 1\nt_end: -1\n")
    assert "give t_end or the times 'at'" in error_of("type: particle\nm: 1\n")


@pytest.mark.parametrize("text, where, message", [
    ("F: [x1, y, 0]", "F", "unknown name 'y'"),
    ("F: [x1, x2]", "F", "list of 3"),
    ("F: [x1, x2, \"t\"]", "F", "unknown name 't'"),
    ("F: [x1, x2, 0]\npath: {x1: t, x2: t, t_span: [0, 1]}", "path.x3", "required field is missing"),
    ("F: [x1, x2, 0]\npath: {x1: t, x2: t, x3: x1, t_span: [0, 1]}", "path.x3", "unknown name 'x1'"),
    ("F: [x1, x2, 0]\npath: {x1: t, x2: t, x3: 0, t_span: [0, 1, 2]}", "path.t_span", "too many times"),
    ("F: [x1, x2, 0]\npath: {x1: t, x2: t, x3: 0, t_span: [1]}", "path", "t_span must be [t1, t2]"),
    ("F: [x1, x2, 0]\npoints: [[1, 2]]", "points.0", "got 2 entries"),
])
def test_invalid_force_field(text, where, message):
    msg = error_of("type: force-field\n" + text + "\n")
    assert where in msg and message in msg, msg


def test_cli_exit_codes():
    rc, out, err = run_cli("solve", "-", input=BASE + "forces: [{kind: spring, k: -1}]\n")
    assert rc == 2 and "forces.0.k" in err and "Traceback" not in err
    # falling into the centre of an inverse-square field: a numerical failure, exit 1
    rc, out, err = run_cli("solve", "-", input="""
type: particle
m: 1
x0: [1, 0, 0]
forces: [{kind: inverse-square, R0: 1, g: 1}]
t_end: 5
""")
    assert rc == 1, err
    assert "falls into the centre" in err
