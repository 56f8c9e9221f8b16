"""A whole course at once (docs/check.md, "A whole course"): a roster in
(missing students, submissions of students not on it), a CSV gradebook out,
the class's statistics per question and a regrade report against an earlier
JSON report."""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, Any

from dyncli.check.emit.common import fmt_points
from dyncli.check.safe import oneline, say, shown

if TYPE_CHECKING:
    from dyncli.check.roster import Roster

NO_SUBMISSION = "(no submission)"
ORDER = ("correct", "carried", "partial", "wrong", "missing", "invalid", "error")
MAX_PREVIOUS_BYTES = 200_000_000


# ---------------------------------------------------------------------------
# the roster


def apply_roster(report, roster) -> list[str]:
    """Students on the roster without a submission become a ``missing``
    submission (0 points); returns a message for every submission whose
    student is not on the roster (also added to the report's warnings)."""
    from dyncli.check.results import QuestionResult, SubmissionResult

    report.roster = roster
    on = set(roster.students)
    messages = []
    for s in report.submissions:
        if s.student is None or s.student not in on:
            who = f"student '{shown(s.student)}'" if s.student is not None else "a submission without a student id"
            msg = f"{shown(s.file)}: {who} is not on the roster {shown(roster.file)}: not in the gradebook"
            messages.append(msg)
            report.warnings.append({"student": s.student, "files": [s.file], "message": msg})
    seen = {s.student for s in report.submissions}
    key = report.key
    for sid in roster.students:
        if sid in seen:
            continue
        sr = SubmissionResult(NO_SUBMISSION, sid, key.max_score)
        for q in key.questions:
            fb = q.feedback.get("missing")
            sr.questions.append(QuestionResult(q.id, "missing", 0.0, q.points, message="no submission" + (
                f"; {fb}" if fb else ""), feedback=fb, visible=q.visible, title=q.title or "", answer=q.answer))
        report.submissions.append(sr)
    return messages


def rows(report) -> list[tuple[str, Any]]:
    """(student, submission result or None) per gradebook row: the roster's
    order when there is one (the first submission of a student counts),
    else every submission in the order given."""
    if getattr(report, "roster", None) is None:
        return [(s.student if s.student is not None else f"(invalid: {s.file})", s) for s in report.submissions]
    first: dict[str, Any] = {}
    for s in report.submissions:
        if s.student is not None:
            first.setdefault(s.student, s)
    return [(sid, first.get(sid)) for sid in report.roster.students]


# ---------------------------------------------------------------------------
# the gradebook


_NUMBER = re.compile(r"^[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?$")


def cell(x: Any) -> str:
    """A CSV cell safe to open in a spreadsheet: text starting with = + - @
    (or a tab or carriage return) gets a leading apostrophe unless it is a
    number, so no cell is read as a formula."""
    s = oneline(x)
    if s and s[0] in "=+-@\t\r" and not _NUMBER.match(s):
        return "'" + s
    return s


# ---------------------------------------------------------------------------
# statistics per question


def stats(report, grader) -> list[dict]:
    """Per question: mean score, % with full points, counts of each status
    and diagnosis, and the range of the true answers (over the students
    graded, the roster's missing students included)."""
    from dyncli.check.grader import scalar
    from dyncli.check.results import FULL
    from dyncli.check.variants import VariantError

    graded = [s for _, s in rows(report) if s is not None and s.questions]
    out = []
    for q in report.key.questions:
        res = [r for s in graded for r in s.questions if r.id == q.id]
        statuses: dict[str, int] = {}
        diagnoses: dict[str, int] = {}
        for r in res:
            statuses[r.status] = statuses.get(r.status, 0) + 1
            if r.diagnosis:
                diagnoses[r.diagnosis] = diagnoses.get(r.diagnosis, 0) + 1
        truths = []
        for s in graded:
            try:
                t = grader.truth(q, s.student)
            except VariantError:
                continue
            v = scalar(t.value) if not t.error else None
            if v is not None and math.isfinite(v):
                truths.append(v)
        n = len(res)
        statuses = {k: statuses[k] for k in ORDER if k in statuses}
        diagnoses = dict(sorted(diagnoses.items(), key=lambda kv: (-kv[1], kv[0])))
        out.append({"id": q.id, "points": q.points, "n": n,
                    "mean": sum(r.score for r in res) / n if n else None,
                    "correct_pct": 100.0 * sum(r.status in FULL for r in res) / n if n else None,
                    "statuses": statuses, "diagnoses": diagnoses,
                    "true_min": min(truths) if truths else None, "true_max": max(truths) if truths else None,
                    "unit": q.unit})
    return out


