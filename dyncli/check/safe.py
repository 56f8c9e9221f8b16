"""Safe echoing of user text and safe problem references (both modes of
``dyncli check``).

* :func:`oneline`: any text a user wrote (a mapping key, a title, a given
  string) becomes one printable line: control characters (newline, ESC,
  NUL, DEL, the C1 range, Unicode line/paragraph separators) are shown as
  ``\\xNN``/``\\uNNNN`` escapes, so no message can forge a second line
  (``file.yaml:1:1: ...``, ``::error ...``) or a terminal escape sequence.
* :func:`resolve_problem`: a ``problem:`` path from an answer file or a key
  must be a relative ``.yaml``/``.yml`` path without NUL or control
  characters, at most :data:`MAX_REF` characters, and must resolve (after
  symlinks) inside the folder of the file that names it, or inside the
  ``--root`` folder the instructor gives.  Messages quote the reference
  (shortened), never the content of the referenced file.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

MAX_REF = 512
MAX_SHOWN = 80

_CTRL = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029\u200e\u200f\u202a-\u202e\u2066-\u2069]")


def _esc(m: re.Match) -> str:
    c = m.group(0)
    return f"\\x{ord(c):02x}" if ord(c) < 0x100 else f"\\u{ord(c):04x}"


def oneline(text: object) -> str:
    """``text`` as one line of printable characters (control characters escaped)."""
    return _CTRL.sub(_esc, str(text))


def say(msg: object) -> None:
    """One diagnostic line of ``dyncli check`` on stderr, made printable by :func:`oneline`."""
    import sys

    print(oneline(msg), file=sys.stderr)


def yaml_diagnostic(file: str, exc, expected: str):
    """A YAML error (:class:`dyncli.yamlsafe.YamlError`) of a key, submission or
    answer file as its Diagnostic; an empty file says what it should hold."""
    from dyncli.loader import Diagnostic

    msg = exc.message
    if msg.startswith("file is empty"):
        msg = f"file is empty: expected {expected}"
    return Diagnostic(file, exc.line, exc.col, None, msg)


def shown(text: object, limit: int = MAX_SHOWN) -> str:
    """A user string to quote in a message: one line, shortened to ``limit``."""
    s = oneline(text)
    return s if len(s) <= limit else s[: limit - 1] + "…"


class RefError(ValueError):
    """A ``problem:`` reference that may not be opened (exit 2)."""


def resolve_problem(ref: str, base_dir: Path, root: Path | None = None) -> Path:
    """The file a ``problem:`` reference names, or :class:`RefError`."""
    if len(ref) > MAX_REF:
        raise RefError(f"problem path is too long ({len(ref)} characters, at most {MAX_REF})")
    if _CTRL.search(ref):
        raise RefError(f"problem path '{shown(ref)}' holds a control character (NUL, newline...)")
    if Path(ref).is_absolute() or ref.startswith(("~", "\\")) or re.match(r"^[A-Za-z]:", ref):
        raise RefError(f"problem path '{shown(ref)}' is absolute: give a path relative to this file")
    if not ref.lower().endswith((".yaml", ".yml")):
        raise RefError(f"problem path '{shown(ref)}' is not a .yaml/.yml problem file")
    fence = (root or base_dir)
    try:
        fence = fence.resolve()
        target = (base_dir / ref).resolve()
    except (OSError, RuntimeError, ValueError):
        raise RefError(f"problem path '{shown(ref)}' cannot be resolved") from None
    if not _inside(target, fence):
        where = "the --root folder" if root is not None else "the folder of this file"
        raise RefError(f"problem path '{shown(ref)}' leads outside {where} ({_display(fence)}); "
                       "problem files must lie inside it" + ("" if root is not None else
                                                              " (an instructor may widen it with --root DIR)"))
    if not target.is_file():
        what = "is a directory" if target.is_dir() else "not found"
        raise RefError(f"problem file '{shown(ref)}' {what} (looked for {_display(target)}; "
                       "paths are relative to the file that names them)")
    return target


def _inside(path: Path, folder: Path) -> bool:
    try:
        path.relative_to(folder)
    except ValueError:
        return False
    return True


def _display(path: Path) -> str:
    try:
        rel = os.path.relpath(path, Path.cwd())
    except ValueError:  # pragma: no cover - other drive on Windows
        return oneline(path)
    return oneline(path if rel.startswith("..") else rel)


def looks_like_problem_file(data: object) -> bool:
    """Whether parsed YAML is shaped like a problem file (a mapping with a
    known ``type``, or ``problems:`` holding such mappings).  Anything else
    is described without echoing its content."""
    from dyncli import registry

    def one(x: object) -> bool:
        return isinstance(x, dict) and isinstance(x.get("type"), str) and x["type"] in registry.TYPES

    if isinstance(data, dict) and "problems" in data and "type" not in data:
        items = data["problems"]
        return isinstance(items, list) and bool(items) and all(one(x) for x in items)
    return one(data)
