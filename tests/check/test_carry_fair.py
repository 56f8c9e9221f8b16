"""Carried credit earned, and only earned (docs/check.md, "Carry").

References are the closed forms of notes §6 case 1 (s = s1 + v1 t + a t²/2,
v = v1 + a t) evaluated here by hand, never the grader's own solves.

* forged submissions: a huge carried-from answer (1e9, "1000 km", 1e308,
  -1e9) earns no carried question, on the course example and along a chain;
* the two wrong grades of the carry rules before: the sheet of a carried
  question showed the key's default, and a rounded intermediate carried
  unrounded scored 0;
* property: random chains, a student answering from the sheet with correct
  arithmetic and any rounding to >= 3 significant figures scores full points.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.check.keyhelpers import check_json, questions, write_sub

COURSE = Path(__file__).resolve().parents[2] / "docs" / "course-example"


def _alice_1c() -> float:
    return 25 ** 2 / 6          # alice: v0 = 25 m/s, a0 = -3 m/s² -> v0²/(2|a0|)


@pytest.mark.parametrize("forged", [1.0e9, "1000 km", 1e308, -1.0e9, "1.0e9 m", 5.0e4])
def test_a_huge_carried_input_earns_nothing(tmp_path, capsys, forged):
    sub = write_sub(tmp_path, "m.yaml", "alice@example.edu", {"1c": forged, "3": forged})
    _, doc, _ = check_json(COURSE / "key.yaml", [sub], capsys)
    q = questions(doc)
    assert q["3"]["status"] == "wrong" and q["3"]["score"] == 0
    assert doc["submissions"][0]["score"] == 0


def test_an_answer_repeating_the_carried_input_earns_nothing(tmp_path, capsys):
    # 1c twice its value (a plausible slip) and 3 = that same number: nothing of "+ 32 m"
    c = 2 * _alice_1c()
    sub = write_sub(tmp_path, "m.yaml", "alice@example.edu", {"1c": round(c, 1), "3": round(c, 1)})
    _, doc, _ = check_json(COURSE / "key.yaml", [sub], capsys)
    q = questions(doc)["3"]
    assert q["status"] == "wrong" and "repeats it" in q["message"]
    # ... while 3 computed from it (s0 + 32 m, by hand) is carried
    sub = write_sub(tmp_path, "n.yaml", "alice@example.edu", {"1c": round(c, 1), "3": round(c + 32, 1)})
    _, doc, _ = check_json(COURSE / "key.yaml", [sub], capsys)
    assert questions(doc)["3"]["status"] == "carried"


CHAIN = """\
title: chain
tolerance: {rtol: 0.01}
questions:
  - {id: A, problem: chain.yaml, index: 0, answer: find.0.s}
  - {id: B, problem: chain.yaml, index: 1, answer: find.0.s, carry: {from: A, param: s0}}
  - {id: C, problem: chain.yaml, index: 1, answer: find.0.v, carry: {from: B, param: v0}}
"""
CHAIN_PROBLEMS = """\
problems:
  - {type: rectilinear, a: 2, v1: 3, find: [{t: 1}]}
  - {type: rectilinear, params: {s0: 0, v0: 1}, a: 0.5, s1: s0, v1: v0, find: [{t: 2}]}
"""


@pytest.mark.parametrize("x", [1e9, -1e9, 1e308, 4e3])
def test_forged_chain_earns_nothing(tmp_path, capsys, x):
    (tmp_path / "chain.yaml").write_text(CHAIN_PROBLEMS)
    (tmp_path / "key.yaml").write_text(CHAIN)
    # A = 4, B = A + 2 v0 + 1 = 7, C = v0 + 1 = B + 1 by hand: every forged link is refused
    for ans in ({"A": x, "B": x, "C": x}, {"A": x, "B": x + 3, "C": x + 4}):
        _, doc, _ = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "f.yaml", "f", ans)], capsys)
        assert doc["submissions"][0]["score"] == 0, (x, ans)


def test_the_sheet_of_a_carried_question_names_the_dependency(capsys):
    from dyncli.check.sheet import run_variant

    capsys.readouterr()
    assert run_variant(str(COURSE / "key.yaml"), "alice@example.edu", "yaml") == 0
    import yaml

    doc = yaml.safe_load(capsys.readouterr().out)
    train = doc["problems"][2]
    assert train["problem"]["params"]["s0"] == {"carried": "1c"}      # never the key's default 50
    assert run_variant(str(COURSE / "key.yaml"), "alice@example.edu", "markdown") == 0
    md = capsys.readouterr().out
    assert "`s0` = **your answer to 1c**" in md and "`s0` = 50" not in md


SENSITIVE = """\
  - {type: rectilinear, title: "HW1.4 from rest at 2 m/s², for the time of 1b", params: {T: 5}, a: 2, v1: 0,
     find: [{t: T}]}
