"""Ids read as written, one id claimed twice, keys no student can answer,
and round-off zeros (docs/check.md)."""

from __future__ import annotations

import json

import pytest

from tests.check.keyhelpers import KEY, check_json, questions, truth


def _sub(tmp_path, name: str, text: str) -> str:
    p = tmp_path / name
    p.write_text(text)
    return str(p)


def test_ids_as_written(tmp_path, capsys):
    from tests.check.keyhelpers import params_of

    for written in ("012345671", "1:30", "0x1F", "1_000", "010", "yes", "1.50"):
        p = params_of(written)
        t = truth(p["v0"], p["a0"])
        sub = _sub(tmp_path, "s.yaml", f"student: {written}\nanswers:\n  1a: {t['1a']!r}\n  1b: {t['1b']!r}\n")
        for opt in (None, written):
            code, doc, err = check_json(KEY, [sub], capsys, student=opt)
            s = doc["submissions"][0]
            assert s["student"] == written and not s["errors"], (written, opt, err)
            assert questions(doc)["1a"]["status"] == "correct" and questions(doc)["1b"]["status"] == "correct"


def test_question_ids_as_written(tmp_path, capsys):
    (tmp_path / "hw.yaml").write_text("problems:\n  - {type: rectilinear, a: 2, v1: 3, find: [{t: 1}]}\n")
    (tmp_path / "key.yaml").write_text("questions:\n  - {id: 010, problem: hw.yaml, index: 0, answer: find.0.s}\n"
                                       "  - {id: 1:30, problem: hw.yaml, index: 0, answer: find.0.v}\n")
    sub = _sub(tmp_path, "s.yaml", "student: x\nanswers:\n  010: 4\n  1:30: 5\n")
    _, doc, _ = check_json(tmp_path / "key.yaml", [sub], capsys)
    q = questions(doc)
    assert set(q) == {"010", "1:30"} and all(r["status"] == "correct" for r in q.values())


def test_two_files_claiming_one_id(tmp_path, capsys):
    a = _sub(tmp_path, "alice.yaml", "student: alice@example.edu\nanswers: {1a: 1}\n")
    m = _sub(tmp_path, "mallory.yaml", "student: alice@example.edu\nanswers: {1a: 2}\n")
    _, doc, err = check_json(KEY, [a, m], capsys)
    assert "warning: 2 submissions claim student 'alice@example.edu'" in err
    assert doc["warnings"][0]["student"] == "alice@example.edu" and len(doc["warnings"][0]["files"]) == 2
    _, out, _ = check_json(KEY, [a, m], capsys, fmt="github")
    assert any(line.startswith("::warning file=") and "claim student" in line for line in out.splitlines())


def test_id_from_filename(tmp_path, capsys):
    (tmp_path / "by-name").mkdir()
    a = _sub(tmp_path / "by-name", "alice.yaml", "answers: {1a: 1}\n")
    b = _sub(tmp_path / "by-name", "bob.yaml", "student: mallory\nanswers: {1a: 1}\n")
    code, doc, err = check_json(KEY, [a, b], capsys, id_from="filename")
    assert doc["submissions"][0]["student"] == "alice" and code == 2
    assert "student 'mallory' does not match the file name 'bob'" in err


def test_cli_id_from(tmp_path):
    from typer.testing import CliRunner

    from dyncli.cli import app

    a = _sub(tmp_path, "alice.yaml", "answers: {1a: 1}\n")
    r = CliRunner().invoke(app, ["check", "--key", str(KEY), a, "--id-from", "filename", "--format", "json"])
    assert json.loads(r.stdout)["submissions"][0]["student"] == "alice"
    r = CliRunner().invoke(app, ["check", "--key", str(KEY), a, "--id-from", "filename", "--student", "x"])
    assert r.exit_code == 2


# -- keys no student can answer ----------------------------------------------

PROBLEMS = """\
problems:
  - {type: rectilinear, s1: "0.1 + 0.2 - 0.3", v1: 0, a: 0, find: [{t: 1}]}
  - {type: rectilinear, params: {w: 2}, v1: w, a: 1, find: [{t: 1}]}
"""


def _selftest(tmp_path, capsys, questions_text: str, tol: str = "{sigfigs: 3}"):
    from dyncli.check.keycommand import run_selftest

    (tmp_path / "p.yaml").write_text(PROBLEMS)
    (tmp_path / "key.yaml").write_text(f"tolerance: {tol}\nquestions:\n{questions_text}")
    capsys.readouterr()
    code = run_selftest(str(tmp_path / "key.yaml"), 3)
    out, err = capsys.readouterr()
    return code, out, err


def test_selftest_refuses_a_record_answer(tmp_path, capsys):
    code, _, err = _selftest(tmp_path, capsys, "  - {id: r, problem: p.yaml, index: 1, answer: find.0}\n")
    assert code == 1 and "is a record" in err and "find.0.s" in err


