"""Case 3, a = a(v): t(v) (6.8) and s(v) (6.10) by quadrature.

    t(v) = t1 + ∫_{v1}^{v} dV / a(V)          (6.8)
    s(v) = s1 + ∫_{v1}^{v} V dV / a(V)        (6.10)

The velocity moves monotonically from v1 in the direction of a(v1), towards
the first zero v* of a in that direction (terminal velocity) or to infinity;
backward in time it moves the other way.  Near a simple zero the integrands
have a logarithmic singularity (t -> infinity as v -> v*); the substitution

    v = v* - (v* - v1) e^(-u),   dv = (v* - v) du

makes them smooth and bounded on 0 <= u < infinity, so t-queries near the
terminal velocity stay accurate.  Towards infinity, v = v1 ± c (e^u - 1).
t-queries invert t(u) by a bracketed root search (v(t) from (6.8)); s(t) is
then (6.10) at that velocity.  A zero of a reached in finite time (a ~ |v-v*|^p
with p < 1, e.g. Coulomb friction a = -mu g sign(v)) is reached and the
velocity stays there; a pole of a ends the motion.

This module holds the queries; one branch of v from v1 is :mod:`.case3_branch`.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.rootfind import root_in_bracket
from dyncli.topics.rectilinear.case3_branch import Branch
from dyncli.topics.rectilinear.constants import BIG, fmt
from dyncli.topics.rectilinear.work import SCALAR, Work


class _Case3:
    def __init__(self, p, ans, rtol, atol):
        self.p, self.ans = p, ans
        self._fn = p.a.scalar_fn()
        self.work = Work(p, 3)          # accuracy.max_steps (.work)
        self.rtol, self.atol = rtol, atol
        self.qr = max(rtol * 1e-2, 1e-15)
        self.v1 = p.v1
        self.a_v1 = float(p.a.evaluate(v=np.float64(p.v1)))
        self._warned = False
        # a target speed far beyond v1 (1e308) must not set the scale: the branches scan 15
        # decades below it, so a terminal velocity of 31 m/s went unseen (a blow-up was reported)
        cap = 1e12 * max(abs(p.v1), 1.0)
        vals = [abs(p.v1)] + [min(abs(q.v), cap) for q in p.find if q.kind == "v"]
        self.scale = max(max(vals), 1e-300)
        if self.scale == 1e-300 or self.scale < 1e-3 * abs(self.a_v1):
            self.scale = max(self.scale, 1.0)
        self._branches: dict[int, Branch] = {}

    def A(self, v):
        v = np.asarray(v, dtype=float)
        self.work.call(v.size)
        return self.p.a.evaluate(v=v)

    def a1(self, v: float) -> float:
        self.work.charge(SCALAR)
        return float(self._fn({'v': v}))

    def check(self, conv) -> None:
        if not np.all(conv) and not self._warned:
            self._warned = True
            self.ans.res.warn("quadrature did not reach the requested tolerance everywhere (non-smooth a?); see error_estimate")

    def branch(self, e: int) -> Branch:
        if e not in self._branches:
            self._branches[e] = Branch(self, e, self.scale)
        return self._branches[e]

    def _end_text(self, b: Branch) -> str:
        if b.kind == "zero":
            return f"terminal velocity v* = {fmt(b.v_end)} (a(v*) = 0)"
        if b.kind == "pole":
            return f"a is singular at v = {fmt(b.v_end)}"
        return "v grows without bound"

    # -- queries ------------------------------------------------------------
    def equilibrium(self) -> None:
        p, ans = self.p, self.ans
        for i, q in enumerate(p.find):
            if q.kind == "t":
                ans.reached(i, q.t, p.s1 + p.v1 * (q.t - p.t1), p.v1)
            elif q.kind == "v":
                if q.v == p.v1:
                    ans.reached(i, p.t1, p.s1, p.v1)
                else:
                    ans.unreached(i, f"a(v1) = 0: the velocity stays v1 = {fmt(p.v1)} (equilibrium)")
            else:
                d = q.s - p.s1
                if d == 0:
                    ans.reached(i, p.t1, p.s1, p.v1)
                elif p.v1 == 0 or d / p.v1 < 0:
                    ans.unreached(i, f"a(v1) = 0: the body moves uniformly with v1 = {fmt(p.v1)} and never gets there")
                elif not ans.beyond_t_max(i, p.t1 + d / p.v1):
                    ans.reached(i, p.t1 + d / p.v1, q.s, p.v1)

    def t_query(self, i: int, T: float) -> None:
        p, ans = self.p, self.ans
        tau = T - p.t1
        if tau == 0:
            ans.reached(i, T, p.s1, p.v1)
            return
        d = 1 if self.a_v1 > 0 else -1
        b = self.branch(d if tau > 0 else -d)
        taus = b.tau
        last = float(taus[-1])
        if abs(tau) <= abs(last):
            k = int(np.searchsorted(np.abs(taus), abs(tau), side="left"))
            k = min(max(k, 1), len(taus) - 1)
            ulo, uhi = float(b.u[k - 1]), float(b.u[k])
            t0 = float(taus[k - 1])
            u = root_in_bracket(lambda u: t0 + float(b.integ(ulo, u)[0][0]) - tau if u != ulo else t0 - tau,
                       ulo, uhi, t0 - tau, float(taus[k]) - tau)
            tt, ds, v, (et, es) = b.at(u)
            # an error et in t(u) moves the answer along the trajectory: v by |a| et;
            # s and t(u) share their integrand, so s moves by about |v| et + es
            ans.reached(i, T, p.s1 + ds, v, err=(0.0, es + abs(v) * et, abs(self.a1(v)) * et))
            return
        when = "after" if tau > 0 else "before"
        if b.kind == "zero":
            # v is v* to machine precision (or reached it in finite time and stays)
            s = p.s1 + float(b.ds[-1]) + b.v_end * (tau - last)
            ans.reached(i, T, s, b.v_end)
        elif b.kind == "pole":
            ans.unreached(i, f"{self._end_text(b)}, which is attained at t ≈ {fmt(p.t1 + last)}; the motion is not defined {when} that")
        else:
            ans.unreached(i, f"|v| exceeds {BIG:g} (finite-time blow-up) at t ≈ {fmt(p.t1 + last)}, {when} which nothing is defined")

    def v_query(self, i: int, V: float) -> None:
        p, ans = self.p, self.ans
        if V == p.v1:
            ans.reached(i, p.t1, p.s1, p.v1)
            return
        d = 1 if self.a_v1 > 0 else -1
        if (V - p.v1) * d < 0:
            ans.unreached(i, f"a(v1) = {fmt(self.a_v1)} drives v away from it")
            return
        b = self.branch(d)
        if b.kind != "inf" and (V - b.v_end) * d >= 0:
            if V == b.v_end and b.kind == "zero" and b.finite_time:
                t = p.t1 + b.T_end
                if not ans.beyond_t_max(i, t):
                    ans.reached(i, t, p.s1 + float(b.ds[-1]), b.v_end)
                return
            what = "beyond" if V != b.v_end else "at"
            if b.kind == "zero":
                extra = "; it is approached as t → ∞ but never reached" if V == b.v_end else ""
                ans.unreached(i, f"the speed lies {what} the {self._end_text(b)}{extra}")
            else:
                ans.unreached(i, f"it lies {what} v = {fmt(b.v_end)}: {self._end_text(b)}")
            return
        u = b.u_of(V)
        if u > b.u[-1]:
            if b.kind == "zero":
                if b.finite_time:
                    t = p.t1 + b.T_end
                    if not ans.beyond_t_max(i, t):
                        ans.reached(i, t, p.s1 + float(b.ds[-1]), V)
                    return
                ans.unreached(i, f"it is within rounding of the {self._end_text(b)}, which is approached as t → ∞")
            else:
                ans.unreached(i, f"it lies beyond v = {fmt(b.v_of(np.float64(b.u[-1])))} where the motion ends ({self._end_text(b)})")
            return
        tau, ds, v, (et, es) = b.at(u)
        t = p.t1 + tau
        if not ans.beyond_t_max(i, t):
            ans.reached(i, t, p.s1 + ds, V, err=(et, es, 0.0))

    def s_query(self, i: int, S: float) -> None:
        p, ans = self.p, self.ans
        if S == p.s1:
            ans.reached(i, p.t1, p.s1, p.v1)
            return
        d = 1 if self.a_v1 > 0 else -1
        b = self.branch(d)
        target = S - p.s1
        ds = b.ds
        tol_of = lambda x: self.rtol * max(abs(S), abs(p.s1 + x)) + self.atol
        tol = tol_of(float(ds[-1]))
        if b.kind == "zero" and b.finite_time and b.v_end == 0 and abs(target - ds[-1]) <= tol:
            # the body stops in finite time exactly at the target (s is monotone
            # on the way: v keeps its sign until it reaches 0)
            t = p.t1 + b.T_end
            if not ans.beyond_t_max(i, t):
                ans.reached(i, t, S, 0.0)
            return
        for k in range(len(ds) - 1):
            lo, hi = min(ds[k], ds[k + 1]), max(ds[k], ds[k + 1])
            tol = max(tol_of(lo), tol_of(hi))
            if not (lo - tol <= target <= hi + tol):
                continue
            ulo, uhi = float(b.u[k]), float(b.u[k + 1])
            s0 = float(ds[k])
            # an end matches within the tolerance of its own value (a cell may span 1e70 in s)
            if abs(target - s0) <= tol_of(s0) and k > 0:
                u = ulo
            elif abs(target - ds[k + 1]) <= tol_of(float(ds[k + 1])) and not (lo <= target <= hi):
                u = uhi
            else:
                u = root_in_bracket(lambda u: s0 + float(b.integ(ulo, u)[1][0]) - target if u != ulo else s0 - target,
                           ulo, uhi, s0 - target, float(ds[k + 1]) - target)
            tau, dss, v, (et, es) = b.at(u)
            t = p.t1 + tau
            if not ans.beyond_t_max(i, t):
                # s = S is found within es: t is off by es / |v| more, v by |a| times that
                dt = et + (es / abs(v) if v else 0.0)
                ans.reached(i, t, p.s1 + dss, v, err=(dt, es, abs(self.a1(v)) * dt))
            return
        last_s = float(ds[-1])
        if b.kind == "zero" and b.v_end != 0 and (target - last_s) * b.v_end > 0:
            tau = float(b.tau[-1]) + (target - last_s) / b.v_end
            t = p.t1 + tau
            if not ans.beyond_t_max(i, t):
                ans.reached(i, t, S, b.v_end)
            return
        ans.unreached(i, f"s never attains it: {self._s_unreached(b, ds, last_s)}")

    def _s_unreached(self, b: Branch, ds, last_s: float) -> str:
        """Why the branch never attains a queried position."""
        p = self.p
        smin, smax = p.s1 + float(ds.min()), p.s1 + float(ds.max())
        if b.kind == "zero" and b.v_end == 0:
            if b.finite_time:
                why = f"the body comes to rest at s = {fmt(p.s1 + last_s)} (v reaches 0 at t = {fmt(p.t1 + b.T_end)})"
            else:
                why = f"the body approaches s = {fmt(p.s1 + last_s)} as t → ∞ (v → 0) and never passes it"
        elif b.kind == "zero":
            ext = smin if b.v_end > 0 else smax
            why = (f"after its extreme position s = {fmt(ext)} the body moves towards "
                   f"{'+' if b.v_end > 0 else '-'}∞ (terminal velocity {fmt(b.v_end)})")
        else:
            why = (f"the motion ends at t ≈ {fmt(p.t1 + float(b.tau[-1]))} ({self._end_text(b)}) "
                   f"with s within [{fmt(smin)}, {fmt(smax)}]")
        return why


def _at_rest_within_input(c) -> bool:
    """a(v1) = 0 to within the uncertainty of the given v1 (dyncli.exact: 4
    round-offs): |a(v1)| is below the change of a over v1(1 ± 2⁻⁵¹).  So a v1
    given as the terminal velocity (``-sqrt(g/k)``) is the equilibrium."""
    from dyncli.exact import INPUT_ROUNDING

    v1 = c.v1
    lo, hi = c.a1(v1 * (1.0 - INPUT_ROUNDING)), c.a1(v1 * (1.0 + INPUT_ROUNDING))
    return bool(math.isfinite(lo) and math.isfinite(hi) and abs(c.a_v1) <= 0.5 * abs(hi - lo))


def motion(p, ans, rtol: float, atol: float) -> _Case3:
    """The case-3 motion of ``p`` (its branches of v built as the queries ask), answering into ``ans``."""
    return _Case3(p, ans, rtol, atol)


def moves(c: _Case3) -> bool:
    """False when the motion ``c`` is the equilibrium: a(v1) = 0, or zero within the input's rounding."""
    return not (c.a_v1 == 0 or _at_rest_within_input(c))


def solve(p, ans, rtol: float, atol: float) -> str:
    c = _Case3(p, ans, rtol, atol)
    ans.res.extra["solved"] = c         # the motion, for find's searches (solved.Solved)
    if c.a_v1 == 0 or _at_rest_within_input(c):
        c.equilibrium()
        return "quadrature"
    roots = False
    for i, q in enumerate(p.find):
        if q.kind == "t":
            ans.ask(i, c.t_query, q.t)
            roots = True
        elif q.kind == "v":
            ans.ask(i, c.v_query, q.v)
        else:
            ans.ask(i, c.s_query, q.s)
            roots = True
    return "quadrature+root" if roots else "quadrature"
