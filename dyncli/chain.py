"""Chained problems: a ``params`` entry taken from another problem's result in the same file.

    problems:
      - type: impact            # problem 0: the bullet strikes the block
        ...
      - type: constrained-particle
        params:
          v1: {from: 0, result: vA2.0, unit: m/s}   # problem 0's result vA2.0, checked to be a velocity
        ...

Rules (each refusal is exit 2 naming the field):

* ``from`` is the index of an **earlier** problem of the same ``problems:`` list: the file is solved
  in order, so a later one (a forward reference) and the problem itself (a cycle) are refused;
  chains run as deep as the list.
* ``result`` is a dotted result path as in answer keys (``vA2.0``, ``find.0.t``,
  ``steady.0.omega``): it must name one number of the source's results (a vector is refused
  with the paths of its components; ``null`` is refused with the source's reason).
* ``unit`` (optional) is checked against the result's declared unit: the same dimension and SI
  scale (params hold SI values), else refused.
* a source that fails (exit 1, 2 or 3) fails its chained problems with the same code.

A chained problem is validated when it is solved (its parameter's value is known only then);
``dyncli validate`` checks the chain itself.  Sweeps (``overrides.expand``) link each point of a
chained problem to the source's point with the same swept values (a sweep of the source's field
alone makes one chained point per source point).  This module knows nothing of any topic.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from typing import Any

from dyncli.errors import InputError

KEYS = ("from", "result", "unit")
_PATH = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*(\.([A-Za-z_][A-Za-z0-9_]*|\d+))*$")


@dataclass(frozen=True)
class Link:
    name: str          # the params name
    source: int        # index of the source problem in the file's list
    path: str          # dotted result path
    unit: str | None


class Failure(Exception):
    """The chained value cannot be had: exit ``code`` with ``message``."""

    def __init__(self, code: int, message: str):
        super().__init__(message)
        self.code, self.message = code, message


def links(raw: Any) -> dict[str, Link]:
    """The chained entries of a problem's ``params`` (mappings), checked for shape; InputError."""
    params = raw.get("params") if isinstance(raw, dict) else None
    if not isinstance(params, dict):
        return {}
    out = {}
    for name, v in params.items():
        if not isinstance(v, dict):
            continue
        where = f"params.{name}"
        for k in v:
            if k not in KEYS:
                from dyncli.expr import did_you_mean

                raise InputError(f"unknown key {str(k)!r}{did_you_mean(str(k), KEYS)}: a parameter taken from "
                                 "another problem is {from: INDEX, result: PATH} (optional unit)", f"{where}.{k}")
        if "from" not in v or "result" not in v:
            raise InputError("a parameter taken from another problem's result needs from (the problem's index in "
                             "this file) and result (a dotted result path such as vA2.0), e.g. "
                             "{from: 0, result: vA2.0}", where)
        src, path, unit = v["from"], v["result"], v.get("unit")
        if isinstance(src, bool) or not isinstance(src, int) or src < 0:
            raise InputError(f"from must be the index (0, 1, ...) of an earlier problem of this file, got {src!r}",
                             f"{where}.from")
        if not isinstance(path, str) or not _PATH.match(path):
            raise InputError(f"result must be a dotted result path such as vA2.0 or find.0.t, got {path!r}",
                             f"{where}.result")
        if unit is not None and not (isinstance(unit, str) and unit.strip()):
            raise InputError(f"unit must be a unit such as m/s, got {unit!r}", f"{where}.unit")
        out[str(name)] = Link(str(name), src, path, unit.strip() if unit else None)
    return out


def check(lp, found: dict[str, Link]) -> None:
    """Order: every link names an earlier problem of the same list (InputError naming ``from``)."""
    count = _count(lp)
    for ln in found.values():
        where = f"params.{ln.name}.from"
        if count is None:
            raise InputError("a parameter taken from another problem's result needs a file of several problems "
                             "(problems: [...]); this file holds one", where)
        if ln.source >= count:
            raise InputError(f"there is no problem {ln.source}: this file holds {count} (0-{count - 1})", where)
        if ln.source == lp.index:
            raise InputError(f"problem {lp.index} cannot take a parameter from its own results (a cycle)", where)
        if ln.source > lp.index:
            raise InputError(f"problem {ln.source} comes after this one (problem {lp.index}): a forward reference; "
                             "the problems are solved in order, so list the source first", where)


def _count(lp) -> int | None:
    items = items_of(lp)
    return None if items is None else len(items)


def items_of(lp):
    """The ``problems:`` list of the file ``lp`` came from (None for a single problem)."""
    data = lp.doc.data if lp.doc is not None else None
    if len(lp.prefix) == 2 and isinstance(data, dict) and isinstance(data.get("problems"), list):
        return data["problems"]
    return None


# ------------------------------------------------------------------ sweeps

def link(problems: list) -> list:
    """Each chained problem linked to its source's copy at the same sweep point; a chained problem
    whose source was swept (and it was not) is repeated once per compatible source point."""
    by_index: dict[tuple, list] = {}
    out = []
    for lp in problems:
        copies = [lp]
        for ln in (lp.chain or {}).values():
            sources = by_index.get((lp.file, id(lp.doc), ln.source), [])
            nxt = []
            for c in copies:
                match = [s for s in sources if _compatible(c.swept, s.swept)]
                if not match:
                    nxt.append(c)
                    continue
                for s in match:
                    nxt.append(replace(c, swept={**s.swept, **c.swept}, sources={**c.sources, ln.source: s}))
            copies = nxt
        by_index.setdefault((lp.file, id(lp.doc), lp.index), []).extend(copies)
        out += copies
    return out


def _compatible(a: dict, b: dict) -> bool:
    return all(a[k] == v for k, v in b.items() if k in a)
