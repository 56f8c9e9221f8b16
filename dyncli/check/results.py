"""What ``dyncli check`` finds, in both modes (docs/check.md): one result
per question, one per graded file, one report.  Every emitter
(:mod:`dyncli.check.emit`) reads these and nothing else.

* Graded work: a :class:`SubmissionResult` per submission, its questions
  those of the instructor's key.
* Self-study: a :class:`SubmissionResult` per answer file, graded against
  the key built from that file (:mod:`dyncli.check.selfstudy`); its answers
  are grouped by the file's checks (:class:`Group`: one problem each), and
  a question's ``answer`` is the dotted result path the student wrote.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from dyncli.check.safe import shown
from dyncli.check.tolerance import Tolerance
from dyncli.loader import Diagnostic

FULL = ("correct", "carried")
#: every status a question can have, in the order reports count them
STATUSES = ("correct", "carried", "partial", "wrong", "missing", "unknown", "invalid", "error")


@dataclass
class QuestionResult:
    id: str
    status: str          # one of STATUSES ('unknown': a self-study result path that is not in the results)
    score: float
    points: float
    given: Any = None
    expected: Any = None           # shown only with --reveal
    diagnosis: str | None = None
    message: str = ""
    rel_error: float | None = None
    feedback: str | None = None              # the key's feedback text shown with this status or slip
    carried_rel_error: float | None = None   # from the answer that follows from the student's carried input
    line: int | None = None
    col: int | None = None
    visible: bool = True
    title: str = ""
    answer: str = ""                         # the dotted path into the problem's results
    tolerance: Tolerance | None = None
    abs_error: float | None = None           # shown only with --reveal

    @property
    def correct(self) -> bool:
        return self.status == "correct"

    @property
    def exit_code(self) -> int:
        return 0 if self.status in FULL else 2 if self.status == "invalid" else 1


@dataclass
class Group:
    """The questions of one check of an answer file: one problem, solved once
    (or not: ``error``, with ``error_code`` 2 for a problem that cannot be
    read, the solver's code when it fails)."""

    index: int
    title: str
    problem_file: str | None
    type: str | None
    questions: list[QuestionResult] = field(default_factory=list)
    error: Diagnostic | None = None
    error_code: int = 0
    trace: str | None = None       # our own traceback (--debug)

    @property
    def score(self) -> float:
        return sum(q.score for q in self.questions)

    @property
    def max_score(self) -> float:
        return sum(q.points for q in self.questions)


@dataclass
class SubmissionResult:
    file: str
    student: str | None
    max_score: float
    params: dict = field(default_factory=dict)
    questions: list[QuestionResult] = field(default_factory=list)
    unknown: list[dict] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    error_code: int = 0
    title: str | None = None                           # an answer file's title
    groups: list[Group] = field(default_factory=list)  # self-study: the answer file's checks

    @property
    def score(self) -> float:
        return sum(q.score for q in self.questions)

    @property
    def exit_code(self) -> int:
        codes = [self.error_code, 2 if self.diagnostics else 0, 1 if self.unknown else 0]
        return max(codes + [q.exit_code for q in self.questions])


@dataclass
class Report:
    """``key``: the instructor's key (graded work), or None (self-study: each
    answer file is its own key)."""

    key: Any = None
    submissions: list[SubmissionResult] = field(default_factory=list)
    solves: int = 0
    reveal: bool = False
    warnings: list[dict] = field(default_factory=list)     # {student, files, message}
    roster: Any = None                                    # --roster (dyncli.check.roster.Roster)
    course: dict = field(default_factory=dict)            # --stats, --compare (dyncli.check.gradebook)

    @property
    def graded(self) -> bool:
        """Graded work (a key), else self-study."""
        return self.key is not None

    @property
    def score(self) -> float:
        return sum(s.score for s in self.submissions)

    @property
    def max_score(self) -> float:
        return sum(s.max_score for s in self.submissions)

    @property
    def exit_code(self) -> int:
        own = 2 if self.key is not None and self.key.diagnostics else 0
        return max([own] + [s.exit_code for s in self.submissions])

    def counts(self) -> dict[str, int]:
        out: dict[str, int] = {}
        for s in self.submissions:
            for q in s.questions:
                out[q.status] = out.get(q.status, 0) + 1
        return out

    def claims(self) -> None:
        """A warning for every student id that several submissions claim."""
        by: dict[str, list[SubmissionResult]] = {}
        for s in self.submissions:
            if s.student is not None:
                by.setdefault(s.student, []).append(s)
        for sid, subs in by.items():
            if len(subs) > 1:
                files = [s.file for s in subs]
                self.warnings.append({"student": sid, "files": files, "message":
                                      f"{len(files)} submissions claim student '{shown(sid)}' ("
                                      + ", ".join(shown(f) for f in files[:5]) + (", ..." if len(files) > 5 else "")
                                      + "): each is graded with that student's numbers; check who wrote which"})
