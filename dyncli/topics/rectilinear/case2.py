"""Case 2, a = a(t): quadrature (6.6a,b).

    v(t) = v1 + ∫_{t1}^{t} a(τ) dτ                                   (6.6a)
    s(t) = s1 + (t - t1) v1 + ∫_{t1}^{t} (t - τ) a(τ) dτ              (6.6b)

The second form is (6.6b) with the inner integral of (6.6a) exchanged
(Cauchy's formula), so every value costs one quadrature, never a nested one;
both hold for t < t1 too (backward queries).

v- and s-queries: the extrema of v are the zeros of a (cheap to sample), so v
is monotone between them; the extrema of s are the zeros of v, found inside the
monotone pieces of v.  Scanning these pieces in time order gives the first
crossing by a bracketed root search on the quadrature, and a target equal to
an extremum (grazing, no sign change) is found at the extremum itself.
Root searches integrate from the nearest point where the state is already
known (a bracket end or an earlier iterate), so each step costs a quadrature
over a shrinking interval only.

Work budget (:mod:`.work`): every evaluation of a is counted, plus the Python
overhead of each call; one solve may do at most ``STEP`` · ``accuracy.max_steps``
evaluations' worth, else NumericalError (exit 1): ~0.3-0.7 s of CPU.  One quadrature
refines at most ``_MAX_PANELS`` panels: an integrand it cannot resolve (an
oscillation without bound near a pole of tan inside a) is accepted with its
error estimate and a warning, and a non-integrable pole (1/(t - c)) ends the
motion there like a non-finite a.

This module holds the quadratures of the state and the root searches (:class:`_Case2`); the
forward scan that answers the v- and s-queries with them is its collaborator
:class:`.case2_scan.Scan`.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import replace
from typing import Any

import numpy as np

from dyncli.rootfind import distinct_sorted, root_in_bracket
from dyncli.topics.rectilinear._quad import NonFinite, integrate
from dyncli.topics.rectilinear.case2_scan import Scan, nonfinite_reason
from dyncli.topics.rectilinear.case2_signs import SignTable, derivatives, irs
from dyncli.topics.rectilinear.constants import EPS, fmt
from dyncli.topics.rectilinear.work import CALL as _CALL, QUAD as _QUAD, SCALAR as _SCALAR, Work

_MAX_PANELS = 4000          # panels one quadrature may evaluate before it gives up refining


class _Case2:
    """The quadratures of one case-2 motion (the state at any time from a known one, the root
    searches of s and v) and its t queries; the interface :class:`.case2_scan.Quadratures` that
    its scan reads."""

    def __init__(self, p, ans, rtol, atol):
        self.p = p
        self.ans = ans
        self.qr = max(rtol * 1e-2, 1e-15)
        self.qa = atol * 1e-2
        self.rtol, self.atol = rtol, atol
        self.a = p.a
        self._fn = p.a.scalar_fn()
        self.warned_conv = False
        self.work = Work(p, 2)
        self.info: dict = {}
        self._bad_xs: list[float] = []  # where quadratures failed to converge
        self._nbad = 0
        self.signs = SignTable(self.A, *derivatives(p.a, self._charge), irs=irs(p.a))

    def _charge(self, n: int) -> None:
        self.work.charge(n, f" (hardest near t = {fmt(self.info['x_bad'])})" if "x_bad" in self.info else "")

    def A(self, x):
        x = np.asarray(x, dtype=float)
        self._charge(x.size + _CALL)
        return self.a.evaluate(t=x)

    def a1(self, x: float) -> float:
        self._charge(_SCALAR)
        return float(self._fn({'t': x}))

    def integrate(self, f, lo, width):
        self._charge(_QUAD)
        return integrate(f, lo, width, self.qr, self.qa, max_panels=_MAX_PANELS, info=self.info)

    def check(self, conv) -> None:
        """Count a quadrature that did not converge (where), and warn about the first."""
        if not np.all(conv) and "x_bad" in self.info:
            self._nbad += 1
            if len(self._bad_xs) < 64:
                self._bad_xs.append(self.info["x_bad"])
        if not np.all(conv) and not self.warned_conv:
            self.warned_conv = True
            where = f" (near t = {fmt(self.info['x_bad'])})" if "x_bad" in self.info else ""
            self.ans.res.warn(f"quadrature did not reach the requested tolerance everywhere{where}: a is not smooth "
                              "or oscillates faster than the quadrature resolves; see error_estimate")

    # state at T from a base state (tb, sb, vb): two integrals, one call
    def state(self, T: float, tb: float, sb: float, vb: float):
        h = T - tb
        if h == 0:
            return sb, vb, 0.0, 0.0

        def f(x, j):
            ax = self.A(x)
            return np.where(j == 0, ax, (T - x) * ax)

        vals, errs, conv = self.integrate(f, [tb, tb], [h, h])
        self.check(conv)
        return sb + vb * h + vals[1], vb + vals[0], errs[1], errs[0]

    def state_split(self, T: float, tb: float, sb: float, vb: float):
        """As :meth:`state`, with the integrals split at the sign changes of a and at the panels of
        its exact analysis (:mod:`.case2_signs`): a pole where a changes sign (1/(t - c), tan t)
        then lies at the end of a piece, where the quadrature sees that the integral does not
        exist, instead of cancelling symmetrically to a principal value; a narrow pulse of a peaks
        at a panel end (one adaptive quadrature over [0, 10] saw none of a = exp(−((t − 5)/0.01)²):
        v(10) was 1e-293 instead of 0.0177; issue 28).  NonFinite where a is not finite."""
        if T == tb:
            return sb, vb, 0.0, 0.0
        roots, panels, stops = self.signs.get(tb, T)
        if stops.size:
            raise NonFinite(float(stops[0] if T > tb else stops[-1]), 0)
        s, v, es, ev = self.state_on(T, tb, sb, vb, np.concatenate([roots, panels]))
        r = self.rounding(tb, T)
        return s, v, es + r * abs(T - tb), ev + r

    def rounding(self, lo: float, hi: float) -> float:
        """The error of v's quadratures over [lo, hi] from the rounding of their abscissae (t known
        to eps |t|: eps |t| times the total variation of a; a narrow pulse far from t = 0)."""
        return EPS * max(abs(lo), abs(hi)) * self.signs.variation(lo, hi)

    def state_on(self, T: float, tb: float, sb: float, vb: float, cuts):
        """The state at T from (tb, sb, vb), the integrals split at the ``cuts`` between them."""
        h = T - tb
        if h == 0:
            return sb, vb, 0.0, 0.0
        cuts = np.asarray(cuts, dtype=float)
        inner = distinct_sorted(cuts[(cuts > min(tb, T)) & (cuts < max(tb, T))])
        B = np.concatenate([[tb], inner[::-1] if h < 0 else inner, [T]])
        lo, w = B[:-1], np.diff(B)
        n = lo.size

        def f(xx, j):
            ax = self.A(xx)
            return np.where(j < n, ax, (T - xx) * ax)

        vals, errs, conv = self.integrate(f, np.concatenate([lo, lo]), np.concatenate([w, w]))
        self.check(conv)
        return (sb + vb * h + float(np.sum(vals[n:])), vb + float(np.sum(vals[:n])),
                float(np.sum(errs[n:])), float(np.sum(errs[:n])))

    def _nearest(self, known, t):
        """The known state to integrate from: not across a stretch where a
        quadrature failed to converge if avoidable (an iterate beyond it
        carries that error once, instead of redoing the stretch every step),
        then a converged one, then the nearest."""
        bad = self._bad_xs

        def key(q):
            lo, hi = min(q[0], t), max(q[0], t)
            crosses = any(lo < x < hi for x in bad)
            return (crosses, not q[-1], abs(q[0] - t))

        return min(known, key=key)

    def crossing(self, kind: str, target: float, t0: float, s0: float, v0: float, t1: float, s1: float, v1: float) -> float:
        """First t in [t0, t1] with v (kind 'v') or s (kind 's') = target; the
        state is known at both ends.  Each evaluation integrates from the
        nearest known state (ends and earlier iterates)."""
        known = [(t0, s0, v0, True)]    # the far end may carry a larger error: iterates only
        k = 1 if kind == "s" else 2

        def g(t):
            tb, sb, vb, _ = self._nearest(known, t)
            n = self._nbad
            s, v, _, _ = self.state(t, tb, sb, vb)
            known.append((t, s, v, self._nbad == n))
            return (s, v)[k - 1] - target

        return root_in_bracket(g, t0, t1, (s0, v0)[k - 1] - target, (s1, v1)[k - 1] - target)

    def vroot(self, t0: float, v0: float, t1: float, v1: float, target: float) -> float:
        """v = target in [t0, t1] (v only: one integral per step)."""
        known = [(t0, v0, True)]        # the far end may carry a larger error: iterates only

        def g(t):
            tb, vb, _ = self._nearest(known, t)
            vals, errs, conv = self.integrate(lambda x, j: self.A(x), [tb], [t - tb])
            self.check(conv)
            v = vb + float(vals[0])
            known.append((t, v, bool(np.all(conv))))
            return v - target

        return root_in_bracket(g, t0, t1, v0 - target, v1 - target)

    # -- t queries ------------------------------------------------------
    def t_query(self, i: int, T: float) -> None:
        p = self.p
        try:
            s, v, es, ev = self.state_split(T, p.t1, p.s1, p.v1)
        except NonFinite as exc:
            self.ans.unreached(i, f"{nonfinite_reason(exc)}, between t1 and t")
            return
        self.ans.reached(i, T, s, v, err=(0.0, es, ev))


def solve(p, ans, rtol: float, atol: float) -> str:
    c = _Case2(p, ans, rtol, atol)
    vq, sq = {}, {}
    for i, q in enumerate(p.find):
        if q.kind == "t":
            ans.ask(i, c.t_query, q.t)
        elif q.kind == "v":
            vq[i] = q.v
        else:
            sq[i] = q.s
    if vq or sq:
        Scan(c).run(vq, sq)
        return "quadrature+root"
    return "quadrature"


class States:
    """The state at any times (in any order), each integrated from the nearest time on its side
    of t1 where the state is already known (t1, or an earlier time asked): a grid costs one sweep
    of the span instead of one quadrature from t1 per time.  Each call has its own work budget;
    an entry where the state is not finite is ``{"reached": False}``."""

    def __init__(self, p, rtol: float, atol: float):
        from dyncli.result import Result
        from dyncli.topics.rectilinear.answers import Answers

        self.p, self.rtol, self.atol = p, rtol, atol
        self.c = _Case2(p, Answers(replace(p, find=()), Result({})), rtol, atol)
        self.kt = [p.t1]                        # the times where the state is known, ascending
        self.known = {p.t1: (p.s1, p.v1)}

    def __call__(self, p, times) -> list[dict]:
        out: dict[float, dict[str, Any]] = {}
        c, t1 = self.c, self.p.t1
        c.work = Work(self.p, 2)
        span = [float(t) for t in times if math.isfinite(float(t))] + [t1]
        c.signs.get(min(span), max(span))       # one analysis of a over the whole span asked
        for T in sorted({float(t) for t in times}, key=lambda t: (t < t1, abs(t - t1))):
            # the nearest known time between t1 and T (t1 itself is known): a bisection, not a scan
            tb = self.kt[bisect.bisect_right(self.kt, T) - 1] if T >= t1 else self.kt[bisect.bisect_left(self.kt, T)]
            sb, vb = self.known[tb]
            try:
                s, v, _, _ = c.state_split(T, tb, sb, vb)
            except NonFinite:
                out[T] = {"reached": False}
                continue
            if T not in self.known:
                bisect.insort(self.kt, T)
            self.known[T] = (s, v)
            out[T] = {"t": T, "s": s, "v": v, "a": c.a1(T), "reached": True}
        return [out[float(t)] for t in times]
