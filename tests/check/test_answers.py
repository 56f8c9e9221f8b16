"""Answer files: structure, tolerances, points, dotted keys, positions,
invalid files (exit 2 with file:line:col)."""

from __future__ import annotations

import pytest

from dyncli.check.compare import Tolerance
from tests.check.helpers import FIX, answer, grade, statuses

INLINE = """\
problem:
  type: rectilinear
  a: -4
  v1: 20
  find: [{t: 2}, {v: 0}]
answers:
  find.0.s: 32
  find.0.v: 12
  find.1.t: 5.02
"""


def test_inline_problem_graded():
    r = grade(INLINE)
    assert statuses(r) == {"find.0.s": "correct", "find.0.v": "correct", "find.1.t": "correct"}
    assert r.exit_code == 0 and r.score == 3 == r.max_score


def test_referenced_problem_relative_to_answer_file(tmp_path):
    from dyncli.check.selfstudy import SelfStudy

    sub = tmp_path / "students"
    sub.mkdir()
    (sub / "p.yaml").write_text((FIX / "brake.yaml").read_text())
    assert grade("problem: p.yaml\nanswers: {find.1.t: 5}\n", base=sub).exit_code == 0
    # outside the answer file's folder: refused, unless the instructor widens it with --root
    (tmp_path / "q.yaml").write_text((FIX / "brake.yaml").read_text())
    r = grade("problem: ../q.yaml\nanswers: {find.1.t: 5}\n", base=sub)
    assert r.exit_code == 2 and "leads outside" in str(r.submissions[0].groups[0].error)
    r = grade("problem: ../q.yaml\nanswers: {find.1.t: 5}\n", base=sub, checker=SelfStudy(root=tmp_path))
    assert r.exit_code == 0


def test_positions_of_answers():
    r = grade(INLINE)
    a = answer(r, "find.1.t")
    assert (a.line, a.col) == (9, 3)


def test_file_level_tolerance_and_per_answer_override():
    text = """\
problem: brake.yaml
tolerance: {sigfigs: 2}
answers:
  find.0.s: 32.4                      # 2 s.f.: bound 0.51 -> correct
  find.0.v: {value: 12.1, sigfigs: 3} # 3 s.f.: bound 0.051 -> wrong
  find.1.t: {value: 5.04, rtol: 0.01} # back to rtol/atol: 0.04 <= 0.05 -> correct
  find.2.t: {value: 5.04, rtol: 0.001, atol: 0}
"""
    r = grade(text)
    assert statuses(r) == {"find.0.s": "correct", "find.0.v": "wrong", "find.1.t": "correct", "find.2.t": "wrong"}
    assert answer(r, "find.0.s").tolerance == Tolerance(sigfigs=2)
    assert answer(r, "find.1.t").tolerance == Tolerance(rtol=0.01, atol=1e-8)
    assert answer(r, "find.2.t").tolerance == Tolerance(rtol=0.001, atol=0.0)


def test_rtol_only_keeps_file_atol():
    text = "problem: brake.yaml\ntolerance: {rtol: 0.1, atol: 0.5}\nanswers:\n  find.1.v: 0.4\n  find.0.s: {value: 33, rtol: 0}\n"
    r = grade(text)
    assert statuses(r) == {"find.1.v": "correct", "find.0.s": "wrong"}
    assert answer(r, "find.0.s").tolerance == Tolerance(rtol=0.0, atol=0.5)


def test_tolerance_numbers_may_be_scientific_strings():
    r = grade("problem: brake.yaml\ntolerance: {rtol: 1e-3, atol: 1e-9}\nanswers: {find.0.s: 32.03}\n")
    assert answer(r, "find.0.s").tolerance == Tolerance(rtol=1e-3, atol=1e-9)
    assert r.exit_code == 0


