"""The motion of a case-3 or case-4 problem solved once, evaluated at any times: what ``find``'s
searches read (issue 29: each try of a search was a new solve)."""

from __future__ import annotations

from dataclasses import replace

from dyncli.result import Result
from dyncli.topics.rectilinear.answers import Answers
from dyncli.topics.rectilinear.setup import Query


class Solved:
    """The motion of one problem solved once by its quadrature route (case 3: the branches of v,
    case 4: the scans and legs, built at the first call and kept), its state at any times per
    call: a search of ``find`` tries many times, each of which was a new solve (issue 29).  The
    same states as :func:`dyncli.topics.rectilinear.solver.sample` (the same model with ``{t: T}`` queries only)."""

    def __init__(self, case: int, seed=None):
        """``seed``: the case object of the problem's own run (its scans and legs reused)."""
        self.case, self.c, self.ready = case, None, False
        if seed is not None:
            from dyncli.topics.rectilinear import case3

            self.c = seed
            self.ready = (case3.moves(seed) if case == 3
                          else hasattr(seed, "fwd"))

    def __call__(self, p, times) -> list[dict | None]:
        import numpy as np

        from dyncli.topics.rectilinear.work import Work

        q = replace(p, find=tuple(Query(t=float(t)) for t in times), labels=None)
        ans = Answers(q, Result({"case": self.case, "find": []}))
        with np.errstate(all="ignore"):
            if self.c is None:
                rtol, atol = q.accuracy.rtol, q.accuracy.atol
                if self.case == 3:
                    from dyncli.topics.rectilinear import case3

                    self.c = case3.motion(q, ans, rtol, atol)
                    self.ready = case3.moves(self.c)
                else:
                    from dyncli.topics.rectilinear import case4

                    self.c = case4.motion(q, ans, rtol, atol)
                    self.ready = self.c.setup()
            c = self.c
            c.p, c.ans, c.work = q, ans, Work(q, self.case)     # each call its own work budget
            if not self.ready:
                c.equilibrium()
            else:
                for i, T in enumerate(times):
                    ans.ask(i, c.t_query, float(T))
        return ans.items
