"""Integrating a particle's motion in phases (notes §16, §19.27, §20).

The state is augmented with the work of the non-conservative forces,
y = [x1, x2, x3, v1, v2, v3, W_nc], dW_nc/dt = F_nc·v (20.3).

Coulomb friction F_f = -mu N v/|v| (19.27) is discontinuous at v = 0.  Each sliding phase uses
a reference direction d (the velocity direction at the start of the phase) and the
continuation F_f = -mu N sign(v·d) v/|v|, which is smooth through a stop along a line; a
terminal event at v·d = 0 ends the phase.  There, if the speed is (numerically) zero the static
condition |F_other| <= mu N decides between sticking (the particle stays at rest, as long as
the condition holds) and slipping on in the direction of F_other; otherwise the velocity merely
turned through 90° and a new phase starts with the new direction.

Each phase steps scipy's solver directly (the loop of ``solve_ivp``): every accepted step is
counted by the runner's budget (:class:`dyncli.ode.Budget`) and stored (time and state); a step's
dense output (``OdeSolver.dense_output()``) is built only where a requested time or a friction
stop falls in it, or for every step when the trajectory must be evaluated anywhere
(``dense=True``: plots, the work of several non-conservative terms).
"""

from __future__ import annotations

import bisect
import math
from itertools import repeat
from typing import Any

import numpy as np

from dyncli import ode, runner
from dyncli.errors import NumericalError
from dyncli.topics.particle.forces import Forces, NonFiniteForce
from dyncli.topics.particle.hints import budget_message, singularity_hint

EPS = np.finfo(float).eps
MAX_PHASES = 20000


class OdePhase:
    """One integrated phase on [t0, t1]: the accepted steps (``steps_t``, ``steps_y`` 7 x n), the
    phase's right-hand side, and ``sol`` (a scipy ``OdeSolution`` over its steps) when the run
    kept every step's dense output (``dense=True``), else None; ``d``: the friction reference
    direction of the phase (its right-hand side on many states: ``Forces.accelerations``)."""

    def __init__(self, t0, t1, sol, rhs, steps_t, steps_y, d=None):
        self.t0, self.t1, self.sol, self.rhs = t0, t1, sol, rhs
        self.steps_t, self.steps_y, self.d = steps_t, steps_y, (np.zeros(3) if d is None else np.asarray(d, float))

    def state(self, t, rows: slice | None = None):
        """The state at t (``rows``: those components only)."""
        if self.t1 > self.t0 and self.sol is None:
            raise RuntimeError("the trajectory was integrated without dense output")
        if self.t1 <= self.t0:
            return self.steps_y[:, 0] if rows is None else self.steps_y[rows, 0]
        if rows is None:
            return self.sol(t)
        from dyncli.dop853 import OdeSolution

        return self.sol(t, rows) if isinstance(self.sol, OdeSolution) else self.sol(t)[rows]


class RestPhase:
    def __init__(self, t0, t1, x, W):
        self.t0, self.t1, self.x, self.W = t0, t1, np.asarray(x, float), float(W)

    def state(self, t):
        return np.concatenate([self.x, np.zeros(3), [self.W]])


