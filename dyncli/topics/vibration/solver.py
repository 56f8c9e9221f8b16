"""Vibrations of a spring–mass–damper, free and base-excited (notes §17) —
numeric core (plain floats at the times of a problem; numpy for sweeps, scipy only on the DOP853
route).

Notation of the notes: w = x − s − L (17.16b), ωₙ² = k/m (17.5b),
c = 2mζωₙ (17.20), ω* the damped frequency (17.22b/17.24b), base motion
s = s0 sin(ωt) (17.26), r = ω/ωₙ.  The time response is the exact total
response of (17.15a) from :mod:`closed_form`, uniform in ζ (continuous
through ζ = 1, no cancellation for large ζ or near resonance).
"""

from __future__ import annotations

import math

from dyncli import exact
from dyncli.errors import InputError, NumericalError
from dyncli.result import Result, Series, SolveOptions, Table
from dyncli.topics.vibration import closed_form as cf
from dyncli.topics.vibration import equations as eq
from dyncli.topics.vibration import forced


#: DOP853's stability bound: a step h needs |h·λ| below ~6, so the run takes at least (fastest
#: rate) × (time span) / DOP853_STABILITY steps whatever rtol is (a stiff run is refused a priori)
DOP853_STABILITY = 6.0


def _f(x) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def forcing(p) -> tuple[float, float] | None:
    """(F0, ω) of the model's ``force`` or rotating ``unbalance`` (:func:`forced.forcing`)."""
    u = getattr(p, "unbalance", None)
    return forced.forcing(None if p.force is None else (p.force.amplitude, p.force.omega),
                          None if u is None else (u.m0, u.e, u.omega))


def setup(p, fo):
    """The plain inputs of ``find`` and ``distance`` (:class:`find.Setup`)."""
    from dyncli.topics.vibration import find

    s0, Om = (p.base.amplitude, p.base.omega) if p.base is not None else (0.0, 0.0)
    return find.Setup(p.m, p.L, p.L if p.x0 is None else p.x0, p.v0, s0, Om, fo, tuple(p.at), tuple(p.find),
                      p.t_end, tuple(p.params.items()))


def solve(p, options: SolveOptions | None = None) -> Result:
    m, k = p.m, p.k
    omega_n = eq.natural_frequency(k, m)                 # (17.5b)
    zeta, c, regime = damping(p, omega_n)
    L = p.L
    x0 = L if p.x0 is None else p.x0
    v0 = p.v0

    omega_d, _, _ = cf.roots(omega_n, zeta)

    res = Result({}, method="closed-form")
    R = res.results
    R.update(omega_n=omega_n, zeta=zeta, c=c, regime=regime, omega_d=omega_d)
    eqs = ["17.5b", "17.16b", "17.20"]
    eqs += {"undamped": ["17.10", "17.12"], "underdamped": ["17.22"], "critical": ["17.23"],
            "overdamped": ["17.24"]}[regime]

    s0 = Om = 0.0
    fo = forcing(p)                 # a force on the mass, or a rotating unbalance's (F0 = m0 e ω²)
    if fo is not None:
        eqs += forced.report(fo[0], res, _ratio(fo[1], k, m, omega_n), zeta, k)
        if p.unbalance is not None:
            R["F0"] = fo[0]
    elif p.base is None:
        A, phi, why = cf.amplitude_phase(x0 - L, v0, omega_n, zeta, omega_d, regime)
        if why is not None:
            res.warn(why)
        R.update(A=A, phi=phi)
        if phi is not None and regime in ("undamped", "underdamped"):
            res.notes.append(PHASE_NOTE)
    else:
        s0, Om = p.base.amplitude, p.base.omega
        r = _ratio(Om, k, m, omega_n)
        eqs += ["17.26", "17.27", "17.30", "17.31", "17.33", "17.34"]
        G, phi, g, Phi = cf.amplification_at(r, zeta)
        R.update(r=r, G=_f(G), phi=phi, g=_f(g), Phi=Phi)
        if R["G"] is None:
            res.warn("undamped resonance (ζ = 0, ω = ωₙ): G and g are unbounded (null); the response grows "
                     "linearly in time, w_p = −(s0 ωₙ t/2) cos(ωₙ t); phi and Phi are the phase of that "
                     "secular term (−π/2, the limit ζ → 0)")
        elif zeta == 0.0:
            res.warn("undamped (ζ = 0): the free vibration never decays, so the response is the steady "
                     "state (G, g) plus a free oscillation at ωₙ for all time")
    res.equations = eqs

    if p.at:
        _time_response(p, res, omega_n, zeta, L, x0, v0, s0, Om)
    if p.at or p.find:
        from dyncli.topics.vibration import find

        find.report(setup(p, fo), res, omega_n, zeta)
    if p.sweep is not None:
        _sweep(p.sweep, zeta, res, p.zeta is not None)
        if fo is not None:
            forced.add_sweep(res, zeta)
    return res


