"""The one escaper of user text, for every output format.

Every string a user wrote (a ``title``, a file name, a mapping key, a
``--set`` path, swept text, an expression) may be echoed in a message, a
table, a report or a data file.  Each output format has one function here,
and every renderer passes user text through it:

* :func:`printable` — terminal and stderr: every character that is not
  printable (newline, carriage return, ESC of terminal escape sequences,
  DEL, C1 controls, line and paragraph separators, bidirectional and other
  format characters) is written as its Python escape (``\\n``, ``\\x1b``,
  ``\\u202e``), so a line stays one line — it cannot forge a second
  diagnostic (``file.yaml:1:1: ...``) or drive the terminal.  Printable
  text, non-ASCII letters and symbols included (ω, ², ∞), is unchanged;
* :func:`line` — one stderr message: :func:`printable`, and a line longer
  than :data:`MAX_LINE` characters (a 100,000-character value echoed back)
  shortened by :func:`shorten`;
* :func:`markdown` and :func:`html` — Markdown and HTML text: markup
  (``<script>``, ``<img onerror=...>``, ``|``, ``*``, `` ` ``, ``[``)
  written as text, never as markup;
* :func:`tex` — LaTeX's special characters (``& % $ # _ { } ~ ^ \\``);
* :func:`csv_cell` — a CSV cell that starts with ``=``, ``+``, ``-``, ``@``,
  a tab or a carriage return is prefixed with ``'`` so that a spreadsheet
  reads it as text, not as a formula; a number (``-1.5e-3``) stays a number.
"""

from __future__ import annotations

import html as _html
import re

#: the longest message line written whole; a longer one keeps its start and end
MAX_LINE = 1000
_HEAD, _TAIL = 600, 200

_SHORT = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}


def _escape(ch: str) -> str:
    if ch in _SHORT:
        return _SHORT[ch]
    n = ord(ch)
    return f"\\x{n:02x}" if n < 0x100 else f"\\u{n:04x}" if n < 0x10000 else f"\\U{n:08x}"


def printable(text: object) -> str:
    """``text`` (any object: ``str()`` of it) with every non-printable
    character escaped; the same string when there is none."""
    s = text if isinstance(text, str) else str(text)
    if s.isprintable():
        return s
    return "".join(ch if ch.isprintable() or ch == " " else _escape(ch) for ch in s)


def shorten(text: str, limit: int = MAX_LINE) -> str:
    """``text`` when at most ``limit`` characters; else its start and end with
    ``… [N characters left out] …`` between them (the one rule for long user
    strings in messages)."""
    if len(text) <= limit:
        return text
    head, tail = limit * _HEAD // MAX_LINE, limit * _TAIL // MAX_LINE
    return f"{text[:head]} … [{len(text) - head - tail:,} characters left out] … {text[len(text) - tail:]}"


def line(text: object) -> str:
    """One message line for stderr: printable and at most about MAX_LINE characters."""
    return shorten(printable(text))


def lines(text: object) -> str:
    """A multi-line text (a traceback for --debug): each line as :func:`line`."""
    return "\n".join(line(part) for part in str(text).split("\n"))


# Markdown's inline markup that can act: code spans, emphasis, table cells,
# and a link (``](``: ``[text](url)``); HTML (raw tags, autolinks ``<url>``)
# is escaped as entities.  A line of the output never starts with user text,
# so the block markers (#, -, >, 1.) need no escape; ``_`` and a bracket
# that opens no link are left alone (``v_A``, ``[2, 0, 0]`` read as written).
_MD = re.compile(r"([\\`*|]|\](?=[(\[]))")


def markdown(text: object, breaks: bool = False) -> str:
    """Markdown inline text (a heading, a table cell): printable, HTML
    escaped, Markdown punctuation backslash-escaped.  With ``breaks`` the
    newlines of a multi-row cell (a tensor) become ``<br>``."""
    s = text if isinstance(text, str) else str(text)
    parts = s.split("\n") if breaks else [s]
    return "<br>".join(_MD.sub(r"\\\1", _html.escape(printable(p), quote=True)) for p in parts)


def html(text: object, breaks: bool = False) -> str:
    """HTML text (element content or a quoted attribute): printable, ``< > & " '``
    escaped.  With ``breaks`` the newlines of a multi-row cell become ``<br>``."""
    s = text if isinstance(text, str) else str(text)
    parts = s.split("\n") if breaks else [s]
    return "<br>".join(_html.escape(printable(p), quote=True) for p in parts)


TEX_SPECIAL = {"&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{", "}": r"\}",
               "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "\\": r"\textbackslash{}"}


def tex_char(ch: str) -> str | None:
    """LaTeX text for one ASCII character that needs it (a special character,
    a control character made visible); None for a character written as is."""
    if ch in TEX_SPECIAL:
        return TEX_SPECIAL[ch]
    if not ch.isprintable() and ch != " ":
        return "".join(TEX_SPECIAL.get(c, c) for c in _escape(ch))
    return None


def tex(text: object) -> str:
    """ASCII text as LaTeX text (the notes' symbols: :func:`dyncli.render.latex.tex_text`)."""
    s = text if isinstance(text, str) else str(text)
    return "".join(tex_char(c) or c for c in s)


_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def csv_cell(text: object) -> str:
    """A CSV cell: a text a spreadsheet would run as a formula (first character
    ``= + - @``, tab or carriage return) gets a leading ``'``; a number keeps its sign."""
    s = text if isinstance(text, str) else str(text)
    if s.startswith(_FORMULA_START) and not _NUMBER.fullmatch(s):
        return "'" + s
    return s
