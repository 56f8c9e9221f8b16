"""Plain-float versions of the numpy functions the derivative jets call
(:mod:`dyncli.expr.jet`), with numpy's conventions for values out of range
instead of Python's exceptions: inf on overflow, ±inf for x/0, nan for a domain error
(sqrt of a negative number, sin(inf), asin(2), a negative base to a fractional power).
So the closed forms of a problem at its few times need no numpy, and give what the arrays
give.  Standard library only.

>>> div(1.0, -0.0), div(0.0, 0.0), sqrt(-1.0), exp(1000.0), power(-8.0, 1 / 3), power(-0.0, -1.0)
(-inf, nan, nan, inf, nan, -inf)
"""

from __future__ import annotations

import math

nan, inf = math.nan, math.inf


def div(a: float, b: float) -> float:
    """a/b; ±inf (the sign of a/b) or nan where b = 0."""
    try:
        return a / b
    except ZeroDivisionError:
        if a == 0.0 or math.isnan(a):
            return nan
        return math.copysign(inf, a) * math.copysign(1.0, b)


def _odd(b: float) -> bool:
    return math.isfinite(b) and b == math.floor(b) and math.fmod(b, 2.0) != 0.0


def power(a: float, b: float) -> float:
    """a**b as C's pow: inf on overflow, nan for a negative base to a non-integer power.

    >>> power(2.0, 10.0), power(-10.0, 401.0), power(0.0, -2.0)
    (1024.0, -inf, inf)
    """
    if b == 0.5:                           # numpy's power takes the square root here (sqrt(−inf) is nan)
        return sqrt(a)
    try:
        return math.pow(a, b)
    except OverflowError:
        return -inf if (a < 0 and _odd(b)) else inf
    except ValueError:
        if a == 0.0:                       # 0 to a negative power: a pole
            return math.copysign(inf, a) if _odd(b) else inf
        return nan


def _total(fn, odd: bool = False):
    """fn, with nan for a domain error and inf on overflow (with the sign of x if fn is odd)."""
    def g(x: float) -> float:
        try:
            return fn(x)
        except ValueError:
            return nan
        except OverflowError:
            return math.copysign(inf, x) if odd else inf
    g.__name__ = fn.__name__
    return g


sin, cos, tan = _total(math.sin), _total(math.cos), _total(math.tan)
arcsin, arccos, arctan = _total(math.asin), _total(math.acos), math.atan
sinh, cosh, tanh = _total(math.sinh, odd=True), _total(math.cosh), math.tanh
exp = _total(math.exp)
arctan2 = math.atan2
fabs = abs


def log(x: float) -> float:
    """ln x: −inf at 0, nan below."""
    if x == 0.0:
        return -inf
    return math.log(x) if x > 0 else nan


def sqrt(x: float) -> float:
    """√x: nan below 0 (−0.0 stays −0.0)."""
    return math.sqrt(x) if not x < 0 else nan


def sign(x: float) -> float:
    """−1, 0 or 1 (nan for nan), as numpy's sign."""
    if x > 0:
        return 1.0
    if x < 0:
        return -1.0
    return 0.0 if x == 0 else nan


def where(cond: bool, a: float, b: float) -> float:
    return a if cond else b


def ones(t: float) -> float:
    return 1.0


def zeros(t: float) -> float:
    return 0.0


f64 = float
