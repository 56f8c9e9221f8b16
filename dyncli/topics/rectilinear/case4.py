"""Case 4, a = a(s): energy (6.14, 6.15) and t(s) (6.12) by quadrature.

    v(s)^2 = v1^2 + 2 ∫_{s1}^{s} a(S) dS                        (6.14, 6.15)
    t(s)   = t1 + ∫_{s1}^{s} dS / |v(S)|                         (6.12)

From s1 the body moves in the direction of v1 (of a(s1) when v1 = 0) until v^2
vanishes: a turning point s_T (it comes back), an unstable equilibrium
approached asymptotically (v^2 has a double zero), a singularity of a, or
|s| -> infinity.  With turning points on both sides the motion is periodic.

Accuracy measures:

* v^2 at s is integrated from the nearest point where it is known exactly
  (s1, or a turning point where it is 0), so near a turning point it is a short
  integral of a non-vanishing a — no cancellation;
* at a turning point dt = ds/|v| has an inverse-square-root singularity; the
  substitution s = s_T - e u^2 makes the integrand 2u/|v| smooth;
* at an asymptotic equilibrium s_E the log singularity is removed by
  s = s_E - (s_E - s_M) e^(-x); towards infinity s = s_M + e c (e^x - 1) with
  c the smallest length of the problem, so that every scale from c to the cap
  |s| = 1e100 gets unit cells in x (the scan is geometric down to c as well);
  whether the body escapes in finite time (∫^∞ ds/|v| converges, a = s^3) or
  only grows without bound (a = 25 s) is read off the decay of dt/dx there;
  where v^2 overflows the doubles the leg is capped like |s| = 1e100;
* each leg (s1 -> end) is split at its midpoint so both ends get their own
  substitution; t-queries invert the leg times by a bracketed root search and
  periodic motion is reduced modulo the period.

This module holds the orbit and the queries (:class:`_Case4`); the scan from s1 is its
collaborator :class:`.case4_scan.Scan`, the ends, v^2 references and legs :mod:`.case4_legs`.
"""

from __future__ import annotations

import math
from typing import Iterable

import numpy as np

from dyncli.errors import NumericalError
from dyncli.rootfind import root_in_bracket
from dyncli.topics.rectilinear.case4_legs import End, Energy, Leg
from dyncli.topics.rectilinear import case4_sens as sens
from dyncli.topics.rectilinear.case4_scan import Scan
from dyncli.topics.rectilinear.constants import BIG, EPS, fmt
from dyncli.topics.rectilinear.work import SCALAR, Work


def _irs(a) -> tuple:
    from dyncli.expr.derivative import d_ir

    try:
        return a.ir, d_ir(a.ir, "s")
    except Exception:                # (no rule: min/max; a recursion too deep)
        return a.ir, None


