"""Euler's equations (39.5) and the torque-free body (notes §39) — numeric core.

* Torque-free (no ``M``), method auto/closed-form: the exact solution
  (``free.py``): axisymmetric (39.14)-(39.22), asymmetric with Jacobi
  elliptic functions.  No scipy.
* With ``M(t)`` or an explicit ODE method: integration of (39.5) with DOP853
  (or RK45, Radau, LSODA); method ``projected`` (torque-free only) projects ω
  back onto the intersection of the energy ellipsoid and the momentum sphere
  (|H| = H₀, T = T₀) after every step.
* With ``M(t)`` the work ∫M·ω dt and ∫2H·M dt are integrated alongside ω so
  that ``drift`` measures the error of the energy and momentum balances
  (T − T₀ = ∫M·ω dt, |H|² − H₀² = ∫2H·M dt).

The closed form at the requested times runs in plain floats (no numpy import, issue 19's cold
start); numpy and the integrator are imported by the ODE routes only.
"""

from __future__ import annotations

import math

from dyncli import vec3
from dyncli.errors import InputError, NumericalError
from dyncli.result import FrameTable, Result, Series, SolveOptions
from dyncli.topics.euler import free

BASIS1 = ("e'₁", "e'₂", "e'₃")


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


def energy_momentum(I, w) -> tuple[float, float]:
    """(|H̄|, T) of one ω in plain floats (the operations of
    :func:`dyncli.topics.euler.equations.energy_momentum`, in its order)."""
    h1, h2, h3 = I[0] * w[0], I[1] * w[1], I[2] * w[2]
    return (math.sqrt(h1 * h1 + h2 * h2 + h3 * h3),
            0.5 * (h1 * w[0] + h2 * w[1] + h3 * w[2]))


def _drifts(I, W, H0, T0) -> tuple[float, float]:
    """The largest relative change of |H̄| and T over the rows of W."""
    HT = [energy_momentum(I, w) for w in W]
    drift_H = max(abs(h - H0) for h, _ in HT) / H0 if H0 > 0 and HT else 0.0
    drift_T = max(abs(t - T0) for _, t in HT) / T0 if T0 > 0 and HT else 0.0
    return drift_H, drift_T


def solve(pb, options: SolveOptions | None = None) -> Result:
    I = tuple(float(v) for v in pb.moments())
    w0 = tuple(float(v) for v in pb.omega0)
    times = [float(t) for t in pb.at]
    res = Result({}, equations=["39.5"])
    method = pb.accuracy.method
    if pb.coin is not None:
        res.equations.append("39.10")
    H0, T0 = energy_momentum(I, w0)
    if not (math.isfinite(H0) and math.isfinite(T0)):
        raise InputError(f"omega0 with these moments gives |H̄| = {H0:.3g} kg·m²/s, T = {T0:.3g} J: beyond a "
                         "double (~1e308); rescale the units", "omega0")
    torque_free = pb.M is None or all(e.is_constant and e.value() == 0.0 for e in pb.M)
    exact = free.exact(I, w0) if torque_free else None
    r = res.results
    if pb.coin is not None:
        r["I"] = list(I)
    if torque_free and method in ("auto", "closed-form"):
        assert exact is not None
        W = [exact.omega(t) for t in times]
        if not all(vec3.finite(w) for w in W):
            raise NumericalError("the exact torque-free solution is not representable in doubles at these "
                                 "magnitudes (its elliptic constants overflow): rescale the units")
        res.method = "closed-form"
        drift_H, drift_T = _drifts(I, W, H0, T0)
    elif method == "closed-form":
        raise InputError("the closed form is for torque-free bodies; remove M or use auto/an ODE method", "accuracy.method")
    else:
        W, drift_H, drift_T = _integrate(pb, I, w0, times, res, exact, H0, T0)
    if exact is not None:
        res.extra["sample"] = exact.omega         # the exact torque-free ω(t), for plots
    r["omega"] = [list(w) for w in W]
    r["H"] = H0
    r["T"] = T0
    if not torque_free:
        HT = [energy_momentum(I, w) for w in W]
        r["H_t"] = [h for h, _ in HT]
        r["T_t"] = [t for _, t in HT]
        res.warn("with an applied moment H and T are the initial values; H_t and T_t give them at the requested times")
    else:
        _torque_free_results(res, exact)
    r["drift"] = max(drift_H, drift_T)
    r["drift_detail"] = {"H": drift_H, "T": drift_T}
    if times:
        res.series.append(Series("t", times, ["omega"] + ([] if torque_free else ["H_t", "T_t"])))
        M = (0.0, 0.0, 0.0) if torque_free else _moment(pb, times[0])
        res.views.append(_table_39_1(I, W[0], M, times[0]))
    return res


