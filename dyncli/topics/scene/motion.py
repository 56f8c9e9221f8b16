"""The routes of a scene in motion, each giving a :class:`Trajectory` (docs/types/scene.md: routes and events).

* ``ode``: (q, q̇, W_nc) integrated by the project's one stepping loop (:func:`dyncli.ode.steps`
  with its budget and method map), q and q̇ projected back onto the joints after every accepted
  step (the constraints then hold to rounding), the step's interpolant projected too.
* ``closed-form``: one degree of freedom whose rows are affine in q (constant Jacobian) and
  whose loads are affine in the coordinate and its rate (decided from the elements'
  structure, never by sampling): constant acceleration, or the vibration formulas of §17.
* One-sided joints are watched on every route: the contact forces, cord tensions, slip margins
  and gaps of each step (or closed-form piece) are searched for their first crossing by sign
  analysis (crossing.py), located to the double's resolution.  A sliding contact that stops
  sticks if the static test holds (an event), else slides back (a new phase).
"""

from __future__ import annotations

import bisect
import itertools
import math
from typing import Any
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from dyncli import cputime, ode
from dyncli import runner
from dyncli.errors import NumericalError
from dyncli.rootfind import brent

from . import crossing
from .contacts import Contact, Rolls
from .dynamics import SceneSystem

EPS = float(np.finfo(float).eps)


@dataclass
class Piece:
    t_a: float
    t_b: float
    fn: Callable[..., tuple]       # t -> (q, v, W)
    modes: tuple
    route: str = "ode"             # the route of its phase: how its forces and W_nc are read
    along: tuple | None = None     # 1-DOF closed form: (N, i), the one direction of motion
    fixed: tuple | None = None     # statics: the one solve (q̈ = 0, λ, power)
    batch: Callable | None = None  # ode: the step's interpolant, unprojected, on an array of times -> (dim, k)
    many: Callable | None = None   # an exact piece's q̇ at an array of times -> (k, n), as fn's one by one
    powers: Callable | None = None  # kinematics: the power of the drives and loads at an array of times -> (k,)
    power_stack: Callable | None = None  # pieces evaluated together: power_stack([fn per time], times) -> (k,)
    coords: Callable | None = None  # pieces evaluated together: coords([fn per time], times) -> (2n, k), q over q̇
    stack: Callable | None = None  # pieces evaluated together: stack([fn per time], times) -> q̇ (k, n)
    states: Callable | None = None  # pieces evaluated together: states([fn per time], times) -> [fn(t)]
    quad: tuple | None = None      # constant accelerations: (t0, q0, v0, a), q = q0 + v0 τ + a τ²/2, τ = t − t0


#: what a one-sided joint's event can be (docs/types/scene.md, "One-sided joints, events and phases")
EVENT_KINDS = ("separates", "slack", "slips", "sticks", "leaves", "impact", "taut", "rests", "wraps", "unwraps",
               "reaches")


@dataclass
class Event:
    t: float
    joint: str
    what: str               # one of EVENT_KINDS


