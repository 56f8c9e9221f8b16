"""The body of ``dyncli check --key`` (graded work, docs/check.md) and of
``--selftest``.  Diagnostics go to stderr; stdout (or ``--output``) holds
only the chosen format."""

from __future__ import annotations

import math
from pathlib import Path

from dyncli.check.safe import oneline, say, shown



def load_key(key_name: str, root: str | None):
    """(key, ProblemFiles) or (None, None) after printing why (exit 2)."""
    from dyncli.check.problemfiles import ProblemFiles
    from dyncli.check.keyfile import read_key

    files = ProblemFiles(root=Path(root).resolve() if root else None)
    key = read_key(key_name, files)
    for d in key.diagnostics:
        say(d)
    return (None, files) if key.diagnostics else (key, files)


def run_key_check(key_name: str, names: list[str], fmt: str = "table", reveal: bool = False,
                  output: str | None = None, student: str | None = None, root: str | None = None,
                  id_from: str = "student", upload: bool = False, course=None) -> int:
    """``course``: a :class:`dyncli.check.gradebook.CourseOptions` (--roster, --stats, --compare) or None."""
    from dyncli.check import emit
    from dyncli.check.command import emit_report
    from dyncli.check.emit.common import summary_line

    if not names and (course is None or course.roster is None):
        say("give the submissions to grade (or --selftest to check the key)")
        return 2
    if names.count("-") > 1:
        say("'-' (stdin) can be given only once")
        return 2
    key, files = load_key(key_name, root)
    if key is None:
        if fmt in ("json", "gradescope"):     # stdout holds JSON whatever happens
            try:
                emit.write_text(_invalid_key_json(key_name, fmt), output)
            except emit.OutputError as exc:
                say(exc)
        return 2
    if course is not None and not course.load():
        return 2
    report = grade_all(key, files, names, reveal, student, id_from, upload)
    if course is not None:
        course.finish(report, files, key)
        if course.summary_only(output):
            say(summary_line(report))
            return report.exit_code
    return emit_report(report, fmt, output)


def grade_all(key, files, names: list[str], reveal: bool = False, student: str | None = None,
              id_from: str = "student", upload: bool = False):
    """Every submission graded (a :class:`~dyncli.check.results.Report`); each problem on stderr."""
    from dyncli.check.grader import Grader
    from dyncli.check.results import Report, SubmissionResult
    from dyncli.check.submission import read_submission
    from dyncli.loader import Diagnostic

    grader = Grader(key, files, reveal)
    report = Report(key, reveal=reveal)
    if upload:
        names, problem = pick_upload(key, names)
        if problem:
            report.submissions.append(SubmissionResult("upload", None, key.max_score,
                                                       diagnostics=[Diagnostic("upload", None, None, None, problem)]))
            say(f"upload: {problem}")
    for name in names:
        sr = grader.grade(read_submission(name, student, id_from))
        report.submissions.append(sr)
        for d in sr.diagnostics:
            say(d)
        for q in sr.questions:
            if q.status in ("invalid", "error"):
                where = ":".join(str(x) for x in (sr.file, q.line, q.col) if x is not None)
                say(f"{where}: answers.{q.id}: {q.message}")
    report.solves = files.solves
    report.claims()
    for w in report.warnings:
        say(f"warning: {w['message']}")
    return report


def pick_upload(key, names: list[str]) -> tuple[list[str], str | None]:
    """The one submission among a student's uploaded files: the file the
    key's ``submission:`` names, else the only .yaml/.yml file; otherwise
    ([], why) listing the files."""
    listed = ", ".join(shown(Path(n).name) for n in names[:20]) + (", ..." if len(names) > 20 else "")
    if key.submission:
        hits = [n for n in names if Path(n).name == key.submission]
        if len(hits) == 1:
            return hits, None
        return [], (f"upload one file named {shown(key.submission)}" + (f"; you uploaded: {listed}" if names else "")
                    + (" (several files have that name)" if hits else ""))
    yaml_files = [n for n in names if Path(n).suffix.lower() in (".yaml", ".yml")]
    if len(yaml_files) == 1:
        return yaml_files, None
    if not yaml_files:
        return [], "no submission found: upload one .yaml file" + (f" (you uploaded: {listed})" if names else "")
    return [], f"upload one .yaml file, not {len(yaml_files)}: you uploaded {listed}"