def test_points_and_score():
    text = "problem: brake.yaml\nanswers:\n  find.0.s: {value: 32, points: 2.5}\n  find.0.v: {value: 13, points: 3}\n  find.1.t: 5\n"
    r = grade(text)
    assert r.score == 3.5 and r.max_score == 6.5
    assert r.exit_code == 1


def test_checks_list_with_top_level_tolerance():
    text = """\
tolerance: {sigfigs: 3}
checks:
  - problem: set.yaml
    index: 0
    answers: {find.0.s: 32.0, find.0.v: 12.0}
  - problem: set.yaml
    index: 1
    tolerance: {rtol: 0.001}
    answers: {find.0.s: 3, find.0.v: 4, find.1.t: 5, find.1.s: 17.01}
"""
    r = grade(text)
    assert r.exit_code == 0, [a.message for a in r.submissions[0].questions]
    assert r.score == 6
    c1 = r.submissions[0].groups[1]
    assert c1.title == "Set 1"
    assert c1.questions[0].tolerance == Tolerance(rtol=0.001, atol=1e-8)


def test_whole_record_answer():
    r = grade("problem: brake.yaml\nanswers:\n  find.1: {t: 5, s: 50, v: 0, a: -4, reached: true, distance: 50}\n")
    assert r.exit_code == 0


def test_params_override_per_student():
    r = grade("problem: params.yaml\nparams: {v0: 30}\nanswers: {find.0.s: 25, find.0.v: 20}\n")
    assert r.exit_code == 0
    r = grade("problem: params.yaml\nanswers: {find.0.s: 15, find.0.v: 10}\n")
    assert r.exit_code == 0


def test_params_override_error_points_at_answer_file():
    r = grade("problem: params.yaml\nparams:\n  v0: 2^3\nanswers: {find.0.s: 25}\n")
    cr = r.submissions[0].groups[0]
    assert r.exit_code == 2
    assert (cr.error.file, cr.error.line) == ("answers.yaml", 3)
    assert "**" in cr.error.message


# -- unknown keys --------------------------------------------------------------

def test_unknown_key_did_you_mean():
    r = grade("problem: brake.yaml\nanswers:\n  find.1.tt: 5\n  fnd.0.s: 32\n")
    a = answer(r, "find.1.tt")
    assert a.status == "unknown" and a.score == 0 and "did you mean 'find.1.t'" in a.message
    assert "did you mean 'find.0.s'" in answer(r, "fnd.0.s").message
    assert r.exit_code == 1


def test_unknown_key_index_out_of_range():
    r = grade("problem: brake.yaml\nanswers:\n  find.5.t: 5\n  find.x.t: 1\n  case.0: 1\n")
    assert "has 3 entries" in answer(r, "find.5.t").message
    assert "use an index" in answer(r, "find.x.t").message
    assert "single value" in answer(r, "case.0").message


def test_unknown_key_without_close_match_lists_results():
    a = answer(grade("problem: brake.yaml\nanswers: {zzzzzz: 1}\n"), "zzzzzz")
    assert "the results are: case, find" in a.message


# -- invalid answer files: diagnostics with positions (exit 2) --------------