@dataclass
class Trajectory:
    system: SceneSystem
    t0: float
    t_end: float
    pieces: list[Piece] = field(default_factory=list)
    events: list[Event] = field(default_factory=list)
    steps: int = 0
    stopped: float | None = None    # where the motion stops (the cap on the phases reached)
    method: str = ""                # the route's method as reported (ode:DOP853, closed-form ...)
    energy: object = None           # quadrature: the EnergyMotion
    energy_index: int = -1          # quadrature: the index of its independent coordinate in q
    phases: list = field(default_factory=list)    # phases.Phase, in order
    impacts: list = field(default_factory=list)   # phases.Impact, in order
    warnings: list = field(default_factory=list)  # what the motion noticed (a point passing behind a stop)
    _memo: dict = field(default_factory=dict, repr=False)   # states asked for, by time
    _stacked: object = field(default=None, repr=False)      # _Stacked: the pieces as velocities() reads them
    _ends: tuple = field(default=(None, []), repr=False)     # (key, each piece's t_b) for piece()

    def add(self, piece: Piece):
        if piece.t_b > piece.t_a or not self.pieces:
            self.pieces.append(piece)

    @property
    def breaks(self) -> list[float]:
        return [self.pieces[0].t_a] + [p.t_b for p in self.pieces] if self.pieces else [self.t0]


    def piece(self, t: float) -> Piece:
        """The piece holding t (at a phase boundary: the one that ends there, before a jump)."""
        return self.pieces[self.index(t)]

    def index(self, t: float) -> int:
        """The index in ``pieces`` of :meth:`piece`'s piece."""
        ps = self.pieces
        key = (id(ps), len(ps), ps[-1].t_b if ps else None)
        if self._ends[0] != key:        # the pieces' ends, kept while the pieces stay as they are
            self._ends = (key, [p.t_b for p in ps])
        return min(bisect.bisect_left(self._ends[1], t), len(ps) - 1)

    def increments(self, col: int) -> np.ndarray:
        """Component ``col`` of the state (unprojected) at each piece's end minus at its start,
        for every DOP853 step in one stacked evaluation (bit for bit each step's own calls);
        NaN for any other piece."""
        dense = self._dense()
        out = np.full(len(self.pieces), np.nan)
        on = np.nonzero(dense.row >= 0)[0]
        if on.size and dense.stack is not None:
            rows = dense.row[on]
            out[on] = dense.stack(rows, dense.t_b[on])[:, col] - dense.stack(rows, dense.t_a[on])[:, col]
        return out

    def velocities(self, ts) -> np.ndarray:
        """q̇ at many times, (len(ts), n): an ODE step's interpolant evaluated once for all its
        times (unprojected: off the joints by the step's local error only, for integrals over
        the motion such as the distance); an exact piece time by time through its own function."""
        ts = np.asarray(ts, dtype=float)
        n = self.system.n
        if ts.size <= FEW and (few := self._few_rates(ts.ravel().tolist())) is not None:
            return few
        if ts.size == 1:                    # one time (a minimiser's probe): no grouping
            p = self.piece(float(ts[0]))
            if p.batch is not None:
                return np.asarray(p.batch(min(max(float(ts[0]), p.t_a), p.t_b)), dtype=float)[n:2 * n].reshape(1, n)
            return np.asarray(self.state(float(ts[0]))[1], dtype=float).reshape(1, n)
        out = np.empty((ts.size, n))
        dense = self._dense()
        which = np.minimum(np.searchsorted(dense.ends, ts, side="left"), len(self.pieces) - 1)
        if ts.size and which[0] == which[-1] and dense.row[which[0]] < 0 and np.all(which == which[0]):
            p = self.pieces[int(which[0])]    # one exact piece (a minimiser's probes): its rates at once
            if p.many is not None and p.stack is None:
                set_modes(self.system, p.modes)
                return np.asarray(p.many(np.clip(ts, p.t_a, p.t_b)), dtype=float).reshape(ts.size, n)
        if dense.stack is not None:         # the DOP853 steps: every time in one stacked evaluation
            on = dense.row[which] >= 0
            if np.any(on):
                k = which[on]
                out[on] = self._stacked_rates(dense, dense.row[k], np.clip(ts[on], dense.t_a[k], dense.t_b[k]))
                which = np.where(on, -1, which)
        stacked: dict = {}                  # pieces evaluated together (the kinematics route's)
        for k in sorted(set(which.tolist()) - {-1}):    # (np.unique would import numpy.ma: 13 ms cold)
            sel = np.nonzero(which == k)[0]
            p = self.pieces[k]
            if p.stack is not None:
                stacked.setdefault((p.stack, p.modes), []).append((sel, p))
            elif p.batch is not None:
                y = np.asarray(p.batch(np.clip(ts[sel], p.t_a, p.t_b)), dtype=float).reshape(-1, sel.size)
                out[sel] = y[n:2 * n].T
            elif p.many is not None:
                set_modes(self.system, p.modes)
                out[sel] = p.many(np.clip(ts[sel], p.t_a, p.t_b))
            else:                           # an exact piece: its own function, the modes set once
                set_modes(self.system, p.modes)
                for i in sel:
                    out[i] = p.fn(min(max(float(ts[i]), p.t_a), p.t_b))[1]
        for (stack, modes), parts in stacked.items():
            set_modes(self.system, modes)
            sel = np.concatenate([sel for sel, _ in parts])
            out[sel] = stack(*_gathered(ts, parts))
        return out

    def coordinates(self, ts) -> np.ndarray:
        """(q, q̇) at many times, (2n, len(ts)): an ODE step's interpolant as integrated
        (unprojected), the DOP853 steps' times all in one stacked evaluation (bit for bit each
        step's own call) and any other step's once per step on an array; any other piece's own
        state (:meth:`state`, after :meth:`prefetch`)."""
        ts = np.asarray(ts, dtype=float).reshape(-1)
        n = self.system.n
        out = np.empty((2 * n, ts.size))
        if not ts.size:
            return out
        dense = self._dense()
        which = np.minimum(np.searchsorted(dense.ends, ts, side="left"), len(self.pieces) - 1)
        if dense.stack is not None:
            on = dense.row[which] >= 0
            if np.any(on):
                k = which[on]
                out[:, on] = dense.stack(dense.row[k], np.clip(ts[on], dense.t_a[k], dense.t_b[k]))[:, :2 * n].T
                which = np.where(on, -1, which)
        stacked: dict = {}                  # pieces evaluated together (the kinematics route's)
        alone = []
        for k in sorted(set(which.tolist()) - {-1}):
            sel = np.nonzero(which == k)[0]
            p = self.pieces[k]
            if p.batch is not None:
                y = np.asarray(p.batch(np.clip(ts[sel], p.t_a, p.t_b)), dtype=float).reshape(-1, sel.size)
                out[:, sel] = y[:2 * n]
            elif p.coords is not None:
                stacked.setdefault((p.coords, p.modes), []).append((sel, p))
            else:
                alone.append(sel)
        if alone:
            sel = np.concatenate(alone)
            self.prefetch(ts[sel])
            for i in sel:
                q, v, _ = self.state(float(ts[i]))
                out[:n, i], out[n:, i] = q, v
        for (coords, modes), parts in stacked.items():
            set_modes(self.system, modes)
            sel = np.concatenate([sel for sel, _ in parts])
            out[:, sel] = coords(*_gathered(ts, parts))
        return out

    def _stacked_rates(self, dense, rows, ts) -> np.ndarray:
        """dop853.DenseStack's evaluation on the q̇ components only (the same operations on each
        element: bit for bit its numbers), its coefficients gathered once per call."""
        if dense.rates is None:
            n, st = self.system.n, dense.stack
            dense.rates = (np.ascontiguousarray(st.F[:, ::-1, n:2 * n]), np.ascontiguousarray(st.y_old[:, n:2 * n]))
        F, y_old = dense.rates
        Fw = F[rows]
        x = ((ts - dense.stack.t_old[rows]) / dense.stack.h[rows])[:, None]
        x1 = 1 - x
        y = np.zeros((len(ts), F.shape[2]))
        for i in range(F.shape[1]):
            y += Fw[:, i]
            y *= x if i % 2 == 0 else x1
        y += y_old[rows]
        return y

    def _few_rates(self, ts: list[float]) -> np.ndarray | None:
        """q̇ at a few times (a minimiser's probes) that all lie on DOP853 steps, in plain floats:
        each step's interpolant by the operations of its own call (DenseOutput: (y + F_j) × x or
        × (1 − x), highest power first, then + y_old), on its q̇ components only, so the same
        numbers without the arrays' cost per call; None when a time lies on another piece."""
        dense = self._dense()
        if dense.stack is None:             # no DOP853 step at all
            return None
        n, out = self.system.n, []
        for t in ts:
            k = self.index(t)
            got = dense.floats.get(k)
            if got is None:
                r = int(dense.row[k])
                if r < 0:
                    return None
                o: Any = self.pieces[k].batch         # (a DOP853 step's DenseOutput)
                got = dense.floats[k] = (float(o.t_old), float(o.h), o.F[::-1, n:2 * n].tolist(),
                                         o.y_old[n:2 * n].tolist(), float(dense.t_a[k]), float(dense.ends[k]))
            t_old, h, F, y_old, a, b = got
            x = (min(max(t, a), b) - t_old) / h
            x1 = 1 - x
            y = [0.0] * n
            for i, f in enumerate(F):
                m = x if i % 2 == 0 else x1
                y = [(u + w) * m for u, w in zip(y, f)]
            out.append([u + w for u, w in zip(y, y_old)])
        return np.array(out, dtype=float).reshape(len(ts), n)

    def _dense(self):
        """The pieces' ends, and the DOP853 steps among them stacked for :meth:`velocities` (made
        once the pieces are all there: remade when they changed)."""
        key = (id(self.pieces), len(self.pieces), self.pieces[-1].t_b if self.pieces else None)
        got = self._stacked
        if got is None or got.key != key:
            ps = self.pieces
            row = np.full(len(ps), -1)
            outs = []
            if any(p.batch is not None for p in ps):        # (dop853 is imported by a motion with steps only)
                from dyncli.dop853 import DenseOutput

                for k, p in enumerate(ps):
                    if isinstance(p.batch, DenseOutput):
                        row[k] = len(outs)
                        outs.append(p.batch)
            got = self._stacked = _Stacked(key, np.array([p.t_b for p in ps]), np.array([p.t_a for p in ps]), row,
                                           _dense_stack(outs) if outs else None)
        return got

    def prefetch(self, ts) -> None:
        """The states at the times ``ts`` that a search is about to read one by one, made together
        where the pieces can (Piece.states: the kinematics route) and kept for :meth:`state`."""
        if not any(p.states is not None for p in self.pieces):
            return
        groups: dict = {}
        for t in ts:
            t = float(t)
            if t in self._memo:
                continue
            p = self.piece(t)
            if p.states is not None:
                groups.setdefault((p.states, p.modes), []).append((t, p))
        for (states, modes), items in groups.items():
            set_modes(self.system, modes)
            got = states([p.fn for _, p in items], [min(max(t, p.t_a), p.t_b) for t, p in items])
            if len(self._memo) + len(items) > 50_000:
                self._memo.clear()
            for (t, _), st in zip(items, got):
                self._memo[t] = st

    def state(self, t: float):
        p = self.piece(t)
        set_modes(self.system, p.modes)
        memo = self._memo
        got = memo.get(t)
        if got is None:                 # a time asked again (a value and its rate, a table row)
            got = p.fn(min(max(t, p.t_a), p.t_b))
            if len(memo) > 50_000:
                memo.clear()
            memo[t] = got
        return got


