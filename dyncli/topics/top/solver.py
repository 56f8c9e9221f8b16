"""The heavy symmetric top (notes §38): the motion from (38.18), the reaction
(38.16), the nutation bounds from the energy and momentum integrals, Table 38.1.

This module is the adapter: it checks and normalises the input, forms the
invariants and the nutation bounds (:mod:`dyncli.topics.top.kinematics`), takes the
exact route (the elliptic solution, :mod:`dyncli.topics.top.exact_route`) or the ODE
route (:mod:`dyncli.topics.top.ode_route`: the reduced equations of
:mod:`dyncli.topics.top.reduced` away from the vertical, the quaternion form of
:mod:`dyncli.topics.top.integrator` next to it) and reports the results, warnings and Table
38.1 (:mod:`dyncli.topics.top.derived`).  Both routes are imported only when taken.
"""

from __future__ import annotations

import math

from dyncli.errors import InputError
from dyncli.result import FrameTable, Result, Series
from dyncli.topics.top.derived import BASIS, TABLE_FORMULAS, table_381
from dyncli.topics.top.kinematics import (S_TINY, TWO_PI, Controls, Top, body_omega, nutation_cubic, quat_from_euler,
                                          turning_points)

#: closest approach to a pole that gets a warning (rad)
POLE_WARN = 1e-3


def _listf(a):
    return [float(x) + 0.0 for x in a]


def solve(p, options=None) -> Result:
    A, C, m, L, g = p.I11, p.I33, p.m, p.L, p.g
    top = Top(m, L, A, C, g)
    res = Result(results={}, method="closed-form",
                 equations=["38.6", "38.11b", "38.15b", "38.16", "38.17c", "38.18"])
    _warn_moments(res, A, C, m, L)
    psi0, th0, phi0, th_dot0, psd0 = _initial_state(res, p)
    y0 = quat_from_euler(psi0, th0, phi0) + body_omega(th0, phi0, psd0, th_dot0, p.phi_dot)   # plain floats
    W3 = float(y0[6])
    E0, H0, Wfast, scales = _integrals(top, p, y0, th0, th_dot0, psd0)

    res.results.update(theta_min=None, theta_max=None)       # from the route taken (the order of the results)
    res.results["invariants"] = {"E": float(E0) + 0.0, "H_e3": float(H0) + 0.0, "omega3": W3 + 0.0}

    # --- the motion at the requested times: exact (auto) or integrated
    times = list(p.at)
    n = len(times)
    out = None
    a = p.accuracy
    acc = Controls(a.method, a.rtol, a.atol, a.max_steps, a.estimate)
    if acc.method in ("auto", "exact"):
        from dyncli.topics.top import exact_route

        out = exact_route.route(res, top, acc, psi0, th0, phi0, psd0, th_dot0, p.phi_dot, times)
    if out is not None:
        th_min, th_max = res.results["theta_min"], res.results["theta_max"]
    else:
        import numpy as np

        from dyncli.topics.top import ode_route

        th_min, th_max, Wp = _bounds(top, p, th0, th_dot0, psd0, W3)
        res.results.update(theta_min=th_min + 0.0, theta_max=th_max + 0.0)
        out = ode_route.route(res, top, acc, np.array(y0, dtype=float), psi0, phi0, times, Wfast, Wp, scales,
                              state=(psi0, th0, phi0, psd0, th_dot0, p.phi_dot), bounds=(th_min, th_max))
        res.extra["sample"] = lambda ts: _resample(p, ts)
        if p.find:                          # the search's motion: one run's steps, cut at exact extremes
            from dyncli.motion_find import find_end

            T = find_end(p)
            res.extra["dense_motion"] = ode_route.dense_motion(top, acc, T, Wfast, Wp, bounds=(th_min, th_max),
                                                               state=(psi0, th0, phi0, psd0, th_dot0, p.phi_dot),
                                                               y0=np.array(y0, dtype=float), scales=scales)
            if res.extra["dense_motion"] is None and T > 0:
                res.warn(f"find: the axis comes within {min(math.sin(th_min), math.sin(th_max)):.2g} of the vertical "
                         "(sinθ), where ψ and φ swing by ~π too fast for a step's interpolant: the queries are "
                         "searched on samples (8 pieces per turn, 4 points each), where a level crossed and crossed "
                         "back between two points is not seen")
    psi, theta, phi, psi_dot, th_dot, phi_dot, S, R, drift, ambiguous = out
    _report_motion(res, p, out)
    _warn_poles(res, top, th_min, th_max, W3, ambiguous, n)

    # --- Table 38.1 at the first requested time (t = 0 without times)
    if n:
        tab = table_381(top, float(theta[0]), float(psi_dot[0]), float(th_dot[0]), W3, float(S[0]))
        t_tab = float(p.at[0])
    else:
        tab = table_381(top, th0, psd0, th_dot0, W3, psd0 * math.sin(th0))
        t_tab = 0.0
    res.views.append(FrameTable(f"Table 38.1 at t = {t_tab:g} s (components on e'')", tab, basis=BASIS,
                                note="Ḣ_O = δH_O/δt + Ω×H_O = M_O = mgL sinθ e''₁ (38.17c)"))
    if options is not None and getattr(options, "symbolic", False):
        res.views.append(FrameTable("Table 38.1 (formulas)", TABLE_FORMULAS, basis=BASIS))
    return res


