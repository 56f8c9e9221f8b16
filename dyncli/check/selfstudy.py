"""Self-study (docs/check.md, "Self-study: answer files"): an answer file
is a key built on the fly, graded by the one grader of both modes
(:class:`~dyncli.check.grader.Grader`).

Each answer of each check becomes a question of that key — its problem
(with the check's ``params``), its result path, tolerance and points —
and the given values a submission of it; the key's
:data:`~dyncli.check.keyfile.SELF_STUDY` policy says where self-study
grades differently from graded work (no secret, unknown paths, round-off,
nulls).  A check whose problem cannot be read (or solved) grades its
answers ``error``; the file's other checks are still graded.

Problem files are read once per resolved path and solved once per content
(:class:`~dyncli.check.problemfiles.ProblemFiles`, shared by every file of
a command).
"""

from __future__ import annotations

from pathlib import Path

from dyncli.check.answers import AnswerFile, CheckSpec, read_answer_source
from dyncli.check.grader import Grader
from dyncli.check.keyfile import SELF_STUDY, Key, Question
from dyncli.check.problemfiles import ProblemFiles
from dyncli.check.results import Group, Report, SubmissionResult
from dyncli.check.safe import shown
from dyncli.check.submission import Submission
from dyncli.loader import Diagnostic, LoadedProblem, validate


class SelfStudy:
    """Grades answer files; one per command (its problems are shared)."""

    def __init__(self, reveal: bool = False, options=None, root: Path | None = None):
        self.reveal = reveal
        self.files = ProblemFiles(options, root)

    @property
    def solves(self) -> int:
        return self.files.solves

    def check_paths(self, names: list[str]) -> Report:
        report = Report(reveal=self.reveal)
        for name in names:
            report.submissions.append(self.check_file(read_answer_source(name)))
        report.solves = self.solves
        return report

    def check_file(self, af: AnswerFile) -> SubmissionResult:
        key, sub, groups = self.key_of(af)
        sr = SubmissionResult(af.file, None, key.max_score, diagnostics=list(af.diagnostics), title=af.title)
        grader = Grader(key, self.files, self.reveal)
        grader.grade_into(sub, sr)
        by_id = {r.id: r for r in sr.questions}
        for g, questions in groups:
            g.questions = [by_id[q.id] for q in questions]
            t = grader.truth(questions[0], sub.student)
            if g.error is None and t.error and not t.unknown:      # solved, and failed
                g.error, g.error_code, g.trace = t.diag, t.code, t.trace
            sr.groups.append(g)
        return sr

    def key_of(self, af: AnswerFile) -> tuple[Key, Submission, list[tuple[Group, list[Question]]]]:
        """The key an answer file stands for, its given values as a
        submission, and its checks (each with its questions)."""
        key = Key(af.file, af.base_dir, title=af.title, policy=SELF_STUDY)
        sub = Submission(af.file, student="")
        groups = []
        for spec in af.checks:
            lp, err = self._problem(af, spec)
            title = spec.title or (lp.title if lp is not None else f"check #{spec.index}")
            g = Group(spec.index, title, lp.file if lp else None, lp.type if lp else None, error=err,
                      error_code=2 if err is not None else 0)
            questions = []
            for a in spec.answers:
                q = Question(f"{spec.index}:{a.key}", answer=a.key, points=a.points, tol=a.tol, title=title,
                             problem=lp, error=err, invalid=a.error)
                sub.answers[q.id], sub.positions[q.id] = a.given, (a.line, a.col)
                questions.append(q)
            key.questions += questions
            groups.append((g, questions))
        return key, sub, groups

    def _problem(self, af: AnswerFile, spec: CheckSpec) -> tuple[LoadedProblem | None, Diagnostic | None]:
        def here(path: tuple, message: str) -> Diagnostic:
            pos = af.doc.locate(spec.prefix + path) if af.doc else None
            line, col = pos if pos else (spec.line, spec.col)
            return Diagnostic(af.file, line, col, ".".join(str(p) for p in spec.prefix + path) or None, message)

        if spec.problem_inline is not None:
            raw = spec.problem_inline
            t = raw.get("type")
            title = tt if isinstance(tt := raw.get("title"), str) else f"{af.file}: inline problem"
            lp = LoadedProblem(af.file, spec.index, t if isinstance(t, str) else None, title, raw, af.doc,
                               spec.prefix + ("problem",), base_dir=af.base_dir)
            if spec.problem_index not in (None, 0):
                return None, here(("index",), "an inline problem has only index 0")
        else:
            ref = spec.problem_ref or ""
            where = Diagnostic(af.file, spec.line, spec.col, ".".join(map(str, spec.prefix + ("problem",))), "")
            ps, err = self.files.read(ref, af.base_dir, where)
            if err is not None:
                return None, err
            idx = spec.problem_index if spec.problem_index is not None else 0
            if spec.problem_index is None and len(ps) > 1:
                return None, Diagnostic(af.file, spec.line, spec.col, "problem",
                                        f"'{shown(ref)}' holds {len(ps)} problems: add 'index: N' (0-{len(ps) - 1}) "
                                        "to say which one these answers are for")
            if idx >= len(ps):
                return None, here(("index",), f"'{shown(ref)}' holds {len(ps)} problem{'s' if len(ps) > 1 else ''}: "
                                              f"index must be 0-{len(ps) - 1}")
            lp = ps[idx]
            if spec.params is None:
                return lp, None
            raw = dict(lp.raw) if isinstance(lp.raw, dict) else lp.raw
            lp = LoadedProblem(lp.file, lp.index, lp.type, lp.title, raw, lp.doc, lp.prefix, base_dir=lp.base_dir)
        if spec.params is not None and isinstance(lp.raw, dict):
            base = bp if isinstance(bp := lp.raw.get("params"), dict) else {}
            lp.raw = dict(lp.raw)
            lp.raw["params"] = {**base, **spec.params}
        validate(lp)
        if lp.error is not None and spec.params and lp.error.path and lp.error.path.startswith("params."):
            name = lp.error.path.split(".", 1)[1]
            if name in spec.params:
                d = here(("params", name), lp.error.message)
                return None, d
        return lp, None