def stats_table(st: list[dict]) -> str:
    from dyncli.render.table import fmt_num

    head = ("question", "points", "mean", "% correct", "statuses", "diagnoses", "true answers")
    lines = [head]
    for r in st:
        rng = "" if r["true_min"] is None else (
            f"{fmt_num(r['true_min'], 4)} ... {fmt_num(r['true_max'], 4)}" + (f" {r['unit']}" if r["unit"] else ""))
        lines.append((oneline(r["id"]), fmt_points(r["points"]),
                      "" if r["mean"] is None else f"{r['mean']:.2f}",
                      "" if r["correct_pct"] is None else f"{r['correct_pct']:.0f}%",
                      ", ".join(f"{k} {v}" for k, v in r["statuses"].items()),
                      ", ".join(f"{k} {v}" for k, v in r["diagnoses"].items()) or "-", oneline(rng)))
    widths = [max(len(x[i]) for x in lines) for i in range(len(head))]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(x, widths)).rstrip() for x in lines) + "\n"


# ---------------------------------------------------------------------------
# a regrade report


class PreviousError(ValueError):
    """An unreadable earlier report (exit 2)."""


def read_previous(name: str) -> dict[str, float]:
    """{student: score} of an earlier ``--format json`` report."""
    import json
    from pathlib import Path

    try:
        raw = Path(name).read_bytes()
        if len(raw) > MAX_PREVIOUS_BYTES:
            raise PreviousError(f"{name}: larger than {MAX_PREVIOUS_BYTES // 1_000_000} MB")
        doc = json.loads(raw.decode("utf-8"))
    except OSError as exc:
        raise PreviousError(f"{name}: cannot read ({exc.strerror})") from None
    except (UnicodeDecodeError, ValueError) as exc:
        if isinstance(exc, PreviousError):
            raise
        raise PreviousError(f"{name}: not a JSON report (write one with --format json): {shown(exc)}") from None
    subs = doc.get("submissions") if isinstance(doc, dict) else None
    if not isinstance(subs, list):
        raise PreviousError(f"{name}: not a report of 'dyncli check --key ... --format json' (no 'submissions' list)")
    out: dict[str, float] = {}
    for s in subs:
        if isinstance(s, dict) and isinstance(s.get("student"), str) and isinstance(s.get("score"), (int, float)) \
                and not isinstance(s.get("score"), bool):
            out.setdefault(s["student"], float(s["score"]))
    return out


def regrade(report, previous: dict[str, float]) -> list[dict]:
    """Every student whose score changed (or who is in only one report)."""
    now: dict[str, float] = {}
    for s in report.submissions:
        if s.student is not None:
            now.setdefault(s.student, s.score)
    out = []
    for sid in list(now) + [p for p in previous if p not in now]:
        old, new = previous.get(sid), now.get(sid)
        if old is None or new is None or abs(old - new) > 1e-9 * max(1.0, abs(old)):
            out.append({"student": sid, "old": old, "new": new})
    return out


def regrade_table(changes: list[dict], previous_name: str | None) -> str:
    if not changes:
        return f"regrade: no student's score changed since {oneline(previous_name)}\n"
    lines = [f"regrade: {len(changes)} student{'s' if len(changes) != 1 else ''} with a changed score since "
             f"{oneline(previous_name)}"]
    w = max(len(oneline(c["student"])) for c in changes)
    for c in changes:
        old = "-" if c["old"] is None else fmt_points(c["old"])
        new = "-" if c["new"] is None else fmt_points(c["new"])
        delta = "" if c["old"] is None or c["new"] is None else f"  ({c['new'] - c['old']:+g})"
        lines.append(f"  {oneline(c['student']).ljust(w)}  {old} -> {new}{delta}")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------
# the options of one command


class CourseOptions:
    """``--roster``, ``--stats``, ``--compare`` of ``dyncli check --key``:
    read before grading (exit 2 on an unreadable file), applied after.
    With ``--stats`` or ``--compare`` stdout holds the statistics and the
    regrade report; the report in ``--format`` goes to ``--output`` (and is
    not printed without it)."""

    def __init__(self, roster: str | None = None, stats: bool = False, compare: str | None = None):
        self.roster_name, self.stats, self.compare = roster, stats, compare
        self.roster: Roster | None = None
        self.previous: dict[str, float] | None = None
        self.summary = ""

    def load(self) -> bool:
        from dyncli.check.roster import RosterError, read_roster

        try:
            if self.roster_name is not None:
                self.roster = read_roster(self.roster_name)
            if self.compare is not None:
                self.previous = read_previous(self.compare)
        except (RosterError, PreviousError) as exc:
            say(exc)
            return False
        return True

    def finish(self, report, files, key) -> bool:
        from dyncli.check.grader import Grader

        if self.roster is not None:
            for msg in apply_roster(report, self.roster):
                say(f"warning: {msg}")
        parts = []
        if self.stats:
            st = stats(report, Grader(key, files))
            report.course["stats"] = st
            parts.append(stats_table(st))
        if self.previous is not None:
            changes = regrade(report, self.previous)
            report.course["regrade"] = {"previous": self.compare, "changed": changes}
            parts.append(regrade_table(changes, self.compare))
        report.solves = files.solves
        self.summary = "\n".join(parts)
        return True

    def summary_only(self, output: str | None) -> bool:
        """Print the summary (if any); True when nothing else goes to stdout."""
        if not self.summary:
            return False
        import sys

        sys.stdout.write(self.summary)
        return output is None
