"""The `top`'s ODE route (accuracy.method DOP853, RK45, Radau, LSODA, projected).

Two formulations of (38.18), chosen before integrating from the turning points:

* away from the vertical, the reduced equations in (θ, θ̇, ψ, φ) with p_ψ and ω3 held
  exactly (:mod:`dyncli.topics.top.reduced`): four states, the cost of a plain script;
* next to θ = 0 or π (and for ``projected``), the spin-free quaternion form of
  :mod:`dyncli.topics.top.integrator`, which has no singularity there.

error_estimate: the runner's policy (dyncli/ode.py, docs/accuracy.md).  With
accuracy.estimate, a check solve (:func:`dyncli.ode.check_solve`: rtol/100, its one
fallback) and :func:`dyncli.ode.relative_difference` over ψ, θ, φ, ψ̇, θ̇, φ̇ and R, each
relative to its own scale over the requested times (θ̇ and ψ̇ at least a tenth of
|ω⊥|max, the transverse-rate bound from the energy integral: in steady precession θ̇ ≡ 0,
its computed values are the integrator's own error and no scale of their own).  Without it (the default), one solve and
:func:`dyncli.ode.nominal_estimate` with the relative drifts of the invariants (E; with the
quaternion form also H_O·e3 and ω3; the reduced form keeps p_ψ and ω3 exactly).

Both forms cap the step at h ≤ 1/W (W the fastest rate) while the axis nutates: with
longer steps DOP853's error estimator underestimates (module docstring of
:mod:`dyncli.topics.top.reduced`); a check solve's cap shrinks with its tolerance
(:func:`step_cap`).
"""

from __future__ import annotations

import math
import sys

import numpy as np

from dyncli import ode, runner
from dyncli.errors import NumericalError
from dyncli.topics.top.derived import rates, reaction
from dyncli.topics.top.integrator import integrate
from dyncli.topics.top.kinematics import Controls
from dyncli.topics.top.reduced import FLOOR, Reduced, usable

EPS = sys.float_info.epsilon
#: below this rtol the route runs its check solve by default (issue 28: round-off floors, not rtol)
TIGHT_RTOL = 1e-11
#: refusal when the a-priori step estimate exceeds the budget by this factor
PREDICT_MARGIN = 4.0


def check_budget(acc: Controls, T, Wfast, Wp, W3, C, A):
    """Refuse at once a run clearly over the step budget (the estimate is 1.1-1.9 times the steps)."""
    budget = int(acc.max_steps or ode.MAX_STEPS)
    work = T * (Wfast + Wp)
    rtol_eff = runner.floor_rtol(min(acc.rtol, 1e-3))
    steps = 0.3 * work * (1e-3 / rtol_eff) ** 0.125
    if not steps <= PREDICT_MARGIN * budget:
        raise NumericalError(
            f"the run to t = {T:g} s needs about {steps:.3g} integrator steps (it turns the top through "
            f"~{work:.3g} rad at its fastest rate: spin {abs(W3):.3g} rad/s, nutation ~I33 ω3/I11 = "
            f"{abs(C * W3 / A):.3g} rad/s), more than the budget of {budget}: shorten 'at', loosen "
            "accuracy.rtol, or raise accuracy.max_steps (or use accuracy.method auto: the exact route "
            "has no budget)")


def motion(top, run, inv, rates, reaction):
    """Reported arrays (requested order) of one run."""
    psi, theta, phi, w = run.psi[inv], run.theta[inv], run.phi[inv], run.w[inv]
    # ω on p and φ_p give the same rates and reaction as body ω and φ (rotation about e'_3)
    psi_dot, th_dot, phi_dot, S = rates(top, theta, run.phi_p[inv], w)
    R = reaction(top, theta, run.phi_p[inv], w)
    return psi, theta, phi, psi_dot, th_dot, phi_dot, S, R