# ---------------------------------------------------------------------------

def _ratio(Om: float, k: float, m: float, omega_n: float) -> float:
    """r = ω/ωₙ, exactly 1 when ω = ωₙ to within the inputs' uncertainty (exact resonance)."""
    return 1.0 if exact.cmp_sqrt(Om, exact.fr(k) / exact.fr(m)) == 0 else Om / omega_n


def damping(p, omega_n):
    """(ζ, c, regime), the regime decided exactly (dyncli.exact): critical when
    c = 2√(km) (or ζ = 1) to within the uncertainty of a given number; ζ is
    then exactly 1.  Otherwise ζ = c/(2√k√m) is kept on its side of 1."""
    m, k = p.m, p.k
    if p.zeta is not None:
        zeta = p.zeta
        side = exact.cmp_sqrt(zeta, 1)
    else:
        c = p.c if p.c is not None else 0.0
        zeta = eq.damping_ratio(c, k, m)                   # (17.20)
        side = exact.cmp_sqrt(c, 4 * exact.fr(k) * exact.fr(m))
    if zeta == 0.0 and side < 0:
        regime = "undamped"
    else:
        regime = ("underdamped", "critical", "overdamped")[side + 1]
    if side == 0:
        zeta = 1.0
    elif side < 0 and zeta >= 1.0:
        zeta = math.nextafter(1.0, 0.0)
    elif side > 0 and zeta <= 1.0:
        zeta = math.nextafter(1.0, 2.0)
    c = eq.damping_coefficient(m, zeta, omega_n) if p.c is None else p.c
    if not (math.isfinite(zeta) and math.isfinite(c)):
        raise InputError("the damping overflows", "c" if p.c is not None else "zeta")
    return zeta, c, regime


#: the free phase's range, stated in the table (docs/types/vibration.md, "Phase convention")
PHASE_NOTE = "φ in (−π, π]; the notes' φ in [0, 2π) is φ + 2π when φ < 0"


def _time_response(p, res, omega_n, zeta, L, x0, v0, s0, Om):
    times = [float(ti) for ti in p.at]
    fo = forcing(p)
    fast = cf.free_response_fn(omega_n, zeta, L, x0, v0) if fo is None and s0 == 0.0 else None
    if fast is not None:    # a free vibration below critical damping: the same doubles, constants hoisted
        rows = [fast(ti) for ti in times]
    elif fo is None:        # the exact response at each time, in plain floats (no numpy)
        rows = [cf.response_at(ti, omega_n=omega_n, zeta=zeta, L=L, x0=x0, v0=v0, s0=s0, Omega=Om) for ti in times]
    else:
        rows = [forced.response_at(ti, m=p.m, omega_n=omega_n, zeta=zeta, L=L, x0=x0, v0=v0,
                                   F0=fo[0], Om=fo[1]) for ti in times]
    x, v, w = ([row[i] for row in rows] for i in range(3))
    method = p.accuracy.method
    if method in ("ode", "DOP853"):
        fm = None if fo is None else forced.ode_rhs(fo[0], fo[1], p.m)
        xo, vo = _ode(times, omega_n, zeta, L, x0, v0, s0, max(Om, 0.0 if fo is None else fo[1]),
                      p.accuracy.rtol, p.accuracy.atol, fm, max_steps=p.accuracy.max_steps)
        from dyncli import ode

        # relative to each quantity's scale over the run (the runner's rule, docs/accuracy.md)
        err = ode.relative_difference([(xo, x), (vo, v)]) if times else 0.0
        x, v = [float(c) for c in xo], [float(c) for c in vo]
        w = [xi - s0 * math.sin(Om * ti) - L for xi, ti in zip(x, times)]
        res.method = "ode:DOP853"
        res.error_estimate = err
        res.warn("accuracy.method = DOP853: x, v, w are integrated numerically; error_estimate is the "
                 "largest difference from the exact closed form (method: auto uses the closed form)")
    if not all(math.isfinite(c) for c in x + v):
        raise NumericalError("the response is not representable at the requested times "
                             "(ω·t beyond the floating-point range)")
    if method not in ("ode", "DOP853"):
        _check_digits(res, times, x, v, w, omega_n=omega_n, zeta=zeta, L=L, x0=x0, v0=v0, s0=s0, Om=Om,
                      f0=0.0 if fo is None else fo[0] / p.m, Of=0.0 if fo is None else fo[1])
    res.results.update(x=x, v=v, w=w)
    res.series.append(Series("t", list(p.at), ["x", "v", "w", "distance"], title="Response x = w + s + L (17.16b)"))


