"""The gyroscope of notes §37 — numeric core.

Ω = q e₂ + θ̇ e''₃, ω = Ω + p e''₁ (37.5-37.6), H̄ (37.9), M̄ = Ḣ (37.10,
Table 37.1) and the free rotation about e''₃ (37.11) giving (37.12):

    Ī₂ θ̈ + (Ī₂ − Ī₁) q² sin θ cos θ − Ī₁ p q cos θ = 0,

with the first integral (37.13)

    ½ Ī₂ θ̇² + ½ (Ī₂ − Ī₁) q² sin² θ − Ī₁ p q sin θ = C.

θ(t) is exact by default (accuracy.method auto or exact: Jacobi elliptic functions of t,
dyncli.topics.gyroscope.elliptic; q = 0 has the closed form θ₀ + θ̇₀ t); the
integrators (DOP853, ...) keep the ODE route as an independent cross-check.
θ_min, θ_max are the turning points of (37.13): zeros of C − V(θ) on either
side of θ₀, found from the roots of a quadratic in sin θ — not from samples.

The exact and closed-form routes work in plain floats at the requested times (no numpy
import, issue 19's cold start); numpy and the integrator are imported by the ODE route only.
"""

from __future__ import annotations

import math

from dyncli.result import FrameTable, Result, Series, SolveOptions
from dyncli.topics.gyroscope.elliptic import quadratic_roots

BASIS2 = ("e''₁", "e''₂", "e''₃")


def theta_ddot(I1, I2, p, q, th, fm=math):
    """(37.12) solved for θ̈ (floats; ``fm``: numpy for arrays of θ)."""
    return ((I1 - I2) * q * q * fm.sin(th) + I1 * p * q) * fm.cos(th) / I2


def first_integral(I1, I2, p, q, th, thd):
    """C of (37.13) (floats)."""
    s = math.sin(th)
    return 0.5 * I2 * thd * thd + 0.5 * (I2 - I1) * q * q * s * s - I1 * p * q * s


def table_rows(I1, I2, p, q, th, thd, thdd):
    """Rows of Table 37.1 on e''."""
    s, c = math.sin(th), math.cos(th)
    Om = [q * s, q * c, thd]
    H = [I1 * (q * s + p), I2 * q * c, I2 * thd]
    dH = [I1 * q * thd * c, -I2 * q * thd * s, I2 * thdd]
    OmH = [Om[1] * H[2] - Om[2] * H[1], Om[2] * H[0] - Om[0] * H[2], Om[0] * H[1] - Om[1] * H[0]]
    Hd = [dH[i] + OmH[i] for i in range(3)]
    return [("Ω", Om), ("ω", [Om[0] + p, Om[1], Om[2]]), ("H̄", H), ("δH̄/δt", dH), ("Ω×H̄", OmH), ("Ḣ = M̄", Hd)]


def moment(I1, I2, p, q, th, thd, thdd, fm=math):
    """M̄ = Ḣ (Table 37.1) at one state, [M1, M2, M3]; the e''₃ component vanishes by (37.11)
    (``fm``: numpy for arrays of states, each component an array)."""
    s, c = fm.sin(th), fm.cos(th)
    m1 = I1 * q * thd * c
    m2 = -2.0 * I2 * q * thd * s + I1 * (q * s + p) * thd
    m3 = I2 * thdd + (I2 - I1) * q * q * s * c - I1 * p * q * c
    return [m1, m2, m3]


def _balanced(I1, I2, p, q, th0) -> bool:
    """θ̈(θ₀) = 0 of (37.12) to within the inputs' uncertainty (dyncli.exact:
    4 round-offs each): cos θ₀ = 0 within θ₀'s own (`theta0: pi/2` gives
    cos = 6.1e-17), or (I1 − I2)q² sin θ₀ + I1 p q = 0 within 16 round-offs of
    its terms' sizes."""
    from dyncli.exact import INPUT_ROUNDING as r

    s, c = math.sin(th0), math.cos(th0)
    if abs(c) <= r * abs(th0):
        return True
    f = (I1 - I2) * q * q * s + I1 * p * q
    return abs(f) <= 4 * r * ((I1 + I2) * q * q * abs(s) + I1 * abs(p * q))


