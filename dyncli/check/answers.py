"""Reading answer files (docs/check.md) with source positions.

An answer file is one check mapping or ``{checks: [mapping, ...]}``::

    problem: p2.yaml            # path relative to this file, or an inline problem mapping
    index: 0                    # which problem of a multi-problem file [0]
    params: {m: 2.5}            # optional: overrides the problem's params (per-student data)
    tolerance: {rtol: 0.01, atol: 1.0e-8}   # or {sigfigs: 3}
    title: free text
    answers:
      vA2: [0.5, 1.0, 0.0]
      energy_loss: {value: 1.25, rtol: 0.001, points: 2}
      find.1.t: 2.04

With ``checks:``, a top-level ``tolerance`` is the default of every check.
Structural problems become :class:`~dyncli.loader.Diagnostic` s (exit 2);
a bad per-answer specification marks only that answer invalid.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from dyncli.check.tolerance import TOL_KEYS, FieldError, Tolerance, parse_tolerance, read_points, tolerance_from
from dyncli.check.safe import shown, yaml_diagnostic
from dyncli.errors import InputError
from dyncli.expr import did_you_mean
from dyncli.loader import Diagnostic
from dyncli.yamlsafe import Document, YamlError, load as yaml_load

CHECK_KEYS = ("problem", "index", "params", "tolerance", "title", "answers")
TOP_KEYS = ("checks", "tolerance", "title")
ANSWER_KEYS = ("value", "rtol", "atol", "sigfigs", "points")


@dataclass
class Answer:
    key: str
    given: Any
    tol: Tolerance
    points: float
    line: int | None
    col: int | None
    error: str | None = None      # invalid specification (exit 2)


@dataclass
class CheckSpec:
    file: str
    index: int
    prefix: tuple                 # path of this check mapping in the document
    problem_ref: str | None = None
    problem_inline: dict | None = None
    problem_index: int | None = None
    params: dict | None = None
    title: str | None = None
    answers: list[Answer] = field(default_factory=list)
    line: int | None = None       # position of the 'problem' value
    col: int | None = None


@dataclass
class AnswerFile:
    file: str
    doc: Document | None
    base_dir: Path
    title: str | None = None
    checks: list[CheckSpec] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)


def read_answer_file(display: str, data: bytes | str, base_dir: Path) -> AnswerFile:
    af = AnswerFile(display, None, base_dir)
    try:
        doc = yaml_load(data)
    except YamlError as exc:
        af.diagnostics.append(yaml_diagnostic(display, exc, "answers (a mapping with 'problem' and 'answers')"))
        return af
    af.doc = doc
    data = doc.data

    def diag(path: tuple, message: str, key: bool = True) -> Diagnostic:
        pos = doc.locate(path) if key else (doc.value_pos(path) or doc.locate(path))
        line, col = pos if pos else (None, None)
        dotted = ".".join(str(p) for p in path) or None
        return Diagnostic(display, line, col, dotted, message)

    if not isinstance(data, dict):
        af.diagnostics.append(diag((), "expected answers: a mapping with 'problem' and 'answers', or 'checks: [...]'"))
        return af
    if "checks" in data and "answers" not in data and "problem" not in data:
        for k in data:
            if k not in TOP_KEYS:
                af.diagnostics.append(diag((k,), f"unknown top-level key '{shown(k)}'{did_you_mean(str(k), TOP_KEYS)}; "
                                           "a file with 'checks:' holds checks, tolerance and title"))
        base = Tolerance()
        if "tolerance" in data:
            try:
                base = parse_tolerance(data["tolerance"], base, ("tolerance",))
            except FieldError as exc:
                af.diagnostics.append(diag(exc.path, exc.message, exc.key))
        if isinstance(data.get("title"), str):
            af.title = data["title"]
        items = data["checks"]
        if not isinstance(items, list) or not items:
            af.diagnostics.append(diag(("checks",), "expected a non-empty list of checks (mappings with 'problem' and 'answers')"))
            return af
        for i, item in enumerate(items):
            _read_check(af, doc, item, ("checks", i), i, base, diag)
    else:
        _read_check(af, doc, data, (), 0, Tolerance(), diag)
        if isinstance(data.get("title"), str):
            af.title = data["title"]
    return af


def _read_check(af: AnswerFile, doc: Document, item: Any, prefix: tuple, index: int, base: Tolerance, diag) -> None:
    if not isinstance(item, dict):
        af.diagnostics.append(diag(prefix, "expected a check: a mapping with 'problem' and 'answers'"))
        return
    spec = CheckSpec(af.file, index, prefix)
    ok = True
    for k in item:
        if k not in CHECK_KEYS:
            hint = did_you_mean(str(k), CHECK_KEYS)
            extra = "" if hint else "; answers go under 'answers:'"
            af.diagnostics.append(diag(prefix + (k,), f"unknown key '{shown(k)}'{hint}; known: {', '.join(CHECK_KEYS)}{extra}"))
            ok = False
    ok = _read_problem(af, doc, item, prefix, spec, diag) and ok
    ok = _read_selection(af, item, prefix, spec, diag) and ok
    if isinstance(item.get("title"), str):
        spec.title = item["title"]
    tol = base
    if "tolerance" in item:
        try:
            tol = parse_tolerance(item["tolerance"], base, prefix + ("tolerance",))
        except FieldError as exc:
            af.diagnostics.append(diag(exc.path, exc.message, exc.key))
            ok = False
    if _missing(af, item, "answers", prefix, diag,
                "a mapping key: value (keys are dotted paths into the results, e.g. find.1.t)"):
        ok = False
    else:
        ans = item["answers"]
        if not isinstance(ans, dict) or not ans:
            af.diagnostics.append(diag(prefix + ("answers",), "'answers' must be a non-empty mapping key: value", key=False))
            ok = False
        else:
            for k, v in ans.items():
                spec.answers.append(_read_answer(doc, prefix + ("answers", k), str(k), v, tol))
    if ok:
        af.checks.append(spec)


def _read_problem(af: AnswerFile, doc: Document, item: dict, prefix: tuple, spec: CheckSpec, diag) -> bool:
    """A check's ``problem``: a file path (relative to the answer file) or an inline mapping."""
    if _missing(af, item, "problem", prefix, diag,
                "a problem file path (relative to this file) or an inline problem mapping"):
        return False
    p = item["problem"]
    pos = doc.value_pos(prefix + ("problem",))
    spec.line, spec.col = pos if pos else (None, None)
    if isinstance(p, str) and p.strip():
        spec.problem_ref = p.strip()
    elif isinstance(p, dict):
        spec.problem_inline = p
    else:
        af.diagnostics.append(diag(prefix + ("problem",), "'problem' must be a file path or an inline problem mapping", key=False))
        return False
    return True


