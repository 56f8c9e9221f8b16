"""Graded work (docs/check.md): the key is the only authority.  References
come from the closed forms of keydata/hw.yaml (keyhelpers.truth), never from
the grader."""

from __future__ import annotations

import hashlib
import math

import numpy as np
import pytest

from tests.check.keyhelpers import KEY, KEYDATA, check_json, params_of, questions, truth, write_sub

STUDENT = "alice@example.edu"


def full_answers(student: str) -> dict:
    p = params_of(student)
    t = truth(p["v0"], p["a0"])
    return {"1a": t["1a"], "1b": t["1b"], "1c": t["1c"], "1d": t["1d"], "1e": t["1e"]}


def test_all_correct_scores_full_and_exit_0(tmp_path, capsys):
    sub = write_sub(tmp_path, "a.yaml", STUDENT, full_answers(STUDENT))
    code, doc, _ = check_json(KEY, [sub], capsys)
    assert code == 0 and doc["exit_code"] == 0
    assert doc["score"] == doc["max_score"] == 6
    assert {q["status"] for q in doc["submissions"][0]["questions"]} == {"correct"}
    assert doc["submissions"][0]["student"] == STUDENT


@pytest.mark.parametrize("field,value", [("tolerance", "{rtol: 10}"), ("points", "100"),
                                         ("params", "{v0: 20}"), ("problem", "hw.yaml"), ("title", "x")])
def test_submission_cannot_set_key_fields(tmp_path, capsys, field, value):
    sub = write_sub(tmp_path, "a.yaml", STUDENT, {"1a": 1}, extra=f"{field}: {value}")
    code, doc, err = check_json(KEY, [sub], capsys)
    assert code == 2
    assert f"a.yaml:2:1: {field}: '{field}' is not allowed in a submission" in err
    assert doc["score"] == 0 and doc["submissions"][0]["questions"] == []


def test_per_answer_mapping_is_invalid(tmp_path, capsys):
    p = tmp_path / "a.yaml"
    p.write_text(f"student: {STUDENT}\nanswers:\n  '1a': {{value: 3, rtol: 10}}\n")
    code, _, err = check_json(KEY, [str(p)], capsys)
    assert code == 2 and "answers.1a.value" in err and "belong to the key" in err


def test_missing_and_unknown(tmp_path, capsys):
    ans = full_answers(STUDENT)
    del ans["1b"]
    ans["1x"] = 3
    ans["1bb"] = 3
    code, doc, _ = check_json(KEY, [write_sub(tmp_path, "a.yaml", STUDENT, ans)], capsys)
    q = questions(doc)
    assert code == 1 and q["1b"]["status"] == "missing" and q["1b"]["score"] == 0
    unknown = {u["id"]: u["message"] for u in doc["submissions"][0]["unknown"]}
    assert set(unknown) == {"1x", "1bb"} and "did you mean '1b'?" in unknown["1bb"]
    assert doc["score"] == 5


def test_student_id_from_option_or_file_stem(tmp_path, capsys):
    sub = write_sub(tmp_path, "bob.yaml", None, {"1a": 1})
    _, doc, _ = check_json(KEY, [sub], capsys)
    assert doc["submissions"][0]["student"] == "bob"
    _, doc, _ = check_json(KEY, [sub], capsys, student="carol")
    assert doc["submissions"][0]["student"] == "carol"
    sub = write_sub(tmp_path, "x.yaml", "dave", {"1a": 1})
    code, _, err = check_json(KEY, [sub], capsys, student="carol")
    assert code == 2 and "does not match --student" in err


# -- variants ---------------------------------------------------------------

