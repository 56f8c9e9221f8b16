"""Force-excited spring–mass–damper: F = F0 sin(ωt) on the mass (the
standard companion of the notes' base excitation, §17).

    m ẍ + c ẋ + k (x − L) = F0 sin(ωt),   w = x − L,
    ẅ + 2ζωₙ ẇ + ωₙ² w = (F0/m) sin(ωt).

Steady state: w_p = X sin(ωt + φ) with D = (1 − r²) + 2iζr (the denominator
of (17.30)), the magnification M = k X/|F0| = 1/|D| and φ = −arg D (the same
phase as G of (17.30b) for F0 > 0; + π for F0 < 0).  The force passed to
the wall, k w + c ẇ, has amplitude F_T = |F0| |1 + 2iζr|/|D| = |F0| g(r, ζ)
(the transmissibility equals g of (17.34b)).

The time response is the exact total response: the free solution with
w(0) = x0 − L, ẇ(0) = v0 (uniform in ζ) plus the zero-initial-condition
forced solution, both from :mod:`closed_form` (exact at resonance and
continuous through ζ = 1).
"""

from __future__ import annotations

import math

from dyncli.topics.vibration import closed_form as cf


def magnification(r, zeta: float):
    """1/|D| over ratios r ≥ 0, D = (1 − r²) + 2iζr (inf at undamped resonance):
    G/r² from the cancellation-free G of :func:`closed_form.amplification`
    (two roundings), and 1/|1 + 2iζr| where r² is below the double's
    resolution of 1 − r² (r < 1e-50)."""
    import numpy as np

    r = np.asarray(r, dtype=float)
    G = cf.amplification(r, zeta)[0]
    tiny = r < 1e-50
    rr = np.where(tiny, 1.0, r)
    with np.errstate(over="ignore"):
        return np.where(tiny, 1.0 / np.hypot(1.0, 2.0 * zeta * r), G / (rr * rr))


def magnification_at(r: float, G: float, zeta: float) -> float:
    """:func:`magnification` at one ratio from its G (plain floats, the same operations).

    >>> magnification_at(2.0, 4.0 / 3.0, 0.0)
    0.3333333333333333
    """
    if r < 1e-50:
        return 1.0 / abs(complex(1.0, 2.0 * zeta * r))       # the C library's hypot, as numpy's
    return G / (r * r)


def steady(F0: float, r: float, k: float, zeta: float):
    """(r, M, X, φ, TR, F_T) at the frequency ratio r: the steady-state
    quantities (X, F_T inf at undamped resonance)."""
    G, phi, g, _ = cf.amplification_at(r, zeta)
    M = magnification_at(r, G, zeta)
    X = abs(F0) / k * M
    if F0 < 0:                                   # −|F0| sin(ωt) = |F0| sin(ωt + π)
        phi = phi + math.pi if phi <= 0 else phi - math.pi
    return r, M, X, phi, g, abs(F0) * g


def response_at(t: float, *, m, omega_n, zeta, L, x0, v0, F0, Om) -> tuple[float, float, float]:
    """Exact total response (x, ẋ, w) at the time t, with w = x − L (plain floats)."""
    wh, vh = cf.free_at(t, x0 - L, v0, omega_n, zeta)
    wf, vf = cf.forced_at(t, F0 / m, Om, omega_n, zeta)
    w = wh + wf
    return w + L, vh + vf, w


def unbalance_force(m0: float, e: float, omega: float) -> float:
    """F0 = m0 e ω² [N]: the amplitude of the force a mass m0 [kg] turning at ω [rad/s] at the
    eccentricity e [m] puts on its machine (the centripetal force on m0, reversed), along the
    direction of motion F = m0 e ω² sin(ωt).

    >>> unbalance_force(0.5, 0.02, 100.0)
    100.0
    """
    return m0 * e * omega * omega


def forcing(force: tuple[float, float] | None, unbalance: tuple[float, float, float] | None) -> tuple[float, float] | None:
    """(F0, ω) of the harmonic force on the mass: a ``force`` (amplitude, ω), or a rotating
    ``unbalance`` (m0, e, ω: F0 = m0 e ω²); None without either.

    >>> forcing(None, (0.5, 0.02, 100.0))
    (100.0, 100.0)
    """
    if force is not None:
        return force
    if unbalance is not None:
        m0, e, omega = unbalance
        return unbalance_force(m0, e, omega), omega
    return None


def response(t, *, m, omega_n, zeta, L, x0, v0, F0, Om):
    """:func:`response_at` over an array of times (numpy; the plots): (x, ẋ)."""
    wh, vh = cf.free(t, x0 - L, v0, omega_n, zeta)
    wf, vf = cf.forced(t, F0 / m, Om, omega_n, zeta)
    return wh + wf + L, vh + vf


def report(F0, res, r, zeta, k) -> list[str]:
    """Fill the steady-state results of a force-excited problem (amplitude F0) at the ratio r
    (exactly 1 at exact resonance); returns the equations of the notes it uses."""
    r, M, X, phi, TR, FT = steady(F0, r, k, zeta)
    R = res.results

    def f(x):
        return x if math.isfinite(x) else None

    R.update(r=r, magnification=f(M), X=f(X), phi=phi, transmissibility=f(TR), F_T=f(FT))
    if R["X"] is None:
        res.warn("undamped resonance (ζ = 0, ω = ωₙ): X, magnification, transmissibility and F_T are unbounded "
                 "(null); the response grows linearly in time, w_p = −(F0 t/(2 m ωₙ)) cos(ωₙ t)")
    elif zeta == 0.0:
        res.warn("undamped (ζ = 0): the free vibration never decays, so the response is the steady state "
                 "plus a free oscillation at ωₙ for all time")
    return ["17.17", "17.30"]


def add_sweep(res, zeta: float) -> None:
    """``sweep_magnification`` over the sweep's ratios (null at undamped resonance)."""
    import numpy as np

    M = magnification(np.array(res.results["sweep_r"]), zeta)
    res.results["sweep_magnification"] = [float(x) if math.isfinite(x) else None for x in M]


def ode_rhs(F0: float, Om: float, m: float):
    """The force per unit mass F(t)/m for the numerical route."""
    return lambda tt: F0 / m * math.sin(Om * tt)