#: how many times :meth:`Trajectory.velocities` evaluates in plain floats (a minimiser's probes)
FEW = 8


@dataclass
class _Stacked:
    key: tuple                  # (the list, its length, the last piece's end) when made
    ends: np.ndarray            # each piece's t_b
    t_a: np.ndarray             # each piece's t_a
    row: np.ndarray             # each piece's row in ``stack`` (-1: not a DOP853 step)
    stack: object               # dop853.DenseStack of the DOP853 steps, or None
    floats: dict = field(default_factory=dict)  # piece index -> its step's q̇ interpolant in plain floats
    rates: tuple | None = None  # the DOP853 steps' q̇ coefficients (highest power first) and q̇ at their starts

    @property
    def t_b(self) -> np.ndarray:
        return self.ends


def modes_of(system) -> tuple:
    return tuple(e.phase() for e in system.elements)


def _dense_stack(outs):
    """dop853.DenseStack of the DOP853 steps ``outs``."""
    from dyncli.dop853 import DenseStack

    return DenseStack(outs)


def _gathered(ts, parts) -> tuple[list, np.ndarray]:
    """(the function of each time's piece, the times each clipped to its piece) for the pieces
    evaluated together, ``parts`` [(the indices into ts, the piece)]: in the order of the parts."""
    fns = list(itertools.chain.from_iterable([p.fn] * len(part) for part, p in parts))
    return fns, np.concatenate([np.minimum(np.maximum(ts[part], p.t_a), p.t_b) for part, p in parts])


