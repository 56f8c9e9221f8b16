"""Loading problem files: safe YAML, caps, positions, did-you-mean."""

from __future__ import annotations

import pytest

from tests.conftest import error_of, solve_text

GOOD = "type: rectilinear\na: -4\nv1: 20\nfind:\n  - {t: 2}\n"


def test_good_file_solves():
    rec = solve_text(GOOD)[0]
    assert rec["results"]["find"][0]["s"] == pytest.approx(32.0)


def test_problems_list_and_titles():
    text = "problems:\n  - " + GOOD.replace("\n", "\n    ").rstrip() + "\n  - type: rectilinear\n    a: 1\n    title: second\n"
    recs = solve_text(text, "set.yaml")
    assert [r["index"] for r in recs] == [0, 1]
    assert recs[0]["title"] == "set.yaml #1" and recs[1]["title"] == "second"


@pytest.mark.parametrize("text,where,msg", [
    ("type: rectilinear\nacc: 3\na: 1\n", "bad.yaml:2:1: acc:", "unknown field 'acc'"),
    ("type: rectlinear\na: 3\n", "bad.yaml:1:7: type:", "did you mean 'rectilinear'"),
    ("type: rectilinear\na: 1\nfind:\n  - {t: 1}\n  - {tt: 2}\n", "bad.yaml:5:6: find.1.tt:", "unknown field 'tt'"),
    ("type: rectilinear\na: 't^2'\n", "bad.yaml:2:1: a:", "use ** for powers"),
    ("type: rectilinear\na: 1\nv1: [1, 2]\n", "bad.yaml:3:1: v1:", "expected a number"),
    ("type: rectilinear\na: 1\nt_max: -1\n", "bad.yaml:3:1: t_max:", "must be > 0"),
    ("type: rectilinear\na: 1\nv1: .nan\n", "bad.yaml:3:1: v1:", "NaN"),
    ("type: rectilinear\na: 1\nv1: .inf\n", "bad.yaml:3:1: v1:", "finite"),
    ("type: rectilinear\na: 1\nparams: {k: 'k+1'}\n", "bad.yaml:3:", "k"),
    ("type: rectilinear\na: '-k*s'\nparams: {k: 'j'}\n", "bad.yaml:3:", "'j' is not a number"),
    ("type: rectilinear\na: 1\naccuracy: {method: foo}\n", "bad.yaml:3:", "unknown method"),
    ("a: 1\n", "bad.yaml:1:1:", "missing 'type'"),
    ("- 1\n- 2\n", "bad.yaml:1:1:", "expected a problem"),
    ("type: rectilinear\na: 1\na: 2\n", "bad.yaml:3:1:", "duplicate key"),
    ("type: rectilinear\na: [1\n", "bad.yaml:3:1:", "YAML syntax error"),
    ("type: rectilinear\na: !!python/object/apply:os.system ['ls']\n", "bad.yaml:2:4:", "tag"),
    ("type: rectilinear\na: !custom 1\n", "bad.yaml:2:4:", "tag"),
    ("", "bad.yaml:1:1:", "empty"),
    ("type: rectilinear\na: 1\n---\ntype: rectilinear\na: 2\n", "bad.yaml:4:1:", "several YAML documents"),
    ("problems: []\n", "bad.yaml:1:", "non-empty list"),
    ("problems:\n  - type: rectilinear\n    a: 1\nextra: 1\n", "bad.yaml:4:1:", "unknown top-level key"),
])
def test_invalid_inputs_have_positions(text, where, msg):
    err = error_of(text)
    assert err.startswith(where), err
    assert msg in err, err
    assert "Traceback" not in err


def test_billion_laughs_fails_fast():
    lines = ['a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]']
    prev = "a"
    for name in "bcdefghij":
        lines.append(f"{name}: &{name} [" + ",".join([f"*{prev}"] * 9) + "]")
        prev = name
    # an unprotected loader would expand 9**10 nodes (a hang): the refusal is the guard
    err = error_of("\n".join(lines) + "\n")
    assert "alias bomb" in err


def test_deep_nesting_rejected():
    err = error_of("type: rectilinear\na: " + "[" * 200 + "]" * 200 + "\n")
    assert "nested" in err


def test_huge_file_rejected():
    err = error_of("# " + "x" * (3 * 1024 * 1024) + "\ntype: rectilinear\na: 1\n")
    assert "too large" in err


def test_scientific_notation_numbers():
    rec = solve_text("type: rectilinear\na: 2.5E-3\nv1: 1e2\nfind:\n  - {t: 1e1}\n")[0]
    assert rec["results"]["find"][0]["v"] == pytest.approx(100.025)


def test_params_in_numeric_fields():
    rec = solve_text("type: rectilinear\nparams: {g0: 9.81, h: 'g0/2'}\na: '-g0'\nv1: 'h*2'\nfind:\n  - {v: 0}\n")[0]
    assert rec["results"]["find"][0]["t"] == pytest.approx(1.0)


def test_g_usable_in_expressions():
    rec = solve_text("type: rectilinear\ng: 10\na: '-g'\nv1: 20\nfind:\n  - {v: 0}\n")[0]
    assert rec["results"]["find"][0]["t"] == pytest.approx(2.0)
    rec = solve_text("type: rectilinear\na: '-g'\nv1: 9.81\nfind:\n  - {v: 0}\n")[0]
    assert rec["results"]["find"][0]["t"] == pytest.approx(1.0)
    # a params entry named g wins
    rec = solve_text("type: rectilinear\nparams: {g: 5}\na: '-g'\nv1: 10\nfind:\n  - {v: 0}\n")[0]
    assert rec["results"]["find"][0]["t"] == pytest.approx(2.0)
