"""General rectilinear motion a = a(t, s, v): the ODE (6.2c,e)

    ds/dt = v,   dv/dt = a(t, s, v),   s(t1) = s1, v(t1) = v1   (6.3a,b)

integrated step by step with one of scipy's ``OdeSolver`` classes (DOP853 by
default) at the user's rtol and atol.

First crossings: after every accepted step the extremes of s (turning points) and of v
inside the step are the critical points of the step's interpolant, a polynomial, decided
exactly (:func:`dyncli.rootfind.polynomial_extremes`, never by samples).  Between them s
(resp. v) is monotone, so a target is crossed inside such a piece exactly when it lies
between the piece's end values — an excursion narrower than the step, crossing the target
twice inside it, included — and the crossing is then polished by a bracketed root search on
the interpolant.  A target equal to an extremum (grazing: no sign change, possibly within one
step of the turning point) is detected at the extremum and reported there.  While a v or s
query is open every step builds its interpolant (DOP853's costs three more evaluations of a);
otherwise only the steps that hold a ``t`` query do, and the integration stops as soon as
every query is answered.

Work budget: :class:`dyncli.ode.Budget` counts every accepted step of the
solve; one that needs more than ``accuracy.max_steps`` steps (default
``DEFAULT_MAX_STEPS`` = 10,000, about 0.7 s) is refused with a NumericalError as soon as the
projection towards the furthest time asked for shows it.  A state that overflows (inf/NaN) ends the integration
there: the queries beyond it are answered ``reached: false`` with a warning
naming the time where it blew up.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dyncli import ode
from dyncli.rootfind import root_in_bracket
from dyncli.topics.rectilinear.constants import fmt


#: default accuracy.max_steps of one run of this route: ~65 us a step (DOP853, 12
#: evaluations of the expression), so a solve stays near 0.7 s (its check solve has its own)
DEFAULT_MAX_STEPS = 10_000


class _Run:
    def __init__(self, p, method: str, rtol: float, atol: float):
        self.p = p
        self.method = method
        self.rtol = max(rtol, 2.5e-14)
        self.atol = atol
        self.fn = fn = p.a.scalar_fn()
        # all integrations of this run (the check solve of accuracy.estimate has its own)
        self.budget = ode.Budget(p.accuracy.max_steps, default=min(ode.MAX_STEPS, DEFAULT_MAX_STEPS))
        # the rate checked by rhs itself (ode.finite's test, one call less per evaluation)
        self._cls = ode.budgeted(method, self.budget, stop_nonfinite=True, check_finite=False)
        self.records: list[Record] = []     # this run's marches as they went (DOP853: replayed by Dense)
        isfinite, NonFinite = math.isfinite, ode.NonFiniteRate

        def rhs(t, y):
            s, v = y[0], y[1]
            a = fn({"t": t, "s": s, "v": v})
            if not isfinite(v + a) and not np.all(np.isfinite([v, a])):
                raise NonFinite(t, y)
            return [v, a]

        self.rhs = rhs

    def acc(self, t, s, v) -> float:
        return float(self.fn({"t": t, "s": s, "v": v}))

    def march(self, t0: float, y0, t_end: float, visit, replay=()):
        """Step from (t0, y0) towards t_end, calling ``visit(step)`` after every accepted
        step until it returns True.  Returns None, or (t, why) where the integration failed.
        ``replay``: earlier marches of the same problem at the same tolerances (:class:`Record`);
        the steps of one of them that this march would take as well are handed to ``visit`` as
        they were, and the march goes on from there (:meth:`Record.prefix`: the same steps, not
        taken again)."""
        kw = {"jac": None} if self.method in ("Radau", "LSODA") else {}
        with np.errstate(all="ignore"):
            solver = self._cls(self.rhs, t0, np.array(y0, dtype=float), t_end, rtol=self.rtol, atol=self.atol, **kw)
            rec = None
            if hasattr(solver, "dense_later"):           # dyncli's DOP853: its steps recorded
                rec = Record(self, t0, y0, t_end, solver)
                self.records.append(rec)
            step = _Step(self, solver)
            for old in replay:
                if rec is None:                          # (scipy's classes: nothing recorded to replay)
                    break
                done = old.prefix(rec, solver, t_end)
                for t_old, t, y, f, h_abs, interp in done:
                    solver.t_old, solver.t, solver.y, solver.f, solver.h_abs = t_old, t, y, f, h_abs
                    rec.steps.append((t_old, t, y, f, h_abs, interp))
                    if solver.direction * (t - t_end) >= 0:
                        solver.status = "finished"
                    step.advance(interp)
                    if visit(step):
                        return None
                if done:
                    break
            try:
                for _ in ode.steps(solver, None, self.method):     # the budgeted class counts the steps
                    interp = rec.add(solver) if rec is not None else None
                    step.advance(interp)
                    if visit(step):
                        return None
            except ode.StepFailed as exc:
                return exc.t, exc.reason
        return None


class Record:
    """One DOP853 march of a :class:`_Run` as it went: its start, its bound, its first step size
    and, after every accepted step, (t_old, t, y, f, h_abs, the step's interpolant made on first
    use).  A march of the same problem towards another bound takes the same steps as long as the
    first try of a step does not pass that bound (a rejected try only shortens the step), from
    the same first step size (the starting step depends on the interval): :meth:`prefix`."""

    def __init__(self, run: _Run, t0: float, y0, t_bound: float, solver):
        self.key = (run.method, run.rtol, run.atol, run.p.a, float(t0), tuple(float(c) for c in y0))
        self.t_bound, self.h0, self.direction = float(t_bound), float(solver.h_abs), float(solver.direction)
        self.max_step = solver.max_step
        self.steps: list[tuple] = []

    def add(self, solver):
        interp = solver.dense_later()
        self.steps.append((solver.t_old, solver.t, solver.y, solver.f, solver.h_abs, interp))
        return interp

    def prefix(self, rec: "Record", solver, t_end: float) -> list[tuple]:
        """The recorded steps the march ``rec`` (just started, ``solver`` its stepper) towards
        ``t_end`` would take too: the same problem, start, tolerances and first step size, and
        every step whose first try (the step size left by the step before, as DOP853 tries it)
        does not pass t_end (a bound no further than this record's)."""
        d = self.direction
        if (rec.key != self.key or rec.h0 != self.h0 or rec.direction != d or rec.max_step != self.max_step
                or d * (self.t_bound - t_end) < 0):
            return []
        out = []
        t, h_abs = rec.key[4], self.h0
        for st in self.steps:
            min_step = 10 * np.abs(np.nextafter(t, d * np.inf) - t)
            h = self.max_step if h_abs > self.max_step else (min_step if h_abs < min_step else h_abs)
            if d * ((t + h * d) - t_end) > 0:
                break
            out.append(st)
            t, h_abs = st[1], st[4]
        return out


class _Step:
    """The last accepted step of a march: its ends (t, y, a) and its interpolant, built on
    first use."""

    def __init__(self, run: _Run, solver):
        self.run, self.solver = run, solver
        self.tb, self.yb = solver.t, solver.y.copy()
        self.ab = run.acc(self.tb, *self.yb)
        self.ta: float | None = None
        self.ya: Any = None
        self.aa: float | None = None
        self._dense: Any = None
        self._interp: Any = None
        self._ext: list[list[float]] | None = None

    def advance(self, interp=None) -> None:
        """On to the solver's last step (``interp``: its interpolant, made on first use; None:
        the solver's dense output, made when asked for)."""
        sv = self.solver
        self.ta, self.ya, self.aa = self.tb, self.yb, self.ab
        self.tb, self.yb = float(sv.t), sv.y.copy()
        f = getattr(sv, "f", None)     # the rate at the step's end (explicit Runge-Kutta: FSAL)
        self.ab = float(f[1]) if f is not None else self.run.acc(self.tb, *self.yb)
        self._dense, self._ext, self._interp = None, None, interp

    def dense(self):
        """The step's interpolant (made now if it was not yet)."""
        if self._dense is None:
            self._dense = self._interp.made() if self._interp is not None else ode.dense_output(self.solver)
        return self._dense

    def y(self, t: float):
        """The state at t inside the step."""
        if t == self.tb:
            return self.yb.copy()
        return self.dense()(t)

    def a(self, t: float) -> float:
        y = self.y(t)
        return self.run.acc(t, y[0], y[1])

    def extremes(self, comp: int) -> list[float]:
        """The critical points of s (``comp`` 0) or v (1) inside the step: of its interpolant, a
        polynomial, decided exactly (:func:`dyncli.rootfind.polynomial_extremes`)."""
        if self._ext is None:
            from dyncli.rootfind import polynomial_extremes

            (self._ext,) = polynomial_extremes([(self.dense(), self.ta, self.tb)])
        return self._ext[comp]


def solve(p, ans, method: str, rtol: float, atol: float) -> str:
    """Answer every query of ``p`` by the ODE route; returns the method name."""
    r = _Run(p, method, rtol, atol)
    t1, s1, v1 = p.t1, p.s1, p.v1
    tq = [(i, q.t) for i, q in enumerate(p.find) if q.kind == "t"]
    vq = {i: q.v for i, q in enumerate(p.find) if q.kind == "v"}
    sq = {i: q.s for i, q in enumerate(p.find) if q.kind == "s"}
    ans.at_start(vq, sq)
    for i, T in tq:
        if T == t1:
            ans.reached(i, t1, s1, v1)
    _times(r, [(i, T) for i, T in tq if T < t1], -1, ans)
    fwd = [(i, T) for i, T in tq if T > t1]
    if not vq and not sq:
        _times(r, fwd, 1, ans)
    else:
        _Forward(r, ans, fwd, vq, sq).run()
    ans.res.extra["nsteps"] = r.budget.n      # accepted steps (the nominal error estimate)
    ans.res.extra["marches"] = r.records      # replayed by Dense (the motion of every find query)
    return f"ode:{method}"


def _stopped(ans, queries, failed, t_end: float) -> None:
    tf, msg = failed if failed else (t_end, "not reached")
    for i, _ in queries:
        ans.unreached(i, f"the integration stopped at t = {fmt(tf)} ({msg}); the solution probably blows up")


def _times(r, queries: list, direction: int, ans) -> None:
    """Only t-queries on one side of t1: one integration to the furthest of them, the state
    read at those times (the interpolant only on the steps that hold one)."""
    if not queries:
        return
    p = r.p
    todo = sorted(queries, key=lambda q: q[1] * direction)
    t_goal = todo[-1][1]
    r.budget.leg(p.t1, t_goal)

    def visit(step) -> bool:
        while todo and (todo[0][1] - step.tb) * direction <= 0:
            i, T = todo.pop(0)
            s, v = step.y(T)
            ans.reached(i, T, s, v)
        return not todo

    failed = r.march(p.t1, [p.s1, p.v1], t_goal, visit)
    _stopped(ans, todo, failed, p.t1)


class _Forward:
    """The forward march with v/s queries: crossings on every step, t queries read on the way,
    until every query is answered or t1 + t_max is passed."""

    def __init__(self, r: _Run, ans, fwd: list, vq: dict, sq: dict):
        p = r.p
        self.r, self.ans, self.vq, self.sq = r, ans, vq, sq
        self.todo = sorted(fwd, key=lambda q: q[1])
        self.horizon = p.t1 + p.t_max
        self.t_need = self.todo[-1][1] if self.todo else p.t1
        self.lo = [p.s1, p.v1]
        self.hi = [p.s1, p.v1]
        self.scale = [abs(p.s1), abs(p.v1)]
        self.entered: dict[int, tuple] = {}    # query -> (when its value came within its tolerance to stay, its rate)

    def run(self) -> None:
        r, p, ans = self.r, self.r.p, self.ans
        t_end = max(self.t_need, self.horizon)
        r.budget.leg(p.t1, t_end)
        self.t_reached = p.t1
        failed = r.march(p.t1, [p.s1, p.v1], t_end, self.visit)
        _stopped(ans, self.todo, failed, self.t_reached)
        why = (f"the integration stopped at t = {fmt(failed[0])} ({failed[1]})" if failed
               else f"search horizon t1 + t_max = {fmt(self.horizon)}")
        (smin, vmin), (smax, vmax) = self.lo, self.hi
        for i in self.vq:
            ans.unreached(i, f"v stays within [{fmt(vmin)}, {fmt(vmax)}] for t >= t1 ({why})")
        for i in self.sq:
            ans.unreached(i, f"s stays within [{fmt(smin)}, {fmt(smax)}] for t >= t1 ({why})")

    def visit(self, step) -> bool:
        todo, ans = self.todo, self.ans
        self.t_reached = step.tb
        if step.ta < self.horizon and (self.vq or self.sq):
            for c in (0, 1):
                x = float(step.yb[c])
                self.lo[c], self.hi[c] = min(self.lo[c], x), max(self.hi[c], x)
                self.scale[c] = max(self.scale[c], abs(x))
            self._crossings(step, min(step.tb, self.horizon))
        while todo and todo[0][1] <= step.tb:
            i, T = todo.pop(0)
            s, v = step.y(T)
            ans.reached(i, T, s, v)
        return not todo and (not (self.vq or self.sq) or step.tb >= self.horizon)

    def _crossings(self, step, tb: float) -> None:
        """Answer the v/s queries first crossed in [step.ta, tb]."""
        ta = step.ta
        # the step cut at the extremes of v (v queries) or of s (s queries) of its interpolant:
        # monotone between them, so a target is crossed in a piece exactly when it lies between
        # the piece's end values (an excursion inside one step included); and at the zero of the
        # true rate (a, resp. v) when it changes sign over the step: an extremum on a step's end
        # that neither step's interpolant has inside it (two polynomials meet there)
        for queries, comp, ga, gb, g in ((self.vq, 1, step.aa, step.ab, step.a),
                                         (self.sq, 0, step.ya[1], step.yb[1], lambda t: float(step.y(t)[1]))):
            if not queries:
                continue
            xa, xb = float(step.ya[comp]), float(step.yb[comp])
            ev = _event(g, ta, step.tb, ga, gb)
            cuts = sorted({x for x in step.extremes(comp) + ([ev] if ev is not None else []) if x < tb})
            xe = [float(step.y(x)[comp]) for x in cuts]
            for x in xe:
                self.scale[comp] = max(self.scale[comp], abs(x))
                self.lo[comp], self.hi[comp] = min(self.lo[comp], x), max(self.hi[comp], x)
            vals = [xa] + xe + [xb if tb == step.tb else float(step.y(tb)[comp])]
            r, lo, hi = self.r, min(vals), max(vals)
            if not any(lo - (r.rtol * max(abs(X), self.scale[comp]) + r.atol) <= X
                       <= hi + r.rtol * max(abs(X), self.scale[comp]) + r.atol for X in queries.values()):
                continue              # the common case: nothing crossed or grazed on this step
            self._pieces(step, queries, comp, [ta] + cuts + [tb], vals)

    def _pieces(self, step, queries: dict, comp: int, bps: list, vals: list) -> None:
        r, ans = self.r, self.ans
        for i, X in list(queries.items()):
            tol = r.rtol * max(abs(X), self.scale[comp]) + r.atol
            for k in range(len(bps) - 1):
                lo, hi = min(vals[k], vals[k + 1]), max(vals[k], vals[k + 1])
                if k + 1 < len(bps) - 1 and abs(X - vals[k + 1]) <= tol:
                    t, graze = bps[k + 1], True      # the target is the extremum
                    xt = vals[k + 1]
                elif lo <= X <= hi:
                    t, graze = root_in_bracket(lambda t: float(step.y(t)[comp]) - X, bps[k], bps[k + 1],
                                      vals[k] - X, vals[k + 1] - X), False
                    xt = X
                else:
                    self._band(step, comp, i, X, tol, bps[k], bps[k + 1], vals[k], vals[k + 1])
                    continue
                if self._creeps(step, comp, i, X, tol, bps[k], vals[k], t, xt):
                    ans.unreached(i, f"{'sv'[comp]} only creeps toward it: within its tolerance from t = "
                                  f"{fmt(self.entered[i][0])} on while still moving toward it (an asymptote, "
                                  "reached as t → ∞; the integration's rounding met it later)")
                    del queries[i]
                    break
                if not ans.beyond_t_max(i, t):
                    y = step.y(t)
                    if not graze:
                        y[comp] = X
                    ans.reached(i, t, y[0], y[1])
                del queries[i]
                break


    def _band(self, step, comp: int, i: int, X: float, tol: float, ta: float, tb: float, xa: float, xb: float) -> None:
        """Keep when query i's value came within ``tol`` of X to stay, and its rate then (the piece
        [ta, tb] of ``step``, monotone from xa to xb): forgotten once it leaves the band."""
        if abs(xb - X) > tol:
            self.entered.pop(i, None)
        elif i not in self.entered:
            edge = ta if abs(xa - X) <= tol else root_in_bracket(
                lambda t: abs(float(step.y(t)[comp]) - X) - tol, ta, tb, abs(xa - X) - tol, abs(xb - X) - tol)
            self.entered[i] = (edge, abs(float(step.y(edge)[1]) if comp == 0 else step.a(edge)))

    def _creeps(self, step, comp: int, i: int, X: float, tol: float, ta: float, xa: float, t: float, xt: float) -> bool:
        """Whether meeting X at t (crossed, or touched at an extreme: ``xt`` the value there) ends a
        creep rather than a pass: the value came within ``tol`` of X at ``edge`` and took longer
        than 4 tol / (its rate there) to meet it (a pass or a touch takes at most 2 tol / rate) — an
        asymptote (a critically damped return, s = e^-t, creeps toward 0 and the integration's
        rounding crosses it tens of time constants later), as the ``when`` search decides."""
        self._band(step, comp, i, X, tol, ta, t, xa, xt)
        edge, rate = self.entered.get(i, (t, 0.0))
        return edge < t and (t - edge) * rate > 4 * tol


def _event(g, ta: float, tb: float, ga: float, gb: float):
    """The zero of g in the step (ta, tb] when g changes sign over it (or reaches 0 at its
    end), else None."""
    if ga == 0 or (gb != 0 and (ga > 0) == (gb > 0)):
        return None
    if gb == 0:
        return tb
    return root_in_bracket(g, ta, tb, ga, gb)


class Dense:
    """The motion from t_start (<= t1) to t_end (or to where an integration fails: ``start``,
    ``end``) as every accepted step's interpolant, integrated from t1 each way: the queries of
    every motion (:mod:`.find`) search it without integrating again.  ``breaks``: the steps' ends
    (ascending); ``extremes``: the breaks with every critical point of s and of v inside each
    step added — the interpolant of a step is a polynomial, whose extremes are decided exactly
    (:func:`dyncli.rootfind.polynomial_extremes`), so s and v are monotone between two of them:
    a target is crossed there exactly when it lies between the values at their ends, and no
    excursion, however narrow, lies between two of them unseen.  ``replay``: the route's own
    marches (:func:`solve`'s, ``res.extra["marches"]``), whose steps it takes as they were as far
    as they are its own (:meth:`_Run.march`): the motion is integrated once."""

    def __init__(self, p, method: str, rtol: float, atol: float, t_end: float, t_start: float | None = None,
                 replay=()):
        import bisect

        from dyncli.rootfind import polynomial_extremes

        self._bisect = bisect.bisect_left
        self.p, self.run = p, _Run(p, method, rtol, atol)
        t1 = float(p.t1)
        sides = []                                  # (step ends from t1 outward, interpolants, where it ends)
        for goal in (t_end, t1 if t_start is None else t_start):
            ends, steps = [t1], list[Any]()

            def visit(step, ends=ends, steps=steps):
                ends.append(float(step.tb))
                steps.append(step.dense())            # made now, while the solver is on this step
                return False

            failed = self.run.march(t1, [p.s1, p.v1], goal, visit, replay) if goal != t1 else None
            reach = float(failed[0]) if failed else float(goal)
            if failed and (ends[-1] - reach) * (goal - t1) > 0:
                reach = ends[-1]
            sides.append((ends, steps, reach))
        (fe, fs, self.end), (be, bs, self.start) = sides
        # ascending: the backward steps reversed, then the forward ones
        self.breaks = be[:0:-1] + fe
        self.steps = bs[::-1] + fs
        cuts = polynomial_extremes((d, self.breaks[k], self.breaks[k + 1]) for k, d in enumerate(self.steps))
        self.extremes = sorted(set(self.breaks).union(x for piece in cuts for comp in piece for x in comp))

    def __call__(self, p, times) -> list[dict]:
        times = [float(x) for x in times]
        if len(times) > 1 and self._stack() is not None:
            return self._many(times)
        out: list[dict[str, Any]] = []
        for t in times:
            if t == self.p.t1 or not self.steps:
                s, v = self.p.s1, self.p.v1
            elif t > self.breaks[-1] or t < self.breaks[0]:
                out.append({"reached": False})
                continue
            else:
                k = min(max(self._bisect(self.breaks, t) - 1, 0), len(self.steps) - 1)
                s, v = (float(c) for c in self.steps[k](t))
            out.append({"t": t, "s": s, "v": v, "a": self.run.acc(t, s, v), "reached": True})
        return out

    def _stack(self):
        """Every step's interpolant stacked (:class:`dyncli.dop853.DenseStack`) when each is a
        DOP853 :class:`dyncli.dop853.DenseOutput` of one shape, else None; made once."""
        if not hasattr(self, "_dense_stack"):
            from dyncli.dop853 import DenseOutput, DenseStack

            ok = (self.steps and all(type(d) is DenseOutput for d in self.steps)
                  and len({d.F.shape for d in self.steps}) == 1)
            self._dense_stack = DenseStack(self.steps) if ok else None
        return self._dense_stack

    def _many(self, times: list[float]) -> list[dict]:
        """:meth:`__call__` at many times in one evaluation of the stacked steps (the same step
        for each time, the same arithmetic: the same values)."""
        t = np.array(times, dtype=float)
        inside = (t >= self.breaks[0]) & (t <= self.breaks[-1]) & (t != self.p.t1)
        k = np.clip(np.searchsorted(np.array(self.breaks), t, side="left") - 1, 0, len(self.steps) - 1)
        rows = self._stack()(k[inside], t[inside]).tolist()
        out: list[dict[str, Any]] = []
        j = 0
        for x, ok in zip(times, inside.tolist()):
            if ok:
                s, v = rows[j]
                j += 1
            elif x == self.p.t1:
                s, v = self.p.s1, self.p.v1
            else:
                out.append({"reached": False})
                continue
            out.append({"t": x, "s": s, "v": v, "a": self.run.acc(x, s, v), "reached": True})
        return out