"""


@pytest.fixture
def course(tmp_path):
    """The course example with a question sensitive to its carried input
    (4: s = T² with T = the answer to 1b)."""
    for f in ("hw1.yaml", "key.yaml"):
        shutil.copy(COURSE / f, tmp_path / f)
    with open(tmp_path / "hw1.yaml", "a") as fh:
        fh.write(SENSITIVE)
    with open(tmp_path / "key.yaml", "a") as fh:
        fh.write('  - {id: "4", problem: hw1.yaml, index: 3, answer: find.0.s, unit: m, carry: {from: "1b", param: T}}\n')
    return tmp_path


def test_rounded_intermediate_carried_unrounded_or_rounded(course, capsys):
    mine = 1.4545454545                # alice's wrong 1b (true 25/3), typed "1.45"
    for four, how in ((mine ** 2, "unrounded"), (1.45 ** 2, "rounded")):
        sub = write_sub(course, f"{how}.yaml", "alice@example.edu", {"1b": 1.45, "4": float(f"{four:.3g}")})
        _, doc, err = check_json(course / "key.yaml", [sub], capsys)
        q = questions(doc)["4"]
        assert q["status"] == "carried" and q["score"] == 1, (how, q, err)
    # a 4 off by 0.8 % from what follows from her 1.45: measured against that, not against the truth
    sub = write_sub(course, "off.yaml", "alice@example.edu", {"1b": 1.45, "4": round(1.45 ** 2 * 1.03, 3)})
    _, doc, _ = check_json(course / "key.yaml", [sub], capsys)
    q = questions(doc)["4"]
    assert q["status"] == "wrong" and "from the answer that follows from your 1b = 1.45" in q["message"]
    assert q["carried_relative_error"] == pytest.approx(0.03, abs=0.011)
    assert q["relative_error"] > 0.9           # against the truth (25/3)² it is far off


def test_an_unsolvable_carried_resolve_leaks_nothing(tmp_path, capsys):
    # the true A = 4 gives the mass T - 4.5 = -0.5: the solver's message quotes it
    (tmp_path / "p.yaml").write_text("problems:\n"
                                     "  - {type: rectilinear, a: 2, v1: 3, find: [{t: 1}]}\n"
                                     "  - {type: vibration, params: {T: 5}, m: T - 4.5, k: 400, zeta: 0.05, x0: 0.2,"
                                     " v0: 0, at: [0, 1]}\n")
    (tmp_path / "key.yaml").write_text("questions:\n  - {id: A, problem: p.yaml, index: 0, answer: find.0.s}\n"
                                       "  - {id: B, problem: p.yaml, index: 1, answer: omega_n, "
                                       "carry: {from: A, param: T}}\n")
    sub = write_sub(tmp_path, "s.yaml", "s", {"A": 4, "B": 1})
    for fmt in ("json", "gradescope", "table", "github", "junit"):
        _, out, err = check_json(tmp_path / "key.yaml", [sub], capsys, fmt=fmt)
        text = str(out) + err
        assert "-0.5" not in text and "not graded" in text, fmt      # m = T - 4.5 with the true A = 4
        assert "not graded: not graded" not in text, fmt
    _, out, _ = check_json(tmp_path / "key.yaml", [sub], capsys, reveal=True)
    assert "got -0.5" in questions(out)["B"]["message"]                # the instructor sees why


# ---------------------------------------------------------------------------
# property: random chains, answered from the sheet with correct arithmetic

def _round(x: float, n: int) -> float:
    return float(f"{x:.{n}g}")


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(v1=st.floats(1, 5), a=st.floats(0.5, 2), t=st.floats(1, 3),
       vb=st.floats(5, 10), ab=st.floats(-2, 2), tb=st.floats(2, 4),
       ac=st.floats(0.5, 3), tc=st.floats(1.5, 3),
       slip=st.sampled_from([1.0, 1.0, 1.7, 0.4, 2.0, -1.0]),
       n=st.lists(st.integers(3, 6), min_size=3, max_size=3), carry_unrounded=st.booleans())
def test_answers_from_the_sheet_score_full_points(v1, a, t, vb, ab, tb, ac, tc, slip, n, carry_unrounded):
    r = lambda x: float(f"{x:.6g}")              # the key's numbers as written in the file  # noqa: E731
    v1, a, t, vb, ab, tb, ac, tc = map(r, (v1, a, t, vb, ab, tb, ac, tc))
    problems = ("problems:\n"
                f"  - {{type: rectilinear, a: {a!r}, v1: {v1!r}, find: [{{t: {t!r}}}]}}\n"
                f"  - {{type: rectilinear, params: {{s0: 0}}, a: {ab!r}, s1: s0, v1: {vb!r}, find: [{{t: {tb!r}}}]}}\n"
                f"  - {{type: rectilinear, params: {{w: 1}}, a: {ac!r}, v1: w, find: [{{t: {tc!r}}}]}}\n")
    key = ("tolerance: {sigfigs: 3}\nquestions:\n"
           "  - {id: A, problem: p.yaml, index: 0, answer: find.0.s}\n"
           "  - {id: B, problem: p.yaml, index: 1, answer: find.0.s, carry: {from: A, param: s0}}\n"
           "  - {id: C, problem: p.yaml, index: 2, answer: find.0.s, carry: {from: B, param: w}}\n")
    # the student: A by hand (perhaps with a slip), then each next from their own previous answer
    A = (v1 * t + a * t * t / 2) * slip
    A_typed = _round(A, n[0])
    B = (A if carry_unrounded else A_typed) + vb * tb + ab * tb * tb / 2
    B_typed = _round(B, n[1])
    C = (B if carry_unrounded else B_typed) * tc + ac * tc * tc / 2
    with tempfile.TemporaryDirectory() as d:
        p = Path(d)
        (p / "p.yaml").write_text(problems)
        (p / "key.yaml").write_text(key)
        (p / "s.yaml").write_text(f"student: s\nanswers:\n  A: {A_typed!r}\n  B: {B_typed!r}\n"
                                  f"  C: {_round(C, n[2])!r}\n")
        from dyncli.check.grader import Grader
        from dyncli.check.keyfile import read_key
        from dyncli.check.problemfiles import ProblemFiles
        from dyncli.check.submission import read_submission

        files = ProblemFiles()
        k = read_key(str(p / "key.yaml"), files)
        assert not k.diagnostics
        sr = Grader(k, files).grade(read_submission(str(p / "s.yaml")))
    got = {q.id: (q.status, q.message) for q in sr.questions}
    assert got["B"][0] in ("correct", "carried") and got["C"][0] in ("correct", "carried"), got
    if slip == 1.0:
        assert got["A"][0] == "correct"
