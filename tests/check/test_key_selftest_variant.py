"""`check --key --selftest` and `dyncli variant` (sheet, markdown, template)."""

from __future__ import annotations


import pytest

from tests.check.keyhelpers import KEY, check_json, params_of, truth
from tests.conftest import run_cli

UNREACHABLE = """\
title: bad draw
variants:
  salt: s
  params:
    a0: {choice: [-3, 2]}
questions:
  - {id: stop, problem: p.yaml, answer: find.0.t}
"""
PROBLEM = "type: rectilinear\nparams: {a0: -3}\na: a0\nv1: 12\nfind: [{v: 0}]\n"


def test_selftest_passes_and_prints_ranges(capsys):
    from dyncli.check.keycommand import run_selftest

    assert run_selftest(str(KEY), 40) == 0
    out = capsys.readouterr().out
    assert "selftest passed: 41 variants, 5 questions" in out
    row = next(line for line in out.splitlines() if line.startswith("1b "))
    lo, hi = (float(x) for x in row.split()[2:4])
    # 1b = v0/|a0| over v0 in [15, 25], |a0| in {3, 4, 5}: inside [3, 8.34]
    assert 3 <= lo <= hi <= 25 / 3 + 1e-9


def test_selftest_fails_on_an_unreachable_query(tmp_path, capsys):
    from dyncli.check.keycommand import run_selftest

    (tmp_path / "p.yaml").write_text(PROBLEM)
    (tmp_path / "key.yaml").write_text(UNREACHABLE)
    assert run_selftest(str(tmp_path / "key.yaml"), 20) == 1
    err = capsys.readouterr().err
    assert "selftest failed for variant" in err and "a0 = 2" in err and "question stop" in err
    assert ("not reached" in err or "null" in err) and len(err.strip().splitlines()) == 1


def test_selftest_flags_a_degenerate_draw(tmp_path, capsys):
    from dyncli.check.keycommand import run_selftest

    (tmp_path / "p.yaml").write_text(PROBLEM.replace("find: [{v: 0}]", "find: [{t: 1}]"))
    (tmp_path / "key.yaml").write_text(UNREACHABLE.replace("find.0.t", "find.0.t").replace("choice: [-3, 2]", "choice: [-3, -4]"))
    assert run_selftest(str(tmp_path / "key.yaml"), 10) == 0
    assert "the same for every variant" in capsys.readouterr().out     # t = 1 whatever a0


def test_selftest_cli_options():
    rc, out, err = run_cli("check", "--key", str(KEY), "--selftest", "-n", "3")
    assert rc == 0 and "4 variants" in out, err
    rc, _, err = run_cli("check", "--selftest", str(KEY))
    assert rc == 2 and "goes with --key" in err
    rc, _, err = run_cli("check", "--key", str(KEY))
    assert rc == 2 and "give the submissions" in err


def test_variant_yaml_holds_the_students_numbers():
    import yaml

    rc, out, err = run_cli("variant", str(KEY), "--student", "alice@example.edu")
    assert rc == 0, err
    doc = yaml.safe_load(out)
    p = params_of("alice@example.edu")
    assert doc["student"] == "alice@example.edu" and doc["params"] == p
    car = doc["problems"][0]
    assert car["problem"]["params"]["v0"] == p["v0"] and car["problem"]["params"]["a0"] == p["a0"]
    assert [q["id"] for q in car["questions"]] == ["1a", "1b", "1d", "1e"]
    assert {q["id"]: q.get("unit") for q in car["questions"]} == {"1a": "m", "1b": "s", "1d": "mm", "1e": "m/s"}
    t = truth(p["v0"], p["a0"])
    for x in t.values():                                       # a sheet holds no answers
        needle = f"{x:.4g}"
        assert len(needle) < 4 or needle not in out, x        # (1- to 3-character numbers occur anyway)


def test_variant_markdown_and_template_round_trip(tmp_path, capsys):
    rc, md, err = run_cli("variant", str(KEY), "--student", "bob", "--format", "markdown")
    assert rc == 0, err
    p = params_of("bob")
    assert f"| `v0` | {p['v0']:g} |" in md and "### 1. Braking car" in md and "**1a (" in md
    rc, tpl, err = run_cli("variant", str(KEY), "--student", "bob", "--template")
    assert rc == 0 and 'student: "bob"' in tpl and '"1d":' in tpl and "unit mm" in tpl
    t = truth(p["v0"], p["a0"])
    filled = tpl
    for qid, x in t.items():
        filled = filled.replace(f'"{qid}":', f'"{qid}": {x!r}', 1)
    (tmp_path / "bob.yaml").write_text(filled)
    code, doc, err = check_json(KEY, [str(tmp_path / "bob.yaml")], capsys)
    assert code == 0 and doc["score"] == doc["max_score"], err
    # the empty template is a valid submission with every question missing
    (tmp_path / "empty.yaml").write_text(tpl)
    code, doc, _ = check_json(KEY, [str(tmp_path / "empty.yaml")], capsys)
    assert code == 1 and {q["status"] for q in doc["submissions"][0]["questions"]} == {"missing"}


@pytest.mark.parametrize("args,needle", [(["--student", "a\nb"], "printable"),
                                         (["--student", "x", "--format", "pdf"], "pdf")])
def test_variant_bad_options(args, needle):
    rc, _, err = run_cli("variant", str(KEY), *args)
    assert rc == 2 and needle in err


def test_selftest_summary_counts_in_the_singular(tmp_path, capsys):
    # "1 questions, 1 solves" read badly
    from dyncli.check.keycommand import run_selftest

    (tmp_path / "p.yaml").write_text(PROBLEM)
    (tmp_path / "key.yaml").write_text("questions:\n  - {id: stop, problem: p.yaml, answer: find.0.t}\n")
    assert run_selftest(str(tmp_path / "key.yaml"), 5) == 0
    assert "selftest passed: 1 variant, 1 question, 1 solve; the key grades itself 100%" in capsys.readouterr().out