def _invalid_key_json(key_name: str, fmt: str) -> str:
    from dyncli.check.emit.common import json_text

    if fmt == "gradescope":   # students see this: no detail of the instructor's files
        return json_text({"score": 0, "output": "The autograder's key is invalid: please tell your instructor.",
                          "tests": []})
    return json_text({"key": key_name, "title": None, "score": 0, "max_score": 0, "exit_code": 2,
                      "errors": ["the key is invalid (messages on stderr)"], "counts": {}, "solves": 0,
                      "submissions": []})


# ---------------------------------------------------------------------------
# --selftest


def selftest_ids(n: int) -> list[str]:
    return [""] + [f"selftest-{i}" for i in range(n)]


def run_selftest(key_name: str, n: int = 100, root: str | None = None) -> int:
    """Every variant solvable, every question defined and finite, the key
    grades itself 100 %; prints the per-question range of the true answers."""
    from dyncli.check.grader import Grader
    from dyncli.check.variants import VariantError

    key, files = load_key(key_name, root)
    if key is None:
        return 2
    grader = Grader(key, files)
    values: dict[str, list] = {q.id: [] for q in key.questions}
    problem = _unanswerable(grader)
    if problem:
        say(f"{key.file}: selftest failed: {problem}")
        return 1
    warned: set[str] = set()
    for sid in selftest_ids(n if key.variants is not None else 0):
        try:
            params = grader.params(sid)
        except VariantError as exc:
            say(f"{key.file}: variants.require: {exc}")
            return 2
        failure = _selftest_variant(grader, sid, values, warned)
        if failure:
            shown_params = ", ".join(f"{k} = {v:g}" for k, v in params.items()) or "no variant parameters"
            say(f"{key.file}: selftest failed for variant '{sid}' ({shown_params}): {failure}")
            _print_ranges(key, values)
            return 1
    _print_ranges(key, values)
    count = len(selftest_ids(n)) if key.variants is not None else 1
    nq, ns = len(key.questions), files.solves
    print(f"selftest passed: {count} variant{'s' if count != 1 else ''}, {nq} question{'s' if nq != 1 else ''}, "
          f"{ns} solve{'s' if ns != 1 else ''}; the key grades itself 100%")
    return 0


def _unanswerable(grader) -> str | None:
    """A question no student can answer, on the key's first variant: an
    ``answer`` path that is a record, a ``unit`` of another dimension."""
    from dyncli.check.quantities import result_unit, unit_spec

    for q in grader.key.questions:
        t = grader.truth(q, "")
        if t.error:
            continue
        if _has_record(t.value):
            return (f"question {shown(q.id)}: answer '{shown(q.answer)}' is a record, which no submission can "
                    "answer: point it at one of its entries (e.g. " + ", ".join(
                        f"{shown(q.answer)}.{shown(k)}" for k in list(_first_record(t.value))[:3]) + ")")
        ru = result_unit(t.units, q.answer)
        if q.unit and ru:
            try:
                want, got = unit_spec(q.unit).dim, unit_spec(ru, bare=False).dim
            except ValueError:  # pragma: no cover - both were read before
                continue
            if want != got:
                return (f"question {shown(q.id)}: unit '{shown(q.unit)}' is not of the dimension of its answer "
                        f"'{shown(q.answer)}' (the solver gives {shown(ru)}): the right answer with its unit "
                        "would score 0; give a unit of that dimension")
    return None


def _has_record(x) -> bool:
    return isinstance(x, dict) or (isinstance(x, list) and any(_has_record(v) for v in x))


def _first_record(x) -> dict:
    return x if isinstance(x, dict) else next(_first_record(v) for v in x if _has_record(v))


