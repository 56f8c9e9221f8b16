"""Euler's equations (39.5) and the torque-free body (notes §39): the motion at the requested
times from plain inputs (:class:`Body`, built by :func:`dyncli.topics.euler.solver.plain`).

* Torque-free (no ``M``), method auto/closed-form: the exact solution
  (``free.py``): axisymmetric (39.14)-(39.22), asymmetric with Jacobi
  elliptic functions.  No scipy.
* With ``M(t)`` or an explicit ODE method: integration of (39.5)
  (:mod:`dyncli.topics.euler.integrated`).

The closed form at the requested times runs in plain floats (no numpy import, issue 19's cold
start); numpy and the integrator are imported by the ODE routes only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from dyncli import vec3
from dyncli.errors import InputError, NumericalError
from dyncli.result import FrameTable, Result, Series, SolveOptions
from dyncli.topics.euler import free, integrated

BASIS1 = ("e'₁", "e'₂", "e'₃")


@dataclass(frozen=True, slots=True)
class Body:
    """A rigid body on its principal axes: the principal moments ``I`` [kg·m²], ω'₀ [rad/s], the
    applied moment ``M`` (3 expressions in t [N·m], or None: torque-free), the times [s], and the
    route's controls (``method`` auto, closed-form, DOP853, RK45, Radau, LSODA or projected;
    rtol, atol, max_steps, estimate); ``coin``: the moments come from a coin (39.10)."""

    I: tuple[float, ...]          # (I1, I2, I3)
    omega0: tuple[float, ...]     # (ω'₁, ω'₂, ω'₃)
    M: tuple | None = None
    times: tuple[float, ...] = (0.0,)
    method: str = "auto"
    rtol: float = 1e-10
    atol: float = 1e-12
    max_steps: int | None = None
    estimate: bool = False
    coin: bool = False


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


def solve(pb: Body, options: SolveOptions | None = None, search_end: float | None = None) -> Result:
    """ω at ``pb.times``, |H̄|, T and the drifts; the torque-free constants or H_t, T_t; Table 39.1.
    ``search_end``: the end of the ``find`` search (None: no query), whose motion an ODE route
    leaves as one run's dense output (``res.extra["dense_motion"]``)."""
    I, w0, times = pb.I, pb.omega0, list(pb.times)
    res = Result({}, equations=["39.5"])
    method = pb.method
    if pb.coin:
        res.equations.append("39.10")
    H0, T0 = energy_momentum(I, w0)
    if not (math.isfinite(H0) and math.isfinite(T0)):
        raise InputError(f"omega0 with these moments gives |H̄| = {H0:.3g} kg·m²/s, T = {T0:.3g} J: beyond a "
                         "double (~1e308); rescale the units", "omega0")
    torque_free = pb.M is None or all(e.is_constant and e.value() == 0.0 for e in pb.M)
    exact = free.exact(I, w0) if torque_free else None
    r = res.results
    if pb.coin:
        r["I"] = list(I)
    if torque_free and method in ("auto", "closed-form"):
        assert exact is not None
        W = [exact.omega(t) for t in times]
        if not all(vec3.finite(w) for w in W):
            raise NumericalError("the exact torque-free solution is not representable in doubles at these "
                                 "magnitudes (its elliptic constants overflow): rescale the units")
        res.method = "closed-form"
        drift_H, drift_T = _drifts(I, W, H0, T0)
        if times and max(abs(t) for t in times) * abs(getattr(exact, "lam", 0.0)) > 1e8:   # (else none can)
            from dyncli.phase import warn_lost

            warn_lost(res, times, [exact.phase_error(t) for t in times], "ω")
    elif method == "closed-form":
        raise InputError("the closed form is for torque-free bodies; remove M or use auto/an ODE method", "accuracy.method")
    else:
        W, drift_H, drift_T = integrated.integrate(pb, times, res, exact, H0, T0)
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
    if search_end is not None and search_end > 0 and res.method.startswith("ode"):
        # the find search's motion: one run's steps, each cut at the exact extremes of the result searched
        res.extra["dense_motion"] = integrated.dense_motion(pb, search_end, torque_free, H0, T0)
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


def _moment(pb: Body, t):
    """The applied moment M(t) (body components, floats)."""
    return tuple(float(e(t=t)) for e in pb.M or ())


def _table_39_1(I, w, M, t):
    w = tuple(float(x) for x in w)
    H = (I[0] * w[0], I[1] * w[1], I[2] * w[2])
    wxH = vec3.cross(w, H)
    dH = vec3.sub(M, wxH)                          # I ω̇ from (39.5)
    rows = [("ω", list(w)), ("H̄", list(H)), ("δH̄/δt", list(dH)), ("ω×H̄", list(wxH)),
            ("Ḣ = M̄", list(vec3.add(dH, wxH)))]
    return FrameTable(f"Table 39.1 at t = {t:.6g} s", rows, basis=BASIS1)
