"""Euler's equations (39.5) integrated (notes §39): with ``M(t)`` or an explicit ODE method,
DOP853 (or RK45, Radau, LSODA) through the runner (:mod:`dyncli.ode`); method ``projected``
(torque-free only) projects ω back onto the intersection of the energy ellipsoid and the
momentum sphere (|H| = H₀, T = T₀) after every step.  With ``M(t)`` the work ∫M·ω dt and
∫2H·M dt are integrated alongside ω so that ``drift`` measures the error of the energy and
momentum balances (T − T₀ = ∫M·ω dt, |H|² − H₀² = ∫2H·M dt)."""

from __future__ import annotations

import math


def make_projector(I, H0, T0):
    """Project ω onto {|Iω| = H0, ω·Iω = 2 T0} (up to three Newton steps, min-norm), in plain
    floats: it runs after every accepted step."""
    I1, I2, I3 = (float(v) for v in I)
    Q1, Q2, Q3 = I1 * I1, I2 * I2, I3 * I3
    HH, TT = H0 * H0, 2.0 * T0

    def project(y):
        w1, w2, w3 = (float(v) for v in y[:3])
        for _ in range(3):
            g1 = Q1 * w1 * w1 + Q2 * w2 * w2 + Q3 * w3 * w3 - HH
            g2 = I1 * w1 * w1 + I2 * w2 * w2 + I3 * w3 * w3 - TT
            a1, a2, a3 = 2.0 * Q1 * w1, 2.0 * Q2 * w2, 2.0 * Q3 * w3      # the gradients of the two constraints
            b1, b2, b3 = 2.0 * I1 * w1, 2.0 * I2 * w2, 2.0 * I3 * w3
            G00, G01, G11 = a1 * a1 + a2 * a2 + a3 * a3, a1 * b1 + a2 * b2 + a3 * b3, b1 * b1 + b2 * b2 + b3 * b3
            det = G00 * G11 - G01 * G01
            if abs(det) > 1e-12 * G00 * G11:
                l1, l2 = (G11 * g1 - G01 * g2) / det, (G00 * g2 - G01 * g1) / det
                w1, w2, w3 = w1 - a1 * l1 - b1 * l2, w2 - a2 * l1 - b2 * l2, w3 - a3 * l1 - b3 * l2
            else:  # ω along a principal axis: both constraints fix |ω| only
                f = math.sqrt(TT / (I1 * w1 * w1 + I2 * w2 * w2 + I3 * w3 * w3))
                w1, w2, w3 = w1 * f, w2 * f, w3 * f
                break
        out = y.astype(float)
        out[:3] = (w1, w2, w3)
        return out

    return project


def integrate(pb, times, res, exact, H0, T0):
    """ω at ``times`` integrated (rows of floats), and the drifts of |H̄| and T (``pb``: a
    :class:`dyncli.topics.euler.motion.Body`)."""
    import numpy as np

    from dyncli import ode, runner

    I = pb.I
    w0 = np.array(pb.omega0, dtype=float)
    times = np.asarray(times, dtype=float)
    method = pb.method
    m = runner.scipy_method(method)
    rtol, atol = pb.rtol, pb.atol
    forced = pb.M is not None and exact is None
    res.method = "ode:projected-DOP853" if method == "projected" else f"ode:{m}"
    res.equations += ["39.4"]
    fun, y0 = _rhs(I, pb.M if forced else None, w0)
    project = make_projector(I, H0, T0) if method == "projected" else None
    drift = _Drift(I, H0, T0, forced)

    steps = [0]

    def run(fn, tol, on_step=None):
        Y, steps[0] = ode.integrate(fn, y0, times, method=m, rtol=tol[0], atol=tol[1], project=project,
                                    on_step=on_step, max_steps=pb.max_steps)
        return Y

    Y = run(fun, (rtol, atol), drift.on_step)
    nsteps = steps[0]
    W = Y[:, :3]
    if exact is None:        # the sampler for plots: the run again with its steps' interpolants, when first asked
        res.extra["sample"] = _LazySampler(lambda on_step: run(fun, (rtol, atol), on_step))
    scale = max(float(np.max(np.linalg.norm(W, axis=1))) if len(W) else 0.0, float(np.linalg.norm(w0)), 1e-300)
    if exact is not None and not pb.estimate:
        res.warn("error_estimate is the actual error against the exact torque-free solution")
        res.error_estimate = float(np.max(np.abs(exact.omega(times) - W)) / scale) if len(times) else 0.0
    else:       # the runner's policy: a check solve (and its one fallback) with accuracy.estimate, else nominal
        runner.estimate_error(
            res, W, estimate=pb.estimate, rtol=rtol, atol=atol, rerun=lambda r, a: run(fun, (r, a)),
            difference=lambda W1, Y2: float(np.max(np.abs(Y2[:, :3] - W1)) / scale) if len(times) else 0.0,
            drifts=(drift.worst_H, drift.worst_T), steps=nsteps)
    return W.tolist(), drift.worst_H, drift.worst_T


