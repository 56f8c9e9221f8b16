"""``--format csv`` (docs/cli.md): one row per problem or sweep point.

Columns: ``file,index,type``, the swept paths, then every result flattened
to dotted keys (``vA2.0``, ``find.0.t``, ``I_com.1.2``).  With ``long``, a
problem's series (lists over ``at``) become one row per time with the index
column (``t``), the other results repeated on each row.  Numbers carry full
precision (``repr``), ``true``/``false`` for booleans, an empty cell for
``null``; a failed problem has its message in an ``error`` column.  A text
cell that a spreadsheet would run as a formula (``=``, ``+``, ``-``, ``@``
first) starts with ``'`` (:func:`dyncli.printable.csv_cell`); numbers keep their sign.
"""

from __future__ import annotations

import csv
import io
import math
from typing import Any, Iterable

from dyncli.printable import csv_cell, printable
from dyncli.render.jsonout import jsonable


def flatten(value: Any, prefix: str, out: dict) -> dict:
    """``out[dotted key] = cell text`` for every leaf of ``value`` (numpy
    arrays and scalars, lists, mappings, numbers, strings, booleans, None)."""
    t = type(value)
    if t is float:
        out[prefix] = repr(value) if math.isfinite(value) else ""
    elif t is dict:
        for k, v in value.items():
            flatten(v, f"{prefix}.{k}" if prefix else str(k), out)
    elif t is list or t is tuple:
        for i, v in enumerate(value):
            flatten(v, f"{prefix}.{i}" if prefix else str(i), out)
    elif value is None:
        out[prefix] = ""
    elif t is bool:
        out[prefix] = "true" if value else "false"
    elif t is int or t is str:
        out[prefix] = str(value)
    elif hasattr(value, "tolist"):
        flatten(value.tolist(), prefix, out)
    else:
        j = jsonable(value)
        out[prefix] = "" if j is None else str(j)
    return out


def rows_of(lp, result, error: str | None, long: bool) -> Iterable[dict]:
    """The CSV rows of one outcome as flat mappings column -> text: one row of its results, or with
    ``long`` one per time of its series (the other results repeated); a failed problem one row
    with its ``error``."""
    head = flatten(getattr(lp, "swept", None) or {}, "", {"file": lp.file, "index": str(lp.index), "type": lp.type})
    if result is None:
        yield {**head, "error": (error or "").replace("\n", "; ")}
        return
    results = result.results
    if not (long and result.series):
        yield flatten(results, "", dict(head))
        return
    in_series = {n for s in result.series for n in s.names} | {s.index_result for s in result.series if s.index_result}
    rest = flatten({k: v for k, v in results.items() if k not in in_series}, "", {})
    for index_name, index, names in _same_index(result.series):
        columns = {n: _plain(results.get(n)) for n in names}
        for i, iv in enumerate(index):
            row = flatten(iv, index_name, dict(head))
            for n, vals in columns.items():
                if isinstance(vals, list) and i < len(vals):
                    flatten(vals[i], n, row)
                elif isinstance(vals, dict):          # a mapping of lists over the index (x_motion)
                    flatten({k: v[i] for k, v in vals.items() if isinstance(v, (list, tuple)) and i < len(v)}, n, row)
            row.update(rest)
            yield row


def _same_index(series) -> list[tuple[str, list, list[str]]]:
    """(index name, index, result names) of the series, those over the same
    index merged: one row per time however many tables the terminal view
    splits them into."""
    groups: dict = {}
    for s in series:
        index = s.index.tolist() if hasattr(s.index, "tolist") else list(s.index)
        key: tuple | int = (s.index_name, tuple(index))
        try:
            hash(key)
        except TypeError:                  # an index of lists: a group of its own
            key = id(s)
        groups.setdefault(key, (s.index_name, index, []))[2].extend(s.names)
    return list(groups.values())


def _plain(v):
    """Arrays as lists, also the values of a mapping of lists over the index."""
    if hasattr(v, "tolist"):
        return v.tolist()
    if isinstance(v, dict):
        return {k: (x.tolist() if hasattr(x, "tolist") else x) for k, x in v.items()}
    return v


def cell(text: str) -> str:
    """Every cell (file names, titles, swept text, messages are user text):
    printable, and never read as a formula by a spreadsheet."""
    return csv_cell(printable(text))


def dumps(outcomes: Iterable[tuple], long: bool = False) -> str:
    """``outcomes``: (loaded problem, Result or None, error message or None)."""
    rows = [r for lp, res, err in outcomes for r in rows_of(lp, res, err, long)]
    columns: dict[str, None] = {}
    for r in rows:
        for k in r:
            if k != "error":
                columns.setdefault(k, None)
    if any("error" in r for r in rows):
        columns["error"] = None
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow([cell(c) for c in columns])
    for r in rows:
        w.writerow([cell(r.get(c, "")) for c in columns])
    return buf.getvalue()
