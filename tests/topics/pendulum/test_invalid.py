"""Invalid pendulum input: exit 2 with file:line:col, the field and a clear message."""

from __future__ import annotations

import pytest

from tests.conftest import error_of, run_cli

HEAD = "type: pendulum\nl: 1\ntheta0: 1\n"

CASES = [
    ("type: pendulum\nl: 0\ntheta0: 1\n", "bad.yaml:2:1: l: must be > 0"),
    ("type: pendulum\nl: -2\ntheta0: 1\n", "bad.yaml:2:1: l: must be > 0"),
    (HEAD + "g: 0\n", "bad.yaml:4:1: g: must be > 0"),
    (HEAD + "g: -9.81\n", "bad.yaml:4:1: g: must be > 0"),
    (HEAD + "m: 0\n", "bad.yaml:4:1: m: must be > 0"),
    ("type: pendulum\ntheta0: 1\n", "l: required field is missing"),
    ("type: pendulum\nl: 1\n", "theta0: required field is missing"),
    ("type: pendulum\nl: .inf\ntheta0: 1\n", "l: must be finite"),
    ("type: pendulum\nl: 1\ntheta0: .nan\n", "theta0: not a number (NaN)"),
    ("type: pendulum\nl: 1\ntheta0: 1e7\n", "bad.yaml:3:1: theta0: |theta0| must be <= 1e+06 rad"),
    (HEAD + "theta_dot0: .inf\n", "theta_dot0: must be finite"),
    ("type: pendulum\nl: 1e-300\ng: 1e300\ntheta0: 1\n", "l: g/l = 1e+300/1e-300 gives a frequency"),
    (HEAD + "theta_dot0: 1e200\n", "theta_dot0: θ̇₀/√(g/l) overflows"),
    # m g (3 − 2 cos θ₀), the tension at the bottom, beyond 1.8e308 (fuzz seed 3404059: exit 3 at find)
    (HEAD + "m: 1.7976931348623157e+308\nfind: [{max: tension}]\n", "bad.yaml:4:1: m: m = 1.79769e+308 kg puts the "
     "energy or the rod's tension beyond the range of a double"),
    (HEAD + "m: 1e300\ng: 1e10\n", "m: m = 1e+300 kg puts the energy or the rod's tension beyond"),
    (HEAD + "at: [0, -1]\n", "bad.yaml:4:1: at: entry 1: times must be >= 0"),
    (HEAD + "omega0: 2\n", "omega0: unknown field"),
    (HEAD + "t_end: 0\n", "t_end: must be > 0"),
    (HEAD + "find: [{max: thetta}]\n", "find.0.max: "),
    ("type: pendulum\nl: long\ntheta0: 1\n", "bad.yaml:2:1: l: unknown name 'long'"),
]


@pytest.mark.parametrize("text,expected", CASES)
def test_invalid(text, expected):
    msg = error_of(text)
    assert expected in msg, msg
    assert "Traceback" not in msg


def test_invalid_via_cli_exit_2():
    rc, out, err = run_cli("solve", "-", input="type: pendulum\nl: -1\ntheta0: 1\n")
    assert rc == 2
    assert "<stdin>:2:1: l: must be > 0" in err
    assert "Traceback" not in err


def test_times_beyond_countable_periods_exit_1():
    """Past 2^52 periods the whole periods of the phase are no longer told apart: a numerical
    limit (exit 1, saying where it lies), not a wrong angle."""
    rc, out, err = run_cli("solve", "-", input=HEAD + "at: [1e150]\n")
    assert rc == 1 and "counted exactly up to 4.5e+15" in err and "Traceback" not in err