def _independent_index(salt: str, student: str, name: str, n: int) -> int:
    """The documented recipe, written out: sha256(salt \\x1f id \\x1f name) -> SeedSequence -> PCG64,
    raw 64-bit outputs, rejection above the last multiple of n."""
    h = hashlib.sha256(f"{salt}\x1f{student}\x1f{name}".encode()).digest()
    bits = np.random.PCG64(np.random.SeedSequence(int.from_bytes(h, "big")))
    while True:
        r = int(bits.random_raw())
        if r < (2 ** 64 // n) * n:
            return r % n


@pytest.mark.parametrize("student", ["alice@example.edu", "bob", "", "ünï 42"])
def test_draws_follow_the_documented_recipe(student):
    p = params_of(student)
    assert p["v0"] == pytest.approx(15 + 0.5 * _independent_index("test-salt", student, "v0", 21), abs=1e-12)
    assert p["a0"] == [-3, -4, -5][_independent_index("test-salt", student, "a0", 3)]
    assert params_of(student) == p   # same id, same numbers


def test_adding_a_parameter_keeps_the_others(tmp_path):
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text().replace("{v0: 20, a0: -4}",
                                                                                  "{v0: 20, a0: -4, n: 1}"))
    text = KEY.read_text().replace("    a0: {choice: [-3, -4, -5]}\n",
                                   "    a0: {choice: [-3, -4, -5]}\n    n: {integers: [2, 6]}\n")
    (tmp_path / "key.yaml").write_text(text)
    for sid in [f"s{i}" for i in range(30)]:
        old, new = params_of(sid), params_of(sid, tmp_path / "key.yaml")
        assert {k: new[k] for k in old} == old
        assert new["n"] in range(2, 7) and isinstance(new["n"], int)


def test_distributions_stay_in_their_sets():
    seen_v, seen_a = set(), set()
    for i in range(300):
        p = params_of(f"id{i}")
        seen_v.add(p["v0"])
        seen_a.add(p["a0"])
    assert seen_a == {-3, -4, -5}
    assert seen_v <= {15 + 0.5 * k for k in range(21)} and {15.0, 25.0} <= seen_v


def test_require_is_met_and_an_impossible_require_is_invalid(tmp_path, capsys):
    text = KEY.read_text().replace("questions:", "  require: \"v0**2/(2*abs(a0)) < 40 and v0 > 16\"\nquestions:")
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    (tmp_path / "key.yaml").write_text(text)
    for i in range(40):
        p = params_of(f"r{i}", tmp_path / "key.yaml")
        assert p["v0"] ** 2 / (2 * abs(p["a0"])) < 40 and p["v0"] > 16
    (tmp_path / "key.yaml").write_text(text.replace("< 40", "< 1"))
    code, _, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"1a": 1})], capsys)
    assert code == 2 and "does not hold after 1000 draws" in err


# -- units, diagnosis, partial credit ------------------------------------------------

def test_units_in_answers(tmp_path, capsys):
    p = params_of(STUDENT)
    t = truth(p["v0"], p["a0"])
    ans = {"1a": f"{t['1a'] * 1000!r} mm", "1b": f"{t['1b'] / 60!r} min", "1d": t["1d"],
           "1e": f"{t['1e'] * 3.6!r} km/h"}
    code, doc, _ = check_json(KEY, [write_sub(tmp_path, "a.yaml", STUDENT, ans)], capsys)
    q = questions(doc)
    assert all(q[i]["status"] == "correct" for i in ("1a", "1b", "1d", "1e")), q
    # a bare number is read in the question's unit (1d: mm; 1b: s)
    ans = {"1d": t["1d"] / 1000}
    _, doc, _ = check_json(KEY, [write_sub(tmp_path, "b.yaml", STUDENT, ans)], capsys)
    assert questions(doc)["1d"]["status"] == "wrong" and questions(doc)["1d"]["diagnosis"] == "power_of_ten"


def test_wrong_dimension_is_a_diagnosed_wrong_answer(tmp_path, capsys):
    code, doc, _ = check_json(KEY, [write_sub(tmp_path, "a.yaml", STUDENT, {"1e": "12 kg"})], capsys)
    q = questions(doc)["1e"]
    assert code == 1 and q["status"] == "wrong" and q["diagnosis"] == "wrong_dimension" and q["score"] == 0


@pytest.mark.parametrize("slip,factor", [("sign", -1.0), ("power_of_ten", 1e3), ("power_of_ten", 1e-2),
                                         ("degrees_radians", 180 / math.pi), ("two_pi", 2 * math.pi),
                                         ("two_pi", 1 / (2 * math.pi)), ("factor_two", 0.5)])
def test_each_slip_is_diagnosed(tmp_path, capsys, slip, factor):
    t = full_answers(STUDENT)
    _, doc, _ = check_json(KEY, [write_sub(tmp_path, "a.yaml", STUDENT, {"1e": t["1e"] * factor})], capsys)
    assert questions(doc)["1e"]["diagnosis"] == slip


