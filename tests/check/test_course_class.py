"""#30 items 2 and 3 on docs/course-example: statement text with the
student's numbers, sheets for a roster of 40 in one call (Markdown, HTML),
the gradebook CSV, the class statistics and a regrade report.  Reference
values from the closed forms of notes §6 (s = v0 t + a t²/2, stop at
t = -v0/a, s = -v0²/(2a)), never from the grader."""

from __future__ import annotations

import csv
import io
import json
import shutil

import pytest

from tests.conftest import ROOT, run_cli

COURSE = ROOT / "docs" / "course-example"
KEY = "docs/course-example/key.yaml"
ROSTER = "docs/course-example/roster.csv"


def _subs() -> list[str]:
    return sorted(str(p.relative_to(ROOT)) for p in (COURSE / "submissions").glob("*.yaml")) + \
        sorted(str(p.relative_to(ROOT)) for p in (COURSE / "class").glob("*.yaml"))


def _draws(sid: str) -> dict:
    from dyncli.check.keyfile import read_key
    from dyncli.check.problemfiles import ProblemFiles

    return read_key(str(COURSE / "key.yaml"), ProblemFiles()).variants.draw(sid)


# -- statement text ----------------------------------------------------------------

def test_formatter_is_safe_and_small():
    from dyncli.check.statement import TextError, check_text, render_text

    p = check_text("v = {v0} m/s, {{literal}}, {a0:.2f}, {v0:+.3g}", {"v0", "a0"})
    assert render_text(p, {"v0": 18.5, "a0": -3}) == "v = 18.5 m/s, {literal}, -3.00, +18.5"
    for bad in ("{v0.__class__}", "{v0[0]}", "{v0!r}", "{v0:{a0}}", "{v0:>99999}", "{", "}", "{1+1}"):
        with pytest.raises(TextError):
            check_text(bad, {"v0", "a0"})
    with pytest.raises(TextError, match="unknown name '{vo}' in text"):
        check_text("{vo}", {"v0"})


def test_unknown_name_refused_by_selftest_at_its_field(tmp_path):
    shutil.copy(COURSE / "hw1.yaml", tmp_path / "hw1.yaml")
    text = (COURSE / "key.yaml").read_text(encoding="utf-8").replace("When does the car stop?",
                                                                     "When does {vv0} stop?")
    (tmp_path / "key.yaml").write_text(text, encoding="utf-8")
    code, out, err = run_cli("check", "--key", str(tmp_path / "key.yaml"), "--selftest", "-n", "2")
    assert code == 2 and "questions.1.text: unknown name '{vv0}'" in err


def test_markdown_sheet_a_student_can_work_from():
    code, out, err = run_cli("variant", KEY, "--student", "alice@example.edu", "--format", "markdown")
    assert code == 0, err
    d = _draws("alice@example.edu")      # v0 = 25, a0 = -3, vb = 15.8
    assert f"A car moving at {d['v0']:g} m/s brakes with a constant acceleration of {d['a0']:g} m/s²" in out
    assert f"thrown straight up at {d['vb']:.1f} m/s" in out
    assert "`s0` = **your answer to 1c**" in out and "`t1` = 10 s" in out and "`a` = 0.5 m/s²" in out   # fixed
    assert "`find: t` = 2 s" in out and "`a` = -9.81 m/s²" in out
    assert "**1a (2 points, in m)**: Where is the car at t = 2 s?" in out
    assert "find.0" not in out and "find.1" not in out and "in dimensionless" not in out   # no result path


def test_html_sheet_is_escaped_and_self_contained(tmp_path):
    shutil.copy(COURSE / "hw1.yaml", tmp_path / "hw1.yaml")
    text = (COURSE / "key.yaml").read_text(encoding="utf-8").replace("title: Homework 1",
                                                                     "title: \"Homework <script>alert(1)</script>\"")
    (tmp_path / "key.yaml").write_text(text, encoding="utf-8")
    code, out, err = run_cli("variant", str(tmp_path / "key.yaml"), "--student", "<b>x</b>", "--format", "html")
    assert code == 0, err
    assert "<script>" not in out and "&lt;script&gt;" in out and "&lt;b&gt;x&lt;/b&gt;" in out
    assert "http" not in out.replace("http-equiv", "") and "<link" not in out and "src=" not in out
    assert out.count("<html") == 1 and "@media print" in out


