"""``--format csv`` (graded work only): the gradebook, one row per student
(the roster's students in its order, else every submission in the order
given): ``student``, the points of each question in key order, ``total``,
``max_total``, then the roster's other columns.  Every cell is neutralised
against formula injection (:func:`dyncli.check.gradebook.cell`)."""

from __future__ import annotations

from dyncli.check.emit.common import fmt_points
from dyncli.check.results import Report


def render(report: Report) -> str:
    import csv
    import io

    from dyncli.check.gradebook import cell, rows

    if not report.graded:
        raise ValueError("the gradebook needs a key (--format csv goes with --key KEY)")
    key = report.key
    extra = list(report.roster.columns) if report.roster is not None else []
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow([cell(c) for c in ["student"] + [q.id for q in key.questions] + ["total", "max_total"] + extra])
    for sid, s in rows(report):
        scores = {q.id: q.score for q in s.questions} if s is not None else {}
        total = s.score if s is not None else 0.0
        more = [report.roster.extra.get(sid, {}).get(c, "") for c in extra] if extra else []
        w.writerow([cell(sid)] + [fmt_points(scores.get(q.id, 0.0)) for q in key.questions]
                   + [fmt_points(total), fmt_points(key.max_score)] + [cell(m) for m in more])
    return buf.getvalue()