def route(res, top, acc: Controls, y0, psi0, phi0, times, Wfast, Wp, scales, *, state, bounds: tuple[float, float]):
    """The integrated motion at ``times`` (requested order) and its error estimate.
    ``state``: (ψ0, θ0, φ0, ψ̇0, θ̇0, φ̇0); ``bounds``: (θ_min, θ_max)."""
    ts, inv = _sorted_times(times)
    method = acc.method           # "projected" stays: the integrator projects (DOP853 steps it)
    method = method if method == "projected" else runner.scipy_method(method)
    rtol, atol = acc.rtol, acc.atol
    T = ts[-1] if ts else 0.0
    if ts:
        res.method = "ode:DOP853+projection" if method == "projected" else f"ode:{method}"
    if not T > 0:
        if ts:
            res.error_estimate = 0.0
        return _quaternion_run(top, acc, y0, psi0, phi0, ts, inv, method, Wp, scales, rtol, atol, math.inf)[0]
    check_budget(acc, T, Wfast, Wp, float(y0[6]), top.C, top.A)
    red = Reduced(top, state, bounds, Wp)
    quat = method == "projected" or not usable(top, *bounds, red.w3, red.b, Wp, Wfast, rtol)

    def run_at(r, a):
        h = step_cap(bounds, Wfast, method, r / rtol)
        if quat:
            return _quaternion_run(top, acc, y0, psi0, phi0, ts, inv, method, Wp, scales, r, a, h)
        return _reduced_run(red, acc, ts, inv, method, scales, r, a, h)

    out, drifts, nsteps = run_at(rtol, atol)
    fl = FLOOR * Wp
    # below TIGHT_RTOL round-off floors, not rtol, bound the error (measured: 5-200 × rtol at 1e-12,
    # 13-2,000 × at 1e-13): the check solve runs by default there, and the larger figure is reported
    check = acc.estimate or rtol < TIGHT_RTOL
    runner.estimate_error(           # the runner's policy: check solve (and fallback) or nominal
        res, out, estimate=check, rtol=rtol, atol=atol, rerun=lambda r, a: run_at(r, a)[0],
        difference=lambda a, b: ode.relative_difference(
            [(x, y) for k, (x, y) in enumerate(zip(a, b)) if k in REPORTED], [0.0, 0.0, 0.0, fl, fl, 0.0, 0.0]),
        note="the largest difference of ψ, θ, φ, ψ̇, θ̇, φ̇, R, each relative to its scale over the requested "
             "times, from a check solve at {how}", drifts=drifts, steps=nsteps)
    measured = res.error_estimate if check else None          # the check solve's difference
    nominal = max([rtol * max(nsteps, 1), *(d for d in drifts if d is not None)])
    if check and not acc.estimate and measured is not None and nominal > measured:
        res.error_estimate = nominal
        res.extra["error_estimate_note"] = ode.NOMINAL_NOTE
    _floor_and_warning(res, rtol, drifts, bounds, measured, floor=not acc.estimate)
    return out


#: safety factor of the pole round-off floor POLE_FACTOR·ε/sinθ (θ the closest approach to a pole; measured:
#: 0.9 ε/sinθ for a top released 1e-6 rad from the vertical)
POLE_FACTOR = 4.0


def _floor_and_warning(res, rtol, drifts, bounds, checked, floor=True):
    """Issue 28: (1) the estimate is at least the round-off floor of a motion next to a pole,
    POLE_FACTOR·ε/sinθ at the closest approach (ψ, φ and their rates are individually ill-conditioned
    there: 1e-16/sinθ absolute, whatever rtol — a top released 1e-6 rad from the vertical keeps an
    error of 2e-10 at every rtol below 1e-10, which rtol × steps at 1e-12 and a check solve's
    difference, 0.98 of it, did not cover); (2) a measured error — the check solve's difference, or
    the invariants' drift (``checked``: the difference, None without a check solve) — or that floor
    above the route's promise (100 × rtol) is said, with its size.  With ``accuracy.estimate`` (``floor``
    false) the estimate is the check solve's difference as asked (0.98-1.02 × the error there too)."""
    s = min(math.sin(bounds[0]), math.sin(bounds[1]))
    pole = POLE_FACTOR * EPS / s if floor and 0.0 < s < 1.0 else 0.0
    if res.error_estimate is not None and pole > res.error_estimate:
        res.error_estimate = pole
        res.extra["error_estimate_note"] = (
            f"the round-off floor next to the pole, {POLE_FACTOR:g}·ε/sinθ at the closest approach (sinθ = "
            f"{s:.3g}): ψ, φ and their rates are ill-conditioned there whatever rtol")
    drift = max([0.0, *(d for d in drifts if d is not None)])
    measured = max(checked, pole) if checked is not None else max(drift, pole)
    what = ("the check solve's difference" if checked is not None and checked >= pole else
            "the round-off floor next to the pole" if pole > drift else "the drift of the invariants")
    runner.warn_unmet(res, rtol, measured, promise=runner.ODE_PROMISE, what=what)