def turning_points(I1, I2, p, q, th0, thd0):
    """(θ_min, θ_max) of the motion starting at (θ₀, θ̇₀) from (37.13), or None
    when θ circulates (no turning point)."""
    C = float(first_integral(I1, I2, p, q, th0, thd0))
    # zeros of G(θ) = C − V(θ):  ½(I2−I1)q² s² − I1 p q s − C = 0,  s = sin θ
    A, B = 0.5 * (I2 - I1) * q * q, -I1 * p * q
    scale = 0.5 * abs(I2 - I1) * q * q + abs(I1 * p * q)
    at_rest = 0.5 * I2 * thd0 * thd0 <= 1e-12 * scale or thd0 == 0.0
    if at_rest:
        # sin θ₀ is an exact root: deflate (Vieta) instead of re-finding it
        s0 = math.sin(th0)
        roots = [] if A == 0 else [-B / A - s0]
        base = [th0, math.pi - th0]
    else:
        roots = quadratic_roots(A, B, -C)
        base = []
    svals = [min(1.0, max(-1.0, s)) for s in roots if -1.0 - 1e-12 <= s <= 1.0 + 1e-12]
    for s in svals:
        a = math.asin(s)
        base += [a, math.pi - a]

    def first_zero(direction):
        best = None
        for b in base:
            # candidates b + 2πn at signed distance in (0, 2π] along direction
            d = (b - th0) * direction
            d = d - 2 * math.pi * math.floor(d / (2 * math.pi))
            if d <= 0.0:
                d += 2 * math.pi
            if best is None or d < best:
                best = d
        return None if best is None else th0 + direction * best

    if at_rest:
        acc = float(theta_ddot(I1, I2, p, q, th0))
        if acc == 0.0 or _balanced(I1, I2, p, q, th0):
            return th0, th0, C
        other = first_zero(1.0 if acc > 0 else -1.0)
        if other is None:  # pragma: no cover - th0 itself is a zero, so a zero recurs within 2π
            return None, None, C
        return min(th0, other), max(th0, other), C
    up, down = first_zero(1.0), first_zero(-1.0)
    if up is None or down is None:
        return None, None, C
    return down, up, C


def _ode_route(pb, times, res):
    """θ, θ̇ integrated (DOP853 by default; lists of floats), the drift of (37.13) and the
    method's estimate."""
    import numpy as np

    from dyncli import ode, runner

    times = np.asarray(times, dtype=float)
    I1, I2, p, q = pb.I1, pb.I2, pb.p, pb.q
    th0, thd0 = pb.theta0, pb.theta_dot0
    m = runner.scipy_method(pb.accuracy.method)
    rtol, atol = pb.accuracy.rtol, pb.accuracy.atol

    def fun(t, y):
        return (float(y[1]), theta_ddot(I1, I2, p, q, float(y[0])))   # plain floats: the runner wraps them once

    C0 = float(first_integral(I1, I2, p, q, th0, thd0))
    scale = 0.5 * I2 * thd0 * thd0 + 0.5 * abs(I2 - I1) * q * q + abs(I1 * p * q)
    Cmax = [0.0]

    def on_step(t_old, t_new, dense, direction):
        if dense is not None:
            y = dense(t_new)
            Cmax[0] = max(Cmax[0], abs(float(first_integral(I1, I2, p, q, y[0], y[1])) - C0))

    Y, nsteps = ode.integrate(fun, [th0, thd0], times, method=m, rtol=rtol, atol=atol, on_step=on_step,
                              max_steps=pb.accuracy.max_steps)
    drift = Cmax[0] / max(scale, 1e-300)
    res.method = f"ode:{m}"
    if pb.accuracy.estimate:
        # the runner's check solve; θ relative to π (its range), θ̇ to its largest value over the run
        check = ode.check_solve(res, lambda r2, a2: ode.integrate(fun, [th0, thd0], times, method=m, rtol=r2,
                                                                  atol=a2, max_steps=pb.accuracy.max_steps)[0],
                                rtol, atol)
        if check is not None:
            Y2 = check[0]
            res.error_estimate = ode.relative_difference([(Y[:, 0], Y2[:, 0]), (Y[:, 1], Y2[:, 1])], [math.pi, 0.0])
    else:
        # over many periods the error is the phase's: the drift of (37.13) shifts the frequency, and the
        # phase error grows with the time run (~ drift × 2π × periods), past rtol × steps (issue 28)
        phase = drift * 2.0 * math.pi * _periods(pb, float(np.max(np.abs(times))) if len(times) else 0.0)
        ode.nominal_estimate(res, rtol, drift, phase, steps=nsteps)
        if phase > rtol * max(nsteps, 1) and phase >= drift:
            res.extra["error_estimate_note"] = (
                "nominal: the drift of (37.13) times the phase run, 2π × periods (a drifting first integral "
                "shifts the frequency; over many periods that phase error dominates rtol times the steps)")
    measured = res.error_estimate if pb.accuracy.estimate else drift
    runner.warn_unmet(res, rtol, measured, promise=runner.ODE_PROMISE,
                      what="the check solve's difference" if pb.accuracy.estimate else "the drift of (37.13)")
    return Y[:, 0].tolist(), Y[:, 1].tolist(), drift


