"""The numerical runner of the ODE routes: the one policy they share (docs/accuracy.md).

* Work budget: :class:`Budget` counts accepted steps of one solve against
  ``accuracy.max_steps`` (default ``MAX_STEPS`` or the type's own); every ODE route
  counts through it (:func:`integrate`, or :func:`budgeted` solver classes for
  ``solve_ivp``), and a run is refused (:class:`OverBudget`) as soon as an
  extrapolation shows it will not fit; the same projection of the solve's CPU against its
  budget (``accuracy.max_cpu``, :mod:`dyncli.cputime`) refuses with :class:`OverCpu`.
* Non-finite detection: :func:`finite` raises :class:`NonFiniteRate` on a rate that
  is inf or NaN (scipy's step-size control would loop on it).
* Check solve: :func:`check_solve` — one divisor (``CHECK_DIV`` = 100: rtol and atol
  of the check run), one fallback (over the budget: one run at ``LOOSER_MUL`` × the
  tolerances, with :func:`fallback_warning`; any other failure: a null estimate and a
  warning, the answer stands).
* ``error_estimate``: :func:`relative_difference`, the largest difference between the
  reported and the check run of every reported quantity, each relative to its own scale
  over the run.
* Stepping: :func:`steps`, the one loop over the stepper's ``step`` (scipy's ``OdeSolver`` interface,
  which dyncli's own DOP853 of :mod:`dyncli.dop853` has too; every route's
  own loop — :func:`integrate`, the particle's phases, the top's tracker, rectilinear's event
  march — iterates it), each step counted, a failed step :class:`StepFailed`.
* Dense output only through the public ``dense_output()`` of the stepper
  (:func:`dense_output`), never its private interpolant internals.
* The error_estimate without a check solve: :func:`nominal_estimate`.

The loop lets the caller read the state at the requested times from each step's dense
output, look at every accepted step (``on_step``) and project the state back onto invariant
manifolds after it (``project``; method "projected" = DOP853 + projection).

scipy is imported lazily, only when a route asks for one of its integrators.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli import cputime
from dyncli.errors import NumericalError
from dyncli.integrators import METHODS, RTOL_FLOOR, floor_rtol, solver_class  # noqa: F401 (ode.RTOL_FLOOR)

MAX_STEPS = 50_000       # default budget (~1-2 s of Python stepping); accuracy.max_steps overrides it
CPU_PROBE = 32           # every this many steps, the solve's CPU is projected (dyncli.cputime.over_budget)
PROBE_STEPS = 2_000      # every this many steps, project the run's total and refuse early


# ---------------------------------------------------------------------------
# the work budget, shared by every route that integrates

def refusal(t_goal: float, need: float, limit: float) -> str:
    """The one message of a run refused by its step budget."""
    return (f"the run to t = {t_goal:.6g} s needs about {need:.3g} integrator steps, more than the budget of "
            f"{limit}: shorten the time span, loosen accuracy.rtol, or raise accuracy.max_steps")


class OverBudget(NumericalError):
    """A run refused by its :class:`Budget`; ``t``, ``y``, ``h``: the state and
    step size where it was refused (for hints such as stiffness); ``stiff``: a route judged it stiff."""

    def __init__(self, t_goal: float, need: float, limit: float, t: float, y=None, h: float = 0.0, message=None):
        super().__init__(message or refusal(t_goal, need, limit))
        self.t_goal, self.need, self.limit, self.t, self.h, self.stiff = t_goal, need, limit, t, h, False
        self.y = None if y is None else np.array(y, dtype=float)


class Budget:
    """Accepted integrator steps of one solve (over all its integrations)
    against ``limit`` (``accuracy.max_steps``; None: ``default``, else
    MAX_STEPS).

    An integration announces where it heads with :meth:`leg` (t0 towards
    t_goal, either direction; chunks of one leg share it).  Every ``probe``
    steps the total is projected from the steps per unit time of the last
    ``probe`` steps, and the run is refused (:class:`OverBudget`) as soon as
    the projection — or the count itself — exceeds the limit."""

    def __init__(self, limit: int | None = None, *, default: int | None = None, probe: int = PROBE_STEPS):
        self.limit = int(limit or default or MAX_STEPS)
        self.probe = int(probe)
        self.n = 0
        self.hmax = 0.0
        self.leg(0.0, 0.0)

    def leg(self, t0: float, t_goal: float) -> None:
        self.t0, self.goal = float(t0), float(t_goal)
        self._n_leg = self._n_win = 0
        self._t_win = self._t_cpu0 = self.t0
        self._cpu_leg0 = cputime.thread_cpu()

    def tick(self, t: float, t_old: float | None = None, y=None) -> None:
        self.n += 1
        self._n_leg += 1
        if self._n_leg == 1:     # the leg's CPU rate is timed from its first step on: what came before
            self._cpu_leg0, self._t_cpu0 = cputime.thread_cpu(), float(t)   # (an integrator's import) is not its rate
        self._n_win += 1
        h = abs(t - t_old) if t_old is not None else 0.0
        self.hmax = max(self.hmax, h)
        left = abs(self.goal - t)
        need = None
        if self.n > self.limit:
            need = self.n + left * self._n_leg / max(abs(t - self.t0), 1e-300)
        elif self._n_win >= self.probe:
            if left > 0:
                need = self.n + left * self._n_win / max(abs(t - self._t_win), 1e-300)
                if need <= self.limit:
                    need = None
            self._n_win, self._t_win = 0, t
        if need is not None:
            raise OverBudget(self.goal, need, self.limit, t, y, h)
        if self._n_leg % CPU_PROBE == 0:
            cpu = cputime.over_budget(self._cpu_leg0, abs(t - self._t_cpu0), abs(self.goal - t))
            if cpu is not None:
                need = self.n + left * self._n_leg / max(abs(t - self.t0), 1e-300)
                if need > self.limit:       # over the step budget too: its message, which the load does not change
                    raise OverBudget(self.goal, need, self.limit, t, y, h)
                raise OverCpu(self.goal, *cpu, need, t, y, h)


class OverCpu(OverBudget):
    """A run refused by the CPU budget of its solve (:func:`dyncli.cputime.solve_budget`)."""

    def __init__(self, t_goal: float, cpu: float, limit: float, need: float, t: float, y=None, h: float = 0.0):
        super().__init__(t_goal, need, limit, t, y, h, message=(
            f"the run to t = {t_goal:.6g} s would take about {cpu:.3g} s of CPU ({need:.3g} integrator steps), "
            f"more than the budget of {limit:g} s: shorten the time span, loosen accuracy.rtol, or raise accuracy.max_cpu"))


class NonFiniteRate(NumericalError):
    """The right-hand side returned inf or NaN (an overflow in the equations)."""

    def __init__(self, t: float, y):
        y = np.asarray(y, dtype=float)
        super().__init__(f"the equations of motion give a non-finite rate (inf or NaN: an overflow) at "
                         f"t = {t:.6g} s, state [{', '.join(f'{c:.6g}' for c in y.ravel()[:8])}]")
        self.t, self.y = t, y


def finite(fun):
    """``fun`` that raises :class:`NonFiniteRate` instead of returning inf/NaN, or instead of
    math's domain error on a state that is no longer finite (scipy's explicit Runge-Kutta step
    never ends on a NaN rate: its step-size control computes a NaN step and loops.)"""

    def checked(t, y):
        try:
            out = fun(t, y)
        except (ValueError, OverflowError):     # math's domain error on a state that overflowed
            if not np.all(np.isfinite(y)):      # (sin of inf): the same failure as a rate of inf
                raise NonFiniteRate(t, y) from None
            raise
        if not math.isfinite(sum(out)) and not np.all(np.isfinite(out)):
            raise NonFiniteRate(t, y)
        return out

    return checked


class StepFailed(NumericalError):
    """scipy's solver reported a failed step (``t``: where; ``reason``: scipy's message)."""

    def __init__(self, method: str, t: float, reason: str | None):
        super().__init__(f"the integrator ({method}) failed at t = {t:.6g} s: {reason}")
        self.t, self.reason = float(t), reason


def steps(solver, budget: Budget | None, method: str):
    """The one stepping loop of the ODE routes (the loop ``solve_ivp`` runs, over the public
    ``OdeSolver.step``): yields ``solver`` after every accepted step (its ``t_old``, ``t``, ``y``
    current; the step's interpolant through :func:`dense_output`), each step counted by
    ``budget`` (None: the solver class counts itself, :func:`budgeted`), until the solver
    finishes or the caller stops iterating.  A failed step raises :class:`StepFailed`."""
    while solver.status == "running":
        msg = solver.step()
        if solver.status == "failed":
            raise StepFailed(method, solver.t, msg)
        if budget is not None:
            budget.tick(float(solver.t), None if solver.t_old is None else float(solver.t_old), solver.y)
        yield solver


def budgeted(method: str, budget: Budget, *, stop_nonfinite: bool = False, check_finite: bool = True,
             scipy: bool = False):
    """The stepper class for ``method`` (the one method map, :func:`dyncli.integrators.solver_class`;
    ``scipy=True``: scipy's own, for ``solve_ivp(method=...)``) with every accepted
    step counted by ``budget`` and a rate that is not finite raised as
    :class:`NonFiniteRate` (``check_finite=False``: the right-hand side checks its own).
    ``stop_nonfinite``: instead, a non-finite rate or state ends the integration as failed
    (status -1, with the reason) at the last good step."""
    base = solver_class(method, scipy=scipy)

    class Budgeted(base):  # type: ignore[misc, valid-type]  # the method's class, chosen at run time
        def __init__(self, fun, *args, **kw):
            super().__init__(finite(fun) if check_finite else fun, *args, **kw)

        def step(self):
            try:
                msg = super().step()
            except NonFiniteRate:
                if not stop_nonfinite:
                    raise
                self.status = "failed"
                return "the state overflows (the rate is not finite) after this time"
            if self.status == "failed":
                return msg
            if stop_nonfinite and not np.all(np.isfinite(self.y)):
                self.status = "failed"
                return "the state overflows (is not finite) after this time"
            budget.tick(float(self.t), None if self.t_old is None else float(self.t_old), self.y)
            return msg

    Budgeted.__name__ = base.__name__
    return Budgeted


def integrate(fun, y0, times, *, method="DOP853", rtol=1e-10, atol=1e-12, t0=0.0, project=None,
              on_step=None, first_step=None, max_steps=None):
    """Integrate y' = fun(t, y) from (t0, y0); return Y with one row per entry of ``times``.

    ``times`` may lie on both sides of t0 (two runs).  ``project(y) -> y`` is
    applied after every accepted step (explicit Runge-Kutta methods only).
    ``on_step(t_old, t_new, dense)`` is called for every accepted step with
    the step's interpolant (projected when ``project`` is given); it is also
    called once as ``on_step(t0, t0, None)`` at the start of each run.
    Returns (Y, nsteps).

    The run is refused (:class:`OverBudget`, a NumericalError) as soon as it
    is clear that it needs more than ``max_steps`` steps (default MAX_STEPS):
    see :class:`Budget`.
    """
    budget = Budget(max_steps)
    cls = solver_class(method)
    times = np.asarray(times, dtype=float)
    y0 = np.asarray(y0, dtype=float)
    Y = np.empty((len(times), len(y0)))
    at0 = times == t0
    Y[at0] = y0
    for direction in (1.0, -1.0):
        sel = np.nonzero((times - t0) * direction > 0)[0]
        if on_step is not None:
            on_step(t0, t0, None, direction)
        if len(sel) == 0:
            continue
        order = sel[np.argsort((times[sel] - t0) * direction)]
        t_end = float(times[order[-1]])
        budget.leg(t0, t_end)
        kw = {"rtol": rtol, "atol": atol}
        if first_step is not None:
            kw["first_step"] = min(first_step, abs(t_end - t0))
        solver = cls(finite(fun), t0, y0.copy(), t_end, **kw)
        k = 0
        for _ in steps(solver, budget, method):
            t_old, t_new = solver.t_old, solver.t
            if project is not None:
                yp = project(solver.y)
                solver.y = yp
                if hasattr(solver, "f"):
                    solver.f = fun(t_new, yp)
            dense = _Lazy(solver, project, t_new)
            if on_step is not None:
                on_step(t_old, t_new, dense, direction)
            while k < len(order) and (times[order[k]] - t_new) * direction <= 0:
                i = order[k]
                Y[i] = solver.y if times[i] == t_new else dense(times[i])
                k += 1
            if k == len(order):
                break
        for i in order[k:]:         # pragma: no cover - defensive: the solver finished early
            Y[i] = solver.y
    return Y, budget.n


def dense_run(fun, y0, T, *, method="DOP853", rtol=1e-10, atol=1e-12, project=None, max_steps=None, t0=0.0):
    """One run of :func:`integrate` from (t0, y0) to T that keeps every accepted step's interpolant
    (projected with ``project``): (the steps' ends, from t0 to T, and ``sol(ts)``, the states at an
    array of times as an array (components, len(ts)), each component a polynomial of the step
    between two step ends) — the motion a ``find`` search cuts at exact extremes
    (:func:`dyncli.motion_find.exact_breaks`)."""
    from dyncli.dop853 import OdeSolution

    ends, its = [float(t0)], []

    def keep(t_old, t_new, dense, direction):
        if dense is not None and t_new != t_old:
            its.append(dense.interpolant())      # made now, while the stepper is on this step
            ends.append(float(t_new))

    integrate(fun, y0, [T], method=method, rtol=rtol, atol=atol, t0=t0, project=project, on_step=keep,
              max_steps=max_steps)
    return ends, OdeSolution(ends, its)


class _Lazy:
    """The step's interpolant, built only when a point inside the step is asked for."""

    def __init__(self, solver, project, t_end):
        self.solver, self.project, self.t_end = solver, project, t_end
        self.y_end = solver.y.copy()
        self._d = None

    def interpolant(self):
        """The step's interpolant itself (projected with ``project``), made now."""
        if self._d is None:
            d = dense_output(self.solver)
            self._d = _Projected(d, self.project, self.t_end, self.y_end) if self.project is not None else d
        return self._d

    def __call__(self, t):
        if np.ndim(t) == 0 and t == self.t_end:
            return self.y_end.copy()
        return self.interpolant()(t)


class _Projected:
    """Dense output of a step whose end point was projected."""

    def __init__(self, dense, project, t_end, y_end):
        self.dense, self.project, self.t_end, self.y_end = dense, project, t_end, y_end

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        if t.ndim == 0:
            return self.y_end.copy() if t == self.t_end else self.project(self.dense(t))
        out = self.dense(t)
        for j in range(out.shape[1]):
            out[:, j] = self.project(out[:, j])
        return out


ODE_METHODS = METHODS       # the one method list (dyncli.integrators), by its former name here


def tighter(rtol: float, atol: float, div: float | None = None) -> tuple[float, float]:
    """Tolerances of a check solve ``div`` times tighter than (rtol, atol)
    (the error_estimate of the ODE routes), rtol no smaller than scipy allows."""
    div = CHECK_DIV if div is None else div
    return floor_rtol(rtol / div), max(atol / div, 1e-300)


def fallback_warning(div: float, cpu: bool = False) -> str:
    """The warning of an error_estimate whose check solve at rtol/div exceeded the budget (of
    steps, or with ``cpu`` of the solve's CPU)."""
    what = "the CPU budget of the solve (accuracy.max_cpu)" if cpu else "the step budget (accuracy.max_steps)"
    return (f"error_estimate: the check solve at rtol/{div:g} exceeds {what}; "
            "the estimate comes from a solve at 10·rtol instead (a conservative bound, typically ~10x the "
            "actual error)")


# ---------------------------------------------------------------------------
# the check-solve policy, shared by every ODE route (docs/accuracy.md)

#: the one divisor: a check solve runs at (rtol, atol) / CHECK_DIV, so its own error is ~1/100 of
#: the reported run's and their difference is 0.99-1.01 times the reported run's error
CHECK_DIV = 100.0
#: the one fallback: a check solve over the step budget is replaced by one at LOOSER_MUL x (rtol,
#: atol) (rtol at most LOOSER_CAP); the difference then measures the looser run's error, a
#: conservative bound (~10x the reported run's error)
LOOSER_MUL = 10.0
LOOSER_CAP = 1e-3


def relative_difference(pairs, floors=None) -> float:
    """The largest |a − b| over every quantity, each relative to its own scale: the largest
    magnitude of that quantity over both runs (at least its floor; a quantity that vanishes in
    both runs counts 0).  ``pairs``: (reported, check) arrays, one pair per reported quantity.
    Non-finite entries are skipped (an overflowed quantity is reported as null elsewhere)."""
    worst = 0.0
    for j, (a, b) in enumerate(pairs):
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        ok = np.isfinite(a) & np.isfinite(b)
        if not np.any(ok):
            continue
        a, b = a[ok], b[ok]
        s = max(float(np.max(np.abs(a))), float(np.max(np.abs(b))), floors[j] if floors else 0.0)
        if s > 0:
            worst = max(worst, float(np.max(np.abs(a - b))) / s)
    return worst


#: the note of an estimate that comes from no second solve (accuracy.estimate false, the default)
NOMINAL_NOTE = ("nominal: rtol times the number of steps (the steps' local error bounds added up), or the "
                "largest relative drift of the route's invariants when larger (no second solve); set "
                "accuracy.estimate: true for a measured estimate")


def nominal_estimate(res, rtol: float, *drifts: float | None, steps: int = 1) -> float:
    """The error_estimate of an ODE route run without a check solve (``accuracy.estimate``
    false, the default): ``rtol`` × ``steps`` — each accepted step keeps its local error within
    ~rtol of the state's scale, and without amplification the global error is at most their sum
    (a conservative bound: 2-1,000 times the actual error on the references; a long run whose
    errors are amplified, e.g. an unstable or chaotic motion, can exceed it) — or the largest
    relative drift of the route's invariants (energy, momenta, first integrals; each relative
    to its scale) when larger.  Sets ``res.error_estimate`` and its note; returns it."""
    est = max([float(rtol) * max(int(steps), 1)] + [float(d) for d in drifts if d is not None and math.isfinite(d)])
    res.error_estimate = est
    res.extra["error_estimate_note"] = NOMINAL_NOTE
    return est


def check_solve(res, run, rtol: float, atol: float, *, fallback: bool = True):
    """The one check-solve rule of the ODE routes: ``run(rtol2, atol2)`` at :func:`tighter`
    (rtol, atol) (÷ CHECK_DIV).  Over the step budget (:class:`OverBudget`): with ``fallback``,
    one run at LOOSER_MUL x (rtol, atol) instead and the :func:`fallback_warning`; any other
    failure (or no fallback): None, with ``res.error_estimate = None`` and a warning (the answer
    stands; only its estimate is missing).  Returns (the check run's output, how) or None."""
    r2, a2 = tighter(rtol, atol)
    try:
        try:
            return run(r2, a2), "tighter"
        except OverBudget as over:
            if not fallback:
                raise
            with cputime.extra(0.5 if isinstance(over, OverCpu) else 0.0):
                out = run(min(rtol * LOOSER_MUL, LOOSER_CAP), atol * LOOSER_MUL)
            res.warn(fallback_warning(CHECK_DIV, isinstance(over, OverCpu)))
            return out, "looser"
    except NumericalError as exc:
        res.error_estimate = None
        res.warn(f"error_estimate is null: the comparison solve at tighter tolerances failed: {exc}")
        return None


def dense_output(solver):
    """The interpolant of ``solver``'s last accepted step, through the public ``dense_output()``
    of scipy's ``OdeSolver`` interface (a callable on a float or an array of times)."""
    return solver.dense_output()


def rel_change(values, ref, scale):
    values = np.asarray(values, dtype=float)
    s = max(abs(ref), scale, 1e-300)
    return float(np.max(np.abs(values - ref)) / s) if values.size else 0.0


def finite_or_none(x):
    return float(x) if x is not None and math.isfinite(x) else None
