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


def _record(text):
    from tests.conftest import solve_text

    (rec,) = solve_text(text)
    return rec


# the ODE route's work budget (method DOP853; the default exact route has none)
OBLATE = ("type: top\nm: 0.5\nL: 0.05\nI11: 0.002\nI33: 3.14159\ntheta: 0.3\ntheta_dot: -2\npsi_dot: 16.918\n"
          "phi_dot: 50\naccuracy: {method: DOP853}\n")


def test_budget_refuses_a_run_that_needs_too_many_steps():
    # strongly oblate: the body-frame nutation rate I33 ω3/I11 ~ 1e5 rad/s, ~1.5e5 steps to t = 0.5 s
    rec = _record(OBLATE + "at: [0, 0.02, 0.1, 0.5]\n")
    assert rec["exit_code"] == 1
    assert "the run to t = 0.5 s needs about" in rec["error"] and "budget of 50000" in rec["error"]
    assert "accuracy.max_steps" in rec["error"]
    # a shorter span is within the budget (~600 steps)
    assert _record(OBLATE + "at: [0, 0.002]\n").get("error") is None


def test_budget_honours_max_steps():
    text = "type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\ntheta: 0.5\nphi_dot: 100\nat: [0, 2]\n"
    assert _record(text + "accuracy: {method: DOP853}\n").get("error") is None       # ~250 steps
    rec = _record(text + "accuracy: {max_steps: 200, method: DOP853}\n")             # watched step by step
    assert rec["exit_code"] == 1 and "budget of 200" in rec["error"]
    rec = _record(text + "accuracy: {max_steps: 20, method: DOP853}\n")              # clearly over: refused before integrating
    assert rec["exit_code"] == 1 and "budget of 20" in rec["error"] and "fastest rate" in rec["error"]