class Trajectory:
    """The phases of a run, the friction notes, and the states recorded during the run at the
    requested times (``recorded``: time -> (phase index, state)); with ``dense`` every phase has
    its dense output and any time can be evaluated."""

    def __init__(self, phases, notes, nfev, nsteps=0, hmax=0.0, recorded=None, dense=True):
        self.phases = phases
        self.notes = notes      # list of (kind, t, info) for stops/slips
        self.nfev = nfev
        self.nsteps = nsteps    # accepted steps over all phases
        self.hmax = hmax        # the longest accepted step
        self.recorded = recorded or {}
        self.dense = dense

    def steps(self) -> tuple[np.ndarray, np.ndarray]:
        """(times, states 7 x M) of every accepted step of every integrated phase, in order."""
        if not hasattr(self, "_steps"):
            ode_ph = [ph for ph in self.phases if isinstance(ph, OdePhase)]
            self._steps = ((np.concatenate([ph.steps_t for ph in ode_ph]),
                            np.concatenate([ph.steps_y for ph in ode_ph], axis=1)) if ode_ph else
                           (np.zeros(0), np.zeros((7, 0))))
        return self._steps

    def phase_at(self, t):
        """The first phase whose interval [t0, t1] contains t."""
        import bisect

        starts = self._starts if hasattr(self, "_starts") else [ph.t0 for ph in self.phases]
        self._starts = starts
        i = max(bisect.bisect_left(starts, t) - 1, 0)
        for ph in self.phases[i:]:
            if ph.t0 <= t <= ph.t1:
                return ph
        return self.phases[-1]

    def states(self, times):
        """(phase, state) at each time."""
        idx, Y = self.state_array(times)
        return [(self.phases[k], Y[:, j]) for j, k in enumerate(idx.tolist())]

    def state_array(self, times, rows: slice | None = None) -> tuple[np.ndarray, np.ndarray]:
        """The phase index of each time (as :meth:`phase_at`) and the states
        y (7 x N) at all ``times`` at once: a time recorded during the run takes its
        recorded state; each phase's dense output is called once on the array of the others
        (the recorded times looked up by one sorted search, not one at a time).  ``rows``: only
        those rows of y (the same values: the dense output works component by component)."""
        t = np.asarray(times, float).reshape(-1)
        rt, ridx, rY = self._recorded_arrays()
        if rows is not None:
            rY = rY[rows]
        pos = np.clip(np.searchsorted(rt, t), 0, max(rt.size - 1, 0))
        hit = rt[pos] == t if rt.size else np.zeros(t.size, bool)
        if hit.all():
            return ridx[pos], rY[:, pos]
        idx, Y = self._dense_array(t, rows)
        if hit.any():                           # the recorded states exactly (the same as the results)
            idx[hit], Y[:, hit] = ridx[pos[hit]], rY[:, pos[hit]]
        return idx, Y

    def _recorded_arrays(self):
        """(times sorted, phase indices, states 7 x R) of the recorded states, made once."""
        if not hasattr(self, "_rec"):
            ts = sorted(self.recorded)
            got = [self.recorded[tt] for tt in ts]
            self._rec = (np.array(ts, float), np.array([k for k, _ in got], dtype=int),
                         np.array([y for _, y in got], dtype=float).reshape(-1, 7).T)
        return self._rec

    def _dense_array(self, t, rows: slice | None = None):
        sl = slice(None) if rows is None else rows
        starts = np.array([ph.t0 for ph in self.phases])
        ends = np.array([ph.t1 for ph in self.phases])
        idx = np.clip(np.searchsorted(starts, t, side="left") - 1, 0, len(self.phases) - 1)
        # the phases are contiguous, so the candidate holds t unless t is on a
        # boundary or outside every phase: those few go the scalar way
        odd = ~((starts[idx] <= t) & (t <= ends[idx])) | ((idx > 0) & (t <= ends[np.maximum(idx - 1, 0)]))
        for j in np.flatnonzero(odd):
            idx[j] = self.phases.index(self.phase_at(float(t[j])))
        Y = np.empty((len(range(7)[sl]), t.size))
        if t.size < 2 or bool((idx[1:] >= idx[:-1]).all()):     # the phases' times already grouped
            cuts = (np.flatnonzero(np.diff(idx)) + 1).tolist()
            groups: list[tuple[int, Any]] = [(int(idx[a]), slice(a, b)) for a, b in zip([0] + cuts, cuts + [t.size])] if t.size else []
        else:
            order = np.argsort(idx, kind="stable")      # the times of each phase present, one slice each
            groups = [(int(idx[sel[0]]), sel) for sel in np.split(order, np.flatnonzero(np.diff(idx[order])) + 1)]
        for k, sel in groups:
            ph = self.phases[k]
            if isinstance(ph, RestPhase):
                Y[:, sel] = np.concatenate([ph.x, np.zeros(3), [ph.W]])[sl, None]
            elif ph.t1 > ph.t0:
                Y[:, sel] = ph.state(t[sel], rows)
            else:
                Y[:, sel] = ph.steps_y[sl, :1]
        return idx, Y


