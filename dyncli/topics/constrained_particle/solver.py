"""A particle constrained to a curve (notes §16 problem II, §18) — numeric core.

Routes (``accuracy.method``):

* ``quadrature`` (auto when the curve is fixed, there is no friction and
  every force depends on the position only): the energy integral along the
  curve and quadrature of dt = dq/q̇ between turning points (quadrature.py);
* ``ode`` (otherwise): the equation of motion along the tangent (dynamics.py).

Results: the motion along the curve (q, q̇, the arc length s and its rate),
x, v, a on the fixed basis, the constraint force N on the path's own basis
{e_t, e_n, e_b} and on the fixed basis, friction, the energy bookkeeping
E − E1 = W_nc + W_N (20.4 with the work of N), and the relative equilibria of
a fixed or uniformly turning curve with their stability (equilibria.py).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from dyncli import ode, runner
from dyncli.errors import InputError
from dyncli.result import Result, Series, SolveOptions

from . import dynamics, equilibria, steady
from .curve import Curve
from .setup import Rotation, Setup
from .report import SERIES, assemble, equation_numbers


def _check_curve(p, curve: Curve) -> None:
    sp = np.linalg.norm(curve.dy(p.q0)[:, 0])
    if not (np.isfinite(sp) and np.all(np.isfinite(curve.y(p.q0)))):
        raise InputError(f"the curve is not defined at q0 = {p.q0:g} (x1, x2, x3 or their derivatives are not finite "
                         "there): choose q0 where the curve exists", "curve")
    if sp == 0:
        raise InputError(f"the curve's tangent dy/dq vanishes at q0 = {p.q0:g}: q is not a regular parameter there",
                         "curve")
    rate = float(sp) * float(p.q_dot0)
    T1 = 0.5 * float(p.m) * rate * rate          # float products overflow to inf, never raise
    if not math.isfinite(T1):
        raise InputError(f"the initial kinetic energy ½ m (|dy/dq| q_dot0)² overflows (q_dot0 = {p.q_dot0:g})", "q_dot0")


#: results whose components turn with the curve (in the fixed frame): a function of the time as
#: well as of q on a turning curve, so not searched along the energy route's legs
TURNING = ("x.", "v.", "a.", "N_vec.")


def quadrature_applies(p, curve, model=None) -> bool:
    """Whether the energy integral holds: a fixed curve, or one turning at constant ω about its axis
    with every force symmetric about that axis (gravity along it, centres and anchors on it: the
    Jacobi integral, the relative motion's energy with the centrifugal potential −½ m ω² ρ²), no
    friction, damper or drag, forces of the position only (and on a turning curve no ``find`` of
    a component that turns with it)."""
    if any(f.kind in ("friction", "damper", "drag") for f in p.forces):
        return False
    if curve.rotating:
        if curve.omega_const is None or model is None or not model.compiled.symmetric_about(curve.k):
            return False
        from dyncli.motion_find import searched_paths

        asked = searched_paths(p.find) if p.find else set()
        if asked is None or any(a.startswith(TURNING) for a in asked):
            return False
    if any(f.kind == "spring" and f.one_sided for f in p.forces):
        return False          # a one-sided spring's kink in the force: the ODE route, stepped across it
    return not any(f.kind == "custom" and (set(v for e in f.F for v in e.variables) - {"x1", "x2", "x3"})
                   for f in p.forces)


def plain(p) -> Setup:
    """The validated problem as plain numbers (setup.py): everything below this module reads only it."""
    from dyncli.topics.particle.solver import accuracy, force_term

    rot = None if p.rotation is None else Rotation(tuple(p.rotation.axis), p.rotation.omega)
    return Setup(m=p.m, curve=(p.curve.x1, p.curve.x2, p.curve.x3), rotation=rot, q0=p.q0, q_dot0=p.q_dot0,
                 forces=tuple(force_term(f) for f in p.forces),
                 q_range=None if p.q_range is None else tuple(p.q_range), t_end=p.t_end, at=tuple(p.at), g=p.g,
                 find=tuple(p.find), params=p.params, steady=tuple(float(s.q) for s in p.steady),
                 accuracy=accuracy(p.accuracy), steady_only=p.steady_only)


def solve(p, options: SolveOptions | None = None) -> Result:
    return solve_setup(plain(p))


def solve_setup(p: Setup) -> Result:
    """:func:`solve` of a problem given in plain numbers (setup.py: a Setup built by hand needs
    ``t_end`` and ``at`` unless it asks only ``steady``)."""
    curve = Curve(p)
    if p.steady_only:
        return _steady_only(p, curve)
    _check_curve(p, curve)
    p, closed = _periodic(p)
    model = dynamics.Model(p, curve)
    steadies = steady.answers(p, model) if p.steady else None     # refused before the motion is solved
    meth = p.accuracy.method
    use_quad = meth == "quadrature" or (meth == "auto" and quadrature_applies(p, curve, model))
    if meth == "quadrature" and not quadrature_applies(p, curve, model):
        raise InputError("method quadrature needs a fixed curve (or one turning at constant omega with every force "
                         "symmetric about its axis, and no find of a component that turns with it), no friction, "
                         "damper or drag, and forces of the position only (the energy integral); use method ode",
                         "accuracy.method")
    if p.find:                              # the motion runs to the end of every window searched (§11)
        from dyncli.topics.particle.setup import extended

        q = extended(p)
        if q is not p:
            p, model = q, dynamics.Model(q, curve)
    times = [float(t) for t in p.at]
    res = None
    from . import find

    if use_quad:
        from . import quadrature

        res = quadrature.solve(p, model, times, fallback=(meth == "auto"))
        if res is not None:
            states = find.quadrature_states(p, model)
            t_end = float(p.t_end or 0.0)     # (set whenever the motion is asked for)
            legs = states.legs(t_end)
            find.report(p, res, states, find.uniform_breaks(t_end, res.results.get("period")) + legs, SERIES,
                        turn_times=states.legs(t_end, turning=True),
                        cuts=find.quadrature_cuts(p, model, states.energy, t_end, res.warn) if p.find else None)
    if res is None:
        res = _solve_ode(p, model, times)
        phases = res.extra.pop("phases")
        find.report(p, res, find.ode_states(p, model, phases), find.ode_breaks(res.extra.pop("breaks_of")), SERIES,
                    subdivide=1, turn_times=find.ode_turns(phases), smooth=True,
                    s_of=find.ode_arc(model, phases, float(p.q0), zip(times, res.results["s"])))
    if closed:
        res.notes.append(closed)
    equilibria.add(res, p, model)
    if steadies is not None:
        steady.add(res, steadies)
    _no_forces(res, p)
    return res


def _periodic(p: Setup) -> tuple[Setup, str | None]:
    """A curve given without ``q_range`` whose coordinates are periodic in q (read from their
    expressions, dyncli.expr.period) is a closed curve: its q_range is one period, the one that
    holds q0 (the energy route, the relative equilibria), and a note says so."""
    if p.q_range is not None:
        return p, None
    from dyncli.expr.period import common_period

    period = common_period(p.curve, "q")
    if period is None:
        return p, None
    lo = -period / 2 + period * round(float(p.q0) / period)
    return (replace(p, q_range=(lo, lo + period)),
            f"a closed curve: its coordinates repeat every {period:.10g} in q (q_range taken as [{lo:.6g}, "
            f"{lo + period:.6g}])")


def _steady_only(p, curve) -> Result:
    """Only steady queries: the rates that hold the particle, no motion (steady.py)."""
    model = dynamics.Model(p, curve)
    res = Result({}, method="closed-form", equations=["16.7", "11.11", "18.4"] + (["19.27"] if model.mu else []))
    steady.add(res, steady.answers(p, model))
    _no_forces(res, p)
    return res


def _no_forces(res, p) -> None:
    if not p.forces:
        res.warn("no forces: the particle moves under the curve's reaction alone (no gravity)"
                 + (", carried round by the turning curve" if p.rotation is not None else "")
                 + "; if it has weight, add {kind: gravity} to forces")


def _ode_method(p):
    return runner.scipy_method(p.accuracy.method)


def _solve_ode(p, model, times) -> Result:
    method = _ode_method(p)
    rtol, atol = runner.floor_rtol(float(p.accuracy.rtol)), float(p.accuracy.atol)
    phases, notes, nsteps = dynamics.integrate(model, rtol, atol, method, p.accuracy.max_steps)
    dynamics.make_dense(phases)       # every sliding step's interpolant (the turning points read them all)
    Y, modes = dynamics.states_at(phases, times)
    out = assemble(p, model, times, Y, modes)
    resid, scale = _residual(p, model, phases, out)
    res = Result(out["results"], method=f"ode:{method}", equations=equation_numbers(model),
                 series=[Series("t", times, SERIES + ["distance"])])
    res.results["energy_residual"] = resid
    res.extra["nsteps"] = nsteps
    res.extra["energy_scale"] = res.scales["energy_residual"] = scale
    res.extra["phases"] = res.extra["breaks_of"] = phases
    _friction_notes(res, model, notes, phases)
    # the runner's policy: a check solve only with accuracy.estimate (x and v each relative to its
    # scale over the run), else the nominal bound (rtol × steps, or the energy balance's drift)
    def difference(_, phases2):
        Y2 = dynamics.states_at(phases2, times)[0]
        x2, v2 = model.curve.motion(np.array(times), Y2[0], Y2[1], Y2[2])
        return ode.relative_difference(
            [(np.array(out["results"]["x"], float).T, x2), (np.array(out["results"]["v"], float).T, v2)])

    drift = resid / scale if resid is not None and scale else None
    runner.estimate_error(res, phases, estimate=p.accuracy.estimate, rtol=rtol, atol=atol,
                          rerun=lambda r2, a2: dynamics.integrate(model, r2, a2, method, p.accuracy.max_steps)[0],
                          difference=difference, drifts=(drift,), steps=nsteps)
    return res


def _residual(p, model, phases, out):
    """max |E − E1 − W_nc − W_N| over every accepted step and the times."""
    m = model.m
    x0 = model.curve.motion(0.0, p.q0, p.q_dot0, 0.0)
    E1 = float(0.5 * m * np.sum(x0[1] ** 2) + model.potential(x0[0])[0])
    resid, scale = 0.0, abs(E1)
    for ph in phases:
        Yp = ph.steps_y
        qd = np.zeros_like(Yp[1]) if ph.mode[0] == "stick" else Yp[1]
        x, v = model.curve.motion(ph.steps_t, Yp[0], qd, Yp[2])
        T = 0.5 * m * np.sum(v * v, axis=0)
        V = model.potential(x)
        resid = max(resid, float(np.max(np.abs(T + V - E1 - Yp[3] - Yp[4]))))
        scale = max(scale, float(np.max(np.abs(T))), float(np.max(np.abs(V))))
    r = out["results"]
    for E, W, WN in zip(r["E"], r["W_nc"], r["W_N"]):
        resid = max(resid, abs(E - E1 - W - WN))
    return resid, scale


def _friction_notes(res, model, notes, phases) -> None:
    if model.mu == 0:
        return
    t_rest = None
    for kind, t in notes:
        if kind == "stick":
            t_rest = t
            res.warn(f"friction: the particle comes to rest on the curve at t = {t:.6g} s and sticks")
        elif kind == "release":
            t_rest = None
            res.warn(f"friction: the particle breaks free at t = {t:.6g} s")
    res.results["t_rest"] = t_rest
