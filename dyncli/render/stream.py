"""``--format json|yaml|csv`` written while a sweep or a batch is solved.

:class:`RecordStream` takes each outcome as it is solved and writes its
record at once (JSON, YAML), so memory stays flat in the number of points
and the first record reaches the output before the last point is solved.
The bytes are those of the whole-output writers (:mod:`dyncli.render.emit`).
CSV needs every row's columns before its header: the rows go to a temporary
file (flat memory) and are written at the end.
"""

from __future__ import annotations

import csv
import json
import sys
import tempfile
from typing import Any


#: characters written at once: a record's pieces are joined up to this size (one write call, not
#: one per piece: ~1 µs each), never the whole of a record of 1e5 times (~70 MB)
CHUNK = 1 << 20


def _write_joined(parts: list[str]) -> None:
    """``parts`` to stdout in order, joined into writes of about :data:`CHUNK` characters."""
    write = sys.stdout.write
    if sum(map(len, parts)) < CHUNK:                # (a sweep point's record: one write)
        write("".join(parts))
        return
    buf: list[str] = []
    size = 0
    for p in parts:
        if len(p) >= CHUNK:                         # a long series' text: written as it is (not copied)
            if buf:
                write("".join(buf))
                buf, size = [], 0
            write(p)
            continue
        buf.append(p)
        size += len(p)
        if size >= CHUNK:
            write("".join(buf))
            buf, size = [], 0
    if buf:
        write("".join(buf))


class RecordStream:
    def __init__(self, fmt: str, long: bool = False):
        from dyncli import stdio

        self.fmt, self.long, self.n = fmt, long, 0
        self.utf = stdio.is_utf(sys.stdout)
        self.columns: dict[str, None] = {}
        self.spill: Any = tempfile.TemporaryFile("w+", encoding="utf-8") if fmt == "csv" else None
        self.errors = False

    def add(self, o) -> None:
        """One outcome (problem, result or None, message, exit code)."""
        if self.fmt == "csv":
            from dyncli.render.csvout import rows_of

            for row in rows_of(o.problem, o.result, o.message, self.long):
                for k in row:
                    if k != "error":
                        self.columns.setdefault(k, None)
                self.errors = self.errors or "error" in row
                self.spill.write(json.dumps(row) + "\n")
            return
        from dyncli.render.jsonout import problem_record

        seen: dict = {}                         # (the lists checked once, not again when written)
        rec = problem_record(o.problem, o.result, o.message, o.exit_code, seen)
        if self.fmt == "json":
            from dyncli.render.jsonout import encode_parts

            _write_joined(["[\n  " if self.n == 0 else ",\n  "] + encode_parts(rec, "  ", not self.utf, seen))
        else:
            from dyncli.render.yamlout import dumps

            sys.stdout.write(dumps([rec], allow_unicode=self.utf))
        self.n += 1

    def close(self) -> None:
        if self.fmt == "json":
            sys.stdout.write("[]\n" if self.n == 0 else "\n]\n")
        elif self.fmt == "yaml" and self.n == 0:
            sys.stdout.write("[]\n")
        elif self.fmt == "csv":
            self._csv()

    def _csv(self) -> None:
        from dyncli.render.csvout import cell

        if self.errors:
            self.columns["error"] = None
        w = csv.writer(sys.stdout, lineterminator="\n")
        w.writerow([cell(c) for c in self.columns])
        self.spill.seek(0)
        for line in self.spill:
            r = json.loads(line)
            w.writerow([cell(r.get(c, "")) for c in self.columns])
        self.spill.close()
