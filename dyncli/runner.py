"""The runner contract: the one module every integrating route of dyncli goes through for its
numerics (docs/accuracy.md; issue #26).  A topic never imports ``scipy.integrate`` or
``scipy.optimize`` itself (``tests/test_one_runner.py``): it states its problem through the
hooks of :class:`Route` (or the functions below), and this module owns the policy.

What lives here, once:

* :data:`METHODS` / :func:`solver_class` — the one map from ``accuracy.method`` to the stepper
  class (``auto``, ``ode``, ``exact`` and ``projected`` step with DOP853: dyncli's own copy of
  scipy's, :mod:`dyncli.dop853`, so an explicit route never imports ``scipy.integrate``);
* :data:`RTOL_FLOOR` / :func:`floor_rtol` — the one rtol floor (scipy's smallest rtol,
  100 machine epsilons);
  both defined in :mod:`dyncli.integrators` (which :mod:`dyncli.ode` uses too) and taken from here;
* :func:`solve_ivp` and :func:`ode_solution` — scipy's driver (with scipy's classes) and the
  piecewise interpolant, with
  every accepted step counted by the work budget (:class:`dyncli.ode.Budget`);
* :func:`march` — the runner's own event driver (terminal events located as scipy's
  ``solve_ivp`` locates them) over dyncli's DOP853, each step's interpolant made only when read,
  and the step control over the state's leading components only (``controlled``);
* :class:`Route` — the contract of a route (below), whose :meth:`Route.estimate_error` is the
  check-solve and fallback policy (:func:`dyncli.ode.check_solve`,
  :func:`dyncli.ode.nominal_estimate`, :func:`dyncli.ode.tighter`).

The stepping loop, the budget and the check-solve rule themselves are :mod:`dyncli.ode`'s; the
quadrature is :mod:`dyncli.quadrature`'s, the bracketed root :mod:`dyncli.rootfind`'s.
scipy is imported lazily, only when a problem actually integrates.
"""

from __future__ import annotations

import math

from dyncli import ode
# the method map and the rtol floor are defined below the runner, in dyncli.integrators (dyncli.ode
# steps with them too); the runner is where the routes take them from
from dyncli.integrators import ALIASES, METHODS, RTOL_FLOOR, floor_rtol, scipy_method, solver_class  # noqa: F401 (re-exported)


def solve_ivp(fun, t_span, y0, *, method: str, budget, check_finite: bool = True, stop_nonfinite: bool = False,
              **kw):
    """scipy's ``solve_ivp`` with the runner's solver class for ``method`` (:func:`dyncli.ode.budgeted`:
    every accepted step counted by ``budget``; a non-finite rate raised, or with ``stop_nonfinite``
    ending the run as failed; ``check_finite=False``: ``fun`` checks its own rates)."""
    from scipy.integrate import solve_ivp as scipy_solve_ivp

    cls = ode.budgeted(method, budget, stop_nonfinite=stop_nonfinite, check_finite=check_finite, scipy=True)
    return scipy_solve_ivp(fun, t_span, y0, method=cls, **kw)


class Marched:
    """A :func:`march`: the accepted steps' times ``t`` and states ``y`` (n × steps), ``sol`` the
    interpolant over them, ``status`` 0 (t_end reached) or 1 (a terminal event), and the event:
    ``event`` (its index, or None), ``t_event``, ``y_event``."""

    def __init__(self, t, y, sol, status, event=None, t_event=None, y_event=None):
        self.t, self.y, self.sol, self.status = t, y, sol, status
        self.event, self.t_event, self.y_event = event, t_event, y_event


