"""The results of a solved scene: the state at every requested time, the events with their
state, the first integrals, W_nc (integrated along the ODE route, by quadrature of the power on
the exact routes), the error estimate of each route and the ``find`` answers."""

from __future__ import annotations

import math

import numpy as np

from dyncli import ode
from dyncli.result import Result, Series

from . import assembly, motion, report
from .contacts import Contact, Rolls

EPS = float(np.finfo(float).eps)
from .prepare import Scene

#: the integrand of W_nc, as the quadrature names it in a refusal
WNC_POWER = "the power of the non-conservative forces (W_nc)"


# ----------------------------------------------------------------------------- results

def instants_of(scene: Scene, traj, route: str, times=()):
    """inst(t): every result at one instant of the solved motion (the forces from the route's
    own solve: the kinematics' J λ balance, the closed form's motion along its one direction);
    ``times``: the instants about to be asked (their W_nc integrated together, _Work.prime)."""
    s = scene.system

    def state_at(t, after=False):
        p = traj.piece(t)
        if after:                               # the state the next phase starts from (after a jump)
            p = _next_piece(traj, t)
            motion.set_modes(s, p.modes)
            q, v, W = p.fn(min(max(t, p.t_a), p.t_b))
        else:
            q, v, W = traj.state(t)
        solved = p.fixed
        if p.route == "kinematics":
            a, lam = _kin_forces(s, q, v, t)
            solved = (a, lam, 0.0)
        elif p.along is not None:
            a, lam, P = s.solve(q, v, t)
            N, i = p.along
            solved = (N * a[i], lam, P)           # the motion is along N: no rounding across it
        return q, v, W, solved

    q0, v0, _, _ = state_at(0.0)
    E1 = s.kinetic(v0) + s.potential(q0)
    W_of = _Work(scene, traj, route)
    W_of.prime(times)

    def inst(t, after=False):
        q, v, W, solved = state_at(t, after)
        work = W_of(t, W, after)
        if not after:
            return report.instant(s, q, v, work, t, E1, solved=solved)
        motion.set_modes(s, _next_piece(traj, t).modes)          # (the work's own lookups set the modes of the piece holding t)
        out = report.instant(s, q, v, work, t, E1, solved=solved)
        traj.state(t)                           # the modes of the piece holding t again
        return out

    return inst


def _next_piece(traj, t: float):
    """The piece that starts at t when a phase ends there (the one after the jump), else the one
    holding t."""
    p = traj.piece(t)
    return traj.pieces[min(traj.index(t) + 1, len(traj.pieces) - 1)] if t >= p.t_b else p


def results(scene: Scene, traj, route: str, times: list[float], find_raw, params, acc) -> Result:
    t_stop = traj.stopped
    inst = instants_of(scene, traj, route, [t for t in times if t_stop is None or t <= t_stop]
                       + [ev.t for ev in traj.events if t_stop is None or ev.t <= t_stop])
    instants = [None if (t_stop is not None and t > t_stop) else inst(t) for t in times]
    res = Result({"dof": scene.dof, "coordinates": scene.coords, "route": route, "t": list(times)})
    shape = inst(t_stop) if t_stop is not None and all(x is None for x in instants) else None
    res.results.update(report.collect(instants, shape))
    res.results["events"] = [{"t": ev.t, "joint": ev.joint, "what": ev.what, "state": inst(ev.t)}
                             for ev in traj.events if t_stop is None or ev.t <= t_stop]
    res.results["phases"] = [dict(ph.as_dict(), integrals=_phase_integrals(scene, traj, ph)) for ph in traj.phases]
    res.results["impacts"] = [im.as_dict() for im in traj.impacts]
    # the first integrals of the first phase (a later phase has its own joint set), over its times
    first = [st for t, st in zip(times, instants) if t <= traj.phases[0].t_end]
    motion.set_modes(scene.system, traj.pieces[0].modes)
    res.results["integrals"] = _integrals(scene, traj, times, first)
    from . import queries

    distance = queries.odometer(scene, traj, float(acc.rtol), res.warn)
    res.results["distance"] = distance(times)
    for w in scene.warnings + traj.warnings:
        res.warn(w)
    if find_raw:
        res.results["find"] = queries.answer(find_raw, scene, traj, inst, params, times, res.warn,
                                             rtol=0.0 if str(traj.method or route).startswith("closed") else acc.rtol,
                                             distance=distance)
        for e in res.results["find"]:
            e["distance"] = ({k: v[0] for k, v in distance([e["t"]]).items()} if e.get("reached") else None)
    res.method = traj.method or route
    _estimate(res, scene, route, acc, traj)
    _energy_check(res, route)
    _present(res, scene, traj, inst, times)
    return res


