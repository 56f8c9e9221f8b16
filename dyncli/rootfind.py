"""The one bracketed root finder of dyncli (docs/accuracy.md; issue #26): Brent's method in
plain floats, step for step the operations of scipy's ``brentq`` (so a root is the same double),
without importing scipy.optimize (~0.1 s at start-up).  Topic-agnostic: every topic finds its
roots here (the top's nutation cubic, the constrained particle's turning points and
equilibria, the particle's events, rectilinear's legs and crossings), never with scipy's
root finders directly (``tests/test_one_runner.py``)."""

from __future__ import annotations

import math
import sys

#: scipy's defaults and smallest rtol of ``brentq``
XTOL = 2e-12
RTOL = 4 * sys.float_info.epsilon
MAXITER = 100


def brentq(f, a: float, b: float, *, xtol: float = XTOL, rtol: float = RTOL, maxiter: int = MAXITER) -> float:
    """Root of ``f`` in the bracket [a, b] (f(a), f(b) of opposite signs, else ValueError):
    scipy's ``brentq`` with its arguments, its checks and its errors (a NaN value: ValueError;
    ``maxiter`` exhausted: RuntimeError), in plain floats (:func:`brent`).

    >>> brentq(lambda x: x * x - 2.0, 0.0, 2.0) == 2 ** 0.5
    True
    """
    if xtol <= 0:
        raise ValueError(f"xtol too small ({xtol:g} <= 0)")
    if rtol < RTOL:
        raise ValueError(f"rtol too small ({rtol:g} < {RTOL:g})")
    return brent(f, float(a), float(b), xtol, rtol, int(maxiter), signs=True)


def brent(f, xa, xb, xtol, rtol, maxiter, *, signs=False):
    """Root of ``f`` bracketed by [xa, xb] by Brent's method (bisection guarding inverse
    quadratic / secant steps), in plain floats: step for step the operations of scipy's
    ``brentq``, so the root is the same double.  Converged when the bracket half-width is
    below (xtol + rtol|x|)/2.  ``signs``: end values of one sign are refused (ValueError), as
    brentq does (without: the caller guarantees the bracket)."""
    def fx(x):
        y = float(f(x))
        if math.isnan(y):           # as brentq: refused, not iterated on
            raise ValueError(f"The function value at x={x:f} is NaN; solver cannot converge.")
        return y

    xpre, xcur = xa, xb
    fpre, fcur = fx(xpre), fx(xcur)
    if fpre == 0:
        return xpre
    if fcur == 0:
        return xcur
    if signs and math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise ValueError("f(a) and f(b) must have different signs")
    xblk = fblk = spre = scur = 0.0
    for _ in range(maxiter):
        if fpre != 0 and fcur != 0 and (math.copysign(1.0, fpre) != math.copysign(1.0, fcur)):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):           # keep the best estimate in xcur
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0 or abs(sbis) < delta:
            return xcur
        stry = math.nan                     # no interpolation: bisect
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            try:
                if xpre == xblk:            # secant
                    stry = -fcur * (xcur - xpre) / (fcur - fpre)
                else:                       # inverse quadratic
                    dpre = (fpre - fcur) / (xpre - xcur)
                    dblk = (fblk - fcur) / (xblk - xcur)
                    stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            except ZeroDivisionError:       # C's ±inf or nan: the test below fails, so bisect
                pass
        if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):
            spre, scur = scur, stry         # a good short step
        else:                               # bisect
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0 else -delta)
        fcur = fx(xcur)
    raise RuntimeError(f"Failed to converge after {maxiter} iterations, value is {xcur}")   # as brentq


def minimize_bounded(f, lo: float, hi: float, xatol: float):
    """The minimum of ``f`` on [lo, hi] by Brent's bounded method (scipy's
    ``minimize_scalar(method="bounded")``, imported here only, lazily): (x, f(x))."""
    from scipy.optimize import minimize_scalar

    r = minimize_scalar(f, bounds=(lo, hi), method="bounded", options={"xatol": xatol})
    return float(r.x), r.fun
