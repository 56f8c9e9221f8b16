"""The ``find`` queries and ``distance`` of a system of particles in motion (§11).

The motion is the run's dense output (every accepted step's interpolant, the same run as the
reported times, continued to t_end); the breaks are its steps.  The state at a time holds the
results over time (``x_motion``, ``com_motion``, ``G_motion``, ``H_O_motion``, ``T_motion``,
``V_internal_motion``, ``P_internal_motion``, ``W_internal``, ``distance``); the velocities in
the state are the rates of the positions, so a turning point is a root (Brent).  ``distance``:
each particle's path length ∫|vᵢ| dt (Gauss–Legendre on every step).
"""

from __future__ import annotations

import bisect

import numpy as np

from dyncli import motion_find as mf
from dyncli.expr import constant, resolve_params


class Steps:
    """The run's accepted steps (``on_step`` of :func:`dyncli.ode.integrate`): y(t) at any time
    of the forward run."""

    def __init__(self):
        self.t: list[float] = []
        self.dense: list = []

    def __call__(self, t_old, t_new, dense, direction=1.0):
        if dense is not None and direction > 0 and t_new > t_old:
            dense(t_old)                        # the interpolant built now, while the solver is on this step
            self.t.append(float(t_new))
            self.dense.append(dense)

    def y(self, ts) -> np.ndarray:
        """States (len(ts), n) at the times (each within the run)."""
        out = []
        for t in ts:
            k = min(bisect.bisect_left(self.t, float(t)), len(self.t) - 1)
            out.append(self.dense[k](float(t)))
        return np.array(out, dtype=float)


def extended(p):
    """p with t_end extended to the end of every ``within`` window and ``t`` query (§11)."""
    params = resolve_params(p.params)
    end = mf.search_end(float(p.t_end), p.find, lambda x: constant(x, params))
    return p.model_copy(update={"t_end": end}) if end > p.t_end else p


def report(p, res, steps: Steps, quantities, n: int) -> None:
    """``distance`` per particle at the times of ``at``, and the ``find`` answers."""
    if not steps.t:
        res.results["distance"] = {str(i): [0.0] * len(p.at) for i in range(n)}
        return
    B = [0.0] + steps.t

    def speeds_of(i):
        return lambda ts: np.linalg.norm(steps.y(ts)[:, 3 * (n + i):3 * (n + i) + 3], axis=1)

    odos = [mf.Odometer(speeds_of(i), B) for i in range(n)]
    res.results["distance"] = {str(i): odos[i].at(p.at) for i in range(n)}
    if not p.find:
        return

    def batch(ts) -> list[dict]:
        Y = steps.y(ts)
        X, G, H, T, com, Vint, Pint, W = quantities(Y)
        D = [o.at(ts) for o in odos]
        return [{"x_motion": {str(i): X[j, i].tolist() for i in range(n)}, "com_motion": com[j].tolist(),
                 "G_motion": G[j].tolist(), "H_O_motion": H[j].tolist(), "T_motion": float(T[j]),
                 "V_internal_motion": float(Vint[j]), "P_internal_motion": float(Pint[j]),
                 "W_internal": float(W[j]), "distance": {str(i): D[i][j] for i in range(n)}}
                for j in range(len(ts))]

    def velocity(t, rest):                           # x_motion.i.c: the rate is v_i,c
        i, _, c = rest.partition(".")
        if not (i.isdigit() and c.isdigit()) or int(i) >= n or int(c) > 2:
            return None
        return float(steps.y([t])[0, 3 * (n + int(i)) + int(c)])

    params = resolve_params(p.params)
    motion = mf.StateMotion(lambda t: batch([t])[0], 0.0, float(p.t_end), B, rtol=float(p.accuracy.rtol),
                            rates={"x_motion": velocity}, batch=batch)
    mf.attach(res, p.find, mf.answer_find(p.find, motion, lambda x: constant(x, params), res.warn))
