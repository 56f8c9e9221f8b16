"""Case 4, a = a(s): the pieces of the orbit — where a leg ends (:class:`End`), v^2(s) from
the nearest exact reference (:class:`Energy`, 6.14, 6.15) and the time along one leg with its
substitutions at the ends (:class:`Leg`, 6.12).  The solver is :mod:`.case4`."""

from __future__ import annotations

import math

import numpy as np

from dyncli.rootfind import distinct_sorted, root_in_bracket
from dyncli.topics.rectilinear._quad import NonFinite, integrate
from dyncli.topics.rectilinear.constants import BIG, EPS, fmt
from dyncli.topics.rectilinear.work import QUAD


def _log1p_ratio(d: float, c: float) -> float:
    """log(1 + d/c) without overflowing d/c (d ~ 1e100, c ~ 1e-290)."""
    r = d / c
    if math.isfinite(r):
        return math.log1p(r)
    return math.log(d) - math.log(c)


class End:
    def __init__(self, kind: str, pos: float):
        self.kind = kind      # turn | asym | sing | inf
        self.pos = pos
        # inf: is the time to infinity finite (∫ ds/|v| converges)?  True, False or None (unknown)
        self.finite_time = None

    def describe(self) -> str:
        if self.kind == "inf" and math.isfinite(self.pos):
            return f"|s| grows without bound; v^2 exceeds the doubles beyond s ≈ {fmt(self.pos)}"
        return {
            "turn": f"turning point s = {fmt(self.pos)}",
            "asym": f"unstable equilibrium s = {fmt(self.pos)}, approached as t → ∞",
            "sing": f"a is singular at s ≈ {fmt(self.pos)}",
            "inf": "|s| grows without bound",
        }[self.kind]


class Energy:
    """v^2(s) integrated from the nearest reference with known v^2."""

    def __init__(self, c4):
        self.c4 = c4
        self.R = np.array([c4.s1])
        self.V2 = np.array([c4.v1 * c4.v1])

    def add(self, s, v2) -> None:
        R = np.concatenate([self.R, np.atleast_1d(s)])
        V2 = np.concatenate([self.V2, np.atleast_1d(v2)])
        order = np.argsort(R, kind="stable")
        self.R, self.V2 = R[order], V2[order]

    def v2(self, base, off):
        base = np.asarray(base, dtype=float)
        off = np.asarray(off, dtype=float)
        base, off = np.broadcast_arrays(base, off)
        s = base + off
        R = self.R
        j = np.clip(np.searchsorted(R, s), 1, max(len(R) - 1, 1))
        if len(R) == 1:
            idx = np.zeros(s.shape, dtype=int)
        else:
            left = np.abs(s - R[j - 1])
            right = np.abs(R[j] - s)
            idx = np.where(left <= right, j - 1, j)
            # an exact reference equal to the base point wins (turning points)
            jb = np.clip(np.searchsorted(R, base), 0, len(R) - 1)
            same = R[jb] == base
            idx = np.where(same & (np.abs(off) <= np.minimum(left, right) * (1 + 1e-9)), jb, idx)
        R = self.R[idx]
        width = np.where(R == base, off, (base - R) + off)
        # absolute floor: the rounding noise of a itself (eps |a|max per unit length)
        w = width.ravel()
        self.c4.work.charge(QUAD)
        vals, errs, conv = integrate(lambda x, j: self.c4.A(x), R.ravel(), w, self.c4.qr,
                                     64 * EPS * self.c4.amax * np.abs(w))
        self.c4.check(conv)
        return self.V2[idx] + 2.0 * vals.reshape(s.shape)


    # used only when a vectorised call met a non-finite a
    def v2_safe(self, b: float, o: float) -> float:
        try:
            return float(self.v2(b, o))
        except NonFinite:
            return math.nan


