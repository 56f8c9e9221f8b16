"""Formats of ``dyncli check --key`` (docs/check.md): table, json, junit,
github, gradescope.  No format shows an expected value (or the reference of
a carried question) without ``--reveal``; errors appear as a relative error
rounded to 2 significant figures, never an absolute error.  Every user
string is echoed on one line (:func:`~dyncli.check.safe.oneline`)."""

from __future__ import annotations

from dyncli.check.compare import round2
from dyncli.check.formats import (GITHUB_MAX_ERRORS, _x, _xbody, fmt_given, fmt_points, gh_command, json_text,
                                   markdown_table, md_cell)
from dyncli.check.keymode import KeyReport, QuestionResult, SubmissionResult
from dyncli.check.safe import oneline

STATUS_TEXT = {"correct": "correct", "carried": "carried", "partial": "partial", "wrong": "wrong",
               "missing": "missing", "invalid": "invalid", "error": "not graded"}


def _given(q: QuestionResult) -> str:
    return oneline(fmt_given(q.given)) if q.given is not None else ""


def _expected(q: QuestionResult, reveal: bool) -> str:
    return oneline(fmt_given(q.expected, 10)) if reveal and q.status != "error" else ""


def feedback(q: QuestionResult, reveal: bool) -> str:
    msg = oneline(q.message)
    exp = _expected(q, reveal)
    if exp and q.status not in ("correct",):
        msg = (msg + "; " if msg else "") + f"expected {exp}"
    return msg


def who(s: SubmissionResult) -> str:
    return oneline(f"{s.file} ({s.student})" if s.student else s.file)


def summary_line(report: KeyReport) -> str:
    c = report.counts()
    total = sum(c.values())
    full = c.get("correct", 0) + c.get("carried", 0)
    pct = 100.0 * report.score / report.max_score if report.max_score else 0.0
    n = len(report.submissions)
    parts = [f"score {fmt_points(report.score)}/{fmt_points(report.max_score)} ({pct:.0f}%)",
             f"{n} submission{'s' if n != 1 else ''}", f"{full} of {total} answers with full points"]
    parts += [f"{c[k]} {STATUS_TEXT[k]}" for k in ("carried", "partial", "wrong", "missing", "invalid", "error")
              if c.get(k)]
    bad = sum(1 for s in report.submissions if s.diagnostics)
    if bad:
        parts.append(f"{bad} invalid submission{'s' if bad != 1 else ''}")
    return ", ".join(parts)


# ---------------------------------------------------------------------------


def render_table(report: KeyReport, console) -> None:
    from dyncli.render.plain import Table, Text, box

    utf = (console.encoding or "").lower().replace("-", "").startswith("utf")
    ok, bad = ("✓", "✗") if utf else ("+", "x")
    marks = {"correct": (ok, "green"), "carried": (ok, "green"), "partial": ("~", "yellow"),
             "wrong": (bad, "red"), "missing": (bad, "red"), "invalid": ("!", "magenta"), "error": ("!", "magenta")}
    for s in report.submissions:
        console.print(Text(who(s), style="bold"))
        for d in s.diagnostics:
            console.print(Text("  " + oneline(d), style="magenta"))
        t = Table(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False)
        for col in ("question", "", "points", "given") + (("expected",) if report.reveal else ()) + ("feedback",):
            t.add_column(col, overflow="fold", justify="right" if col == "points" else "left")
        for q in s.questions:
            mark, style = marks[q.status]
            row = [Text(oneline(q.id)), Text(f"{mark} {STATUS_TEXT[q.status]}", style=style),
                   f"{fmt_points(q.score)}/{fmt_points(q.points)}", Text(_given(q))]
            if report.reveal:
                row.append(Text(_expected(q, True)))
            row.append(Text(oneline(q.message)))
            t.add_row(*row)
        for u in s.unknown:
            row = [Text(oneline(u["id"])), Text("? unknown", style="yellow"), "0", Text("")]
            t.add_row(*(row + ([Text("")] if report.reveal else []) + [Text(oneline(u["message"]))]))
        if s.questions or s.unknown:
            console.print(t)
        console.print(Text(f"  {fmt_points(s.score)}/{fmt_points(s.max_score)} points", style="dim"))
        console.print()
    console.print(Text(summary_line(report) + f"; {report.solves} problem variant"
                       f"{'s' if report.solves != 1 else ''} solved", style="bold"))


# ---------------------------------------------------------------------------