def set_modes(system, modes) -> None:
    changed = False
    for e, m in zip(system.elements, modes):
        if m is not None and e.phase() != m:
            e.set_phase(m)
            changed = True
    if changed:
        system.refresh()


def watches(system, q, v, t, lam=None) -> list[tuple[str, str, float]]:
    """(joint, what, g) of every one-sided quantity (event where g crosses 0 downwards), and
    ("", "switch", s) for each one-sided spring's stretch (a kink: a new phase, no event);
    ``lam``: the multipliers at (q, v, t) when already solved for."""
    if lam is None and system.watching:     # (joints that watch nothing read no multiplier)
        lam = system.solve_lists(q.tolist(), v.tolist(), t)[1]      # (a list: each watch reads floats)
    out = []
    for i, e in enumerate(system.elements):
        for what, g in e.watch(None if lam is None else system.lam_of(lam, i), q, v, t):
            out.append((e.name, what, g))
    for ld in system.loads:
        if ld.kind == "spring" and ld.one_sided:
            out.append(("", "switch", ld.stretch(q)))
    if not all(math.isfinite(g) for _, _, g in out):
        bad = next(f"{j or 'a one-sided spring'} ({w})" for j, w, g in out if not math.isfinite(g))
        raise NumericalError(f"the forces of the scene are not finite at t = {t:.6g} s ({bad}): its numbers "
                             "overflow the doubles; rescale the units")
    return out


