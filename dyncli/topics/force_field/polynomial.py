"""Sparse polynomials with exact rational coefficients, built from dyncli's expression IR
(no sympy, no text): the exact route of force-field for polynomial fields (notes §19).

A polynomial in the variables ``names`` is a dict ``{exponents: Fraction}`` (no zero
coefficients).  :func:`from_ir` accepts the textbook polynomial: numbers that are
integers (as ``dyncli.expr.to_sympy`` turns them into sympy Integers), the variables,
``+ - *``, division by a non-zero constant and powers with a constant non-negative
integer exponent.  Anything else (a decimal or a constant such as ``pi``, a function,
a division by a variable, a very large degree, term count or coefficient) is
:class:`NotPolynomial`, and the caller keeps the sympy route.

:func:`sstr` prints a polynomial exactly as sympy's ``sstr`` prints its expanded form
(terms in descending lexicographic order of the exponents, the rational coefficient
as ``2*x1*x2/3``, and sympy's one special case: a positive constant and one negative
single-factor term print as ``1 - x1``); the property test
``tests/topics/force_field/test_force_field_polynomial.py`` holds it against sympy.
"""

from __future__ import annotations

import math
from fractions import Fraction

MAX_DEGREE = 40        # of any variable: above it, sympy's route (and its CPU limit)
MAX_TERMS = 400        # of any intermediate product
MAX_PRODUCTS = 20000   # term-by-term products of one multiplication (bounds the time before MAX_TERMS)
MAX_BITS = 1000        # of a coefficient's numerator and denominator (a float's range is 2**1024)
_SAFE_INT = 1e15       # dyncli.expr.to_sympy keeps integers below this exact (Integer), else Float

Poly = dict  # dict[tuple[int, ...], Fraction]


class NotPolynomial(Exception):
    """The expression is not a polynomial of the accepted shape (or is too large)."""


def _check(p: Poly) -> Poly:
    if len(p) > MAX_TERMS:
        raise NotPolynomial("too many terms")
    for m, c in p.items():
        if max(m, default=0) > MAX_DEGREE:
            raise NotPolynomial("degree too large")
        if c.numerator.bit_length() > MAX_BITS or c.denominator.bit_length() > MAX_BITS:
            raise NotPolynomial("coefficient too large")
    return p


def const(c, n: int) -> Poly:
    c = Fraction(c)
    return {(0,) * n: c} if c else {}


def add(p: Poly, q: Poly, sign: int = 1) -> Poly:
    out = dict(p)
    for m, c in q.items():
        v = out.get(m, 0) + sign * c
        if v:
            out[m] = v
        else:
            out.pop(m, None)
    return out


def scale(p: Poly, c) -> Poly:
    return {m: v * c for m, v in p.items()} if c else {}


def mul(p: Poly, q: Poly) -> Poly:
    if len(p) * len(q) > MAX_PRODUCTS:
        raise NotPolynomial("product too large")
    out: Poly = {}
    for m1, c1 in p.items():
        for m2, c2 in q.items():
            m = tuple(a + b for a, b in zip(m1, m2))
            v = out.get(m, 0) + c1 * c2
            if v:
                out[m] = v
            else:
                out.pop(m, None)
    return _check(out)


def _constant_of(p: Poly, n: int):
    """The value of a constant polynomial, or None."""
    if not p:
        return Fraction(0)
    if len(p) == 1 and (0,) * n in p:
        return p[(0,) * n]
    return None


def _power(base: Poly, ex: Poly, n: int) -> Poly:
    e = _constant_of(ex, n)
    if e is None or e.denominator != 1:
        raise NotPolynomial("exponent not an integer constant")
    k = int(e)
    b = _constant_of(base, n)
    if b is not None and k < 0:                     # 2**-1 = 1/2 (sympy: Rational)
        if not b:
            raise NotPolynomial("zero to a negative power")
        if -k > MAX_DEGREE:
            raise NotPolynomial("exponent too large")
        return _check(const(b ** k, n))
    if k < 0 or k > MAX_DEGREE:
        raise NotPolynomial("exponent negative or too large")
    out, sq = const(1, n), base
    while k:                                         # repeated squaring
        if k & 1:
            out = mul(out, sq)
        k >>= 1
        if k:
            sq = mul(sq, sq)
    return out


def _number(v: float, n: int) -> Poly:
    if not (float(v).is_integer() and abs(v) < _SAFE_INT):
        raise NotPolynomial("not an integer literal")
    return const(int(v), n)


