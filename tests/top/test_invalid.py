"""Invalid top input: exit 2 with file:line:col, the field and a clear message."""

from __future__ import annotations

import pytest

from tests.conftest import error_of, run_cli

HEAD = "type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\n"

CASES = [
    ("type: top\nm: 0\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\n", "bad.yaml:2:1: m: must be > 0"),
    ("type: top\nm: -1\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\n", "bad.yaml:2:1: m: must be > 0"),
    ("type: top\nm: 0.5\nL: 0\nI11: 2.0e-3\nI33: 1.0e-3\n", "bad.yaml:3:1: L: must be > 0"),
    ("type: top\nm: 0.5\nL: 0.05\nI11: -2.0e-3\nI33: 1.0e-3\n", "bad.yaml:4:1: I11: must be > 0"),
    ("type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 0\n", "bad.yaml:5:1: I33: must be > 0"),
    ("type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\n", "I33: required field is missing"),
    (HEAD + "at: [0, -1]\n", "bad.yaml:6:9: at.1: times must be >= 0"),
    (HEAD + "at: [0, .inf]\n", "at: entry 1: must be finite"),
    (HEAD + "theta: .nan\n", "bad.yaml:6:1: theta: not a number (NaN)"),
    (HEAD + "phi_dot: .inf\n", "bad.yaml:6:1: phi_dot: must be finite"),
    (HEAD + "psi_dot: \"w^2\"\n", "psi_dot: "),
    (HEAD + "accuracy: {method: Euler}\n", "accuracy.method: unknown method 'Euler'"),
    (HEAD + "accuracy: {rtol: 0}\n", "accuracy.rtol: must be > 0"),
    (HEAD + "spin: 3\n", "bad.yaml:6:1: spin: unknown field 'spin'"),
    (HEAD + "theta_dott: 3\n", "did you mean 'theta_dot'"),
    ("type: top\nm: \"2 m\"\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\n", "bad.yaml:2:1: m: "),
]


@pytest.mark.parametrize("text,expected", CASES)
def test_invalid(text, expected):
    assert expected in error_of(text)


def test_cli_exit_2(tmp_path):
    f = tmp_path / "bad.yaml"
    f.write_text("type: top\nm: 0.5\nL: -1\nI11: 2.0e-3\nI33: 1.0e-3\n")
    rc, out, err = run_cli("solve", str(f))
    assert rc == 2
    assert "bad.yaml:3:1: L: must be > 0" in err
    assert "Traceback" not in err


def test_inconsistent_inertia_warns():
    from tests.conftest import solve_one_text

    rec = solve_one_text("type: top\nm: 1\nL: 0.5\nI11: 0.1\nI33: 0.05\nphi_dot: 10\ntheta: 0.3\nat: [0.1]\n")
    assert any("smaller than mL²" in w for w in rec["warnings"])
    rec = solve_one_text("type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 3.0e-3\nphi_dot: 10\ntheta: 0.3\nat: [0.1]\n")
    assert any("triangle inequality" in w for w in rec["warnings"])
