"""The exact route of ``particle``: an inverse-square central force alone is the Kepler problem
(notes §19 (19.18), §21), solved without integrating (:mod:`~dyncli.topics.particle.kepler`).

The route is taken when every force term is ``inverse-square`` about one centre (their strengths
add) and ``accuracy.method`` is ``auto`` or ``exact``; any other term, or ``method: ode`` or a
scipy integrator, keeps the ODE.  The state at any time comes from Kepler's equation; the
reported results are those of the ODE route at the same times (through the same reporting code,
on a trajectory whose one phase is the conic) plus ``orbit``.  ``res.extra["state"]`` is
``state(t) -> {result: value}`` at one time (for ``find``), ``res.extra["sample"]`` the arrays at
many times (plots).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import InputError, NumericalError
from dyncli.phase import LOSS, warn_lost
from dyncli.result import Result, Series
from dyncli.topics.particle.kepler import EPS, Orbit, e_minus_sin, kepler_H, sinh_minus
from dyncli.topics.particle.trajectory import OdePhase, Trajectory

#: the error_estimate note of the exact route
NOTE = ("round-off of the Kepler solution: 8 ε (1 + X) + 2 X (1.5 κ + 0.5) δ w, X = t_max v_p/r_p: the rounding "
        "of the time, and δ of mu = g R0² through the mean motion (κ = (1 + e)/(1 − e), w = min(1, t/period) "
        "revolutions), carried through the fastest rate of the orbit, relative to each quantity's scale")


def kepler_estimate(orb: Orbit, t_max: float, mu_err: float = 0.0) -> float:
    """8 ε (1 + X) + 2 X (1.5 κ + 0.5) δ w with X = t v_p/r_p: the rounding of the time carried
    through the orbit's fastest rate, and that of mu = g R0² (δ, relative, :func:`mu_rounding`)
    through the mean motion, δn/n = (1.5 κ + 0.5) δ with κ = (1 + e)/(1 − e) (1/a = 2/r − v²/mu
    amplifies it), weighted by the revolutions run, w = min(1, t/period) (before a revolution the
    motion next to a parabola hardly depends on a).  At e = 0.97 over five revolutions (g = 9.81,
    R0 = 6371 km: δ = 0.23 ε) the true error is 4.4e-11 of scale, this 1.0e-10 (without δ: 1.5e-11)."""
    X = t_max * (orb.h / orb.r_p) / orb.r_p
    kappa = (1.0 + orb.e) / max(1.0 - orb.e, EPS) if orb.period else 0.0   # (e rounded to 1: fuzz 1308217)
    w = min(1.0, t_max / orb.period) if orb.period else 0.0
    return 8 * EPS * (1.0 + X) + 2.0 * X * (1.5 * kappa + 0.5) * mu_err * w


def mu_rounding(p, mu: float) -> float:
    """|mu − Σ g R0²| / Σ g R0², the latter exact in rationals of the given doubles."""
    from fractions import Fraction as Fr

    exact = sum(Fr(float(p.g if f.g is None else f.g)) * Fr(float(f.R0)) ** 2 for f in p.forces)
    return float(abs(Fr(mu) - exact) / exact) if exact else 0.0


def kepler_field(p):
    """(centre, mu = g R0² summed) when every force term is inverse-square about one centre, else None."""
    if not p.forces or any(f.kind != "inverse-square" for f in p.forces):
        return None
    centres = {tuple(map(float, f.center)) for f in p.forces}
    if len(centres) != 1:
        return None
    mu = sum(float(p.g if f.g is None else f.g) * float(f.R0) * float(f.R0) for f in p.forces)
    return np.array(next(iter(centres))), mu


def conic(p, field=None):
    """The Orbit of the initial state when the forces are an inverse-square field alone (radial
    or not), else None."""
    field = field or kepler_field(p)
    if field is None or not math.isfinite(field[1]) or not field[1] > 0:
        return None                     # (an overflowing field: the Forces refuse it; one below the doubles: μ = 0)
    c, mu = field
    try:
        return Orbit(mu, np.asarray(p.x0, float) - c, np.asarray(p.v0, float))
    except (ZeroDivisionError, OverflowError, ValueError):     # elements beyond the doubles: the ODE route
        return None


def choose(p, res_warn):
    """The Orbit when the exact route solves ``p``, else None (the ODE route).  ``accuracy.method:
    exact`` on another problem is refused (exit 2); a radial orbit (h = 0) goes to the ODE with a
    warning under ``auto`` and is refused under ``exact``."""
    method = p.accuracy.method
    if method not in ("auto", "exact"):
        return None
    field = kepler_field(p)
    if field is None:
        if method == "exact":
            raise InputError("accuracy.method exact solves an inverse-square central force alone (Kepler's "
                             "equation); these forces need the ODE: use auto or ode", "accuracy.method")
        return None
    orb = conic(p, field)
    if orb is None:
        return None
    if orb.radial:
        _radial(p, orb, res_warn)
        return None
    return orb


def _radial(p, orb: Orbit, res_warn) -> None:
    """A radial orbit (h = 0): no conic plane.  Falling into the centre before t_end fails (exit 1,
    as the integration would: the force is infinite there) with the time it happens; else the ODE route with a warning
    (``accuracy.method: exact`` refuses it)."""
    from dyncli.topics.particle.kepler import radial_fall_time

    R = orb.R0
    try:
        t_c = radial_fall_time(orb.mu, R, float(orb.r0 @ orb.v0) / R)
    except (ZeroDivisionError, OverflowError, ValueError):     # beyond the doubles: the ODE route says when
        t_c = None
    msg = "the orbit is radial (x0 − center parallel to v0, angular momentum 0)"
    if t_c is not None and t_c <= float(p.t_end):
        raise NumericalError(f"{msg}: the particle falls into the centre of the inverse-square field at "
                             f"t = {t_c:.6g} s, before t_end, where the force is infinite (a collision): take "
                             f"t_end (and every time of at) below {t_c:.6g} s")
    if p.accuracy.method == "exact":
        raise InputError(msg + ": it has no conic plane and the exact route does not solve it; use "
                         "accuracy.method ode", "accuracy.method")
    fall = f"; it reaches the centre at t = {t_c:.6g} s" if t_c is not None else "; it escapes"
    res_warn.append(msg + fall + "; integrated by the ODE route")


def solve_exact(p, F, orb: Orbit) -> Result:
    """The Kepler route's Result: the reported quantities at ``at`` from the conic, ``orbit``,
    the collision and surface warnings, a round-off error estimate."""
    from . import report

    c = np.asarray(next(iter(p.forces)).center, float)
    times = [float(t) for t in p.at]
    traj = _trajectory(orb, c, F, float(p.t_end), times)
    S = report.at_times(traj, F, times, steps=True)
    resid, scale = report.energy_residual(p, F, S)
    res = Result(report.reported(S, resid), method="exact", equations=_equations(),
                 series=[Series("t", times, list(report.REPORTED) + ["distance"])])
    res.scales["energy_residual"] = scale
    report.report_terms(res, p, F, traj, S)
    res.results["orbit"] = orbit_results(orb)
    _warn_surface(res, p, orb)
    t_max = max(times) if times else 0.0
    res.error_estimate = kepler_estimate(orb, t_max, mu_rounding(p, orb.mu)) if times else 0.0
    if res.error_estimate > LOSS:           # the mean anomaly n·t run for many revolutions
        mu_err = mu_rounding(p, orb.mu)
        warn_lost(res, times, [kepler_estimate(orb, t, mu_err) for t in times], "the state")
    res.extra["error_estimate_note"] = NOTE
    res.extra["energy_scale"] = scale
    res.extra["nfev"] = 0
    res.extra["sample"] = lambda ts: report.at_times(traj, F, ts)
    res.extra["state"] = lambda t: state_at(traj, F, t)
    res.extra["orbit"] = orb
    res.extra["trajectory"] = traj
    return res


#: pieces of the search per turn of the eccentric anomaly (find, distance), and the most pieces
PIECES_PER_TURN, PIECES_CAP = 64, 200_000


def breaks(orb: Orbit, t_end: float) -> list[float]:
    """Times over [0, t_end] at equal steps of the eccentric (hyperbolic) anomaly, so that the
    pieces are short where the body is fast (at perigee) — the ``find`` search and the distance's
    Gauss–Legendre pieces; a parabola: equal steps of time (its speed varies slowly but for a
    close pass, where the steps are many)."""
    if t_end <= 0 or orb.radial:
        return [0.0, max(t_end, 0.0)]
    if orb.kind == "elliptic":
        assert orb.period is not None          # an ellipse has one
        turns = t_end / orb.period
        n = int(min(max(PIECES_PER_TURN * math.ceil(turns + 1), 8), PIECES_CAP))
        dE = 2 * math.pi / PIECES_PER_TURN
        out = []
        for k in range(n + 1):
            E = orb.anom0 + k * dE
            t = (orb.ome * E + orb.e * e_minus_sin(E) - orb.M0) / orb.n
            if t >= t_end:
                break
            out.append(t)
        return sorted(set(out) | {0.0, t_end})
    if orb.kind == "hyperbolic":
        H1 = float(kepler_H(np.array([orb.M0 + orb.n * t_end]), orb.e, orb.emo)[0])
        n = 256
        out = [(orb.emo * math.sinh(H) + sinh_minus(H) - orb.M0) / orb.n
               for H in (orb.anom0 + (H1 - orb.anom0) * k / n for k in range(n + 1))]
        return sorted({min(max(t, 0.0), t_end) for t in out} | {0.0, t_end})
    return [t_end * k / 1024 for k in range(1025)]


def state_at(traj, F, t: float) -> dict:
    """The reported results at one time t (single values): x, v, a, T, V, E, W_nc, H_O."""
    from . import report

    S = report.at_times(traj, F, [float(t)])
    return {k: (S[k][:, 0].tolist() if S[k].ndim == 2 else float(S[k][0])) for k in report.REPORTED}


def _trajectory(orb: Orbit, c, F, t_end: float, times) -> Trajectory:
    """A trajectory of one phase whose 'dense output' is the conic: the reporting code of the ODE
    route reads it as it reads an integrated run (its steps: the requested times)."""

    y0 = np.concatenate([orb.r0 + c, orb.v0, [0.0]])

    def sol(t):
        scalar = np.ndim(t) == 0
        t = np.atleast_1d(np.asarray(t, float))
        X, V = orb.state(t)
        Y = np.concatenate([X + c[:, None], V, np.zeros((1, X.shape[1]))])
        Y[:, t == 0.0] = y0[:, None]            # the state at t = 0 is the input, exactly
        return Y[:, 0] if scalar else Y

    ts = np.array(sorted(set(times) | {0.0, t_end}))
    phase = OdePhase(0.0, t_end, sol, F.make_rhs(np.zeros(3)), ts, sol(ts))
    return Trajectory([phase], [], 0, dense=True)


def orbit_results(orb: Orbit) -> dict:
    """``orbit``: e, a (null on a parabola, < 0 on a hyperbola), r_p, r_a and period (null when
    open), the speeds at the apsides (h/r), the circular and escape speeds at the start."""
    r_a, period = (orb.r_a, orb.period) if orb.kind == "elliptic" else (None, None)    # (an ellipse has both)
    v_c = math.sqrt(orb.mu / orb.R0)
    return {"e": float(orb.e), "a": float(orb.a) if math.isfinite(orb.a) else None, "r_p": float(orb.r_p),
            "r_a": float(r_a) if r_a is not None else None, "period": float(period) if period is not None else None,
            "v_p": orb.h / orb.r_p, "v_a": orb.h / r_a if r_a is not None else None,
            "v_circular": v_c, "v_escape": math.sqrt(2.0) * v_c}


def _warn_surface(res, p, orb: Orbit) -> None:
    """A path below R0 (the radius of the attracting body) before t_end: its least distance (the
    perigee when it is passed, else an end of the run) and the time it meets R = R0 (a collision;
    past it the motion is that of a point mass through the body)."""
    R0 = max(float(f.R0) for f in p.forces)
    t_end = float(p.t_end)
    if orb.r_p >= R0 * (1 - 1e-9):
        return
    tp = orb.perigee_time()
    if tp is not None and tp <= t_end:
        Rmin = orb.r_p
    else:
        Rmin = min(orb.R0, float(orb.anomalies(np.array([t_end]))[0][0]))
    if Rmin >= R0 * (1 - 1e-9):
        return
    t_hit = orb.time_at_radius(R0, t_end) if orb.R0 >= R0 else 0.0
    when = f"; it meets R = R0 at t = {t_hit:.6g} s: a collision with the body" if t_hit is not None else ""
    res.warn(f"the path passes inside R0 = {R0:g} m of the inverse-square centre (R_min = {Rmin:.6g} m): "
             f"below the surface of the attracting body{when}")


def _equations() -> list[str]:
    return ["16.7", "18.6", "19.18", "19.20b", "20.5", "21.3", "21.8"]
