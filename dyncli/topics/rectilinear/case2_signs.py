"""Case 2, a = a(t): where a changes sign (the extrema of v, 6.6a) and where the quadratures must
cut, decided exactly (issue #28: never by sampling).

* The critical points of a (the roots of a' = da/dt, its exact derivative, by the sign analysis of
  :func:`dyncli.rootfind.all_roots`: a' at the critical points of its resolved Chebyshev
  interpolant; sign changes and tangencies) split the time axis into pieces on which a is
  monotone, so a has at most one root in each: the signs of a at their ends decide every root
  (a bracketed root search then), a double root of a included (a minimum of a at 1e-20 below
  zero is two roots, not none).  Without a derivative (``min``/``max``) the roots of a itself are
  decided the same way.
* Where a or a' is not finite (all_roots' unresolved cells: a pole, the edge of a domain) the
  motion stops.
* The quadrature panels: the roots, the narrow peaks of a (a pulse narrower than a quarter of the
  gap to the next critical point: panels graded by 4 towards it down to its curvature scale
  sqrt|a/a''|), and a starting table of 64 cells per analysed stretch (only a table: the adaptive
  quadrature refines every panel).

The analysis of a stretch of time is kept (:class:`SignTable`), so that the scan's chunks and the
states at many times analyse each stretch once.
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

from dyncli.rootfind import all_roots, distinct_sorted, roots_in_brackets
from dyncli.topics.rectilinear.constants import EPS
from dyncli.topics.rectilinear.enclose import hidden

TABLE = 64                  # starting panels per analysed stretch (refined by the adaptive quadrature)
BUDGET = 2000               # all_roots' cells per stretch (near a pole of a it halves without end)


def _scale(f, lo: float, hi: float, cells: int) -> float:
    """The largest finite |f| on the Chebyshev nodes of ``cells`` equal cells of [lo, hi]."""
    nodes = (np.linspace(lo, hi, cells + 1)[:-1, None]
             + (hi - lo) / cells * 0.5 * (1 + np.cos(np.pi * (np.arange(33) + 0.5) / 33))[None, :]).ravel()
    with np.errstate(all="ignore"):
        y = np.abs(f(nodes))
    return float(np.max(y[np.isfinite(y)], initial=0.0))


def irs(a) -> tuple:
    """(the IR of a, of da/dt or None) for the enclosures."""
    from dyncli.expr.derivative import d_ir

    try:
        return a.ir, d_ir(a.ir, "t")
    except Exception:                # (no rule: min/max; a recursion too deep)
        return a.ir, None


def derivatives(a, charge: Callable[[int], None] | None = None) -> tuple[Callable | None, Callable | None]:
    """(a', a'') of the expression ``a`` of t as array evaluators, or None where the rules give none
    (``min``/``max``: no sympy here, the roots of a are then decided from a itself).  ``charge(n)``
    is told the work of each call (the points, plus a call's or a scalar call's overhead)."""
    from dyncli.expr import Expr
    from dyncli.expr.derivative import d_ir
    from dyncli.topics.rectilinear.work import CALL, SCALAR

    out: list[Callable | None] = []
    ir = a.ir
    for _ in range(2):
        try:
            ir = d_ir(ir, "t")
        except Exception:            # (no rule: min/max; a recursion too deep)
            out.append(None)
            break
        e = Expr("da/dt", ir, ("t",), frozenset({"t"}))
        out.append(_evaluator(e, charge or (lambda n: None), CALL, SCALAR))
    out += [None] * (2 - len(out))
    return out[0], out[1]


def _evaluator(e, charge, call: int, scalar: int) -> Callable:
    """``e`` of t on an array (one point: the compiled scalar function, ~5 times faster)."""
    fn = e.scalar_fn()

    def f(x):
        x = np.asarray(x, dtype=float)
        if x.size == 1:
            charge(1 + scalar)
            with np.errstate(all="ignore"):
                return np.full(x.shape, float(fn({"t": float(x.ravel()[0])})))
        charge(x.size + call)
        return e.evaluate(t=x)
    return f


class SignTable:
    """The analysis of a(t) over the stretch of time analysed so far (it grows on demand):
    ``roots`` (sign changes of a), ``panels`` (quadrature cuts), ``stops`` (where a is not finite),
    ``unresolved`` (all_roots ran out of cells somewhere: a changes sign too often)."""

    def __init__(self, A: Callable, dA: Callable | None, d2A: Callable | None, irs: tuple = (None, None)):
        self.A, self.dA, self.d2A = A, dA, d2A
        self.ir, self.dir = irs             # the IR of a and of a' (the enclosures), or None
        self.lo = self.hi = math.nan
        self.roots, self.panels, self.stops = np.zeros(0), np.zeros(0), np.zeros(0)
        self.cpts, self.cval = np.zeros(0), np.zeros(0)     # the critical points of a and a there
        self.unresolved = False

    def get(self, lo: float, hi: float):
        """(roots, panels, stops) strictly inside (lo, hi), each ascending."""
        lo, hi = min(lo, hi), max(lo, hi)
        if math.isnan(self.lo):
            self._add(lo, hi)
            self.lo, self.hi = lo, hi
        if lo < self.lo:
            self._add(lo, self.lo)
            self.lo = lo
        if hi > self.hi:
            self._add(self.hi, hi)
            self.hi = hi

        def inside(x):
            return x[(x > lo) & (x < hi)]

        return inside(self.roots), inside(self.panels), inside(self.stops)

    def _add(self, lo: float, hi: float) -> None:
        if not hi > lo:
            return
        roots, panels, stops = self._analyse(lo, hi)
        self.roots = distinct_sorted(np.concatenate([self.roots, roots]))
        self.panels = distinct_sorted(np.concatenate([self.panels, panels]))
        self.stops = distinct_sorted(np.concatenate([self.stops, stops]))

    def variation(self, lo: float, hi: float) -> float:
        """The total variation of a over [lo, hi] (a is monotone between its critical points):
        a quadrature's abscissae are known to eps |t|, so its result only to eps |t| times this."""
        lo, hi = min(lo, hi), max(lo, hi)
        inside = (self.cpts > lo) & (self.cpts < hi)
        ends = self.A(np.array([lo, hi]))
        vals = np.concatenate([[ends[0]], self.cval[inside], [ends[1]]])
        with np.errstate(all="ignore"):
            tv = float(np.sum(np.abs(np.diff(vals[np.isfinite(vals)]))))
        return tv

    def _analyse(self, lo: float, hi: float):
        A, dA = self.A, self.dA
        f = dA if dA is not None else A
        # the floor of rounding at 1e-15 of f's scale S (the largest |f| on the first cells' nodes):
        # where f underflows (the tails of a pulse) its cells are resolved as they are
        crit, touch, bad = all_roots(f, lo, hi, floor=1e-15 * _scale(f, lo, hi, TABLE), budget=BUDGET)
        # where the enclosures of a exceed its samples (a feature narrower than all_roots' first
        # nodes: a pulse 1e-6 of the span wide), all_roots again on the cells that locate it
        leaves, spent = hidden(self.ir, self.dir, A, lo, hi) if self.ir is not None else ([], False)
        self.unresolved = self.unresolved or spent
        fine: list[float] = []      # a leaf's cells all_roots leaves unresolved (at the rounding of a
        for u, v in leaves:         # pulse's tails): their midpoints join the sign analysis
            c2, t2, b2 = all_roots(f, u, v, cells=2, floor=1e-15 * _scale(f, u, v, 2), budget=BUDGET // 10)
            crit, touch, fine = crit + c2, touch + t2, fine + b2
        crit, touch = sorted(set(crit)), sorted(set(touch + [x for x in fine if np.all(np.isfinite(A([x])))]))
        stops: list[float] = []
        spots: list[float] = []     # unresolved cells where a is finite (a pole of a: 1/(t - c), tan t)
        if bad:
            xb = np.array(bad, dtype=float)
            fin = np.isfinite(A(xb)) & (np.isfinite(dA(xb)) if dA is not None else True)
            stops, spots = [float(x) for x in xb[~fin]], [float(x) for x in xb[fin]]
            self.unresolved = self.unresolved or bool(spots)
        if dA is None:              # all_roots decided the roots of a itself
            return np.array(crit, dtype=float), np.array(crit + touch + spots, dtype=float), np.array(stops)
        pts = distinct_sorted(np.array([lo] + crit + touch + spots + [hi], dtype=float))
        ap = A(pts)
        order = np.argsort(np.concatenate([self.cpts, pts[1:-1]]), kind="stable")
        self.cpts = np.concatenate([self.cpts, pts[1:-1]])[order]
        self.cval = np.concatenate([self.cval, ap[1:-1]])[order]
        roots = self._roots(pts, ap, stops)
        table = np.linspace(lo, hi, TABLE + 1)[1:-1]
        cuts = np.array([x for leaf in leaves for x in leaf], dtype=float)
        return roots, np.concatenate([table, roots, spots, cuts, self._graded(pts, ap)]), np.array(stops)

    def _roots(self, pts, ap, stops) -> np.ndarray:
        """The roots of a between consecutive critical points (a monotone there: at most one each;
        a pole where a changes sign is such a root too, the quadrature then finds it not integrable)."""
        ok = np.isfinite(ap)
        nz = [j for j in range(pts.size) if ok[j] and ap[j] != 0]
        out: list[float] = []
        ja: list[int] = []
        for j, k in zip(nz, nz[1:]):
            if (ap[j] > 0) == (ap[k] > 0) or not ok[j:k + 1].all() or any(pts[j] < s < pts[k] for s in stops):
                continue
            if k > j + 1:           # exact zeros between them (a plateau of zeros: where it starts)
                out.append(float(pts[j + 1]))
            else:
                ja.append(j)
        if ja:                      # one vectorised root search over every bracket
            jj = np.array(ja)
            out += [float(x) for x in roots_in_brackets(lambda t, idx: self.A(t), pts[jj], pts[jj + 1], ap[jj], ap[jj + 1])]
        return distinct_sorted(np.array(out, dtype=float))

    def _graded(self, pts, ap) -> np.ndarray:
        """Panel cuts graded by 4 towards each peak of |a| narrower than the gap to its neighbours
        (the curvature scale sqrt|a/a''| there): the panels next to a narrow pulse see it."""
        out: list[float] = []
        if pts.size < 3:
            return np.zeros(0)
        mid = np.arange(1, pts.size - 1)
        with np.errstate(all="ignore"):
            mag = np.abs(ap)
            peak = mid[(mag[mid] >= mag[mid - 1]) & (mag[mid] >= mag[mid + 1]) & (mag[mid] > 0)]
            if not peak.size:
                return np.zeros(0)
            c = pts[peak]
            d2 = self.d2A(c) if self.d2A is not None else np.zeros_like(c)
            w = np.where(np.isfinite(d2) & (d2 != 0), np.sqrt(np.abs(ap[peak] / d2)), 0.0)
        for j, x, wj in zip(peak, c, w):
            gap = min(x - pts[j - 1], pts[j + 1] - x)
            if not (wj < gap / 4):
                continue
            levels = min(int(math.ceil(math.log(gap / max(wj, 4 * EPS * max(abs(x), gap)), 4))) + 1, 24)
            d = gap * 4.0 ** -np.arange(1, levels + 1)
            out += [float(x)] + list(x - d) + list(x + d)
        return np.array(out, dtype=float)