def dense_motion(pb, T, torque_free, H0, T0):
    """ω (and, with an applied moment, |H̄| and T) from 0 to T as one run's dense output for the
    ``find`` search (:func:`dyncli.ode.dense_run`, the route's method, tolerances and projection):
    (the steps' ends, ``states(ts)``, the results at many times as lists, smooth functions of the
    step's polynomial between two ends, and ``{"omega": rate}``, ω̇ from Euler's equations at the
    interpolated state), so that every step is cut at the exact extremes of the result searched
    (:func:`dyncli.motion_find.exact_breaks`) and an extreme of ω polished as a root of ω̇."""
    import numpy as np

    from dyncli import ode, runner

    I = np.asarray(pb.I, dtype=float)
    w0 = np.array(pb.omega0, dtype=float)
    fun, y0 = _rhs(pb.I, None if torque_free else pb.M, w0)
    project = make_projector(pb.I, H0, T0) if pb.method == "projected" else None
    ends, sol = ode.dense_run(fun, y0, T, method=runner.scipy_method(pb.method), rtol=pb.rtol, atol=pb.atol,
                              project=project, max_steps=pb.max_steps)

    def states(ts) -> dict:
        ts = np.asarray(ts, dtype=float).reshape(-1)
        W = np.asarray(sol(ts), dtype=float).reshape(len(y0), -1)[:3].T.copy()
        W[ts == 0.0] = w0                       # the initial state as given
        out = {"omega": (W + 0.0).tolist()}
        if not torque_free:                     # (the operations of motion.energy_momentum, on arrays)
            h = W * I
            out["H_t"] = np.sqrt(h[:, 0] * h[:, 0] + h[:, 1] * h[:, 1] + h[:, 2] * h[:, 2]).tolist()
            out["T_t"] = (0.5 * (h[:, 0] * W[:, 0] + h[:, 1] * W[:, 1] + h[:, 2] * W[:, 2])).tolist()
        return out

    def omega_rate(t: float, rest: str):
        """ω̇ of component ``rest`` from Euler's equations at the interpolated state (None: not a component)."""
        if rest not in ("0", "1", "2"):
            return None
        y = np.asarray(sol(float(t)), dtype=float)
        return float(fun(float(t), y)[int(rest)])
    return ends, states, {"omega": omega_rate}


class _Drift:
    """The largest relative drift of |H| and T over the accepted steps (plain floats: it runs
    once per step).  With an applied moment the drift is that of the balances
    T − T₀ = ∫M·ω dt and |H|² − H₀² = ∫2H·M dt (state entries 3 and 4)."""

    def __init__(self, I, H0, T0, forced):
        self.I = tuple(float(v) for v in I)
        self.H0, self.T0, self.forced = H0, T0, forced
        self.Hscale, self.Tscale = H0, T0
        self.worst_H = self.worst_T = 0.0

    def on_step(self, t_old, t_new, dense, direction):
        if dense is None:
            return
        y = dense(t_new).tolist()
        I1, I2, I3 = self.I
        w1, w2, w3 = y[0], y[1], y[2]
        h1, h2, h3 = I1 * w1, I2 * w2, I3 * w3
        Hn = math.sqrt(h1 * h1 + h2 * h2 + h3 * h3)
        Tn = 0.5 * (h1 * w1 + h2 * w2 + h3 * w3)
        self.Tscale = max(self.Tscale, Tn)
        self.Hscale = max(self.Hscale, Hn)
        H0, T0 = self.H0, self.T0
        if self.forced:
            self.worst_H = max(self.worst_H, abs(Hn * Hn - H0 * H0 - y[4]) / (2 * self.Hscale ** 2))
            self.worst_T = max(self.worst_T, abs(Tn - T0 - y[3]) / self.Tscale)
        else:
            self.worst_H = max(self.worst_H, abs(Hn - H0) / self.Hscale)
            self.worst_T = max(self.worst_T, abs(Tn - T0) / self.Tscale)