# ---------------------------------------------------------------------------
# the work budget: dyncli.ode.Budget over all phases, with a hint on what limits the steps

MAX_STEPS = 5_000      # default accuracy.max_steps for particle (~1 s of solve_ivp stepping)
PROBE_STEPS = 500      # every this many steps, project the run's total and refuse early (dyncli.ode.Budget)


def integrate(p, F: Forces, rtol: float, atol: float, method: str, *, max_steps: int | None = None,
              times=(), dense: bool = True, max_step: float = math.inf) -> Trajectory:
    """Integrate the motion from t = 0 to t_end (phases for friction), recording the state at
    ``times``; ``dense``: keep every step's dense output (for plots and for the work of several
    non-conservative terms), else a step's interpolant is built only where a requested time or a
    friction stop falls in it.

    The run is refused with a NumericalError as soon as it is clear that it
    needs more than ``max_steps`` accepted steps (default MAX_STEPS); a
    non-finite force is a NumericalError at once.  ``max_step``: the longest step allowed."""
    with np.errstate(all="ignore"):     # overflow is detected and reported, not warned about
        return _integrate(p, F, (rtol, atol, min(max_step, F.kink_step)), method, max_steps, times, dense)


def _integrate(p, F, tol, method, max_steps, times, dense) -> Trajectory:
    rtol, atol, max_step = tol
    rtol = runner.floor_rtol(rtol)
    t_end = float(p.t_end)
    y = np.array([*p.x0, *p.v0, 0.0], dtype=float)
    if t_end == 0.0:
        rhs = F.make_rhs(np.zeros(3))
        return Trajectory([OdePhase(0.0, 0.0, None, rhs, np.array([0.0]), y[:, None].copy())], [], 0,
                          recorded={float(t): (0, y.copy()) for t in times})
    budget = ode.Budget(max_steps, default=MAX_STEPS, probe=PROBE_STEPS)
    budget.leg(0.0, t_end)
    run = _Run(F, (rtol, atol, max_step), method, budget, t_end, y, times, dense)
    try:
        run.phases_to_end()
    except NonFiniteForce as exc:
        raise NumericalError(f"the force is not finite (inf or NaN) at t = {exc.t:.6g} s, x = "
                             f"[{', '.join(f'{c:.6g}' for c in exc.x)}] m" + singularity_hint(F, exc.x)) from None
    except ode.OverBudget as exc:
        msg, stiff = budget_message(exc, method, run.rhs)
        exc.args = (msg,)               # the runner's refusal with a hint on what limits the steps
        exc.stiff = stiff               # method auto switches to LSODA
        raise exc from None
    return Trajectory(run.phases, run.notes, run.nfev, budget.n, budget.hmax, run.recorded, dense)


_NO_FRICTION = np.zeros(3)