def _torque_free_results(res, exact):
    """λ, ψ̇, θ of (39.15)-(39.21) (axisymmetric) or m and the period (asymmetric)."""
    r = res.results
    if isinstance(exact, free.Axisymmetric):
        res.equations += ["39.12", "39.15", "39.17", "39.18", "39.20", "39.21", "39.22"]
        r["lambda"] = exact.lam
        r["psi_dot"] = exact.psi_dot
        r["theta"] = exact.theta
        r["symmetry_axis"] = exact.k + 1
        if exact.w[2] == 0.0:
            res.warn("ω'₀₃ = 0: α in (39.20) is taken as +1 (θ = π/2, the body tumbles end over end)")
    else:
        r["m"] = exact.m
        per = exact.period
        r["period"] = per
        if per is None:
            res.warn("period is null: ω is constant or the motion lies on the separatrix (infinite period)")


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


def _moment(pb, t):
    """The applied moment M(t) (body components, floats)."""
    return tuple(float(e(t=t)) for e in pb.M)


def _table_39_1(I, w, M, t):
    w = tuple(float(x) for x in w)
    H = (I[0] * w[0], I[1] * w[1], I[2] * w[2])
    wxH = vec3.cross(w, H)
    dH = vec3.sub(M, wxH)                          # I ω̇ from (39.5)
    rows = [("ω", list(w)), ("H̄", list(H)), ("δH̄/δt", list(dH)), ("ω×H̄", list(wxH)),
            ("Ḣ = M̄", list(vec3.add(dH, wxH)))]
    return FrameTable(f"Table 39.1 at t = {t:.6g} s", rows, basis=BASIS1)


def _integrate(pb, I, w0, times, res, exact, H0, T0):
    """ω at ``times`` integrated (rows of floats), and the drifts of |H̄| and T."""
    import numpy as np

    from dyncli import ode, runner

    w0 = np.array(w0, dtype=float)
    times = np.asarray(times, dtype=float)
    method = pb.accuracy.method
    m = runner.scipy_method(method)
    rtol, atol = pb.accuracy.rtol, pb.accuracy.atol
    forced = pb.M is not None and exact is None
    res.method = "ode:projected-DOP853" if method == "projected" else f"ode:{m}"
    res.equations += ["39.4"]
    fun, y0 = _rhs(I, pb.M if forced else None, w0)
    project = make_projector(I, H0, T0) if method == "projected" else None
    drift = _Drift(I, H0, T0, forced)

    steps = [0]

    def run(fn, tol, on_step=None):
        Y, steps[0] = ode.integrate(fn, y0, times, method=m, rtol=tol[0], atol=tol[1], project=project,
                                    on_step=on_step, max_steps=pb.accuracy.max_steps)
        return Y

    Y = run(fun, (rtol, atol), drift.on_step)
    nsteps = steps[0]
    W = Y[:, :3]
    if exact is None:        # the sampler for plots: the run again with its steps' interpolants, when first asked
        res.extra["sample"] = _LazySampler(lambda on_step: run(fun, (rtol, atol), on_step))
    scale = max(float(np.max(np.linalg.norm(W, axis=1))) if len(W) else 0.0, float(np.linalg.norm(w0)), 1e-300)
    if exact is not None and not pb.accuracy.estimate:
        res.warn("error_estimate is the actual error against the exact torque-free solution")
        res.error_estimate = float(np.max(np.abs(exact.omega(times) - W)) / scale) if len(times) else 0.0
    else:       # the runner's policy: a check solve (and its one fallback) with accuracy.estimate, else nominal
        runner.estimate_error(
            res, W, estimate=pb.accuracy.estimate, rtol=rtol, atol=atol, rerun=lambda r, a: run(fun, (r, a)),
            difference=lambda W1, Y2: float(np.max(np.abs(Y2[:, :3] - W1)) / scale) if len(times) else 0.0,
            drifts=(drift.worst_H, drift.worst_T), steps=nsteps)
    return W.tolist(), drift.worst_H, drift.worst_T


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

    m1, m2, m3 = (_scalar(e) for e in M)

    def fun(t, y):
        w1, w2, w3 = y[:3].tolist()
        env = {"t": float(t)}
        with np.errstate(all="ignore"):
            M1, M2, M3 = float(m1(env)), float(m2(env)), float(m3(env))
        h1, h2, h3 = I1 * w1, I2 * w2, I3 * w3
        return [(M1 - (w2 * h3 - w3 * h2)) * j1, (M2 - (w3 * h1 - w1 * h3)) * j2, (M3 - (w1 * h2 - w2 * h1)) * j3,
                M1 * w1 + M2 * w2 + M3 * w3, 2.0 * (h1 * M1 + h2 * M2 + h3 * M3)]
    return fun, np.concatenate([w0, [0.0, 0.0]])


def _scalar(e):
    """The expression's compiled function of an environment dict (scalar in, scalar out; the
    caller turns numpy's warnings off), or a call of ``e`` when it has none."""
    try:
        e(t=0.0)                                   # compiles e._fn
    except Exception:  # noqa: BLE001 - evaluated again, and reported, in the integration
        pass
    fn = getattr(e, "_fn", None)
    return fn if callable(fn) else (lambda env: e(**env))
