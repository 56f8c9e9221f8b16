"""Output formats of ``dyncli check``: table (rich), json, junit, github,
gradescope.  Every format shows the expected value only with ``--reveal``."""

from __future__ import annotations

import json
import math
import re
from typing import Any

from dyncli.check.engine import AnswerResult, Report
from dyncli.check.safe import oneline

STATUS_TEXT = {
    "correct": "correct",
    "wrong": "wrong",
    "missing": "missing",
    "unknown": "unknown key",
    "invalid": "invalid",
    "error": "not graded",
}

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


def feedback(a: AnswerResult, reveal: bool) -> str:
    """One line: what is wrong (never the expected value unless ``reveal``)."""
    if a.status == "correct":
        return ""
    msg = oneline(a.message)
    if reveal and a.status in ("wrong", "missing"):
        msg = (msg + "; " if msg else "") + f"expected {fmt_given(a.expected, 10)}"
    return msg


def summary_line(report: Report) -> str:
    c = report.counts()
    total = sum(c.values())
    ok = c.get("correct", 0)
    pct = 100.0 * report.score / report.max_score if report.max_score else 0.0
    parts = [f"score {fmt_points(report.score)}/{fmt_points(report.max_score)} ({pct:.0f}%)",
             f"{ok} of {total} answer{'s' if total != 1 else ''} correct"]
    for k in ("wrong", "missing", "unknown", "invalid", "error"):
        if c.get(k):
            parts.append(f"{c[k]} {STATUS_TEXT[k]}")
    nd = sum(len(f.diagnostics) for f in report.files)
    if nd:
        parts.append(f"{nd} invalid file{'s' if nd != 1 else ''}")
    return ", ".join(parts)


def _where(file: str, line: int | None, col: int | None) -> str:
    return f"{file}:{line}:{col or 1}" if line is not None else file


# ---------------------------------------------------------------------------
# table


def render_table(report: Report, console) -> None:
    from dyncli.render.plain import Table, Text, box

    utf = (console.encoding or "").lower().replace("-", "").startswith("utf")
    ok, bad = ("✓", "✗") if utf else ("+", "x")
    marks = {"correct": (ok, "green"), "wrong": (bad, "red"), "missing": (bad, "red"),
             "unknown": ("?", "yellow"), "invalid": ("!", "magenta"), "error": ("!", "magenta")}
    for fr in report.files:
        for d in fr.diagnostics:
            console.print(Text(oneline(d), style="magenta"))
        for cr in fr.checks:
            head = Text()
            head.append(oneline(fr.file), style="bold")
            head.append(f"  -  {oneline(cr.title)}", style="")
            if cr.problem_file and cr.problem_file != fr.file:
                head.append(f"  ({oneline(cr.problem_file)})", style="dim")
            console.print(head)
            if cr.error is not None:
                console.print(Text(f"  problem not solved: {oneline(cr.error)}", style="magenta"))
            t = Table(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False)
            t.add_column("line", justify="right", style="dim")
            t.add_column("answer")
            t.add_column("", no_wrap=True)
            t.add_column("points", justify="right")
            t.add_column("given", overflow="fold")
            if report.reveal:
                t.add_column("expected", overflow="fold")
            t.add_column("feedback", overflow="fold")
            for a in cr.answers:
                mark, style = marks.get(a.status, ("?", ""))
                row = [str(a.line or ""), Text(oneline(a.key)), Text(f"{mark} {STATUS_TEXT[a.status]}", style=style),
                       f"{fmt_points(a.score)}/{fmt_points(a.points)}", Text(fmt_given(a.given))]
                if report.reveal:
                    row.append(Text(fmt_given(a.expected) if a.status not in ("unknown", "invalid", "error") else ""))
                row.append(Text(oneline(a.message) if a.status != "correct" else ""))
                t.add_row(*row)
            console.print(t)
            console.print(Text(f"  {fmt_points(cr.score)}/{fmt_points(cr.max_score)} points", style="dim"))
            console.print()
    console.print(Text(summary_line(report) + f"; {report.solves} problem{'s' if report.solves != 1 else ''} solved",
                       style="bold"))


# ---------------------------------------------------------------------------
# json


def _round2(x: float | None) -> float | None:
    from dyncli.check.compare import round2

    return round2(x) if x is not None else None


def _num_or_none(x: float | None):
    return x if x is not None and math.isfinite(x) else None


def _given_json(x: Any) -> Any:
    from dyncli.render.jsonout import jsonable

    return jsonable(x)


