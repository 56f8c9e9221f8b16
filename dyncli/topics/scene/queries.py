"""The scene's answers to the ``find`` queries (§11), through the topic-agnostic
:mod:`dyncli.queries`: the motion is the trajectory's pieces (steps of the ODE, phases of a
closed form), each answer filled with the whole state at its time."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from dyncli import queries as _q
from dyncli.expr import constant

from . import report
from .motion import EVENT_KINDS


class SceneMotion:
    def __init__(self, traj, inst, rtol: float = 0.0, distance=None):
        self.traj, self.inst, self.rtol = traj, inst, float(rtol)   # rtol: equal extremes, touches
        self.distance = distance        # :func:`odometer`'s at(times), for distance.BODY (or None)
        self._coords = _coordinate_paths(traj.system)
        self.t0 = traj.t0
        self.t_end = traj.stopped if traj.stopped is not None else traj.t_end
        self.breaks = [t for t in traj.breaks if t <= self.t_end] or [self.t0, self.t_end]
        if self.breaks[-1] < self.t_end:
            self.breaks.append(self.t_end)
        self._cache: dict[float, dict] = {}
        self._paths = None
        self._ahead = False             # the sample grid's states made together (once)
        # set by _cut_at_extremes: each result's pieces cut at its exact extremes (dyncli.queries)
        self.breaks_for: Callable[[str], list[float]] | None = None
        self.monotone, self.cuts_approximate = False, False
        self.subdivide: int | None = None

    event_kinds = EVENT_KINDS

    @property
    def joint_names(self) -> list[str]:
        return [e.name for e in self.traj.system.elements if e.kind != "guide"]

    def events(self) -> list[tuple[float, str, str]]:
        """(t, joint, what) of every event up to the end searched, in time order."""
        return [(ev.t, ev.joint, ev.what) for ev in self.traj.events if ev.t <= self.t_end]

    def _flat(self, t: float) -> dict:
        got = self._cache.get(t)
        if got is None:
            if len(self._cache) > 4096:
                self._cache.clear()
            got = self._cache[t] = report.flatten(self.inst(t))
        return got

    def paths(self):
        if self._paths is None:
            walked = [f"distance.{b.name}" for b in self.traj.system.bodies] if self.distance else []
            self._paths = sorted(list(self._flat(self.t0)) + walked)
        return self._paths

    def distances(self, path: str, ts) -> np.ndarray:
        """distance.BODY at many times (the odometer's, one pass over them)."""
        body = path.partition(".")[2]
        got = self.distance([float(t) for t in ts]).get(body) if self.distance is not None else None
        if got is None or any(x is None for x in got):
            raise KeyError(path)
        return np.asarray(got, dtype=float)

    def value(self, path: str, t: float) -> float:
        if path.startswith("distance."):
            return float(self.distances(path, [t])[0])
        fast = self._coords.get(path)
        if fast is not None:            # a body's coordinate or rate: the state alone, no solve
            if not self._ahead:         # the searches' sample grid, made together where the route can
                self._ahead = True
                self.traj.prefetch(_q.sample_grid(self.breaks, self.t0, self.t_end, _q.subdivisions(self)))
            q, v, _ = self.traj.state(float(t))
            which, k = fast
            return float((q if which == "q" else v)[k]) + 0.0
        flat = self._flat(float(t))
        if path not in flat:
            raise KeyError(path)
        return flat[path]

    def rate(self, path: str, t: float):
        head, _, rest = path.partition(".")
        if head in ("x", "angle") and path in self._coords:
            _, v, _ = self.traj.state(float(t))
            return float(v[self._coords[path][1]])
        d = {"x": "v", "v": "a", "angle": "omega"}.get(head)
        if d is None:
            return None
        flat = self._flat(float(t))
        if head == "angle":
            return flat.get(f"omega.{rest}.2")
        return flat.get(f"{d}.{rest}")


def _coordinate_paths(system) -> dict:
    """Dotted paths that read the state directly: x.B.i, v.B.i, angle.B, omega.B.2."""
    out = {}
    for b in system.bodies:
        i = b.index
        for c in (0, 1):
            out[f"x.{b.name}.{c}"] = ("q", i[c])
            out[f"v.{b.name}.{c}"] = ("v", i[c])
        if b.rigid:
            out[f"angle.{b.name}"] = ("q", i[2])
            out[f"omega.{b.name}.2"] = ("v", i[2])
    return out


def answer(raw, scene, traj, inst, params, times, warn=None, rtol: float = 0.0, distance=None) -> list[dict]:
    """The answers; ``distance``: :func:`odometer`'s at(times), searched as ``distance.BODY``."""
    qs = _q.parse_queries(raw, lambda text: constant(text, params))
    motion = SceneMotion(traj, inst, rtol, distance)
    _cut_at_extremes(motion, raw, warn)
    out, names = [], None
    for k, ans in enumerate(_q.answer(qs, motion)):
        entry = dict(ans)
        after = bool(entry.pop("after", False))
        if not ans.get("reached") and warn is not None:
            warn(f"find.{k}: not reached between t = {motion.t0:g} and t = {motion.t_end:.10g} s"
                 + (" (the motion stops there at an event)" if traj.stopped is not None else
                    "; raise t_end to search further"))
        if ans.get("reached") and ans.get("t") is not None:
            entry.update(inst(ans["t"], after=after))
        else:                                         # every other entry null (§11)
            names = list(inst(motion.t0)) if names is None else names
            entry.update({n: None for n in names if n not in entry})
        out.append(entry)
    return out


#: uniform pieces added to the trajectory's own breaks for the distance's quadrature, inside its
#: exact pieces (a closed form's phase can span many oscillations)
DISTANCE_PIECES = 128


def odometer(scene, traj, rtol: float = 1e-10, warn=None):
    """Each body's path length since t = 0 (its reference point: the centre of mass): in closed
    form when every piece has constant accelerations (:func:`_uniform_odometer`), else ∫|v| dt by
    Gauss–Legendre on the trajectory's pieces, each resolved to ``rtol`` (``warn``: told when one
    cannot be): ``at(times) -> {body: [..]}``."""
    from dyncli.motion_find import Odometer, check_resolved

    bodies = scene.system.bodies
    t0 = traj.t0
    t_end = traj.stopped if traj.stopped is not None else traj.t_end
    i1 = [b.index[0] for b in bodies]
    i2 = [b.index[1] for b in bodies]
    if t_end > t0 and (exact := _uniform_odometer(traj, i1, i2, t0, t_end)) is not None:
        return lambda times: {b.name: [None if v is None else v[j] for v in map(exact, times)]
                              for j, b in enumerate(bodies)}
    # the uniform cuts go inside the exact pieces only: an ODE step is a polynomial (its
    # interpolant), resolved on its own and halved where it is not
    grid = [t0 + (t_end - t0) * k / DISTANCE_PIECES for k in range(DISTANCE_PIECES + 1)]
    pts = {t for t in traj.breaks if t0 <= t <= t_end} | {t0, t_end}
    for p in traj.pieces:
        if p.batch is None and p.t_b > p.t_a:
            pts.update(t for t in grid if p.t_a < t < p.t_b)

    def speeds(ts):
        V = traj.velocities(ts)
        return np.hypot(V[:, i1], V[:, i2])

    odo = Odometer(speeds, pts, rtol=rtol) if t_end > t0 else None
    if odo is not None:
        check_resolved(odo, warn)

    def at(times) -> dict:
        times = [float(t) for t in times]
        if odo is None:
            return {b.name: [0.0 if t <= t0 else None for t in times] for b in bodies}
        ok = [t for t in times if t <= t_end]
        vals = odo.at(ok) if ok else []
        got = dict(zip(ok, vals))
        return {b.name: [got[t][j] if t in got else None for t in times] for j, b in enumerate(bodies)}
    return at


def _within_budget(f, ts: list[float], every: int = 128) -> list[float]:
    """[f(t) for t in ts], the solve's CPU budget checked every ``every`` values (a result read
    state by state — a joint force at the nodes of every step — can take seconds in one round of
    the search of extremes, which checks it between rounds)."""
    from dyncli.rootfind import check_extremes_budget

    out = []
    for i, t in enumerate(ts):
        if i % every == every - 1:
            check_extremes_budget()
        out.append(f(t))
    return out


def _uniform_odometer(traj, i1, i2, t0: float, t_end: float):
    """``t -> [each body's path length]`` (None past t_end) when every piece of the motion up to
    t_end has constant accelerations (``Piece.quad``: a block on an incline, an Atwood machine, a
    ball between its bounces): the path of each piece in closed form
    (:func:`dyncli.motion_find.uniform_path_length`), summed; else None."""
    from bisect import bisect_right

    from dyncli.motion_find import uniform_path_length

    pieces = [p for p in traj.pieces if p.t_b > p.t_a and p.t_a < t_end]
    if not pieces or any(p.quad is None for p in pieces):
        return None

    def path(p, t: float) -> list[float]:
        tq, _q0, v0, a = p.quad
        lag = p.t_a - tq
        return [uniform_path_length((float(v0[x] + a[x] * lag), float(v0[y] + a[y] * lag)),
                                    (float(a[x]), float(a[y])), t - p.t_a) for x, y in zip(i1, i2)]

    starts, before = [], []
    total = [0.0] * len(i1)
    for p in pieces:
        starts.append(p.t_a)
        before.append(total)
        total = [c + d for c, d in zip(total, path(p, min(p.t_b, t_end)))]

    def at(t) -> list[float] | None:
        t = float(t)
        if t > t_end:
            return None
        if t <= t0:
            return [0.0] * len(i1)
        k = max(bisect_right(starts, t) - 1, 0)
        p = pieces[k]
        return [c + d for c, d in zip(before[k], path(p, min(t, p.t_b, t_end)))]
    return at


def _cut_at_extremes(motion: SceneMotion, raw, warn) -> None:
    """Each piece of the motion (an ODE step, a closed-form phase, a kinematics piece) cut at the
    exact extremes of every result the queries search (dyncli.motion_find.exact_breaks: the roots
    of the derivative of its Chebyshev interpolant, resolved to rounding), so that the search
    takes each as monotone between cuts: a level crossed and crossed back inside one piece is
    found.  Where a result is not resolved the search reads the pieces as before, with a warning."""
    from dyncli import motion_find as mf

    traj, n = motion.traj, motion.traj.system.n

    def coordinates(ts) -> np.ndarray:
        """(q, q̇) at many times, (2n, len(ts)): an ODE step's interpolant as integrated (a
        polynomial, within the step's error of the joints: smooth to rounding; the times of all
        the steps in one stacked evaluation), any other piece's own state."""
        return traj.coordinates(ts)

    def values(paths, ts):
        ts = [float(t) for t in np.atleast_1d(np.asarray(ts, dtype=float))]
        Y = coordinates(ts) if any(path in motion._coords for path in paths) else None
        rows = []
        for path in paths:
            fast = motion._coords.get(path)
            if fast is not None and Y is not None:
                which, k = fast
                rows.append(Y[k if which == "q" else n + k])
            elif path.startswith("distance."):
                rows.append(motion.distances(path, ts))
            else:
                rows.append(np.array(_within_budget(lambda t, path=path: motion.value(path, t), ts), dtype=float))
        return np.array(rows, dtype=float)

    B = sorted(set(motion.breaks))
    if len(B) < 2 or not B[-1] > B[0]:
        return
    # each piece resolved in a few halvings at most (a piece that needs more is searched as before,
    # with a warning): the cost stays a small multiple of the motion's own
    known = (quadratic_extremes(traj, motion._coords, B[0], B[-1])
             or step_extremes(traj, motion._coords, B[0], B[-1])
             or turning_extremes(traj, motion._coords, B[0], B[-1]))
    own = mf.exact_breaks(raw, B, values, known=known, warn=warn, budget=max(4096, 33 * 8 * (len(B) - 1)))
    if own is not None:
        motion.breaks_for, motion.monotone, motion.subdivide = own, True, 1
        motion.cuts_approximate = True      # an extreme's time then polished as a root of its rate


def quadratic_extremes(traj, coords: dict, t0: float, t_end: float):
    """``known(path)`` for :func:`dyncli.motion_find.exact_breaks` when every piece of the motion
    over [t0, t_end] has constant accelerations (``Piece.quad``): a coordinate q_k = q0 + v0 τ +
    a τ²/2 has its one extreme at τ = −v0/a (kept when inside its piece), a rate q̇_k none — the
    extremes decided from the formula itself, no interpolant.  None for a path that is not a
    coordinate or a motion with another piece (the search then resolves it by
    :func:`dyncli.rootfind.smooth_extremes`)."""
    pieces = [p for p in traj.pieces if p.t_b > t0 and p.t_a < t_end]
    if not pieces or any(p.quad is None for p in pieces) \
            or pieces[0].t_a > t0 or pieces[-1].t_b < t_end:
        return None

    def known(path: str) -> list[float] | None:
        got = coords.get(path)
        if got is None:
            return None
        which, k = got
        if which != "q":
            return []                   # q̇_k linear in t on every piece
        out = []
        for p in pieces:
            tq, _, v0, a = p.quad
            if a[k] != 0.0:
                t = tq - float(v0[k]) / float(a[k])
                if p.t_a < t < p.t_b:
                    out.append(t)
        return out
    return known


def turning_extremes(traj, coords: dict, t0: float, t_end: float):
    """``known(path)`` for :func:`dyncli.motion_find.exact_breaks` on the quadrature route: the
    independent coordinate s has its extremes exactly at the turning points, whose times are the
    sums of the quadratures between them (EnergyMotion.turning_times) — not located again from
    the values of s, which are flat there (a minimum read from values is good to √ε of its
    time only).  None for any other path, or another route (the search then resolves it by
    :func:`dyncli.rootfind.smooth_extremes`)."""
    em, i = traj.energy, traj.energy_index
    if em is None or i < 0:
        return None
    times = [t for t in em.turning_times(t_end) if t0 < t < t_end]

    def known(path: str) -> list[float] | None:
        return times if coords.get(path) == ("q", i) else None
    return known


def step_extremes(traj, coords: dict, t0: float, t_end: float):
    """``known(path)`` for :func:`dyncli.motion_find.exact_breaks` when every piece of the motion
    over [t0, t_end] is a DOP853 step (``Piece.batch``, its interpolant of degree 7 as integrated:
    the values the search reads through :meth:`Trajectory.coordinates`): a coordinate or a rate is
    a polynomial on each step, whose critical points are the real roots of its derivative
    (:func:`dyncli.rootfind.polynomial_extremes`, all the steps in one pass, that component alone) — no
    halving of a degree-32 interpolant.  None for a path that is not a coordinate or a rate, or a
    motion with another piece (the search then resolves it by :func:`dyncli.rootfind.smooth_extremes`)."""
    pieces = [p for p in traj.pieces if p.t_b > t0 and p.t_a < t_end]
    if not pieces or pieces[0].t_a > t0 or pieces[-1].t_b < t_end:
        return None
    from dyncli.dop853 import DenseOutput

    if not all(isinstance(p.batch, DenseOutput) for p in pieces):
        return None
    n = traj.system.n

    def known(path: str) -> list[float] | None:
        got = coords.get(path)
        if got is None:
            return None
        from dyncli.rootfind import polynomial_extremes

        which, k = got
        per = polynomial_extremes([(p.batch, p.t_a, p.t_b) for p in pieces], deg=DENSE_DEGREE,
                                  components=[k if which == "q" else n + k])
        return sorted(t for (cuts,) in per for t in cuts)
    return known


#: the degree of a DOP853 step's interpolant (dop853.DenseOutput: seven coefficient rows)
DENSE_DEGREE = 7

