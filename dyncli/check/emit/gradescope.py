"""``--format gradescope``: Gradescope's autograder ``results.json``: a test
per answer (``name``, ``score``, ``max_score``, ``status``, ``output``;
graded work adds ``visibility``: ``after_published`` for ``visible: false``).

Graded work: the top-level ``output`` counts only the visible questions,
and the top-level ``score`` — which *overrides* the sum of the tests in
Gradescope — is written only when every question is visible (with hidden
questions Gradescope totals the tests itself, and no number written here
for the student before publication counts a hidden question).  An invalid
submission gives every question 0 with its one-line error.  Self-study
writes ``score`` and the summary line; ``max_score`` is left out (it is
the assignment's setting)."""

from __future__ import annotations

from typing import Any

from dyncli.check.emit.common import FULL, STATUS_TEXT, after_status, fmt_given, json_text, summary_line, who
from dyncli.check.results import Report
from dyncli.check.safe import oneline


def render(report: Report) -> str:
    return json_text(_graded(report) if report.graded else _self_study(report))


def _self_study(report: Report) -> dict:
    tests = []
    multi = len(report.submissions) > 1
    for s in report.submissions:
        for d in s.diagnostics:
            tests.append({"name": f"{s.file}: answer file", "score": 0, "max_score": 0, "status": "failed",
                          "output": str(d)})
        for g in s.groups:
            for q in g.questions:
                out = STATUS_TEXT[q.status]
                if q.status != "correct":
                    text = after_status(q, report.reveal)
                    out += (f": {text}" if text else "") + (f"\nline {q.line} of {s.file}; given {fmt_given(q.given)}; "
                                                            f"tolerance {q.tolerance.describe() if q.tolerance else ''}")
                tests.append({"name": (f"{s.file}: " if multi else "") + f"{g.title}: {q.answer}", "score": q.score,
                              "max_score": q.points, "status": "passed" if q.correct else "failed", "output": out})
    return {"score": report.score, "output": summary_line(report), "tests": tests}


def _visibility(visible: bool) -> str:
    return "visible" if visible else "after_published"


def _graded(report: Report) -> dict:
    tests = []
    multi = len(report.submissions) > 1
    for s in report.submissions:
        pre = f"{who(s)}: " if multi else ""
        if s.diagnostics:
            d = s.diagnostics[0]
            error = oneline(d.message if not d.path else f"{d.path}: {d.message}")
            for q in report.key.questions:
                title = q.title or (q.problem.title if q.problem is not None else "")
                tests.append({"name": f"{pre}{oneline(q.id)}" + (f" ({oneline(title)})" if title else ""),
                              "score": 0, "max_score": q.points, "status": "failed",
                              "output": f"not graded: {error}", "visibility": _visibility(q.visible)})
        for q in s.questions:
            out = STATUS_TEXT[q.status]
            text = after_status(q, report.reveal)
            if text:
                out += f": {text}"
            if q.given is not None and q.status != "correct":
                out += f"\ngiven: {oneline(fmt_given(q.given))}"
            tests.append({"name": f"{pre}{oneline(q.id)}" + (f" ({oneline(q.title)})" if q.title else ""),
                          "score": q.score, "max_score": q.points, "status": "passed" if q.status in FULL else "failed",
                          "output": out, "visibility": _visibility(q.visible)})
        for u in s.unknown:
            tests.append({"name": f"{pre}{oneline(u['id'])}", "score": 0, "max_score": 0, "status": "failed",
                          "output": oneline(u["message"]), "visibility": "visible"})
    visible = [q for s in report.submissions for q in s.questions if q.visible]
    full = sum(1 for q in visible if q.status in FULL)
    hidden = sum(1 for q in report.key.questions if not q.visible) * max(1, len(report.submissions))
    bad = [s for s in report.submissions if s.diagnostics]
    if bad and not multi:
        output = "Not graded: " + oneline(bad[0].diagnostics[0])
    else:
        output = f"{full} of {len(visible)} visible answers with full points" + \
            (f"; {hidden} question{'s' if hidden != 1 else ''} graded after release" if hidden else "")
    doc: dict[str, Any] = {"output": output, "tests": tests}
    if not hidden or (bad and not multi):
        doc = {"score": report.score, **doc}
    return doc