def march(fun, t0: float, y0, t_end: float, *, method: str, budget, rtol: float, atol: float, events=(),
          max_step: float = math.inf, controlled: int | None = None) -> Marched:
    """y' = fun(t, y) from (t0, y0) towards t_end, stopped by the first terminal event: scipy's
    ``solve_ivp(..., dense_output=True, events=...)`` for terminal events, with the runner's own
    loop (:func:`dyncli.ode.steps`, every accepted step counted by ``budget``).  An event
    ``g(t, y)`` (scipy's convention: its ``direction``) is checked at every step's end and its
    root located by Brent's method on the step's interpolant (``xtol = rtol = 4 ε``, as scipy);
    the earliest root of the step ends the run.  With dyncli's DOP853 (``method`` DOP853) a
    step's interpolant is made only when it is read (:meth:`dyncli.dop853.DOP853.dense_later`)
    and ``controlled`` leading components alone steer the steps (the rest: quadratures of the
    motion carried along, see :class:`dyncli.dop853.DOP853`); with another method every
    component is controlled.  ``fun`` checks its own rates (a non-finite rate is its error)."""
    import numpy as np

    from dyncli.rootfind import brent

    cls = solver_class(method)
    kw = {"controlled": controlled} if controlled is not None and method == "DOP853" else {}
    solver = cls(fun, t0, np.asarray(y0, dtype=float), t_end, rtol=rtol, atol=atol, max_step=max_step, **kw)
    lazy = getattr(solver, "dense_later", None) or solver.dense_output
    eps4 = 4 * float(np.finfo(float).eps)
    dirs = [float(getattr(ev, "direction", 0.0)) for ev in events]
    g = [float(ev(t0, solver.y)) for ev in events]
    ts, ys, sols = [float(t0)], [solver.y.copy()], []
    for _ in ode.steps(solver, budget, method):
        t_old, t, y = float(solver.t_old), float(solver.t), solver.y
        sol = lazy()
        hit = None
        if events:
            g_new = [float(ev(t, y)) for ev in events]
            for i, (a, b, d) in enumerate(zip(g, g_new, dirs)):
                up, down = a <= 0 <= b, a >= 0 >= b
                if (up and d > 0) or (down and d < 0) or ((up or down) and d == 0):
                    root = brent(lambda s, ev=events[i]: ev(s, sol(s)), t_old, t, eps4, eps4, 100)
                    if hit is None or root < hit[0]:
                        hit = (root, i)
            g = g_new
        if hit is not None:
            y = sol(hit[0])
            t = hit[0]
        ts.append(t)
        ys.append(y if method != "LSODA" else y.copy())
        sols.append(sol)
        if hit is not None:
            from dyncli.dop853 import OdeSolution

            return Marched(np.array(ts), np.array(ys).T, OdeSolution(ts, sols), 1, hit[1], hit[0], np.array(y))
    from dyncli.dop853 import OdeSolution

    return Marched(np.array(ts), np.array(ys).T, OdeSolution(ts, sols) if sols else None, 0)


def ode_solution(ts, interpolants):
    """One interpolant over consecutive steps (scipy's ``OdeSolution``, as :mod:`dyncli.dop853` has it)."""
    from dyncli.dop853 import OdeSolution

    return OdeSolution(ts, interpolants)


