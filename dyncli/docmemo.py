"""The document memo: what depends only on a problem's plain data (its ``params`` resolved,
its ``find`` queries parsed), computed once for the points of a sweep that share it.

A value is remembered under a type-exact fingerprint of the data it was computed from
(``True``, ``1`` and ``1.0`` are three keys, ``0.0`` and ``-0.0`` two; a mapping's keys in their
order), so a swept value that changes a query or a param is another key and is computed
afresh.  Data that is not plain (str, int, float, bool, None, lists, tuples, dicts of them, at
most :data:`DEPTH` deep) is never remembered.  At most :data:`LIMIT` entries (the oldest
dropped first); errors are never remembered (each point raises its own).
"""

from __future__ import annotations

import threading
from typing import Any, Callable, Hashable

LIMIT = 256
DEPTH = 24

_MEMO: dict[Hashable, Any] = {}
_LOCK = threading.Lock()


class Unkeyable(Exception):
    """The data is not plain (or too deep): it has no fingerprint."""


_SCALARS = frozenset({str, int, bool, type(None)})


def fingerprint(x: Any, depth: int = 0) -> Hashable:
    """A hashable, type-exact image of plain data; raises :class:`Unkeyable` otherwise.
    (A container's plain items are imaged in place, the same as :func:`fingerprint` of each:
    a params mapping or a list of numbers costs one call, not one per item.)"""
    t = type(x)
    if t is str or t is int or t is bool or x is None:
        return (t, x)
    if t is float:
        return (t, x.hex())                         # -0.0 and 0.0 apart, a NaN equal to itself
    if depth >= DEPTH:
        raise Unkeyable
    d, scalars = depth + 1, _SCALARS
    if t is list or t is tuple:
        return (t, tuple([(float, v.hex()) if (u := type(v)) is float else (u, v) if u in scalars
                          else fingerprint(v, d) for v in x]))
    if t is dict:
        return (t, tuple([((u, k) if (u := type(k)) in scalars else fingerprint(k, d),
                           (float, v.hex()) if (w := type(v)) is float else (w, v) if w in scalars
                           else fingerprint(v, d)) for k, v in x.items()]))
    raise Unkeyable


def recall(kind: str, data: Any, compute: Callable[[], Any], still: Callable[[Any], bool] | None = None,
           print_: Hashable | None = None) -> Any:
    """``compute()`` for ``data`` (its value remembered under ``kind`` and the fingerprint of
    ``data``, or ``print_`` when the caller made that fingerprint already); ``still(value)``: whether
    a remembered value holds for this call (else computed again).  The caller must not change the
    value it is given (a shared one)."""
    try:
        key = (kind, fingerprint(data) if print_ is None else print_)
    except (Unkeyable, RecursionError):
        return compute()
    got = _MEMO.get(key, _MEMO)
    if got is not _MEMO and (still is None or still(got)):
        return got
    got = compute()
    with _LOCK:
        while len(_MEMO) >= LIMIT:
            _MEMO.pop(next(iter(_MEMO)))
        _MEMO[key] = got
    return got


def size() -> int:
    """How many values are remembered (bounded by :data:`LIMIT`)."""
    return len(_MEMO)
