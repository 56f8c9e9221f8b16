"""A course roster (docs/check.md, "A whole course"): a CSV file with a
``student`` column (the variant ids); other columns are kept for the
gradebook.  ``dyncli variant KEY --roster roster.csv -o sheets/`` writes
one sheet per student in one process, the units of the answers solved once.
"""

from __future__ import annotations

import hashlib
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

from dyncli.check.safe import oneline, shown
from dyncli.stdio import write_file

MAX_ROSTER = 100_000
MAX_ROSTER_BYTES = 20_000_000
_UNSAFE = re.compile(r"[^A-Za-z0-9@._+-]")


class RosterError(ValueError):
    """An unreadable roster (exit 2); the message names the file and line."""


@dataclass
class Roster:
    file: str
    students: list[str] = field(default_factory=list)
    columns: list[str] = field(default_factory=list)           # the other columns, in file order
    extra: dict[str, dict[str, str]] = field(default_factory=dict)   # student -> {column: value}



def read_roster(name: str) -> Roster:
    import csv
    import io

    from dyncli.expr import did_you_mean

    try:
        raw = Path(name).read_bytes()
    except OSError as exc:
        raise RosterError(f"{name}: cannot read the roster ({exc.strerror})") from None
    if len(raw) > MAX_ROSTER_BYTES:
        raise RosterError(f"{name}: the roster is larger than {MAX_ROSTER_BYTES // 1_000_000} MB")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise RosterError(f"{name}: the roster is not UTF-8 text (save it as CSV UTF-8)") from None
    rows = csv.reader(io.StringIO(text, newline=""))
    header = next(rows, None)
    if not header:
        raise RosterError(f"{name}: the roster is empty: expected a CSV header with a 'student' column")
    header = [h.strip() for h in header]
    if "student" not in header:
        raise RosterError(f"{name}:1: no 'student' column{did_you_mean('student', header)} (the header has "
                          f"{', '.join(shown(h) for h in header[:10])}): name the column of the student ids "
                          "'student'")
    col = header.index("student")
    r = Roster(name, columns=[h for i, h in enumerate(header) if i != col and h])
    for line, row in enumerate(rows, 2):
        if not any(c.strip() for c in row):
            continue
        sid = row[col].strip() if col < len(row) else ""
        if not sid or oneline(sid) != sid or len(sid) > 200:
            raise RosterError(f"{name}:{line}: student: expected the student's id (printable text, at most 200 "
                              "characters)")
        if sid in r.extra:
            raise RosterError(f"{name}:{line}: student '{shown(sid)}' is listed twice")
        if len(r.students) >= MAX_ROSTER:
            raise RosterError(f"{name}: more than {MAX_ROSTER} students")
        r.students.append(sid)
        r.extra[sid] = {h: (row[i].strip() if i < len(row) else "") for i, h in enumerate(header) if i != col and h}
    if not r.students:
        raise RosterError(f"{name}: the roster lists no student")
    return r


def file_stem(student: str) -> str:
    """A file name for a student id: the id itself when it is made of
    letters, digits and @ . _ + - (and does not start with a dot); else the
    id with those characters replaced by '_' and 8 hex digits of its hash,
    so two ids never share a file."""
    stem = _UNSAFE.sub("_", student)
    if stem == student and not stem.startswith(".") and stem:
        return stem
    digest = hashlib.sha256(student.encode("utf-8")).hexdigest()[:8]
    return f"{stem.lstrip('.')[:80] or 'student'}-{digest}"


SUFFIX = {"yaml": ".yaml", "markdown": ".md", "html": ".html"}


def write_sheets(key_name: str, roster_name: str, outdir: str, fmt: str = "yaml", template: bool = False,
                 root: str | None = None) -> int:
    """One sheet (or empty submission) per roster student in ``outdir``."""
    from dyncli.check.keycommand import load_key
    from dyncli.check.safe import say
    from dyncli.check.grader import Grader
    from dyncli.check.sheet import render_template, sheet
    from dyncli.check.sheetview import render
    from dyncli.check.variants import VariantError

    try:
        roster = read_roster(roster_name)
    except RosterError as exc:
        say(exc)
        return 2
    key, files = load_key(key_name, root)
    if key is None:
        return 2
    out = Path(outdir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        say(f"{outdir}: cannot create the folder ({exc.strerror})")
        return 2
    grader = Grader(key, files)
    cache: dict = {}
    suffix = ".yaml" if template else SUFFIX[fmt]
    for sid in roster.students:
        try:
            text = render_template(key, grader, sid, cache) if template else render(key, sheet(key, grader, sid,
                                                                                               cache), fmt)
        except VariantError as exc:
            say(f"{key.file}: {exc}")
            return 2
        target = out / (file_stem(sid) + suffix)
        try:
            write_file(str(target), text)
        except OSError as exc:
            say(f"{target}: cannot write ({exc.strerror})")
            return 2
    n = len(roster.students)
    print(f"wrote {n} {'submission template' if template else 'sheet'}{'s' if n != 1 else ''} to {oneline(outdir)} "
          f"({files.solves} problem variant{'s' if files.solves != 1 else ''} solved)", file=sys.stderr)
    return 0