class _Case4:
    """One case-4 motion: the orbit from s1 (its scans, legs and period, built by :meth:`setup`)
    and its queries; the interface :class:`.case4_scan.Motion` that its scans read."""

    def __init__(self, p, ans, rtol, atol):
        self.p, self.ans = p, ans
        self._fn = p.a.scalar_fn()
        self.irs = _irs(p.a)            # a and da/ds as IR (the enclosures of the scan, .enclose)
        self.work = Work(p, 4)          # accuracy.max_steps (.work)
        self.rtol, self.atol = rtol, atol
        # the quadratures' rtol: 100 x tighter, but not below what their error estimate can
        # certify (_quad.integrate floors it at 50 eps x the integral of |f|: a tighter rtol never
        # converges and bisects until the work budget refuses the problem, e.g. at rtol 1e-12)
        self.qr = max(rtol * 1e-2, 100 * EPS)
        self.s1, self.v1 = p.s1, p.v1
        if not abs(p.s1) <= 0.5 * BIG:
            from dyncli.errors import InputError

            raise InputError(f"|s1| = {abs(p.s1):.6g} m is beyond the positions case 4 (a = a(s)) tracks: the energy "
                             f"route (6.14) follows the body up to |s| = {BIG:g} m; use |s1| <= {0.5 * BIG:g} m "
                             "(e.g. shift or rescale the coordinate)", "s1")
        self.a_s1 = self.a1(p.s1)
        self._warned = False
        # positions beyond |s| = BIG are never reached (escape): they must not set the scan scale,
        # or the scan grid s1 + c g (|s| <= BIG) would hold no cell at all
        cands = [abs(p.s1)] + [abs(q.s - p.s1) for q in p.find if q.kind == "s" and abs(q.s) <= BIG]
        if self.a_s1 != 0 and p.v1 != 0:
            cands.append(p.v1 * p.v1 / abs(self.a_s1))
        cands = [c for c in cands if math.isfinite(c) and c > 0]
        # (capped so that the scan s1 + c g, |s| <= BIG, always has cells and the midpoint of an
        # escaping leg lies inside |s| < BIG)
        self.scale = min(max(cands), 0.25 * BIG) if cands else 1.0
        # the smallest of them (e.g. |s1| = 1e-151 next to v1^2/|a(s1)| = 4e133 for a = 25 s): the scan
        # and the escaping legs resolve every scale between it and BIG geometrically
        self.scale_min = min(max(min(cands), 1e-290), self.scale) if cands else self.scale
        self.amax = max(abs(self.a_s1), 1e-300)
        self.energy = Energy(self)
        self.scans: dict[int, dict] = {}

    def A(self, s):
        s = np.asarray(s, dtype=float)
        self.work.call(s.size)
        return self.p.a.evaluate(s=s)

    def a1(self, s: float) -> float:
        self.work.charge(SCALAR)
        return float(self._fn({'s': s}))

    def check(self, conv) -> None:
        if not np.all(conv) and not self._warned:
            self._warned = True
            self.ans.res.warn("quadrature did not reach the requested tolerance everywhere (non-smooth or singular a?); "
                              "see error_estimate")


    def scan(self, e: int, v2start: float) -> End:
        """Where the body goes from s1 in direction ``e`` (v² = ``v2start`` there): the scan's
        cells kept in ``scans[e]``, its nodes and stop made references of the energy."""
        found = Scan(self).run(e, v2start)
        if found.amax is not None:
            self.amax = max(self.amax, found.amax)
        self.scans[e] = {"s": found.s, "v2": found.v2, "a": found.a}
        self.energy.add(found.ref_s, found.ref_v2)
        if found.end.kind in ("turn", "asym"):
            self.energy.add(found.end.pos, 0.0)
        return found.end

    # -- the orbit --------------------------------------------------------------
    def setup(self) -> bool:
        """False for an equilibrium (v1 = 0 and a(s1) = 0)."""
        v1 = self.v1
        if v1 == 0 and self.a_s1 == 0:
            return False
        if v1 != 0:
            e = 1 if v1 > 0 else -1
            self.endF = self.scan(e, v1 * v1)
            self.endB = self.scan(-e, v1 * v1)
            start_turn = False
        else:
            e = 1 if self.a_s1 > 0 else -1
            self.endF = self.scan(e, 0.0)
            self.endB = End("turn", self.s1)
            self.scans[-e] = {"s": np.array([self.s1]), "v2": np.array([0.0]), "a": np.array([self.a_s1])}
            start_turn = True
        self.e = e
        self.F = Leg(self, self.s1, start_turn, self.endF, e)
        self.B = Leg(self, self.s1, start_turn, self.endB, -e)
        self.periodic = self.endF.kind == "turn" and self.endB.kind == "turn"
        F, B = self.F, self.B
        # legs in the order of travel forward in time: (leg, reversed, sign of v, first time)
        self.fwd = [(F, False, e)]
        if self.endF.kind == "turn":
            self.fwd += [(F, True, -e), (B, False, -e)]
            if self.periodic:
                self.fwd += [(B, True, e)]
        self.bwd = [(B, False, e)]
        if self.endB.kind == "turn":
            self.bwd += [(B, True, -e), (F, False, -e)]
        self.period = 2 * (F.duration + B.duration) if self.periodic else math.inf
        if self.periodic and not (self.period > 0 and math.isfinite(self.period)):
            raise NumericalError(f"the oscillation between the turning points s = {fmt(self.endB.pos)} and "
                                 f"{fmt(self.endF.pos)} has a period of {fmt(self.period)} s in doubles: its "
                                 "amplitude is below the rounding of s (or its period beyond the doubles); rescale "
                                 "the units of s or v1")
        sens.setup(self)
        return True

    def _walk(self, legs, tau: float):
        """State at local time tau >= 0 along the legs: (s, v, None, None) or
        (None, None, end, time from t1 at which the motion ends)."""
        total = 0.0
        for leg, rev, sign in legs:
            d = leg.duration
            if tau <= d:
                local = d - tau if rev else tau
                if not rev and tau > leg.reach:
                    if leg.end.kind == "asym":
                        return leg.B, 0.0, None, None
                    total += leg.reach
                    break
                s, av, err = leg.state_at(local)
                self.last_err = err
                return s, sign * av, None, None
            tau -= d
            total += d
        return None, None, legs[-1][0].end, total

    def state(self, T: float):
        self.last_err = 0.0
        tau = T - self.p.t1
        self.sens = sens.time_sens(self, self.fwd if tau >= 0 else self.bwd, abs(tau))
        if self.periodic:
            P = self.period
            r = math.fmod(tau, P)
            if r < 0:
                r += P
            return self._walk(self.fwd, r)
        if tau >= 0:
            return self._walk(self.fwd, tau)
        return self._walk(self.bwd, -tau)

    def _reason_end(self, end: End, t_end: float, forward: bool) -> str:
        when = "after" if forward else "before"
        at = f"at t ≈ {fmt(t_end)}"
        if end.kind == "inf":
            lead = f"|s| exceeds {BIG:g}"
            if math.isfinite(end.pos):
                lead = f"the body passes s ≈ {fmt(end.pos)}, beyond which v^2 exceeds the doubles,"
            if end.finite_time:
                if math.isfinite(end.pos):
                    return f"{lead} {at} (escape to infinity in finite time); nothing is defined {when} that"
                return f"{lead} (escape to infinity in finite time) {at}; nothing is defined {when} that"
            how = ("|s| grows without bound, reaching infinity only as t → ∞" if end.finite_time is False
                   else "|s| grows without bound")
            return f"{lead} {at} ({how}); the motion is not followed {when} that"
        if end.kind == "sing":
            return f"the body reaches s ≈ {fmt(end.pos)}, where a is singular, {at}; the motion is not defined {when} that"
        return end.describe()

    # -- queries ------------------------------------------------------------------
    def t_query(self, i: int, T: float) -> None:
        s, v, end, t_end = self.state(T)
        forward = T >= self.p.t1
        if s is None:
            self.ans.unreached(i, self._reason_end(end, self.p.t1 + (t_end if forward else -t_end), forward))
            return
        # an error e of the time along the leg moves the state along the trajectory: s by |v| e, v by |a| e
        dt, ds = self.sens           # next to a separatrix: the energy's rounding (case4_sens)
        e = self.last_err + dt
        self.ans.reached(i, T, s, v, err=(0.0, abs(v) * e + ds, abs(self.a1(s)) * e))

    def _time_on(self, k: int, s: float) -> float:
        """Time after t1 at which leg k of the forward sequence passes s (last_err counts the
        turning points' sensitivity up to that leg's, case4_sens)."""
        t0 = sum(leg.duration for leg, _, _ in self.fwd[:k])
        leg, rev, _ = self.fwd[k]
        tl, err = leg.time_to(s)
        dt, self.turn_ds = sens.time_sens(self, self.fwd, 0.0, upto=k)
        self.last_err = err + dt
        return t0 + (leg.duration - tl if rev else tl)

    def s_query(self, i: int, S: float) -> None:
        p, ans = self.p, self.ans
        if S == p.s1:
            ans.reached(i, p.t1, p.s1, p.v1)
            return
        for k, (leg, rev, sign) in enumerate(self.fwd):
            if rev:
                continue
            lo, hi = sorted((leg.A, leg.B))
            inside = lo <= S <= hi
            if leg.end.kind in ("asym", "inf") and S == leg.B:
                inside = False
            s_at = S
            if leg.end.kind == "turn" and abs(S - leg.B) <= self.rtol * max(abs(S), abs(leg.B - leg.A)) + self.atol:
                inside, s_at = True, leg.B       # the target is the turning point (grazing)
            if inside:
                t = p.t1 + self._time_on(k, s_at)
                err = self.last_err
                if not ans.beyond_t_max(i, t):
                    s, v, _, _ = self.state(t)
                    ans.reached(i, t, S, v if s is not None else 0.0, err=(err, 0.0, 0.0))
                return
        ends = [self.endF] + ([self.endB] if self.endF.kind == "turn" else [])
        ans.unreached(i, "it lies beyond the reachable positions: " + "; ".join(e.describe() for e in ends))

    def v_query(self, i: int, V: float) -> None:
        p, ans = self.p, self.ans
        if V == p.v1:
            ans.reached(i, p.t1, p.s1, p.v1)
            return
        V2 = V * V
        for k, (leg, rev, sign) in enumerate(self.fwd):
            if V != 0 and (V > 0) != (sign > 0):
                continue
            if V == 0:
                if not rev and leg.end.kind == "turn":
                    t = p.t1 + self._time_on(k, leg.B)
                    if not ans.beyond_t_max(i, t):
                        ans.reached(i, t, leg.B, 0.0, err=(self.last_err, self.turn_ds, 0.0))
                    return
                continue
            sc = self.scans[leg.e]
            ss, v2, av = sc["s"], sc["v2"], sc["a"]
            hit = self._first_on_cells(ss, v2, av, V2, rev)
            if hit is not None:
                t = p.t1 + self._time_on(k, hit)
                if not ans.beyond_t_max(i, t):
                    ans.reached(i, t, hit, V, err=(self.last_err, 0.0, 0.0))
                return
        v2s = np.concatenate([self.scans[leg.e]["v2"] for leg, _, _ in self.fwd])
        lo, hi = math.sqrt(max(float(v2s.min()), 0.0)), math.sqrt(max(float(v2s.max()), 0.0))
        if V == 0:
            ans.unreached(i, "the body never stops: " + "; ".join(dict.fromkeys(e.describe() for e in (self.endF, self.endB))))
        else:
            where = f"for t >= t1 the speed stays within [{fmt(lo)}, {fmt(hi)}]"
            if lo <= abs(V) <= hi:
                where += ", but never with this sign"
            ans.unreached(i, where)

    def _first_on_cells(self, ss, v2, av, V2: float, rev: bool):
        """First position (in travel order) with v^2 = V2 on the scanned cells."""
        n = len(ss)
        cells: Iterable[int] = range(n - 1)
        if rev:
            cells = reversed(range(n - 1))
        for k in cells:
            a_, b_ = (k, k + 1) if not rev else (k + 1, k)
            s_a, s_b = float(ss[a_]), float(ss[b_])
            w_a, w_b = float(v2[a_]), float(v2[b_])
            tol = self.rtol * max(V2, abs(w_a), abs(w_b)) + self.atol * math.sqrt(max(V2, 1e-300))
            pieces: list[tuple] = [(s_a, w_a, s_b, w_b)]
            if av[k] * av[k + 1] < 0:   # an extremum of v^2 inside the cell
                sm = root_in_bracket(self.a1, float(ss[k]), float(ss[k + 1]), float(av[k]), float(av[k + 1]))
                wm = float(self.energy.v2(sm, 0.0))
                pieces = [(s_a, w_a, sm, wm, True), (sm, wm, s_b, w_b, False)]
            for pc in pieces:
                s0, w0, s1_, w1 = pc[:4]
                ext = pc[4] if len(pc) > 4 else False
                if ext and abs(w1 - V2) <= tol:
                    return s1_
                if min(w0, w1) <= V2 <= max(w0, w1):
                    if w0 == V2:
                        return s0
                    return root_in_bracket(lambda s: float(self.energy.v2(s, 0.0)) - V2, s0, s1_, w0 - V2, w1 - V2)
        return None

    def equilibrium(self) -> None:
        p, ans = self.p, self.ans
        for i, q in enumerate(p.find):
            if q.kind == "t":
                ans.reached(i, q.t, p.s1, 0.0)
            elif (q.kind == "v" and q.v == 0) or (q.kind == "s" and q.s == p.s1):
                ans.reached(i, p.t1, p.s1, 0.0)
            else:
                ans.unreached(i, f"v1 = 0 and a(s1) = 0: the body rests at s1 = {fmt(p.s1)} (equilibrium)")


def motion(p, ans, rtol: float, atol: float) -> _Case4:
    """The case-4 motion of ``p`` (scans and legs built by its ``setup()``), answering into ``ans``."""
    return _Case4(p, ans, rtol, atol)


def solve(p, ans, rtol: float, atol: float) -> str:
    c = _Case4(p, ans, rtol, atol)
    ans.res.extra["solved"] = c         # the motion, for find's searches (solved.Solved)
    if not c.setup():
        c.equilibrium()
        return "quadrature"
    for i, q in enumerate(p.find):
        if q.kind == "t":
            ans.ask(i, c.t_query, q.t)
        elif q.kind == "v":
            ans.ask(i, c.v_query, q.v)
        else:
            ans.ask(i, c.s_query, q.s)
    if c.periodic:
        ans.res.results["period"] = c.period
    sens.warn(c, ans, rtol)
    return "quadrature+root"
