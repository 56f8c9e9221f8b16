"""``--format junit``: JUnit XML for GitLab, Jenkins and GitHub's test
reporters.  A ``<testsuite>`` per graded file (an answer file: properties
score, max_score; a submission: student, score, max_score), a
``<testcase>`` per answer (``classname`` the problem or question title,
``name`` the answer path or question id, ``file``, ``line``); wrong,
partial, missing and unknown answers are ``<failure type=STATUS>``,
invalid ones and unsolved problems ``<error>``; a carried answer (or a
correct one with the instructor's words) passes with its message in
``<system-out>``."""

from __future__ import annotations

from dyncli.check.emit.common import (FULL, STATUS_TEXT, after_status, fmt_given, fmt_points, points, where, who,
                                      xml_body, xml_text)
from dyncli.check.results import Report, SubmissionResult
from dyncli.check.safe import oneline

HEAD = '<?xml version="1.0" encoding="UTF-8"?>\n'


def render(report: Report) -> str:
    import xml.etree.ElementTree as ET

    name = f"dyncli check --key {oneline(report.key.file)}" if report.graded else "dyncli check"
    root = ET.Element("testsuites", name=xml_text(name))
    totals = [0, 0, 0]
    for s in report.submissions:
        suite = ET.SubElement(root, "testsuite", name=xml_text(who(s)))
        n = _submission(report, s, suite) if report.graded else _answer_file(report, s, suite)
        for k, v in zip(("tests", "failures", "errors"), n):
            suite.set(k, str(v))
        suite.set("skipped", "0")
        suite.set("time", "0")
        if not report.graded:
            ET.SubElement(suite, "system-out").text = xml_text(f"score {fmt_points(s.score)}/{fmt_points(s.max_score)}")
        totals = [a + b for a, b in zip(totals, n)]
    for k, v in zip(("tests", "failures", "errors"), totals):
        root.set(k, str(v))
    if not report.graded:
        root.set("time", "0")
    ET.indent(root)
    return HEAD + ET.tostring(root, encoding="unicode") + "\n"


def _properties(suite, pairs) -> None:
    import xml.etree.ElementTree as ET

    props = ET.SubElement(suite, "properties")
    for k, v in pairs:
        ET.SubElement(props, "property", name=k, value=xml_text(v))


def _answer_file(report: Report, s: SubmissionResult, suite) -> list[int]:
    import xml.etree.ElementTree as ET

    _properties(suite, (("score", fmt_points(s.score)), ("max_score", fmt_points(s.max_score))))
    n = [0, 0, 0]
    for d in s.diagnostics:
        tc = ET.SubElement(suite, "testcase", classname=xml_text(s.file), name="answer file", file=xml_text(d.file),
                           time="0")
        if d.line is not None:
            tc.set("line", str(d.line))
        ET.SubElement(tc, "error", message=xml_text(str(d)), type="invalid-file").text = xml_text(str(d))
        n[0] += 1
        n[2] += 1
    for g in s.groups:
        for q in g.questions:
            tc = _case(suite, g.title, q.answer, s.file, q.line, n)
            if q.status == "correct":
                continue
            text = after_status(q, report.reveal)
            msg = f"{q.answer}: {STATUS_TEXT[q.status]}" + (f": {text}" if text else "")
            body = [f"{where(s.file, q.line, q.col)}: {msg}", f"points: {points(q)}", f"given: {fmt_given(q.given)}",
                    f"tolerance: {q.tolerance.describe() if q.tolerance else ''}"]
            _verdict(tc, q.status, msg, body, n)
    return n


def _submission(report: Report, s: SubmissionResult, suite) -> list[int]:
    import xml.etree.ElementTree as ET

    _properties(suite, (("student", oneline(s.student or "")), ("score", fmt_points(s.score)),
                        ("max_score", fmt_points(s.max_score))))
    n = [0, 0, 0]
    for d in s.diagnostics:
        tc = ET.SubElement(suite, "testcase", classname=xml_text(s.file), name="submission", time="0")
        ET.SubElement(tc, "error", message=xml_text(d), type="invalid-submission").text = xml_text(d)
        n[0] += 1
        n[2] += 1
    for q in s.questions:
        tc = _case(suite, q.title, q.id, s.file, q.line, n)
        if q.status in FULL:
            if q.message:           # carried, or the instructor's feedback for a correct answer
                ET.SubElement(tc, "system-out").text = xml_text(q.message)
            continue
        text = after_status(q, report.reveal)
        msg = f"{oneline(q.id)}: {STATUS_TEXT[q.status]} ({points(q)})" + (f": {text}" if text else "")
        _verdict(tc, q.status, msg, [msg] + ([f"given: {oneline(fmt_given(q.given))}"] if q.given is not None else []), n)
    return n


def _case(suite, classname: str, name: str, file: str, line: int | None, n: list[int]):
    """The ``<testcase>`` of one answer (counted in ``n``)."""
    import xml.etree.ElementTree as ET

    tc = ET.SubElement(suite, "testcase", classname=xml_text(classname), name=xml_text(name), file=xml_text(file),
                       time="0")
    if line is not None:
        tc.set("line", str(line))
    n[0] += 1
    return tc


def _verdict(tc, status: str, msg: str, body: list[str], n: list[int]) -> None:
    """A ``<failure>``, or an ``<error>`` for an invalid answer or an unsolved problem."""
    import xml.etree.ElementTree as ET

    kind = "error" if status in ("invalid", "error") else "failure"
    ET.SubElement(tc, kind, message=xml_text(msg), type=status).text = xml_body(body)
    n[2 if kind == "error" else 1] += 1
