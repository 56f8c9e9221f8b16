"""Standard output that behaves the same in a terminal, a pipe and a file.

* :func:`setup` (the command's entry) lets a stdout or stderr that cannot
  encode the notes' symbols (``PYTHONIOENCODING=ascii``, a C locale) print
  ASCII spellings instead (``ωₙ`` -> ``omegan``, ``∞`` -> ``inf``); JSON
  escapes them instead (``ensure_ascii``), so it holds the same data;
* writes to stdout are guarded: a closed pipe (``dyncli solve X | head``)
  raises :class:`ClosedPipe` (the command then ends quietly with exit 0), any
  other failure (``> /dev/full``) :class:`OutputFailed` (one line, exit 2);
  :func:`finish` flushes and maps both;
* :func:`table_width`: the terminal's width in a terminal, else
  :data:`DEFAULT_WIDTH` (100) columns, or the tables' natural width with
  ``--wide``; ``COLUMNS`` is honoured when it holds a number of at least
  :data:`MIN_COLUMNS` (a narrower width could show no value: it is treated
  as unknown);
* :func:`write_file`: a whole output file (``-o FILE``) written atomically —
  a reader or a concurrent run sees the old file or the new one, never a
  part of one.
"""

from __future__ import annotations

import codecs
import os
import re
import sys
import unicodedata

NATURAL_WIDTH = 100_000
#: the width of the tables off a terminal when ``COLUMNS`` does not say (``--wide``: natural width)
DEFAULT_WIDTH = 100
#: a COLUMNS (or terminal) narrower than this is unusable for the tables
#: (values would be cut to "…"): treated as unknown
MIN_COLUMNS = 40

ASCII = {"∞": "inf", "−": "-", "—": "-", "–": "-", "·": "*", "×": "x", "≈": "~", "′": "'", "″": "''",
         "…": "...", "°": "deg", "∥": "||", "→": "->", "≤": "<=", "≥": ">=", "±": "+-", "∂": "d",
         "√": "sqrt", "ℓ": "l", "∫": "int", "∇": "nabla", "⊥": "_|_", "‘": "'", "’": "'", "“": '"', "”": '"',
         "│": "|", "─": "-", "┌": "+", "┐": "+", "└": "+", "┘": "+", "├": "+", "┤": "+", "┬": "+", "┴": "+",
         "┼": "+", "━": "-", "╸": "-", "§": "sec ", "⊗": "(x)", "∠": "angle", "½": "1/2", "◀": "<", "⁄": "/", "\u00a0": " "}


class ClosedPipe(Exception):
    """stdout's reader went away (``| head``): not an error."""


class OutputFailed(Exception):
    """stdout cannot be written (a full disk, an I/O error)."""

    def __init__(self, exc: OSError):
        super().__init__(exc.strerror or str(exc))
        self.exc = exc


def ascii_spelling(ch: str) -> str:
    """An ASCII spelling of one character (Greek letters by name)."""
    if ch in ASCII:
        return ASCII[ch]
    m = re.match(r"GREEK (SMALL|CAPITAL) LETTER (\w+)$", unicodedata.name(ch, ""))
    if m:
        word = m.group(2).lower()
        return word if m.group(1) == "SMALL" else word.capitalize()
    if ch in _ACCENTS:
        return _ACCENTS[ch]
    base = unicodedata.normalize("NFKD", ch)
    if base != ch:
        name = unicodedata.name(ch, "")
        mark = "_" if "SUBSCRIPT" in name else "^" if "SUPERSCRIPT" in name else ""
        return mark + "".join(ascii_spelling(c) if ord(c) >= 128 else c for c in base)
    return "" if unicodedata.combining(ch) else "?"


_ACCENTS = {"\u0307": "dot", "\u0308": "ddot", "\u0302": "hat", "\u0304": "bar"}


def ascii_text(s: str) -> str:
    """``ωₙ`` -> ``omega_n``, ``θ̇`` -> ``thetadot``, ``∞`` -> ``inf``."""
    if s.isascii():
        return s
    return "".join(c if ord(c) < 128 else ascii_spelling(c) for c in unicodedata.normalize("NFD", s))