def test_selftest_refuses_a_unit_of_another_dimension(tmp_path, capsys):
    code, _, err = _selftest(tmp_path, capsys, "  - {id: r, problem: p.yaml, index: 1, answer: find.0.v, unit: rad}\n")
    assert code == 1 and "unit 'rad' is not of the dimension" in err and "m/s" in err


@pytest.mark.parametrize("tol", ["{sigfigs: 3}", "{rtol: 0.01}"])
def test_roundoff_zero_flagged_and_graded_as_zero(tmp_path, capsys, tol):
    q = "  - {id: z, problem: p.yaml, index: 0, answer: find.0.s, partial: {power_of_ten: 0.5, sign: 0.5}}\n"
    code, _, err = _selftest(tmp_path, capsys, q, tol)
    assert code == 0 and "zero up to round-off" in err
    assert abs(0.1 + 0.2 - 0.3) > 0                       # the problem's s1 is 5.6e-17 in doubles
    for given, status in ((0, "correct"), (0.0001, "correct" if "sigfigs" in tol else "wrong"),
                          (7, "wrong"), (-3e-16, "correct"), (5.55e-16, "correct"), (0.5, "wrong")):
        sub = _sub(tmp_path, "s.yaml", f"student: s\nanswers: {{z: {given!r}}}\n")
        _, doc, _ = check_json(tmp_path / "key.yaml", [sub], capsys)
        r = questions(doc)["z"]
        assert r["status"] == status and r["diagnosis"] is None, (given, r)


# -- the instructor's feedback ------------------------------------------------

FEEDBACK_KEY = """\
questions:
  - {id: s, problem: p.yaml, index: 1, answer: find.0.s, partial: {sign: 0.5},
     feedback: {correct: "Well done: s = v t + a t^2/2.", sign: "Which way is positive?",
                wrong: "Start from s = v t + a t^2/2 (notes 6.5a).", missing: "Try it: 6.5a."}}
"""


@pytest.mark.parametrize("given,status,text", [
    (2.5, "correct", "Well done"), (-2.5, "partial", "Which way is positive?"), (7, "wrong", "notes 6.5a"),
    (None, "missing", "Try it")])
def test_feedback_by_status_and_slip_in_every_format(tmp_path, capsys, monkeypatch, given, status, text):
    monkeypatch.setenv("COLUMNS", "1000")         # the table unwrapped: the feedback stays on one line
    (tmp_path / "p.yaml").write_text(PROBLEMS)
    (tmp_path / "key.yaml").write_text(FEEDBACK_KEY)     # s = 2·1 + 1·1²/2 = 2.5 by hand
    sub = _sub(tmp_path, "s.yaml", "student: x\nanswers: {s: %s}\n" % ("null" if given is None else given))
    _, doc, _ = check_json(tmp_path / "key.yaml", [sub], capsys)
    q = questions(doc)["s"]
    assert q["status"] == status and text in q["feedback"] and text in q["message"]
    for fmt in ("table", "junit", "gradescope"):
        _, out, _ = check_json(tmp_path / "key.yaml", [sub], capsys, fmt=fmt)
        assert text in (json.dumps(out) if isinstance(out, dict) else out.replace("\n", " ")), fmt
    if status != "correct":
        _, out, _ = check_json(tmp_path / "key.yaml", [sub], capsys, fmt="github")
        assert text in out


def test_feedback_key_is_checked(tmp_path, capsys):
    (tmp_path / "p.yaml").write_text(PROBLEMS)
    (tmp_path / "key.yaml").write_text(FEEDBACK_KEY.replace('sign: "Which', 'sing: "Which'))
    code, _, err = check_json(tmp_path / "key.yaml", [_sub(tmp_path, "s.yaml", "answers: {s: 1}\n")], capsys)
    assert code == 2 and "unknown feedback key 'sing'" in err and "did you mean 'sign'" in err


def test_selftest_prints_the_carry_window_and_warns_of_a_carry_that_repeats(tmp_path, capsys):
    from dyncli.check.keycommand import run_selftest

    (tmp_path / "p.yaml").write_text("problems:\n  - {type: rectilinear, a: 2, v1: 3, find: [{t: 1}]}\n"
                                     "  - {type: rectilinear, params: {s0: 0}, s1: s0, v1: 0.0001, a: 0, find: [{t: 1}]}\n")
    (tmp_path / "key.yaml").write_text("questions:\n  - {id: A, problem: p.yaml, index: 0, answer: find.0.s}\n"
                                       "  - {id: B, problem: p.yaml, index: 1, answer: find.0.s, "
                                       "carry: {from: A, param: s0}}\n")
    capsys.readouterr()
    assert run_selftest(str(tmp_path / "key.yaml"), 2) == 0
    out, err = capsys.readouterr()
    assert "carry: B takes the answer to A (either sign) within 0.4 ... 40" in out   # A = 4 by hand
    assert "question B's true answer is within its tolerance of the answer to A it carries" in err
