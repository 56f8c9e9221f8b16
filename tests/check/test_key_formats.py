"""Every format of `check --key` (table, json per §7, junit, github,
gradescope with visibility), and grep-style proof that none of them leaks an
expected value — nor the correct answer of a carried question — without
--reveal, in both modes."""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET

import pytest

from tests.check.keyhelpers import check_json, write_sub

PROBLEMS = """\
problems:
  - type: rectilinear
    title: "Leak car"
    params: {v0: 20.13, a0: -3.7}
    a: a0
    v1: v0
    find: [{t: 1.7}, {v: 0}]
  - type: rectilinear
    title: "Leak train"
    params: {s0: 1, u0: 2.3}
    a: 0.77
    s1: s0
    v1: u0
    find: [{t: 2.9}]
"""
KEYTEXT = """\
title: leak test
variants:
  salt: leak
  params:
    v0: {uniform: [15.13, 25.13], step: 0.37}
    a0: {choice: [-3.7, -4.3]}
questions:
  - {id: p, problem: hw.yaml, index: 0, answer: find.0.s}
  - {id: q, problem: hw.yaml, index: 0, answer: find.1.t, partial: {sign: 0.5}}
  - {id: r, problem: hw.yaml, index: 0, answer: find.1.s, visible: false}
  - {id: c, problem: hw.yaml, index: 1, answer: find.0.s, carry: {from: r, param: s0}}
  - {id: z, problem: hw.yaml, index: 0, answer: find.1.v}
"""
FORMATS = ("table", "json", "junit", "github", "gradescope")


def _truth(v0: float, a0: float) -> dict[str, float]:
    """By hand: s = v0 t + a t²/2, v = v0 + a t; the train starts at s0 = r."""
    r = v0 ** 2 / (-2 * a0)
    return {"p": v0 * 1.7 + a0 * 1.7 ** 2 / 2, "q": -v0 / a0, "r": r, "z": 0.0,
            "c": r + 2.3 * 2.9 + 0.77 * 2.9 ** 2 / 2}


@pytest.fixture
def leak(tmp_path):
    from dyncli.check.problemfiles import ProblemFiles
    from dyncli.check.keyfile import read_key

    (tmp_path / "hw.yaml").write_text(PROBLEMS)
    (tmp_path / "key.yaml").write_text(KEYTEXT)
    key = read_key(str(tmp_path / "key.yaml"), ProblemFiles())
    p = key.variants.draw("eve")
    t = _truth(p["v0"], p["a0"])
    wrong_r = t["r"] * 1.37
    mine_c = wrong_r + 2.3 * 2.9 + 0.77 * 2.9 ** 2 / 2     # c computed from her wrong r: carried
    answers = {"p": t["p"] * 1.29, "q": -t["q"], "r": wrong_r, "c": mine_c, "z": 0.31}
    sub = write_sub(tmp_path, "eve.yaml", "eve", answers)
    return tmp_path / "key.yaml", sub, t


def _needles(x: float) -> list[str]:
    return sorted({repr(x), f"{x:.6g}", f"{x:.5g}", f"{x:.4g}"}, key=len)


def test_no_format_leaks_an_expected_value_without_reveal(leak, capsys):
    key, sub, t = leak
    for fmt in FORMATS:
        code, out, err = check_json(key, [sub], capsys, fmt=fmt)
        text = (json.dumps(out) if isinstance(out, dict) else out) + err
        assert code == 1
        for qid, x in t.items():
            if x == 0 or qid == "q":   # q: a sign slip, -given is the answer (the student's own number)
                continue
            for n in _needles(x):
                assert n not in text, f"{fmt} leaks {qid} = {x} as {n!r}"
        assert "expected" not in text.lower() and "absolute" not in text.lower()


def test_reveal_shows_them(leak, capsys):
    key, sub, t = leak
    for fmt in FORMATS:
        _, out, _ = check_json(key, [sub], capsys, fmt=fmt, reveal=True)
        if isinstance(out, dict):
            text = json.dumps(out)
            assert ("expected" in text or "35.86" in text) and re.search(r"3[0-9]\.86", text), fmt
        else:
            assert f"{t['p']:.6g}" in out, fmt


def test_json_shape_of_section_7(leak, capsys):
    key, sub, _ = leak
    code, doc, _ = check_json(key, [sub], capsys)
    assert {"score", "max_score", "exit_code", "submissions"} <= set(doc) and doc["exit_code"] == code == 1
    s = doc["submissions"][0]
    assert {"file", "student", "score", "max_score", "questions", "unknown"} <= set(s)
    q = {x["id"]: x for x in s["questions"]}
    for rec in q.values():
        assert {"id", "status", "score", "points", "diagnosis", "message", "given"} <= set(rec)
        assert "expected" not in rec and "absolute_error" not in rec
    assert q["q"]["status"] == "partial" and q["q"]["diagnosis"] == "sign" and q["q"]["score"] == 0.5
    assert q["c"]["status"] == "carried" and q["r"]["status"] == "wrong" and q["p"]["status"] == "wrong"
    assert q["p"]["relative_error"] == 0.29                # 2 significant figures
    assert q["z"]["relative_error"] is None and "0.31" not in q["z"]["message"].replace("0.31", "", 0)