def crossed(g0: float, g1: float, what: str) -> bool:
    """Whether a watched quantity went from g0 to g1 across its event (downwards through 0; a
    one-sided spring's stretch, "switch", either way)."""
    if what == "switch":
        return (g0 > 0) != (g1 > 0) and g0 != 0
    # a force at 0 is where the last phase ended (not a new crossing); a gap or a slip speed at 0
    # that goes negative is one: the point returns to its surface, the sliding stops
    return g1 < 0 <= g0 and not (g0 == 0 and what not in ("sticks", "impact", "taut", "leaves"))


# ----------------------------------------------------------------------------- the ODE route

class OdeRoute:
    def __init__(self, system, acc, method: str):
        self.system, self.method = system, method
        system.use_lapack()
        n = system.n
        self.n = n

        solve = system.solve_lists

        def rhs(t, y):                      # in plain floats: (q̇, q̈, P) a list, as the stepper takes it
            y = y.tolist()
            v = y[n:2 * n]
            a, lam, P = solve(y[:n], v, t)
            self.lam = lam                  # the multipliers of the last evaluation (the step's end)
            v += a
            v.append(P)
            return v

        self.rhs = rhs
        self.lam = None

    def project(self, y, t):
        """(q, q̇) of the state y projected onto the joints (W_nc as it is), in plain floats: the
        operations of SceneSystem.project_position and project_velocity, one array made."""
        n, s = self.n, self.system
        yl = y.tolist()
        ql = s.project_position_list(yl[:n], t)
        return np.array(ql + s.project_velocity_list(ql, yl[n:2 * n], t) + yl[2 * n:], dtype=float)

    def phase(self, t0, q0, v0, W0, t_end, budget, traj: Trajectory, rtol: float, atol: float):
        """Integrate one phase from (t0, q0, v0) until t_end or the first located event; fills
        ``traj`` and returns (t, q, v, W, hit) with hit = (t, joint, what) or None."""
        s, n = self.system, self.n
        y0 = self.project(np.concatenate([q0, v0, [W0]]), t0)
        if not np.all(np.isfinite(y0)):
            raise NumericalError(f"the state of the scene is not finite at t = {t0:.6g} s: its numbers overflow the "
                                 "doubles; rescale the units")
        cls = runner.solver_class(self.method)
        # the budget's leg is the whole motion (routes.run): its projection of the steps left spans
        # the phases, so a motion of many short phases is refused as early as one long integration
        solver = cls(ode.finite(self.rhs), t0, y0.copy(), t_end, rtol=runner.floor_rtol(rtol), atol=atol)
        modes = modes_of(s)
        w_old = watches(s, y0[:n], y0[n:2 * n], t0)
        # a one-sided spring that switched at t0 sits at its free length to rounding: its
        # stretch may still read on the old side there; the first step does not count it again
        size = max(1.0, float(np.max(np.abs(y0[:n]))))
        skip = {k for k, (_, what, g) in enumerate(w_old) if what == "switch" and abs(g) <= 1e-9 * size}
        tol = crossing.rounding(s, y0[:n], y0[n:2 * n], t0, y0[n:2 * n])
        # the screen reads the step's interpolant off the joints (unprojected: within the step's
        # error of them), so a quantity is cleared only beyond that error too
        screen = {what: g * (1.0 + rtol / (4 * EPS)) for what, g in tol.items()}
        tol0 = tol["sticks"]
        try:
            return self._steps(solver, budget, y0, t0, w_old, skip, tol, screen, tol0, modes, traj, rtol)
        except ode.StepFailed:
            _painleve(s, y0[:n], self.project(solver.y, float(solver.t))[:n], float(solver.t))
            raise

    def _steps(self, solver, budget, y0, t0, w_old, skip, tol, screen, tol0, modes, traj, rtol):
        """The steps of :meth:`phase` (its state as it left it)."""
        s, n = self.system, self.n
        y = y0
        for _ in ode.steps(solver, budget, self.method):
            t_old, t_new = float(solver.t_old), float(solver.t)
            yp = self.project(solver.y, t_new)
            solver.y = yp
            lam = None
            if hasattr(solver, "f"):
                solver.f = np.array(self.rhs(t_new, yp))
                lam = np.array(self.lam)
            dense = _ProjectedStep(ode.dense_output(solver), self, t_new, yp.copy())
            w_new = watches(s, yp[:n], yp[n:2 * n], t_new, lam)
            # a speed's rounding is that of the step's speeds (from rest, the phase's start has none)
            v_step = max(map(abs, y[n:2 * n].tolist() + yp[n:2 * n].tolist()), default=0.0)
            tol["sticks"] = max(tol0, 64 * EPS * v_step)
            screen["sticks"] = tol["sticks"] * (1.0 + rtol / (4 * EPS))
            hit = self._first_crossing(w_old, w_new, dense, t_old, t_new, skip, (tol, screen), t_old == t0)
            skip = set()
            traj.steps += 1
            if hit is None:
                traj.add(Piece(t_old, t_new, self._fn(dense), modes, batch=dense.dense))
                w_old, y = w_new, yp
                continue
            y = dense(hit[0])
            traj.add(Piece(t_old, hit[0], self._fn(dense), modes, batch=dense.dense))
            return hit[0], y[:n], y[n:2 * n], float(y[2 * n]), hit
        if not traj.pieces or traj.pieces[-1].t_b < t0:
            traj.add(Piece(t0, t0, lambda t, y=y0: (y[:n], y[n:2 * n], float(y[2 * n])), modes))
        return float(solver.t), y[:n], y[n:2 * n], float(y[2 * n]), None

    def _fn(self, dense):
        n = self.n
        return lambda t: (lambda y: (y[:n], y[n:2 * n], float(y[2 * n])))(dense(t))

    def _first_crossing(self, w_old, w_new, dense, t_old, t_new, skip, tols, start):
        """The first event inside one step, decided from the step's interpolant, not from its ends
        alone: each watched quantity read at the step's Lobatto points (crossing.step_screen, on
        the interpolant as integrated); where the screen cannot clear it, its first crossing by
        crossing.first_crossing (the sign analysis of all_roots on that interpolant, a polynomial
        within the step's error of the joints; the state there projected): a contact force that
        dips below 0 and back inside one step is an event.  ``tols``: each quantity's rounding,
        and the screen's (with the step's error)."""
        if not w_old:                   # nothing watched (bilateral joints, no one-sided spring)
            return None
        s, n = self.system, self.n
        tol, screen = tols
        cache: dict[float, list[float]] = {t_old: [g for _j, _w, g in w_old], t_new: [g for _j, _w, g in w_new]}

        def at(t: float) -> list[float]:
            got = cache.get(t)
            if got is None:
                y = dense(t)
                got = cache[t] = [g for _j, _w, g in watches(s, y[:n], y[n:2 * n], t)]
            return got

        def raw_at(ts, k: int) -> np.ndarray:
            ts = np.atleast_1d(np.asarray(ts, dtype=float))
            if (limit := cputime.over()) is not None:
                raise NumericalError(f"the forces of the joints were searched to t = {float(ts[0]):.6g} s only within the "
                                     f"CPU budget of {limit:g} s (accuracy.max_cpu): shorten the times asked (at, "
                                     "t_max) or raise accuracy.max_cpu")
            ys = np.asarray(dense.dense(ts), dtype=float).reshape(-1, ts.size)
            return np.array([watches(s, ys[:n, i], ys[n:2 * n, i], float(t))[k][2] for i, t in enumerate(ts)])

        inner = crossing.screen_times(t_old, t_new)
        raw = np.asarray(dense.dense(np.array(inner)), dtype=float).reshape(-1, len(inner))
        seen = [[g for _j, _w, g in watches(s, raw[:n, i], raw[n:2 * n, i], t)] for i, t in enumerate(inner)]
        best = None
        for k, (joint, what, g0) in enumerate(w_old):
            if k in skip:
                continue
            g1 = w_new[k][2]
            seen_k = crossing.step_screen([g0] + [w[k] for w in seen] + [g1], screen[what])
            if seen_k == "clear" and not crossed(g0, g1, what):
                continue
            tc = None
            if seen_k == "search":      # on the interpolant as integrated: a polynomial, smooth to rounding
                tc = crossing.first_crossing(lambda ts, k=k: raw_at(ts, k), t_old, t_new if best is None else best[0],
                                             what, screen[what], start, 1)
            if tc is None and crossed(g0, g1, what):     # one crossing, or ends on the band below 0
                tc = t_new if g1 == 0 else brent(lambda t, k=k: at(t)[k], t_old, t_new,
                                                 4 * EPS * max(abs(t_new), 1e-300), 4 * EPS, 200)
            if tc is not None and (best is None or tc < best[0]):
                best = (tc, joint, what)
        return best