def _warn_moments(res, A, C, m, L):
    """Warnings for moments of inertia no rigid body has (solved as given)."""
    if A < m * L * L * (1 - 1e-12):
        res.warn(f"I11 = {A:.6g} kg·m² < mL² = {m * L * L:.6g} kg·m²: no rigid body has a transverse "
                 "moment about O smaller than mL² (31.7); solved as given")
    if C > 2.0 * (A - m * L * L) * (1 + 1e-12) and A >= m * L * L:
        res.warn(f"I33 = {C:.6g} kg·m² > 2(I11 − mL²) = {2 * (A - m * L * L):.6g} kg·m²: the central moments "
                 "violate the triangle inequality (no rigid body has them); solved as given")


def _initial_state(res, p):
    """(ψ0, θ0, φ0, θ̇0, ψ̇0) with θ0 in [0, π]: θ outside it is the same orientation as
    (ψ + π, −θ, φ + π) with −θ̇ (a warning says so)."""
    psi0, phi0, th_dot0, psd0 = p.psi, p.phi, p.theta_dot, p.psi_dot
    th0 = math.remainder(p.theta, TWO_PI)
    if th0 < 0:
        th0, psi0, phi0, th_dot0 = -th0, psi0 + math.pi, phi0 + math.pi, -th_dot0
    if th0 != p.theta:
        res.warn(f"theta = {p.theta:.6g} rad is outside [0, π]: the same orientation is "
                 f"(ψ, θ, φ) = ({psi0:.6g}, {th0:.6g}, {phi0:.6g}) rad (θ̇ = {th_dot0 + 0.0:.6g} rad/s), used from t = 0")
    return psi0, th0, phi0, th_dot0, psd0


def _integrals(top, p, y0, th0, th_dot0, psd0):
    """E, H·e3, the fastest rate and the scales (E, H, ω) of the ODE route, in plain floats;
    InputError when they, or the nutation cubic, overflow a double."""
    A, C = top.A, top.C
    W3 = float(y0[6])
    w1, w2 = y0[4], y0[5]
    E0, H0, _ = top.invariants(y0[:4], y0[4:])
    Wn = math.hypot(*y0[4:])
    Wg = math.sqrt(4.0 * top.mgL / A)
    Es = 0.5 * (A * (w1 * w1 + w2 * w2) + C * W3 * W3) + top.mgL
    Hs = math.hypot(A * math.hypot(w1, w2), C * W3) + A * Wg
    # fastest rates of the motion in the spin-free frame (the spin ω3 is taken out exactly):
    # nutation ≈ I33 ω3/I11 (the turning of ω⊥ on p) and the pendulum rate √(4mgL/I11)
    Wfast = abs(C * W3 / A) + Wg
    coef, _ = nutation_cubic(A, C, top.mgL, th0, th_dot0, psd0, W3)
    if not all(math.isfinite(x) for x in (E0, H0, Wn, Wg, Es, Hs, Wfast, *coef)):
        raise InputError(_overflow_message(A, C, W3, th_dot0, psd0, p.phi_dot), _fastest_rate(th_dot0, psd0, p.phi_dot))
    Ws = Wn + Wg
    return E0, H0, Wfast, (Es, Hs, Ws if Ws > 0 else 1.0)


def _bounds(top, p, th0, th_dot0, psd0, W3):
    """θ_min, θ_max from the nutation cubic's roots (numpy) and the bound of |ω⊥| (the ODE route)."""
    A, C = top.A, top.C
    th_min, th_max, wperp2 = turning_points(A, C, top.mgL, th0, th_dot0, psd0, W3)
    if not all(math.isfinite(x) for x in (th_min, th_max, wperp2)):
        raise InputError(_overflow_message(A, C, W3, th_dot0, psd0, p.phi_dot), _fastest_rate(th_dot0, psd0, p.phi_dot))
    return th_min, th_max, math.sqrt(max(wperp2, 0.0))


