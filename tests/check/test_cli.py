"""`dyncli check` end to end: exit codes, stdin, several files, --output,
the instructor's key round trip, and the course example."""

from __future__ import annotations

import json
import sys
import xml.etree.ElementTree as ET

import pytest

from tests.check.helpers import FIX
from tests.conftest import ROOT, run_cli

COURSE = ROOT / "docs" / "course-example"


def rel(p):
    return str(p.relative_to(ROOT))


def test_exit_0_all_correct():
    rc, out, err = run_cli("check", rel(FIX / "good.yaml"))
    assert rc == 0, err
    assert "score 3/3" in out


def test_exit_1_wrong_answer_and_feedback_without_expected_value():
    rc, out, err = run_cli("check", rel(FIX / "alice.yaml"), "-f", "json")
    assert rc == 1, err
    doc = json.loads(out)
    ans = {a["key"]: a for a in doc["files"][0]["checks"][0]["answers"]}
    assert ans["find.0.v"]["status"] == "wrong" and "expected" not in ans["find.0.v"]
    assert "score 2/3" in err


def test_exit_2_invalid_answer_file_with_position():
    rc, out, err = run_cli("check", "-", input="problem: tests/check/fixtures/brake.yaml\nanswerz: {case: 1}\n")
    assert rc == 2
    assert "<stdin>:2:1: answerz: unknown key 'answerz' (did you mean 'answers'?)" in err
    assert "Traceback" not in err


def test_exit_2_invalid_problem_file_with_position():
    rc, out, err = run_cli("check", "-", input="problem: tests/check/fixtures/bad-problem.yaml\nanswers: {case: 1}\n")
    assert rc == 2
    assert "tests/check/fixtures/bad-problem.yaml:4:1: finds: unknown field 'finds' (did you mean 'find'?)" in err


def test_stdin_and_several_files_worst_exit_code():
    # stdin: problem paths are relative to the current directory
    text = (FIX / "good.yaml").read_text().replace("brake.yaml", "tests/check/fixtures/brake.yaml")
    rc, out, err = run_cli("check", rel(FIX / "good.yaml"), "-", rel(FIX / "alice.yaml"), "-f", "json", input=text)
    assert rc == 1
    doc = json.loads(out)
    assert [f["file"] for f in doc["files"]] == [rel(FIX / "good.yaml"), "<stdin>", rel(FIX / "alice.yaml")]
    assert doc["solves"] == 1
    assert doc["score"] == 8 and doc["max_score"] == 9


def test_missing_file_is_exit_2():
    rc, out, err = run_cli("check", "nope.yaml")
    assert rc == 2 and "nope.yaml: no such file" in err


def test_reveal_shows_expected():
    rc, out, err = run_cli("check", rel(FIX / "alice.yaml"), "-f", "junit", "--reveal")
    assert rc == 1 and "expected 12" in out


def test_output_file_and_step_summary(tmp_path):
    report = tmp_path / "reports" / "check.xml"
    summary = tmp_path / "summary.md"
    rc, out, err = run_cli("check", rel(FIX / "alice.yaml"), "-f", "junit", "-o", str(report))
    assert rc == 1 and out == ""
    root = ET.parse(report).getroot()
    assert root.tag == "testsuites" and root.get("failures") == "1"
    rc, out, err = run_cli("check", rel(FIX / "alice.yaml"), "-f", "github", env={"GITHUB_STEP_SUMMARY": str(summary)})
    assert rc == 1 and out.startswith("::error file=tests/check/fixtures/alice.yaml,line=4,col=3,")
    assert "| `find.0.v` | wrong |" in summary.read_text()


def test_write_key_round_trip(tmp_path):
    key = tmp_path / "key.yaml"
    prob = tmp_path / "p.yaml"
    prob.write_text((FIX / "set.yaml").read_text())
    rc, out, err = run_cli("check", "--write-key", str(prob), "-o", str(key))
    assert rc == 0, err
    text = key.read_text()
    assert "problem: p.yaml" in text and "index: 1" in text and "find.1.s: 17.0" in text
    rc, out, err = run_cli("check", str(key), "-f", "json")
    assert rc == 0, err
    doc = json.loads(out)
    assert doc["score"] == doc["max_score"] == 20 and doc["solves"] == 2    # 17 values + 3 find distances


def test_write_key_to_stdout_is_accepted_unchanged_via_stdin():
    rc, key, err = run_cli("check", "--write-key", rel(FIX / "brake.yaml"))
    assert rc == 0, err
    assert "problem: tests/check/fixtures/brake.yaml" in key
    assert "find.0.s: 32.0" in key and "find.2.t: 5.0" in key
    rc, out, err = run_cli("check", "-", "-f", "gradescope", input=key)
    assert rc == 0, err
    doc = json.loads(out)
    assert doc["score"] == 19 and all(t["status"] == "passed" for t in doc["tests"])   # 16 + 3 distances


def test_write_key_invalid_problem_is_exit_2():
    rc, out, err = run_cli("check", "--write-key", rel(FIX / "bad-problem.yaml"))
    assert rc == 2 and out == "" and "bad-problem.yaml:4:1" in err


# -- exit 3: internal errors (in-process) ----------------------------------------

def test_solver_bug_is_exit_3(monkeypatch, capsys):
    from dyncli import registry
    from dyncli.check.command import run_check

    def broken(problem, options):
        raise ZeroDivisionError("boom")

    monkeypatch.setattr(registry, "solver", lambda name: broken)
    rc = run_check([str(FIX / "good.yaml")], "json")
    assert rc == 3
    err = capsys.readouterr().err
    assert "internal error" in err and "This is a bug" in err


def test_checker_bug_is_exit_3(monkeypatch, capsys):
    from dyncli import cli
    from dyncli.check import selfstudy

    def broken(self, names):
        raise RuntimeError("boom")

    monkeypatch.setattr(selfstudy.SelfStudy, "check_paths", broken)
    monkeypatch.setattr(sys, "argv", ["dyncli", "check", str(FIX / "good.yaml")])
    with pytest.raises(SystemExit) as exc:
        cli.main()
    assert exc.value.code == 3
    assert "internal error" in capsys.readouterr().err
