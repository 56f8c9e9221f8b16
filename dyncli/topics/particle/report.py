"""A particle's trajectory reported at the requested times (notes §16, §20, §21), for every route
that makes one: the ODE route (``solver.py``) and the exact Kepler route (``orbit.py``).

:func:`at_times` evaluates the motion at many times at once (x, v, a, the energies, H_O),
:func:`reported` turns it into the results, :func:`energy_residual` measures the energy equation
(20.4) over the run, :func:`report_terms` adds the power and work per force and the cylindrical
components.
"""

from __future__ import annotations

import numpy as np

from dyncli.errors import NumericalError
from dyncli.topics.particle import equations as eq
from dyncli.topics.particle.forces import Forces, NonFiniteForce
from dyncli.topics.particle.trajectory import RestPhase, Trajectory


#: the reported quantities at the requested times (each with its error in error_estimate)
REPORTED = ("x", "v", "a", "T", "V", "E", "W_nc", "H_O")


def reported(S, resid) -> dict:
    """The results at the requested times as lists (vectors as lists of 3, -0.0 as 0.0): one
    array of every reported row, converted at once."""
    rows = np.concatenate([S[k] if S[k].ndim == 2 else S[k][None] for k in REPORTED]) + 0.0
    out, i = {}, 0
    for k in REPORTED:
        n = 3 if S[k].ndim == 2 else 1
        out[k] = rows[i:i + 3].T.tolist() if n == 3 else rows[i].tolist()
        i += n
    out["energy_residual"] = resid
    return out


def energy_residual(p, F, S):
    """(max |E − E1 − W_nc| over every accepted step and the requested times (20.4), the energy
    scale it is measured against: the largest |E1|, |T|, |V|, |W_nc| over them)."""
    x0, v0 = np.asarray(p.x0, float), np.asarray(p.v0, float)
    E1 = 0.5 * F.m * float(v0 @ v0) + float(F.potential(x0))
    T, V, W = S["energies"]
    if not T.size:
        return 0.0, abs(E1)
    return eq.energy_residual(T + V, E1, W), max(abs(E1), float(abs(np.concatenate(S["energies"])).max()))


def at_times(traj: Trajectory, F: Forces, times, steps: bool = False) -> dict:
    """The motion at every time of ``times`` at once, as arrays: x, v, a
    (3 x N), T, V, E, W_nc (N), H_O (3 x N); with ``steps``, also T, V, W_nc over every accepted
    step and the times (``energies``, for the energy residual).  Every quantity on whole arrays:
    one evaluation of the states at all the times, a = f(t, y) by the phase's own right-hand side
    on the arrays of its times (``Forces.accelerations``, friction continuation included)."""
    times = [float(t) for t in times]
    m = F.m
    idx, Y = traj.state_array(times)
    X, Vel = Y[0:3], Y[3:6]
    kinds = np.array([isinstance(ph, RestPhase) for ph in traj.phases], dtype=bool)
    rest = kinds[idx] if idx.size else np.zeros(0, dtype=bool)
    A = np.zeros((3, len(times)))
    t_arr = np.asarray(times, float)
    order = np.argsort(idx, kind="stable")          # the times of each phase, one call each
    for sel in np.split(order, np.flatnonzero(np.diff(idx[order])) + 1) if idx.size else ():
        ph = traj.phases[int(idx[sel[0]])]
        if isinstance(ph, RestPhase):
            continue
        try:
            A[:, sel] = F.accelerations(ph.d, t_arr[sel], X[:, sel], Vel[:, sel])
        except NonFiniteForce as exc:
            raise NumericalError(f"the force is not finite (inf or NaN) at t = {exc.t:.6g} s, x = "
                                 f"[{', '.join(f'{c:.6g}' for c in exc.x)}] m") from None
    Z = np.concatenate([traj.steps()[1], Y], axis=1) if steps else Y
    T = eq.kinetic_energy(m, Z[3:6])
    V = F.potential(Z[0:3])
    k = Z.shape[1] - len(times)
    S = {"x": X, "v": Vel, "a": A, "T": T[k:], "V": V[k:],
         "E": T[k:] + V[k:], "W_nc": Y[6], "H_O": eq.angular_momentum(m, X, Vel), "t": times, "Y": Y,
         "rest": rest}
    if steps:
        S["energies"] = (T, V, Z[6])
    return S


def report_terms(res, p, F, traj, S) -> None:
    """Power and work per force (work.py); the cylindrical basis (cylindrical.py)."""
    from . import work

    work.add(res, p, F, traj, S)
    if getattr(p, "basis", "cartesian") == "cylindrical":
        from . import cylindrical

        cylindrical.add(res, p, traj, S, F.m)