class _ProjectedStep:
    def __init__(self, dense, route, t_end, y_end):
        self.dense, self.route, self.t_end, self.y_end = dense, route, t_end, y_end

    def __call__(self, t):
        if t == self.t_end:
            return self.y_end.copy()
        return self.route.project(self.dense(t), t)


def _painleve(system, q0, q1, t: float) -> None:
    """After a failed step: where a rough contact slides, the matrix of the accelerations and
    multipliers (its friction column in it) turning singular between the phase's start and the
    failed step (its determinant through 0, or down to 1e-4 of the start's) is Painlevé's paradox — sliding with that friction needs an unbounded normal force
    (a rod sliding on a rough floor with μ_k above its limit, 4/3 for a uniform rod on its end).
    Raised as such (NumericalError), with the contacts; else nothing (the step's own error stands)."""
    sliding = [e for e in system.elements if isinstance(e, (Contact, Rolls)) and e.mode in ("slide", "slip")
               and (e.mu_k or 0.0) > 0]
    if not sliding:
        return
    dets = []
    for q in (q0, q1):
        with np.errstate(all="ignore"):
            sign, logdet = np.linalg.slogdet(system.kkt_matrix(q, system.jac(q)))
        dets.append((float(sign), float(logdet)))
    (s0, l0), (s1, l1) = dets
    if s0 * s1 < 0 or s1 == 0 or l1 < l0 - math.log(1e4):      # through, or to within 1e-4 of, singular
        names = ", ".join(f"{e.name} (μ_k = {e.mu_k:g})" for e in sliding)
        raise NumericalError(f"at t = {t:.6g} s the sliding contact {names} meets Painlevé's paradox: sliding on with "
                             "that friction needs a normal force that grows without bound (the friction turns the "
                             "normal force back on itself; a uniform rod sliding on its end jams above μ_k = 4/3); "
                             "dyncli does not follow the jam (it would take a tangential impact): the motion is "
                             "not solved past it; lower μ_k below that limit")


