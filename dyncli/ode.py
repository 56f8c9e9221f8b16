"""Step-by-step ODE integration with a work budget, shared by the topics that integrate.

A thin loop over scipy's ``OdeSolver`` classes (the same loop ``solve_ivp``
runs), which lets the caller

* read the state at the requested times from each step's dense output,
* look at every accepted step (``on_step``: invariants, angle unwrapping),
* project the state back onto invariant manifolds after every step
  (``project``; method "projected" = DOP853 + projection).

scipy is imported lazily, only when a problem actually integrates.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import NumericalError

ODE_METHODS = ("DOP853", "RK45", "Radau", "LSODA")
MAX_STEPS = 50_000       # default budget (~1-2 s of Python stepping); accuracy.max_steps overrides it
PROBE_STEPS = 2_000      # after this many steps, project the run's total and refuse early


def integrate(fun, y0, times, *, method="DOP853", rtol=1e-10, atol=1e-12, t0=0.0, project=None,
              on_step=None, first_step=None, max_steps=None):
    """Integrate y' = fun(t, y) from (t0, y0); return Y with one row per entry of ``times``.

    ``times`` may lie on both sides of t0 (two runs).  ``project(y) -> y`` is
    applied after every accepted step (explicit Runge-Kutta methods only).
    ``on_step(t_old, t_new, dense)`` is called for every accepted step with
    the step's interpolant (projected when ``project`` is given); it is also
    called once as ``on_step(t0, t0, None)`` at the start of each run.
    Returns (Y, nsteps).

    The run is refused with a NumericalError as soon as it is clear that it
    needs more than ``max_steps`` steps (default MAX_STEPS): after
    PROBE_STEPS steps the total is extrapolated from the time covered.
    """
    budget = int(max_steps or MAX_STEPS)
    from scipy import integrate as si

    cls = {"DOP853": si.DOP853, "RK45": si.RK45, "Radau": si.Radau, "LSODA": si.LSODA}[method]
    times = np.asarray(times, dtype=float)
    y0 = np.asarray(y0, dtype=float)
    Y = np.empty((len(times), len(y0)))
    at0 = times == t0
    Y[at0] = y0
    nsteps = 0
    for direction in (1.0, -1.0):
        sel = np.nonzero((times - t0) * direction > 0)[0]
        if on_step is not None:
            on_step(t0, t0, None, direction)
        if len(sel) == 0:
            continue
        order = sel[np.argsort((times[sel] - t0) * direction)]
        t_end = float(times[order[-1]])
        kw = {"rtol": rtol, "atol": atol}
        if first_step is not None:
            kw["first_step"] = min(first_step, abs(t_end - t0))
        solver = cls(fun, t0, y0.copy(), t_end, **kw)
        k = 0
        while k < len(order):
            msg = solver.step()
            if solver.status == "failed":
                raise NumericalError(f"the {method} integrator failed at t = {solver.t:.6g}: {msg}")
            nsteps += 1
            covered = abs(solver.t - t0)
            span = abs(t_end - t0)
            if nsteps > budget or (nsteps == PROBE_STEPS and covered < span and
                                   nsteps * span / max(covered, 1e-300) > budget):
                need = nsteps * span / max(covered, 1e-300)
                raise NumericalError(
                    f"the run to t = {t_end:.6g} needs about {need:.3g} integrator steps, more than the budget of "
                    f"{budget}: shorten the time span, loosen accuracy.rtol, or raise accuracy.max_steps")
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
            if solver.status == "finished" and k < len(order):  # pragma: no cover - defensive
                for i in order[k:]:
                    Y[i] = solver.y
                break
    return Y, nsteps


class _Lazy:
    """The step's interpolant, built only when a point inside the step is asked for."""

    def __init__(self, solver, project, t_end):
        self.solver, self.project, self.t_end = solver, project, t_end
        self.y_end = solver.y.copy()
        self._d = None

    def __call__(self, t):
        if np.ndim(t) == 0 and t == self.t_end:
            return self.y_end.copy()
        if self._d is None:
            d = self.solver.dense_output()
            self._d = _Projected(d, self.project, self.t_end, self.y_end) if self.project is not None else d
        return self._d(t)


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


def tighter(rtol: float, atol: float) -> tuple[float, float]:
    """Tolerances for the second run of ``accuracy.estimate``."""
    return max(rtol * 1e-2, 2.5e-14), max(atol * 1e-2, 1e-300)


def check_method(method: str, allowed) -> str:
    return "DOP853" if method == "auto" else method


def rel_change(values, ref, scale):
    values = np.asarray(values, dtype=float)
    s = max(abs(ref), scale, 1e-300)
    return float(np.max(np.abs(values - ref)) / s) if values.size else 0.0


def finite_or_none(x):
    return float(x) if x is not None and math.isfinite(x) else None
