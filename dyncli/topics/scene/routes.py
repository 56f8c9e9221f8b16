"""Set up a scene (assembly, DOF, initial modes, refusals), pick and run its route, report.

Routes (``route`` and ``method``), the cheapest that is exact, decided from the structure:

* ``statics``: no degree of freedom and no drive (or every contact sticking with constant
  loads): the reactions of equilibrium, Jᵀ λ = −f;
* ``kinematics``: no degree of freedom with drives: positions by Newton on φ(q, t) = 0 from the
  previous time, J q̇ = −φ_t, J q̈ = γ, and the forces from M q̈ − f = Jᵀ λ;
* ``closed-form``: one DOF, rows affine in q and loads affine along the motion (motion.py);
* ``quadrature`` (``accuracy.method: quadrature`` only, in this release: it costs seconds):
  one DOF with an energy integral (energy.py);
* ``ode``: otherwise.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli import ode
from dyncli.errors import InputError, NumericalError

from . import assembly, motion
from .elements import Contact

EPS = float(np.finfo(float).eps)
from .prepare import Scene


# ----------------------------------------------------------------------------- routes

def run(scene: Scene, t_end: float, acc):
    s = scene.system
    traj = motion.Trajectory(s, 0.0, t_end)
    drives = any(e.kind == "drive" for e in s.elements)
    if scene.dof == 0 and drives:
        return _kinematics(scene, traj, acc), "kinematics"
    if _effective_dof(s, scene.q0) == 0 and _steady(s):
        return _statics(scene, traj), "statics"     # held by the joints, or by friction at rest
    if acc.method in ("auto", "closed-form"):
        cf = _closed_form(scene, traj, t_end)
        if cf is not None:
            return cf, "closed-form"
        if acc.method == "closed-form":
            raise InputError("this scene has no closed form (it needs one degree of freedom, joints whose rows are "
                             "affine in the positions and loads affine along the motion): use method auto",
                             "accuracy.method")
    if acc.method == "quadrature":      # on request only in this release: its cost is seconds (docs)
        from . import energy

        why = energy.applies(s) if scene.dof == 1 else "the scene has more than one degree of freedom"
        if why is None:
            energy.run(scene, traj, t_end, acc)
            _one_sided_events(s, traj)
            return traj, "quadrature"
        if acc.method == "quadrature":
            raise InputError(f"the quadrature route needs one degree of freedom and an energy integral: {why}; use "
                             "method auto", "accuracy.method")
    method = "DOP853" if acc.method in ("auto", "ode") else acc.method
    route = motion.OdeRoute(s, acc, method)
    budget = ode.Budget(acc.max_steps)
    route.run(scene.q0, scene.v0, t_end, budget, traj, acc.rtol, acc.atol)
    traj.method = f"ode:{method}"
    return traj, "ode"


def _effective_dof(s, q) -> int:
    J = s.jac(q)
    return s.n - assembly.rank(J)


def _steady(s) -> bool:
    return all(ld.constant and ld.kind != "damper" for ld in s.loads) and not any(e.kind == "drive" for e in s.elements)


def _statics(scene: Scene, traj):
    s, q = scene.system, scene.q0
    v = np.zeros(s.n)
    f, _ = s.applied(q, v, 0.0)
    J = s.jac(q)
    lam, *_ = np.linalg.lstsq(J.T, -f, rcond=None)
    if float(np.max(np.abs(J.T @ lam + f), initial=0.0)) > 1e-9 * max(float(np.max(np.abs(f), initial=0.0)), 1e-300):
        raise NumericalError("the joints cannot hold the loads in equilibrium")
    a = np.zeros(s.n)
    fixed = (a, lam, 0.0)
    traj.add(motion.Piece(0.0, traj.t_end, lambda t: (q, v, 0.0), motion.modes_of(s)))
    traj.fixed = fixed
    traj.method = "statics"
    return traj


def _kinematics(scene: Scene, traj, acc):
    s = scene.system
    grid = _drive_grid(s, traj.t_end)
    qs = [scene.q0]
    for t in grid[1:]:
        qs.append(_position(s, qs[-1], t))
    conds = [float(np.linalg.cond(s.jac(q))) for q in qs]
    worst = int(np.argmax(conds))
    if conds[worst] > 1e8:
        scene.warnings.append(f"the mechanism comes near a toggle position (the joint rows' condition number reaches "
                              f"{conds[worst]:.3g} at t = {grid[worst]:.6g} s): its velocities and forces lose about "
                              f"{math.log10(conds[worst]):.0f} digits there")
    for k in range(len(grid) - 1):
        q_start, t_a, t_b = qs[k], grid[k], grid[k + 1]
        traj.add(motion.Piece(t_a, t_b, lambda t, q_start=q_start: _kin_state(s, q_start, t), motion.modes_of(s)))
    if len(grid) == 1:
        traj.add(motion.Piece(0.0, 0.0, lambda t: _kin_state(s, scene.q0, t), motion.modes_of(s)))
    traj.method = "kinematics"
    return traj


def _drive_grid(s, t_end: float) -> np.ndarray:
    """Times at which the positions are continued from one to the next: at least 64 pieces, and
    so many that no drive moves more than 0.05 rad (an angle) or 2 % of the scene's size (a
    coordinate) within one (Newton from the piece's start then stays on the branch)."""
    if not t_end > 0:
        return np.array([0.0])
    fine = np.linspace(0.0, t_end, 1025)
    size = max(assembly.length_scale(np.zeros(1), s), 1e-300)
    pieces = 64
    for e in s.elements:
        if e.kind == "drive":
            vals = np.array([e.f(t)[0] for t in fine])
            step = 0.05 if s.names[e.index].startswith("angle.") else 0.02 * size
            pieces = max(pieces, int(np.sum(np.abs(np.diff(vals))) / step) + 1)
    return np.linspace(0.0, t_end, min(pieces, 20_000) + 1)


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


def _kin_state(s, q_start, t):
    q = _position(s, q_start, t)
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
    A1 = (float(s.solve(q0 + L * N, N * 0.0, 0.0)[0][i]) - A0) / L if has_k else 0.0
    A2 = float(s.solve(q0, N, 0.0)[0][i]) - A0 if has_c else 0.0
    return motion.Linear1(q0, N, i, A0, A1, A2)


def _closed_form(scene: Scene, traj, t_end):
    s, q0, v0 = scene.system, scene.q0, scene.v0
    nd = _null_direction(s, q0)
    if nd is None or motion.closed_form_reason(s, nd[0], q0) is not None:
        return None
    N, i = nd
    has_k, has_c = motion.along(s, q0, N)
    rough = [e for e in s.elements if isinstance(e, Contact) and e.mode == "slide" and e.mu_k]
    if rough and (has_k or has_c):
        return None
    lin = _linear(s, q0, N, i, has_k, has_c)
    A1, A2, sd0 = lin.A1, lin.A2, float(v0[i])
    t_a, s_a, sd_a = 0.0, float(q0[i]), sd0
    while True:
        modes = motion.modes_of(s)
        t_stop = None
        if rough and A1 == 0 and A2 == 0 and sd_a != 0 and (sd_a > 0) != (lin.A0 > 0):
            t_stop = t_a - sd_a / lin.A0
        t_b = min(t_end, t_stop) if t_stop is not None else t_end

        def fn(t, t_a=t_a, s_a=s_a, sd_a=sd_a, lin=lin, qa=q0 + N * (s_a - float(q0[i]))):
            sv, sdv = lin.motion(t - t_a, s_a, sd_a)
            return qa + N * (sv - s_a), N * sdv, 0.0

        traj.add(motion.Piece(t_a, t_b, fn, modes))
        if t_stop is None or t_stop >= t_end:
            break
        qs, _, _ = fn(t_stop)
        vs = N * 0.0
        e = rough[0]
        sticks, sign = motion.stick_test(s, e, qs, vs, t_stop)
        if sticks:
            traj.events.append(motion.Event(t_stop, e.name, "sticks"))
            traj.stopped = t_stop
            break
        e.mode, e.sign = "slide", sign
        s.refresh()
        A0 = float(s.solve(qs, vs, t_stop)[0][i])
        lin = motion.Linear1(qs, N, i, A0, 0.0, 0.0)
        t_a, s_a, sd_a = t_stop, float(qs[i]), 0.0
    _one_sided_events(s, traj)
    traj.method = "closed-form"
    traj.along = (N, i)
    return traj


def _one_sided_events(s, traj) -> None:
    """Contact forces and tensions along a closed-form motion: a sign change is located
    (each piece scanned at 64 points, then Brent) and stops the motion there."""
    from dyncli.rootfind import brent

    for p in list(traj.pieces):
        if p.t_b <= p.t_a:
            continue
        motion.set_modes(s, p.modes)
        ts = np.linspace(p.t_a, p.t_b, 65)

        def w(t):
            q, v, _ = p.fn(t)
            return motion.watches(s, q, v, t)

        prev = w(ts[0])
        for t0, t1 in zip(ts[:-1], ts[1:]):
            cur = w(t1)
            for k, ((joint, what, g0), (_, _, g1)) in enumerate(zip(prev, cur)):
                if what in ("sticks", "switch") or not motion._crossed(g0, g1, what):
                    continue
                tc = brent(lambda t, k=k: w(t)[k][2], t0, t1, 4 * EPS * t1, 4 * EPS, 200)
                traj.events.append(motion.Event(tc, joint, what))
                traj.stopped = tc
                return
            prev = cur


