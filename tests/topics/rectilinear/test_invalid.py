"""Invalid rectilinear input: exit 2 with file:line:col, the field and a clear message."""

from __future__ import annotations

import pytest

from tests.conftest import error_of, run_cli


@pytest.mark.parametrize("text,where,words", [
    ("type: rectilinear\na: -1\nt_max: 0\n", "bad.yaml:3:", ["t_max"]),
    ("type: rectilinear\na: -1\nt_max: -5\n", "bad.yaml:3:", ["t_max"]),
    ("type: rectilinear\na: \"1/s\"\n", "bad.yaml:2:", ["a:", "not finite at the initial state", "s1 = 0"]),
    ("type: rectilinear\na: \"sqrt(v - 1)\"\nv1: 0\n", "bad.yaml:2:", ["a:", "not finite"]),
    ("type: rectilinear\na: \"3*t\"\naccuracy: {method: closed-form}\n", "bad.yaml:3:",
     ["accuracy.method", "closed-form applies only to case 1"]),
    ("type: rectilinear\na: \"t*v\"\naccuracy: {method: quadrature}\n", "bad.yaml:3:",
     ["accuracy.method", "no quadrature route"]),
    ("type: rectilinear\na: -1\naccuracy: {method: DOP85}\n", "bad.yaml:3:", ["did you mean 'DOP853'"]),
    ("type: rectilinear\na: -1\nfind:\n  - {t: 1, v: 2}\n", "bad.yaml:4:", ["find.0", "exactly one"]),
    ("type: rectilinear\na: -1\nfind:\n  - {}\n", "bad.yaml:4:", ["find.0", "exactly one"]),
    ("type: rectilinear\na: -1\nfind:\n  - {x: 1}\n", "bad.yaml:4:", ["find.0"]),
    ("type: rectilinear\na: \"-k*x\"\nparams: {k: 1}\n", "bad.yaml:2:", ["a:", "'x'"]),
    ("type: rectilinear\na: \"v^2\"\n", "bad.yaml:2:", ["use ** for powers"]),
    ("type: rectilinear\na: -1\nv1: \"__import__('os')\"\n", "bad.yaml:3:", ["v1"]),
])
def test_invalid(text, where, words):
    msg = error_of(text)
    assert msg.startswith(where), msg
    for w in words:
        assert w in msg, (w, msg)


def test_cli_exit_code_and_no_traceback(tmp_path):
    f = tmp_path / "bad.yaml"
    f.write_text("type: rectilinear\na: \"1/(v - 2)\"\nv1: 2\n")
    rc, out, err = run_cli("solve", str(f))
    assert rc == 2
    assert "Traceback" not in err and "not finite at the initial state" in err
