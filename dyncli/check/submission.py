"""Reading a student's submission (docs/check.md): ``student`` and
``answers`` only.  Anything else — ``tolerance``, ``points``, ``params``,
``problem``... — is invalid input naming the field (exit 2): the key alone
decides what is graded and how."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from dyncli.check.safe import oneline, shown, yaml_diagnostic
from dyncli.expr import did_you_mean
from dyncli.loader import Diagnostic

SUB_KEYS = ("student", "answers")
MAX_ANSWERS = 2000


def as_written(doc, path: tuple, value: Any) -> Any:
    """A scalar as its source text when YAML read it as a number or boolean
    (``012345671`` is octal, ``1:30`` is 90 in YAML 1.1): ids are text."""
    if isinstance(value, (int, float)) and doc is not None:
        return doc.text.get(tuple(path), value)
    return value


def key_as_written(doc, path: tuple, key: Any) -> str:
    """A mapping key as its source text (``010:`` stays "010")."""
    if isinstance(key, str) or doc is None:
        return str(key)
    return doc.text.get(tuple(path) + (key, "<key>"), str(key))


@dataclass
class Submission:
    file: str
    student: str | None = None
    answers: dict[str, Any] = field(default_factory=dict)
    positions: dict[str, tuple[int | None, int | None]] = field(default_factory=dict)
    written: dict[str, str] = field(default_factory=dict)   # an answer's source text (numbers only)
    diagnostics: list[Diagnostic] = field(default_factory=list)


def read_submission(name: str, student_opt: str | None = None, id_from: str = "student") -> Submission:
    """``id_from``: ``student`` (the file's ``student:``, else ``student_opt``,
    else the file name's stem) or ``filename`` (the file name's stem is the
    id; a ``student:`` that differs is refused)."""
    from dyncli.errors import InputError
    from dyncli.loader import read_source
    from dyncli.yamlsafe import YamlError, load as yaml_load

    sub = Submission(name)
    try:
        sub.file, data = read_source(name)
        doc = yaml_load(data)
    except YamlError as exc:
        sub.diagnostics.append(yaml_diagnostic(sub.file, exc, "a submission (a mapping with 'student' and 'answers')"))
        return sub
    except InputError as exc:
        sub.diagnostics.append(Diagnostic(name, None, None, None, exc.message.removeprefix(f"{name}: ")))
        return sub

    def diag(path: tuple, message: str) -> None:
        line, col = doc.locate(path) or (None, None)
        sub.diagnostics.append(Diagnostic(sub.file, line, col, ".".join(oneline(p) for p in path) or None, message))

    data = doc.data
    if not isinstance(data, dict):
        diag((), "expected a submission: a mapping with 'student' and 'answers'")
        return sub
    for k in data:
        if k not in SUB_KEYS:
            hint = did_you_mean(str(k), SUB_KEYS)
            diag((k,), f"'{shown(k)}' is not allowed in a submission{hint}: it holds only 'student' and "
                       "'answers' (the key sets problems, tolerances, points and params)")
    if id_from == "filename" and name != "-":
        student_opt, source = Path(name).stem, "the file name"
    else:
        source = "--student"
    _student(sub, doc, student_opt, source, name, diag)
    ans = data.get("answers")
    if not isinstance(ans, dict) or len(ans) > MAX_ANSWERS:
        diag(("answers",), f"'answers' must be a mapping question-id: value (at most {MAX_ANSWERS})")
        return sub
    for k, v in ans.items():
        qid = key_as_written(doc, ("answers",), k)
        if isinstance(v, dict):
            inner = next(iter(v), "value")
            diag(("answers", k, inner), f"answer '{shown(qid)}' must be a value (a number, an expression, "
                                        "'12 m/s', a list): points and tolerances belong to the key")
            continue
        sub.answers[qid] = v
        if ("answers", k) in doc.text and not isinstance(v, bool):
            sub.written[qid] = doc.text[("answers", k)]
        pos = doc.locate(("answers", k))
        if pos:
            sub.positions[qid] = pos
    return sub


def _student(sub: Submission, doc, opt: str | None, source: str, name: str, diag) -> None:
    data = doc.data
    sid = as_written(doc, ("student",), data.get("student"))
    if "student" in data and (not isinstance(sid, str) or not sid.strip()
                              or len(str(sid)) > 200 or oneline(sid) != str(sid)):
        diag(("student",), "student must be the student's id (printable text, at most 200 characters)")
        return
    sid = str(sid).strip() if sid is not None else None
    if opt is not None and sid is not None and sid != opt:
        diag(("student",), f"student '{shown(sid)}' does not match {source} '{shown(opt)}'")
        return
    sid = sid or opt
    if sid is None and name != "-":
        sid = Path(name).stem
    if not sid:
        diag((), "no student id: write 'student: ID' in the submission or give --student ID")
        return
    sub.student = sid
