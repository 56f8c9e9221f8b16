"""A particle under forces (notes §16, §18-§22): the adapter from the validated model to the
integration (:mod:`~dyncli.topics.particle.trajectory`, forces in
:mod:`~dyncli.topics.particle.forces`, formulas in :mod:`~dyncli.topics.particle.equations`) and
from the trajectory to a :class:`~dyncli.result.Result`.

The equation of motion m a = F(t, x, v) (16.7) is built from the listed force terms and
integrated by stepping scipy's solvers (DOP853 by default).  The state is augmented with the work
of the non-conservative forces, y = [x, v, W_nc] with dW_nc/dt = F_nc·v (20.3), so that the
energy equation (20.4) E − E1 = W_nc becomes a built-in accuracy check (``energy_residual``).

``error_estimate`` (the runner's policy, dyncli/ode.py): relative to each reported quantity's
scale.  With ``accuracy.estimate`` a check solve (:func:`_check_estimate`); else nominal: rtol,
or the relative energy residual when larger (:func:`dyncli.ode.nominal_estimate`).  Under an
inverse-square force (an orbit, whose perigee passage amplifies a phase error beyond the nominal
estimate) the run is solved to its promise (:func:`_to_promise`).  An inverse-square force
alone takes the exact Kepler route instead (:mod:`~dyncli.topics.particle.orbit`).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli import ode, runner
from dyncli.errors import NumericalError
from dyncli.result import Result, Series, SolveOptions
from dyncli.topics.particle import equations as eq
from dyncli.topics.particle.forces import Forces
from dyncli.topics.particle.setup import FORCE_FIELDS, Accuracy, ForceTerm, Setup, extended
from dyncli.topics.particle.report import REPORTED, at_times, energy_residual, report_terms, reported
from dyncli.topics.particle.trajectory import MAX_STEPS, OdePhase, RestPhase, Trajectory, integrate  # noqa: F401 (re-exported)


def _ode_method(p) -> str:
    return runner.scipy_method(p.accuracy.method)


def force_term(f) -> ForceTerm:
    """The plain copy of a validated force entry (of ``particle`` or ``constrained-particle``): its
    kind and the fields it has (vectors as tuples of floats; a custom term's compiled expressions)."""
    kw = {n: getattr(f, n) for n in FORCE_FIELDS if hasattr(f, n)}
    for n in ("F", "center", "anchor"):
        if n in kw and kw[n] is not None:
            kw[n] = tuple(kw[n])
    return ForceTerm(f.kind, **kw)


def accuracy(a) -> Accuracy:
    """The plain copy of the validated ``accuracy`` block."""
    return Accuracy(a.rtol, a.atol, a.method, a.estimate, a.max_steps, a.max_cpu)


def plain(p) -> Setup:
    """The validated problem as plain numbers (setup.py): everything below this module reads only it."""
    return Setup(m=p.m, x0=tuple(p.x0), v0=tuple(p.v0), forces=tuple(force_term(f) for f in p.forces), t_end=p.t_end,
                 at=tuple(p.at), g=p.g, find=tuple(p.find), params=p.params, basis=p.basis,
                 steady=tuple(tuple(q.axis) for q in p.steady), accuracy=accuracy(p.accuracy))


def solve(p, options: SolveOptions | None = None) -> Result:
    """The motion, and the steady circular motions of ``steady`` (steady.py; alone: no motion)."""
    return solve_setup(plain(p))


def solve_setup(s: Setup) -> Result:
    """:func:`solve` of a problem given in plain numbers (setup.py: a Setup built by hand needs
    ``t_end`` and ``at`` unless it asks only ``steady``)."""
    from . import steady

    steady_only = bool(s.steady) and not s.at and s.t_end is None and not s.find
    s = extended(s)                     # the motion runs to the end of every window searched (§11)
    F = Forces(s)
    notes: list[str] = []
    entries = steady.answers(s, F, notes.append) if s.steady else None      # refused before the motion is solved
    if steady_only:
        res = Result({}, method="closed-form", equations=["16.7", "11.11"])
    else:
        res = _motion(s)
    if entries is not None:
        res.results["steady"] = entries
    for n in notes:
        res.warn(n)
    return res


def _motion(p) -> Result:
    from . import find, orbit

    F = Forces(p)
    notes: list[str] = []
    orb = orbit.choose(p, notes)
    if orb is not None:
        res = orbit.solve_exact(p, F, orb)
        t_end = float(p.t_end)
        T = orb.period if orb.kind == "elliptic" and orb.period is not None and orb.period < t_end else None
        if T is not None and t_end / T > orbit.PIECES_CAP / orbit.PIECES_PER_TURN and p.find:
            res.warn(f"find: the orbit makes {t_end / T:.3g} turns to t = {t_end:g} s, more than "
                     f"{orbit.PIECES_CAP // orbit.PIECES_PER_TURN} searched piece by piece: crossings inside "
                     "one piece of several turns may be missed (narrow the search with within)")
        find.report(p, res, res.extra["sample"], lambda: res.extra["trajectory"], orbit.breaks(orb, t_end),
                    period=(T, orbit.breaks(orb, T)) if T is not None else None)
        for msg in notes:
            res.warn(msg)
        return res
    rtol, atol = float(p.accuracy.rtol), float(p.accuracy.atol)
    times = [float(t) for t in p.at]
    # every step's dense output: the distance travelled, the find queries, and the work of several
    # non-conservative terms (a quadrature over the steps; of one term it is W_nc itself)
    traj, method, switched = _integrate_route(p, F, rtol, atol, times, True)
    res = Result({}, method=f"ode:{method}", equations=_equations(F))
    if F.inv and p.t_end > 0:           # an orbit: the nominal estimate cannot be trusted
        traj = _to_promise(res, p, F, traj, method, rtol, atol, times, True)
    orb = orbit.conic(p)
    if orb is not None and not orb.radial:
        res.results["orbit"] = orbit.orbit_results(orb)
    S = at_times(traj, F, times, steps=True)
    resid, scale = energy_residual(p, F, S)
    res.results.update(reported(S, resid))
    res.scales["energy_residual"] = scale
    res.series.append(Series("t", times, list(REPORTED) + ["distance"]))
    report_terms(res, p, F, traj, S)
    res.extra["nfev"] = traj.nfev
    res.extra["sample"] = sampler = _Sampler(p, F, traj, method, times)     # the dense output, for plots
    find.report(p, res, lambda ts: sampler(ts), sampler.dense)
    res.extra["nsteps"] = traj.nsteps
    if not p.forces:
        res.warn("no forces: the particle moves in a straight line at constant velocity (no gravity); "
                 "if it has weight, add {kind: gravity} to forces")
    res.extra["state"] = res.extra["sample"].state
    for msg in notes:
        res.warn(msg)
    if switched:
        res.warn("method auto: the problem is stiff for DOP853, so it was integrated with LSODA; "
                 f"DOP853 reported: {switched}")
    res.extra["energy_scale"] = scale
    if F.muN:
        _report_friction(res, F, traj)
    _report_inside_R0(res, F, traj)
    if resid > 1e3 * (rtol * scale + atol) and resid > 1e-9 * scale:
        res.warn(f"energy residual {resid:.3g} J is large for rtol = {rtol:g} (energy scale {scale:.3g} J): "
                 "tighten accuracy.rtol")
    if not p.t_end > 0:
        res.error_estimate = 0.0            # nothing integrated: the initial state is exact
    elif F.inv:
        pass                                # set by _to_promise
    elif p.accuracy.estimate:
        _check_estimate(res, p, F, traj, S, rtol, atol, method)
    else:                                   # the relative drift of the energy equation (20.4)
        ode.nominal_estimate(res, rtol, resid / scale if scale > 0 else 0.0, steps=traj.nsteps)
    return res


def _to_promise(res, p, F, traj, method, rtol, atol, times, dense) -> Trajectory:
    """An inverse-square force (an orbit): the runner's :func:`~dyncli.runner.solve_to_promise`,
    a check solve for every reported run, the internal rtol tightened until the estimate meets
    100 x rtol (docs/accuracy.md: on an eccentric orbit the nominal estimate was 0.0004-0.6 of the
    true error, itself 500-700,000 x rtol, benchmarks/eccentric_orbits.py).  The check runs
    take steps at most half the reported run's longest (:func:`_check_estimate`)."""
    from . import orbit

    def run(r, a, ref):
        hmax = ref.hmax / 2 if ref is not None and ref.hmax > 0 else math.inf
        return integrate(p, F, r, a, method, max_steps=p.accuracy.max_steps, times=times,
                         dense=dense and ref is None, max_step=hmax)

    def difference(out, check):
        S1, S2 = at_times(out, F, times), at_times(check, F, times)
        return ode.relative_difference([(S1[k], S2[k]) for k in REPORTED])

    out, _ = runner.solve_to_promise(res, run, difference, rtol, atol, out=traj)
    if res.error_estimate is not None and res.error_estimate > runner.PROMISE * rtol and orbit.kepler_field(p):
        res.warn("an inverse-square force alone is solved to rounding by the exact route (Kepler's "
                 "equation): leave accuracy.method at auto, or set it to exact")
    return out


class _Sampler:
    """The motion at any times (plots): the run again with every step's dense output, made on the
    first call (the same steps, so the requested times give the results exactly)."""

    def __init__(self, p, F, traj, method, times):
        self.p, self.F, self.traj, self.method, self.times = p, F, traj, method, times

    def dense(self) -> Trajectory:
        if not self.traj.dense:
            p = self.p
            self.traj = integrate(p, self.F, float(p.accuracy.rtol), float(p.accuracy.atol), self.method,
                                  max_steps=p.accuracy.max_steps, times=self.times, dense=True)
        return self.traj

    def __call__(self, ts) -> dict:
        return at_times(self.dense(), self.F, ts)

    def state(self, t: float) -> dict:
        """The reported results at one time t (single values), from the dense output."""
        S = self([float(t)])
        return {k: (S[k][:, 0].tolist() if S[k].ndim == 2 else float(S[k][0])) for k in REPORTED}


def _integrate_route(p, F, rtol, atol, times, dense):
    """(trajectory, method, why it switched or None): method auto hands a run that is stiff for
    DOP853 to LSODA."""
    method = _ode_method(p)
    kw = {"max_steps": p.accuracy.max_steps, "times": times, "dense": dense}
    try:
        return integrate(p, F, rtol, atol, method, **kw), method, None
    except NumericalError as exc:
        if p.accuracy.method != "auto" or not getattr(exc, "stiff", False):
            raise
        try:
            traj = integrate(p, F, rtol, atol, "LSODA", **kw)
        except NumericalError:
            raise exc from None
        return traj, "LSODA", str(exc)


def _check_estimate(res, p, F, traj, S, rtol, atol, method) -> None:
    """The runner's check solve (ode.check_solve: rtol/100, its one looser fallback over the step
    budget); error_estimate: the largest difference of every reported quantity at the requested
    times, each relative to its own scale over the run (ode.relative_difference).  The tighter
    check run's steps are at most half the longest step of the reported run: steps limited by
    their growth from a small first step, not by the tolerance, would otherwise be the very same
    steps (and the difference zero) at any tolerance.  (The looser fallback runs only for a long
    run, whose steps the tolerance limits.)"""
    hmax = traj.hmax / 2 if traj.hmax > 0 else math.inf
    times = S["t"]

    def run(r2, a2):
        return integrate(p, F, r2, a2, method, max_steps=p.accuracy.max_steps, times=times, dense=False,
                         max_step=hmax if r2 < rtol else math.inf)

    check = ode.check_solve(res, run, rtol, atol)
    if check is None:
        return
    S2 = at_times(check[0], F, times)
    res.error_estimate = ode.relative_difference([(S[k], S2[k]) for k in REPORTED])


def _report_friction(res, F, traj) -> None:
    """Friction: stops, sticking, slipping, and t_rest."""
    t_rest = None
    slips = [t for kind, t, _ in traj.notes if kind == "slip"]
    if slips:
        when = f"at t = {slips[0]:.6g} s" if len(slips) == 1 else \
            f"{len(slips)} times (first at t = {slips[0]:.6g} s, last at t = {slips[-1]:.6g} s)"
        res.warn(f"friction: the particle stops momentarily {when} and slips on "
                 f"(|other forces| > mu N = {F.muN:.6g} N there)")
    for kind, t, nFo in traj.notes:
        if kind == "stick":
            t_rest = t
            res.warn(f"friction: the particle comes to rest at t = {t:.6g} s and sticks "
                     f"(|other forces| = {nFo:.6g} N <= mu N = {F.muN:.6g} N)")
        elif kind == "release":
            t_rest = None
            res.warn(f"friction: the particle breaks free at t = {t:.6g} s "
                     f"(|other forces| = {nFo:.6g} N > mu N = {F.muN:.6g} N)")
    res.results["t_rest"] = t_rest
    if t_rest is None:
        res.warn("t_rest is null: the particle does not come to rest for good before t_end")


def _report_inside_R0(res, F, traj) -> None:
    """Inverse-square: a path below R0 passes inside the attracting body."""
    if not F.inv:
        return
    X = np.concatenate([traj.steps()[1][0:3]] + [ph.x[:, None] for ph in traj.phases if isinstance(ph, RestPhase)],
                       axis=1)
    for c, _, R0 in F.inv:
        Rmin = float(np.min(eq.distance(X - c[:, None])))
        if Rmin < R0 * (1 - 1e-9):
            res.warn(f"the path passes inside R0 = {R0:g} m of the inverse-square centre "
                     f"(R_min = {Rmin:.6g} m): below the surface of the attracting body")


def _equations(F: Forces) -> list[str]:
    eq = ["16.7", "18.6"]
    if F.weight:
        eq.append("19.23")
    if F.inv:
        eq += ["19.18", "19.20b"]
    if F.springs:
        eq += ["19.26a", "19.26b"]
    if F.muN:
        eq.append("19.27")
    eq += ["20.3", "20.4", "20.5", "21.3"]
    return eq


