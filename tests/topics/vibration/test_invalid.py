"""Invalid vibration input: exit 2 with file:line:col, the field and a clear message."""

from __future__ import annotations

import pytest

from tests.conftest import error_of, run_cli

HEAD = "type: vibration\nm: 1\nk: 1\n"

CASES = [
    ("type: vibration\nm: 0\nk: 1\n", "bad.yaml:2:1: m: must be > 0"),
    ("type: vibration\nm: -1\nk: 1\n", "bad.yaml:2:1: m: must be > 0"),
    ("type: vibration\nm: 1\nk: -2\n", "bad.yaml:3:1: k: must be > 0"),
    ("type: vibration\nm: 1\n", "bad.yaml:1:1: k: required field is missing"),
    (HEAD + "c: 0.1\nzeta: 0.2\n", "bad.yaml:5:1: zeta: give the damping as either c or zeta, not both"),
    (HEAD + "c: -0.1\n", "bad.yaml:4:1: c: must be >= 0"),
    (HEAD + "zeta: -0.1\n", "bad.yaml:4:1: zeta: must be >= 0"),
    (HEAD + "zeta: .inf\n", "bad.yaml:4:1: zeta: must be finite"),
    (HEAD + "base: {amplitude: .inf, omega: 1}\n", "bad.yaml:4:8: base.amplitude: must be finite"),
    (HEAD + "base: {amplitude: 0.1, omega: .nan}\n", "bad.yaml:4:24: base.omega: not a number (NaN)"),
    (HEAD + "base: {amplitude: 0.1, omega: -1}\n", "bad.yaml:4:24: base.omega: must be >= 0"),
    (HEAD + "base: {amplitude: 0.1}\n", "base.omega: required field is missing"),
    (HEAD + "base: {amplitude: 1e300, omega: 1e300}\n", "bad.yaml:4:26: base.omega: ω/ωₙ must be <= 1e+100"),
    (HEAD + "base: {amplitude: 1e300, omega: 1e90}\n", "bad.yaml:4:1: base: amplitude·ω² overflows"),
    (HEAD + "base: {amplitude: 0.1, omega: 1, phase: 2}\n", "base.phase: unknown field"),
    (HEAD + "at: [0, -1]\n", "bad.yaml:4:1: at: entry 1: times must be >= 0"),
    (HEAD + "at: [0, .inf]\n", "at: entry 1: must be finite"),
    (HEAD + "sweep: {ratio: [2, 1], points: 10}\n", "bad.yaml:4:9: sweep.ratio: must be [r_min, r_max] with r_min < r_max"),
    (HEAD + "sweep: {ratio: [0, 1], points: 10, spacing: log}\n", "sweep.ratio: log spacing needs r_min > 0"),
    (HEAD + "sweep: {ratio: [0, 1], points: 1}\n", "sweep.points: must be greater than or equal to 2"),
    (HEAD + "sweep: {ratio: [0, 1], spacing: cubic}\n", "sweep.spacing: must be 'linear' or 'log'"),
    (HEAD + "sweep: {ratio: [0, 1, 2]}\n", "sweep.ratio: expected [r_min, r_max]"),
    (HEAD + "sweep: {ratio: [-1, 2]}\n", "sweep.ratio.0: must be >= 0"),
    (HEAD + "zetta: 0.1\n", "bad.yaml:4:1: zetta: unknown field 'zetta' (did you mean 'zeta'?)"),
    (HEAD + "accuracy: {method: RK45}\n", "accuracy.method: unknown method 'RK45'"),
    ("type: vibration\nm: heavy\nk: 1\n", "bad.yaml:2:1: m: 'heavy' is not a number"),
    ("type: vibration\nm: 1e-300\nk: 1e300\n", "bad.yaml:3:1: k: k/m = 1e+300/1e-300 gives a natural frequency"),
    ("type: vibration\nm: 1\nk: 1\nx0: \"2^2\"\n", "x0: "),
]


@pytest.mark.parametrize("text,expected", CASES)
def test_invalid(text, expected):
    msg = error_of(text)
    assert expected in msg, msg
    assert "Traceback" not in msg


def test_invalid_via_cli_exit_2():
    rc, out, err = run_cli("solve", "-", input=HEAD + "c: 1\nzeta: 1\n")
    assert rc == 2
    assert "<stdin>:5:1: zeta: give the damping as either c or zeta, not both" in err
    assert "Traceback" not in err
