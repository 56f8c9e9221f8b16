"""The ``scene`` solver (contract §10): the only reader of the validated model.

1. the model becomes plain data (:class:`build.Plan`), then bodies, points and joint rows;
2. assembly places the positions left out; the degrees of freedom come from the rank of J;
3. the route, the cheapest exact one: ``statics`` or ``kinematics`` (0 DOF), ``closed-form``
   (one DOF, affine), ``ode`` (otherwise);
4. one-sided joints are watched on every route; the first stopping event ends the motion;
5. results at the requested times, the events with their state, the ``find`` queries.
"""

from __future__ import annotations

from dyncli.expr.jet import jet_at
from dyncli.result import Result, SolveOptions

from . import build, outcome, prepare, routes


def _plan(p) -> build.Plan:
    bodies = {}
    for name, b in p.bodies.items():
        shape = b.shape or ("disk" if b.radius else "rod" if b.length else "box" if b.size else "custom")
        bodies[name] = {"shape": shape, "mass": b.mass, "length": b.length, "radius": b.radius, "size": b.size,
                        "I": b.I, "x": b.x, "angle": b.angle, "v": b.v, "omega": b.omega,
                        "points": {k: tuple(v) for k, v in b.points.items()}}
    surfaces = {k: {"through": s.through, "direction": s.direction} for k, s in p.surfaces.items()}
    joints = {}
    for name, j in p.joints.items():
        val = getattr(j, j.kind)
        if j.kind == "cord":
            val = [it.model_dump() if hasattr(it, "model_dump") else it for it in val]
        d = {"kind": j.kind, j.kind: val, "mu": j.mu, "mu_s": j.mu_s, "mu_k": j.mu_k, "at": j.at,
             "length": j.length, "angle": j.angle}
        if j.kind == "drive":
            e = j.value
            d["value"] = lambda t, e=e: jet_at(e, t)
        joints[name] = d
    loads = []
    for f in p.forces:
        d = {"kind": f.kind, "name": f.name, "spring": f.spring, "damper": f.damper, "force": f.force,
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


def solve(p, options: SolveOptions | None = None) -> Result:
    plan = _plan(p)
    scene = prepare.setup(plan)
    times = [float(t) for t in p.at]
    acc = p.accuracy
    traj, route = routes.run(scene, float(p.t_end), acc)
    return outcome.results(scene, traj, route, times, p.find, dict(p.params), acc)