class Route:
    """The contract of a numerical route (in the spirit of sympy.physics.mechanics' ``_Methods``):
    a subclass states its problem through these hooks, and the runner owns the policy.

    Problem hooks (a subclass overrides what its route needs):

    * :meth:`initial_state` — y0, a sequence of floats;
    * :meth:`rhs` — ``rhs(t, y)``, the rate as a list of plain floats or an array (plain floats
      are 2-5 times faster on the small states of dyncli);
    * :attr:`events` — event functions ``g(t, y)`` in scipy's convention (``terminal``,
      ``direction`` attributes), empty by default;
    * :meth:`solve` — one run at ``(rtol, atol)``: returns the route's output (default: the
      state at :attr:`times` by :func:`dyncli.ode.integrate`, from :meth:`initial_state`);
    * :meth:`reported` — the output's reported quantities, one array per quantity;
    * :meth:`floors` — the scale floor of each reported quantity (None: none), for quantities
      that may vanish throughout (docs/accuracy.md);
    * :meth:`difference` — the error measure between the reported and the check run (default:
      :func:`dyncli.ode.relative_difference` over :meth:`reported`, each quantity relative to
      its own scale);
    * :meth:`drifts` — the relative drifts of the route's invariants (for the nominal estimate);
    * :meth:`steps` — accepted steps of a run (for the nominal estimate).

    Policy (the runner's; a subclass does not override these):

    * :attr:`method` through :func:`solver_class` (the one method map), :attr:`rtol` through
      :func:`floor_rtol` (the one rtol floor), :attr:`max_steps` the work budget
      (:class:`dyncli.ode.Budget`; None: the route's :attr:`default_steps`, else
      ``ode.MAX_STEPS``);
    * :meth:`run` — the reported run, then :meth:`estimate_error`: with ``estimate`` the check
      solve at rtol/100 and its one fallback (:func:`dyncli.ode.check_solve`), else the nominal
      estimate (:func:`dyncli.ode.nominal_estimate`).
    """

    events: tuple = ()
    times: object = ()
    default_steps: int | None = None
    #: the error_estimate note of a check solve (``{how}``: rtol/100, or 10·rtol after the fallback)
    note = "the largest difference of every reported quantity, each relative to its scale, from a check solve at {how}"

    def __init__(self, *, method: str = "DOP853", rtol: float = 1e-10, atol: float = 1e-12,
                 max_steps: int | None = None, estimate: bool = False):
        self.method = scipy_method(method)
        self.rtol, self.atol = floor_rtol(float(rtol)), float(atol)
        self.max_steps, self.estimate = max_steps, bool(estimate)
        self.nsteps = 0

    # -- problem hooks --------------------------------------------------------------------------

    def initial_state(self):
        raise NotImplementedError

    def rhs(self, t, y):
        raise NotImplementedError

    def budget(self, probe: int = ode.PROBE_STEPS):
        """A fresh work budget for one solve."""
        return ode.Budget(self.max_steps, default=self.default_steps, probe=probe)

    def solve(self, rtol: float, atol: float):
        """One run at (rtol, atol); default: the state at :attr:`times` (rows)."""
        Y, self.nsteps = ode.integrate(self.rhs, self.initial_state(), self.times, method=self.method, rtol=rtol,
                                       atol=atol, max_steps=self.max_steps or self.default_steps)
        return Y

    def reported(self, out):
        """The reported quantities of a run's output, one array each (default: the state's columns)."""
        return [out[:, j] for j in range(out.shape[1])]

    def floors(self):
        return None

    def difference(self, out, check) -> float:
        return ode.relative_difference(list(zip(self.reported(out), self.reported(check))), self.floors())

    def drifts(self, out):
        return ()

    def steps(self, out) -> int:
        return self.nsteps

    # -- the policy -----------------------------------------------------------------------------

    def run(self, res):
        """The reported run and its error_estimate (on ``res``); returns the run's output."""
        out = self.solve(self.rtol, self.atol)
        self.estimate_error(res, out)
        return out

    def estimate_error(self, res, out):
        """The error_estimate of ``out`` (docs/accuracy.md): the check solve and its one fallback
        with ``estimate``, else the nominal bound.  Returns the check run's output or None."""
        return estimate_error(res, out, estimate=self.estimate, rtol=self.rtol, atol=self.atol,
                              rerun=self.solve, difference=self.difference, note=self.note,
                              drifts=self.drifts(out), steps=self.steps(out))


def estimate_error(res, out, *, estimate: bool, rtol: float, atol: float, rerun, difference, note=None,
                   drifts=(), steps: int = 1):
    """The check-solve and fallback policy of docs/accuracy.md as a function (what
    :meth:`Route.estimate_error` runs, for the routes not yet written as a :class:`Route`):
    with ``estimate``, ``rerun(rtol2, atol2)`` at rtol/100 (over the budget: once at 10·rtol,
    with a warning; any other failure: a null estimate and a warning) and
    ``res.error_estimate = difference(out, check)``; without, :func:`dyncli.ode.nominal_estimate`
    from ``drifts`` and ``steps``.  Returns the check run's output or None."""
    if not estimate:
        ode.nominal_estimate(res, rtol, *drifts, steps=steps)
        return None
    check = ode.check_solve(res, rerun, rtol, atol)
    if check is None:
        return None
    est = difference(out, check[0])
    res.error_estimate = float(est) if est is not None and math.isfinite(est) else est
    if note:
        res.extra["error_estimate_note"] = note.format(how="rtol/100" if check[1] == "tighter" else "10·rtol")
    return check[0]


#: the global error an ODE route promises, in units of rtol (docs/accuracy.md, "What the numbers guarantee")
ODE_PROMISE = 100.0