def stick_test(system, e: Contact, q, v, t) -> tuple[bool, float]:
    """Hold the contact's point (a second row) and solve: it sticks when |F| ≤ μ_s N (the
    boundary, within the rounding of the solve, sticks); else it slides opposite to the
    friction it would need.  Leaves the contact in mode "stick" (a rolling body: "roll"), with
    the rough contacts whose sticking row would be its own row held with it (:func:`join_held`:
    the group holds while |ΣF| ≤ Σ μ_s N)."""
    if isinstance(e, Rolls):
        e.mode, e.sign, e.c0 = "roll", 0.0, e.roll_const(q)
    else:
        e.mode, e.sign = "stick", 0.0
        e.stick_here(q)
        join_held(system, e, q)
    system.refresh()
    v0 = np.array(v, float)
    v0 = system.project_velocity(q, v0, t)
    _, lam, _ = system.solve(q, v0, t)
    lm = system.lam_of(lam, system.elements.index(e))
    if e.held(lm):
        return True, 0.0
    return False, -math.copysign(1.0, e.grip(lm)[1])


def join_held(system, e: Contact, q) -> list[str]:
    """The rough contacts whose sticking row would be the row of ``e`` (sticking): points of the
    same body on the same line (two feet of a crate on a floor), sliding with it or held.  Held
    together their friction is statically indeterminate: each is made a member of the group
    e's row holds (mode "shared", contacts.py) instead of a second, dependent row.  Their names."""
    if getattr(e.surface, "curved", False) or e.mode != "stick":
        return []
    row = e.tangent_jac(q)
    tol = 1e-12 * max(float(np.max(np.abs(row), initial=0.0)), 1e-300)
    out = []
    for o in system.elements:
        if (o is e or type(o) is not type(e) or not o.rough or o.mode not in ("stick", "slide", "shared")
                or getattr(o.surface, "curved", False)):
            continue
        if float(np.max(np.abs(o.tangent_jac(q) - row), initial=0.0)) > tol:
            continue
        if o.mode != "shared" or o.holder != e.name:
            out.append(o.name)
        for x in system.elements:               # a group o held joins e's
            if isinstance(x, Contact) and x.mode == "shared" and x.holder == o.name:
                x.holder = e.name
        o.mode, o.sign, o.holder = "shared", 0.0, e.name
        o.stick_here(q)
    if out:
        system.refresh()
    return out


def held_groups(system) -> list[list[str]]:
    """The groups of contacts held together (their names, the holder's first)."""
    out: dict[str, list[str]] = {}
    for x in system.elements:
        if isinstance(x, Contact) and x.mode == "shared" and x.holder is not None:
            out.setdefault(x.holder, [x.holder]).append(x.name)
    return list(out.values())


