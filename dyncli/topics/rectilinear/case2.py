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
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.topics.rectilinear._quad import NonFinite, brentq, integrate

_N0 = 2048
_NMAX = 1 << 16


def _fmt(x: float) -> str:
    return f"{x:.10g}"


class _Case2:
    def __init__(self, p, ans, rtol, atol):
        self.p = p
        self.ans = ans
        self.qr = max(rtol * 1e-2, 1e-15)
        self.qa = atol * 1e-2
        self.rtol, self.atol = rtol, atol
        self.a = p.a
        from dyncli.topics.rectilinear.solver import scalar_fn

        self._fn = scalar_fn(p.a)
        self.warned_conv = False

    def A(self, x):
        return self.a.evaluate(t=np.asarray(x, dtype=float))

    def a1(self, x: float) -> float:
        return float(self._fn({'t': x}))

    def _check(self, conv) -> None:
        if not np.all(conv) and not self.warned_conv:
            self.warned_conv = True
            self.ans.res.warn("quadrature did not reach the requested tolerance everywhere (non-smooth a?); see error_estimate")

    # state at T from a base state (tb, sb, vb): two integrals, one call
    def state(self, T: float, tb: float, sb: float, vb: float):
        h = T - tb
        if h == 0:
            return sb, vb, 0.0, 0.0

        def f(x, j):
            ax = self.A(x)
            return np.where(j == 0, ax, (T - x) * ax)

        vals, errs, conv = integrate(f, [tb, tb], [h, h], self.qr, self.qa)
        self._check(conv)
        return sb + vb * h + vals[1], vb + vals[0], errs[1], errs[0]

    def dv(self, tb: float, h: float) -> float:
        vals, errs, conv = integrate(lambda x, j: self.A(x), [tb], [h], self.qr, self.qa)
        self._check(conv)
        return float(vals[0])

    def ds(self, tb: float, vb: float, h: float) -> float:
        T = tb + h
        vals, errs, conv = integrate(lambda x, j: (T - x) * self.A(x), [tb], [h], self.qr, self.qa)
        self._check(conv)
        return vb * h + float(vals[0])

    # -- t queries ------------------------------------------------------
    def t_query(self, i: int, T: float) -> None:
        p = self.p
        try:
            s, v, es, ev = self.state(T, p.t1, p.s1, p.v1)
        except NonFinite as exc:
            self.ans.unreached(i, f"a is not finite at t = {_fmt(exc.x)}, between t1 and t")
            return
        self.ans.reached(i, T, s, v, err=max(es, ev))

    # -- v and s queries: scan forward in chunks ------------------------
    def scan(self, vq: dict[int, float], sq: dict[int, float]) -> None:
        p, ans = self.p, self.ans
        t1, s1, v1 = p.t1, p.s1, p.v1
        for i, V in list(vq.items()):
            if V == v1:
                ans.reached(i, t1, s1, v1)
                del vq[i]
        for i, S in list(sq.items()):
            if S == s1:
                ans.reached(i, t1, s1, v1)
                del sq[i]
        if not vq and not sq:
            return
        H = p.t_max
        edges = t1 + H * np.concatenate([[0.0], 2.0 ** -np.arange(12, -1, -1)])
        tc, sc, vc = t1, s1, v1
        vmin = vmax = v1
        smin = smax = s1
        stop_reason = None
        for ca, cb in zip(edges[:-1], edges[1:]):
            if not vq and not sq:
                break
            (tc, sc, vc, lo_v, hi_v, lo_s, hi_s, stop) = self._chunk(ca, cb, sc, vc, vq, sq)
            vmin, vmax = min(vmin, lo_v), max(vmax, hi_v)
            smin, smax = min(smin, lo_s), max(smax, hi_s)
            if stop:
                stop_reason = stop
                break
        horizon = stop_reason or f"search horizon t1 + t_max = {_fmt(t1 + H)}"
        for i, V in vq.items():
            ans.unreached(i, f"v stays within [{_fmt(vmin)}, {_fmt(vmax)}] for t1 <= t <= {_fmt(tc)} ({horizon})")
        for i, S in sq.items():
            ans.unreached(i, f"s stays within [{_fmt(smin)}, {_fmt(smax)}] for t1 <= t <= {_fmt(tc)} ({horizon})")

    def _samples(self, ca: float, cb: float):
        n = _N0
        while True:
            x = np.linspace(ca, cb, n + 1)
            ax = self.A(x)
            bad = ~np.isfinite(ax)
            changes = int(np.count_nonzero(np.signbit(ax[:-1]) != np.signbit(ax[1:])))
            if bad.any() or changes <= n // 16 or n >= _NMAX:
                if changes > n // 16 and not bad.any():
                    self.ans.res.warn("a changes sign very often; crossings closer than the sampling step "
                                      f"{_fmt((cb - ca) / n)} s may be missed")
                return x, ax
            n *= 4

    def _chunk(self, ca, cb, sc, vc, vq, sq):
        """Scan [ca, cb] starting from the state (sc, vc); answer what is crossed."""
        ans = self.ans
        x, ax = self._samples(ca, cb)
        stop = None
        bad = ~np.isfinite(ax)
        if bad.any():
            k = int(np.argmax(bad))
            stop = f"a is not finite at t = {_fmt(x[k])}"
            if k <= 1:
                return ca, sc, vc, vc, vc, sc, sc, stop
            x, ax = x[:k], ax[:k]
            cb = float(x[-1])
        # extrema of v: sign changes of a
        roots = []
        sb = np.signbit(ax)
        for k in np.nonzero(sb[:-1] != sb[1:])[0]:
            if ax[k] == 0:
                roots.append(float(x[k]))
            elif ax[k + 1] == 0:
                continue
            else:
                roots.append(brentq(self.a1, float(x[k]), float(x[k + 1]), float(ax[k]), float(ax[k + 1])))
        Bv = np.unique(np.array([ca] + [r for r in roots if ca < r < cb] + [cb]))
        try:
            vals, errs, conv = integrate(lambda t, j: self.A(t), Bv[:-1], np.diff(Bv), self.qr, self.qa)
        except NonFinite as exc:
            return ca, sc, vc, vc, vc, sc, sc, f"a is not finite at t = {_fmt(exc.x)}"
        self._check(conv)
        vB = vc + np.concatenate([[0.0], np.cumsum(vals)])
        # v queries (interior breakpoints are extrema of v)
        for i, V in list(vq.items()):
            for k in range(len(Bv) - 1):
                lo, hi = min(vB[k], vB[k + 1]), max(vB[k], vB[k + 1])
                tol = self.rtol * max(abs(V), abs(lo), abs(hi)) + self.atol
                tb, vb = float(Bv[k]), float(vB[k])
                ext = k + 1 < len(Bv) - 1
                if ext and abs(V - vB[k + 1]) <= tol:
                    t, graze = float(Bv[k + 1]), True     # target = extremum (grazing)
                elif lo <= V <= hi:
                    t, graze = brentq(lambda t: vb + self.dv(tb, t - tb) - V, tb, float(Bv[k + 1]),
                                      vb - V, float(vB[k + 1]) - V), False
                else:
                    continue
                if not ans.beyond_t_max(i, t):
                    s, v, es, ev = self.state(t, ca, sc, vc)
                    at = abs(self.a1(t))
                    ans.reached(i, t, s, v, err=max(es, ev, ev / at if (at > 0 and not graze) else 0.0))
                del vq[i]
                break
        # extrema of s: zeros of v inside the monotone pieces of v
        Bs, vs = [ca], [vc]
        last = len(Bv) - 1
        for k in range(last):
            va, vb_ = vB[k], vB[k + 1]
            if va != 0 and vb_ != 0 and (va > 0) != (vb_ > 0):
                # v grazing 0 at an extremum of v (a double zero, e.g. v = c(1 - cos ωt)): the
                # sign change is quadrature noise within the tolerance; the zero is the extremum
                # itself (a root search there converges only slowly on the noise)
                tolz = self.rtol * max(abs(va), abs(vb_)) + self.atol
                if 0 < k + 1 < last and abs(vb_) <= tolz:
                    if Bs[-1] < float(Bv[k + 1]) < cb:
                        Bs.append(float(Bv[k + 1]))
                        vs.append(0.0)
                    continue
                if 0 < k and abs(va) <= tolz:
                    continue
                tb = float(Bv[k])
                r = brentq(lambda t: va + self.dv(tb, t - tb), tb, float(Bv[k + 1]), float(va), float(vb_))
                if Bs[-1] < r < cb:
                    Bs.append(r)
                    vs.append(0.0)
            elif vb_ == 0 and 0 < k + 1 < len(Bv) - 1:
                Bs.append(float(Bv[k + 1]))
                vs.append(0.0)
        Bs.append(cb)
        vs.append(float(vB[-1]))
        Bs = np.array(Bs)
        vs = np.array(vs)
        h = np.diff(Bs)
        ends = Bs[1:]
        vals2, errs2, conv2 = integrate(lambda t, j: (ends[j] - t) * self.A(t), Bs[:-1], h, self.qr, self.qa)
        self._check(conv2)
        sB = sc + np.concatenate([[0.0], np.cumsum(vs[:-1] * h + vals2)])
        # s queries (interior breakpoints are turning points)
        for i, S in list(sq.items()):
            for k in range(len(Bs) - 1):
                lo, hi = min(sB[k], sB[k + 1]), max(sB[k], sB[k + 1])
                tol = self.rtol * max(abs(S), abs(lo), abs(hi)) + self.atol
                tb, sb_, vb = float(Bs[k]), float(sB[k]), float(vs[k])
                ext = k + 1 < len(Bs) - 1
                if ext and abs(S - sB[k + 1]) <= tol:
                    t, graze = float(Bs[k + 1]), True      # target = turning point
                elif lo <= S <= hi:
                    t, graze = brentq(lambda t: sb_ + self.ds(tb, vb, t - tb) - S, tb, float(Bs[k + 1]),
                                      sb_ - S, float(sB[k + 1]) - S), False
                else:
                    continue
                if not ans.beyond_t_max(i, t):
                    s, v, es, ev = self.state(t, ca, sc, vc)
                    ans.reached(i, t, s, v, err=max(es, ev, es / abs(v) if (v != 0 and not graze) else 0.0))
                del sq[i]
                break
        return (cb, float(sB[-1]), float(vB[-1]), float(vB.min()), float(vB.max()),
                float(sB.min()), float(sB.max()), stop)


def solve(p, ans, rtol: float, atol: float) -> str:
    c = _Case2(p, ans, rtol, atol)
    vq, sq = {}, {}
    for i, q in enumerate(p.find):
        if q.kind == "t":
            c.t_query(i, q.t)
        elif q.kind == "v":
            vq[i] = q.v
        else:
            sq[i] = q.s
    if vq or sq:
        c.scan(vq, sq)
        return "quadrature+root"
    return "quadrature"