class _Run:
    """The phases of one integration from t = 0 to t_end: each starts with the friction
    decision (:meth:`direction`) and integrates until a stop or t_end (:meth:`integrate_phase`)."""

    def __init__(self, F, tol, method, budget, t_end, y, times, dense):
        self.F, self.method, self.budget = F, method, budget
        self.rtol, self.atol, self.max_step = tol
        self.solver_cls = runner.solver_class(method)      # the runner's one method map
        self.t_end, self.dense = t_end, dense
        self.t, self.y = 0.0, y
        self.phases: list = []
        self.notes: list = []       # (kind, t, |F_other|) for stops, slips and releases
        self.nfev = 0
        self.vscale = float(np.linalg.norm(y[3:6])) if F.muN else 0.0     # friction decides stops on it
        self.rhs = None             # the right-hand side of the current phase
        self.want = sorted(set(map(float, times)))      # the requested times, in order
        self.k = 0                                              # the next one to record
        self.recorded: dict = {}

    def record_rest(self, ph) -> None:
        """The requested times within a rest phase (up to its end)."""
        y = np.concatenate([ph.x, np.zeros(3), [ph.W]])
        while self.k < len(self.want) and self.want[self.k] <= ph.t1:
            self.recorded[self.want[self.k]] = (len(self.phases) - 1, y)
            self.k += 1

    def phases_to_end(self) -> None:
        for _ in range(MAX_PHASES):
            d = self.direction()
            if d is None or self.integrate_phase(d):
                return
        raise NumericalError(f"friction: more than {MAX_PHASES} stick/slip phases before t_end; "
                             "the motion chatters at this tolerance")

    def direction(self):
        """The friction reference direction d of the next phase (zeros without friction), after
        a rest phase if the particle sticks; None when it sticks until t_end."""
        F, y, t = self.F, self.y, self.t
        if not F.muN:
            return _NO_FRICTION
        speed = float(np.linalg.norm(y[3:6]))
        self.vscale = max(self.vscale, speed)
        if not speed <= 10.0 * (self.atol + self.rtol * self.vscale):     # sliding (or not a number)
            return y[3:6] / speed
        y[3:6] = 0.0
        Fo = F.other(t, y[0:3])
        nFo = float(np.linalg.norm(Fo))
        if not np.isfinite(nFo):
            raise NonFiniteForce(t, y[0:3])
        # static condition |F_other| <= mu N, decided within the tolerance
        # (a marginal case would otherwise creep at roundoff level)
        if nFo <= F.muN * (1.0 + 10.0 * self.rtol):
            t_free = _release_time(F, t, self.t_end, y[0:3]) if F.time_dependent else None
            t1 = self.t_end if t_free is None else t_free
            self.phases.append(RestPhase(t, t1, y[0:3], y[6]))
            self.record_rest(self.phases[-1])
            self.notes.append(("stick", t, nFo))
            if t_free is None:
                return None
            self.t = t = t_free
            Fo = F.other(t, y[0:3])
            nFo = float(np.linalg.norm(Fo))
            self.notes.append(("release", t, nFo))
        elif self.phases:
            self.notes.append(("slip", t, nFo))
        return Fo / nFo

    def integrate_phase(self, d) -> bool:
        """Integrate one phase with friction direction d; True when it reaches t_end."""
        t0, y0, method = self.t, self.y, self.method
        self.rhs = rhs = self.F.make_rhs(d)
        try:
            solver = self.solver_cls(rhs, t0, y0, self.t_end, rtol=self.rtol, atol=self.atol, max_step=self.max_step)
            stop, ts, ys, sols = self._steps(solver, d)
        except (ValueError, ZeroDivisionError, FloatingPointError, OverflowError) as exc:
            raise NumericalError(f"the integrator ({method}) failed near t = {self.t:g}: {exc}") from None
        self.nfev += solver.nfev
        Y = np.array(ys).T
        if not np.isfinite(Y).all():
            bad = int(np.argmax(~np.all(np.isfinite(Y), axis=0)))
            raise NumericalError(f"the motion is not finite near t = {ts[max(bad - 1, 0)]:g} "
                                 "(a singular force: the particle reached an inverse-square centre or a spring anchor?)")
        if self.F.muN:
            self.vscale = max(self.vscale, float(np.linalg.norm(Y[3:6], axis=0).max()))
        sol = None
        if self.dense and sols:
            sol = runner.ode_solution(ts, sols)
        self.phases.append(OdePhase(t0, ts[-1], sol, rhs, np.array(ts), Y, d))
        self.t, self.y = ts[-1], ys[-1]
        return not stop or ts[-1] >= self.t_end

    def _steps(self, solver, d):
        """The accepted steps of one phase (the loop of scipy's ``solve_ivp``): the budget ticks,
        the requested times recorded from the step's dense output, and the friction stop: the
        terminal event v·d = 0 crossed downwards, located by brentq on the dense output as
        ``solve_ivp`` does.  Returns (stopped, step times, states, interpolants if dense)."""
        t, y = float(solver.t), solver.y.copy()
        ts, ys, sols = [t], [y], []
        want, k, rec, n_ph = self.want, self.k, self.recorded, len(self.phases)
        n_want = len(want)
        while k < n_want and want[k] <= t:          # a time at the phase's start
            rec[want[k]] = (n_ph, y)
            k += 1
        muN, dense = self.F.muN, self.dense
        copy = self.method == "LSODA"               # the others make a new state array every step
        g = float(y[3:6] @ d) if muN else 0.0
        stop = False
        for _ in self._stepping(solver):
            t_old, t, y = float(solver.t_old), float(solver.t), solver.y
            if copy:
                y = y.copy()
            sol = solver.dense_output() if dense else None
            if muN:
                g_new = float(y[3:6] @ d)
                if g >= 0 and g_new <= 0:           # solve_ivp's event of direction −1
                    t, y, sol = self._stop(solver, sol, d, t_old, t)
                    stop = True
                    if not t > ts[-1]:              # the stop at the step's start (to rounding): the
                        ys[-1] = y                  # phase ends there, no step of zero length
                        break
                g = g_new
            if k < n_want and want[k] <= t:         # the requested times in this step: one interpolation
                j = bisect.bisect_right(want, t, k)
                inner = want[k:j - 1] if want[j - 1] == t else want[k:j]
                if inner:
                    sol = sol or solver.dense_output()
                    Yk = sol(np.array(inner)).T
                    rec.update(zip(inner, zip(repeat(n_ph), Yk)))
                if want[j - 1] == t:
                    rec[t] = (n_ph, y)
                k = j
            ts.append(t)
            ys.append(y)
            if dense:
                sols.append(sol)
            if stop:
                break
        self.k = k
        return stop, ts, ys, sols

    def _stepping(self, solver):
        """The runner's stepping loop (:func:`dyncli.ode.steps`, the budget counting every step),
        a failed step told with the hint of a singular force where there is one."""
        try:
            yield from ode.steps(solver, self.budget, self.method)
        except ode.StepFailed as exc:
            raise NumericalError(f"the integrator ({self.method}) failed near t = {exc.t:g}: {exc.reason}"
                                 + singularity_hint(self.F, solver.y[0:3])) from None

    @staticmethod
    def _stop(solver, sol, d, t_old, t):
        """(time, state, interpolant) of the friction stop v·d = 0 inside the last step: brentq on
        the step's dense output, as ``solve_ivp`` locates a terminal event."""
        from dyncli.rootfind import brentq

        sol = sol or solver.dense_output()
        te = brentq(lambda s: float(sol(s)[3:6] @ d), t_old, t, xtol=4 * EPS, rtol=4 * EPS)
        return te, sol(te), sol


def _release_time(F: Forces, t0: float, t_end: float, x) -> float | None:
    """First time after t0 at which |F_other(t, x)| exceeds mu N (the particle
    breaks free); None if it stays stuck until t_end.  Decided by the roots of
    h = |F_other| − mu N (dyncli.rootfind.all_roots: the sign of h at the critical
    points of its resolved interpolant, so a pulse between any two sample points is
    not missed — issue #28): the first root after which h > 0."""
    from dyncli.rootfind import all_roots

    def h(t):
        return float(np.linalg.norm(F.other(t, x))) - F.muN

    if h(t0) > 0.0:
        return float(t0)
    roots, _, bad = all_roots(lambda ts: np.array([h(float(t)) for t in np.ravel(ts)]), t0, t_end, cells=128)
    ends = sorted(set(roots)) + [t_end]
    for r, nxt in zip(ends[:-1], ends[1:]):
        if h(0.5 * (r + nxt)) > 0.0:          # h > 0 on the whole piece after r (no root inside)
            return float(r)
    if bad:
        raise NumericalError(f"friction: the other force is not finite near t = {bad[0]:.6g} s while the particle "
                             "is stuck: the release time is not decided")
    return None