def _phase_integrals(scene, traj, ph) -> list[str]:
    """The names of the first integrals that hold by structure through one phase (34.20, 36.10)."""
    p = next((p for p in traj.pieces if p.t_a >= ph.t_start), traj.pieces[-1])
    motion.set_modes(scene.system, p.modes)
    return holding(scene.system, p.fn(p.t_a)[0])


def _present(res, scene, traj, inst, times) -> None:
    """The tables, the plots' data, the equations."""
    from . import views

    t_last = traj.stopped if traj.stopped is not None else traj.t_end
    res.extra["scene_t_end"] = t_last
    res.extra["scene_sample"] = lambda t: inst(min(float(t), t_last))
    res.extra["scene_draw"] = _drawing(scene)
    res.extra["scene_draw"]["cords"] = _cords_drawn(scene, traj, times)
    res.views.extend(views.views(res))
    res.covered.extend(views.COVERED)
    res.equations = ["16.7", "29.5", "32.15", "34.20"] + (["28.7", "28.16", "33.2"] if traj.impacts else [])
    res.series.append(Series("t", list(times), [k for k in ("T", "V", "E", "W_nc", "energy_residual")
                                                 if k in res.results], index_result="t"))
    # every other result over the times of `at` is a series too, for a frame's rows, csv --long
    # and to_xarray's t (the tables show them through the views)
    res.series.append(Series("t", list(times), [k for k in OVER_TIME if k in res.results], index_result="t",
                             frame_only=True))


#: the scene's results that hold one value per time of `at` (each body's, point's, joint's, load's)
OVER_TIME = ("x", "v", "a", "angle", "omega", "alpha", "point", "reaction", "drive", "force", "distance")


def _drawing(scene) -> dict:
    """What the plots draw: each body's shape and size, the surfaces, the fixed pulleys and pegs."""
    s = scene.system
    bodies = {b.name: {"shape": b.shape, "length": b.length, "radius": b.radius, "size": b.size} for b in s.bodies}
    span = max(assembly.length_scale(scene.q0, s), 1.0)
    pulleys = []
    for e in s.elements:
        if e.kind == "cord":
            for run in e.runs:
                for seg in run:
                    for end in (seg.a, seg.b):
                        if end.fixed is not None:
                            pulleys.append(((float(end.fixed[0]), float(end.fixed[1])), 0.0))
            pegs = getattr(e, "pegs", ())
            radii = getattr(e, "radii", None) or [0.0] * len(pegs)
            pulleys += [((float(p.p[0]), float(p.p[1])), float(r)) for p, r in zip(pegs, radii)]
    return {"bodies": bodies, "surfaces": [x.drawing() if hasattr(x, "drawing") else {"name": x.name, "origin": x.origin, "d": x.d, "length": x.length}
                                          for x in scene.surfaces if not getattr(x, "carried", False)],
            "carried": [_carried_drawing(x, span) for x in scene.surfaces if getattr(x, "carried", False)],
            "pulleys": pulleys, "span": span}


def _cords_drawn(scene, traj, times) -> list:
    """Per requested time: the polylines of every cord there (None past the motion's end)."""
    cords = [e for e in scene.system.elements if e.kind == "cord"]
    if not cords:
        return []
    out: list[list | None] = []
    for t in times:
        if traj.stopped is not None and t > traj.stopped:
            out.append(None)
            continue
        q = traj.state(t)[0]
        out.append([line for e in cords for line in e.drawn(q)])
    return out


