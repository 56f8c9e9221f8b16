"""Printing solved problems in each ``--format`` (the ``solve`` command and
the Python API share it).

The table view goes straight to a terminal (colour, the terminal's width);
anywhere else it is laid out by dyncli's own tables (:mod:`dyncli.render.plain`,
no rich) at ``COLUMNS`` or 100 columns (``--wide``: natural width) and written
without trailing spaces, so a pipe or a file holds the same rows.
"""

from __future__ import annotations

import io
import os
import sys


class _Buffer(io.StringIO):
    """A StringIO that reports stdout's encoding."""

    def __init__(self, encoding: str):
        super().__init__()
        self._encoding = encoding

    @property
    def encoding(self):
        return self._encoding


def _out(file, width, terminal: bool):
    from dyncli.render.out import Out

    return Out(file, width, terminal, getattr(file, "encoding", None) or "utf-8", bool(os.environ.get("NO_COLOR")))


class TableWriter:
    """The terminal view, problem by problem (streamed); with ``sweep``, one
    wide table of rows per problem (:mod:`dyncli.render.sweeptable`),
    printed by :meth:`close`."""

    def __init__(self, digits: int, units: list[str] | None, wide: bool = False, sweep: bool = False):
        from dyncli import stdio

        self.digits, self.units = digits, units
        self.tty = stdio.stdout_is_terminal()
        self.ascii = not stdio.is_utf(sys.stdout)
        self.buf = None if self.tty else _Buffer(getattr(sys.stdout, "encoding", None) or "utf-8")
        self.console = _out(sys.stdout if self.tty else self.buf, stdio.table_width(wide), self.tty)
        self.sweep = None
        if sweep:
            from dyncli.render.sweeptable import SweepTable

            self.sweep = SweepTable(self.console, digits, units)

    def write(self, lp, result) -> None:
        from dyncli import stdio
        from dyncli.render.table import render

        if self.ascii:
            lp, result = _titled(lp, stdio.ascii_text(lp.title)), stdio.ascii_copy(result)
        if self.sweep is not None:
            self.sweep.write(lp, result)
            return
        if getattr(lp, "swept", None):
            from dyncli.render.view import swept_label

            lp = _titled(lp, lp.title + swept_label(lp.swept, self.digits))
        render(self.console, lp, result, self.digits, self.units)
        self._flush()

    def close(self) -> None:
        if self.sweep is not None:
            self.sweep.close()
            self._flush()

    def _flush(self) -> None:
        from dyncli import stdio

        if self.buf is not None:
            stdio.write_lines(self.buf.getvalue())
            self.buf.seek(0)
            self.buf.truncate()


def table_text(lp, result, digits: int = 6, units: list[str] | None = None) -> str:
    """The terminal view of one problem as plain text at its natural width."""
    from dyncli.render.table import render

    buf = io.StringIO()
    render(_out(buf, None, False), lp, result, digits, units)
    return "\n".join(line.rstrip() for line in buf.getvalue().split("\n"))


def _titled(lp, title: str):
    from dataclasses import replace

    return replace(lp, title=title)


def records(outcomes) -> list[dict]:
    """The JSON/YAML record of every outcome (problem, results, message, exit code)."""
    from dyncli.render.jsonout import problem_record

    return [problem_record(o.problem, o.result, o.message, o.exit_code) for o in outcomes]


def _views(outcomes, digits: int, units: list[str] | None) -> list:
    from dyncli.render.view import build

    return [build(o.problem, o.result, digits, units) for o in outcomes if o.result is not None]


def _json(outcomes, digits, units, long) -> str:
    from dyncli import stdio
    from dyncli.render.jsonout import dumps as jdumps

    return jdumps(records(outcomes), ascii_only=not stdio.is_utf(sys.stdout)) + "\n"


def _yaml(outcomes, digits, units, long) -> str:
    from dyncli import stdio
    from dyncli.render.yamlout import dumps as ydumps

    return ydumps(records(outcomes), allow_unicode=stdio.is_utf(sys.stdout))


def _csv(outcomes, digits, units, long) -> str:
    from dyncli.render.csvout import dumps as cdumps

    return cdumps([(o.problem, o.result, o.message) for o in outcomes], long=long)


def _markdown(outcomes, digits, units, long) -> str:
    from dyncli.render.markdown import markdown

    return markdown(_views(outcomes, digits, units))


def _latex(outcomes, digits, units, long) -> str:
    from dyncli.render.latex import latex

    return latex(_views(outcomes, digits, units))


#: every ``--format`` of ``solve`` with the writer of its whole output, the
#: one list of formats (the CLI's choices are made from it); the table is
#: streamed problem by problem instead (:class:`TableWriter`)
WRITERS = {"table": None, "json": _json, "yaml": _yaml, "csv": _csv, "markdown": _markdown, "latex": _latex}
FORMATS = tuple(WRITERS)


def dumps(fmt: str, outcomes, digits: int = 6, units: list[str] | None = None, long: bool = False) -> str:
    """The whole output of a non-streamed format."""
    write = WRITERS.get(fmt)
    if write is None:
        raise ValueError(fmt)
    return write(outcomes, digits, units, long)


def write_view(draw, output: str | None = None) -> None:
    """A view drawn by ``draw(console)`` (the ``check`` reports): straight
    to a terminal; to a pipe laid out at the tables' width
    (:func:`dyncli.stdio.table_width`), to the file ``output`` at its
    natural width, written without trailing spaces like the tables of
    ``solve``.  OSError from ``output`` propagates."""
    from dyncli import stdio

    if output is None and stdio.stdout_is_terminal():
        draw(_out(sys.stdout, stdio.table_width(), True))
        return
    buf = _Buffer("utf-8" if output else (getattr(sys.stdout, "encoding", None) or "utf-8"))
    draw(_out(buf, None if output else stdio.table_width(), False))
    text = "\n".join(line.rstrip() for line in buf.getvalue().split("\n"))
    if output:
        stdio.write_file(output, text)
    else:
        sys.stdout.write(text)