def dense_motion(top, acc: Controls, T: float, Wfast, Wp, *, state, bounds, y0, scales):
    """The motion from 0 to T as one run's dense output for the ``find`` search: (the steps' ends,
    ``states(ts)``) of the form the route takes — the reduced form
    (:meth:`dyncli.topics.top.reduced.Reduced.dense`) or, next to the vertical and for
    ``projected``, the quaternion form (:func:`dyncli.topics.top.integrator.dense_run`: ψ and φ
    carried from each step's start by the tracker); None when T is not positive or the axis comes
    within :data:`DENSE_POLE` of the vertical (ψ swings by ~π in ~θ_min/ω there: no interpolant
    resolves it, and the tracker bisects every point — that motion is searched by solving again
    on a grid, sampled, with a warning: :func:`dyncli.motion_find.resolved`)."""
    from dyncli.topics.top.integrator import dense_run

    method = acc.method if acc.method == "projected" else runner.scipy_method(acc.method)
    red = Reduced(top, state, bounds, Wp)
    if not T > 0:
        return None
    cap = step_cap(bounds, Wfast, method)
    if min(math.sin(bounds[0]), math.sin(bounds[1])) < DENSE_POLE:
        return None
    if method == "projected" or not usable(top, bounds[0], bounds[1], red.w3, red.b, Wp, Wfast, acc.rtol):
        return dense_run(top, y0, state[0], state[2], T, rtol=acc.rtol, atol=acc.atol, method=method, Wp=Wp,
                         scales=scales, max_steps=acc.max_steps, max_step=cap)
    return red.dense(T, rtol=acc.rtol, atol=acc.atol, method=method, max_step=cap, max_steps=acc.max_steps)


#: closest approach to a pole (sinθ) below which the ``find`` search reads samples (:func:`dense_motion`)
DENSE_POLE = 1e-3


def step_cap(bounds, Wfast, method, ratio=1.0):
    """The largest step while the axis nutates: 1/W (W the fastest rate), times ratio^(1/order) for
    a run at ``ratio`` × rtol (the step an error ∝ h^order scales by), so that a check solve's
    capped steps are as much shorter as its uncapped ones (with the same cap both runs would make
    the same capped-step error, and their difference would miss it).  No cap in steady precession."""
    if not (bounds[1] > bounds[0] and Wfast > 0):
        return math.inf
    return ratio ** (1.0 / (8.0 if method in ("DOP853", "projected") else 5.0)) / Wfast


#: indices of the reported quantities in a run's output (ψ, θ, φ, ψ̇, θ̇, φ̇, R; not S, drift, ...)
REPORTED = (0, 1, 2, 3, 4, 5, 7)


def _quaternion_run(top, acc: Controls, y0, psi0, phi0, ts, inv, method, Wp, scales, rtol, atol, cap):
    run = integrate(top, y0, psi0, phi0, ts, rtol=rtol, atol=atol, method=method, Wp=Wp, scales=scales,
                    max_steps=acc.max_steps, max_step=cap)
    return motion(top, run, inv, rates, reaction) + (max(run.drift), run.ambiguous), run.drift, run.steps


def _reduced_run(red, acc: Controls, ts, inv, method, scales, rtol, atol, cap):
    """One run of the reduced form at the sorted times ``ts`` (requested order by ``inv``)."""
    uniq, back = np.unique(np.asarray(ts, dtype=float), return_inverse=True)
    arrays, dE = red.run(uniq, rtol=rtol, atol=atol, method=method, max_step=cap,
                         max_steps=acc.max_steps)
    drift = dE * red.top.A / scales[0] if scales[0] > 0 else 0.0
    idx = back[inv]
    return tuple(a[idx] for a in arrays) + (drift, []), (drift,), red.steps


def _sorted_times(times):
    order = np.argsort(np.asarray(times, dtype=float), kind="stable")
    inv = np.empty(len(times), dtype=int)
    inv[order] = np.arange(len(times))
    return [float(times[i]) for i in order], inv
