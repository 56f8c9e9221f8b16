"""Set up a scene (assembly, DOF, initial modes, refusals), pick and run its route, report.

Routes (``route`` and ``method``), the cheapest that is exact, decided from the structure:

* ``statics``: no degree of freedom and no drive (or every contact sticking with constant
  loads): the reactions of equilibrium, Jᵀ λ = −f;
* ``kinematics``: no degree of freedom with drives: positions by Newton on φ(q, t) = 0 (the
  grid's from the previous grid time, a state between from its piece start's Taylor
  polynomial), J q̇ = −φ_t, J q̈ = γ, and the forces from M q̈ − f = Jᵀ λ;
* ``closed-form``: one DOF, rows affine in q and loads affine along the motion (motion.py);
* ``quadrature`` (``accuracy.method: quadrature`` only, in this release: it costs seconds):
  one DOF with an energy integral (energy.py);
* ``ode``: otherwise.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dyncli import ode
from dyncli.errors import InputError, NumericalError

from . import assembly, crossing, elements, motion, phases

EPS = float(np.finfo(float).eps)
from .prepare import Scene


# ----------------------------------------------------------------------------- routes

#: the generality of each route: a scene whose phases took several reports the most general
#: a double's relative spacing (the assembled coefficients' rounding unit)
EPS_RATE = 2.0 ** -52
ORDER = ("statics", "closed-form", "quadrature", "ode")


def run(scene: Scene, t_end: float, acc):
    """The motion phase after phase (phases.py): each phase on its own cheapest route, the
    joint set changed at each event, until t_end (or the cap on the phases)."""
    s = scene.system
    traj = motion.Trajectory(s, 0.0, t_end)
    if scene.dof == 0 and any(e.kind == "drive" for e in s.elements):
        return _kinematics(scene, traj, acc), "kinematics"
    if acc.method == "closed-form" and _closed_form_kind(s, scene.q0, scene.v0) is None:
        raise InputError("this scene has no closed form (it needs constant loads and joints whose rows keep their "
                         "Jacobian along the motion, or one degree of freedom with rows affine in the positions and "
                         "loads affine along the motion): use method auto", "accuracy.method")
    if acc.method == "quadrature":      # on request only in this release: its cost is seconds (docs)
        from . import energy

        why = energy.applies(s) if scene.dof == 1 else "the scene has more than one degree of freedom"
        if why is not None:
            raise InputError(f"the quadrature route needs one degree of freedom and an energy integral: {why}; use "
                             "method auto", "accuracy.method")
    budget = ode.Budget(acc.max_steps)
    budget.leg(0.0, t_end)
    change = phases.Transitions(s, traj, acc.rtol)
    t, q, v = 0.0, scene.q0, scene.v0
    methods, still = [], 0
    while True:
        route, (t_b, q, v, hit) = _phase(scene, traj, t, q, v, t_end, acc, budget)
        methods.append(traj.method or route)
        traj.phases.append(phases.Phase(t, t_b, phases.joints_of(s), route))
        if hit is None or t_b >= t_end:
            break
        if hit[2] == "reaches":         # a cord's end at its pulley: nothing past it is the scene's
            change.event(t_b, hit[1], "reaches")
            traj.stopped = t_b
            cord = next(e for e in s.elements if e.name == hit[1])
            assert isinstance(cord, elements.Cord), "a cord's segment reaches its pulley"
            left = elements.REACH * max(abs(c) for c in cord.consts)
            scene.warnings.append(f"a segment of the cord {hit[1]!r} has no straight part left at t = {t_b:.7g} s (an "
                                  "end at its pulley, or two pulleys it joins touching; taken where it is down to "
                                  f"{left:.3g} m, a millionth of the cord: its direction is not defined at 0): the "
                                  "motion stops there; the results at later times are null")
            break
        still = still + 1 if t_b == t else 0
        if still >= phases.MAX_INSTANT:
            if why := change.locked_with(t_b, q, hit[1]):
                raise NumericalError(why)       # made with the others it would lock them: wedged
            raise NumericalError(f"the joints chatter at t = {t_b:.10g} s: {hit[1]!r} changes {phases.MAX_INSTANT} times "
                                 "at that instant (made and released again); the scene has no consistent joint "
                                 "set there")
        if len(traj.phases) >= phases.MAX_PHASES:
            traj.stopped = t_b
            scene.warnings.append(f"the motion has {phases.MAX_PHASES} phases by t = {t_b:.10g} s (the most one solve "
                                  "follows): it stops there; the results at later times are null")
            break
        t = t_b
        q, v = change.after(t, q, v, hit)
    traj.events.sort(key=lambda ev: ev.t)
    routes = [ph.route for ph in traj.phases]
    route = max(routes, key=ORDER.index)
    traj.method = next(m for m, r in zip(methods, routes) if r == route)
    return traj, route


def _phase(scene, traj, t, q, v, t_end, acc, budget):
    """One phase from (t, q, v): its route and (t_b, q, v, hit) at its end."""
    s = scene.system
    if _effective_dof(s, q) == 0 and not any(e.kind == "drive" for e in s.elements):
        # held by the joints, or by friction at rest: under loads that change in time only the
        # forces change (watched for the instant they slip or let go)
        return "statics", _statics(s, traj, t, q, t_end)
    if acc.method in ("auto", "closed-form"):
        got = _closed_form(s, traj, t, q, v, t_end, scene.warnings.append)
        if got is not None:
            return "closed-form", got
    if acc.method == "quadrature" and t == 0:
        from . import energy

        energy.run(scene, traj, t_end, acc)
        for p in traj.pieces:
            p.route = "quadrature"
        return "quadrature", _first_event(s, traj, 0, t_end)
    method = "DOP853" if acc.method in ("auto", "ode", "closed-form", "quadrature") else acc.method
    traj.method = f"ode:{method}"
    held = [ld for ld in s.loads if ld.kind == "spring" and ld.one_sided]
    for ld in held:                     # on or off for the whole phase: it ends at the switch
        ld.hold_mode(q, v)
    try:
        t_b, q, v, _W, hit = motion.OdeRoute(s, acc, method).phase(t, q, v, 0.0, t_end, budget, traj, acc.rtol,
                                                                    acc.atol)
    finally:
        for ld in held:                 # read by sign again (the results at any state)
            ld.mode = None
    return "ode", (t_b, q, v, hit)


def _effective_dof(s, q) -> int:
    J = s.jac(q)
    return s.n - assembly.rank(J)


def _steady(s) -> bool:
    return all(ld.constant and ld.kind != "damper" for ld in s.loads) and not any(e.kind == "drive" for e in s.elements)


def _statics(s, traj, t, q, t_end):
    v = np.zeros(s.n)
    f, _ = s.applied(q, v, t)
    J = s.jac(q)
    lam, *_ = np.linalg.lstsq(J.T, -f, rcond=None)
    if float(np.max(np.abs(J.T @ lam + f), initial=0.0)) > 1e-9 * max(float(np.max(np.abs(f), initial=0.0)), 1e-300):
        raise NumericalError("the joints cannot hold the loads in equilibrium")
    fixed = (np.zeros(s.n), lam, 0.0) if _steady(s) else None
    traj.add(motion.Piece(t, t_end, lambda _t: (q, v, 0.0), motion.modes_of(s), "statics", fixed=fixed))
    traj.method = "statics"
    if fixed is not None:
        return t_end, q, v, None
    return _first_event(s, traj, len(traj.pieces) - 1, t_end)


def _kinematics(scene: Scene, traj, acc):
    s = scene.system
    grid = _drive_grid(s, traj.t_end)
    qs: list = [scene.q0]
    for k, t in enumerate(grid[1:]):
        # Newton from the quadratic through the last three grid positions (off by O(h³), so
        # two steps fewer than from the last one; the same branch, nearer): from the last
        # position itself where that does not converge (_position)
        guess = qs[-1] if k < 2 else 3.0 * (qs[-1] - qs[-2]) + qs[-3]
        qs.append(_newton(s, guess, t) if k >= 2 else None)
        if qs[-1] is None:
            qs[-1] = _position(s, qs[-2], t)
    starts = _starts(s, qs, grid)
    conds = [st[3] for st in starts]
    worst = int(np.argmax(conds))
    if conds[worst] > 1e8:
        scene.warnings.append(f"the mechanism comes near a toggle position (the joint rows' condition number reaches "
                              f"{conds[worst]:.3g} at t = {grid[worst]:.6g} s): its velocities and forces lose about "
                              f"{math.log10(conds[worst]):.0f} digits there")
    subs = []
    for k in range(len(grid) - 1):
        fn = _KinPiece(s, qs[k], grid[k])
        fn.start, fn.sigma = starts[k][:3], starts[k][4]
        subs.append(fn)
    for k in range(0, len(subs), KIN_RUN):
        run = _KinRun(subs[k:k + KIN_RUN])
        traj.add(motion.Piece(grid[k], grid[min(k + KIN_RUN, len(subs))], run, motion.modes_of(s), "kinematics",
                              many=run.velocities, powers=run.powers, stack=_kin_velocities, states=_kin_states,
                              power_stack=_kin_powers, coords=_kin_coordinates))
    if len(grid) == 1:
        traj.add(motion.Piece(0.0, 0.0, _KinPiece(s, scene.q0, 0.0), motion.modes_of(s), "kinematics"))
    traj.phases.append(phases.Phase(0.0, traj.t_end, phases.joints_of(s), "kinematics"))
    traj.method = "kinematics"
    return traj


def _starts(s, qs, grid) -> list:
    """Per grid position: (q̇, q̈, the length scale, cond(J), (J, σ_max, σ_min)) — _KinPiece's
    start (q̇ and q̈ None near a toggle, cond(J) > 1e8) and its ``sigma``, all in stacked solves."""
    Q = np.array(qs, dtype=float)
    X = s.stack(Q)
    Js = s.jac_many(X)
    sv = np.linalg.svd(Js, compute_uv=False) if Js.size else np.ones((len(qs), 1))
    with np.errstate(divide="ignore", invalid="ignore"):
        conds = sv[:, 0] / sv[:, -1]            # (np.linalg.cond's 2-norm)
    td = s.at_times(np.asarray(grid, dtype=float))
    out = []
    V: np.ndarray | None
    A: np.ndarray | None
    try:
        V = np.linalg.solve(Js, -s.phi_t_many(td)[:, :, None])[:, :, 0]
        A = np.linalg.solve(Js, s.gamma_many(X, V, td)[:, :, None])[:, :, 0]
    except np.linalg.LinAlgError:
        V = A = None
    for k, q in enumerate(qs):
        c = float(conds[k])
        if V is not None and A is not None and c <= 1e8:
            out.append((V[k], A[k], assembly.length_scale(q, s), c, (Js[k], float(sv[k, 0]), float(sv[k, -1]))))
        else:                           # near a toggle the rates are not to be trusted
            out.append((None, None, assembly.length_scale(q, s), c, (Js[k], float(sv[k, 0]), float(sv[k, -1]))))
    return out


def _drive_grid(s, t_end: float) -> np.ndarray:
    """Times at which the positions are continued from one to the next: at least 64 pieces, and
    so many that no drive moves more than 0.05 rad (an angle) or 2 % of the scene's size (a
    coordinate) within one (Newton from the piece's start then stays on the branch)."""
    if not t_end > 0:
        return np.array([0.0])
    fine = np.linspace(0.0, t_end, 1025)    # sizes the pieces only (each position is Newton's)
    size = max(assembly.length_scale(np.zeros(1), s), 1e-300)
    pieces = 64
    for e in s.elements:
        if e.kind == "drive":
            vals = e.at_times(fine)[:, 0]
            angle = s.names[e.index].startswith("angle.")
            step = 0.05 if angle else 0.02 * size
            travel = float(np.sum(np.abs(np.diff(vals))))
            need = travel / step + 1
            if not need <= KIN_PIECES:         # (a longer piece could leave the branch unseen)
                unit = "rad" if angle else "m"
                raise NumericalError(f"the drive {e.name!r} moves {travel:.3g} {unit} by t = {t_end:.6g} s: the "
                                     f"kinematics follows at most {KIN_PIECES} pieces of {step:.3g} {unit} "
                                     f"({KIN_PIECES * step:.3g} {unit}); shorten t_end (or the times asked)")
            pieces = max(pieces, int(need))
    return np.linspace(0.0, t_end, pieces + 1)


#: the most pieces the kinematics route continues its positions over
KIN_PIECES = 20_000


def _newton(s, q, t, scale: float | None = None):
    """Newton on φ(q, t) = 0 from q (positions of the length ``scale``, default q's own): stopped
    when the correction is at the rounding of the positions, or (well inside Newton's quadratic
    convergence, |dq| ≤ 1e-6 of the scale) the next one, |dq|³/|dq_prev|², is foreseen below it
    (that step would not change q); None if it does not converge in 6 steps."""
    if scale is None:
        scale = assembly.length_scale(q, s)
    last = None
    for _ in range(6):
        try:
            dq = np.linalg.solve(s.jac(q), s.phi(q, t))
        except np.linalg.LinAlgError:
            return None
        q = q - dq
        size = float(np.max(np.abs(dq)))
        if size <= 4 * EPS * scale or last is not None and size <= 1e-6 * scale and \
                size ** 3 <= EPS * scale * last * last:
            return q
        last = size
    return None


def _position(s, q, t, depth: int = 0):
    """Newton on φ(q, t) = 0 from q, until the correction is at the rounding of the positions."""
    q = q.copy()
    scale = assembly.length_scale(q, s)
    for _ in range(30):
        ph = s.phi(q, t)
        dq = np.linalg.solve(s.jac(q), ph)
        q = q - dq
        if float(np.max(np.abs(dq))) <= 4 * EPS * scale:
            return q
    raise NumericalError(f"the mechanism cannot be placed at t = {t:.6g} s: the drive takes it past a position where "
                         "the joints lock (a toggle position)")


class _KinPiece:
    """t -> (q, v, 0) on one piece of the kinematics route.  The position is Newton's on
    φ(q, t) = 0 started from the piece start's Taylor polynomial q_a + v_a τ + ½ a_a τ² (off by
    O(τ³), so Newton needs about two steps fewer than from q_a itself, the last skipped when
    its size is foreseen below the rounding; near a toggle, cond(J) > 1e8 at q_a, from q_a
    itself); where that does not converge, Newton from q_a as the grid was placed (_position)."""

    def __init__(self, s, q_a, t_a: float):
        self.s, self.q_a, self.t_a = s, q_a, float(t_a)
        self.start = None               # (v_a, a_a, the length scale), made when first asked
        self.sigma = None               # (J, σ_max, σ_min) at q_a, when the grid made them (_near_toggle)

    def _start(self):
        s = self.s
        if self.start is None:
            J = s.jac(self.q_a)
            v = a = None
            if float(np.linalg.cond(J)) <= 1e8:     # near a toggle the rates are not to be trusted
                v = np.linalg.solve(J, -s.phi_t(self.t_a))
                a = np.linalg.solve(J, s.gamma(self.q_a, v, self.t_a))
            self.start = (v, a, assembly.length_scale(self.q_a, s))
        return self.start

    def position(self, t):
        s = self.s
        v, a, scale = self._start()
        tau = t - self.t_a
        q = self.q_a + v * tau + 0.5 * a * (tau * tau) if v is not None else self.q_a
        if np.all(np.isfinite(q)):
            got = _newton(s, q, t, scale)
            if got is not None:
                return got
        return _position(s, self.q_a, t)

    def positions(self, ts):
        """:meth:`position` at many times of the piece: :func:`_kin_positions`."""
        return _kin_positions([self] * len(ts), ts)

    def __call__(self, t):
        return _kin_state(self.s, self.position(t), t)

    def velocities(self, ts) -> np.ndarray:
        """q̇ at many times of the piece, (len(ts), n)."""
        return _kin_velocities([self] * len(ts), ts)

    def powers(self, ts) -> np.ndarray:
        """The power of the drives and the loads at many times of the piece (:func:`_kin_powers`)."""
        return _kin_powers([self] * len(ts), ts)


#: the grid's pieces one piece of the trajectory holds (:class:`_KinRun`)
KIN_RUN = 16


class _KinRun:
    """t -> (q, v, 0) on a run of consecutive pieces of the drive grid, each time read from the
    grid piece that holds it (its Newton start: :class:`_KinPiece`, at a join the piece that
    ends there, as Trajectory.piece picks).  The positions are the roots of the same joint
    equations on both sides of a join — the motion is as smooth across it as inside — so the
    trajectory holds one piece per run: what integrates or searches along the motion (W_nc's
    quadrature, the distance, the extremes of the find queries) sees a few smooth pieces, not
    every step of the grid."""

    def __init__(self, subs):
        self.subs, self.s = subs, subs[0].s
        self.starts = np.array([p.t_a for p in subs])

    def sub(self, t: float) -> _KinPiece:
        return self.subs[max(int(np.searchsorted(self.starts, t, side="left")) - 1, 0)]

    def __call__(self, t):
        return self.sub(t)(t)

    def velocities(self, ts) -> np.ndarray:
        return _kin_velocities([self] * len(ts), ts)

    def powers(self, ts) -> np.ndarray:
        return _kin_powers([self] * len(ts), ts)


def _grid_pieces(pieces, ts) -> list:
    """Each entry of ``pieces`` (a :class:`_KinRun` or a :class:`_KinPiece`) as the grid piece
    that holds ``ts[i]`` (_KinRun.sub, for all the times of a run in one search)."""
    uniq, which = _pieces_of(pieces)
    if not any(isinstance(p, _KinRun) for p in uniq):
        return list(pieces)
    T = np.asarray(ts, dtype=float)
    out = list(pieces)
    for j, p in enumerate(uniq):
        if isinstance(p, _KinRun):
            sel = np.flatnonzero(which == j)
            k = np.maximum(np.searchsorted(p.starts, T[sel], side="left") - 1, 0)
            for i, kk in zip(sel.tolist(), k.tolist()):
                out[i] = p.subs[kk]
    return out


def _kin_positions(pieces, ts):
    """_KinPiece.position of ``pieces[i]`` at ``ts[i]`` for every i at once, (len(ts), n), with
    the times' data ``td`` (SceneSystem.at_times): each Newton step of all the states still
    moving in one stacked evaluation of the rows and one stacked solve (the same LU per state),
    each state started from its own piece's Taylor polynomial and stopped by the same test as
    :meth:`_KinPiece.position` (the same numbers); a state that does not converge, or a
    singular step, as :meth:`_KinPiece.position` alone."""
    s = pieces[0].s
    T = np.asarray(ts, dtype=float)
    k = len(T)
    td = s.at_times(T)
    uniq, which = _pieces_of(pieces)
    # per piece, then per state (its piece's row): the start (q_a, v_a, a_a, t_a, length scale)
    g = len(uniq)
    Qg, Vg, Ag = np.empty((g, s.n)), np.zeros((g, s.n)), np.zeros((g, s.n))
    Tg, Sg, Yg = np.empty(g), np.empty(g), np.zeros(g, dtype=bool)
    for j, p in enumerate(uniq):
        v, a, sc = p._start()
        Qg[j], Tg[j], Sg[j] = p.q_a, p.t_a, sc
        if v is not None:
            Vg[j], Ag[j], Yg[j] = v, a, True
    Qa, Va, Aa, Ta, scale, taylor = Qg[which], Vg[which], Ag[which], Tg[which], Sg[which], Yg[which]
    tau = T - Ta
    Q = Qa.copy()
    Q[taylor] = (Qa + Va * tau[:, None] + (0.5 * Aa) * (tau * tau)[:, None])[taylor]
    out = Q.copy()
    act = np.nonzero(np.all(np.isfinite(Q), axis=1))[0]
    alone = set(range(k)) - set(act.tolist())
    last = np.full(k, np.nan)
    for _ in range(6):
        if not act.size:
            break
        Qs = Q[act]
        X = s.stack(Qs)
        try:
            dQ = np.linalg.solve(s.jac_many(X), s.phi_many(X, [d[act] for d in td])[:, :, None])[:, :, 0]
        except np.linalg.LinAlgError:
            break
        Qs = Qs - dQ
        Q[act] = Qs
        size = np.max(np.abs(dQ), axis=1)
        prev, sc = last[act], scale[act]
        with np.errstate(invalid="ignore"):
            done = (size <= 4 * EPS * sc) | (~np.isnan(prev) & (size <= 1e-6 * sc) & (size ** 3 <= EPS * sc * prev * prev))
        out[act[done]] = Qs[done]
        last[act] = size
        act = act[~done]
    alone |= set(act.tolist())
    for i in sorted(alone):
        out[i] = pieces[i].position(float(T[i]))
    return out, td


def _kin_rates(pieces, ts):
    """(the positions as a Stack, Jacobians, velocities, times' data) of ``pieces[i]`` at ``ts[i]``: the
    condition numbers and the velocities in one stacked call each (the numbers of _kin_state)."""
    s = pieces[0].s
    Q, td = _kin_positions(pieces, ts)
    X = s.stack(Q)
    Js = s.jac_many(X)
    maybe = _near_toggle(pieces, Js, 1e12)
    for i in maybe[_conds_above(Js[maybe], 1e12)] if maybe.size else ():
        _kin_state(s, pieces[i].position(float(ts[i])), float(ts[i]))      # raises its message
    V = np.linalg.solve(Js, -s.phi_t_many(td)[:, :, None])[:, :, 0]
    return X, Js, V, td


def _pieces_of(pieces) -> tuple[list, np.ndarray]:
    """(the distinct pieces in order of first appearance, the index of each entry's among them)."""
    ids = list(map(id, pieces))
    by_id = dict(zip(ids, pieces))              # (keeps the order of first appearance)
    slot = {k: j for j, k in enumerate(by_id)}
    return list(by_id.values()), np.fromiter(map(slot.__getitem__, ids), dtype=np.intp, count=len(ids))


def _near_toggle(pieces, Js, limit: float) -> np.ndarray:
    """The indices of the Jacobians ``Js`` (of ``pieces[i]``) whose condition number may exceed
    ``limit``: excluded without a factorization where the piece's start knows J_a and its
    extreme singular values (Weyl: each σ of J moves by at most ‖J − J_a‖₂ ≤ ‖J − J_a‖_F, so
    cond(J) ≤ (σ_max + d)/(σ_min − d) with d = ‖J − J_a‖_F)."""
    uniq, which = _pieces_of(pieces)
    g = len(uniq)
    Jg = np.zeros((g,) + Js.shape[1:])
    smax, smin = np.zeros(g), np.zeros(g)       # σ_min 0: not known, never excluded
    for j, p in enumerate(uniq):
        if p.sigma is not None:
            Jg[j], smax[j], smin[j] = p.sigma
    Ja, smax, smin = Jg[which], smax[which], smin[which]
    d = np.sqrt(((Js - Ja) ** 2).sum(axis=(1, 2)))
    with np.errstate(all="ignore"):
        ok = (smin > d) & (smax + d <= limit * (smin - d))
    return np.nonzero(~ok)[0]


def _conds_above(Js, limit: float) -> list[int]:
    """The indices of the stacked square matrices ``Js`` whose condition number (2-norm) exceeds
    ``limit``: the SVD only where the bound cond₂ ≤ n ‖J‖∞ ‖J⁻¹‖∞ (one stacked LU) cannot exclude
    it, so that a mechanism far from its toggles pays no SVD per state."""
    k, n = Js.shape[0], Js.shape[-1]
    if k == 0:
        return []
    try:
        with np.errstate(all="ignore"):
            bound = n * np.abs(Js).sum(axis=2).max(axis=1) * np.abs(np.linalg.inv(Js)).sum(axis=2).max(axis=1)
        maybe = np.nonzero(~(bound <= limit))[0]
    except np.linalg.LinAlgError:
        maybe = np.arange(k)
    return [int(i) for i, c in zip(maybe, np.linalg.cond(Js[maybe]) if maybe.size else ()) if c > limit]


#: the most states of one stacked evaluation of the kinematics route: its arrays (the Jacobians,
#: k × m × n doubles) then stay at a few hundred kB, reused by the C allocator from call to call,
#: where the thousands of states of a quadrature or a search at once would fault in megabytes of
#: fresh pages per call (four-bar: ~3,800 page faults per solve without it, ~250 with it); every
#: operation is state by state (the same numbers)
KIN_CHUNK = 256


def _chunks(pieces, ts) -> list:
    """[(pieces, ts)] in slices of at most KIN_CHUNK states."""
    if len(ts) <= KIN_CHUNK:
        return [(pieces, ts)]
    return [(pieces[i:i + KIN_CHUNK], ts[i:i + KIN_CHUNK]) for i in range(0, len(ts), KIN_CHUNK)]


def _kin_states(pieces, ts) -> list:
    """(q, q̇, 0) of ``pieces[i]`` at ``ts[i]`` (Piece.states of the kinematics route: the
    states a search will read, made together; the numbers of each piece's own call)."""
    pieces = _grid_pieces(pieces, ts)
    out = []
    for ps, tt in _chunks(pieces, ts):
        X, _Js, V, _td = _kin_rates(ps, tt)
        out += [(X.Q[i].copy(), V[i].copy(), 0.0) for i in range(len(tt))]
    return out


def _kin_coordinates(pieces, ts) -> np.ndarray:
    """(q, q̇) of ``pieces[i]`` at ``ts[i]``, (2n, len(ts)) (Piece.coords of the kinematics route:
    the numbers of :func:`_kin_states`)."""
    pieces = _grid_pieces(pieces, ts)
    parts = []
    for ps, tt in _chunks(pieces, ts):
        X, _Js, V, _td = _kin_rates(ps, tt)
        parts.append(np.concatenate([X.Q.T, V.T]))
    return parts[0] if len(parts) == 1 else np.concatenate(parts, axis=1)


def _kin_velocities(pieces, ts) -> np.ndarray:
    """q̇ of ``pieces[i]`` at ``ts[i]``, (len(ts), n) (Piece.stack of the kinematics route)."""
    pieces = _grid_pieces(pieces, ts)
    parts = [_kin_rates(ps, tt)[2] for ps, tt in _chunks(pieces, ts)]
    return parts[0] if len(parts) == 1 else np.concatenate(parts)


def _kin_powers(pieces, ts) -> np.ndarray:
    """The power of the drives and the loads (outcome's W_nc) of ``pieces[i]`` at ``ts[i]``: q̈
    from J q̈ = γ, the multipliers from Jᵀ λ = M q̈ − f, each stacked (the numbers of one
    state at a time, outcome._kin_forces)."""
    pieces = _grid_pieces(pieces, ts)
    parts = [_kin_powers_of(ps, tt) for ps, tt in _chunks(pieces, ts)]
    return parts[0] if len(parts) == 1 else np.concatenate(parts)


def _kin_powers_of(pieces, ts) -> np.ndarray:
    """:func:`_kin_powers` of one slice of states."""
    s = pieces[0].s
    X, Js, V, td = _kin_rates(pieces, ts)
    A = np.linalg.solve(Js, s.gamma_many(X, V, td)[:, :, None])[:, :, 0]
    if s.loads:
        got = [s.applied(q, v, float(t)) for q, v, t in zip(X.Q, V, ts)]
        F = np.array([f for f, _ in got])
        P = np.array([p for _, p in got])
    else:
        F, P = s.grav[None, :], np.zeros(len(ts))
    lam = np.linalg.solve(np.swapaxes(Js, 1, 2), (s.mass[None, :] * A - F)[:, :, None])[:, :, 0]
    drive = 0
    for i, e in enumerate(s.elements):
        if e.kind == "drive":
            drive = drive + lam[:, s.offsets[i]] * V[:, e.index]
    return drive + P


def _kin_state(s, q, t):
    """(q, v, 0) at a placed position q: the velocities from J q̇ = −φ_t."""
    J = s.jac(q)
    cond = np.linalg.cond(J)
    if cond > 1e12:
        raise NumericalError(f"the mechanism is at a toggle position at t = {t:.6g} s (condition number of the joint "
                             f"rows {cond:.3g}): its velocities and forces are not determined there")
    v = np.linalg.solve(J, -s.phi_t(t))
    return q, v, 0.0


def _null_direction(s, q0):
    """(N, i): the one direction of motion allowed by the rows, scaled so that its largest
    coordinate q_i (the independent one) has N_i = 1; None unless the scene has one DOF."""
    J = s.jac(q0)
    if s.n - assembly.rank(J) != 1:
        return None
    N = np.linalg.svd(J)[2][-1] if J.size else np.eye(s.n)[0]
    i = int(np.argmax(np.abs(N)))
    N = N / N[i]
    N[np.abs(N) <= 8 * EPS] = 0.0          # rows that hold a coordinate fixed give an exact 0
    return N, i


def _linear(s, q0, N, i, has_k: bool, has_c: bool) -> motion.Linear1:
    """s̈ = A0 + A1 (s − s0) + A2 ṡ: the coefficients of a motion known to be affine (a
    coefficient whose load is absent is exactly 0)."""
    A0 = float(s.solve(q0, N * 0.0, 0.0)[0][i])
    L = assembly.length_scale(q0, s)
    for ld in s.loads:          # a spring's pull is affine along N while its ends do not cross
        if ld.kind == "spring":
            d = ld.P.pos(q0) - ld.Q.pos(q0)
            w = ld.P.jac(q0, s.n) @ N - ld.Q.jac(q0, s.n) @ N
            if np.any(w != 0):
                L = min(L, 0.5 * math.hypot(*d) / math.hypot(*w))
    A1 = (float(s.solve(q0 + L * N, N * 0.0, 0.0)[0][i]) - A0) / L if has_k else 0.0
    A2 = float(s.solve(q0, N, 0.0)[0][i]) - A0 if has_c else 0.0
    # A1 by a difference over L: its rounding relative to A1 grows with |A0|/|A1 L|
    rel = 8.0 * EPS_RATE * (1.0 + abs(A0) / abs(A1 * L)) if A1 != 0 else 0.0
    return motion.Linear1(q0, N, i, A0, A1, A2, rel)


def _closed_form_kind(s, q0, v0=None):
    """How a phase from (q0, v0) has a closed form, decided from the structure: ("constant", None)
    when every made row has a constant Jacobian and every load is constant (any number of
    degrees of freedom: constant accelerations, free flight included), or when the rows that are
    not linear keep their Jacobians over the plane the motion stays in, q0 + span(v0, a0)
    (:func:`_keeps_jacobian`: a block on a table hoisting a moving pulley whose strands stay
    parallel, from rest); ("affine", (N, i)) for one degree of freedom with loads affine along it
    (motion.Linear1); else None."""
    nd = _null_direction(s, q0)
    if nd is not None and motion.closed_form_reason(s, nd[0], q0) is None:
        has_k, has_c = motion.along(s, q0, nd[0])
        if not ((has_k or has_c) and any(e.rows and getattr(e, "mode", "") in ("slide", "slip") and e.mu_k
                                         for e in s.elements)):
            return "affine", nd
    made = [e for e in s.elements if e.rows > 0]
    if (any(e.kind == "drive" for e in made)
            or not all(ld.kind in ("force", "torque") and ld.constant for ld in s.loads)
            or any(ld.kind == "force" and ld.P.turns_with_body for ld in s.loads)):
        return None
    # the rows that may change their Jacobian: not linear, or at a point turning with its body
    fixed = [e for e in made if not e.linear or (getattr(e, "P", None) is not None and e.P.turns_with_body)]
    if not fixed:
        return "constant", None
    if v0 is None:
        return None
    a0 = s.solve(q0, v0, 0.0)[0]
    dirs = [d for d in (np.asarray(v0, float), a0) if np.any(d)]
    if all(_keeps_jacobian(e, q0, dirs) for e in fixed):
        return "constant", None
    return None


def _keeps_jacobian(e, q0, dirs) -> bool:
    """Whether the element's rows keep their Jacobian over q0 + span(dirs): a pin or a contact on
    a fixed straight line whose points do not turn along them, a cord whose segments keep their
    directions (their ends moving apart along them, no end turning with its body).  Then the
    matrix of the accelerations and multipliers is one over the plane, J̇ q̇ = 0 on it, and the
    accelerations stay those of the start: the motion stays in the plane, a quadratic in t."""
    from .contacts import Contact
    from .elements import Cord, Pin, String

    if type(e) not in (Pin, Contact, Cord, String):
        return False
    return all(e.straight_along(q0, d) for d in dirs)


def _closed_form(s, traj, t0, q0, v0, t_end, warn=None):
    """A closed-form phase from (t0, q0, v0): one piece to t_end, cut at its first event; ``warn``
    told when the vibration's phase ω*·t has lost its digits by the piece's end
    (:func:`long_phase`)."""
    kind = _closed_form_kind(s, q0, v0)
    if kind is None:
        return None
    along = quad = None
    quadratic = kind[0] == "constant"           # constant accelerations: q(t) a quadratic
    if kind[0] == "constant":
        a = s.solve(q0, v0, t0)[0]
        quad = (t0, q0, v0, a)

        def fn(t):
            tau = t - t0
            return q0 + v0 * tau + 0.5 * a * tau * tau, v0 + a * tau, 0.0

        def many(ts):                   # fn's q̇ at many times, the same operations on arrays
            tau = np.asarray(ts, dtype=float)[:, None] - t0
            return v0[None, :] + a[None, :] * tau
    else:
        N, i = along = kind[1]
        has_k, has_c = motion.along(s, q0, N)
        lin = _linear(s, q0, N, i, has_k, has_c)
        s_a, sd_a = float(q0[i]), float(v0[i])
        quadratic = lin.A1 == 0 and lin.A2 == 0
        if quadratic:                   # Linear1.motion's quadratic, per coordinate
            quad = (t0, q0, N * sd_a, N * lin.A0)

        def fn(t):
            sv, sdv = lin.motion(t - t0, s_a, sd_a)
            return q0 + N * (sv - s_a), N * sdv, 0.0

        def many(ts):                   # fn's q̇ at many times (the rate alone: no positions made)
            return lin.rates(np.asarray(ts, dtype=float) - t0, s_a, sd_a)[:, None] * N[None, :]
    traj.add(motion.Piece(t0, t_end, fn, motion.modes_of(s), "closed-form", along=along, many=many, quad=quad))
    traj.method = "closed-form"
    got = _first_event(s, traj, len(traj.pieces) - 1, t_end, quadratic)
    if along is not None and warn is not None and got is not None:
        long_phase(lin, t0, got[0], warn)
    return got


def long_phase(lin: motion.Linear1, t0: float, t1: float, warn) -> None:
    """Warn (:func:`dyncli.phase.warn_lost`) when a vibration's phase ω*·(t1 − t0) is uncertain
    by more than :data:`dyncli.phase.LOSS` of its oscillation: ω* from the assembled A1, A2 to
    ``lin.rel`` relative (:func:`dyncli.phase.rounded`), times the free part's decay e^(−ζωₙt)
    (an overdamped or unstable motion has no phase)."""
    if not (lin.A1 < 0 and math.isfinite(t1) and t1 > t0):
        return
    wn = math.sqrt(-lin.A1)
    zeta = -lin.A2 / (2.0 * wn)
    if not zeta < 1.0:
        return
    from dyncli.phase import LOSS, rounded

    tau = t1 - t0
    err = rounded(wn * math.sqrt(1.0 - zeta * zeta), tau, 0.0, lin.rel) * math.exp(-max(zeta, 0.0) * wn * tau) \
        + math.ulp(t1) * wn
    if err > LOSS:
        from types import SimpleNamespace

        from dyncli.phase import warn_lost

        warn_lost(SimpleNamespace(warn=warn), [t1], [err], "the vibration")


def constant_forces(s) -> bool:
    """Whether the joints' forces are one constant over a closed-form phase of the current joint
    set, decided from the structure: every made row linear (one matrix, SceneSystem.constant_matrix:
    constant Jacobian and friction columns, no J̇ q̇ term), nothing driven, and every load a
    constant force or couple (gravity's included) at a point that does not turn with its body —
    the equations M q̈ − Jᵀ λ = f, J q̈ = 0 then have one right-hand side at every state, so
    λ (the normal forces, the tensions, the friction margins μ_s N ∓ F) does not change."""
    return (s.constant_matrix() and not any(e.kind == "drive" for e in s.elements)
            and all(ld.kind in ("force", "torque") and ld.constant
                    and not (ld.kind == "force" and ld.P.turns_with_body) for ld in s.loads))


def _first_event(s, traj, k0: int, t_end: float, quadratic: bool = False):
    """The first event on the exact pieces from index k0 (:func:`_piece_event`: decided by the
    sign analysis of each watched quantity, not by samples; ``quadratic``: the pieces' positions
    are quadratics in t, constant accelerations); the pieces are cut there.  Returns
    (t, q, v, hit)."""
    for k in range(k0, len(traj.pieces)):
        p = traj.pieces[k]
        if p.t_b <= p.t_a:
            continue
        motion.set_modes(s, p.modes)
        got = _piece_event(s, p, quadratic)
        if got is not None:
            p.t_b = got[0]
            del traj.pieces[k + 1:]
            q, v, _ = p.fn(got[0])
            return got[0], q, v, got
    q, v, _ = traj.pieces[-1].fn(t_end)
    return t_end, q, v, None


def _watchers(s, at, state) -> list:
    """The element of each watched quantity of ``at`` (motion.watches' list at ``state`` = (q, v,
    t): the elements' entries in their order, each named by its joint, then the one-sided
    springs'), None for a spring's: read from the names (no solve) where the elements that watch
    are named apart, else from each element's own entries (one solve)."""
    els = s.elements
    names = [e.name for e in els]
    out = []
    if all(names.count(j) == 1 for j in {j for j, _w, _g in at if j}):
        i = 0
        for joint, _what, _g in at:
            while i < len(els) and els[i].name != joint:
                i += 1
            out.append(els[i] if joint and i < len(els) else None)
        return out
    q, v, t = state
    lam = s.solve(q, v, t)[1]
    for i, e in enumerate(els):
        out += [e] * len(e.watch(s.lam_of(lam, i), q, v, t))
    return out + [None] * (len(at) - len(out))


def _affine_watches(s, at, state) -> list[bool]:
    """Per watched quantity of ``at`` (motion.watches' list at the piece's start): whether it is
    affine in the positions by the structure of its joint — a point that does not turn with its
    body, or a rolling body's centre, over a line without ends (its gap, "impact"), a cord whose
    runs are linear (a slack run's gap, "taut").  Over constant accelerations such a quantity is
    a quadratic in t."""
    from .contacts import Contact, Rolls
    from .elements import Cord

    def affine(e, what: str) -> bool:
        if type(e) is Contact:
            return what == "impact" and not e.P.turns_with_body and e.surface.length is None
        if type(e) is Rolls:
            return what == "impact" and e.surface.length is None
        return type(e) is Cord and what == "taut" and e.linear

    return [e is not None and affine(e, what) for e, (_j, what, _g) in zip(_watchers(s, at, state), at)]


def _turning_gaps(s, p, at, state) -> dict:
    """Per watched quantity of ``at`` (motion.watches' list at the piece's start) that is the gap
    of a released contact whose point turns with its body, over a plane line, on a piece of
    constant accelerations without angular acceleration of that body (``p.quad``: a free rigid
    body under gravity): its index -> :func:`_gap_forms`."""
    from .contacts import Contact

    acc = p.quad[3]
    return {j: _gap_forms(e, p.quad) for j, (e, (_j, what, _g)) in enumerate(zip(_watchers(s, at, state), at))
            if type(e) is Contact and what == "impact" and e.mode == "off" and e.P.turns_with_body
            and e.P.body is not None and acc[e.P.body.index[2]] == 0.0}


def _gap_forms(e, quad) -> tuple:
    """(the gap of the contact ``e``'s point over its line as a crossing.Sinusoid, its place along
    the line from the line's origin (None for a line without ends), the line's length, the
    forms' error over [a, b] beyond a reading's: the arm's through its angle's rounding and the
    terms' of the quadratic) over the piece of constant accelerations ``quad``."""
    t0, q0, v0, acc = quad
    i1, i2, ia = e.P.body.index
    p1, p2 = e.P.p
    sf = e.surface

    def form(w1: float, w2: float) -> crossing.Sinusoid:
        o = w1 * sf.origin[0] + w2 * sf.origin[1]
        return crossing.Sinusoid(t0, w1 * float(q0[i1]) + w2 * float(q0[i2]) - o,
                                 w1 * float(v0[i1]) + w2 * float(v0[i2]),
                                 0.5 * (w1 * float(acc[i1]) + w2 * float(acc[i2])),
                                 w1 * p1 + w2 * p2, w2 * p1 - w1 * p2, float(q0[ia]), float(v0[ia]))

    arm = math.hypot(p1, p2)
    th0, w = abs(float(q0[ia])), abs(float(v0[ia]))
    vmax, amax = max(abs(float(v0[i1])), abs(float(v0[i2]))), max(abs(float(acc[i1])), abs(float(acc[i2])))

    def err(a: float, b: float) -> float:
        tau = max(abs(a - t0), abs(b - t0))
        return 16 * EPS * (arm * (1.0 + th0 + w * tau) + vmax * tau + amax * tau * tau)

    return form(*sf.n), (form(*sf.d) if sf.length is not None else None), sf.length, err


def _piece_event(s, p, quadratic: bool = False):
    """The first event on one exact piece (closed form, quadrature, or held at rest under loads
    that change in time): each watched quantity's first crossing (crossing.first_crossing, by
    sign analysis, not samples).  The span is searched in windows: held at rest (loads that are
    the user's functions of t), from 64 s, each in 16 starting cells; moving (constant loads),
    from 1/16 of the span (64 s at most), each in one starting cell (an early event costs a few
    cells); each window 16 times wider than the last (all_roots resolves a cell to 2^-48 of its
    width: a period of 1 s is not lost in a window of 1e300 s).  Where the joint rows have one
    matrix over the piece, the states of a cell are solved in one stacked call
    (SceneSystem.solve_many: the same numbers as one solve each).  In a closed form whose joint
    forces are one constant by structure (:func:`constant_forces`), a force off its band (more
    than twice its rounding from 0) has no crossing and is not searched; over constant
    accelerations (``quadratic``) a gap affine in the positions (:func:`_affine_watches`) is a
    quadratic in t, its crossing decided from the quadratic (crossing.quadratic_crossing),
    searched as before where that is too close to call.  The solve's CPU budget bounds the
    search.  Returns (t, joint, what) or None."""
    from dyncli import cputime

    cache: dict[float, list[float]] = {}
    states_at: dict[float, tuple] = {}          # p.fn's states, by time (a reading's and a search's)
    stacked = p.route == "statics" or s.constant_matrix()

    def state(t: float) -> tuple:
        got = states_at.get(t)
        if got is None:
            got = states_at[t] = p.fn(t)
        return got

    def column(j: int, ts) -> np.ndarray:
        ts = [float(t) for t in np.atleast_1d(ts)]
        if missing := [t for t in dict.fromkeys(ts) if t not in cache]:
            if (limit := cputime.over()) is not None:
                raise NumericalError(
                    f"the forces of the joints were followed to t = {missing[0]:.6g} s only within the CPU budget of "
                    f"{limit:g} s (accuracy.max_cpu): shorten the times asked (at, t_max) or raise accuracy.max_cpu")
            states = [state(t)[:2] + (t,) for t in missing]
            lams = [lam for _a, lam, _P in s.solve_many(states)] if stacked and len(states) > 1 and s.watching \
                else [None] * len(states)
            for (q, v, t), lam in zip(states, lams):
                cache[t] = [g for _j, _w, g in motion.watches(s, q, v, t, lam)]
        return np.array([cache[t][j] for t in ts])

    q, v, _ = state(p.t_a)
    q_b, v_b, _ = state(p.t_b)
    tol = crossing.rounding(s, q, v, p.t_a, v_b)
    at_a = motion.watches(s, q, v, p.t_a)
    # held at rest, a one-sided spring's stretch does not change (no switch to look for)
    # the geometry's watches first: an end that reaches its pulley or the end of its surface
    # bounds the search of the forces, which jump there (the segment's direction does)
    # (in a closed form every cord keeps its segments' directions: an arc's angle does not move,
    # its watch ``turns`` cannot cross)
    watched = sorted(((j, joint, what) for j, (joint, what, _g) in enumerate(at_a)
                      if not (what == "switch" and p.route == "statics")
                      and not (what == "turns" and p.route == "closed-form")), key=lambda w: w[2] in crossing.FORCES)
    if p.route == "closed-form" and constant_forces(s):
        # the multipliers are one constant over the piece: a force off its band has no crossing
        # (the piece's end read as a check of the structure; where it is beyond the doubles, the
        # search below decides as before)
        try:
            at_b = motion.watches(s, q_b, v_b, p.t_b)
        except NumericalError:
            at_b = None
        if at_b is not None:
            watched = [(j, joint, what) for j, joint, what in watched
                       if not (what in crossing.FORCES and abs(at_a[j][2]) > 2 * tol[what]
                               and abs(at_b[j][2] - at_a[j][2]) <= tol[what])]
            if not watched:
                return None
    # held, the loads are the user's functions of t (a narrow pulse is seen by 16 cells of 33
    # points each over a window); moving, the loads are constant and the motion's own scales rule
    held = p.route == "statics"
    formed = quadratic and p.route == "closed-form"
    affine = _affine_watches(s, at_a, (q, v, p.t_a)) if formed else [False] * len(at_a)
    turning = _turning_gaps(s, p, at_a, (q, v, p.t_a)) if formed else {}
    L = tol["impact"] / (64 * EPS)              # the lengths' scale of their rounding

    def reading(a: float, b: float) -> float:
        """The rounding of one reading of an affine gap over [a, b]: of the largest coordinate."""
        return 4 * EPS * max([L] + [abs(x) for t in (a, 0.5 * (a + b), b) for x in state(t)[0].tolist()])

    lo, width = p.t_a, crossing.FIRST_WINDOW if held else min(crossing.FIRST_WINDOW, (p.t_b - p.t_a) / 16)
    while lo < p.t_b:                           # window by window, every watched quantity in each
        hi = min(p.t_b, lo + width)
        if not hi > lo:                         # (a width below the spacing of the doubles at lo)
            hi = p.t_b
        best = None
        for j, joint, what in watched:
            end = hi if best is None else best[0]
            got: Any = crossing.UNDECIDED
            if affine[j]:
                got = crossing.quadratic_crossing(lambda ts, j=j: column(j, ts), lo, end, tol[what], reading)
            elif j in turning:
                G, S, length, err = turning[j]
                try:
                    got = crossing.sinusoid_crossing(G, S, length, lambda ts, j=j: column(j, ts), lo, end,
                                                     tol[what], 2 * reading(lo, end) + err(lo, end))
                except (ArithmeticError, ValueError):   # the form beyond the doubles: searched
                    got = crossing.UNDECIDED
            if got == crossing.UNDECIDED:
                got = crossing.first_crossing(lambda ts, j=j: column(j, ts), lo, end, what, tol[what],
                                              start=lo == p.t_a, cells=16 if held else 1)
            if got is not None:
                best = (got, joint, what)
        if best is not None:
            return best
        lo, width = hi, 16 * width
    return None