def _carried_drawing(x, span: float) -> dict:
    """A surface carried by a body, as points on its carrier's own axes (the plots place them
    with the carrier at each time): a line's ends (±span without a length), a curve's polyline."""
    W = x.body
    if hasattr(x, "polyline"):                      # a curve, drawn as at t = 0 with W at x0, th0
        c, sn = math.cos(x.th0), math.sin(x.th0)
        pts = [((p1 - x.x0[0]) * c + (p2 - x.x0[1]) * sn, -(p1 - x.x0[0]) * sn + (p2 - x.x0[1]) * c)
               for p1, p2 in x.polyline()]
    else:                                           # a line: its origin o and direction on W's axes
        a, b = (0.0, float(x.length)) if x.length is not None else (-span, span)
        pts = [(x.o[0] + u * x.dl[0], x.o[1] + u * x.dl[1]) for u in (a, b)]
    return {"name": x.name, "carrier": W.name, "points": pts}


def _energy_check(res, route: str) -> None:
    """A warning where the energy balance E − E₁ − W_nc (34.20), which the motion keeps exactly,
    is off by more than 100 × the route's error estimate of the energy's scale: the motion is less
    accurate than the estimate says (a nominal estimate, rtol × steps, assumes errors that do not
    grow).  The gallery's integrated scenes stay below 0.03 × their estimate; two carts and a
    bumper integrated across its switch were off by 4.6e6 ×."""
    r = res.results
    if route not in ("ode", "quadrature") or "energy_residual" not in r or res.error_estimate is None:
        return
    resid = [abs(x) for x in r["energy_residual"] if x is not None]
    scale = max([abs(x) for k in ("T", "V", "E", "W_nc") for x in r.get(k) or [] if x is not None], default=0.0)
    if not resid or not scale > 0:
        return
    worst = max(resid)
    if worst > 100 * max(float(res.error_estimate), EPS) * scale:
        k = next(i for i, x in enumerate(r["energy_residual"]) if x is not None and abs(x) == worst)
        res.warn(f"the energy balance E − E₁ − W_nc is off by {worst:.3g} J at t = {r['t'][k]:.6g} s ({worst / scale:.2g} of "
                 f"the energy's scale) where the error estimate is {float(res.error_estimate):.2g}: the motion is less "
                 "accurate than its estimate says; tighten accuracy.rtol, or set accuracy.estimate: true")


def _estimate(res, scene, route, acc, traj) -> None:
    """The error estimate of each route: nominal on the ODE route (rtol × steps, the policy of
    every ODE route), the linear solves' rounding bound on statics and kinematics, none (exact
    to rounding) on the closed form."""
    s = scene.system
    if route == "ode":
        ode.nominal_estimate(res, acc.rtol, steps=traj.steps)
    elif route == "quadrature":
        res.error_estimate = float(traj.energy.error_estimate)
        res.extra["error_estimate_note"] = ("the energy quadrature's own estimate (dyncli.energy_route: the "
                                            "quadratures' error sums and the turning points' uncertainty)")
    elif route in ("statics", "kinematics"):
        J = s.jac(scene.q0)
        cond = float(np.linalg.cond(J)) if J.size else 1.0
        res.error_estimate = max(cond * EPS, EPS)
        res.extra["error_estimate_note"] = ("the linear solves' rounding bound, cond(J) × ε at t = 0 (the positions "
                                            "by Newton to the double's resolution)")


def _kin_forces(s, q, v, t):
    J = s.jac(q)
    a = np.linalg.solve(J, s.gamma(q, v, t))
    f, _ = s.applied(q, v, t)
    lam = np.linalg.solve(J.T, s.mass * a - f)
    return a, lam


