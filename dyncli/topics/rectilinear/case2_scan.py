"""Case 2, a = a(t): the forward scan that answers the v- and s-queries (6.6a,b).

The time axis from t1 is scanned in chunks that double in length up to t1 + t_max.  In each
chunk the sign changes of a (the extrema of v) are decided exactly (:mod:`.case2_signs`: the
sign of a at its critical points, never by sampling), v integrated over the monotone pieces
between them (cut into the quadrature panels that analysis gives); the zeros of v inside those pieces (the extrema of s)
split s into monotone pieces in turn.  A target inside a piece is crossed there (a bracketed
root search), a target equal to an extremum is answered at the extremum (grazing).  The error
estimates of the state at each chunk start are carried along.

:class:`Scan` is a collaborator of the case's quadratures (:class:`.case2._Case2`): it owns the
scan's own state (the error estimates at the chunk start, whether the sign analysis warned) and
reads the motion only through the interface :class:`Quadratures` declares.
"""

from __future__ import annotations

from typing import Any, Protocol

import numpy as np

from dyncli.rootfind import distinct_sorted, roots_in_brackets
from dyncli.topics.rectilinear._quad import NonFinite, NotIntegrable
from dyncli.topics.rectilinear.constants import fmt


def nonfinite_reason(exc: NonFinite) -> str:
    """Why a case-2 motion ends at the time of ``exc`` (a quadrature met a non-finite a, or a
    non-integrable pole): the text of a ``reached: false`` reason."""
    if isinstance(exc, NotIntegrable):
        return f"a is not integrable near t = {fmt(exc.x)} (a pole: the velocity diverges there)"
    return f"a is not finite at t = {fmt(exc.x)}"


class Quadratures(Protocol):
    """What the scan reads of a case-2 motion: its problem ``p``, the answers ``ans`` it fills,
    the user's ``rtol``/``atol``, the sign analysis of a (``signs``: :class:`.case2_signs.SignTable`),
    a on arrays (``A``) and at one time (``a1``), one batched quadrature (``integrate``) whose
    convergence ``check`` warns about, the state at a time from a known one (``state``, ``state_on``
    with the integrals cut at given times), the rounding of the abscissae (``rounding``), and the
    bracketed root searches of s or v (``root``) and of v alone (``vroot``)."""

    p: Any
    ans: Any
    rtol: float
    atol: float
    signs: Any

    def A(self, x) -> Any: ...
    def a1(self, x: float) -> float: ...
    def integrate(self, f, lo, width) -> Any: ...
    def check(self, conv) -> None: ...
    def state(self, T: float, tb: float, sb: float, vb: float) -> Any: ...
    def state_on(self, T: float, tb: float, sb: float, vb: float, cuts) -> Any: ...
    def rounding(self, lo: float, hi: float) -> float: ...
    def crossing(self, kind: str, target: float, t0: float, s0: float, v0: float, t1: float, s1: float, v1: float) -> float: ...
    def vroot(self, t0: float, v0: float, t1: float, v1: float, target: float) -> float: ...


