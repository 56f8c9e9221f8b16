"""The grader of ``dyncli check`` (docs/check.md): every submission graded
against a key, in both modes — the instructor's key (graded work) or the key
built from a self-study answer file (:mod:`dyncli.check.selfstudy`); where
the two differ is the key's :class:`~dyncli.check.keyfile.Policy`.

* A variant is the key's problems with the student's drawn ``params``
  substituted (only names a problem's ``params`` already has).
* ``carry: {from: Q, param: P}``: the reference is solved with ``params.P``
  set to Q's true answer; when the student's answer to Q was not correct but
  numeric, the question is also graded against the problem re-solved with
  the student's value of Q (status ``carried``, full points).
* Every wrong answer is diagnosed (:mod:`dyncli.check.diagnose`) and earns
  the key's ``partial`` fraction for that slip.
* Each distinct (problem, variant) is solved once per command (the shared
  :class:`~dyncli.check.problemfiles.ProblemFiles` cache).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any

from dyncli.check import carry, zeros
from dyncli.check.compare import compare, has_unit_text, rel_text
from dyncli.check.diagnose import TEXT, diagnose
from dyncli.check.emit.common import fmt_given
from dyncli.check.keyfile import Key, Question
from dyncli.check.paths import lookup, unknown_key_message
from dyncli.check.quantities import NO_UNIT, UnitSpec, WrongDimension, convert, result_unit, unit_spec
from dyncli.check.results import QuestionResult, SubmissionResult
from dyncli.check.safe import shown
from dyncli.check.submission import Submission
from dyncli.loader import Diagnostic, LoadedProblem

_DIAG_RE = re.compile(r"^(?P<file>.*?):(?P<line>\d+):(?P<col>\d+): (?P<msg>.*)$", re.S)


@dataclass
class Truth:
    """A question's reference answer for one variant (or an error)."""

    value: Any = None
    units: dict = field(default_factory=dict)
    error: str | None = None
    code: int = 0
    reached: bool = True
    roundoff: bool = False         # a number zero up to round-off, graded as 0 (dyncli.check.zeros)
    quotes_values: bool = False    # a solver's message: may quote values derived from true answers
    unknown: bool = False          # self-study: the answer path is not in the results (error says why)
    diag: Diagnostic | None = None  # where the problem failed (self-study reports it per check)
    trace: str | None = None       # our own traceback (--debug)


def diagnostic_of(msg: str) -> Diagnostic:
    """A solver's one-line message (``file:line:col: text``) as a Diagnostic."""
    m = _DIAG_RE.match(msg or "")
    if m:
        return Diagnostic(m["file"], int(m["line"]), int(m["col"]), None, m["msg"])
    head, sep, rest = (msg or "").partition(": ")
    if sep and not head.count(" "):
        return Diagnostic(head, None, None, None, rest)
    return Diagnostic("", None, None, None, msg or "unknown error")


def not_reached(results: Any, path: str) -> bool:
    """Whether a record along ``path`` says ``reached: false``."""
    cur = results
    for part in path.split("."):
        if isinstance(cur, dict) and cur.get("reached") is False:
            return True
        if isinstance(cur, dict):
            cur = cur.get(part)
        elif isinstance(cur, list) and part.isdigit() and int(part) < len(cur):
            cur = cur[int(part)]
        else:
            return False
    return isinstance(cur, dict) and cur.get("reached") is False


def scalar(x: Any) -> float | None:
    return float(x) if isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) else None