def _selftest_variant(grader, sid: str, values: dict, warned: set | None = None) -> str | None:
    from dyncli.check.grader import scalar
    from dyncli.check.submission import Submission

    key = grader.key
    sub = Submission("<selftest>", sid or "(empty id)")
    for q in key.questions:
        t = grader.truth(q, sid)
        if t.error:
            return f"question {shown(q.id)} ({shown(q.answer)}): {t.error}"
        if t.value is None:
            return f"question {shown(q.id)} ({shown(q.answer)}) is null (not defined) for this variant"
        if not t.reached:
            return f"question {shown(q.id)} ({shown(q.answer)}) is not reached for this variant"
        if not _finite(t.value):
            return f"question {shown(q.id)} ({shown(q.answer)}) is not finite for this variant"
        if q.carry is not None and warned is not None and q.id + "\x00carry" not in warned \
                and _repeats_input(grader, q, sid, t):
            warned.add(q.id + "\x00carry")
            say(f"{key.file}: warning: question {shown(q.id)}'s true answer is within its tolerance of the answer "
                 f"to {shown(q.carry[0])} it carries (variant '{shown(sid)}'): repeating that answer would be "
                 "correct, and no carried answer can earn credit (it would repeat its input)")
        if t.roundoff and warned is not None and q.id not in warned:
            warned.add(q.id)
            say(f"{key.file}: warning: question {shown(q.id)} ({shown(q.answer)}) is zero up to round-off for "
                 f"variant '{shown(sid)}': graded as exactly 0 (correct within {_zero_bound(q.tol)}), never "
                 "diagnosed; make the problem give 0 exactly or ask for another quantity")
        values[q.id].append(t.value)
        sub.answers[q.id] = _in_unit(t.value, q.unit) if scalar(t.value) is not None else t.value
    sub.student = sid
    sr = grader.grade(sub)
    for r in sr.questions:
        if r.status != "correct":
            return f"the key does not grade its own answer to {shown(r.id)} as correct ({r.status}: {r.message})"
    return None


def _repeats_input(grader, q, sid: str, t) -> bool:
    from dyncli.check.compare import number_ok
    from dyncli.check.grader import scalar

    src = grader.truth(grader.key.question(q.carry[0]), sid)
    y, c = scalar(t.value), scalar(src.value)
    return y is not None and c is not None and number_ok(y, c, q.tol)


def _zero_bound(tol) -> str:
    return f"{0.51 * 10.0 ** (1 - tol.sigfigs):g}" if tol.sigfigs is not None else f"atol = {tol.atol:g}"


def _in_unit(x: float, unit: str | None) -> float:
    """An SI value as a bare number in the question's unit."""
    from dyncli.check.quantities import unit_spec

    return x / unit_spec(unit).scale if unit else x


def _finite(x) -> bool:
    if isinstance(x, list):
        return all(_finite(v) for v in x)
    if isinstance(x, dict):
        return all(_finite(v) for v in x.values())
    return not (isinstance(x, float) and not math.isfinite(x))


def _print_ranges(key, values: dict) -> None:
    from dyncli.render.table import fmt_num

    rows = [("question", "answer", "min", "max", "distinct")]
    for q in key.questions:
        vs = values[q.id]
        nums = [v for v in vs if isinstance(v, (int, float)) and not isinstance(v, bool)]
        distinct = len({repr(v) for v in vs})
        if nums:
            lo, hi = fmt_num(min(nums), 6), fmt_num(max(nums), 6)
        else:
            lo = hi = ", ".join(sorted({oneline(fmt_num(v, 6) if isinstance(v, float) else v) for v in vs})[:3])
        flag = "  <- the same for every variant" if len(vs) > 1 and distinct == 1 and key.variants else ""
        rows.append((oneline(q.id), oneline(q.answer), lo, hi, f"{distinct}{flag}"))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    for r in rows:
        print("  ".join(c.ljust(w) for c, w in zip(r, widths)) + "  " + r[4])
    _print_carries(key, values)


def _print_carries(key, values: dict) -> None:
    """What a carried answer may carry: a factor WINDOW around the values the
    earlier question has (docs/check.md, "Carried answers")."""
    from dyncli.check.carry import WINDOW
    from dyncli.render.table import fmt_num

    for q in key.questions:
        nums = [abs(v) for v in values.get(q.carry[0], []) if isinstance(v, (int, float)) and not isinstance(v, bool)
                and v != 0] if q.carry else []
        if nums:
            print(f"carry: {oneline(q.id)} takes the answer to {oneline(q.carry[0])} (either sign) within "
                  f"{fmt_num(min(nums) / WINDOW, 3)} ... {fmt_num(max(nums) * WINDOW, 3)} "
                  f"(a factor {WINDOW:g} around its true answers above)")