def indeterminate_warning(names: list[str]) -> str:
    """The warning of a group of contacts held together."""
    return (f"the friction at {', '.join(names)} (points of one body held on one line) is statically "
            "indeterminate: their sum is what the motion needs, and each F is shown in proportion to its "
            "μ_s N (the split at which all reach their limits together); the group slips when |ΣF| exceeds "
            "Σ μ_s N")


# ----------------------------------------------------------------------------- the closed form

@dataclass
class Linear1:
    """s̈ = A0 + A1 (s − s0) + A2 ṡ along q = q0 + N (s − s0)."""

    q0: np.ndarray
    N: np.ndarray
    i: int
    A0: float
    A1: float
    A2: float
    #: the relative error of A1 (and so of ωₙ², of the phase's rate) from its assembly
    rel: float = 0.0

    def motion(self, t: float, s0: float, sd0: float) -> tuple[float, float]:
        A0, A1, A2 = self.A0, self.A1, self.A2
        if A1 == 0 and A2 == 0:
            return s0 + sd0 * t + 0.5 * A0 * t * t, sd0 + A0 * t
        if A1 == 0:          # damped drift to the terminal rate −A0/A2
            vinf = -A0 / A2
            e = math.expm1(A2 * t)
            return s0 + vinf * t + (sd0 - vinf) * e / A2, vinf + (sd0 - vinf) * (e + 1.0)
        from dyncli.topics.vibration.closed_form import free_at

        wn = math.sqrt(-A1)
        zeta = -A2 / (2 * wn)
        s_eq = s0 - A0 / A1
        w, wd = free_at(t, s0 - s_eq, sd0, wn, zeta)
        return s_eq + w, wd

    def rates(self, ts, s0: float, sd0: float) -> np.ndarray:
        """ṡ of :meth:`motion` at an array of times (the same formulas on arrays, numpy's exp and
        cos: within an ulp or two of the scalar's — for integrals over the motion, the distance)."""
        A0, A1, A2 = self.A0, self.A1, self.A2
        t = np.asarray(ts, dtype=float)
        if A1 == 0 and A2 == 0:
            return sd0 + A0 * t
        if A1 == 0:
            vinf = -A0 / A2
            return vinf + (sd0 - vinf) * (np.expm1(A2 * t) + 1.0)
        from dyncli.topics.vibration.closed_form import free

        wn = math.sqrt(-A1)
        return free(t, s0 - (s0 - A0 / A1), sd0, wn, -A2 / (2 * wn))[1]


def closed_form_reason(system, N: np.ndarray, q0) -> str | None:
    """None when the 1-DOF motion along N is affine (constant Jacobian, affine loads); else why not."""
    for e in system.elements:
        if e.rows and not e.linear and not (hasattr(e, "straight_along") and e.straight_along(q0, N)):
            return f"the {e.kind} {e.name!r} is not linear in the coordinates"
        if e.kind == "drive":
            return "a drive prescribes a motion in time"
    for ld in system.loads:
        if ld.kind in ("force", "torque") and not ld.constant:
            return f"{ld.label} depends on time"
        if ld.kind in ("force",) and ld.P.turns_with_body:
            return f"{ld.label} acts at a point that turns with its body"
        if ld.kind in ("spring", "damper"):
            if ld.P.turns_with_body or ld.Q.turns_with_body:
                return f"{ld.label} is attached to a point that turns with its body"
            if ld.kind == "spring" and ld.one_sided:
                return f"{ld.label} is one-sided"
            d = ld.P.pos(q0) - ld.Q.pos(q0)
            w = ld.P.jac(q0, system.n) @ N - ld.Q.jac(q0, system.n) @ N
            if abs(d[0] * w[1] - d[1] * w[0]) > 1e-12 * math.hypot(*d) * math.hypot(*w):
                return f"{ld.label} turns as the scene moves"
    return None


def along(system, q0, N) -> tuple[bool, bool]:
    """(springs act along the motion, dampers act along it): structural, from the loads."""
    k = c = False
    for ld in system.loads:
        if ld.kind in ("spring", "damper"):
            w = ld.P.jac(q0, system.n) @ N - ld.Q.jac(q0, system.n) @ N
            if np.any(w != 0) and (ld.k if ld.kind == "spring" else ld.c) > 0:
                k, c = (True, c) if ld.kind == "spring" else (k, True)
    return k, c