def _check_digits(res, times, x, v, w, *, omega_n, zeta, L, x0, v0, s0, Om, f0, Of):
    """Warn when the closed form's reported values have lost digits (:func:`_warn_lost_digits`):
    under a base motion by :func:`closed_form.base_rounding` (its velocity cancels too), else by
    the phases alone (:func:`closed_form.phase_rounding`) — skipped when no phase at the reported
    times is large enough to matter (one ulp of it below a quarter of LOSS_FRACTION)."""
    if not times:
        return
    if s0 != 0.0 and Om != 0.0:
        def bound(ti, xi, vi, wi):
            return cf.base_rounding(ti, omega_n=omega_n, zeta=zeta, L=L, x0=x0, v0=v0, s0=s0, Omega=Om,
                                    x=xi, v=vi, w=wi)
        _warn_lost_digits(res, times, x, v, w, bound, base_cures(s0 * Om))
        return
    if 4.0 * math.ulp(max(omega_n, Of) * max(abs(ti) for ti in times)) <= cf.LOSS_FRACTION:
        return
    phase = "ω*·t" if f0 == 0.0 else "ω*·t or Ω·t"

    def bound(ti, xi, vi, wi):
        return cf.phase_rounding(ti, omega_n=omega_n, zeta=zeta, L=L, w0=x0 - L, wd0=v0, f0=f0, Omega=Of)
    cure = (f"the phase {phase} is held to one ulp (a double holds a frequency to 16 digits, so a "
            "phase beyond ~1e9 rad costs the answer its digits); ask for a smaller t")
    _warn_lost_digits(res, times, x, v, w, bound, (cure, cure, cure))


def base_cures(speed: float) -> tuple[str, str, str]:
    """The cure of each quantity's lost digits (x, ẋ, w) under a base motion of speed Y·Ω."""
    return ("the base's phase Ω·t is held to one ulp; use a smaller Ω·t",
            f"the base's velocity Y·Ω = {speed:.3g} m/s cancels in ṡ + ẇ and the phase Ω·t is held to "
            "one ulp; use w (relative motion) where it is not warned about, or a smaller Ω·t",
            "its free and forced parts (each of size ≈ Y·Ω/ωₙ) cancel and the phase Ω·t is held to "
            "one ulp; use a smaller Ω·t")


def _warn_lost_digits(res, times, x, v, w, bound, cures):
    """Warn, once per quantity, when a reported time's rounding error (``bound(t, x, v, w)`` ->
    (errors, scales)) exceeds LOSS_FRACTION of the quantity's scale: naming the worst such time,
    how many there are and the quantity's cure."""
    from dyncli.phase import lost_at, worst_loss

    names = ("x", "ẋ", "w")
    bounds = [bound(ti, x[i], v[i], w[i]) for i, ti in enumerate(times)]      # ((ex, ev, ew), scales)
    said: dict[str, list[str]] = {}             # quantities with the same time, loss and cure: one warning
    for q in range(3):
        # (a motion of scale 0 has errors 0: no loss)
        hit = worst_loss([errs[q] / scales[q] if scales[q] > 0 else (math.inf if errs[q] > 0 else 0.0)
                          for errs, scales in bounds], cf.LOSS_FRACTION)
        if hit is None:
            continue
        k, count = hit
        e, sc = bounds[k][0][q], bounds[k][1][q]
        how = ("no correct digits" if e >= sc else
               f"a rounding error up to {e:.2g} (more than {cf.LOSS_FRACTION:g} of its scale {sc:.3g})")
        said.setdefault(f" at t = {times[k]:g} s {{}} {how}{lost_at(count, len(times))}: {cures[q]}",
                        []).append(names[q])
    for tail, who in said.items():
        if len(who) == 1:
            res.warn(who[0] + tail.format("has"))
        else:
            res.warn(", ".join(who[:-1]) + " and " + who[-1] + tail.format("have"))


