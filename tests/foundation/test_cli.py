"""The command line: exit codes, formats, stdin, version, schema, new."""

from __future__ import annotations

import json

import pytest

from dyncli import __version__, registry
from tests.conftest import run_cli

EX = "problems/rectilinear/case1-constant-acceleration.yaml"


def test_version():
    rc, out, err = run_cli("--version")
    assert rc == 0 and out.strip() == f"dyncli {__version__}"


def test_version_does_not_import_numpy():
    import subprocess
    import sys

    from tests.conftest import ROOT

    code = ("import sys; sys.argv=['dyncli','--version']\n"
            "from dyncli.cli import main\n"
            "try:\n    main()\nexcept SystemExit:\n    pass\n"
            "bad=[m for m in ('numpy','scipy','sympy','pydantic','yaml') if m in sys.modules]\n"
            "print('BAD:' + ','.join(bad))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT).stdout
    assert out.strip().splitlines()[-1] == "BAD:", out


def test_solve_table():
    rc, out, err = run_cli("solve", EX)
    assert rc == 0, err
    assert "Braking car" in out and "32" in out
    assert "\x1b[" not in out  # no colour codes when piped / NO_COLOR


def test_solve_json_stdout_is_only_json():
    rc, out, err = run_cli("solve", EX, "--format", "json")
    assert rc == 0
    data = json.loads(out)
    assert data[0]["type"] == "rectilinear" and data[0]["method"] == "closed-form"
    assert set(data[0]) >= {"file", "index", "type", "title", "results", "method", "equations", "warnings"}


def test_solve_yaml():
    import yaml

    rc, out, err = run_cli("solve", EX, "--format", "yaml")
    assert rc == 0
    assert yaml.safe_load(out)


def test_stdin():
    rc, out, err = run_cli("solve", "-", "--format", "json", input="type: rectilinear\na: 2\nfind: [{t: 1}]\n")
    assert rc == 0, err
    assert json.loads(out)[0]["results"]["find"][0]["s"] == 1.0


def test_invalid_exit_2_one_line_no_traceback():
    rc, out, err = run_cli("solve", "-", input="type: rectilinear\nacc: 3\na: 1\n")
    assert rc == 2
    assert "Traceback" not in err
    assert err.strip().startswith("<stdin>:2:1: acc: unknown field")


def test_invalid_json_still_json_on_stdout():
    rc, out, err = run_cli("solve", "-", "--format", "json", input="type: rectilinear\na: 't^2'\n")
    assert rc == 2
    data = json.loads(out)
    assert data[0]["results"] is None and "powers" in data[0]["error"]


def test_missing_file_exit_2():
    rc, out, err = run_cli("solve", "no-such-file.yaml")
    assert rc == 2 and "no such file" in err


def test_usage_error_exit_2():
    rc, out, err = run_cli("solve", "--format", "xml", EX)
    assert rc == 2


def test_validate():
    rc, out, err = run_cli("validate", EX)
    assert rc == 0 and "ok" in out
    rc, out, err = run_cli("validate", "-", input="type: rectilinear\n")
    assert rc == 2 and "a: required field is missing" in err


def test_types_lists_every_type_with_section():
    rc, out, err = run_cli("types")
    assert rc == 0
    for name, info in registry.TYPES.items():
        assert name in out and info.sections in out


def test_schema_all_and_one():
    rc, out, err = run_cli("schema")
    assert rc == 0
    sch = json.loads(out)
    assert "anyOf" in sch
    rc, out, err = run_cli("schema", "rectilinear")
    assert rc == 0 and "find" in json.loads(out)["properties"]
    rc, out, err = run_cli("schema", "rectlinear")
    assert rc == 2 and "did you mean" in err


def test_new_template_solves():
    rc, out, err = run_cli("new", "rectilinear")
    assert rc == 0 and "type: rectilinear" in out
    rc2, out2, err2 = run_cli("solve", "-", input=out)
    assert rc2 == 0, err2


def test_internal_error_exit_3(monkeypatch, tmp_path):
    # a solver that raises a bug-like exception maps to exit 3 with one line
    from dyncli.loader import split_problems, validate
    from dyncli.run import solve_one

    ps, _ = split_problems("x.yaml", b"type: rectilinear\na: 1\n")
    validate(ps[0])
    import dyncli.topics.rectilinear.solver as s
    from dyncli import registry

    monkeypatch.setattr(registry, "_LOADED", {})          # the solver looked up again, not the one kept
    monkeypatch.setattr(s, "solve", lambda p, o=None: 1 / 0)
    o = solve_one(ps[0])
    assert o.exit_code == 3 and "internal error" in o.message and "ZeroDivisionError" in o.message
