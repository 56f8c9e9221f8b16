"""Error carried forward, graded fairly and only when earned (docs/check.md).

A question with ``carry: {from: S, param: P}`` is also graded against its
problem re-solved with ``params.P`` set to the student's own answer to S.
Three rules decide whether such a match earns the points:

* **Plausible input** (:func:`in_window`): the student's answer to S must lie
  within a factor :data:`WINDOW` of a value S can have: S's true answer for
  this variant, or — along a chain — the answer that follows from the
  student's own (plausible) earlier answer.  Either sign.  A huge answer
  (``1e9``, ``"1000 km"``) carries nothing: where the carried input dwarfs
  the question's own contribution the tolerance would swallow it.
* **What was typed stands for an interval** (:func:`halfwidth`): ``1.45``
  stands for every value in [1.445, 1.455] (half a unit in its last digit),
  at most the interval of its 3rd significant figure (``1e3`` and ``1000``
  stand for [995, 1005]); an expression (``"2*pi"``) is exact.  The problem
  is re-solved at the interval's ends and at the typed value; an answer
  within the question's tolerance of any of them, or between the ends'
  answers when the three are monotonic (so some value of the interval gives
  it exactly), is ``carried``.
* **The answer shows the question's own physics** (:func:`repeats`): an answer
  within the question's tolerance of the carried input itself (in SI) earns
  no carried credit — it repeats the earlier answer.
"""

from __future__ import annotations

import math
import re
from typing import Any

WINDOW = 10.0          # a carried input within a factor 10 of a value the earlier question can have
CAP_FIGURES = 3        # a typed value stands for at most the rounding interval of its 3rd figure

_LITERAL = re.compile(r"^\s*[+-]?(?P<int>\d*)(?:\.(?P<frac>\d*))?(?:[eE](?P<exp>[+-]?\d+))?\s*(?P<rest>.*)$", re.S)


def in_window(c: float, ref: float | None) -> bool:
    """``c`` within a factor WINDOW of ``ref`` (either sign); never around 0."""
    if ref is None or ref == 0 or not math.isfinite(c) or not math.isfinite(ref):
        return False
    return abs(ref) / WINDOW <= abs(c) <= abs(ref) * WINDOW


def _typed_half_unit(text: str) -> tuple[float, float] | None:
    """(typed number, half a unit in its last significant digit) of a decimal
    literal (optionally followed by a unit), or None for anything else."""
    m = _LITERAL.match(text)
    if not m or not ((m["int"] or "") + (m["frac"] or "")) or len(text) > 64:
        return None
    rest = m["rest"]
    if rest and not (rest[0].isalpha() or rest[0] in "°µ"):
        return None                       # an expression ("2*pi", "3/4"): exact
    exp = int(m["exp"]) if m["exp"] else 0
    if abs(exp) > 400:
        return None
    if m["frac"] is not None:
        last = exp - len(m["frac"])
    else:                                 # 1230: the trailing zeros are not significant
        digits = m["int"] or "0"
        zeros = len(digits) - len(digits.rstrip("0")) if digits.strip("0") else 0
        last = exp + zeros
    try:
        value = float(text[: m.start("rest")].strip())
    except ValueError:
        return None
    return value, 0.5 * 10.0 ** last


def halfwidth(given: Any, written: str | None, c_si: float) -> float:
    """Half-width (SI) of the interval of values the typed answer stands for."""
    text = written if written is not None else given if isinstance(given, str) else \
        repr(given) if isinstance(given, (int, float)) and not isinstance(given, bool) else None
    if text is None:
        return 0.0
    got = _typed_half_unit(str(text))
    if got is None:
        return 0.0
    value, half = got
    if value == 0 or not math.isfinite(value):
        return 0.0
    cap = 0.5 * 10.0 ** (math.floor(math.log10(abs(value))) - (CAP_FIGURES - 1))
    return min(half, cap) * abs(c_si / value)


def repeats(g: float | None, c: float, tol) -> bool:
    """Whether the answer ``g`` (SI) only repeats the carried input ``c``."""
    from dyncli.check.compare import number_ok

    return g is not None and number_ok(g, c, tol)


def between(g: float | None, refs: list[float | None]) -> bool:
    """``g`` between the answers at the interval's ends, the three monotonic."""
    if g is None or len(refs) != 3:
        return False
    lo, mid, hi = refs
    if lo is None or mid is None or hi is None:
        return False
    if not (lo <= mid <= hi or lo >= mid >= hi):
        return False
    return min(lo, hi) <= g <= max(lo, hi)


def nearest_rel(g: float | None, refs: list[float | None]) -> float | None:
    """The smallest relative error of ``g`` from the carried references."""
    rels = [abs(g - r) / abs(r) for r in refs if g is not None and r is not None and r != 0]
    return min(rels) if rels else None
