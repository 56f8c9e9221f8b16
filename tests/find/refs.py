"""Independent references for the ``find`` tests (§11): roots, turning points and path lengths
of motions known in closed form, computed in mpmath — never from dyncli.

``crossings(f, a, b)`` lists the sign changes of f on [a, b] refined to the working precision
(a fine sample of a function the test knows exactly, then a bracketed solve: a reference, not
the method under test); ``length(f, turns, a, b)`` is Σ|Δf| between turning points.
"""

from __future__ import annotations

import mpmath as mp

from tests.conftest import lookup, solve_one_text

__all__ = ["crossings", "length", "solve", "entry", "extreme", "Vib"]


def crossings(f, a, b, n: int = 2000, direction: int = 0) -> list:
    """The times in (a, b] where f changes sign (direction +1: from below, -1: from above)."""
    a, b = mp.mpf(a), mp.mpf(b)
    ts = [a + (b - a) * k / n for k in range(n + 1)]
    fs = [f(t) for t in ts]
    out = []
    for t1, t2, f1, f2 in zip(ts, ts[1:], fs, fs[1:]):
        if f1 * f2 < 0 and (direction == 0 or direction * (f2 - f1) > 0):
            out.append(mp.findroot(f, (t1, t2), solver="anderson"))
    return out


def length(f, turns, a, b) -> mp.mpf:
    """Σ|Δf| over [a, b] cut at the turning points ``turns`` (the path length of one coordinate)."""
    a, b = mp.mpf(a), mp.mpf(b)
    knots = [a] + [t for t in turns if a < t < b] + [b]
    return sum(abs(f(y) - f(x)) for x, y in zip(knots, knots[1:]))


def solve(text: str) -> tuple[dict, list[str]]:
    """(results, warnings) of one problem (asserts it solved)."""
    rec = solve_one_text(text)
    return rec["results"], rec["warnings"]


def entry(results: dict, k: int) -> dict:
    """find.k, asserted reached."""
    e = lookup(results, f"find.{k}")
    assert e is not None and e["reached"] is True, e
    return e


def extreme(f, df, a, b, sense: int = 1, n: int = 2000) -> tuple:
    """(time, value, at_end) of the largest (sense +1) or smallest (-1) f on [a, b]: the roots of
    its rate ``df`` inside and the two ends."""
    cands = [(mp.mpf(a), True), (mp.mpf(b), True)] + [(t, False) for t in crossings(df, a, b, n)]
    t, end = max(cands, key=lambda c: sense * f(c[0]))
    return t, f(t), end


class Vib:
    """The exact total response of the base-excited (s0 = 0: free) damped oscillator, in mpmath."""

    def __init__(self, m, k, zeta, y0, v0, s0=0, Om=0):
        wn = mp.sqrt(mp.mpf(k) / m)
        sg = zeta * wn
        self.wn, self.s0, self.Om = wn, mp.mpf(s0), mp.mpf(Om)
        A = mp.matrix([[wn**2 - self.Om**2, 2 * sg * self.Om], [-2 * sg * self.Om, wn**2 - self.Om**2]])
        self.P, self.Q = mp.lu_solve(A, mp.matrix([2 * sg * self.s0 * self.Om, wn**2 * self.s0])) if s0 else (0, 0)
        h0, hv0 = mp.mpf(y0) - self.P, mp.mpf(v0) - self.Om * self.Q
        self.crit = zeta == 1
        if self.crit:
            self.c = (h0, hv0 + wn * h0)
        else:
            d = mp.sqrt(mp.mpc(sg**2 - wn**2))
            self.l1, self.l2 = -sg + d, -sg - d
            c1 = (hv0 - self.l2 * h0) / (self.l1 - self.l2)
            self.c = (c1, h0 - c1)

    def y(self, t):
        t = mp.mpf(t)
        if self.crit:
            h = (self.c[0] + self.c[1] * t) * mp.exp(-self.wn * t)
        else:
            h = mp.re(self.c[0] * mp.exp(self.l1 * t) + self.c[1] * mp.exp(self.l2 * t))
        return h + self.P * mp.cos(self.Om * t) + self.Q * mp.sin(self.Om * t)

    def v(self, t):
        return mp.diff(self.y, t)

    def w(self, t):                                  # x − s − L, the spring's stretch
        return self.y(t) - self.s0 * mp.sin(self.Om * t)

    def wdot(self, t):
        return self.v(t) - self.s0 * self.Om * mp.cos(self.Om * t)
