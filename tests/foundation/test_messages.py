"""Messages that name the fix: the slips a newcomer makes in a first problem
file, each answered with what is wrong, where, and what to write instead."""

from __future__ import annotations

import pytest

from tests.conftest import ROOT, error_of

IMPACT = "vA1: [5, 0, 0]\nvB1: [0, 0, 0]\nn: [1, 0, 0]\ne: 0\n"


def _loaders(monkeypatch, which: str) -> None:
    import yaml

    if which == "python":   # the pure-Python parser (no libyaml) words its errors differently
        monkeypatch.delattr(yaml, "CSafeLoader", raising=False)


@pytest.mark.parametrize("which", ["default", "python"])
@pytest.mark.parametrize("text,line,col", [
    ("type: rectilinear\ntitle: x\n\ta: 1\n", 3, 1),                       # a tab as the whole indentation
    ("type: rectilinear\nfind:\n  - {t: 1}\n \t- {t: 2}\na: 1\n", 4, 2),   # a tab after a space
    ("type: rectilinear\nparams:\n\tk: 2\na: 1\n", 3, 1),
])
def test_tab_is_named_with_its_place(monkeypatch, which, text, line, col):
    _loaders(monkeypatch, which)
    err = error_of(text)
    assert f"tab character at line {line}, column {col}: use spaces for indentation" in err, err
    assert err.startswith(f"bad.yaml:{line}:{col}:"), err
    assert "cannot start any token" not in err and "Traceback" not in err


def test_tab_inside_quoted_text_is_fine():
    err = error_of('type: rectilinear\ntitle: "a\tb"\na: 1\nv1: [1\n')   # another error: not blamed on the tab
    assert "tab" not in err, err


@pytest.mark.parametrize("value", ["two", "'two'", '"two"'])
def test_word_where_a_number_is_expected(value):
    err = error_of(f"type: impact\nmA: {value}\nmB: 3\n" + IMPACT)
    assert "bad.yaml:2:1: mA: 'two' is not a number" in err, err
    assert "params" in err                                    # how to name a value
    assert "unknown name" not in err and "variables allowed here" not in err, err


def test_near_miss_of_a_parameter_keeps_did_you_mean():
    err = error_of("type: impact\nparams: {mass: 2}\nmA: mas\nmB: 3\n" + IMPACT)
    assert "mA: unknown name 'mas'" in err and "(did you mean 'mass'?)" in err, err


def test_unknown_name_inside_an_expression_says_how_to_define_it():
    err = error_of("type: impact\nmA: 2*x\nmB: 3\n" + IMPACT)
    assert "unknown name 'x'" in err and "define 'x' under params" in err, err


def test_word_in_a_field_with_variables_lists_them():
    err = error_of("type: rectilinear\na: fast\n")
    assert "unknown name 'fast'" in err and "variables allowed here: t, s, v" in err, err


@pytest.mark.parametrize("value", ['"2,5"', "2,5", "'2,5'"])
def test_decimal_comma(value):
    err = error_of(f"type: impact\nmA: {value}\nmB: 3\n" + IMPACT)
    assert "mA: 2,5: use a decimal point (2.5)" in err, err
    assert "tuples" not in err


def test_decimal_comma_in_an_expression_and_in_params():
    assert "0,5: use a decimal point (0.5)" in error_of("type: rectilinear\na: '-0,5*v'\n")
    assert "params.k: 1,5: use a decimal point (1.5)" in error_of("type: rectilinear\nparams: {k: '1,5'}\na: k\n")


def test_thousands_separator():
    err = error_of("type: impact\nmA: 1,000\nmB: 3\n" + IMPACT)
    assert "1,000: numbers take no commas: write 1000" in err, err


def test_function_arguments_keep_their_commas():
    from dyncli import expr

    assert expr.parse("atan2(1,2)").value() == pytest.approx(0.4636476090008061)
    assert expr.parse("max(2,5)").value() == 5.0


@pytest.mark.parametrize("key", ["problem", "Problems", "problms"])
def test_misspelt_problems_key(key):
    err = error_of(f"{key}:\n  - type: impact\n    mA: 2\n")
    assert err.startswith(f"bad.yaml:1:1: {key}:"), err
    assert "did you mean 'problems'" in err, err
    assert "missing 'type'" not in err


