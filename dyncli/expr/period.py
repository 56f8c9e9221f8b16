"""The exact period of expressions in one variable, read from the IR (no sampling): an expression
is periodic in ``var`` when ``var`` enters it only through ``sin``, ``cos`` or ``tan`` of an affine
argument a·var + b (a constant), whatever is built on top of those (sums, products, powers,
any function); its angular frequencies are the |a| (2|a| for ``tan``, π-periodic), and several
expressions share the period 2π/g, g the greatest common divisor of all their frequencies as the
exact rationals the doubles are.  A curve given without ``q_range`` whose coordinates share a
period is a closed curve (constrained-particle: the energy route over one period).

>>> from dyncli.expr import parse
>>> round(common_period([parse("R*sin(q)", ("q",), {"R": 0.5}), parse("-cos(2*q)", ("q",))], "q"), 9)
6.283185307
>>> common_period([parse("q*cos(q)", ("q",))], "q") is None
True
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Iterable

from dyncli.expr.evaluate import uses

#: the most oscillations of the fastest frequency one common period may hold (frequencies whose
#: ratio is a rational of large terms, 1 and 1.1 as doubles, have no useful common period)
MAX_OSCILLATIONS = 64


def _affine(n: tuple, var: str) -> tuple[float, float] | None:
    """(a, b) with n = a·var + b, or None when n is not affine in var."""
    from dyncli.expr.evaluate import fold

    if not uses(n, var):
        return 0.0, fold(n)
    k = n[0]
    if k == "var":
        return 1.0, 0.0
    if k == "neg":
        got = _affine(n[1], var)
        return None if got is None else (-got[0], -got[1])
    if k in ("add", "sub"):
        x, y = _affine(n[1], var), _affine(n[2], var)
        if x is None or y is None:
            return None
        s = 1.0 if k == "add" else -1.0
        return x[0] + s * y[0], x[1] + s * y[1]
    if k == "mul":
        x, y = _affine(n[1], var), _affine(n[2], var)
        if x is None or y is None or (x[0] and y[0]):
            return None
        return (x[0] * y[1], x[1] * y[1]) if x[0] else (y[0] * x[1], x[1] * y[1])
    if k == "div":
        x, y = _affine(n[1], var), _affine(n[2], var)
        if x is None or y is None or y[0] or not y[1]:
            return None
        return x[0] / y[1], x[1] / y[1]
    return None


def frequencies(n: tuple, var: str) -> set[float] | None:
    """The angular frequencies (in var) of the node: an empty set for a constant, None when it is
    not provably periodic."""
    if not uses(n, var):
        return set()
    k = n[0]
    if k == "var":
        return None
    if k == "call" and n[1] in ("sin", "cos", "tan") and len(n[2]) == 1:
        aff = _affine(n[2][0], var)
        if aff is not None:
            a = abs(aff[0])
            if not (a > 0 and math.isfinite(a)):
                return set() if a == 0 else None
            return {2 * a if n[1] == "tan" else a}
    children = n[2] if k == "call" else n[1:]
    out: set[float] = set()
    for c in children:
        got = frequencies(c, var)
        if got is None:
            return None
        out |= got
    return out


def common_period(exprs: Iterable, var: str) -> float | None:
    """A common period in ``var`` of the expressions (the least one of their frequencies: sin(q)²
    is given 2π, not π) (dyncli Expr objects or numbers), or
    None when one is not provably periodic, none depends on var, or the period holds more than
    MAX_OSCILLATIONS of the fastest frequency."""
    freqs: set[float] = set()
    for e in exprs:
        ir = getattr(e, "ir", None)
        if ir is None:
            continue                        # a number: constant
        got = frequencies(ir, var)
        if got is None:
            return None
        freqs |= got
    if not freqs:
        return None
    fr = [Fraction(f) for f in freqs]
    g = fr[0]
    for f in fr[1:]:
        g = Fraction(math.gcd(g.numerator * f.denominator, f.numerator * g.denominator), g.denominator * f.denominator)
    period = 2 * math.pi / float(g)
    if period * max(freqs) / (2 * math.pi) > MAX_OSCILLATIONS:
        return None
    return period
