"""``--format github``: GitHub Actions workflow commands.  An ``::error``
on the line of every answer without full points (and of every invalid file
and unsolved problem), escaped like the Actions toolkit; GitHub shows at
most 10 error annotations per step, so the rest are listed in one
``::notice``; a ``::warning`` per student id that several submissions
claim; a final ``::notice`` with the score.  :func:`step_summary` is the
Markdown table appended to ``$GITHUB_STEP_SUMMARY``."""

from __future__ import annotations

from dyncli.check.emit.common import (FULL, GITHUB_MAX_ERRORS, STATUS_TEXT, feedback, gh_command, md_cell, points,
                                      summary_line, where, who)
from dyncli.check.results import Report
from dyncli.check.safe import oneline


def _said(d) -> str:
    return d.message if not d.path else f"{d.path}: {d.message}"


def error_annotations(report: Report) -> list[tuple[str, int | None, int | None, str, str]]:
    """Everything to annotate: (file, line, col, title, message)."""
    out = []
    for s in report.submissions:
        for d in s.diagnostics:
            out.append((d.file, d.line, d.col, "invalid submission" if report.graded else "invalid answer file",
                        oneline(_said(d))))
        groups = [(g.error, g.title, g.questions) for g in s.groups] if not report.graded else [(None, "", s.questions)]
        for error, title, questions in groups:
            if error is not None:
                out.append((error.file or s.file, error.line, error.col, f"problem not solved: {title}", _said(error)))
            for q in questions:
                if q.status in FULL or (q.status == "error" and not report.graded):   # the check's error says it
                    continue
                name = oneline(q.id) if report.graded else q.answer
                out.append((s.file, q.line, q.col, f"{name}: {STATUS_TEXT[q.status]} ({points(q)})",
                            feedback(q, report.reveal) or STATUS_TEXT[q.status]))
        for u in s.unknown:
            out.append((s.file, u.get("line"), u.get("col"), f"{oneline(u['id'])}: unknown", oneline(u["message"])))
    return out


def render(report: Report) -> str:
    lines = []
    items = error_annotations(report)
    for file, line, col, title, msg in items[:GITHUB_MAX_ERRORS]:
        f = oneline(file) if file not in ("<stdin>", "") else None
        lines.append(gh_command("error", msg, file=f, line=line if f else None, col=col if f else None, title=title))
    rest = items[GITHUB_MAX_ERRORS:]
    if rest:
        listed = "\n".join(oneline(f"{where(f, l, c)}: {t}: {m}") for f, l, c, t, m in rest)
        lines.append(gh_command("notice", f"{len(rest)} more not annotated (GitHub shows at most "
                                          f"{GITHUB_MAX_ERRORS} error annotations per step):\n{listed}",
                                title=f"dyncli check: {len(rest)} more"))
    for w in report.warnings:
        f = oneline(w["files"][-1]) if w["files"][-1] not in ("<stdin>", "") else None
        lines.append(gh_command("warning", oneline(w["message"]), file=f, title="one student id, several submissions"))
    lines.append(gh_command("notice", summary_line(report), title="dyncli check score"))
    return "\n".join(lines) + "\n"


def step_summary(report: Report) -> str:
    """A Markdown table for ``$GITHUB_STEP_SUMMARY``: a row per answer."""
    if report.graded:
        title, header = "dyncli check --key", ("submission", "question", "status", "points", "feedback")
        rows = [(md_cell(who(s)), f"`{md_cell(q.id)}`", STATUS_TEXT[q.status], points(q),
                 md_cell(feedback(q, report.reveal))) for s in report.submissions for q in s.questions]
    else:
        title, header = "dyncli check", ("file", "answer", "status", "points", "feedback")
        rows = []
        for s in report.submissions:
            rows += [(md_cell(s.file), "—", "invalid file", "0", md_cell(d)) for d in s.diagnostics]
            rows += [(md_cell(s.file + (f":{q.line}" if q.line else "")), f"`{md_cell(q.answer)}`",
                      STATUS_TEXT[q.status], points(q), md_cell(feedback(q, report.reveal))) for q in s.questions]
    out = [f"### {title}", "", summary_line(report), "", "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out) + "\n"