def from_ir(ir: tuple, names: tuple[str, ...]) -> Poly:
    """The polynomial of an expression IR in the variables ``names`` (raises NotPolynomial)."""
    n = len(names)

    def conv(node) -> Poly:
        k = node[0]
        if k == "num":
            return _number(node[1], n)
        if k == "param":
            return _number(node[2], n)
        if k == "var":
            if node[1] not in names:
                raise NotPolynomial(f"variable {node[1]}")
            m = [0] * n
            m[names.index(node[1])] = 1
            return {tuple(m): Fraction(1)}
        if k == "neg":
            return scale(conv(node[1]), -1)
        if k in ("add", "sub"):
            return _check(add(conv(node[1]), conv(node[2]), 1 if k == "add" else -1))
        if k == "mul":
            return mul(conv(node[1]), conv(node[2]))
        if k == "div":
            d = _constant_of(conv(node[2]), n)
            if not d:                                 # a variable divisor, or zero
                raise NotPolynomial("division by a variable or by zero")
            return _check(scale(conv(node[1]), 1 / d))
        if k == "pow":
            return _power(conv(node[1]), conv(node[2]), n)
        raise NotPolynomial(f"{k} node")

    try:
        return conv(ir)
    except RecursionError:
        raise NotPolynomial("nested too deeply") from None


def diff(p: Poly, j: int) -> Poly:
    """∂p/∂(variable j), exactly."""
    out: Poly = {}
    for m, c in p.items():
        if m[j]:
            d = list(m)
            d[j] -= 1
            out[tuple(d)] = c * m[j]
    return out


def exact_value(p: Poly, x) -> Fraction:
    """p at the point x (floats, taken at their exact binary values), exactly."""
    xs = [Fraction(float(v)) for v in x]
    return sum((c * math.prod(xi ** e for xi, e in zip(xs, m) if e) for m, c in p.items()), Fraction(0))


def value(p: Poly, x) -> float:
    """p at the point x (floats), computed exactly and rounded once (±inf on overflow)."""
    s = exact_value(p, x)
    try:
        return float(s)
    except OverflowError:
        return math.inf if s > 0 else -math.inf


def values(p: Poly, X):
    """p at many points in floating point (numpy; X has one row per variable)."""
    import numpy as np

    X = np.asarray(X, dtype=float)
    out = np.zeros(X.shape[1:])
    with np.errstate(all="ignore"):
        for m, c in p.items():
            t = np.full(X.shape[1:], float(c))
            for xi, e in zip(X, m):
                if e:
                    t = t * xi ** e
            out = out + t
    return out


# -- sympy's str printer for an expanded polynomial -----------------------------------

def _rational(c: Fraction) -> str:
    return str(c.numerator) if c.denominator == 1 else f"{c.numerator}/{c.denominator}"


def _term(m: tuple, c: Fraction, names: tuple[str, ...]) -> str:
    """sympy's _print_Mul of c * x**m (or _print_Rational of a constant)."""
    factors = [name if e == 1 else f"{name}**{e}" for name, e in zip(names, m) if e]
    if not factors:
        return _rational(c)
    sign = "-" if c < 0 else ""
    c = abs(c)
    num = ([str(c.numerator)] if c.numerator != 1 else []) + factors
    return sign + "*".join(num) + (f"/{c.denominator}" if c.denominator != 1 else "")


def sstr(p: Poly, names: tuple[str, ...]) -> str:
    """``sympy.sstr`` of the expanded polynomial (``names`` in sorted order, as sympy's
    default sort key orders the symbols)."""
    if list(names) != sorted(names):
        raise ValueError("names must be sorted")
    if not p:
        return "0"
    terms = sorted(p.items(), reverse=True)           # descending lex order of the exponents
    zero = (0,) * len(names)
    if len(terms) == 2 and terms[1][0] == zero and terms[1][1] > 0 and terms[0][1] < 0 \
            and sum(1 for e in terms[0][0] if e) == 1:
        terms.reverse()                                # sympy's "1 - x1" (as_ordered_terms)
    out = []
    for m, c in terms:
        t = _term(m, c, names)
        sign, t = ("-", t[1:]) if t.startswith("-") else ("+", t)
        out += [sign, t]
    first = out.pop(0)
    return ("-" if first == "-" else "") + " ".join(out)
