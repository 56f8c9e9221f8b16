"""Exact decisions at the boundary of a classification (regime, case, yes/no result).

The rule (documented in docs/expressions.md, "Exact inputs and boundaries"):

* every number of a problem file is a double; a decision is made in exact
  rational arithmetic (:class:`fractions.Fraction`) of those doubles, never
  from a rounded intermediate such as ζ = c/(2√k√m);
* each given number is allowed an uncertainty of ``INPUT_ROUNDING`` =
  4 units of round-off (4·2⁻⁵³ = 2⁻⁵¹ ≈ 4.4e-16 relative) — the largest
  error of a short expression evaluated in doubles (``2*sqrt(k*m)``,
  ``sqrt(4*k*m)``, ``2*sqrt(k)*sqrt(m)``, ``2*m*sqrt(k/m)``: at most 2.5
  round-offs each).  When the quantity that decides the class is zero to
  within what that uncertainty can change, the boundary class is reported
  (critical damping, no approach, a double root ...).

So ``c: 20`` with ``m: 2, k: 50`` (c² = 4km exactly) and ``c: 2*sqrt(k*m)``
for any k, m are critical, while a c one part in 10¹⁵ away from 2√(km) is
not.  Pure Python, no imports beyond the standard library.
"""

from __future__ import annotations

import math
from fractions import Fraction

INPUT_ROUNDING = 2.0 ** -51     # 4 round-offs u = 2^-53: the uncertainty of one given number


def fr(x) -> Fraction:
    """The exact rational value of a double (or int)."""
    return Fraction(x)


def cmp_sqrt(x: float, square, rel: float = INPUT_ROUNDING) -> int:
    """Compare x >= 0 with √square (square >= 0, a double or Fraction) exactly:
    0 when |x − √square| <= rel·√square, else the sign of x − √square.

    Decided as (1−rel)²·square <= x² <= (1+rel)²·square in rational
    arithmetic, so no square root is rounded.  A float test comes first: when
    x² and square differ by more than 1e-9 relative (a million times the
    rounding of either and of rel), the exact test could only agree, so the
    rational arithmetic is done only near the boundary."""
    quick = _quick_cmp_sqrt(x, square, rel)
    if quick is not None:
        return quick
    xq, sq, r = fr(x), fr(square), fr(rel)
    x2 = xq * xq
    if x2 < (1 - r) ** 2 * sq:
        return -1
    if x2 > (1 + r) ** 2 * sq:
        return 1
    return 0


_FLOAT_SAFE = (1e-140, 1e140)     # x² and square stay normal doubles in this range


def _quick_cmp_sqrt(x, square, rel):
    """The sign of x − √square from doubles when it is far from the boundary, else None."""
    if rel > 1e-12 or type(x) is not float:
        return None
    try:
        sq = float(square)
    except OverflowError:
        return None
    lo, hi = _FLOAT_SAFE
    if not (lo < x < hi and lo * lo < sq < hi * hi):
        return None
    x2 = x * x                       # relative error <= 2^-53; float(square) likewise
    if x2 > sq * (1.0 + 1e-9):
        return 1
    if x2 < sq * (1.0 - 1e-9):
        return -1
    return None


def _quick_approach(vA, vB, n, rel):
    """The sign of (vA − vB)·n from doubles when far from 0, else None: the float
    sum differs from the exact one by at most a few round-offs of
    S = Σ(|vAᵢ| + |vBᵢ|)|nᵢ|, so |d| > 1e-9·S decides it (rel·S << 1e-9·S)."""
    if rel > 1e-12:
        return None
    try:
        d = sum((float(a) - float(b)) * float(c) for a, b, c in zip(vA, vB, n))
        size = sum((abs(float(a)) + abs(float(b))) * abs(float(c)) for a, b, c in zip(vA, vB, n))
    except (TypeError, OverflowError):
        return None
    if not (1e-250 < size < 1e300) or not math.isfinite(d):
        return None
    if d > 1e-9 * size:
        return 1
    if d < -1e-9 * size:
        return -1
    return None


def sign_within(value, bound) -> int:
    """Sign of an exact value, 0 when |value| <= bound (both exact or doubles)."""
    v, b = fr(value), fr(bound)
    if v > b:
        return 1
    if v < -b:
        return -1
    return 0


def approach_sign(vA, vB, n, rel: float = INPUT_ROUNDING) -> int:
    """Sign of (vA − vB)·n, exact; 0 when within what ``rel`` in every given
    component can change: 2·rel·Σ(|vAᵢ| + |vBᵢ|)|nᵢ|."""
    quick = _quick_approach(vA, vB, n, rel)
    if quick is not None:
        return quick
    d = sum((fr(a) - fr(b)) * fr(c) for a, b, c in zip(vA, vB, n))
    bound = 2 * fr(rel) * sum((abs(fr(a)) + abs(fr(b))) * abs(fr(c)) for a, b, c in zip(vA, vB, n))
    return sign_within(d, bound)