def test_sign_slip_with_partial_half_scores_half(tmp_path, capsys):
    t = full_answers(STUDENT)
    code, doc, _ = check_json(KEY, [write_sub(tmp_path, "a.yaml", STUDENT, {"1a": -t["1a"]})], capsys)
    q = questions(doc)["1a"]
    assert code == 1 and q["status"] == "partial" and q["diagnosis"] == "sign"
    assert q["score"] == 1.0 and q["points"] == 2.0
    _, doc, _ = check_json(KEY, [write_sub(tmp_path, "b.yaml", STUDENT, {"1a": t["1a"] * 100})], capsys)
    assert questions(doc)["1a"]["score"] == 0.5        # power_of_ten: 0.25 of 2 points
    _, doc, _ = check_json(KEY, [write_sub(tmp_path, "c.yaml", STUDENT, {"1a": t["1a"] * 1.3})], capsys)
    assert questions(doc)["1a"]["status"] == "wrong" and questions(doc)["1a"]["diagnosis"] is None


# -- carry ------------------------------------------------------------------

def test_carried_forward(tmp_path, capsys):
    p = params_of(STUDENT)
    t = truth(p["v0"], p["a0"])
    wrong_1a = t["1a"] * 1.2
    mine = truth(p["v0"], p["a0"], s0=wrong_1a)["1c"]
    code, doc, _ = check_json(KEY, [write_sub(tmp_path, "a.yaml", STUDENT, {"1a": wrong_1a, "1c": mine})], capsys)
    q = questions(doc)
    assert q["1a"]["status"] == "wrong" and q["1c"]["status"] == "carried" and q["1c"]["score"] == 1
    assert "correct with your answer to 1a carried forward" in q["1c"]["message"]
    # the true chain is correct too; a 1c matching neither is wrong
    _, doc, _ = check_json(KEY, [write_sub(tmp_path, "b.yaml", STUDENT, {"1a": wrong_1a, "1c": t["1c"]})], capsys)
    assert questions(doc)["1c"]["status"] == "correct"
    _, doc, _ = check_json(KEY, [write_sub(tmp_path, "c.yaml", STUDENT, {"1a": wrong_1a, "1c": mine + 30})], capsys)
    assert questions(doc)["1c"]["status"] == "wrong"
    # a correct 1a carries nothing: its consequence must match the truth
    _, doc, _ = check_json(KEY, [write_sub(tmp_path, "d.yaml", STUDENT, {"1a": t["1a"], "1c": mine})], capsys)
    assert questions(doc)["1c"]["status"] == "wrong"