def dense_motion(pb, T):
    """The ODE route's motion from 0 to T as one run's dense output for the ``find`` search
    (:func:`dyncli.ode.dense_run`, the route's method and tolerances): (the steps' ends,
    ``states(ts)``, θ, θ̇ and M̄ at many times as lists, smooth functions of the step's
    polynomial between two ends, and θ̇'s rate θ̈ of (37.12)), so that every step is cut at the
    exact extremes of the result searched (:func:`dyncli.motion_find.exact_breaks`) and an
    extreme of θ̇ polished as a root of θ̈."""
    import numpy as np

    from dyncli import ode, runner

    I1, I2, p, q = pb.I1, pb.I2, pb.p, pb.q
    th0, thd0 = pb.theta0, pb.theta_dot0

    def fun(t, y):
        return (float(y[1]), theta_ddot(I1, I2, p, q, float(y[0])))

    ends, sol = ode.dense_run(fun, [th0, thd0], T, method=runner.scipy_method(pb.accuracy.method),
                              rtol=pb.accuracy.rtol, atol=pb.accuracy.atol, max_steps=pb.accuracy.max_steps)

    def states(ts) -> dict:
        ts = np.asarray(ts, dtype=float).reshape(-1)
        th, thd = np.asarray(sol(ts), dtype=float).reshape(2, -1)
        zero = ts == 0.0                        # the initial state as given
        th[zero], thd[zero] = th0, thd0
        M = moment(I1, I2, p, q, th, thd, theta_ddot(I1, I2, p, q, th, np), np)
        return {"theta": (th + 0.0).tolist(), "theta_dot": (thd + 0.0).tolist(),
                "M": (np.stack([np.broadcast_to(np.asarray(m, dtype=float), th.shape) for m in M], axis=1)
                      + 0.0).tolist()}

    def theta_dot_rate(t: float, rest: str):
        """θ̈ of (37.12) at the interpolated θ."""
        return None if rest else theta_ddot(I1, I2, p, q, float(sol(float(t))[0]))
    return ends, states, {"theta_dot": theta_dot_rate}


def _periods(pb, T):
    """Periods of θ(t) in [0, T] (revolutions when θ circulates), from the elliptic solution's period
    (plain floats); 0 where that is not representable or θ is steady."""
    from dyncli.topics.gyroscope.elliptic import GyroTheta

    g = GyroTheta(pb.I1, pb.I2, pb.p, pb.q, pb.theta0, pb.theta_dot0)
    period = g.period if g.finite else math.inf
    return T / period if math.isfinite(period) and period > 0 else 0.0


