"""The pendulum's numeric core: the exact period and the motion by Jacobi's elliptic functions
(:mod:`.motion`), plain floats only (no numpy, no scipy); ``find`` on the same closed form."""

from __future__ import annotations

import math

from dyncli import motion_find as mf
from dyncli.errors import NumericalError
from dyncli.expr import constant, resolve_params
from dyncli.result import Result, Series, SolveOptions

from . import equations as eq
from .motion import Motion

#: the most periods whose count a double holds exactly (2^52): the phase's whole periods beyond
#: it cannot be told apart
MAX_PERIODS = 2.0 ** 52
#: pieces per period (or per 2π/ωₙ) of the find search, and the most it takes (beyond: warned)
PER_PERIOD, MAX_PIECES = 8, 20_000


def solve(p, options: SolveOptions | None = None) -> Result:
    mo = Motion(p.l, p.g, p.theta0, p.theta_dot0)
    res = Result({}, method="closed-form")
    R = res.results
    T0 = eq.small_angle_period(p.l, p.g)
    R.update(omega_n=mo.omega0, period_small=T0, regime=mo.regime, k=math.sqrt(mo.k2), period=mo.period,
             period_ratio=None if mo.period is None else mo.period / T0)
    if mo.regime == "swing":
        R["theta_max"] = mo.theta_max
    R["theta_slack"] = eq.slack_angle(mo.k2) if mo.regime != "rest" else None
    if p.m is not None:
        R["E"] = eq.energy(p.m, p.l, p.g, mo.k2)
    res.equations = ["20.5"] if p.m is not None else []
    _warn_regime(mo, res)
    params = resolve_params(p.params)
    const = lambda text: constant(text, params)      # noqa: E731
    t_end = mf.search_end(max([p.t_end or 0.0] + list(p.at)), p.find, const)
    if p.find and t_end == 0.0 and mo.period:         # nothing sets the end: one period (one turn)
        t_end = mo.period
    if mo.regime in ("swing", "rotating") and mo.period is not None and not t_end <= MAX_PERIODS * mo.period:
        raise NumericalError(f"t = {t_end:g} s is {t_end / mo.period:.3g} periods: the whole periods of the "
                             f"phase are counted exactly up to {MAX_PERIODS:.3g} of them only (ask at earlier times)")
    mo.long(t_end)

    def state(t: float) -> dict:
        th, thd = mo.state(t)
        out = {"theta": th, "theta_dot": thd, "theta_ddot": -(p.g / p.l) * math.sin(th)}
        if p.m is not None:
            out["tension"] = eq.tension(p.m, p.l, p.g, th, thd)
        out["distance"] = p.l * mo.turned(t)
        return out

    res.extra["sample"] = lambda ts: [mo.state(float(t)) for t in ts]      # for the plots
    if p.at:
        rows = [state(float(t)) for t in p.at]
        for name in rows[0]:
            R[name] = [row[name] for row in rows]
        res.series.append(Series("t", list(p.at), list(rows[0]), title="Motion θ(t) by Jacobi's elliptic functions"))
    if p.find:
        _find(p, mo, res, state, t_end, const)
    _warn_long(mo, res, list(p.at) + [e["t"] for e in R.get("find") or () if e.get("t") is not None])
    return res


def _warn_long(mo: Motion, res: Result, times: list) -> None:
    """One warning when a reported time's phase error exceeds :data:`dyncli.phase.LOSS`."""
    if mo.period and times and max(abs(float(t)) for t in times) > 1e6 * mo.period:   # (else none can)
        from dyncli.phase import warn_lost

        times = [float(t) for t in times]
        warn_lost(res, times, [mo.phase_error(t) for t in times], "θ")


def _warn_regime(mo: Motion, res: Result) -> None:
    if mo.regime == "separatrix":
        near = "" if mo.m1 == 0.0 else (
            f" (within the inputs' rounding: 1 − k² = {mo.m1:.3g}, below its uncertainty {mo.tol:.2g}; a release just "
            "inside swings with a period growing like ln(1/|1 − k²|), just outside it goes over the top)")
        if mo.top:
            res.warn("balanced at the top (θ₀ = ±π, θ̇₀ = 0): the unstable equilibrium; θ stays at θ₀ and there is "
                     "no period" + near)
        else:
            res.warn("on the separatrix (E = 2mgl, k = 1): θ = 2 atan(sinh(ωₙt + u₀)) creeps up to the top "
                     "as t → ∞; period and period_ratio are null" + near)
    elif mo.regime == "rotating":
        res.warn("k > 1: the pendulum goes over the top; period is the time of one turn, θ grows without bound "
                 "(a string would need to stay taut: see theta_slack)")


def _find(p, mo: Motion, res: Result, state, t_end: float, const) -> None:
    period = mo.period if mo.period else 2.0 * math.pi / mo.omega0
    h = period / PER_PERIOD
    n = min(max(math.ceil(t_end / h), 1), MAX_PIECES) if t_end > 0 else 1
    if t_end / h > MAX_PIECES:
        res.warn(f"find: the motion to t = {t_end:g} s spans more than {MAX_PIECES} eighths of a period; "
                 "turning points closer than the coarser grid may be missed (shorten the window with within)")
    rates = {"theta": "theta_dot", "theta_dot": "theta_ddot",
             "distance": lambda t, _: p.l * abs(mo.state(t)[1])}
    if p.m is not None:
        rates["tension"] = lambda t, _: eq.tension_rate(p.m, p.g, *mo.state(t))
    motion = mf.StateMotion(state, 0.0, t_end, [t_end * j / n for j in range(n + 1)], rates=rates)
    if mo.regime == "swing":
        motion.period = mo.period
    mf.attach(res, p.find, mf.answer_find(p.find, motion, const, res.warn))