@pytest.mark.parametrize("key", ["Type", "typ", "tpye"])
def test_misspelt_type_key(key):
    err = error_of(f"{key}: impact\nmA: 2\n")
    assert f"bad.yaml:1:1: {key}:" in err and "did you mean 'type'" in err, err


def test_missing_type_says_what_to_add():
    err = error_of("title: x\nmA: 2\n")
    assert "missing 'type': add 'type: NAME'" in err and "rectilinear" in err, err


# ------------------------------------------------------------------ the review: what, where, how to fix

@pytest.mark.parametrize("text,where,fix", [
    ("type: particle\nt_end: 1\n", "bad.yaml:1:1: m: required field is missing", "add m (mass [kg])"),
    ("type: particle\nm: 1\nforces: gravity\nt_end: 1\n", "forces: must be a list, got 'gravity'", "one '- ' line per entry"),
    ("type: particle\nm: 1\nt_end: 1\naccuracy: {max_steps: 1.5}\n", "accuracy.max_steps:", "must be a whole number, got 1.5"),
    ("type: particle\nm: 1\nt_end: 1\naccuracy: {estimate: maybe}\n", "accuracy.estimate:", "must be true or false, got 'maybe'"),
    ("type: inertia\nparts: []\n", "parts:", "must have at least 1 entry, got 0"),
    ("type: particle\nm: 1\nt_end: 1\naccuracy: 3\n", "accuracy:", "must be a mapping"),
    ("type: rectilinear\nparams: {pi: 3}\na: 1\n", "params.pi:", "rename it (e.g. 'pi_1')"),
    ("type: rectilinear\nparams: {a: b, b: a}\na: 1\n", "in a cycle", "give one of them a value"),
    ("type: rectilinear\na: '1/s'\n", "not finite at the initial state", "change t1, s1 or v1"),
    ("type: vibration\nm: 1\nk: 1\nsweep: {ratio: [0, 1], points: 10, spacing: log}\n", "log spacing needs r_min > 0",
     "spacing: linear"),
    ("type: impact\nmA: 1\nmB: 1\nvA1: [1, 0, 0]\nvB1: [0, 0, 0]\nn: [1, 0, 0]\neta: 0.5\nphi: 0.1\nt: [0, 2, 0]\n",
     "t must be a unit vector", "omit t and dyncli computes it"),
    ("type: particle\nm: 1\nforces: [{kind: spring, k: 1, L: 0.5}]\nt_end: 1\n", "forces.0.anchor", "off the anchor"),
    ("type: constrained-particle\nm: 1\ncurve: {x1: q, x2: 0, x3: 0}\nq_range: [2, 1]\nt_end: 1\n", "got [2, 1]", "q_min < q_max"),
    ("type: constrained-particle\nm: 1\ncurve: {x1: q, x2: 0, x3: 0}\nq_range: [1, 2]\nt_end: 1\n", "outside q_range",
     "widen q_range"),
])
def test_message_names_the_fix(text, where, fix):
    err = error_of(text)
    assert where in err and fix in err, err


def test_sweep_of_one_number_says_give_a_list():
    import dyncli

    with pytest.raises(dyncli.InputError, match=r"sweep k: give a list of values, e\.g\. \{'k': \[100, 200, 300\]\} \(got 100\)"):
        dyncli.sweep(str(ROOT / "problems" / "vibration" / "base-excitation.yaml"), {"k": 100})


@pytest.mark.parametrize("line,said", [
    ("s0: 1", "s0: unknown field 's0' (did you mean 's1'?)"),
    ("v0: 1", "v0: unknown field 'v0' (did you mean 'v1'?)"),
    ("t_end: 3", "t_end: unknown field 't_end' (did you mean 't_max'?)"),
    ("at: [1, 2]", "at: unknown field 'at': the state at a time is a query: find: [{t: T}]"),
    ("case: 1", "case: unknown field 'case': the notes' case is read from a"),
    ("find: [{event: impact}]", "find.0.event: unknown field 'event': event queries are for scenes"),
])
def test_rectilinear_names_students_write(line, said):
    """Names taken from the other types or from textbooks (s0, at, an event query) get the
    rectilinear way of saying them, not the list of its fields (or 'a' for 'at')."""
    err = error_of(f"type: rectilinear\na: -9.81\n{line}\n")
    assert said in err, err
    assert "known fields" not in err and err.count("\n") == 0, err