def _exact_route(pb, times, res, steady):
    """θ, θ̇ in closed form (dyncli.topics.gyroscope.elliptic), or None where the parameter
    is beyond doubles (auto then integrates)."""
    from dyncli.topics.gyroscope.exact_route import ExactRun

    run = ExactRun(pb.I1, pb.I2, pb.p, pb.q, pb.theta0, pb.theta_dot0, times, steady=steady, rtol=pb.accuracy.rtol)
    if not run.finite:
        msg = "the elliptic solution is not representable in doubles here (next to the separatrix)"
        if pb.accuracy.method == "exact":
            from dyncli.errors import NumericalError

            raise NumericalError(msg + ": use accuracy.method DOP853")
        res.warn(msg + "; integrated with DOP853 instead")
        return None
    res.method = "exact"
    res.error_estimate = run.error_estimate
    from dyncli.phase import LOSS

    lost = max(run.phase_errors, default=0.0) > LOSS
    if lost:
        from dyncli.phase import warn_lost

        warn_lost(res, [float(t) for t in times], run.phase_errors, "θ")
    if not lost and times and max(abs(t) for t in times) > 0 and run.error_estimate > pb.accuracy.rtol:
        from dyncli import runner       # (numpy: only when there is something to say)

        runner.warn_unmet(res, pb.accuracy.rtol, run.error_estimate,
                          what=f"error_estimate (the elliptic solution's round-off over λt = {run.lam_T:.3g} rad)")
    res.extra["sample"] = run.sample
    return run.theta, run.theta_dot, run.drift


def solve(pb, options: SolveOptions | None = None) -> Result:
    I1, I2, p, q = pb.I1, pb.I2, pb.p, pb.q
    th0, thd0 = pb.theta0, pb.theta_dot0
    times = [float(t) for t in pb.at]
    res = Result({}, equations=["37.5", "37.6", "37.9", "37.12", "37.13", "37.15", "Table 37.1"])
    method = pb.accuracy.method
    tmin, tmax, C = turning_points(I1, I2, p, q, th0, thd0)
    if not math.isfinite(C):
        from dyncli.errors import InputError

        raise InputError(f"the constant C of (37.13) is {C:.3g} J for these θ̇0, p, q and moments: beyond a double "
                         "(~1e308); rescale the units", "theta_dot0")
    out = None
    if method in ("auto", "closed-form") and q == 0.0:
        th = [th0 + thd0 * t for t in times]
        thd = [thd0 for _ in times]
        res.method = "closed-form"
        drift = 0.0
        res.extra["sample"] = lambda ts: [th0 + thd0 * float(t) for t in ts]
    elif method == "closed-form":
        from dyncli.errors import InputError

        raise InputError("the closed form exists only for q = 0; use auto, exact or an ODE method", "accuracy.method")
    else:
        if method in ("auto", "exact"):
            out = _exact_route(pb, times, res, steady=tmin is not None and tmin == tmax)
        if out is None:
            th, thd, drift = _ode_route(pb, times, res)
            res.extra["sample"] = lambda ts: _ode_route(pb, ts, Result({}))[0]
            if pb.find:                 # the search's motion: one run's steps, cut at exact extremes
                from dyncli.motion_find import find_end

                T = find_end(pb)
                res.extra["dense_motion"] = dense_motion(pb, T) if T > 0 else None
        else:
            th, thd, drift = out
    if not all(math.isfinite(x) for x in th + thd):
        from dyncli.errors import NumericalError

        raise NumericalError("θ(t) is beyond a double at the requested times (|θ̇0 t| ~ 1e308): rescale the units")
    thdd = [theta_ddot(I1, I2, p, q, x) for x in th]
    r = res.results
    r["theta"] = [float(x) for x in th]
    r["theta_dot"] = [float(x) for x in thd]
    r["M"] = [moment(I1, I2, p, q, *state) for state in zip(th, thd, thdd)]
    r["theta_min"] = tmin
    r["theta_max"] = tmax
    r["C"] = C
    r["drift"] = float(drift)
    if tmin is None:
        res.warn("θ circulates: C exceeds the largest value of V(θ) in (37.13), so there is no turning point; "
                 "theta_min and theta_max are null")
    if times:
        res.series.append(Series("t", times, ["theta", "theta_dot", "M"]))
        res.views.append(FrameTable(f"Table 37.1 at t = {times[0]:.6g} s",
                                    table_rows(I1, I2, p, q, th[0], thd[0], thdd[0]), basis=BASIS2))
    return res