@pytest.mark.parametrize("text,line,col,fragment", [
    ("problem: brake.yaml\nanswer: {case: 1}\n", 2, 1, "did you mean 'answers'"),
    ("answers: {case: 1}\n", 1, 1, "missing 'problem'"),
    ("problem: brake.yaml\n", 1, 1, "missing 'answers'"),
    ("problem: brake.yaml\nanswers: []\n", 2, 10, "non-empty mapping"),
    ("problem: brake.yaml\ntolerance: {rtol: -1}\nanswers: {case: 1}\n", 2, 19, "rtol must be"),
    ("problem: brake.yaml\ntolerance: {sigfigs: 2, rtol: 0.1}\nanswers: {case: 1}\n", 2, 13, "either sigfigs"),
    ("problem: brake.yaml\ntolerance: {sigfig: 2}\nanswers: {case: 1}\n", 2, 13, "did you mean 'sigfigs'"),
    ("problem: brake.yaml\ntolerance: {sigfigs: 2.5}\nanswers: {case: 1}\n", 2, 22, "whole number"),
    ("problem: 3\nanswers: {case: 1}\n", 1, 10, "file path or an inline"),
    ("- 1\n- 2\n", 1, 1, "expected answers"),
    ("problem: brake.yaml\nanswers: {case: 1\n", 3, 1, "YAML syntax error"),
    ("checks: []\n", 1, 1, "non-empty list"),
    ("checks: [{problem: brake.yaml, answers: {case: 1}}]\nextra: 1\n", 2, 1, "unknown top-level key"),
    ("", 1, 1, "empty"),
    ("problem: brake.yaml\nanswers: {case: !!python/object:os.system 1}\n", 2, 17, "not allowed"),
])
def test_invalid_answer_files(text, line, col, fragment):
    r = grade(text)
    assert r.exit_code == 2
    d = r.submissions[0].diagnostics[0]
    assert fragment in d.message, str(d)
    assert (d.line, d.col) == (line, col), str(d)
    assert str(d).startswith(f"answers.yaml:{line}:{col}: ")


@pytest.mark.parametrize("spec,fragment", [
    ("{value: 1, pionts: 2}", "did you mean 'points'"),
    ("{value: 1, points: -2}", "points must be"),
    ("{rtol: 0.1}", "missing 'value'"),
    ("{value: 1, sigfigs: 0}", "sigfigs must be"),
])
def test_invalid_answer_spec_marks_that_answer(spec, fragment):
    r = grade(f"problem: brake.yaml\nanswers:\n  case: {spec}\n  find.1.t: 5\n")
    assert answer(r, "case").status == "invalid" and fragment in answer(r, "case").message
    assert answer(r, "find.1.t").status == "correct"
    assert r.exit_code == 2


def test_problem_file_missing_or_invalid():
    r = grade("problem: nothere.yaml\nanswers: {case: 1}\n")
    cr = r.submissions[0].groups[0]
    assert r.exit_code == 2 and "not found" in cr.error.message and cr.error.line == 1
    assert cr.questions[0].status == "error" and cr.questions[0].score == 0 and cr.max_score == 1
    r = grade("problem: bad-problem.yaml\nanswers: {case: 1}\n")
    cr = r.submissions[0].groups[0]
    assert r.exit_code == 2
    assert cr.error.file.endswith("bad-problem.yaml") and cr.error.line == 4
    assert "did you mean 'find'" in cr.error.message


def test_inline_problem_error_points_into_answer_file():
    r = grade("problem:\n  type: rectilinear\n  a: -4\n  v1: [1, 2]\n  find: [{t: 1}]\nanswers: {case: 1}\n")
    cr = r.submissions[0].groups[0]
    assert r.exit_code == 2 and cr.error.file == "answers.yaml" and cr.error.line == 4


def test_multi_problem_file_needs_index():
    r = grade("problem: set.yaml\nanswers: {case: 1}\n")
    assert r.exit_code == 2 and "index: N" in r.submissions[0].groups[0].error.message
    r = grade("problem: set.yaml\nindex: 5\nanswers: {case: 1}\n")
    assert r.exit_code == 2 and "index must be 0-1" in r.submissions[0].groups[0].error.message


def test_answers_with_units_in_self_study():
    r = grade("problem: brake.yaml\nanswers:\n  find.0.s: \"3200 cm\"\n  find.0.v: \"43.2 km/h\"\n"
              "  find.1.t: \"5 kg\"\n  find.1.s: \"50 furlongz\"\n")
    st = statuses(r)
    assert st == {"find.0.s": "correct", "find.0.v": "correct", "find.1.t": "wrong", "find.1.s": "invalid"}
    assert "wrong dimension" in answer(r, "find.1.t").message
