"""``--format table`` (the default): a table per graded file (dyncli's own,
:mod:`dyncli.render.plain`: rich draws it only on a terminal), then the
score.  Self-study: a table per check of an answer file (line, answer,
status, points, given, [expected], feedback); graded work: a table per
submission (question, status, points, given, [expected], feedback) with its
answers to no question listed as ``unknown``."""

from __future__ import annotations

from typing import Any

from dyncli.check.emit.common import MARKS, STATUS_TEXT, fmt_given, fmt_points, points, summary_line, who
from dyncli.check.results import Report, SubmissionResult
from dyncli.check.safe import oneline


def render(report: Report) -> str:
    """The table as plain text at its natural width (what a pipe or a file holds)."""
    import io

    from dyncli.render.out import Out

    buf = io.StringIO()
    draw(report, Out(buf, None, no_color=True))
    return "\n".join(line.rstrip() for line in buf.getvalue().split("\n"))


def draw(report: Report, console) -> None:
    from dyncli.render.plain import Text

    utf = (console.encoding or "").lower().replace("-", "").startswith("utf")
    ok, bad = ("✓", "✗") if utf else ("+", "x")
    marks = {k: ({"ok": ok, "bad": bad}.get(m, m), style) for k, (m, style) in MARKS.items()}
    for s in report.submissions:
        if report.graded:
            _submission(report, s, console, marks)
        else:
            _answer_file(report, s, console, marks)
    solved = "problem variant" if report.graded else "problem"
    console.print(Text(summary_line(report) + f"; {report.solves} {solved}{'s' if report.solves != 1 else ''} solved",
                       style="bold"))


def _table(columns: list[tuple[str, dict]]):
    from dyncli.render.plain import Table, box

    t = Table(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False)
    for name, opts in columns:
        t.add_column(name, **opts)
    return t


def _answer_file(report: Report, s: SubmissionResult, console, marks: dict) -> None:
    from dyncli.render.plain import Text

    for d in s.diagnostics:
        console.print(Text(oneline(d), style="magenta"))
    fold = {"overflow": "fold"}
    columns: list[tuple[str, dict[str, Any]]] = [("line", {"justify": "right", "style": "dim"}), ("answer", {}), ("", {"no_wrap": True}),
               ("points", {"justify": "right"}), ("given", fold)]
    columns += [("expected", fold)] * report.reveal + [("feedback", fold)]
    for g in s.groups:
        head = Text()
        head.append(oneline(s.file), style="bold")
        head.append(f"  -  {oneline(g.title)}", style="")
        if g.problem_file and g.problem_file != s.file:
            head.append(f"  ({oneline(g.problem_file)})", style="dim")
        console.print(head)
        if g.error is not None:
            console.print(Text(f"  problem not solved: {oneline(g.error)}", style="magenta"))
        t = _table(columns)
        for q in g.questions:
            mark, style = marks[q.status]
            row = [str(q.line or ""), Text(oneline(q.answer)), Text(f"{mark} {STATUS_TEXT[q.status]}", style=style),
                   points(q), Text(fmt_given(q.given))]
            if report.reveal:
                row.append(Text(fmt_given(q.expected) if q.status not in ("unknown", "invalid", "error") else ""))
            row.append(Text(oneline(q.message) if q.status != "correct" else ""))
            t.add_row(*row)
        console.print(t)
        console.print(Text(f"  {fmt_points(g.score)}/{fmt_points(g.max_score)} points", style="dim"))
        console.print()


def _submission(report: Report, s: SubmissionResult, console, marks: dict) -> None:
    from dyncli.render.plain import Text

    console.print(Text(who(s), style="bold"))
    for d in s.diagnostics:
        console.print(Text("  " + oneline(d), style="magenta"))
    names = ("question", "", "points", "given") + (("expected",) if report.reveal else ()) + ("feedback",)
    t = _table([(n, {"overflow": "fold", "justify": "right" if n == "points" else "left"}) for n in names])
    for q in s.questions:
        mark, style = marks[q.status]
        row = [Text(oneline(q.id)), Text(f"{mark} {STATUS_TEXT[q.status]}", style=style), points(q),
               Text(oneline(fmt_given(q.given)) if q.given is not None else "")]
        if report.reveal:
            row.append(Text(oneline(fmt_given(q.expected, 10)) if q.status != "error" else ""))
        row.append(Text(oneline(q.message)))
        t.add_row(*row)
    for u in s.unknown:
        row = [Text(oneline(u["id"])), Text("? unknown", style="yellow"), "0", Text("")]
        t.add_row(*(row + ([Text("")] if report.reveal else []) + [Text(oneline(u["message"]))]))
    if s.questions or s.unknown:
        console.print(t)
    console.print(Text(f"  {fmt_points(s.score)}/{fmt_points(s.max_score)} points", style="dim"))
    console.print()