def _missing(af: AnswerFile, item: dict, key: str, prefix: tuple, diag, what: str) -> bool:
    """True (with the diagnostic "missing 'key': what") when a check lacks ``key``."""
    if key in item:
        return False
    af.diagnostics.append(diag(prefix, f"missing '{key}': {what}"))
    return True


def _read_selection(af: AnswerFile, item: dict, prefix: tuple, spec: CheckSpec, diag) -> bool:
    """A check's ``index`` (which problem of a ``problems:`` file) and ``params``."""
    ok = True
    if "index" in item:
        v = item["index"]
        if isinstance(v, bool) or not isinstance(v, int) or v < 0:
            af.diagnostics.append(diag(prefix + ("index",), "index must be a whole number >= 0 (which problem of a 'problems:' file)", key=False))
            ok = False
        else:
            spec.problem_index = v
    if "params" in item:
        v = item["params"]
        if not isinstance(v, dict) or not v:
            af.diagnostics.append(diag(prefix + ("params",), "params must be a mapping name: number-or-expression", key=False))
            ok = False
        else:
            bad = [k for k, x in v.items() if isinstance(x, (bool, list, dict)) or x is None]
            if bad:
                af.diagnostics.append(diag(prefix + ("params", bad[0]), "a parameter must be a number or an expression", key=False))
                ok = False
            spec.params = {str(k): x for k, x in v.items()}
    return ok


def _read_answer(doc: Document, path: tuple, key: str, v: Any, tol: Tolerance) -> Answer:
    line, col = doc.locate(path) or (None, None)
    a = Answer(key, v, tol, 1.0, line, col)
    if isinstance(v, dict) and "value" not in v and v and all(k in ANSWER_KEYS for k in v):
        a.error = "missing 'value' (write {value: 1.25, rtol: 0.001, points: 2})"
        return a
    if isinstance(v, dict) and "value" in v:
        try:
            for k in v:
                if k not in ANSWER_KEYS:
                    raise FieldError(path + (k,), f"unknown key '{shown(k)}'{did_you_mean(str(k), ANSWER_KEYS)}; known: {', '.join(ANSWER_KEYS)}")
            a.tol = tolerance_from({k: x for k, x in v.items() if k not in ("value", "points")}, tol, path, TOL_KEYS)
        except FieldError as exc:
            a.error = f"{exc.message}"
            pos = doc.locate(exc.path) if exc.key else doc.value_pos(exc.path)
            if pos:
                a.line, a.col = pos
            return a
        a.given = v["value"]
        if "points" in v:
            try:
                a.points = read_points(v["points"])
            except ValueError as exc:
                a.error = str(exc)
                pos = doc.value_pos(path + ("points",))
                if pos:
                    a.line, a.col = pos
                return a
    return a


def read_answer_source(name: str) -> AnswerFile:
    """Read an answer file by name (``-`` = stdin)."""
    from dyncli.loader import read_source

    try:
        display, data = read_source(name)
    except InputError as exc:
        af = AnswerFile(name, None, Path.cwd())
        af.diagnostics.append(Diagnostic(name, None, None, None, exc.message.removeprefix(f"{name}: ")))
        return af
    base = Path(name).parent if name != "-" else Path.cwd()
    return read_answer_file(display, data, base)