class _Work:
    """W_nc(t) (called as ``W(t, W_state)``): on an ODE phase integrated with the state; on an
    exact phase by quadrature of the power; each impact's energy loss counted from its instant on
    (the work of the impulsive reactions).  The pieces whose power is evaluated for many pieces
    at once (Piece.power_stack: the kinematics route's) are integrated together
    (quadrature.gauss_kronrod_many: every piece's panels in one evaluation per pass, each piece
    to its own tolerance, as it would be alone): every whole piece when the first is needed, and
    the partial pieces of the times :meth:`prime` is given."""

    def __init__(self, scene, traj, route):
        self.s, self.traj = scene.system, traj
        self.free = not any(ld.kind in ("force", "torque") for ld in self.s.loads)
        self.cum = [0.0]                # W_nc over the whole pieces before piece k, built as asked
        self.steps: list = []           # W_nc across each whole DOP853 step (one stacked evaluation)
        self.stacked: dict | None = None    # W_nc of the whole pieces integrated together, by index
        self.partial: dict = {}         # (piece index, t) -> W_nc from the piece's start to t

    def power(self, p, t) -> float:
        s = self.s
        motion.set_modes(s, p.modes)
        q, v, _ = p.fn(float(t))
        if p.route == "kinematics":
            a, lam = _kin_forces(s, q, v, float(t))
            P = sum(float(s.lam_of(lam, i)[0]) * float(v[e.index]) for i, e in enumerate(s.elements) if e.kind == "drive")
            return P + s.applied(q, v, float(t))[1]
        return s.solve(q, v, float(t))[2]

    def powers(self, p, ts) -> np.ndarray:
        """power(p, t) at the nodes ``ts``: one stacked solve when the piece's matrix is constant."""
        s = self.s
        motion.set_modes(s, p.modes)
        if p.powers is not None:
            return p.powers(ts)
        if p.route == "kinematics" or not s.constant_matrix():
            return np.array([self.power(p, t) for t in ts])
        states = [p.fn(float(t))[:2] + (float(t),) for t in ts]
        return np.array([P for _a, _lam, P in s.solve_many(states)])

    def _trivial(self, p, b: float) -> bool:
        return b <= p.t_a or p.route == "statics" or p.route == "quadrature" and self.free

    def piece(self, p, b: float) -> float:
        s = self.s
        if self._trivial(p, b):
            return 0.0
        if p.route == "ode":          # W_nc is a component of the state (never projected): the raw step
            if p.batch is not None:
                return float(p.batch(b)[2 * s.n]) - float(p.batch(p.t_a)[2 * s.n])
            return p.fn(b)[2] - p.fn(p.t_a)[2]
        motion.set_modes(s, p.modes)
        if not _powered(s):             # the power is 0.0 at every state: so is its integral
            return 0.0
        from dyncli.quadrature import gauss_kronrod

        mid = 0.5 * (p.t_a + b)
        q, v, _ = p.fn(mid)
        # each piece to the rounding of the energies it moves (an exact motion: only the
        # quadrature's own error is left, well below the energy residual it is checked by)
        scale = abs(self.power(p, mid)) * (b - p.t_a) + s.kinetic(v) + abs(s.potential(q))
        return gauss_kronrod(lambda x: self.powers(p, x), p.t_a, b, 1e-12, 1e-13 * scale, what=WNC_POWER)[0]

    def together(self, items) -> list[float]:
        """:meth:`piece` of each (piece, b) in ``items``, those with a ``power_stack`` integrated
        together (grouped by their joint set): the same integrand and tolerance per piece, the
        scale's states and powers at the midpoints stacked too."""
        from dyncli.quadrature import gauss_kronrod_many

        s = self.s
        out = [0.0] * len(items)
        groups: dict = {}
        for k, (p, b) in enumerate(items):
            if p.power_stack is None or p.states is None:
                out[k] = self.piece(p, b)
            elif not self._trivial(p, b):
                groups.setdefault((p.power_stack, p.states, p.modes), []).append(k)
        for (stack, states, modes), ks in groups.items():
            motion.set_modes(s, modes)
            if not _powered(s):
                continue
            fns = [items[k][0].fn for k in ks]
            a = np.array([items[k][0].t_a for k in ks])
            b = np.array([items[k][1] for k in ks], dtype=float)
            mid = 0.5 * (a + b)
            P = stack(fns, mid)
            E = np.array([s.kinetic(v) + abs(s.potential(q)) for q, v, _ in states(fns, mid)])
            scale = np.abs(P) * (b - a) + E

            def f(i, t, fns=fns, stack=stack):
                return stack([fns[j] for j in i.tolist()], t)
            I = gauss_kronrod_many(f, a, b, 1e-12, 1e-13 * scale, what=WNC_POWER)[0]
            for k, val in zip(ks, I.tolist()):
                out[k] = val
        return out

    def prime(self, ts) -> None:
        """The W_nc of the whole pieces and of the partial pieces of the times ``ts`` (the
        instants about to be reported), integrated together where the pieces allow."""
        traj = self.traj
        ps = traj.pieces
        if not any(p.power_stack is not None for p in ps):
            return
        wanted = [] if self.stacked is not None else [(j, p.t_b) for j, p in enumerate(ps) if p.power_stack is not None]
        for t in dict.fromkeys(float(t) for t in ts):
            if t != traj.t0:
                k = traj.index(t)
                if ps[k].power_stack is not None and (k, t) not in self.partial:
                    wanted.append((k, t))
        got = self.together([(ps[j], b) for j, b in wanted])
        if self.stacked is None:
            self.stacked = {}
        for (j, b), val in zip(wanted, got):
            if b == ps[j].t_b:
                self.stacked.setdefault(j, val)
            self.partial[(j, b)] = val

    def whole(self, j: int) -> float:
        traj, s = self.traj, self.s
        p = traj.pieces[j]
        if p.route == "ode" and p.t_b > p.t_a:
            if not self.steps:
                self.steps.append(traj.increments(2 * s.n))
            if not np.isnan(self.steps[0][j]):
                return float(self.steps[0][j])
        if p.power_stack is not None:
            if self.stacked is None:
                self.prime(())
            if self.stacked is not None and j in self.stacked:
                return self.stacked[j]
        return self.piece(p, p.t_b)

    def __call__(self, t, _W, after: bool = False):
        """W_nc at t: the loads' work to t less the energy the impacts before t took (``after``:
        also those at t, the state just after them)."""
        traj = self.traj
        if t == traj.t0:
            return 0.0
        k = traj.index(t)
        cum = self.cum
        while len(cum) <= k:
            cum.append(cum[-1] + self.whole(len(cum) - 1))
        p = traj.pieces[k]
        got = self.partial.get((k, float(t)))
        total = cum[k] + (got if got is not None else self.piece(p, t))
        motion.set_modes(self.s, p.modes)
        return total - sum(im.energy_loss for im in traj.impacts if im.t < t or (after and im.t == t))


