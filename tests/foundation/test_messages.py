"""Messages that name the fix: the slips a newcomer makes in a first problem
file, each answered with what is wrong, where, and what to write instead."""

from __future__ import annotations

import pytest

from tests.conftest import error_of

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