def ascii_copy(x, skip: tuple = ("plots", "extra")):
    """A copy of strings, lists, mappings and dataclasses (a Result, its
    views) with every string in ASCII spelling, so a table is laid out with
    the characters that will be printed."""
    import dataclasses

    if isinstance(x, str):
        return ascii_text(x)
    if isinstance(x, (list, tuple)):
        return type(x)(ascii_copy(v, skip) for v in x)
    if isinstance(x, dict):
        return {ascii_copy(k, skip): ascii_copy(v, skip) for k, v in x.items()}
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        return dataclasses.replace(x, **{f.name: ascii_copy(getattr(x, f.name), skip)
                                         for f in dataclasses.fields(x) if f.init and f.name not in skip})
    return x


def _fallback(err: UnicodeError):
    if not isinstance(err, UnicodeEncodeError):  # pragma: no cover - encoding only
        raise err
    return ascii_text(err.object[err.start:err.end]), err.end


codecs.register_error("dyncli-ascii", _fallback)


def is_utf(stream) -> bool:
    enc = getattr(stream, "encoding", None) or ""
    try:
        return codecs.lookup(enc).name.startswith("utf")
    except LookupError:
        return False


class _Guard:
    """A proxy of sys.stdout whose write/flush failures are ClosedPipe or
    OutputFailed (exceptions click does not turn into its own exit 1)."""

    def __init__(self, stream):
        self._stream = stream

    def _call(self, fn, *args):
        try:
            return fn(*args)
        except BrokenPipeError:
            raise ClosedPipe() from None
        except OSError as exc:
            raise OutputFailed(exc) from None

    def write(self, s):
        return self._call(self._stream.write, s)

    def flush(self):
        return self._call(self._stream.flush)

    def __getattr__(self, name):
        return getattr(self._stream, name)


def setup() -> None:
    for name in ("stdout", "stderr"):
        stream = getattr(sys, name)
        if stream is not None and not is_utf(stream) and hasattr(stream, "reconfigure"):
            try:
                stream.reconfigure(errors="dyncli-ascii")
            except (ValueError, OSError):  # pragma: no cover - defensive
                pass
    if sys.stdout is not None and not isinstance(sys.stdout, _Guard):
        sys.stdout = _Guard(sys.stdout)


def _stdout_fd() -> int:
    """The file descriptor of the interpreter's stdout (AttributeError when there is none)."""
    if sys.__stdout__ is None:
        raise AttributeError("sys.__stdout__ is None")
    return sys.__stdout__.fileno()


def _discard_stdout() -> None:
    """Point fd 1 at /dev/null so the interpreter's last flush cannot fail."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, _stdout_fd())
    except (OSError, AttributeError, ValueError):  # pragma: no cover - defensive
        pass


def finish(code: int, exc: BaseException | None = None) -> int:
    """Flush stdout; the exit code after a closed pipe (0) or a failed write (2)."""
    try:
        if exc is not None:
            raise exc
        if sys.stdout is not None:
            sys.stdout.flush()
    except ClosedPipe:
        _discard_stdout()
        return 0
    except OutputFailed as failed:
        _discard_stdout()
        print(f"dyncli: cannot write the output: {failed}", file=sys.stderr)
        return 2
    return code


def table_width(wide: bool = False) -> int | None:
    """The tables' width: None (their natural width) with ``--wide``; else
    COLUMNS when it is a usable width; else the terminal's width (when at
    least MIN_COLUMNS, else 80) in a terminal, DEFAULT_WIDTH elsewhere."""
    if wide:
        return None
    cols = os.environ.get("COLUMNS", "").strip()
    if cols.isdigit() and MIN_COLUMNS <= int(cols) < NATURAL_WIDTH:
        return int(cols)
    if stdout_is_terminal():
        try:
            width = os.get_terminal_size(_stdout_fd()).columns
        except (OSError, AttributeError, ValueError):
            return 80
        return width if width >= MIN_COLUMNS else 80
    return DEFAULT_WIDTH


def write_file(path: str, text: str) -> None:
    """Write ``text`` (UTF-8) to ``path`` atomically: a temporary file in the
    same directory, flushed to disk, then renamed over ``path``
    (``os.replace``).  OSError propagates; the temporary file is removed."""
    import tempfile

    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=".dyncli-", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        try:
            os.chmod(tmp, 0o666 & ~_umask())
        except OSError:  # pragma: no cover - a file system without modes
            pass
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def stdout_is_terminal() -> bool:
    """Whether stdout is a terminal (False for a pipe, a file, or a stream that cannot say)."""
    try:
        return bool(sys.stdout.isatty())
    except (AttributeError, ValueError):
        return False


def write_lines(text: str) -> None:
    """Write ``text`` with the trailing spaces of every line removed."""
    sys.stdout.write("\n".join(line.rstrip() for line in text.split("\n")))