class Scan:
    """The forward scan of one case-2 motion ``m`` (its :class:`Quadratures`): :meth:`run` answers
    the v- and s-queries into ``m.ans``; the error estimates of the state at the current chunk
    start (``es_c``, ``ev_c``) are carried from chunk to chunk."""

    def __init__(self, m: Quadratures):
        self.m = m
        self.es_c = self.ev_c = 0.0     # error estimates of the state at the current chunk start
        self.warned_signs = False

    def run(self, vq: dict[int, float], sq: dict[int, float]) -> None:
        p, ans = self.m.p, self.m.ans
        t1, s1, v1 = p.t1, p.s1, p.v1
        ans.at_start(vq, sq)
        if not vq and not sq:
            return
        H = p.t_max
        # chunks (not samples: each is analysed whole by .case2_signs) doubling up to t1 + t_max
        edges = t1 + H * np.concatenate([[0.0], 2.0 ** -np.arange(12, -1, -1)])
        tc, sc, vc = t1, s1, v1
        vmin = vmax = v1
        smin = smax = s1
        stop_reason = None
        for ca, cb in zip(edges[:-1], edges[1:]):
            if not vq and not sq:
                break
            try:
                (tc2, sc2, vc2, lo_v, hi_v, lo_s, hi_s, stop) = self._chunk(ca, cb, sc, vc, vq, sq)
            except NonFinite as exc:
                # a pole inside the chunk that the sampling missed (only the quadrature's nodes or
                # the bisection met it): scan up to just before it, then stop
                x = exc.x if ca < exc.x <= cb else cb
                cut = ca + (x - ca) * (1 - 1e-9)
                stop = nonfinite_reason(exc)
                try:
                    (tc2, sc2, vc2, lo_v, hi_v, lo_s, hi_s, _) = self._chunk(ca, cut, sc, vc, vq, sq) \
                        if cut > ca else (ca, sc, vc, vc, vc, sc, sc, None)
                except NonFinite:
                    (tc2, sc2, vc2, lo_v, hi_v, lo_s, hi_s) = (ca, sc, vc, vc, vc, sc, sc)
            tc, sc, vc = tc2, sc2, vc2
            vmin, vmax = min(vmin, lo_v), max(vmax, hi_v)
            smin, smax = min(smin, lo_s), max(smax, hi_s)
            if stop:
                stop_reason = stop
                break
        horizon = stop_reason or f"search horizon t1 + t_max = {fmt(t1 + H)}"
        for i, V in vq.items():
            ans.unreached(i, f"v stays within [{fmt(vmin)}, {fmt(vmax)}] for t1 <= t <= {fmt(tc)} ({horizon})")
        for i, S in sq.items():
            ans.unreached(i, f"s stays within [{fmt(smin)}, {fmt(smax)}] for t1 <= t <= {fmt(tc)} ({horizon})")

    def _chunk(self, ca, cb, sc, vc, vq, sq):
        """Scan [ca, cb] starting from the state (sc, vc); answer what is crossed."""
        roots, panels, stops = self.m.signs.get(ca, cb)
        stop = None
        if stops.size:
            x = float(stops[0])
            stop = f"a is not finite at t = {fmt(x)}"
            cb = ca + (x - ca) * (1 - 1e-9)
            roots, panels = roots[roots < cb], panels[panels < cb]
            if not cb > ca:
                return ca, sc, vc, vc, vc, sc, sc, stop
        if self.m.signs.unresolved and not self.warned_signs:
            self.warned_signs = True
            self.m.ans.res.warn("a varies too fast somewhere (a pole, or sign changes closer than the rounding) "
                              "for its sign changes to be decided there; see error_estimate")
        # the extrema of v (the roots of a: ext) and the quadrature panels between them
        Bv = distinct_sorted(np.concatenate([[ca], roots, panels, [cb]]))
        ext = np.isin(Bv, roots)
        vals, errs, conv = self.m.integrate(lambda t, j: self.m.A(t), Bv[:-1], np.diff(Bv))
        self.m.check(conv)
        vB = vc + np.concatenate([[0.0], np.cumsum(vals)])
        evB = self.ev_c + np.concatenate([[0.0], np.cumsum(errs)]) + self.m.rounding(ca, cb)
        self._v_queries(vq, Bv, vB, ext, ca, sc, vc)
        if not sq:
            # no position queries left: s only at the chunk end (for the next chunk and the range)
            h = float(cb - ca)
            s_end, _, es_end, _ = self.m.state(cb, ca, sc, vc) if h else (sc, vc, 0.0, 0.0)
            self.es_c += es_end + self.ev_c * abs(h)
            self.ev_c = float(evB[-1])
            return (cb, float(s_end), float(vB[-1]), float(vB.min()), float(vB.max()),
                    float(min(sc, s_end)), float(max(sc, s_end)), stop)
        Bs, vs, turn = self._s_breaks(Bv, vB, ext, ca, cb)
        h = np.diff(Bs)
        ends = Bs[1:]
        vals2, errs2, conv2 = self.m.integrate(lambda t, j: (ends[j] - t) * self.m.A(t), Bs[:-1], h)
        self.m.check(conv2)
        sB = sc + np.concatenate([[0.0], np.cumsum(vs[:-1] * h + vals2)])
        esB = self.es_c + self.ev_c * (Bs - ca) + np.concatenate([[0.0], np.cumsum(errs2 + float(evB.max()) * h)])
        self._s_queries(sq, Bs, sB, vs, turn, esB, evB)
        self.es_c = float(esB[-1])
        self.ev_c = float(evB[-1])
        return (cb, float(sB[-1]), float(vB[-1]), float(vB.min()), float(vB.max()),
                float(sB.min()), float(sB.max()), stop)

    def _v_queries(self, vq, Bv, vB, ext, ca, sc, vc) -> None:
        """Answer (and remove from ``vq``) the v queries crossed on the pieces Bv of the chunk
        (v monotone on each; ``ext``: the breakpoints that are extrema of v)."""
        ans = self.m.ans
        for i, V in list(vq.items()):
            for k in range(len(Bv) - 1):
                lo, hi = min(vB[k], vB[k + 1]), max(vB[k], vB[k + 1])
                tol = self.m.rtol * max(abs(V), abs(lo), abs(hi)) + self.m.atol
                tb, vb = float(Bv[k]), float(vB[k])
                if ext[k + 1] and k + 1 < len(Bv) - 1 and abs(V - vB[k + 1]) <= tol:
                    t, graze = float(Bv[k + 1]), True     # target = extremum (grazing)
                elif lo <= V <= hi:
                    t, graze = self.m.vroot(tb, vb, float(Bv[k + 1]), float(vB[k + 1]), V), False
                else:
                    continue
                if not ans.beyond_t_max(i, t):
                    s, v, es, ev = self.m.state_on(t, ca, sc, vc, Bv)
                    r = self.m.rounding(ca, t)
                    es += self.es_c + (self.ev_c + r) * abs(t - ca)
                    ev += self.ev_c + r
                    at = abs(self.m.a1(t))
                    # t is off by the error of v over |a| (at a grazing extremum: the root search on a)
                    ans.reached(i, t, s, v, err=(ev / at if (at > 0 and not graze) else 0.0, es, ev))
                del vq[i]
                break

    def _s_breaks(self, Bv, vB, ext, ca, cb):
        """The breakpoints of s on the chunk (the pieces of v and the zeros of v inside them, i.e.
        the extrema of s), v there and which are turning points: (Bs, vs, turn) arrays."""
        last = len(Bv) - 1
        zero = np.zeros(len(Bv), dtype=bool)    # breakpoints where v is zero (turning points)
        pend = []                       # pieces with a sign change of v: one vectorised root search
        for k in range(last):
            va, vb_ = vB[k], vB[k + 1]
            if va != 0 and vb_ != 0 and (va > 0) != (vb_ > 0):
                # v grazing 0 at an extremum of v (a double zero, e.g. v = c(1 - cos ωt)): the
                # sign change is quadrature noise within the tolerance; the zero is the extremum
                # itself (a root search there converges only slowly on the noise)
                tolz = self.m.rtol * max(abs(va), abs(vb_)) + self.m.atol
                if 0 < k + 1 < last and ext[k + 1] and abs(vb_) <= tolz:
                    zero[k + 1] = True
                    continue
                if 0 < k and ext[k] and abs(va) <= tolz:
                    continue
                pend.append(k)
            elif vb_ == 0 and 0 < k + 1 < last:
                zero[k + 1] = True
        roots: list[float] = []
        if pend:
            pk = np.array(pend)
            t0, v0 = Bv[pk], vB[pk]

            def fv(t, j):
                vals, errs, conv = self.m.integrate(lambda x, i: self.m.A(x), t0[j], t - t0[j])
                self.m.check(conv)
                return v0[j] + vals

            roots = [float(r) for r in roots_in_brackets(fv, t0, Bv[pk + 1], v0, vB[pk + 1])]
        rts = np.array(sorted(set(r for r in roots if ca < r < cb) - set(Bv.tolist())), dtype=float)
        Bs = np.concatenate([Bv, rts])
        vs = np.concatenate([np.where(zero, 0.0, vB), np.zeros(rts.size)])
        turn = np.concatenate([zero, np.ones(rts.size, dtype=bool)])
        order = np.argsort(Bs, kind="stable")
        return Bs[order], vs[order], turn[order]

    def _s_queries(self, sq, Bs, sB, vs, turn, esB, evB) -> None:
        """Answer (and remove from ``sq``) the s queries crossed on the pieces Bs of the chunk
        (s monotone on each; ``turn``: the breakpoints that are turning points)."""
        ans = self.m.ans
        for i, S in list(sq.items()):
            for k in range(len(Bs) - 1):
                lo, hi = min(sB[k], sB[k + 1]), max(sB[k], sB[k + 1])
                tol = self.m.rtol * max(abs(S), abs(lo), abs(hi)) + self.m.atol
                tb, sb_, vb = float(Bs[k]), float(sB[k]), float(vs[k])
                if turn[k + 1] and k + 1 < len(Bs) - 1 and abs(S - sB[k + 1]) <= tol:
                    t, graze = float(Bs[k + 1]), True      # target = turning point
                elif lo <= S <= hi:
                    t, graze = self.m.crossing("s", S, tb, sb_, vb, float(Bs[k + 1]), float(sB[k + 1]), float(vs[k + 1])), False
                else:
                    continue
                if not ans.beyond_t_max(i, t):
                    s, v, es, ev = self.m.state(t, tb, sb_, vb)
                    es += float(esB[k]) + float(evB.max()) * abs(t - tb)
                    ev += float(evB.max())
                    # t is off by the error of s over |v| (at a turning point: the root search on v)
                    ans.reached(i, t, s, v, err=(es / abs(v) if (v != 0 and not graze) else 0.0, es, ev))
                del sq[i]
                break
