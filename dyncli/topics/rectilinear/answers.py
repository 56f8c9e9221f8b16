"""The answers to a rectilinear motion's ``find`` queries (notes §6, §11), as every route gives them:
the closed form (``solver.py``), the quadratures (``case2.py``, ``case3.py``, ``case4.py``) and the
ODE (``general.py``).  :class:`Answers` collects each query's state (or why it is not reached),
the warnings and the error bounds the quadrature routes propagate.
"""

from __future__ import annotations

import math

from dyncli.result import Result
from dyncli.topics.rectilinear.constants import fmt


class Answers:
    """Collects the per-query answers, warnings and error estimates."""

    def __init__(self, p, res: Result):
        self.p = p
        self.res = res
        self.items: list[dict | None] = [None] * len(p.find)
        #: the absolute error bounds (t, s, v) of each reached answer (quadrature routes)
        self.errs: list[tuple] = []
        #: how a query is named in warnings (its index in the user's list; see _distinct)
        self.labels = p.labels or [f"find[{i}]" for i in range(len(p.find))]

    def acc(self, t: float, s: float, v: float) -> float:
        val = self.p.a(t=t, s=s, v=v)
        return float(val)

    def reached(self, i: int, t: float, s: float, v: float, err=(0.0, 0.0, 0.0), a: float | None = None) -> None:
        """Answer query i with the state (t, s, v); ``err``: the absolute error bounds of t, s
        and v (the quadrature routes' propagated estimates)."""
        t, s, v = float(t), float(s), float(v)
        a = self.acc(t, s, v) if a is None else float(a)
        if not all(math.isfinite(x) for x in (t, s, v, a)):
            self.unreached(i, f"the state is not finite there (t = {t!r}, s = {s!r}, v = {v!r})")
            return
        self.items[i] = {"t": t, "s": s, "v": v, "a": a, "reached": True}
        if any(err):
            self.errs.append(tuple(float(e) for e in err))

    def relative_error(self) -> float:
        """The largest error bound of t, s, v over the answers, each relative to its own scale
        (the largest |t - t1|, |s|, |v| over the reached answers; at least atol for s and v):
        the quadrature routes' error_estimate, in the terms of :func:`dyncli.ode.relative_difference`."""
        if not self.errs:
            return 0.0
        got = [x for x in self.items if x is not None and x["reached"]]
        floor = self.p.accuracy.atol
        scales = (max(abs(x["t"] - self.p.t1) for x in got),
                  max([abs(x["s"]) for x in got] + [floor]), max([abs(x["v"]) for x in got] + [floor]))
        worst = 0.0
        for err in self.errs:
            for e, sc in zip(err, scales):
                if e > 0 and sc > 0:
                    worst = max(worst, e / sc)
        return worst

    def at_start(self, vq: dict, sq: dict) -> None:
        """Answer (and remove) the v and s queries equal to the initial state: at t1 itself."""
        p = self.p
        for queries, x1 in ((vq, p.v1), (sq, p.s1)):
            for i, X in list(queries.items()):
                if X == x1:
                    self.reached(i, p.t1, p.s1, p.v1)
                    del queries[i]

    def ask(self, i: int, query, target: float) -> None:
        """Run one query (``query(i, target)``); integrals t = ∫ dv/a, s = ∫ v dv/a
        (or t = ∫ ds/v) that overflow a double on the way to the target (a tiny a,
        a target beyond the doubles) answer it as not reached, with the reason."""
        from dyncli.topics.rectilinear._quad import NonFinite

        try:
            query(i, target)
        except NonFinite as exc:
            self.unreached(i, f"the integrals that lead to it are not finite in doubles on the way (at "
                              f"{fmt(exc.x)} of the integration variable): a is too small, or the target too "
                              "far, for floating point")

    def unreached(self, i: int, reason: str) -> None:
        q = self.p.find[i]
        self.res.warn(f"{self.labels[i]} ({q.kind} = {fmt(q.target)}): not reached — {reason}")
        self.items[i] = {"t": None, "s": None, "v": None, "a": None, "reached": False}

    def beyond_t_max(self, i: int, t: float) -> bool:
        """True (and the query marked unreached) when t lies beyond t1 + t_max."""
        p = self.p
        if t - p.t1 > p.t_max:
            self.unreached(i, f"first attained at t = {fmt(t)}, beyond the search horizon t1 + t_max = {fmt(p.t1 + p.t_max)}")
            return True
        return False
