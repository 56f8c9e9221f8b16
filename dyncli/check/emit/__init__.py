"""One emitter per output format of ``dyncli check`` (docs/check.md,
"Formats"), in both modes: a module per format (``table``, ``json``,
``junit``, ``github``, ``gradescope``, ``csv``), each with

    render(report: Report) -> str       # the whole report in that format

fed by the same :class:`~dyncli.check.results.Report` whatever the mode
(self-study or graded work); :mod:`~dyncli.check.emit.common` holds what
they share (status words, feedback, the score line, escaping).  The table
also has ``draw(report, console)`` for a terminal, and ``github`` a
``step_summary(report)`` for ``$GITHUB_STEP_SUMMARY``.

:data:`FORMATS` is the one list of formats (the CLI's ``--format`` choices
are made from it); this module imports no emitter until one is asked for.
"""

from __future__ import annotations

import os
from importlib import import_module
from pathlib import Path

FORMATS = ("table", "json", "junit", "github", "gradescope", "csv")
#: formats of graded work only (the gradebook needs a key)
GRADED_ONLY = ("csv",)


class OutputError(Exception):
    """The report could not be written (``-o FILE``): the message says why."""


def emitter(fmt: str):
    """The module of the format ``fmt``."""
    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}")
    return import_module(f"dyncli.check.emit.{fmt}")


def write_text(text: str, output: str | None) -> None:
    """``text`` to ``output`` (atomically: a reader never sees half a report)
    or to stdout; raises :class:`OutputError`."""
    import sys

    if not output:
        sys.stdout.write(text)
        return
    try:
        from dyncli.stdio import write_file

        Path(output).parent.mkdir(parents=True, exist_ok=True)
        write_file(output, text)
    except OSError as exc:
        raise OutputError(f"{output}: cannot write ({exc.strerror})") from None


def write(report, fmt: str, output: str | None = None) -> list[str]:
    """The report in ``fmt`` to ``output`` or stdout (the table straight to a
    terminal); returns warnings to print.  Raises :class:`OutputError`."""
    em = emitter(fmt)
    if fmt == "table":
        from dyncli.render.emit import write_view

        try:
            write_view(lambda console: em.draw(report, console), output)
        except OSError as exc:
            raise OutputError(f"{output}: cannot write ({exc.strerror})") from None
        return []
    write_text(em.render(report), output)
    summary = os.environ.get("GITHUB_STEP_SUMMARY") if fmt == "github" else None
    if summary:
        try:
            with open(summary, "a", encoding="utf-8") as fh:
                fh.write(em.step_summary(report))
        except OSError as exc:
            return [f"warning: cannot write GITHUB_STEP_SUMMARY ({exc.strerror})"]
    return []