def test_gradescope_visibility_and_hidden_summary(leak, capsys):
    key, sub, _ = leak
    _, doc, _ = check_json(key, [sub], capsys, fmt="gradescope")
    vis = {t["name"].split(" ")[0]: t["visibility"] for t in doc["tests"]}
    assert vis == {"p": "visible", "q": "visible", "r": "after_published", "c": "visible", "z": "visible"}
    assert "1 question graded after release" in doc["output"]
    # the top-level score would override the tests' total and count the hidden r: left out
    assert "score" not in doc and sum(t["score"] for t in doc["tests"]) == pytest.approx(0.5 + 1)


def test_junit_and_github_shapes(leak, capsys):
    key, sub, _ = leak
    _, out, _ = check_json(key, [sub], capsys, fmt="junit")
    suite = ET.fromstring(out).find("testsuite")
    assert suite.get("tests") == "5" and suite.get("failures") == "4"
    _, out, _ = check_json(key, [sub], capsys, fmt="github")
    lines = out.splitlines()
    assert all(line.startswith(("::error ", "::notice ")) for line in lines)
    assert sum(line.startswith("::error file=") for line in lines) == 4


def test_junit_failure_body_has_real_line_breaks(leak, capsys):
    # the body was one line with a literal "\x0a" between the feedback and the given value
    key, sub, _ = leak
    _, out, _ = check_json(key, [sub], capsys, fmt="junit")
    fail = next(c for c in ET.fromstring(out).iter("testcase") if c.get("name") == "p").find("failure")
    assert "\\x0a" not in fail.text
    first, given = fail.text.split("\n")
    assert first.startswith("p: wrong (0/1)") and given.startswith("given: ")


HOSTILE = "x\n::error file=a.yaml,line=1::forged\x1b[31mred\u2028"


def test_user_strings_never_break_a_line(tmp_path, capsys):
    (tmp_path / "hw.yaml").write_text(PROBLEMS)
    (tmp_path / "key.yaml").write_text(KEYTEXT)
    sub = tmp_path / "s.yaml"
    sub.write_text("student: eve\nanswers:\n  p: " + json.dumps(HOSTILE) + "\n  " + json.dumps(HOSTILE)
                   + ": 3\n  q: " + json.dumps("3 " + HOSTILE) + "\n")
    for fmt in FORMATS:
        _, out, err = check_json(tmp_path / "key.yaml", [str(sub)], capsys, fmt=fmt)
        text = json.dumps(out) if isinstance(out, dict) else out
        for stream in (text, err):
            assert "\x1b" not in stream and "\u2028" not in stream
            assert not any(line.startswith("::error file=a.yaml") for line in stream.splitlines()), fmt
            assert not re.search(r"^\S+:1:1: ", stream, re.M)


def test_section5_json_has_no_absolute_error_and_rounded_relative_error(capsys):
    from dyncli.check.command import run_check
    from tests.check.helpers import FIX

    capsys.readouterr()
    run_check([str(FIX / "alice.yaml")], "json")
    doc = json.loads(capsys.readouterr().out)
    answers = [a for f in doc["files"] for c in f["checks"] for a in c["answers"]]
    assert all("absolute_error" not in a and "expected" not in a for a in answers)
    rels = [a["relative_error"] for a in answers if a["relative_error"]]
    assert rels and all(float(f"{r:.2g}") == r for r in rels)
    run_check([str(FIX / "alice.yaml")], "json", reveal=True)
    doc = json.loads(capsys.readouterr().out)
    assert any("absolute_error" in a for f in doc["files"] for c in f["checks"] for a in c["answers"])


def test_section5_zero_true_value_does_not_echo_the_distance(tmp_path, capsys):
    """For a true 0 the absolute error is the given value's distance to the answer: never shown."""
    from dyncli.check.command import run_check

    p = tmp_path / "a.yaml"
    p.write_text("problem: {type: rectilinear, a: -4, v1: 20, find: [{v: 0}]}\nanswers: {find.0.v: 0.4375}\n")
    for fmt in FORMATS:
        capsys.readouterr()
        assert run_check([str(p)], fmt) == 1
        out, err = capsys.readouterr()
        assert "absolute" not in (out + err)
        # the given value is echoed as given, and no other number says how far it is from 0
        assert "4.4e-01" not in out and "0.44" not in out and "error exceeds the tolerance" in out.replace("\n", " ")


@pytest.mark.parametrize("fmt", ["json", "gradescope"])
def test_an_invalid_key_still_prints_json(tmp_path, capsys, fmt):
    (tmp_path / "key.yaml").write_text("questions: []\n")
    code, doc, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"p": 1})], capsys, fmt=fmt)
    assert code == 2 and doc["score"] == 0 and "questions" in err