def test_sheets_for_the_roster_in_one_call(tmp_path):
    code, out, err = run_cli("variant", KEY, "--roster", ROSTER, "-o", str(tmp_path / "sheets"), "--format", "markdown")
    assert code == 0, err
    files = sorted((tmp_path / "sheets").glob("*.md"))
    assert len(files) == 40 and "wrote 40 sheets" in err
    bob = (tmp_path / "sheets" / "bob@example.edu.md").read_text(encoding="utf-8")
    d = _draws("bob@example.edu")
    assert f"A car moving at {d['v0']:g} m/s" in bob
    code, out, err = run_cli("variant", KEY, "--roster", ROSTER, "-o", str(tmp_path / "t"), "--template")
    assert code == 0 and len(list((tmp_path / "t").glob("*.yaml"))) == 40


def test_file_names_of_odd_ids():
    from dyncli.check.roster import file_stem

    assert file_stem("alice@example.edu") == "alice@example.edu"
    a, b = file_stem("../x"), file_stem("_./x")
    assert "/" not in a and not a.startswith(".") and a != b
    assert file_stem("a b") != file_stem("a_b")


# -- roster in, gradebook out --------------------------------------------------------

def test_csv_cells_never_formulas():
    from dyncli.check.gradebook import cell

    assert cell("=HYPERLINK(1)") == "'=HYPERLINK(1)" and cell("+1+1") == "'+1+1" and cell("@SUM(A1)") == "'@SUM(A1)"
    assert cell("-x") == "'-x" and cell("-1.5") == "-1.5" and cell("+2e3") == "+2e3" and cell("alice") == "alice"


def test_gradebook_and_stats_of_the_course_example(tmp_path):
    """The committed gradebook.csv and stats.txt are what the documented command writes."""
    out_csv = tmp_path / "gradebook.csv"
    code, out, err = run_cli("check", "--key", KEY, "--roster", ROSTER, *_subs(), "--format", "csv",
                             "-o", str(out_csv), "--stats")
    book = out_csv.read_text(encoding="utf-8")
    assert code == 1
    assert "student 'eve@elsewhere.edu' is not on the roster" in err
    assert book == (COURSE / "gradebook.csv").read_text(encoding="utf-8")
    assert out == (COURSE / "stats.txt").read_text(encoding="utf-8")
    rows = list(csv.DictReader(io.StringIO(book)))
    assert len(rows) == 40 and [r["student"] for r in rows] == \
        [r["student"] for r in csv.DictReader(open(COURSE / "roster.csv", encoding="utf-8"))]
    by = {r["student"]: r for r in rows}
    assert by["kira@example.edu"]["total"] == "0" and by["alice@example.edu"]["total"] == "8"
    assert by["bob@example.edu"]["total"] == "7.5" and all(r["max_total"] == "9" for r in rows)
    for r in rows:
        assert float(r["total"]) == pytest.approx(sum(float(r[q]) for q in ("1a", "1b", "1c", "2a", "2b", "3")))
    # the stats' mean of 1c is the gradebook column's mean; the true range of 1c is -v0²/(2 a0) over the class
    line = next(x for x in out.splitlines() if x.startswith("1c "))
    assert f"{sum(float(r['1c']) for r in rows) / 40:.2f}" in line
    stops = [-d["v0"] ** 2 / (2 * d["a0"]) for d in map(_draws, by)]
    assert f"{min(stops):.4g} ... {max(stops):.4g} m" in line


def test_regrade_report_after_a_key_fix(tmp_path):
    prev = tmp_path / "prev.json"
    code, _, err = run_cli("check", "--key", KEY, "--roster", ROSTER, *_subs(), "--format", "json", "-o", str(prev))
    assert code == 1, err
    old = json.loads(prev.read_text(encoding="utf-8"))
    slipped = {s["student"] for s in old["submissions"]
               for q in s["questions"] if q["id"] == "2a" and q["diagnosis"] == "power_of_ten"}
    assert slipped
    shutil.copy(COURSE / "hw1.yaml", tmp_path / "hw1.yaml")
    before = 'launch point?", partial: {factor_two: 0.5}}'
    assert before in (COURSE / "key.yaml").read_text(encoding="utf-8")
    fixed = (COURSE / "key.yaml").read_text(encoding="utf-8").replace(
        before, 'launch point?", partial: {factor_two: 0.5, power_of_ten: 0.5}}')
    (tmp_path / "key.yaml").write_text(fixed, encoding="utf-8")
    code, out, err = run_cli("check", "--key", str(tmp_path / "key.yaml"), "--roster", ROSTER, *_subs(),
                             "--compare", str(prev), "--format", "json")
    assert code == 1, err
    listed = {ln.split()[0] for ln in out.splitlines()[1:]}
    assert listed == slipped and all("(+1)" in ln for ln in out.splitlines()[1:])