def warn_unmet(res, rtol: float, achieved, *, promise: float = 1.0, what: str = "error_estimate") -> bool:
    """The warning of issue 28 when a route did not deliver what was asked: ``achieved`` (the
    route's error_estimate, or a measured part of it) above ``promise`` × rtol.  Exact routes
    compare their estimate with rtol itself; ODE routes a measured error (a check solve's
    difference, an invariant's drift: lower bounds of the error) with :data:`ODE_PROMISE` × rtol,
    their documented guarantee (their nominal estimate, rtol × steps, is above it by design).
    Returns whether it warned."""
    if achieved is None or not math.isfinite(achieved) or not achieved > promise * rtol:
        return False
    goal = f"{promise:g} × rtol = {promise * rtol:.2g}" if promise != 1.0 else f"rtol = {rtol:.2g}"
    res.warn(f"the requested accuracy was not met: {what} {achieved:.2g} > {goal} (accuracy.rtol); the "
             "answer stands with that estimate")
    return True


#: the accuracy promised of an ODE route (docs/accuracy.md): every reported quantity within
#: PROMISE x rtol of its scale (the same promise as warn_unmet's)
PROMISE = ODE_PROMISE
#: a route solved to its promise reports MARGIN x the difference from its check run (the check
#: run's own error is ~1/100 of the reported run's, 1/10 at the rtol floor; measured within 2 %)
MARGIN = 2.0
#: the tightest internal rtol of a reported run: its check run (÷ 100) still lies 10 x tighter
TIGHTEST = 10 * RTOL_FLOOR


def solve_to_promise(res, run, difference, rtol: float, atol: float, out=None):
    """A route whose cheap (nominal) estimate cannot be trusted — its errors are amplified, as on an
    eccentric orbit whose fast perigee passage magnifies a phase error (docs/accuracy.md) — solved
    to the promise: every reported run is checked (:func:`dyncli.ode.check_solve`, rtol/100) and
    its error_estimate is MARGIN x the difference; while that exceeds PROMISE x rtol the run is
    repeated at an internal rtol lowered in proportion (to aim at a third of the promise, at least
    100 x tighter, not below TIGHTEST).  ``run(r, a, ref)``: the route's output at (r, a) (``ref``:
    the run it checks, or None); ``difference(out, check)``: the relative error measure; ``out``:
    the first run at (rtol, atol) if already made.  A promise the budget or the rtol floor does not
    allow is said in a warning naming the achieved estimate.  Returns (the reported output, its
    internal rtol); sets ``res.error_estimate`` and its note."""
    r, a = floor_rtol(rtol), atol
    out = run(r, a, None) if out is None else out
    while True:
        check = ode.check_solve(res, lambda r2, a2: run(r2, a2, out), r, a)
        if check is None:
            return out, r
        est = MARGIN * difference(out, check[0])
        if not math.isfinite(est) or est <= PROMISE * rtol or r <= TIGHTEST:
            break
        r_new = max(r * min(0.01, PROMISE * rtol / (3 * est)), TIGHTEST)
        try:
            out, r, a = run(r_new, a * r_new / r, None), r_new, a * r_new / r
        except ode.OverBudget:
            res.warn(f"the run at the internal rtol {r_new:.2g} needed to meet {PROMISE:g} x rtol exceeds "
                     "the step budget (accuracy.max_steps): the answer of the run at "
                     f"{r:.2g} is reported")
            break
    res.error_estimate = est
    tight = "" if r == floor_rtol(rtol) else f" (internal rtol tightened to {r:.2g} to meet {PROMISE:g} x rtol)"
    res.extra["error_estimate_note"] = (f"{MARGIN:g} x the largest difference of every reported quantity, each "
                                        f"relative to its scale, from a check solve at rtol/100{tight}")
    if est > PROMISE * rtol:
        why = ("at its floor: the integrator cannot do better in double precision" if r <= TIGHTEST else
               "the step budget stopped it: raise accuracy.max_steps")
        warn_unmet(res, rtol, est, promise=PROMISE, what=f"error_estimate (internal rtol {r:.2g}, {why})")
    return out, r
