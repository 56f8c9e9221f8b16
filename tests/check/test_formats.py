"""Output formats: JUnit XML (the fields GitLab reads), GitHub workflow
commands (escaping, the 10-error limit), Gradescope results.json, JSON."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

from dyncli.check.emit import github, gradescope, junit, table
from dyncli.check.emit import json as jsonfmt
from dyncli.check.emit.common import gh_command, gh_escape_data, gh_escape_property
from tests.check.helpers import grade

ALICE = """\
problem: brake.yaml
answers:
  case: 1
  find.0.s: 32
  find.0.v: -12
  find.1.tt: 5
  find.2.t: {value: "x+", points: 2}
"""


def _junit(report):
    text = junit.render(report)
    assert text.startswith('<?xml version="1.0" encoding="UTF-8"?>')
    return ET.fromstring(text.encode())


def test_junit_structure_and_gitlab_fields():
    root = _junit(grade(ALICE))
    assert root.tag == "testsuites"
    assert root.get("tests") == "5" and root.get("failures") == "2" and root.get("errors") == "1"
    suites = root.findall("testsuite")
    assert len(suites) == 1 and suites[0].get("name") == "answers.yaml"
    cases = suites[0].findall("testcase")
    assert [c.get("name") for c in cases] == ["case", "find.0.s", "find.0.v", "find.1.tt", "find.2.t"]
    for c in cases:
        assert c.get("classname") == "Brake"
        assert c.get("file") == "answers.yaml"
        assert c.get("line").isdigit()
    assert cases[2].get("line") == "5"
    assert cases[0].find("failure") is None and cases[0].find("error") is None
    f = cases[2].find("failure")
    assert f is not None and "find.0.v" in f.get("message") and "relative error" in f.get("message")
    assert "answers.yaml:5:3" in f.text
    assert cases[3].find("failure").get("type") == "unknown"
    assert "did you mean" in cases[3].find("failure").get("message")
    assert cases[4].find("error") is not None
    props = {p.get("name"): p.get("value") for p in suites[0].iter("property")}
    assert props == {"score": "2", "max_score": "6"}


def test_junit_hides_expected_unless_revealed():
    hidden = junit.render(grade(ALICE))
    assert "expected 12" not in hidden
    shown = junit.render(grade(ALICE, reveal=True))
    assert "expected 12" in shown


def test_junit_invalid_file_and_hostile_text():
    root = _junit(grade('problem: brake.yaml\nanswers: {case: 1}\n"bogus<&>\\"\\x01": 1\n'))
    (case,) = root.find("testsuite").findall("testcase")
    assert case.get("name") == "answer file" and case.find("error") is not None
    assert "bogus<&>" in case.find("error").get("message")
    root = _junit(grade('problem: brake.yaml\nanswers: {"a<b>&\\u0001": 1}\n'))
    assert root.find("testsuite/testcase").get("name").startswith("a<b>&")


def test_junit_failure_body_lines():
    # one fact a line (was one line with literal "\x0a" escapes); a hostile given stays on its line
    fail = _junit(grade(ALICE)).find("testsuite/testcase/failure")
    lines = fail.text.split("\n")
    assert [line.split(":")[0] for line in lines[1:]] == ["points", "given", "tolerance"]
    assert "\\x0a" not in fail.text
    root = _junit(grade('problem: brake.yaml\nanswers: {case: "1\\n::error forged"}\n'))
    text = root.find("testsuite/testcase/error").text
    assert len(text.split("\n")) == 4 and not any(x.startswith("::error") for x in text.split("\n"))


def test_junit_several_files():
    from dyncli.check.results import Report

    r = Report()
    for n in ("a.yaml", "b.yaml"):
        r.submissions += grade("problem: brake.yaml\nanswers: {case: 1}\n", name=n).submissions
    root = _junit(r)
    assert [s.get("name") for s in root.findall("testsuite")] == ["a.yaml", "b.yaml"]
    assert root.get("tests") == "2" and root.get("failures") == "0"


# -- GitHub -------------------------------------------------------------------

def test_github_escaping_matches_toolkit():
    assert gh_escape_data("50%\r\nnext") == "50%25%0D%0Anext"
    assert gh_escape_data("a: b, c") == "a: b, c"
    assert gh_escape_property("a: b, c%\n") == "a%3A b%2C c%25%0A"
    line = gh_command("error", "line1\nline2 100%", file="dir,x/a:b.yaml", line=3, col=5, title="t: x, y")
    assert line == "::error file=dir%2Cx/a%3Ab.yaml,line=3,col=5,title=t%3A x%2C y::line1%0Aline2 100%25"


def test_github_annotations_point_at_answer_lines():
    out = github.render(grade(ALICE)).splitlines()
    errors = [l for l in out if l.startswith("::error ")]
    assert len(errors) == 3
    assert errors[0].startswith("::error file=answers.yaml,line=5,col=3,title=find.0.v%3A wrong (0/1)::")
    assert all("\n" not in l for l in out)
    assert out[-1].startswith("::notice title=dyncli check score::score 2/6 (33%25)")


def test_github_limit_of_ten_errors():
    answers = "\n".join(f"  find.0.s{i}: 1" for i in range(14))
    out = github.render(grade(f"problem: brake.yaml\nanswers:\n{answers}\n")).splitlines()
    assert sum(l.startswith("::error ") for l in out) == 10
    notices = [l for l in out if l.startswith("::notice ")]
    assert len(notices) == 2
    assert "4 more not annotated" in notices[0]
    assert "answers.yaml:14:3" in notices[0] and "%0A" in notices[0]


def test_github_stdin_has_no_file_property():
    out = github.render(grade(ALICE, name="<stdin>"))
    assert "file=" not in out and "::error title=" in out


def test_step_summary_markdown():
    md = github.step_summary(grade(ALICE))
    assert "| answers.yaml:5 | `find.0.v` | wrong | 0/1 |" in md


# -- Gradescope ------------------------------------------------------------------

def test_gradescope_results_json():
    doc = json.loads(gradescope.render(grade(ALICE)))
    assert set(doc) == {"score", "output", "tests"}
    assert doc["score"] == 2
    assert len(doc["tests"]) == 5
    for t in doc["tests"]:
        assert set(t) == {"name", "score", "max_score", "status", "output"}
        assert t["status"] in ("passed", "failed")
    t = {x["name"]: x for x in doc["tests"]}
    assert t["Brake: case"] == {"name": "Brake: case", "score": 1.0, "max_score": 1.0, "status": "passed",
                                "output": "correct"}
    assert t["Brake: find.0.v"]["status"] == "failed" and "relative error" in t["Brake: find.0.v"]["output"]
    assert t["Brake: find.2.t"]["max_score"] == 2.0 and t["Brake: find.2.t"]["score"] == 0
    assert "12" not in t["Brake: find.0.v"]["output"].replace("-12", "")


def test_gradescope_invalid_file_still_valid_json():
    doc = json.loads(gradescope.render(grade("answers: {case: 1}\n")))
    assert doc["score"] == 0 and doc["tests"][0]["status"] == "failed"
    assert "missing 'problem'" in doc["tests"][0]["output"]


# -- JSON ---------------------------------------------------------------------------

def test_json_report():
    doc = json.loads(jsonfmt.render(grade(ALICE)))
    assert doc["score"] == 2 and doc["max_score"] == 6 and doc["exit_code"] == 2 and doc["solves"] == 1
    ans = {a["key"]: a for a in doc["files"][0]["checks"][0]["answers"]}
    assert ans["find.0.v"]["relative_error"] == 2.0 and ans["find.0.v"]["line"] == 5
    assert ans["find.0.v"]["tolerance"] == {"rtol": 0.01, "atol": 1e-8}
    assert "expected" not in ans["find.0.v"]
    doc = json.loads(jsonfmt.render(grade(ALICE, reveal=True)))
    ans = {a["key"]: a for a in doc["files"][0]["checks"][0]["answers"]}
    assert ans["find.0.v"]["expected"] == 12.0


def test_table_renders_and_hides_expected():
    import io

    from dyncli.render.table import make_console

    buf = io.StringIO()
    con = make_console(buf)
    con.width = 160
    table.draw(grade(ALICE), con)
    out = buf.getvalue()
    assert "find.0.v" in out and "score 2/6" in out and "expected" not in out
    assert "(rtol 0.01, atol 1e-08)" in out
    buf = io.StringIO()
    con = make_console(buf)
    con.width = 160
    table.draw(grade(ALICE, reveal=True), con)
    assert "expected" in buf.getvalue()
