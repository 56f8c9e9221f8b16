"""The ``scene`` solver (docs/types/scene.md): the only reader of the validated model.

1. the model becomes plain data (:class:`build.Plan`), then bodies, points and joint rows;
2. assembly places the positions left out; the degrees of freedom come from the rank of J;
3. the route, the cheapest exact one: ``statics`` or ``kinematics`` (0 DOF), ``closed-form``
   (one DOF, affine), ``ode`` (otherwise; ``quadrature`` on request);
4. one-sided joints are watched on every route; the first stopping event ends the motion;
5. results at the requested times, the events with their state, the ``find`` queries.
"""

from __future__ import annotations

from dataclasses import replace

from dyncli import ode
from dyncli.errors import InputError, NumericalError
from dyncli.expr import resolve_params
from dyncli.expr.jet import jet, jet_at
from dyncli.integrators import Accuracy
from dyncli.result import Result, SolveOptions

from . import build, outcome, prepare, report, routes


def _plan(p) -> build.Plan:
    bodies = {}
    for name, b in p.bodies.items():
        shape = b.shape or ("disk" if b.radius else "rod" if b.length else "box" if b.size else "custom")
        bodies[name] = {"shape": shape, "mass": b.mass, "length": b.length, "radius": b.radius, "size": b.size,
                        "I": b.I, "x": b.x, "angle": b.angle, "v": b.v, "omega": b.omega,
                        "points": {k: tuple(v) for k, v in b.points.items()}}
    surfaces = {k: {"through": s.through, "direction": s.direction, "length": s.length, "q_range": s.q_range,
                    "curve": (s.curve.x1, s.curve.x2) if s.curve is not None else None, "body": s.body,
                    "corner": s.corner, "normals": s.normals}
                for k, s in p.surfaces.items()}
    joints = {}
    for name, j in p.joints.items():
        val = getattr(j, j.kind)
        if j.kind == "cord":
            val = [it.model_dump() if hasattr(it, "model_dump") else it for it in val]
        d = {"kind": j.kind, j.kind: val, "mu": j.mu, "mu_s": j.mu_s, "mu_k": j.mu_k, "at": j.at,
             "length": j.length, "angle": j.angle, "e": j.e, "radii": j.radii, "internal": j.internal}
        if j.kind == "drive":
            e = j.value
            d["value"] = lambda t, e=e: jet_at(e, t)
            d["values"] = lambda T, e=e: jet(e, T)
        joints[name] = d
    loads = []
    for f in p.forces:
        d = {"kind": f.kind, "name": f.name, "spring": f.spring, "damper": f.damper, "force": f.force.model_dump() if hasattr(f.force, "model_dump") else f.force,
             "torque": f.torque, "k": f.k, "L": f.L, "one_sided": f.one_sided, "c": f.c, "constant": True}
        if f.F is not None:
            fns = [e.scalar_fn() for e in f.F]
            d["F"] = lambda t, fns=fns: (float(fns[0]({"t": t})), float(fns[1]({"t": t})))
            d["constant"] = all(not e.variables for e in f.F)
        if f.M is not None:
            fn = f.M.scalar_fn()
            d["M"] = lambda t, fn=fn: float(fn({"t": t}))
            d["constant"] = not f.M.variables
        loads.append(d)
    return build.Plan(bodies, surfaces, joints, loads, float(p.g))


def _search_end(t_end: float, find, params) -> float:
    """The motion runs to t_end, extended to a `find` query's `within` window when that ends
    later (§11); a malformed window is left to the queries' own validation."""
    from dyncli.expr import constant

    for q in find or []:
        w = q.get("within") if isinstance(q, dict) else None
        if isinstance(w, (list, tuple)) and len(w) == 2:
            try:
                t_end = max(t_end, float(constant(w[1], params)))
            except (InputError, ValueError, TypeError):     # reported by dyncli.queries with its field path
                pass
    return t_end


def solve(p, options: SolveOptions | None = None) -> Result:
    """The scene solved; a linear solve, a division or a square root that fails on the way (a
    degenerate geometry — a body that does not fit its surface's curvature, coincident points —
    or numbers beyond the doubles) is a numerical failure with what to check (exit 1), not an
    internal error."""
    import numpy as np

    try:
        return _solve(p, options)
    except (np.linalg.LinAlgError, ZeroDivisionError, OverflowError) as exc:
        raise NumericalError(_degenerate(exc)) from None
    except ValueError as exc:
        if "math domain error" not in str(exc):
            raise
        raise NumericalError(_degenerate(exc)) from None


def _degenerate(exc: Exception) -> str:
    return (f"the scene's equations cannot be evaluated ({type(exc).__name__}: {exc}): its geometry is degenerate "
            "(a body that does not fit the curvature of its surface, points that coincide, a size of 0) or its "
            "numbers are beyond the doubles; check the sizes and positions, or rescale the units")