def to_json(report: Report) -> dict:
    files = []
    for fr in report.files:
        checks = []
        for cr in fr.checks:
            answers = []
            for a in cr.answers:
                rec = {
                    "key": a.key, "status": a.status, "correct": a.correct,
                    "score": a.score, "points": a.points,
                    "given": _given_json(a.given),
                    "line": a.line, "col": a.col,
                    "tolerance": a.tolerance.as_dict(),
                    "relative_error": _num_or_none(a.rel_error if report.reveal else _round2(a.rel_error)),
                    "message": a.message if a.status != "correct" else "",
                }
                if report.reveal and a.status not in ("unknown", "invalid", "error"):
                    # the absolute error, like the expected value, only with --reveal
                    # (for a true 0 it *is* the given value's distance to the answer)
                    rec["absolute_error"] = _num_or_none(a.abs_error)
                    rec["expected"] = _given_json(a.expected)
                answers.append(rec)
            checks.append({
                "index": cr.index, "title": cr.title, "problem_file": cr.problem_file, "type": cr.type,
                "score": cr.score, "max_score": cr.max_score,
                "error": str(cr.error) if cr.error is not None else None,
                "answers": answers,
            })
        files.append({
            "file": fr.file, "title": fr.title, "score": fr.score, "max_score": fr.max_score,
            "exit_code": fr.exit_code,
            "errors": [str(d) for d in fr.diagnostics],
            "checks": checks,
        })
    return {"score": report.score, "max_score": report.max_score, "exit_code": report.exit_code,
            "counts": report.counts(), "solves": report.solves, "files": files}


def json_text(doc: Any) -> str:
    """Indented JSON, no NaN; U+2028/U+2029 escaped too (JSON allows them raw,
    but JavaScript and some log viewers take them for line breaks)."""
    text = json.dumps(doc, indent=2, allow_nan=False, ensure_ascii=False)
    return text.replace("\u2028", "\\u2028").replace("\u2029", "\\u2029") + "\n"


def render_json(report: Report) -> str:
    return json_text(to_json(report))


# ---------------------------------------------------------------------------
# JUnit XML (GitLab / Jenkins / GitHub test reporters)

_XML_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")


def _x(s: Any) -> str:
    """Text safe for XML 1.0 on one line (ElementTree escapes markup;
    control characters are shown escaped, the rest XML cannot hold dropped)."""
    return _XML_BAD.sub("\ufffd", oneline(s))


def _xbody(lines: list[str]) -> str:
    """A JUnit failure body: each line made safe (and kept on its line) by :func:`_x`,
    joined by real newlines."""
    return "\n".join(_x(line) for line in lines)


def render_junit(report: Report) -> str:
    import xml.etree.ElementTree as ET

    root = ET.Element("testsuites", name="dyncli check")
    t_all = f_all = e_all = 0
    for fr in report.files:
        suite = ET.SubElement(root, "testsuite", name=_x(fr.file))
        props = ET.SubElement(suite, "properties")
        ET.SubElement(props, "property", name="score", value=fmt_points(fr.score))
        ET.SubElement(props, "property", name="max_score", value=fmt_points(fr.max_score))
        tests = fails = errs = 0
        for d in fr.diagnostics:
            tc = ET.SubElement(suite, "testcase", classname=_x(fr.file), name="answer file", file=_x(d.file), time="0")
            if d.line is not None:
                tc.set("line", str(d.line))
            el = ET.SubElement(tc, "error", message=_x(str(d)), type="invalid-file")
            el.text = _x(str(d))
            tests += 1
            errs += 1
        for cr in fr.checks:
            for a in cr.answers:
                tc = ET.SubElement(suite, "testcase", classname=_x(cr.title), name=_x(a.key), file=_x(fr.file), time="0")
                if a.line is not None:
                    tc.set("line", str(a.line))
                tests += 1
                if a.status == "correct":
                    continue
                text = feedback(a, report.reveal)
                where = _where(fr.file, a.line, a.col)
                msg = f"{a.key}: {STATUS_TEXT[a.status]}" + (f": {text}" if text else "")
                body = [f"{where}: {msg}", f"points: {fmt_points(a.score)}/{fmt_points(a.points)}",
                        f"given: {fmt_given(a.given)}", f"tolerance: {a.tolerance.describe()}"]
                if a.status in ("invalid", "error"):
                    el = ET.SubElement(tc, "error", message=_x(msg), type=a.status)
                    errs += 1
                else:
                    el = ET.SubElement(tc, "failure", message=_x(msg), type=a.status)
                    fails += 1
                el.text = _xbody(body)
        suite.set("tests", str(tests))
        suite.set("failures", str(fails))
        suite.set("errors", str(errs))
        suite.set("skipped", "0")
        suite.set("time", "0")
        out = ET.SubElement(suite, "system-out")
        out.text = _x(f"score {fmt_points(fr.score)}/{fmt_points(fr.max_score)}")
        t_all += tests
        f_all += fails
        e_all += errs
    root.set("tests", str(t_all))
    root.set("failures", str(f_all))
    root.set("errors", str(e_all))
    root.set("time", "0")
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


