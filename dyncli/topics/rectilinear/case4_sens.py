"""Case 4 next to a separatrix: how much the rounding of the energy moves the turning points and
the time spent near them (issue 28's oracle: a = −sin s from v1 = 2(1 − 1e-9) reached its turning
point 9e-8 s off with an error_estimate of 6e-14).

v² = v1² + 2∫a is known to ~8 ε of its scale, so a turning point s_T (v² = 0) moves by
δs = δv²/(2|a(s_T)|).  Where the motion turns just short of a barrier's top c (a(c) = 0 beyond s_T
with a' = λ² > 0: an unstable equilibrium), the time near s_T grows like (1/λ) ln(1/|s_T − c|)
with |s_T − c| ≈ |a(s_T)|/λ², so the time moves by λ δs/|a(s_T)|: the log of a separatrix.  Where
a' <= 0 (no barrier) the time does not depend on s_T to first order: 0.  A start at rest (s1 a
turning point itself) is known to its own rounding, 4 ε |s1|."""

from __future__ import annotations

import math

from dyncli.phase import LOSS
from dyncli.topics.rectilinear.constants import EPS


def turn_sensitivity(c4, s: float, ds: float) -> tuple[float, float]:
    """(δs, δt) of the turning point ``s`` known to ``ds``: δt = λ δs/|a(s)| where λ² = a'(s) > 0."""
    try:
        aT = abs(c4.a1(s))
        h = 1e-6 * max(abs(s), c4.scale_min)
        slope = (c4.a1(s + h) - c4.a1(s - h)) / (2 * h)
    except (ArithmeticError, ValueError):
        return ds, 0.0
    if not (aT > 0 and math.isfinite(aT) and math.isfinite(slope)) or slope <= 0:
        return ds, 0.0
    return ds, math.sqrt(slope) * ds / aT


def setup(c4) -> None:
    """c4.turns: {id(leg): (δs, δt)} for the legs that end at a turning point; c4.cycle_sens the
    time lost per period; c4.start_sens the start's when it is a turning point (v1 = 0)."""
    v2scale = max([c4.v1 * c4.v1] + [float(abs(sc["v2"]).max()) for sc in c4.scans.values() if len(sc["v2"])])
    dv2 = 8 * EPS * v2scale
    c4.turns = {}
    for leg in (c4.F, c4.B):
        if leg.end.kind == "turn" and leg.B != c4.s1:
            aT = abs(c4.a1(leg.B))
            c4.turns[id(leg)] = turn_sensitivity(c4, leg.B, dv2 / (2 * aT) if aT > 0 else 0.0)
    c4.start_sens = (0.0, 0.0)
    if c4.v1 == 0:
        c4.start_sens = turn_sensitivity(c4, c4.s1, 4 * EPS * abs(c4.s1))
    c4.cycle_sens = 2 * (sum(dt for _, dt in c4.turns.values()) + c4.start_sens[1]) if c4.periodic else 0.0
    # the period's own error: its legs' quadratures and its last digit; the reduction modulo the
    # period (math.fmod) is exact, so n periods shift the time by n times that
    c4.period_err = (2 * (_duration_err(c4.F) + _duration_err(c4.B)) + math.ulp(c4.period)) if c4.periodic else 0.0
    c4.cycle_sens += c4.period_err
    c4.sens_used = 0.0
    c4.long_used = (0.0, 0.0)        # (the time shift n·δP, n) of the latest reported time


def _duration_err(leg) -> float:
    """The error estimate of a leg's duration (its quadratures', summed)."""
    return float(leg.cerrs[-1][-1]) if leg.cerrs and len(leg.cerrs[-1]) else 0.0


def time_sens(c4, legs, tau: float, upto: int | None = None) -> tuple[float, float]:
    """(δt, δs) of the state at local time ``tau`` along ``legs`` (or at the end of entry ``upto``):
    2 δt per turning point passed (there and back), a share of δt on the way to the next one, the
    start's δt once, whole periods at cycle_sens each; δs the largest of the turning points met."""
    extra, ds = c4.start_sens[1], c4.start_sens[0]
    if c4.periodic and upto is None and c4.period > 0:
        n = math.floor(tau / c4.period)
        extra += n * c4.cycle_sens
        if n * c4.period_err > c4.long_used[0]:
            c4.long_used = (n * c4.period_err, n)
        tau -= n * c4.period
    for k, (leg, rev, _) in enumerate(legs):
        sd = c4.turns.get(id(leg)) if not rev else None
        if sd:
            ds = max(ds, sd[0])
        if upto is not None and k == upto:
            extra += sd[1] if sd else 0.0
            break
        if upto is None and tau <= leg.duration:
            if sd and leg.duration > 0:
                extra += sd[1] * min(1.0, tau / leg.duration)
            break
        tau -= leg.duration
        if sd:
            extra += 2 * sd[1]
    c4.sens_used = max(c4.sens_used, extra)
    return extra, ds


def warn(c4, ans, rtol: float) -> None:
    """A warning when the separatrix's sensitivity exceeds rtol of the answers' time scale, and
    one when whole periods have shifted a reported state by more than LOSS of its phase."""
    shift, n = c4.long_used
    phase = 2 * math.pi * shift / c4.period if c4.periodic and c4.period > 0 else 0.0
    if phase > LOSS:
        how = "no correct digits" if phase >= 1.0 else f"a phase error up to {phase:.2g} rad"
        ans.res.warn(f"the state at t ≈ {c4.p.t1 + n * c4.period:.3g} s ({n:.3g} periods after t1) has {how}: "
                     f"the period {c4.period:.9g} s is known to ±{c4.period_err:.2g} s (its quadratures and last digit), so n periods shift the time by "
                     f"±{shift:.2g} s (counted in error_estimate); ask for an earlier time")
    got = [x for x in ans.items if x is not None and x.get("reached")]
    tsc = max([abs(x["t"] - c4.p.t1) for x in got] + [0.0])
    if got and tsc > 0 and c4.sens_used / tsc > rtol:
        ans.res.warn(f"the motion passes close to an unstable equilibrium (a separatrix): its timing depends on the "
                     f"last digits of the energy v1² + 2∫a ds (about {c4.sens_used / tsc:.2g} of the times, > rtol "
                     f"{rtol:g}; counted in error_estimate); move the start further from the separatrix for a "
                     "better-determined answer")