def question_json(q: QuestionResult, reveal: bool) -> dict:
    from dyncli.render.jsonout import jsonable

    rel = q.rel_error if reveal else (round2(q.rel_error) if q.rel_error is not None else None)
    rec = {"id": q.id, "status": q.status, "score": q.score, "points": q.points, "diagnosis": q.diagnosis,
           "message": q.message, "given": jsonable(q.given), "answer": q.answer, "title": q.title,
           "visible": q.visible, "line": q.line, "col": q.col,
           "relative_error": jsonable(rel) if q.status not in ("correct", "carried") else None}
    if q.feedback is not None:
        rec["feedback"] = q.feedback
    if q.carried_rel_error is not None and q.status not in ("correct", "carried"):
        c = q.carried_rel_error
        rec["carried_relative_error"] = jsonable(c if reveal else round2(c))
    if reveal and q.status != "error":
        rec["expected"] = jsonable(q.expected)
    return rec


def to_json(report: KeyReport) -> dict:
    subs = []
    for s in report.submissions:
        subs.append({"file": s.file, "student": s.student, "score": s.score, "max_score": s.max_score,
                     "exit_code": s.exit_code, "params": s.params,
                     "errors": [str(d) for d in s.diagnostics],
                     "questions": [question_json(q, report.reveal) for q in s.questions],
                     "unknown": [{"id": u["id"], "message": u["message"]} for u in s.unknown]})
    return {"key": report.key.file, "title": report.key.title, "score": report.score,
            "max_score": report.max_score, "exit_code": report.exit_code, "counts": report.counts(),
            "solves": report.solves, "submissions": subs, "warnings": list(report.warnings),
            **({"roster": report.roster.file} if report.roster is not None else {}), **report.course}


def render_json(report: KeyReport) -> str:
    return json_text(to_json(report))


# ---------------------------------------------------------------------------


def render_junit(report: KeyReport) -> str:
    import xml.etree.ElementTree as ET

    root = ET.Element("testsuites", name=_x(f"dyncli check --key {oneline(report.key.file)}"))
    totals = [0, 0, 0]
    for s in report.submissions:
        suite = ET.SubElement(root, "testsuite", name=_x(who(s)))
        props = ET.SubElement(suite, "properties")
        for k, v in (("student", s.student or ""), ("score", fmt_points(s.score)),
                     ("max_score", fmt_points(s.max_score))):
            ET.SubElement(props, "property", name=k, value=_x(oneline(v)))
        n = [0, 0, 0]
        for d in s.diagnostics:
            tc = ET.SubElement(suite, "testcase", classname=_x(oneline(s.file)), name="submission", time="0")
            ET.SubElement(tc, "error", message=_x(oneline(d)), type="invalid-submission").text = _x(oneline(d))
            n[0] += 1
            n[2] += 1
        for q in s.questions:
            tc = ET.SubElement(suite, "testcase", classname=_x(oneline(q.title)), name=_x(oneline(q.id)),
                               file=_x(oneline(s.file)), time="0")
            if q.line is not None:
                tc.set("line", str(q.line))
            n[0] += 1
            if q.status in ("correct", "carried"):
                if q.message:           # carried, or the instructor's feedback for a correct answer
                    ET.SubElement(tc, "system-out").text = _x(oneline(q.message))
                continue
            text = feedback(q, report.reveal)
            msg = f"{oneline(q.id)}: {STATUS_TEXT[q.status]} ({fmt_points(q.score)}/{fmt_points(q.points)})" \
                  + (f": {text}" if text else "")
            kind = "error" if q.status in ("invalid", "error") else "failure"
            el = ET.SubElement(tc, kind, message=_x(msg), type=q.status)
            el.text = _xbody([msg] + ([f"given: {_given(q)}"] if q.given is not None else []))
            n[2 if kind == "error" else 1] += 1
        for k, v in zip(("tests", "failures", "errors"), n):
            suite.set(k, str(v))
        suite.set("skipped", "0")
        suite.set("time", "0")
        totals = [a + b for a, b in zip(totals, n)]
    for k, v in zip(("tests", "failures", "errors"), totals):
        root.set(k, str(v))
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


# ---------------------------------------------------------------------------


