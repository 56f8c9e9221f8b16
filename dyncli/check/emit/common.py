"""What every emitter of ``dyncli check`` shares (docs/check.md): the words
of a status, points and given values as text, the one-line feedback (never
an expected value without ``--reveal``), the score summary, and text made
safe for JSON, XML, workflow commands and Markdown.  Every user string is
echoed on one line (:func:`~dyncli.check.safe.oneline`)."""

from __future__ import annotations

import json
import re
from typing import Any

from dyncli.check.results import FULL, QuestionResult, Report, SubmissionResult
from dyncli.check.safe import oneline

STATUS_TEXT = {"correct": "correct", "carried": "carried", "partial": "partial", "wrong": "wrong",
               "missing": "missing", "unknown": "unknown key", "invalid": "invalid", "error": "not graded"}
#: the mark and colour of a status in the table
MARKS = {"correct": ("ok", "green"), "carried": ("ok", "green"), "partial": ("~", "yellow"),
         "wrong": ("bad", "red"), "missing": ("bad", "red"), "unknown": ("?", "yellow"),
         "invalid": ("!", "magenta"), "error": ("!", "magenta")}
#: statuses without an expected value to reveal
NO_EXPECTED = ("correct", "unknown", "error")
GITHUB_MAX_ERRORS = 10


def fmt_points(x: float) -> str:
    return str(int(x)) if float(x).is_integer() else f"{x:.4g}"


def fmt_given(x: Any, digits: int = 6) -> str:
    from dyncli.render.table import fmt_num

    if isinstance(x, list):
        return "[" + ", ".join(fmt_given(v, digits) for v in x) + "]"
    if isinstance(x, dict):
        return "{" + ", ".join(f"{k}: {fmt_given(v, digits)}" for k, v in x.items()) + "}"
    if x is None:
        return "null"
    if isinstance(x, str):
        return oneline(x)
    return fmt_num(x, digits)


def points(q: QuestionResult) -> str:
    return f"{fmt_points(q.score)}/{fmt_points(q.points)}"


def expected_text(q: QuestionResult, reveal: bool) -> str:
    """The expected value (``--reveal`` only), else ''."""
    return oneline(fmt_given(q.expected, 10)) if reveal and q.status not in NO_EXPECTED else ""


def feedback(q: QuestionResult, reveal: bool) -> str:
    """One line: what is wrong, the instructor's words, and with ``reveal``
    the expected value."""
    msg = oneline(q.message)
    exp = expected_text(q, reveal)
    if exp:
        msg = (msg + "; " if msg else "") + f"expected {exp}"
    return msg


def after_status(q: QuestionResult, reveal: bool) -> str:
    """:func:`feedback` to follow the status word ("not graded: ..." does
    not say "not graded" twice)."""
    return feedback(q, reveal).removeprefix(f"{STATUS_TEXT[q.status]}: ")


def who(s: SubmissionResult) -> str:
    return oneline(f"{s.file} ({s.student})" if s.student else s.file)


def where(file: str, line: int | None, col: int | None) -> str:
    return f"{file}:{line}:{col or 1}" if line is not None else file


def summary_line(report: Report) -> str:
    """The one-line score (stderr, GitHub's notice, the step summary)."""
    c = report.counts()
    total = sum(c.values())
    pct = 100.0 * report.score / report.max_score if report.max_score else 0.0
    parts = [f"score {fmt_points(report.score)}/{fmt_points(report.max_score)} ({pct:.0f}%)"]
    if report.graded:
        n = len(report.submissions)
        full = sum(c.get(k, 0) for k in FULL)
        parts += [f"{n} submission{'s' if n != 1 else ''}", f"{full} of {total} answers with full points"]
        parts += [f"{c[k]} {STATUS_TEXT[k]}" for k in ("carried", "partial", "wrong", "missing", "invalid", "error")
                  if c.get(k)]
        bad = sum(1 for s in report.submissions if s.diagnostics)
        noun = "submission"
    else:
        parts.append(f"{c.get('correct', 0)} of {total} answer{'s' if total != 1 else ''} correct")
        parts += [f"{c[k]} {STATUS_TEXT[k]}" for k in ("wrong", "missing", "unknown", "invalid", "error") if c.get(k)]
        bad = sum(len(s.diagnostics) for s in report.submissions)
        noun = "file"
    if bad:
        parts.append(f"{bad} invalid {noun}{'s' if bad != 1 else ''}")
    return ", ".join(parts)


def json_text(doc: Any) -> str:
    """Indented JSON, no NaN; U+2028/U+2029 escaped too (JSON allows them raw,
    but JavaScript and some log viewers take them for line breaks)."""
    text = json.dumps(doc, indent=2, allow_nan=False, ensure_ascii=False)
    return text.replace("\u2028", "\\u2028").replace("\u2029", "\\u2029") + "\n"


_XML_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")


def xml_text(s: Any) -> str:
    """Text safe for XML 1.0 on one line (ElementTree escapes markup;
    control characters are shown escaped, the rest XML cannot hold dropped)."""
    return _XML_BAD.sub("\ufffd", oneline(s))


def xml_body(lines: list[str]) -> str:
    """A JUnit failure body: each line made safe (and kept on its line) by
    :func:`xml_text`, joined by real newlines."""
    return "\n".join(xml_text(line) for line in lines)


def gh_escape_data(s: str) -> str:
    """The Actions toolkit's escapeData: % CR LF."""
    return str(s).replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def gh_escape_property(s: str) -> str:
    """The Actions toolkit's escapeProperty: % CR LF : ,"""
    return gh_escape_data(s).replace(":", "%3A").replace(",", "%2C")


def gh_command(kind: str, message: str, **props: Any) -> str:
    """One workflow command on one line: user text is first made printable
    (:func:`oneline`), then escaped like the Actions toolkit, so no value can
    start a second command."""
    ps = ",".join(f"{k}={gh_escape_property(oneline(v))}" for k, v in props.items() if v is not None and v != "")
    text = "\n".join(oneline(part) for part in str(message).split("\n"))   # our own line breaks stay %0A
    return f"::{kind}{(' ' + ps) if ps else ''}::{gh_escape_data(text)}"


def md_cell(x: object) -> str:
    """A Markdown table cell: one line, ``|`` escaped."""
    return oneline(x).replace("|", "\\|")