# ---------------------------------------------------------------------------
# GitHub Actions workflow commands


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


def _problems(report: Report) -> list[tuple[str, int | None, int | None, str, str]]:
    """Everything to annotate: (file, line, col, title, message)."""
    out = []
    for fr in report.files:
        for d in fr.diagnostics:
            out.append((d.file, d.line, d.col, "invalid answer file", d.message if not d.path else f"{d.path}: {d.message}"))
        for cr in fr.checks:
            if cr.error is not None:
                d = cr.error
                out.append((d.file or fr.file, d.line, d.col, f"problem not solved: {cr.title}",
                            d.message if not d.path else f"{d.path}: {d.message}"))
            for a in cr.answers:
                if a.status == "correct" or a.status == "error":
                    continue
                title = f"{a.key}: {STATUS_TEXT[a.status]} ({fmt_points(a.score)}/{fmt_points(a.points)})"
                out.append((fr.file, a.line, a.col, title, feedback(a, report.reveal) or STATUS_TEXT[a.status]))
    return out


def render_github(report: Report) -> str:
    lines = []
    items = _problems(report)
    for file, line, col, title, msg in items[:GITHUB_MAX_ERRORS]:
        f = file if file not in ("<stdin>", "") else None
        lines.append(gh_command("error", msg, file=f, line=line if f else None, col=col if f else None, title=title))
    rest = items[GITHUB_MAX_ERRORS:]
    if rest:
        listed = "\n".join(oneline(f"{_where(f, l, c)}: {t}: {m}") for f, l, c, t, m in rest)
        lines.append(gh_command("notice", f"{len(rest)} more not annotated (GitHub shows at most "
                                          f"{GITHUB_MAX_ERRORS} error annotations per step):\n{listed}",
                                title=f"dyncli check: {len(rest)} more"))
    lines.append(gh_command("notice", summary_line(report), title="dyncli check score"))
    return "\n".join(lines) + "\n"


def md_cell(x: object) -> str:
    """A Markdown table cell: one line, ``|`` escaped."""
    return oneline(x).replace("|", "\\|")


def markdown_table(title: str, summary: str, header: tuple, rows: list[tuple]) -> str:
    """The $GITHUB_STEP_SUMMARY table of both modes (cells already escaped)."""
    out = [f"### {title}", "", summary, "", "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out) + "\n"


def step_summary_markdown(report: Report) -> str:
    """A Markdown table for $GITHUB_STEP_SUMMARY."""
    rows = []
    for fr in report.files:
        for d in fr.diagnostics:
            rows.append((md_cell(fr.file), "—", "invalid file", "0", md_cell(d)))
        for cr in fr.checks:
            for a in cr.answers:
                rows.append((md_cell(fr.file + (f":{a.line}" if a.line else "")), f"`{md_cell(a.key)}`",
                             STATUS_TEXT[a.status], f"{fmt_points(a.score)}/{fmt_points(a.points)}",
                             md_cell(feedback(a, report.reveal))))
    return markdown_table("dyncli check", summary_line(report), ("file", "answer", "status", "points", "feedback"), rows)


# ---------------------------------------------------------------------------
# Gradescope results.json


def render_gradescope(report: Report) -> str:
    tests = []
    multi = len(report.files) > 1
    for fr in report.files:
        for d in fr.diagnostics:
            tests.append({"name": f"{fr.file}: answer file", "score": 0, "max_score": 0, "status": "failed",
                          "output": str(d)})
        for cr in fr.checks:
            for a in cr.answers:
                name = f"{cr.title}: {a.key}"
                if multi:
                    name = f"{fr.file}: {name}"
                out = STATUS_TEXT[a.status]
                text = feedback(a, report.reveal)
                if a.status != "correct":
                    out += f": {text}" if text else ""
                    out += f"\nline {a.line} of {fr.file}; given {fmt_given(a.given)}; tolerance {a.tolerance.describe()}"
                tests.append({"name": name, "score": a.score, "max_score": a.points,
                              "status": "passed" if a.correct else "failed", "output": out})
    doc = {"score": report.score, "output": summary_line(report), "tests": tests}
    return json_text(doc)
