"""The body of ``dyncli check`` in self-study (the CLI only parses options
and calls :func:`run_check`) and ``--write-key``.  Diagnostics go to
stderr; stdout (or ``--output``) holds only the chosen format, written by
the emitters both modes share (:mod:`dyncli.check.emit`)."""

from __future__ import annotations

import sys
from pathlib import Path

from dyncli.check.safe import say

FORMATS = ("table", "json", "junit", "github", "gradescope")   # self-study: every format but the gradebook


def run_check(files: list[str], fmt: str = "table", reveal: bool = False, output: str | None = None,
              write_key: bool = False, debug: bool = False, root: str | None = None) -> int:
    if write_key:
        return _write_key(files, output)
    if sum(1 for f in files if f == "-") > 1:
        say("'-' (stdin) can be given only once")
        return 2
    from dyncli.check.selfstudy import SelfStudy

    report = SelfStudy(reveal=reveal, root=Path(root).resolve() if root else None).check_paths(files)
    for s in report.submissions:       # diagnostics on stderr for every format
        for d in s.diagnostics:
            say(d)
        for g in s.groups:
            if g.error is not None:
                named = f" ({g.title})" if g.title != f"check #{g.index}" else ""
                say(f"{s.file}: check #{g.index}{named}: problem not solved: {g.error}")
                if g.trace and debug:
                    print(g.trace, file=sys.stderr)   # our own traceback (--debug): several lines
            for q in g.questions:
                if q.status == "invalid":
                    say(f"{s.file}:{q.line}:{q.col}: answers.{q.answer}: {q.message}")
    return emit_report(report, fmt, output)


def emit_report(report, fmt: str, output: str | None) -> int:
    """The report in ``fmt`` (then, but for the table, the score on stderr): its exit code, 2 when it cannot be written."""
    from dyncli.check import emit
    from dyncli.check.emit.common import summary_line

    try:
        for w in emit.write(report, fmt, output):
            say(w)
    except emit.OutputError as exc:
        say(exc)
        return 2
    if fmt != "table":
        say(summary_line(report))
    return report.exit_code


def _write_key(files: list[str], output: str | None) -> int:
    from dyncli.check import emit
    from dyncli.check.key import write_key

    key_dir = Path(output).parent if output else Path.cwd()
    text, messages, code = write_key(files, key_dir)
    for m in messages:
        say(m)
    if text:
        try:
            emit.write_text(text, output)
        except emit.OutputError as exc:
            say(exc)
            return 2
    return code
