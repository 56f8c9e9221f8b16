"""A phase τ = λt + τ0 reduced modulo its period P in double-double arithmetic (issue 28).

An elliptic solution is a function of a phase τ = λt + τ0 that is periodic in P.  Formed
in doubles, τ carries an absolute error of ~ε·λt (λ itself is known to ε relative, the product
and the reduction modulo P round once more): at λt = 1e7 rad that is 1e-9 of the motion, whatever
the elliptic functions do afterwards.  Here the frequency f = λ/P (periods per unit t) and the
offset c = τ0/P are held as double-double pairs (hi + lo, |lo| ≤ ulp(hi)/2), made once by the
caller from a high-precision λ and P (:func:`pair`), and f·t is formed exactly by an error-free
product (TwoProd: ``math.fma`` where Python has it, 3.13+, else Dekker's split), so that the
whole periods n and the fraction φ ∈ [−½, ½] of f·t + c come out with an absolute error of a
few ε, and the reduced phase r = φ·P with ~ε·P — as if t were a small time.

Written once for a float t (plain floats, no numpy) and for an array (numpy: the same
operations element by element; Dekker's split there).  Neutral (no topic).

>>> ph = ReducedPhase(pair(0.125), pair(0.25), 2.0)
>>> ph.reduce(9.0)           # 0.125 × 9 + 0.25 = 1.375 periods: n = 1, r = 0.375 × 2
(1.0, 0.75)
>>> two_prod(1.0 + 2.0 ** -30, 1.0 - 2.0 ** -30)     # the product and its rounding error, exactly
(1.0, -8.673617379884035e-19)
"""

from __future__ import annotations

import math

#: a reported state whose phase is uncertain by more than this (radians: the same fraction of its
#: oscillation) is warned about — a route whose period is not held exactly (a quadrature's, or a
#: frequency rounded to a double) loses it over enough periods
LOSS = 1e-6

_EPS = 2.0 ** -52


def rounded(rate: float, t: float, u0: float = 0.0, rel: float = 8 * _EPS) -> float:
    """The error of a phase u = rate·t + u0 formed in doubles from a rate known to ``rel``
    (relative: its formula's roundings): |rate·t|·rel + ulp(u).  A Jacobi or circular function's
    slope in its phase is at most 1, so this bounds its error relative to its amplitude.

    >>> rounded(5.0, 1e12) > 1e-3, rounded(5.0, 10.0) < 1e-13
    (True, True)
    """
    u = rate * t + u0
    return abs(rate * t) * rel + math.ulp(u)


#: why a phase loses its digits, by default (a route may say its own, e.g. a period from quadratures)
WHY = ("its phase is formed in doubles, held to about one ulp and its rate's last digits, so a phase "
       "beyond ~1e9 costs the answer its digits")


def worst_loss(rels, limit: float = LOSS) -> tuple[int, int] | None:
    """(the index of the largest of ``rels`` above ``limit``, how many are above it), or None:
    the worst reported time of a loss of digits (relative errors, one per time).

    >>> worst_loss([1e-9, 3e-6, 2e-5, 1e-7])
    (2, 2)
    """
    worst, count = None, 0
    for k, e in enumerate(rels):
        if e > limit:
            count += 1
            if worst is None or e > rels[worst]:
                worst = k
    return None if worst is None else (worst, count)


def lost_at(count: int, n: int) -> str:
    """The warnings' note of how many of the n reported times lost digits (none for one)."""
    return f" (digits lost at {count} of the {n} reported times)" if count > 1 else ""


def warn_lost(res, times, errs, what: str, why: str = WHY) -> float:
    """Warn once (naming the worst time and how many) when a reported time's phase error ``errs[i]``
    (radians, or the same fraction of the oscillation) exceeds :data:`LOSS`; the largest error."""
    hit = worst_loss(errs)
    if hit is not None:
        k, count = hit
        t, e = times[k], errs[k]
        how = "has no correct digits" if e >= 1.0 else f"has a phase error up to {e:.2g}"
        msg = f"{what} at t = {t:g} s {how}{lost_at(count, len(times))}: {why}; ask for a smaller t"
        res.warn(msg)
        extra = getattr(res, "extra", None)
        if extra is not None:           # (for a find search that solves again at its answers' times)
            extra["phase_lost"] = msg
    return max(errs, default=0.0)


#: Dekker's splitter for doubles, 2^27 + 1
_SPLIT = 134217729.0
_FMA = getattr(math, "fma", None)


def _split(a):
    """a = hi + lo with hi holding the upper 26 bits (Dekker); floats or arrays."""
    c = _SPLIT * a
    hi = c - (c - a)
    return hi, a - hi


def two_prod(a, b):
    """(p, e) with p = fl(a·b) and p + e = a·b exactly (TwoProd; |a·b| below ~1e300)."""
    p = a * b
    if _FMA is not None and isinstance(p, float):
        return p, _FMA(a, b, -p)
    ah, al = _split(a)
    bh, bl = _split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def two_sum(a, b):
    """(s, e) with s = fl(a + b) and s + e = a + b exactly (Knuth's TwoSum)."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def pair(x):
    """A number of higher precision (an mpmath mpf, a Fraction, a float) as the double-double
    (hi, lo) nearest it."""
    hi = float(x)
    return hi, float(x - hi) if math.isfinite(hi) else 0.0


def _round(x):
    if isinstance(x, float):
        return float(round(x)) if math.isfinite(x) else x     # (a phase beyond the doubles: nan, as numpy's)
    import numpy as np

    return np.round(x)


class ReducedPhase:
    """f·t + c split into whole periods and the remainder, in double-double (module docstring).

    ``freq`` = λ/P and ``offset`` = τ0/P as (hi, lo) pairs; ``period`` = P (a double: it only
    scales the fraction back, ε relative)."""

    def __init__(self, freq, offset, period: float):
        self.f_hi, self.f_lo = freq
        self.c_hi, self.c_lo = offset
        self.period = float(period)

    def cycles(self, t):
        """(n, φ): the whole periods n (a float holding an integer) and φ ∈ [−½, ½], with
        n + φ = f·t + c to a few ε absolute."""
        p, e = two_prod(self.f_hi, t)
        n = _round(p)
        # p − n is exact (Sterbenz, or n = 0); the small terms are summed once
        frac, err = two_sum(p - n, e + self.f_lo * t + self.c_hi)
        frac = frac + (err + self.c_lo)
        n2 = _round(frac)
        return n + n2, frac - n2

    def reduce(self, t):
        """(n, r): τ(t) = n·P + r with |r| ≤ P/2 (+ rounding), r to ~ε·P absolute."""
        n, phi = self.cycles(t)
        return n, phi * self.period