def _powered(s) -> bool:
    """Whether the current joint set has a non-conservative power at all (SceneSystem.solve's
    P): a force, couple or damper, a drive, or a made contact sliding with kinetic friction;
    without one, P is exactly 0.0 at every state (34.20)."""
    return (any(ld.kind in ("damper", "force", "torque") for ld in s.loads)
            or any(e.kind == "drive" or isinstance(e, (Contact, Rolls)) and e.mode in ("slide", "slip") and e.mu_k
                   for e in s.elements if e.rows))


def holding(s, q) -> list[str]:
    """The first integrals that hold by the structure of the current joint set: "E" (34.20)
    when every load is conservative and no made joint dissipates or drives; "G.0", "G.1"
    (36.10) where a translation of the whole scene along e_i is allowed by every made row (so
    the joint forces have no net e_i component), gravity has none (e1, or g = 0), and no load or
    friction ties the scene to the ground along e_i (SceneSystem.translations)."""
    return (["E"] if not _powered(s) else []) + [f"G.{axis}" for axis in s.translations(q)]


def _integrals(scene, traj, times, instants) -> list:
    """The integrals of the first phase, over its times, with their values and drifts."""
    s = scene.system
    names = holding(s, scene.q0)
    out = []
    Es = [st["E"] for st in instants if st is not None]
    if "E" in names and Es:
        # relative to the energy's terms (E itself is 0 for a pendulum let go level with its pivot)
        scale = max(max(abs(st["E"]), abs(st["T"]), abs(st["V"])) for st in instants if st is not None)
        drift = max(abs(E - Es[0]) for E in Es) / max(scale, 1e-300)
        out.append({"name": "E", "value": Es[0], "drift": drift, "equation": "34.20"})
    for axis, name in ((0, "G.0"), (1, "G.1")):
        if name not in names:
            continue
        if any(getattr(getattr(e, "surface", None), "curved", False) for e in s.elements):
            continue                    # a curve's normal turns: the check at t = 0 says nothing
        vals, scale = [], 0.0
        for st in instants:
            if st is None:
                continue
            G = sum(b.mass * st["v"][b.name][axis] for b in s.bodies)
            scale = max(scale, sum(b.mass * abs(st["v"][b.name][axis]) for b in s.bodies))
            vals.append(G)
        if vals:
            drift = max(abs(g - vals[0]) for g in vals) / max(scale, 1e-300) if scale else 0.0
            out.append({"name": name, "value": vals[0], "drift": drift, "equation": "36.10"})
    return out
