"""``--format json`` (docs/check.md, the two documented shapes).

* self-study: ``{score, max_score, exit_code, counts, solves, files: [{file,
  title, score, max_score, exit_code, errors, checks: [{index, title,
  problem_file, type, score, max_score, error, answers: [...]}]}]}``;
* graded work: ``{key, title, score, max_score, exit_code, counts, solves,
  submissions: [{file, student, score, max_score, exit_code, params, errors,
  questions: [...], unknown: [...]}], warnings, roster?, stats?, regrade?}``.

Without ``--reveal`` no expected value (nor the absolute error, which for a
true 0 *is* the distance to the answer), and relative errors rounded to 2
significant figures."""

from __future__ import annotations

import math

from dyncli.check.emit.common import json_text
from dyncli.check.results import FULL, Group, QuestionResult, Report, SubmissionResult
from dyncli.check.tolerance import round2


def render(report: Report) -> str:
    return json_text(to_json(report))


def to_json(report: Report) -> dict:
    if not report.graded:
        return {"score": report.score, "max_score": report.max_score, "exit_code": report.exit_code,
                "counts": report.counts(), "solves": report.solves,
                "files": [_answer_file(s, report.reveal) for s in report.submissions]}
    return {"key": report.key.file, "title": report.key.title, "score": report.score,
            "max_score": report.max_score, "exit_code": report.exit_code, "counts": report.counts(),
            "solves": report.solves, "submissions": [_submission(s, report.reveal) for s in report.submissions],
            "warnings": list(report.warnings),
            **({"roster": report.roster.file} if report.roster is not None else {}), **report.course}


def _plain(x):
    from dyncli.render.jsonout import jsonable

    return jsonable(x)


def _finite(x: float | None):
    return x if x is not None and math.isfinite(x) else None


def _rel(x: float | None, reveal: bool) -> float | None:
    return x if reveal or x is None else round2(x)


# -- self-study ---------------------------------------------------------------


def _answer_file(s: SubmissionResult, reveal: bool) -> dict:
    return {"file": s.file, "title": s.title, "score": s.score, "max_score": s.max_score, "exit_code": s.exit_code,
            "errors": [str(d) for d in s.diagnostics], "checks": [_check(g, reveal) for g in s.groups]}


def _check(g: Group, reveal: bool) -> dict:
    return {"index": g.index, "title": g.title, "problem_file": g.problem_file, "type": g.type,
            "score": g.score, "max_score": g.max_score, "error": str(g.error) if g.error is not None else None,
            "answers": [_answer(q, reveal) for q in g.questions]}


def _answer(q: QuestionResult, reveal: bool) -> dict:
    rec = {"key": q.answer, "status": q.status, "correct": q.correct, "score": q.score, "points": q.points,
           "given": _plain(q.given), "line": q.line, "col": q.col,
           "tolerance": q.tolerance.as_dict() if q.tolerance is not None else None,
           "relative_error": _finite(_rel(q.rel_error, reveal)),
           "message": q.message if q.status != "correct" else ""}
    if reveal and q.status not in ("unknown", "invalid", "error"):
        rec["absolute_error"] = _finite(q.abs_error)
        rec["expected"] = _plain(q.expected)
    return rec


# -- graded work ----------------------------------------------------------------


def _submission(s: SubmissionResult, reveal: bool) -> dict:
    return {"file": s.file, "student": s.student, "score": s.score, "max_score": s.max_score,
            "exit_code": s.exit_code, "params": s.params, "errors": [str(d) for d in s.diagnostics],
            "questions": [question_json(q, reveal) for q in s.questions],
            "unknown": [{"id": u["id"], "message": u["message"]} for u in s.unknown]}


def question_json(q: QuestionResult, reveal: bool) -> dict:
    rec = {"id": q.id, "status": q.status, "score": q.score, "points": q.points, "diagnosis": q.diagnosis,
           "message": q.message, "given": _plain(q.given), "answer": q.answer, "title": q.title,
           "visible": q.visible, "line": q.line, "col": q.col,
           "relative_error": _plain(_rel(q.rel_error, reveal)) if q.status not in FULL else None}
    if q.feedback is not None:
        rec["feedback"] = q.feedback
    if q.carried_rel_error is not None and q.status not in FULL:
        rec["carried_relative_error"] = _plain(_rel(q.carried_rel_error, reveal))
    if reveal and q.status != "error":
        rec["expected"] = _plain(q.expected)
    return rec
