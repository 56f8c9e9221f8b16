"""A particle's motion on the cylindrical polar basis (notes §16, §21-§22).

With ``basis: cylindrical`` the ``particle`` results are also given on
{e_r, e_θ, e3} (e_r = cosθ e1 + sinθ e2, e_θ = −sinθ e1 + cosθ e2):

    x = r e_r + x3 e3,  v = ṙ e_r + r θ̇ e_θ + ẋ3 e3            (22.6a,b)
    F = m a = m[(r̈ − r θ̇²) e_r + (2ṙθ̇ + r θ̈) e_θ + ẍ3 e3]      (22.6d)
    H_O = m[−r θ̇ x3 e_r + (x3 ṙ − r ẋ3) e_θ + r² θ̇ e3]          (22.10b, corrected)

and the quantities the notes show conserved, with their drift over the run
(the largest change from t = 0 over every accepted integrator step and the
requested times):

* r² θ̇ = (x × v)·e3 — conserved when e3·M_O = 0 (22.11), e.g. a force
  F = F_r e_r (22.4) or any force central about a point of the e3 axis;
* ẋ3 — conserved when F3 = 0 (22.8b);
* H_O — conserved when M_O = 0, a central force about O (21.8).

θ is continuous in time (unwrapped through the accepted steps), starting in
(−π, π].  On the e3 axis (r = 0) e_r is not defined: θ is then carried over
from the nearest earlier state (0 at the start) and a warning says so.
"""

from __future__ import annotations

import numpy as np

SERIES = ["r", "theta", "x_cyl", "v_cyl", "a_cyl", "F_cyl", "H_O_cyl", "r2_theta_dot", "x3_dot"]


def angles(times, X, step_t, step_X) -> tuple[np.ndarray, bool]:
    """θ at the times, unwrapped through the accepted steps; and whether a
    state on the axis (r = 0) was met."""
    t_all = np.concatenate([np.asarray(step_t, float), np.asarray(times, float)])
    X_all = np.concatenate([step_X, X], axis=1)
    order = np.argsort(t_all, kind="stable")
    x1, x2 = X_all[0, order], X_all[1, order]
    on_axis = (x1 == 0) & (x2 == 0)
    th = np.arctan2(x2, x1)
    if on_axis.any():
        idx = np.where(~on_axis, np.arange(th.size), 0)
        np.maximum.accumulate(idx, out=idx)
        th = np.where(on_axis & ~on_axis[idx], 0.0, th[idx])
    th = np.unwrap(th)
    out = np.empty_like(th)
    out[order] = th
    return out[len(step_t):], bool(on_axis.any())


def components(th, vecs):
    """Components of vectors (3, n) on {e_r(θ), e_θ(θ), e3}."""
    c, s = np.cos(th), np.sin(th)
    return np.stack([c * vecs[0] + s * vecs[1], -s * vecs[0] + c * vecs[1], vecs[2]])


def _drifts(m, Xs, Vs):
    """max |Δ(r²θ̇)|, max |Δẋ3|, max |ΔH_O| from the first state."""
    from .equations import angular_momentum, distance

    h = Xs[0] * Vs[1] - Xs[1] * Vs[0]
    H = angular_momentum(m, Xs, Vs)
    return (float(np.max(np.abs(h - h[0]))), float(np.max(np.abs(Vs[2] - Vs[2, 0]))),
            float(np.max(distance(H - H[:, :1]))))


def add(res, p, traj, S, m) -> None:
    """Add the results on {e_r, e_θ, e3} at the requested times (``S``: the motion there)."""
    times = S["t"]
    X, V, A, H = S["x"], S["v"], S["a"], S["H_O"]
    step_t, step_Y = traj.steps()
    th, on_axis = angles(times, X, step_t, step_Y[0:3])
    cyl = {name: components(th, vec) for name, vec in
           (("x_cyl", X), ("v_cyl", V), ("a_cyl", A), ("F_cyl", m * A), ("H_O_cyl", H))}
    r = np.hypot(X[0], X[1])
    Xs = np.concatenate([np.asarray(p.x0, float)[:, None], step_Y[0:3], X], axis=1)
    Vs = np.concatenate([np.asarray(p.v0, float)[:, None], step_Y[3:6], V], axis=1)
    d_h, d_x3, d_H = _drifts(m, Xs, Vs)
    out = res.results
    out["r"] = [float(v) for v in r]
    out["theta"] = [float(v) + 0.0 for v in th]
    for name, comps in cyl.items():
        out[name] = (comps.T + 0.0).tolist()
    out["r2_theta_dot"] = [float(v) + 0.0 for v in X[0] * V[1] - X[1] * V[0]]
    out["x3_dot"] = [float(v) + 0.0 for v in V[2]]
    out["drift_r2_theta_dot"], out["drift_x3_dot"], out["drift_H_O"] = d_h, d_x3, d_H
    from dyncli.result import Series

    res.series.append(Series("t", [float(t) for t in times], SERIES, title="on the cylindrical basis {e_r, e_θ, e₃}"))
    for eq in ("22.6", "22.8", "22.10b", "22.11", "21.8"):
        if eq not in res.equations:
            res.equations.append(eq)
    if on_axis:
        res.warn("the particle is on the e3 axis (r = 0) at some time, where e_r and θ are not defined: "
                 "θ is carried over from the last state off the axis (0 at the start)")
