"""The body of ``dyncli check`` (the CLI only parses options and calls
:func:`run_check`).  Diagnostics go to stderr; stdout (or ``--output``)
holds only the chosen format."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from dyncli.check.safe import say

FORMATS = ("table", "json", "junit", "github", "gradescope")



def run_check(files: list[str], fmt: str = "table", reveal: bool = False, output: str | None = None,
              write_key: bool = False, debug: bool = False, root: str | None = None) -> int:
    if write_key:
        return _write_key(files, output)
    if sum(1 for f in files if f == "-") > 1:
        say("'-' (stdin) can be given only once")
        return 2
    from dyncli.check.engine import Checker
    from dyncli.check import formats

    checker = Checker(reveal=reveal, root=Path(root).resolve() if root else None)
    report = checker.check_paths(files)

    # diagnostics on stderr for every format
    for fr in report.files:
        for d in fr.diagnostics:
            say(str(d))
        for cr in fr.checks:
            if cr.error is not None:
                say(f"{fr.file}: check #{cr.index} ({cr.title}): problem not solved: {cr.error}")
                if cr.trace and debug:
                    print(cr.trace, file=sys.stderr)   # our own traceback (--debug): several lines
            for a in cr.answers:
                if a.status == "invalid":
                    say(f"{fr.file}:{a.line}:{a.col}: answers.{a.key}: {a.message}")

    if fmt == "table":
        from dyncli.render.emit import write_view

        try:
            write_view(lambda console: formats.render_table(report, console), output)
        except OSError as exc:
            say(f"{output}: cannot write ({exc.strerror})")
            return 2
    else:
        text = {
            "json": formats.render_json,
            "junit": formats.render_junit,
            "github": formats.render_github,
            "gradescope": formats.render_gradescope,
        }[fmt](report)
        try:
            _emit(text, output)
        except _OutputError as exc:
            say(str(exc))
            return 2
        if fmt == "github":
            summary = os.environ.get("GITHUB_STEP_SUMMARY")
            if summary:
                try:
                    with open(summary, "a", encoding="utf-8") as fh:
                        fh.write(formats.step_summary_markdown(report))
                except OSError as exc:
                    say(f"warning: cannot write GITHUB_STEP_SUMMARY ({exc.strerror})")
        say(formats.summary_line(report))
    return report.exit_code


def _emit(text: str, output: str | None) -> None:
    if output:
        try:
            from dyncli.stdio import write_file

            Path(output).parent.mkdir(parents=True, exist_ok=True)
            write_file(output, text)            # atomic: a reader never sees half a report
        except OSError as exc:
            raise _OutputError(f"{output}: cannot write ({exc.strerror})") from None
    else:
        sys.stdout.write(text)


class _OutputError(Exception):
    pass


def _write_key(files: list[str], output: str | None) -> int:
    from dyncli.check.key import write_key

    key_dir = Path(output).parent if output else Path.cwd()
    text, messages, code = write_key(files, key_dir)
    for m in messages:
        say(m)
    if text:
        try:
            _emit(text, output)
        except _OutputError as exc:
            say(str(exc))
            return 2
    return code