class Leg:
    """Motion from A to the end B in direction e, split at the midpoint M."""

    def __init__(self, c4, A: float, a_turn: bool, end: End, e: int):
        self.c4, self.A, self.e, self.end = c4, A, e, end
        self.B = end.pos
        # towards infinity: a short first part and then the geometric map s = M + e c (e^x - 1),
        # c the smallest length of the problem, so every scale from c to BIG gets cells of its own
        self.c = c4.scale_min
        if end.kind == "inf":
            if math.isfinite(self.B):
                self.c = min(self.c, 0.5 * abs(self.B - A))
            self.M = A + e * self.c
        else:
            self.M = A + 0.5 * (self.B - A)
        self.k1 = "sqrt" if a_turn else "lin"
        self.k2 = {"turn": "sqrt", "asym": "exp", "sing": "lin", "inf": "geo"}[end.kind]
        L1 = abs(self.M - A)
        self.X1 = math.sqrt(L1) if self.k1 == "sqrt" else L1
        L2 = abs(self.B - self.M) if end.kind != "inf" else 0.0
        if self.k2 == "sqrt":
            self.X2 = math.sqrt(L2)
        elif self.k2 == "lin":
            self.X2 = L2
        elif self.k2 == "exp":
            # (difference of logarithms: the ratio overflows for L2 > ~1e18)
            self.X2 = max(math.log(L2) - math.log(max(8 * EPS * abs(self.B), 1e-290)), 0.0) if L2 > 0 else 0.0
        else:
            self.X2 = _log1p_ratio(max(min(BIG, e * self.B) - e * self.M, 0.0), self.c)
        self.degenerate = L1 == 0 and end.kind != "inf"
        self._build()

    # position and |ds/dx| in part 1 (x in [0, X1]) and part 2 (x in [0, X2])
    def _map(self, part: int, x):
        e = self.e
        if part == 1:
            if self.k1 == "sqrt":
                return self.A, e * x * x, 2.0 * x
            return self.A, e * x, np.ones_like(x)
        if self.k2 == "sqrt":
            u = self.X2 - x
            return self.B, -e * u * u, 2.0 * u
        if self.k2 == "lin":
            return self.B, -e * (self.X2 - x), np.ones_like(x)
        if self.k2 == "exp":
            L2 = abs(self.B - self.M)
            d = L2 * np.exp(-x)
            return self.B, -e * d, d
        c, lc = self.c, math.log(self.c)
        # (c e^x as e^(x + ln c): with c ~ 1e-290 the map needs x up to ~900, beyond e^709)
        with np.errstate(over="ignore"):
            off = np.where(x < 700, c * np.expm1(np.minimum(x, 700)), np.exp(x + lc) - c)
        return self.M, e * off, np.exp(x + lc)

    def _dtdx(self, part: int, x):
        base, off, dsdx = self._map(part, x)
        try:
            v2 = self.c4.energy.v2(base, off)
        except NonFinite:
            # report the failure at this level (x), not at the inner abscissa
            v2 = np.array([self.c4.energy.v2_safe(b, o) for b, o in zip(np.ravel(base + 0 * off), np.ravel(off))])
        return dsdx / np.sqrt(np.maximum(v2, 0.0))

    def _integ(self, part: int, lo, hi):
        lo = np.atleast_1d(np.asarray(lo, dtype=float))
        hi = np.atleast_1d(np.asarray(hi, dtype=float))
        vals = np.zeros(lo.shape)
        errs = np.zeros(lo.shape)
        # next to an asymptotic equilibrium v^2 ~ (s_E - s)^2 drowns in the rounding
        # of a; there dt/dx is integrated loosely: an error in t there moves the
        # state by |v| dt, which is ~ (s_E - s) — negligible
        rtol = np.full(lo.shape, self.c4.qr)
        if part == 2 and self.k2 == "exp":
            # relative rounding noise of a at distance d from s_E is ~ eps |s_E| / d;
            # integrating dt/dx only to that level moves the state by about
            # |v| dt ~ eps |s_E| per cell — negligible
            d = abs(self.B - self.M) * np.exp(-np.maximum(lo, hi))
            rtol = np.maximum(rtol, 64 * EPS * max(abs(self.B), abs(self.M)) / np.maximum(d, 1e-300))
        self.c4.work.charge(QUAD)
        vals, errs, conv = integrate(lambda x, j: self._dtdx(part, x), lo, hi - lo, np.minimum(rtol, 0.5), 0.0)
        self.c4.check(conv)
        return vals, errs

    def _grid(self, part: int, X: float, kind: str):
        # quadrature panels of the leg's t(s) table (issue 28 audit): a starting table the adaptive
        # quadrature refines; the leg is monotone, no decision is made on these nodes
        if X <= 0:
            return np.array([0.0])
        if kind in ("exp", "geo"):
            g = np.concatenate([[0.0, 1 / 8, 1 / 4, 1 / 2], np.arange(1.0, X, 1.0), [X]])
            return distinct_sorted(g[g <= X])
        return np.linspace(0.0, X, 9)

    def _build(self) -> None:
        self.grids = []
        self.cums = []
        self.cerrs = []
        total = 0.0
        etotal = 0.0
        self.finite_end = True
        for part, X, kind in ((1, self.X1, self.k1), (2, self.X2, self.k2)):
            g = self._grid(part, X, kind)
            while True:
                try:
                    if g.size > 1:
                        vals, errs = self._integ(part, g[:-1], g[1:])
                    else:
                        vals = errs = np.zeros(0)
                    break
                except NonFinite as exc:
                    keep = g[g < exc.x]
                    if keep.size >= 2:
                        g = keep
                    else:
                        g = np.array([0.0, 0.5 * exc.x]) if exc.x > 1e-12 else np.array([0.0])
                    self.finite_end = False
            cum = total + np.concatenate([[0.0], np.cumsum(vals)])
            cerr = etotal + np.concatenate([[0.0], np.cumsum(errs)])
            self.grids.append(g)
            self.cums.append(cum)
            self.cerrs.append(cerr)
            total = float(cum[-1])
            etotal = float(cerr[-1])
        self.reach = total       # time to the last resolved point
        if self.k2 == "geo":
            self.end.finite_time = self._tail_finite()
        self.duration = math.inf if self.k2 == "exp" else total

    def _tail_finite(self):
        """Does ∫^∞ ds/|v| converge?  On the geometric map dt/dx = |s - M + e c|/|v| tends to a
        constant for |v| ~ |s| (a linear in s: growth without bound, infinity only as t -> ∞), grows
        for slower |v| and decays like e^(-(p-1) x) for |v| ~ |s|^p, p > 1 (escape in finite time,
        e.g. a = s^3).  Judged on the decay rate of dt/dx over the last resolved 20 units of x;
        None when they are not resolved (v^2 overflowed early, or too few cells)."""
        g, cum = self.grids[1], self.cums[1]
        if g.size < 2:
            return None
        w, dt = np.diff(g), np.diff(cum)
        ok = (w > 0) & (dt > 0) & np.isfinite(dt)
        n = len(ok)
        if not ok.all():
            # up to the first cell where dt/dx vanished (v^2 overflowed), that one and its neighbour excluded
            n = max(int(np.argmin(ok)) - 1, 0)
        if n == 0:
            return None
        x_end = float(g[n])
        span = min(10.0, 0.5 * (x_end - float(g[0])))
        if span < 2.0:
            return None
        mid = 0.5 * (g[:n] + g[1:n + 1])
        last = mid >= x_end - span
        prev = (mid >= x_end - 2 * span) & ~last
        if not (last.any() and prev.any()):
            return None
        r_last = float(np.sum(dt[:n][last]) / np.sum(w[:n][last]))
        r_prev = float(np.sum(dt[:n][prev]) / np.sum(w[:n][prev]))
        # decay rate of dt/dx per unit x; 0.02 leaves borderline tails (|v| ~ |s| log^2|s|) 'unbounded'
        return math.log(r_prev / r_last) / span > 0.02

    # -- time to a position -------------------------------------------------
    def time_to(self, s: float) -> tuple[float, float]:
        d = abs(s - self.A)
        if d <= abs(self.M - self.A):
            part = 1
            x = math.sqrt(d) if self.k1 == "sqrt" else d
        else:
            part = 2
            if self.k2 == "sqrt":
                x = self.X2 - math.sqrt(abs(self.B - s))
            elif self.k2 == "lin":
                x = self.X2 - abs(self.B - s)
            elif self.k2 == "exp":
                r = abs(self.B - s)
                if r == 0:
                    return math.inf, 0.0
                x = math.log(abs(self.B - self.M) / r)
            else:
                x = _log1p_ratio(abs(s - self.M), self.c)
        return self._time_at(part, x)

    def _time_at(self, part: int, x: float):
        g = self.grids[part - 1]
        cum = self.cums[part - 1]
        x = min(max(x, 0.0), float(g[-1]))
        k = int(np.searchsorted(g, x, side="right")) - 1
        k = min(max(k, 0), len(g) - 1)
        t = float(cum[k])
        err = float(self.cerrs[part - 1][k])
        if x != g[k]:
            v, e = self._integ(part, g[k], x)
            t += float(v[0])
            err += float(e[0])
        return t, err

    # -- position at a time ---------------------------------------------------
    def state_at(self, tau: float):
        """(s, |v|, err) at time tau after leaving A (tau <= self.reach)."""
        for part in (1, 2):
            g, cum = self.grids[part - 1], self.cums[part - 1]
            if g.size < 2 or tau > cum[-1]:
                continue
            k = int(np.searchsorted(cum, tau, side="left"))
            k = min(max(k, 1), len(cum) - 1)
            lo, hi, c0 = float(g[k - 1]), float(g[k]), float(cum[k - 1])

            def f(x, part=part, lo=lo, c0=c0):
                return c0 + (float(self._integ(part, lo, x)[0][0]) if x != lo else 0.0) - tau

            x = root_in_bracket(f, lo, hi, c0 - tau, float(cum[k]) - tau)
            base, off, _ = self._map(part, np.float64(x))
            s = float(base + off)
            v2 = float(self.c4.energy.v2(base, off))
            return s, math.sqrt(max(v2, 0.0)), float(self.cerrs[part - 1][k])
        # at (or numerically at) the end
        if self.degenerate:
            return self.A, 0.0, 0.0
        if self.end.kind in ("turn", "asym"):
            return self.B, 0.0, 0.0
        g = self.grids[1]
        base, off, _ = self._map(2, np.float64(g[-1]))
        return float(base + off), math.sqrt(max(float(self.c4.energy.v2(base, off)), 0.0)), 0.0