def test_roster_errors_name_the_line(tmp_path):
    r = tmp_path / "r.csv"
    r.write_text("Student,name\nalice@example.edu,A\n", encoding="utf-8")
    code, _, err = run_cli("check", "--key", KEY, "--roster", str(r), "docs/course-example/submissions/alice.yaml")
    assert code == 2 and "no 'student' column" in err and "Traceback" not in err
    r.write_text("student\nalice@example.edu\nalice@example.edu\n", encoding="utf-8")
    code, _, err = run_cli("check", "--key", KEY, "--roster", str(r), "docs/course-example/submissions/alice.yaml")
    assert code == 2 and ":3: student 'alice@example.edu' is listed twice" in err


def test_fixed_data_units_and_dimensionless(tmp_path):
    """Every number a vibration problem uses (drawn k0; fixed ζ, a 2 mm base amplitude) with its unit, and
    'dimensionless' only for a result declared as a pure number (the amplification G), 'in rad' for φ."""
    (tmp_path / "p.yaml").write_text(
        "type: vibration\ntitle: Base-excited\nparams: {k0: 400, Y: \"2 mm\"}\nm: 1\nk: k0\nzeta: 0.05\n"
        "L: 0.2\nx0: 0.2\nv0: 0\nbase: {amplitude: Y, omega: 30}\nat: [0, 0.1]\n", encoding="utf-8")
    (tmp_path / "key.yaml").write_text(
        'title: HW\nvariants: {salt: s, params: {k0: {uniform: [300, 500], step: 10, unit: N/m}}}\n'
        'problems:\n  - {problem: p.yaml, text: "A {{mass}} on k = {k0:.3g} N/m, base amplitude {Y} mm."}\n'
        'questions:\n  - {id: G, problem: p.yaml, answer: G, text: "Transmissibility?"}\n'
        '  - {id: phi, problem: p.yaml, answer: phi}\n', encoding="utf-8")
    code, out, err = run_cli("variant", str(tmp_path / "key.yaml"), "--student", "x", "--format", "markdown")
    assert code == 0, err
    from dyncli.check.keyfile import read_key
    from dyncli.check.problemfiles import ProblemFiles

    k0 = read_key(str(tmp_path / "key.yaml"), ProblemFiles()).variants.draw("x")["k0"]
    assert f"A {{mass}} on k = {k0:.3g} N/m, base amplitude 2 mm." in out
    assert "`zeta` = 0.05;" in out and "`base.amplitude` = Y = 2 mm" in out and "`base.omega` = 30 rad/s" in out
    assert "`m` = 1 kg" in out and f"`k` = k0 = {k0:g} N/m" in out
    assert "**G (1 point, dimensionless)**: Transmissibility?" in out and "**phi (1 point, in rad)**" in out


def test_course_options_go_with_their_commands():
    for args in (["check", "docs/course-example/self-study.yaml", "--format", "csv"],
                 ["check", "docs/course-example/self-study.yaml", "--stats"],
                 ["check", "docs/course-example/self-study.yaml", "--roster", ROSTER],
                 ["variant", KEY, "--student", "a", "--roster", ROSTER, "-o", "x"],
                 ["variant", KEY, "--roster", ROSTER],
                 ["variant", KEY, "--student", "a", "-o", "x"]):
        code, _, err = run_cli(*args)
        assert code == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err, (args, err)


def test_missing_students_in_json_and_a_not_json_previous(tmp_path):
    code, out, err = run_cli("check", "--key", KEY, "--roster", ROSTER, "docs/course-example/submissions/alice.yaml",
                             "--format", "json")
    assert code == 1
    doc = json.loads(out)
    missing = [s for s in doc["submissions"] if s["file"] == "(no submission)"]
    assert len(missing) == 39 and all(q["status"] == "missing" and q["score"] == 0
                                      for s in missing for q in s["questions"])
    assert doc["roster"] == ROSTER and doc["score"] == 8
    bad = tmp_path / "prev.json"
    bad.write_text("[1, 2]", encoding="utf-8")
    code, _, err = run_cli("check", "--key", KEY, "docs/course-example/submissions/alice.yaml", "--compare", str(bad))
    assert code == 2 and "not a report" in err