def _solve(p, options: SolveOptions | None) -> Result:
    plan = _plan(p)
    times = [float(t) for t in p.at]
    a = p.accuracy
    acc = Accuracy(float(a.rtol), float(a.atol), a.method, bool(a.estimate), a.max_steps)
    params = resolve_params(p.params)
    t_end = _search_end(float(p.t_end), p.find, params)
    scene = prepare.setup(plan)
    traj, route = routes.run(scene, t_end, acc)
    res = outcome.results(scene, traj, route, times, p.find, params, acc)
    if route == "ode" and acc.estimate:
        _check_solve(res, plan, t_end, times, acc)
    if p.linearize:
        _linearize(res, plan, times)
    if options is not None and options.symbolic:
        _symbolic(res, p, plan)
    return res


def _symbolic(res: Result, p, plan) -> None:
    """``--symbolic``: the equations in the notes' form (sympy, imported only here), on a scene
    set up afresh (the route may have changed the contacts' modes)."""
    from . import symbolic, symbolic_view

    exprs = {"drive": {n: j.value for n, j in p.joints.items() if j.kind == "drive"},
             "load": {i: (f.F if f.kind == "force" else [f.M]) for i, f in enumerate(p.forces)
                      if f.kind in ("force", "torque")}}
    try:
        derived = symbolic.derive(prepare.setup(plan), exprs)
    except ValueError as exc:           # a curve's arc without a closed form
        res.warn(f"--symbolic: the equations are not written out: {exc} (the numeric results are exact as always)")
        return
    res.views.extend(symbolic_view.views(derived))


def _linearize(res: Result, plan, times: list[float]) -> None:
    """`linearize: true`: the equilibria and small oscillations, on a scene set up afresh (the
    route may have changed the contacts' modes)."""
    from . import modes, views

    from dyncli import cputime
    from dyncli.errors import NumericalError

    scene = prepare.setup(plan)
    why = modes.refusal(scene)
    if why:
        raise InputError(why, "linearize")
    try:
        res.results["equilibria"] = modes.results(scene, times, res.warn)
    except NumericalError:
        if (limit := cputime.over()) is None:
            raise
        curved = [n for n, sf in plan.surfaces.items() if "curve" in sf and sf.get("q_range") is None]
        where = (f"; on a curve without q_range ({', '.join(curved)}) the search runs over several laps of it: give "
                 "the curve a q_range that holds the motion" if curved else "")
        raise NumericalError(f"linearize: the search for the rest configurations along the joints' paths used the "
                             f"solve's CPU budget of {limit:g} s (accuracy.max_cpu){where}, or raise accuracy.max_cpu "
                             "(the motion alone, without linearize, is not limited by it)") from None
    res.views.extend(views.equilibria(res.results["equilibria"]))


def _kind(key: str) -> str:
    """The kind of a flattened result: x, v, a, angle, omega, alpha, force or energy."""
    parts = [p for p in key.split(".") if p not in ("events", "state")]
    head = parts[0]
    if head == "point":
        return parts[-1]
    if head in ("reaction", "drive", "force"):
        return "force"
    if head in ("T", "V", "E", "W_nc", "energy_residual"):
        return "energy"
    return head


def _check_solve(res: Result, plan, t_end: float, times: list[float], acc: Accuracy) -> None:
    """``accuracy.estimate``: the one check-solve rule of the ODE routes (dyncli.ode.check_solve):
    the scene solved again at tighter tolerances; the estimate is the largest difference of every
    reported quantity at the requested times, the events' times and states included, each
    relative to its own scale."""
    def flat(r) -> dict:
        out = report.flatten({k: r.get(k) for k in report.PER_TIME})
        for i, ev in enumerate(r.get("events", [])):
            out[f"events.{i}.t"] = ev["t"]
            out.update(report.flatten(ev["state"], f"events.{i}.state."))
        return out

    def run(rtol: float, atol: float) -> dict:
        acc2 = replace(acc, rtol=rtol, atol=atol, estimate=False)
        scene2 = prepare.setup(plan)
        traj2, route2 = routes.run(scene2, t_end, acc2)
        return flat(outcome.results(scene2, traj2, route2, times, [], {}, acc2).results)

    got = ode.check_solve(res, run, acc.rtol, acc.atol)
    if got is None:
        return
    other, _how = got
    mine = flat(res.results)
    groups: dict[str, list] = {}
    for k, v in mine.items():       # one scale per quantity over the times: x.A.0 over every time
        key = ".".join(part for part in k.split(".") if not part.isdigit())
        groups.setdefault(key, []).append((v, other.get(k, v)))
    # each quantity at least at the scale of its kind (a component that is 0 but for rounding is
    # measured against the positions, forces or energies of the scene, not against itself)
    kinds: dict[str, float] = {}
    for key, g in groups.items():
        kinds[_kind(key)] = max(kinds.get(_kind(key), 0.0), max(abs(a) for a, _ in g))
    keys = list(groups)
    pairs = [([a for a, _ in groups[k]], [b for _, b in groups[k]]) for k in keys]
    res.error_estimate = ode.relative_difference(pairs, [kinds[_kind(k)] for k in keys])
    res.extra.pop("error_estimate_note", None)