def _ode(t, omega_n, zeta, L, x0, v0, s0, Om, rtol, atol, force_per_mass=None, max_steps=None):
    """(17.15a) integrated with DOP853 by the runner (:func:`dyncli.ode.integrate`: the step
    budget accuracy.max_steps, non-finite rates refused) (the numerical route)."""
    import numpy as np

    from dyncli import ode

    t = np.asarray(t, dtype=float)
    T = float(np.max(t)) if t.size else 0.0
    _, _, lam2 = cf.roots(omega_n, zeta)
    rate = max(omega_n, lam2 if zeta >= 1 else omega_n, Om)
    limit = int(max_steps or ode.MAX_STEPS)
    if rate * T / DOP853_STABILITY > limit:
        raise NumericalError(f"DOP853 would need more than {rate * T / DOP853_STABILITY:.3g} steps here "
                             f"(fastest rate {rate:.3g}/s over {T:.3g} s), more than the budget of {limit} "
                             "(accuracy.max_steps); use accuracy.method: auto")
    if T == 0.0:
        return np.full(t.shape, x0), np.full(t.shape, v0)
    wn2 = omega_n * omega_n
    two_zw = 2.0 * zeta * omega_n

    def rhs(tt, y):
        s = s0 * math.sin(Om * tt)
        sd = s0 * Om * math.cos(Om * tt)
        f = 0.0 if force_per_mass is None else force_per_mass(tt)
        return [y[1], -wn2 * (y[0] - s - L) - two_zw * (y[1] - sd) + f]

    Y, _ = ode.integrate(rhs, [x0, v0], t, method="DOP853", rtol=rtol, atol=atol, max_steps=limit)
    return Y[:, 0], Y[:, 1]


def _sweep(sw, zeta, res, given_zeta):
    import numpy as np

    lo, hi = sw.ratio
    if sw.spacing == "log":
        r = np.geomspace(lo, hi, sw.points)
    else:
        r = np.linspace(lo, hi, sw.points)
    r[0], r[-1] = lo, hi
    G, phi, g, Phi = cf.amplification(r, zeta)
    R = res.results
    R["sweep_r"] = r.tolist()
    R["sweep_G"] = [_f(a) for a in G]
    R["sweep_phi"] = phi.tolist()
    R["sweep_g"] = [_f(a) for a in g]
    R["sweep_Phi"] = Phi.tolist()
    if any(a is None for a in R["sweep_G"]):
        res.warn("sweep: G and g are null at r = 1 (undamped resonance: unbounded)")

    pG = cf.peak_G(zeta, rel=exact.INPUT_ROUNDING if given_zeta else 2 * exact.INPUT_ROUNDING)
    pg = cf.peak_g(zeta)
    R["peak_G_r"], R["peak_G"] = pG if pG else (None, None)
    R["peak_g_r"], R["peak_g"] = pg if pg else (None, None)
    if zeta == 0.0:
        res.warn("peaks are null: undamped, G and g are unbounded at r = 1")
    elif pG is None:
        res.warn("peak_G_r, peak_G are null: for ζ ≥ 1/√2 G has no maximum; it rises monotonically "
                 "towards 1 as r → ∞")

    _sweep_display(res, r, lo, hi, zeta, pG, pg)


def _sweep_display(res, r, lo, hi, zeta, pG, pg) -> None:
    """The sweep's series (the points nearest to the exact peaks marked) and the peaks table."""
    import numpy as np

    marks: dict[int, list[str]] = {}

    def mark(rp, label):
        if rp is not None and lo <= rp <= hi:
            i = int(np.argmin(np.abs(r - rp)))
            marks.setdefault(i, []).append(label)

    mark(pG[0] if pG else None, "◀ G max")
    mark(pg[0] if pg else None, "◀ g max")
    if zeta == 0.0:
        mark(1.0, "◀ resonance")
    # the index stays the numbers (a frame's column r); the marks are the tables' alone
    res.series.append(Series("r", r.tolist(), ["sweep_G", "sweep_phi", "sweep_g", "sweep_Phi"],
                             title="Frequency sweep: amplification functions G (17.30b), g (17.34b); "
                                   "◀ marks the point nearest to a peak", index_result="sweep_r",
                             index_marks={i: " ".join(m) for i, m in marks.items()}))
    rows = []
    for name, pk, where in (("G (17.30b)", pG, "r = 1/√(1 − 2ζ²), G = 1/(2ζ√(1 − ζ²))"),
                            ("g (17.34b)", pg, "r² = 2/(1 + √(1 + 8ζ²))")):
        if pk:
            inside = "yes" if lo <= pk[0] <= hi else "no"
            rows.append([name, pk[0], pk[1], inside, where])
        else:
            why = "unbounded at r = 1 (ζ = 0)" if zeta == 0.0 else "none (ζ ≥ 1/√2): increases towards 1"
            rows.append([name, None, None, "—", why])
    res.views.append(Table("Resonance peaks (exact)", ["function", "r at peak", "peak value", "in sweep", "formula"], rows))