def _report_motion(res, p, out):
    """The arrays of one route as results, with the motion's series."""
    psi, theta, phi, psi_dot, th_dot, phi_dot, S, R, drift, ambiguous = out
    res.results.update(
        psi=_listf(psi), theta=_listf(theta), phi=_listf(phi),
        psi_dot=[float(x) + 0.0 if math.isfinite(x) else None for x in psi_dot],
        theta_dot=_listf(th_dot),
        phi_dot=[float(x) + 0.0 if math.isfinite(x) else None for x in phi_dot],
        R=[_listf(r) for r in R],
        drift=float(drift),
    )
    if len(p.at) and not all(math.isfinite(x) for x in psi_dot):
        res.warn("psi_dot and phi_dot are null where sinθ = 0: at the vertical only ψ̇ + φ̇ (θ = 0) "
                 "or ψ̇ − φ̇ (θ = π) is defined")
    res.series.append(Series("t", list(p.at), ["psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot", "R"],
                             title="Motion of the top (3-1-3 Euler angles, R on e'')"))


def _warn_poles(res, top, th_min, th_max, W3, ambiguous, n):
    """Warnings about the poles θ = 0, π (sleeping top, near passages, ambiguous angles)."""
    A, C = top.A, top.C
    sleeping = th_max == 0.0 or th_min == math.pi
    if sleeping:
        up = th_max == 0.0
        res.warn(f"a sleeping top (θ = {'0' if up else 'π'} throughout): ψ and φ are individually undefined; "
                 f"ψ is held at its initial value and φ carries {'ψ + φ' if up else 'φ − ψ'}")
        if up and top.mgL > 0 and (C * W3) ** 2 < 4.0 * A * top.mgL:
            res.warn(f"this sleeping top is unstable: I33²ω3² = {(C * W3) ** 2:.6g} < 4 I11 mgL = "
                     f"{4 * A * top.mgL:.6g} (kg·m²/s)²; the slightest disturbance makes it fall "
                     "(the computed motion stays upright only because the input is exactly vertical)")
    elif th_min < POLE_WARN:
        res.warn(_pole_warning("θ = 0", th_min, "ψ + φ"))
    if not sleeping and math.pi - th_max < POLE_WARN:
        res.warn(_pole_warning("θ = π", math.pi - th_max, "ψ − φ"))
    if ambiguous:
        res.warn(f"the axis passes through the vertical (sinθ < {S_TINY:g}) at t ≈ {ambiguous[0]:.6g} s"
                 + (f" and {len(ambiguous) - 1} more time(s)" if len(ambiguous) > 1 else "")
                 + ": there ψ and φ are individually undefined; they are kept continuous (ψ may jump "
                 "by about ±π there, ψ ± φ does not)")
    if not n:
        res.warn("no times in 'at': only theta_min, theta_max (from the energy and momentum integrals) "
                 "are reported")


def _resample(p, ts):
    """(ψ, θ) of the integrated motion at other times (for plots): the same run on those times."""
    import numpy as np

    R = solve(p.model_copy(update={"at": [float(t) for t in ts], "find": []})).results
    return np.asarray(R["psi"], dtype=float), np.asarray(R["theta"], dtype=float)


def _fastest_rate(th_dot, psi_dot, phi_dot) -> str:
    rates_ = {"theta_dot": abs(th_dot), "psi_dot": abs(psi_dot), "phi_dot": abs(phi_dot)}
    return max(rates_, key=lambda k: rates_[k])


def _overflow_message(A, C, W3, th_dot, psi_dot, phi_dot) -> str:
    return (f"the energy, angular momentum or nutation equation of this top overflows a double (values beyond "
            f"~1e308): θ̇ = {th_dot:.3g}, ψ̇ = {psi_dot:.3g}, φ̇ = {phi_dot:.3g} rad/s, ω3 = {W3:.3g} rad/s, "
            f"I33/I11 = {C / A:.3g}")


def _pole_warning(where, dist, combo):
    near = "reaches" if dist == 0 else f"comes within {dist:.3g} rad of"
    return (f"the axis {near} the vertical ({where}): near there ψ and φ are "
            f"individually ill-conditioned (only {combo} is well defined; ψ swings by about π quickly) — "
            "they are reported continuously, with an absolute accuracy of roughly 1e-16/sinθ rad")