class _LazySampler:
    """ω at given times from the interpolants of the accepted steps of ``rerun(on_step)``, which
    runs only when the sampler is first called (plots), so a solve without plots keeps no steps."""

    def __init__(self, rerun):
        self.rerun, self.steps = rerun, None

    def __call__(self, ts):
        if self.steps is None:
            steps = []

            def on_step(t_old, t_new, dense, direction):
                if dense is not None and t_new != t_old:
                    dense(0.5 * (t_old + t_new))     # build the step's interpolant now, while the solver is on it
                    steps.append((min(t_old, t_new), max(t_old, t_new), dense))

            self.rerun(on_step)
            self.steps = steps
        return _sample_steps(self.steps, ts)


def _sample_steps(steps, ts):
    """ω at ``ts`` (N x 3) from the interpolants of the accepted steps; NaN
    outside the integrated span."""
    import numpy as np

    ts = np.asarray(ts, dtype=float)
    out = np.full((ts.size, 3), np.nan)
    if not steps:
        return out
    steps = sorted(steps, key=lambda s: s[0])
    lo = np.array([s[0] for s in steps])
    hi = np.array([s[1] for s in steps])
    k = np.clip(np.searchsorted(lo, ts, side="right") - 1, 0, len(steps) - 1)
    inside = (lo[k] <= ts) & (ts <= hi[k])
    for j in np.unique(k[inside]):
        sel = np.flatnonzero(inside & (k == j))
        out[sel] = np.asarray(steps[j][2](ts[sel]))[:3].T
    return out


def _rhs(I, M, w0):
    """(f, y0) of Euler's equations (39.5), ω̇ = (M − ω × Iω)/I, in plain float arithmetic
    (the same operations, in the same order, as :func:`euler_rates`); with an applied moment M
    the state carries the work of M and the change of |H|², y = [ω, W_M, |H|² − |H₀|²], to check
    the two balances."""
    import numpy as np

    I1, I2, I3 = (float(v) for v in I)
    j1, j2, j3 = 1.0 / I1, 1.0 / I2, 1.0 / I3
    if M is None:
        def fun(t, y):
            w1, w2, w3 = y.tolist()
            h1, h2, h3 = I1 * w1, I2 * w2, I3 * w3
            return [-(w2 * h3 - w3 * h2) * j1, -(w3 * h1 - w1 * h3) * j2, -(w1 * h2 - w2 * h1) * j3]
        return fun, w0.copy()

    m1, m2, m3 = (_moment_fn(e) for e in M)

    def fun(t, y):
        w1, w2, w3, _, _ = y.tolist()
        t = float(t)                               # (scipy's may be numpy's float: plain-float rules)
        M1, M2, M3 = m1(t), m2(t), m3(t)
        h1, h2, h3 = I1 * w1, I2 * w2, I3 * w3
        return [(M1 - (w2 * h3 - w3 * h2)) * j1, (M2 - (w3 * h1 - w1 * h3)) * j2, (M3 - (w1 * h2 - w2 * h1)) * j3,
                M1 * w1 + M2 * w2 + M3 * w3, 2.0 * (h1 * M1 + h2 * M2 + h3 * M3)]
    return fun, np.concatenate([w0, [0.0, 0.0]])


def _moment_fn(e):
    """A component of M as a plain-float function of t (:mod:`dyncli.expr.floateval`: no numpy
    per call); a constant component as its value."""
    from dyncli.expr.floateval import float_fn

    if e.is_constant:
        v = float(e.value())
        return lambda t: v
    return float_fn(e, "t")