class Grader:
    def __init__(self, key: Key, files, reveal: bool = False):
        self.key, self.files, self.reveal = key, files, reveal
        self._params: dict[str | None, dict] = {}
        self._truth: dict[tuple, Truth] = {}
        self._outcomes: dict[tuple, Any] = {}

    # -- variants and references ------------------------------------------
    def params(self, student: str | None) -> dict[str, float]:
        """The student's drawn values (raises VariantError); ``student`` None: self-study (no variants)."""
        if student not in self._params:
            v = self.key.variants
            assert v is None or student is not None          # variants are drawn for a student id
            self._params[student] = v.draw(student) if v is not None and student is not None else {}
        return self._params[student]

    def problem(self, q: Question, values: dict[str, Any], extra: dict[str, float]) -> LoadedProblem:
        """The question's problem with the drawn values and carried inputs
        in its ``params`` (not validated: :meth:`ProblemFiles.solve` does it
        once per distinct content)."""
        base = q.problem
        assert base is not None              # solved only when the question has its problem (q.error None)
        raw = base.raw
        if isinstance(raw, dict) and (values or extra):
            own = op if isinstance(op := raw.get("params"), dict) else {}
            sub = self.key.variants.substitution(values) if self.key.variants is not None else {}
            raw = {**raw, "params": {**own, **{n: v for n, v in sub.items() if n in own}, **extra}}
        return LoadedProblem(base.file, base.index, base.type, base.title, raw, base.doc, base.prefix,
                             base_dir=base.base_dir)

    def truth(self, q: Question, student: str | None, carried: float | None = None) -> Truth:
        """Q's reference for this student; ``carried``: the value of the
        carry parameter (default: the true answer of the question it comes from)."""
        memo = (q.id, student, carried)
        if memo in self._truth:
            return self._truth[memo]
        t = self._truth[memo] = Truth(error="carry cycle", code=2)   # guards re-entry
        extra: dict[str, float] = {}
        if q.carry is not None:
            if carried is None:
                src = self.truth(self._source(q), student)
                carried = scalar(src.value)
                if src.error or carried is None:
                    t = Truth(error=src.error or f"the true answer to '{shown(q.carry[0])}' (carried forward) "
                                                 "is not one finite number (a carry needs a question whose answer "
                                                 "is a single number)", code=src.code or 2,
                              quotes_values=src.quotes_values)
                    self._truth[memo] = t
                    return t
            extra[q.carry[1]] = carried
        t = self._solve(q, self.params(student), extra) if q.error is None else \
            Truth(error=q.error.message, code=2, diag=q.error)
        self._truth[memo] = t
        return t

    def _solve(self, q: Question, values: dict, extra: dict) -> Truth:
        memo = (id(q.problem), tuple(sorted(values.items())), tuple(sorted(extra.items())))
        outcome = self._outcomes.get(memo)      # the questions of one problem share its solve
        if outcome is None:
            outcome = self._outcomes[memo] = self.files.solve(self.problem(q, values, extra), validated=False)
        if outcome.exit_code != 0 or outcome.result is None:
            d = diagnostic_of(outcome.message or "")
            return Truth(error=d.message, code=outcome.exit_code or 3, quotes_values=True, diag=d, trace=outcome.trace)
        solved = self.files.results(outcome)
        results = solved.results
        found, value, msg = lookup(results, q.answer)
        if not found and self.key.policy.unknown_path:
            return Truth(error=unknown_key_message(results, q.answer, solved.index), code=1, unknown=True)
        if not found:                   # the key's mistake, said as such, with what it may have meant
            hint = unknown_key_message(results, q.answer, solved.index).removeprefix(f"unknown answer key "
                                                                                   f"'{shown(q.answer)}'")
            return Truth(error=f"the key's question '{shown(q.id)}': its answer path '{shown(q.answer)}' is not in "
                               f"the results{hint} (fix the key: `dyncli check --key KEY --selftest` finds this "
                               "before grading)", code=2)
        value, roundoff = zeros.snap(value, solved.scale) if self.key.policy.snap_zeros else (value, False)
        return Truth(value, outcome.result.units, reached=not not_reached(results, q.answer), roundoff=roundoff)

    def unit(self, q: Question, truth: Truth, given: Any = None) -> UnitSpec:
        """How ``given`` is read: the question's ``unit``, else (for an
        answer written with a unit) the dimension of the solver's unit;
        a bare number without ``unit`` needs no units library at all."""
        if q.unit:
            return unit_spec(q.unit)
        if not has_unit_text(given):
            return NO_UNIT
        try:
            return unit_spec(result_unit(truth.units, q.answer), bare=False)
        except ValueError:  # pragma: no cover - solvers report units pint knows
            return NO_UNIT

    # -- grading ----------------------------------------------------------
    def grade(self, sub: Submission) -> SubmissionResult:
        """A submission of the key's students: nothing is graded for an
        invalid submission or a student whose variant cannot be drawn."""
        from dyncli.check.variants import VariantError

        sr = SubmissionResult(sub.file, sub.student, self.key.max_score, diagnostics=list(sub.diagnostics))
        if sub.diagnostics or sub.student is None:
            return sr
        try:
            sr.params = dict(self.params(sub.student))
        except VariantError as exc:
            sr.diagnostics.append(Diagnostic(self.key.file, None, None, "variants.require", str(exc)))
            return sr
        self.grade_into(sub, sr)
        return sr

    def grade_into(self, sub: Submission, sr: SubmissionResult) -> None:
        """Every question of the key graded from ``sub`` into ``sr``."""
        for q in self.key.questions:
            r = self.grade_one(q, sub, sr)
            text = q.feedback.get(r.diagnosis or "") or q.feedback.get(r.status)
            if text:           # the instructor's words for this status or slip, in every format
                r.feedback, r.message = text, (f"{r.message}; {text}" if r.message else text)
            r.line, r.col = sub.positions.get(q.id, (None, None))
            sr.questions.append(r)
        self.unknown(sub, sr)

    def grade_one(self, q: Question, sub: Submission, sr: SubmissionResult) -> QuestionResult:
        title = q.title or (q.problem.title if q.problem is not None else "")
        r = QuestionResult(q.id, "missing", 0.0, q.points, sub.answers.get(q.id), visible=q.visible,
                           title=title, answer=q.answer, tolerance=q.tol)
        t = self.truth(q, sub.student)
        policy = self.key.policy
        r.expected = t.value
        if t.error and not t.unknown:   # the detail may quote values derived from true answers: only with --reveal
            r.status = "error"
            key_fault = t.error.startswith("the key's question ")       # (its answer path: no solve failed)
            r.message = (f"not graded: {t.error}" if key_fault else f"not graded: {policy.not_solved}"
                         + (f" ({t.error})" if self.reveal or not t.quotes_values or not policy.secret
                            else " (tell your instructor: --selftest shows why)"))
            sr.error_code = max(sr.error_code, t.code)
            return r
        if q.invalid is not None or t.unknown:
            r.status, r.message = ("invalid", q.invalid) if q.invalid is not None else ("unknown", t.error or "")
            return r
        if r.given is None and not policy.null_is_answer:
            r.message = "not answered"
            return r
        spec = self.unit(q, t, r.given)
        v = compare(r.given, t.value, q.tol, spec)
        r.rel_error, r.abs_error = v.rel_error, v.abs_error
        if v.correct:
            r.status, r.score = "correct", q.points
            return r
        if v.status in ("invalid", "missing"):
            r.status, r.message = v.status, v.message
            return r
        r.status, r.message, r.diagnosis = "wrong", v.message, v.diagnosis
        if self._carried(q, sub, r, spec):
            return r
        self._partial(q, r, t, spec)
        return r

    def _carried(self, q: Question, sub: Submission, r: QuestionResult, spec: UnitSpec) -> bool:
        """Grade against the problem re-solved with the student's answer to
        the question this one carries from (:mod:`dyncli.check.carry`)."""
        if q.carry is None or sub.answers.get(q.carry[0]) is None:
            return False
        src = self._source(q)
        true_src = self.truth(src, sub.student)
        if true_src.error:
            return False
        src_spec = self.unit(src, true_src, sub.answers[src.id])
        mine = _si_scalar(sub.answers[src.id], src_spec)
        if mine is None:
            return False
        src_ok = compare(sub.answers[src.id], true_src.value, src.tol, src_spec).correct
        if not self.plausible(src, mine, sub):
            if not src_ok:
                r.message += (f"; not graded with your answer to {shown(src.id)} carried forward: it is too far "
                              f"from any value {shown(src.id)} can have (more than {carry.WINDOW:g} times off)")
            return False
        g = _si_scalar(r.given, spec)
        if g is not None and carry.repeats(g, mine, q.tol):
            if not src_ok:
                r.message += (f"; not graded with your answer to {shown(src.id)} carried forward: your answer "
                              f"repeats it and shows nothing of this question's own part")
            return False
        h = carry.halfwidth(sub.answers[src.id], sub.written.get(src.id), mine)
        points = (mine - h, mine, mine + h) if h > 0 else (mine,)
        alts = [self.truth(q, sub.student, carried=c) for c in points]
        values = [None if a.error else a.value for a in alts]
        if any(v is not None and compare(r.given, v, q.tol, spec).correct for v in values) or \
                carry.between(g, [scalar(v) for v in values]):
            r.status, r.score, r.diagnosis, r.rel_error = "carried", q.points, None, None
            r.message = f"correct with your answer to {shown(src.id)} carried forward"
            return True
        rel = carry.nearest_rel(g, [scalar(v) for v in values])
        if not src_ok and rel is not None:
            r.carried_rel_error = rel
            r.message = (f"relative error {rel_text(rel)} from the answer that follows from your "
                         f"{shown(src.id)} = {shown(fmt_given(sub.answers[src.id]), 24)} (carried forward) "
                         f"exceeds the tolerance ({q.tol.describe()})")
        return False

    def _source(self, q: Question) -> Question:
        """The question ``q`` carries its input from (the key's reader checked that it exists)."""
        assert q.carry is not None
        src = self.key.question(q.carry[0])
        assert src is not None
        return src

    def plausible(self, src: Question, c: float, sub: Submission) -> bool:
        """Whether ``c`` is a value the question ``src`` can carry forward:
        within :data:`~dyncli.check.carry.WINDOW` of its true answer, or of the
        answer that follows from the student's own plausible earlier answer."""
        if carry.in_window(c, scalar(self.truth(src, sub.student).value)):
            return True
        if src.carry is None or sub.answers.get(src.carry[0]) is None:
            return False
        up = self._source(src)
        t_up = self.truth(up, sub.student)
        m = None if t_up.error else _si_scalar(sub.answers[up.id], self.unit(up, t_up, sub.answers[up.id]))
        if m is None or not self.plausible(up, m, sub):
            return False
        alt = self.truth(src, sub.student, carried=m)
        return not alt.error and carry.in_window(c, scalar(alt.value))

    def _partial(self, q: Question, r: QuestionResult, t: Truth, spec: UnitSpec) -> None:
        if r.diagnosis is None:
            try:
                g = convert(r.given, spec)
            except WrongDimension:  # pragma: no cover - compare diagnosed it already
                g = None
            r.diagnosis = diagnose(g, t.value, q.tol)
        if r.diagnosis is None:
            return
        if r.diagnosis != "wrong_dimension" and TEXT[r.diagnosis] not in r.message and "hint:" not in r.message:
            r.message += f"; hint: {TEXT[r.diagnosis]}"
        frac = q.partial.get(r.diagnosis, 0.0)
        if r.diagnosis == "wrong_dimension" and frac and not _magnitude_ok(r.given, t.value, q.tol):
            frac = 0.0
        if frac > 0:
            r.status, r.score = "partial", frac * q.points
            r.message += f" ({frac:g} of the points for this slip)"

    def unknown(self, sub: Submission, sr: SubmissionResult) -> None:
        from dyncli.expr import did_you_mean

        ids = [q.id for q in self.key.questions]
        known = set(ids)
        for i, qid in enumerate(a for a in sub.answers if a not in known):
            hint = did_you_mean(qid, ids) if i < 50 and len(qid) <= 200 else ""
            line, col = sub.positions.get(qid, (None, None))
            sr.unknown.append({"id": qid, "message": f"'{shown(qid)}' is not a question of this key{hint}",
                               "line": line, "col": col})


def _si_scalar(given: Any, spec: UnitSpec) -> float | None:
    from dyncli.check.compare import GivenError
    from dyncli.check.quantities import to_si

    try:
        v = to_si(given, spec)
    except (GivenError, WrongDimension):
        return None
    return v if v is not None and math.isfinite(v) else None


def _magnitude_ok(given: Any, true: Any, tol) -> bool:
    """A number with a unit of the wrong dimension whose SI magnitude is right."""
    from dyncli import units
    from dyncli.check.compare import number_ok

    m = units.QUANTITY.match(given) if isinstance(given, str) else None
    t = scalar(true)
    if not m or t is None:
        return False
    try:
        q = units.registry().Quantity(float(m.group("num")), units.registry().parse_units(units.clean_unit(m.group("unit"))))
        return number_ok(float(q.to_base_units().magnitude), t, tol)
    except Exception:  # noqa: BLE001
        return False
