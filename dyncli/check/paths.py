"""Dotted paths into a problem's results (``find.1.t``, ``vA2.0``): following
one, listing them, and "did you mean" for a path that is not there."""

from __future__ import annotations

import re
from typing import Any

from dyncli.check.safe import shown

MAX_PATHS = 5000


def split_key(key: str) -> list[str]:
    return [p for p in str(key).split(".")]


def lookup(results: Any, key: str) -> tuple[bool, Any, str]:
    """Follow a dotted key into ``results``.  Returns (found, value, message)."""
    cur = results
    done: list[str] = []
    for part in split_key(key):
        here = ".".join(done) or "results"
        if isinstance(cur, dict):
            if part in cur:
                cur = cur[part]
            else:
                return False, None, ""
        elif isinstance(cur, list):
            if not re.fullmatch(r"\d+", part):
                return False, None, (f"'{shown(here)}' is a list of {len(cur)} entries: use an index "
                                     f"0-{len(cur) - 1} instead of '{shown(part)}'")
            i = int(part)
            if i >= len(cur):
                return False, None, (f"'{shown(here)}' has {len(cur)} entr{'y' if len(cur) == 1 else 'ies'} "
                                     f"(indices 0-{len(cur) - 1}); there is no index {i}")
            cur = cur[i]
        else:
            return False, None, f"'{shown(here)}' is a single value: it has no entry '{shown(part)}'"
        done.append(part)
    return True, cur, ""


def available_paths(results: Any, limit: int = MAX_PATHS) -> list[str]:
    out: list[str] = []

    def rec(x: Any, prefix: str) -> None:
        if len(out) >= limit:
            return
        if prefix:
            out.append(prefix)
        if isinstance(x, dict):
            for k, v in x.items():
                rec(v, f"{prefix}.{k}" if prefix else str(k))
        elif isinstance(x, list):
            for i, v in enumerate(x):
                rec(v, f"{prefix}.{i}" if prefix else str(i))

    rec(results, "")
    return out


MAX_HINT_CANDIDATES = 60    # "did you mean" compares with at most this many paths
MAX_HINT_KEY = 200          # ... and only for keys up to this length


class PathIndex:
    """The result paths of one solution, indexed once for "did you mean":
    an unknown key is compared with its siblings (same parent path), else
    with paths of its depth under the same first part, at most
    MAX_HINT_CANDIDATES of them — so 200 unknown keys against thousands of
    result paths cost milliseconds."""

    def __init__(self, paths: list[str]):
        self.paths = paths
        self.children: dict[str, list[str]] = {}
        self.by_depth: dict[tuple[str, int], list[str]] = {}
        for p in paths:
            parent, _, _ = p.rpartition(".")
            self.children.setdefault(parent, []).append(p)
            self.by_depth.setdefault((p.split(".", 1)[0], p.count(".")), []).append(p)

    def candidates(self, key: str) -> list[str]:
        parent, _, _ = key.rpartition(".")
        near = self.children.get(parent) or self.by_depth.get((key.split(".", 1)[0], key.count(".")), [])
        return near[:MAX_HINT_CANDIDATES]


def unknown_key_message(results: Any, key: str, index: PathIndex | None = None) -> str:
    from dyncli.expr import did_you_mean

    found, _, msg = lookup(results, key)
    if msg:
        return f"unknown answer key '{shown(key)}': {msg}"
    if len(key) <= MAX_HINT_KEY:
        index = index or PathIndex(available_paths(results))
        hint = did_you_mean(key, index.candidates(key))
        head, dot, rest = key.partition(".")
        if not hint and dot and isinstance(results, dict):   # a misspelled first part: fnd.2.s
            import difflib

            close = difflib.get_close_matches(head, [str(k) for k in results], n=1, cutoff=0.6)
            if close and lookup(results, f"{close[0]}.{rest}")[0]:
                hint = f" (did you mean '{shown(close[0])}.{shown(rest)}'?)"
        if hint:
            return f"unknown answer key '{shown(key)}'{hint}"
    top = ", ".join(str(k) for k in results) if isinstance(results, dict) else ""
    return f"unknown answer key '{shown(key)}'; the results are: {top}"