CHAIN = """\
title: chain
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


def test_carry_chain(tmp_path, capsys):
    (tmp_path / "chain.yaml").write_text(CHAIN_PROBLEMS)
    (tmp_path / "key.yaml").write_text(CHAIN)
    A = 3 + 1                      # s = v1 t + a t²/2 at t = 1
    B = A + 2 * 1 + 1              # s0 = A, v0 = 1: s = s0 + 2 v0 + 0.5*4/2
    C = B + 0.5 * 2                # v0 = B: v = v0 + a t
    a_ = 10.0                      # the student's wrong A ...
    b_ = a_ + 2 + 1                # ... carried into B ...
    c_ = b_ + 1                    # ... and B's value carried into C
    cases = {"ok": ({"A": A, "B": B, "C": C}, ["correct"] * 3),
             "carried": ({"A": a_, "B": b_, "C": c_}, ["wrong", "carried", "carried"]),
             "last": ({"A": A, "B": 19, "C": 20}, ["correct", "wrong", "carried"]),
             # B 14 times its true value: carries nothing (C = B + 1 would repeat it within 1 %)
             "huge": ({"A": A, "B": 99, "C": 100}, ["correct", "wrong", "wrong"])}
    for name, (ans, want) in cases.items():
        _, doc, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, f"{name}.yaml", name, ans)], capsys)
        assert doc, err
        assert [questions(doc)[i]["status"] for i in "ABC"] == want, name


@pytest.mark.parametrize("carries,message", [
    ({"A": "C", "B": "A", "C": "B"}, "carry forms a cycle"),
    ({"A": "A"}, "carry forms a cycle"),
    ({"B": "Z"}, "no such question"),
])
def test_carry_cycle_or_unknown_is_invalid_key(tmp_path, capsys, carries, message):
    (tmp_path / "chain.yaml").write_text(CHAIN_PROBLEMS)
    lines = ["questions:"]
    for q in "ABC":
        c = f", carry: {{from: {carries[q]}, param: s0}}" if q in carries else ""
        lines.append(f"  - {{id: {q}, problem: chain.yaml, index: 1, answer: find.0.s{c}}}")
    (tmp_path / "key.yaml").write_text("\n".join(lines) + "\n")
    code, _, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"A": 1})], capsys)
    assert code == 2 and message in err


@pytest.mark.parametrize("bad,message", [
    ("  - {id: '1a', problem: hw.yaml, index: 0, answer: find.0.s}\n", "duplicate question id '1a'"),
    ("  - {id: z, problem: hw.yaml, index: 0, answer: find.0.s, pionts: 2}\n", "did you mean 'points'?"),
    ("  - {id: z, problem: hw.yaml, index: 0, answer: find.0.s, partial: {sgn: 1}}\n", "did you mean 'sign'?"),
    ("  - {id: z, problem: hw.yaml, index: 0, answer: find.0.s, points: 1e308}\n", "points must be a number from 0"),
    ("  - {id: z, problem: hw.yaml, index: 0, answer: find.0.s, unit: furlongz}\n", "unknown unit"),
    ("  - {id: z, problem: ../hw.yaml, answer: find.0.s}\n", "leads outside"),
])
def test_invalid_keys(tmp_path, capsys, bad, message):
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    (tmp_path / "key.yaml").write_text(KEY.read_text() + bad)
    code, _, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"1a": 1})], capsys)
    assert code == 2 and message in err and len(err.strip().splitlines()) <= 2


def test_variant_parameter_unknown_to_the_problems_is_invalid(tmp_path, capsys):
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    (tmp_path / "key.yaml").write_text(KEY.read_text().replace("    a0: {", "    vv0: {integers: [1, 2]}\n    a0: {"))
    code, _, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"1a": 1})], capsys)
    assert code == 2 and "no problem of this key has a parameter 'vv0'" in err


def test_each_problem_variant_solved_once(tmp_path, capsys):
    subs = []
    for i in range(12):
        sid = f"s{i % 4}"          # 4 students, 3 submissions each
        subs.append(write_sub(tmp_path, f"x{i}.yaml", sid, full_answers(sid)))
    code, doc, _ = check_json(KEY, subs, capsys)
    assert code == 0
    # per student: problem 0 once, problem 1 once with the true 1a (carry) -> 2 solves
    assert doc["solves"] == 4 * 2


def test_an_invalid_problem_of_the_key_is_reported_once(tmp_path, capsys):
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text().replace("    v1: v0\n", "    v1: v0\n    fnd: 1\n", 1))
    (tmp_path / "key.yaml").write_text(KEY.read_text())
    code, _, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"1a": 1})], capsys)
    assert code == 2
    assert err.strip().splitlines() == [f"{tmp_path / 'hw.yaml'}:8:5: fnd: unknown field 'fnd' (did you mean 'find'?)"]


def test_invalid_answer_and_unsolvable_variant_statuses(tmp_path, capsys):
    (tmp_path / "v.yaml").write_text("type: vibration\nparams: {mm: 1}\nm: mm\nk: 400\nzeta: 0.05\n")
    (tmp_path / "key.yaml").write_text(
        "variants: {salt: s, params: {mm: {choice: [-1]}}}\n"
        "questions:\n  - {id: w, problem: v.yaml, answer: omega_n}\n")
    code, doc, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"w": 20})], capsys)
    q = questions(doc)["w"]
    assert code == 2 and q["status"] == "error" and q["score"] == 0 and "not graded" in q["message"]
    # an unreadable value is invalid (exit 2); the other answers are still graded
    ans = full_answers(STUDENT)
    ans["1b"] = "2^3"
    code, doc, err = check_json(KEY, [write_sub(tmp_path, "b.yaml", STUDENT, ans)], capsys)
    q = questions(doc)
    assert code == 2 and q["1b"]["status"] == "invalid" and "use ** for powers" in q["1b"]["message"]
    assert q["1a"]["status"] == "correct" and "b.yaml:4:3: answers.1b" in err   # file:line:col (col was missing)


@pytest.mark.parametrize("require,needle", [
    ("__import__('os').system('x') < 1", "require:"),
    ("v0 + 1", "must be a comparison"),
    ("v0 < (", "syntax error"),
    ("v0 < w9", "require:"),
    ("v0 is 3", "compares with"),
])
def test_hostile_or_malformed_require_is_invalid(tmp_path, capsys, require, needle):
    import json as _json

    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    (tmp_path / "key.yaml").write_text(KEY.read_text().replace("questions:", f"  require: {_json.dumps(require)}\nquestions:"))
    code, _, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"1a": 1})], capsys)
    assert code == 2 and needle in err and len(err.strip().splitlines()) == 1


def test_every_bad_variant_parameter_is_reported(tmp_path, capsys):
    # only the first bad parameter was reported; now one line for each
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    text = KEY.read_text()
    start = text.index("  params:")
    end = text.index("questions:")
    bad = ("  params:\n    v0: {uniform: [15, 25], step: 0}\n    a0: {choice: []}\n"
           "    s9: {integers: [5, 2]}\n")
    (tmp_path / "key.yaml").write_text(text[:start] + bad + text[end:])
    code, _, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"1a": 1})], capsys)
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 3, err
    assert "v0.step: step must be > 0" in lines[0] and "a0.choice: choice must be a list" in lines[1]
    assert "s9.integers: integers: lo must not exceed hi" in lines[2]


def test_empty_key_and_submission_say_what_was_expected(tmp_path, capsys):
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    (tmp_path / "key.yaml").write_text(KEY.read_text())
    (tmp_path / "empty.yaml").write_text("")
    code, _, err = check_json(tmp_path / "key.yaml", [str(tmp_path / "empty.yaml")], capsys)
    assert code == 2 and "file is empty: expected a submission" in err and "problem" not in err
    code, _, err = check_json(tmp_path / "empty.yaml", [str(tmp_path / "empty.yaml")], capsys)
    assert code == 2 and "file is empty: expected a key" in err


def test_carry_from_a_question_whose_answer_is_not_a_number(tmp_path, capsys):
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    (tmp_path / "key.yaml").write_text(
        "questions:\n  - {id: A, problem: hw.yaml, index: 0, answer: find.1.reached}\n"
        "  - {id: B, problem: hw.yaml, index: 1, answer: find.0.s, carry: {from: A, param: s0}}\n")
    code, doc, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"A": True, "B": 1})],
                                capsys)
    q = questions(doc)
    assert code == 2 and q["A"]["status"] == "correct" and q["B"]["status"] == "error"
    assert "the true answer to 'A' (carried forward) is not one finite number" in q["B"]["message"]


def test_dimensionless_question_refuses_a_length(tmp_path, capsys):
    # r = ω/ωn has no reported unit, so "0.75 m" passed as correct; `unit: dimensionless` refuses it
    (tmp_path / "v.yaml").write_text("type: vibration\nm: 2\nk: 800\nzeta: 0.1\nforce: {amplitude: 10, omega: 15}\n")
    (tmp_path / "key.yaml").write_text("questions:\n  - {id: r, problem: v.yaml, answer: r, unit: dimensionless}\n")
    code, doc, _ = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"r": "0.75 m"})], capsys)
    q = questions(doc)["r"]                      # r = 15 / sqrt(800/2) = 0.75
    assert code == 1 and q["status"] == "wrong" and q["diagnosis"] == "wrong_dimension"
    code, doc, _ = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "b.yaml", "x", {"r": 0.75})], capsys)
    assert code == 0 and questions(doc)["r"]["status"] == "correct"


def test_result_unit_reads_the_path_from_its_start():
    """A result with a unit holds it all the way down its path: a cord's tension
    ``reaction.rope.T.0.0`` is in N, not the unit of the kinetic energy ``T``; a body named ``V``
    is a position in ``x.V.2.1``; a container without a unit is looked into (``find.0.s``,
    ``events.0.state.reaction.axle.R``), past the names it is owned by (``point.T.end2.a``); a
    record without a unit has none to lend (the frames' columns read the same rule)."""
    from dyncli.check.quantities import result_unit

    units = {"x": "m", "a": "m/s²", "reaction": "N", "T": "J", "V": "J", "s": "m", "find": "", "events": "",
             "point": "", "orbit": ""}
    assert result_unit(units, "reaction.rope.T.0.0") == "N"
    assert result_unit(units, "x.V.2.1") == "m"
    assert result_unit(units, "find.0.s") == "m"
    assert result_unit(units, "find.0.reaction.rope.T.1") == "N"
    assert result_unit(units, "events.0.state.reaction.axle.R.0") == "N"
    assert result_unit(units, "point.T.end2.a.0.1") == "m/s²"
    assert result_unit(units, "T.3") == "J"
    assert result_unit(units, "drive.motor.0") is None
    # a record without a unit of its own borrows none: orbit.a is a semi-major axis, not an acceleration
    assert result_unit(units, "orbit.a") is None


ATWOOD_V = """\
type: scene
params: {m1: 3, m2: 2, M: 1, R: 0.1}
bodies:
  pulley: {shape: disk, mass: M, radius: R, x: [0, 0], angle: 0}
  A: {shape: point, mass: m1, x: ["-R", -1]}
  V: {shape: point, mass: m2, x: [R, -1.5]}
joints:
  axle: {pin: [pulley, ground]}
  rope: {cord: [A, pulley, V]}
at: [0, 0.5, 1]
"""


def test_a_cord_tension_and_a_body_named_v_are_graded_in_their_own_units(tmp_path, capsys):
    """A key without `unit:` grades a scene's cord tension (reaction.rope.T.0.0, by hand
    T1 = m1 (g − a), a = (m1 − m2) g/(m1 + m2 + M/2) = 9.81/5.5: 24.079 N) and the height of a
    body named V (x.V.2.1 = −1.5 + a/2 = −0.608 m) in N and m: "24.1 N" and "-60.8 cm" are
    correct (before: both read as energies, J, and marked "wrong dimension")."""
    (tmp_path / "atw.yaml").write_text(ATWOOD_V)
    key = tmp_path / "key.yaml"
    key.write_text("title: t\ntolerance: {sigfigs: 3}\nquestions:\n"
                   "  - {id: T1, problem: atw.yaml, answer: reaction.rope.T.0.0}\n"
                   "  - {id: yV, problem: atw.yaml, answer: x.V.2.1}\n")
    sub = write_sub(tmp_path, "s.yaml", STUDENT, {"T1": "24.1 N", "yV": "-60.8 cm"})
    code, doc, err = check_json(key, [sub], capsys)
    assert code == 0, err
    assert {q["id"]: q["status"] for q in doc["submissions"][0]["questions"]} == {"T1": "correct", "yV": "correct"}


@pytest.mark.parametrize("given, name", [("twenty-one", "twenty"), ("19.6/s", "s")])
def test_an_answer_with_an_unknown_name_says_what_an_answer_may_be(given, name):
    """A submission cannot define params: the expression language's hint to define the name
    there is replaced by what an answer may be — and the example given is one the grader reads."""
    from dyncli.check.quantities import GivenError, to_si

    with pytest.raises(GivenError) as exc:
        to_si(given)
    msg = str(exc.value)
    assert f"'{name}' is not a number or a unit here" in msg and "params" not in msg
    assert to_si("3.2 1/s") == pytest.approx(3.2) and to_si("19.6 m/s") == pytest.approx(19.6)


def test_a_misspelt_answer_path_in_the_key_is_the_keys_fault_with_a_hint(tmp_path, capsys):
    """The key's answer path `reaction.rop.T.0.0` is not in the results: the submission's answer
    is not graded, and the message says it is the key's question, what it may have meant and how
    to find such a mistake before grading (not "the key's problem could not be solved")."""
    (tmp_path / "atw.yaml").write_text(ATWOOD_V)
    key = tmp_path / "key.yaml"
    key.write_text("title: t\nquestions:\n  - {id: T1, problem: atw.yaml, answer: reaction.rop.T.0.0}\n")
    sub = write_sub(tmp_path, "s.yaml", STUDENT, {"T1": "24.1 N"})
    code, doc, err = check_json(key, [sub], capsys)
    (q,) = doc["submissions"][0]["questions"]
    assert q["status"] == "error"
    assert "the key's question 'T1'" in q["message"] and "did you mean 'reaction.rope.T.0.0'" in q["message"]
    assert "could not be solved" not in q["message"] and "--selftest" in q["message"]
