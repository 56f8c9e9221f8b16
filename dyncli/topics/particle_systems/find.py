"""The ``find`` queries and ``distance`` of a system of particles in motion (§11).

The motion is the run's dense output (every accepted step's interpolant, the same run as the
reported times, continued to t_end); the breaks are its steps.  The state at a time holds the
results over time (``x_motion``, ``com_motion``, ``G_motion``, ``H_O_motion``, ``T_motion``,
``V_internal_motion``, ``P_internal_motion``, ``W_internal``, ``distance``); the velocities in
the state are the rates of the positions, so a turning point is a root (Brent); every step is
cut at the exact extremes of each result searched (:func:`dyncli.motion_find.exact_breaks`),
between which the search takes it as monotone.  ``distance``:
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
        """States (len(ts), n) at the times (each within the run): one call of a step's
        interpolant for all the times inside that step."""
        ts = np.asarray(ts, dtype=float).reshape(-1)
        if ts.size == 1:
            k = min(bisect.bisect_left(self.t, float(ts[0])), len(self.t) - 1)
            return np.asarray(self.dense[k](float(ts[0])), dtype=float)[None, :]
        k = np.minimum(np.searchsorted(self.t, ts, side="left"), len(self.t) - 1)
        order = np.argsort(k, kind="stable")
        cuts = np.flatnonzero(np.diff(k[order])) + 1
        out = None
        for group in np.split(order, cuts):
            Y = np.asarray(self.dense[int(k[group[0]])](ts[group]), dtype=float)
            if out is None:
                out = np.empty((ts.size, Y.shape[0]))
            out[group] = Y.T
        assert out is not None                        # (ts has one group at least)
        return out


def report(p, res, steps: Steps, quantities, n: int) -> None:
    """``distance`` per particle at the times of ``at``, and the ``find`` answers."""
    if not steps.t:
        res.results["distance"] = {str(i): [0.0] * len(p.at) for i in range(n)}
        return
    B = [0.0] + steps.t

    def speeds(ts):                                  # every particle's speed: one column each
        return np.linalg.norm(steps.y(ts)[:, 3 * n:6 * n].reshape(-1, n, 3), axis=2)

    odo = mf.Odometer(speeds, B, rtol=float(p.accuracy.rtol))
    mf.check_resolved(odo, res.warn)
    D0 = odo.at(p.at)
    res.results["distance"] = {str(i): [row[i] for row in D0] for i in range(n)}
    if not p.find:
        return

    def batch(ts) -> list[dict]:
        Y = steps.y(ts)
        X, G, H, T, com, Vint, Pint, W = quantities(Y)
        rows = odo.at(ts)
        D = [[row[i] for row in rows] for i in range(n)]
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
    own = mf.exact_breaks(p.find, B, _values(steps, quantities, odo, n), warn=res.warn)
    motion = mf.StateMotion(lambda t: batch([t])[0], 0.0, float(p.t_end), B, rtol=float(p.accuracy.rtol), subdivide=1,
                            rates={"x_motion": velocity}, batch=batch, breaks_for=own, monotone=own is not None)
    mf.attach(res, p.find, mf.answer_find(p.find, motion, lambda x: constant(x, params), res.warn))


def _values(steps: Steps, quantities, odo, n: int):
    """``values(paths, ts)`` for :func:`dyncli.motion_find.exact_breaks`: the searched results at an
    array of times as rows, read from the arrays of the dense output (each a smooth function of
    the step's polynomial: every step is cut at its exact extremes)."""
    def values(paths, ts):
        ts = np.asarray(ts, dtype=float).reshape(-1)
        X, G, H, T, com, Vint, Pint, W = quantities(steps.y(ts))
        arrays = {"x_motion": X, "com_motion": com, "G_motion": G, "H_O_motion": H, "T_motion": T,
                  "V_internal_motion": Vint, "P_internal_motion": Pint, "W_internal": W}
        rows = []
        for path in paths:
            head, _, rest = path.partition(".")
            parts = rest.split(".") if rest else []
            if head == "distance":
                arr = np.asarray(odo.at(ts), dtype=float)            # (times, particles)
            elif head in arrays:
                arr = np.asarray(arrays[head], dtype=float)
            else:
                raise KeyError(path)
            if not all(x.isdigit() for x in parts) or len(parts) != arr.ndim - 1:
                raise KeyError(path)
            for x in parts:
                if int(x) >= arr.shape[1]:
                    raise KeyError(path)
                arr = arr[:, int(x)]
            rows.append(arr)
        return np.stack(rows)
    return values