def render_github(report: KeyReport) -> str:
    items = []
    for s in report.submissions:
        for d in s.diagnostics:
            items.append((d.file, d.line, d.col, "invalid submission", oneline(d.message if not d.path
                                                                               else f"{d.path}: {d.message}")))
        for q in s.questions:
            if q.status in ("correct", "carried"):
                continue
            title = f"{oneline(q.id)}: {STATUS_TEXT[q.status]} ({fmt_points(q.score)}/{fmt_points(q.points)})"
            items.append((s.file, q.line, q.col, title, feedback(q, report.reveal) or STATUS_TEXT[q.status]))
        for u in s.unknown:
            items.append((s.file, u.get("line"), u.get("col"), f"{oneline(u['id'])}: unknown", oneline(u["message"])))
    lines = []
    for file, line, col, title, msg in items[:GITHUB_MAX_ERRORS]:
        f = oneline(file) if file not in ("<stdin>", "") else None
        lines.append(gh_command("error", msg, file=f, line=line if f else None, col=col if f else None, title=title))
    if len(items) > GITHUB_MAX_ERRORS:
        rest = items[GITHUB_MAX_ERRORS:]
        listed = " | ".join(f"{oneline(f)}:{l or ''}: {t}: {m}" for f, l, _, t, m in rest)
        lines.append(gh_command("notice", f"{len(rest)} more not annotated: {listed}",
                                title=f"dyncli check: {len(rest)} more"))
    for w in report.warnings:
        f = oneline(w["files"][-1]) if w["files"][-1] not in ("<stdin>", "") else None
        lines.append(gh_command("warning", oneline(w["message"]), file=f, title="one student id, several submissions"))
    lines.append(gh_command("notice", summary_line(report), title="dyncli check score"))
    return "\n".join(lines) + "\n"


def step_summary_markdown(report: KeyReport) -> str:
    rows = [(md_cell(who(s)), f"`{md_cell(q.id)}`", STATUS_TEXT[q.status], f"{fmt_points(q.score)}/{fmt_points(q.points)}",
             md_cell(feedback(q, report.reveal))) for s in report.submissions for q in s.questions]
    return markdown_table("dyncli check --key", summary_line(report),
                          ("submission", "question", "status", "points", "feedback"), rows)


# ---------------------------------------------------------------------------


def render_gradescope(report: KeyReport) -> str:
    """Gradescope's results.json (its autograder specification): a test per
    question with ``score``, ``max_score``, ``output`` and ``visibility``
    (``visible: false`` -> ``after_published``); ``output`` at the top counts
    only visible questions.  The top-level ``score`` overrides the sum of the
    tests, so it is written only when every question is visible: with hidden
    questions Gradescope totals the tests itself, and no number written here
    for the student before publication counts a hidden question.  An invalid
    submission gives every question 0 with its one-line error."""
    tests = []
    multi = len(report.submissions) > 1
    for s in report.submissions:
        pre = f"{who(s)}: " if multi else ""
        if s.diagnostics:
            error = oneline(s.diagnostics[0].message if not s.diagnostics[0].path
                            else f"{s.diagnostics[0].path}: {s.diagnostics[0].message}")
            for q in report.key.questions:
                title = q.title or (q.problem.title if q.problem is not None else "")
                tests.append({"name": f"{pre}{oneline(q.id)}" + (f" ({oneline(title)})" if title else ""),
                              "score": 0, "max_score": q.points, "status": "failed",
                              "output": f"not graded: {error}",
                              "visibility": "visible" if q.visible else "after_published"})
        for q in s.questions:
            out = STATUS_TEXT[q.status]
            text = feedback(q, report.reveal)
            if text.startswith(out):          # "not graded: ..." says its status itself
                out = text
            elif text:
                out += f": {text}"
            if q.given is not None and q.status not in ("correct",):
                out += f"\ngiven: {_given(q)}"
            tests.append({"name": f"{pre}{oneline(q.id)}" + (f" ({oneline(q.title)})" if q.title else ""),
                          "score": q.score, "max_score": q.points,
                          "status": "passed" if q.status in ("correct", "carried") else "failed",
                          "output": out, "visibility": "visible" if q.visible else "after_published"})
        for u in s.unknown:
            tests.append({"name": f"{pre}{oneline(u['id'])}", "score": 0, "max_score": 0, "status": "failed",
                          "output": oneline(u["message"]), "visibility": "visible"})
    visible = [q for s in report.submissions for q in s.questions if q.visible]
    full = sum(1 for q in visible if q.status in ("correct", "carried"))
    hidden = sum(1 for q in report.key.questions if not q.visible) * max(1, len(report.submissions))
    bad = [s for s in report.submissions if s.diagnostics]
    if bad and not multi:
        output = "Not graded: " + oneline(bad[0].diagnostics[0])
    else:
        output = f"{full} of {len(visible)} visible answers with full points" + \
            (f"; {hidden} question{'s' if hidden != 1 else ''} graded after release" if hidden else "")
    doc = {"output": output, "tests": tests}
    if not hidden or (bad and not multi):
        doc = {"score": report.score, **doc}
    return json_text(doc)
