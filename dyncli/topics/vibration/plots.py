"""Plots of ``vibration`` problems (``dyncli solve --plot``).

* x(t) on a fine grid (the exact total response of :mod:`closed_form`) with
  its envelope: L ± A e^(−ζωₙt) for a free undamped/underdamped motion
  (17.10, 17.22a); for base excitation the steady band L ± s0·g (17.32) and,
  when ζ < 1, the bound L ± (s0·g + B e^(−ζωₙt)) where B is the amplitude of
  the free (transient) part, found by the solver from the initial conditions
  minus the particular solution (17.28).  The base motion L + s(t) is drawn
  too, and the requested ``at`` times are marked.
* The amplification functions G (17.30b) and g (17.34b) over the sweep (or
  over 0 ≤ r ≤ max(3, 1.5 r) when only ``base`` is given), like Fig. 17.4,
  with the chosen r = ω/ωₙ marked.

Everything is evaluated by the topic's own exact functions (``closed_form``,
the solver's amplitude–phase form); nothing here re-derives the physics or
solves again.  A span with more than ZOOM_CYCLES cycles is drawn as a band by
the renderer, and a second panel shows the first few periods one by one.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.result import Line, Plot
from dyncli.topics.vibration import closed_form as cf
from dyncli.topics.vibration import forced
from dyncli.topics.vibration.solver import forcing as _forcing

MIN_POINTS, MAX_POINTS, PER_PERIOD = 400, 40000, 40
ENVELOPE_MAX = 20      # an envelope more than this many times the largest |x − L| is not drawn
ZOOM_CYCLES = 60        # more cycles than this in the span: a second panel shows the first ZOOM_PERIODS
ZOOM_PERIODS = 3
SWEEP_POINTS = 801


def plots(problem, result) -> list[Plot]:
    out = []
    R = result.results
    moves = problem.at or problem.base is not None or (problem.x0 is not None and problem.x0 != problem.L) \
        or problem.v0 != 0 or _forcing(problem) is not None
    if moves:
        out.append(_response(problem, R))
        zoom = _zoom(problem, R)
        if zoom is not None:
            out.append(zoom)
    if problem.sweep is not None or problem.base is not None:
        out.append(_amplification(problem, R))
    return out


def _nan(values):
    return [float("nan") if v is None else float(v) for v in values]


def _time_span(p, R) -> float:
    if p.at and max(p.at) > 0:
        return float(max(p.at))
    wn, zeta = R["omega_n"], R["zeta"]
    period = 2 * math.pi / wn
    T = 5 * period
    _, slow, _ = cf.roots(wn, zeta)            # the slowest decay rate (ζωₙ, or λ₁ when ζ ≥ 1)
    if zeta >= 1:
        T = max(T, 4.0 / slow)                 # no oscillation: show the creep back to L
    elif zeta > 0:
        T = max(T, min(4.0 / slow, 40 * period))
    if _omega(p) > 0:
        T = max(T, min(5 * 2 * math.pi / _omega(p), 40 * period))
    return T


def _zoom(p, R) -> Plot | None:
    """x(t) over the first ZOOM_PERIODS periods of the fastest oscillation,
    when the whole span holds more cycles than a panel can show one by one
    (the renderer then draws the full span as a band)."""
    wn = R["omega_n"]
    Om = _omega(p)
    fastest = max(wn, Om)
    T = _time_span(p, R)
    if fastest * T / (2 * math.pi) <= ZOOM_CYCLES:
        return None
    span = ZOOM_PERIODS * 2 * math.pi / fastest
    t = np.linspace(0.0, span, 600)
    x = _x(p, R, t)
    return Plot(f"x(t) over the first {ZOOM_PERIODS} periods (2π/{fastest:.4g} s each), exact",
                "t [s]", "x, position of the mass [m]", [Line(t.tolist(), x.tolist(), "x(t), exact", style="-")])


def _omega(p) -> float:
    """The excitation's frequency (base, force or unbalance; 0 for free vibration)."""
    fo = _forcing(p)
    return p.base.omega if p.base is not None else (fo[1] if fo is not None else 0.0)


def _x(p, R, t):
    """The exact total response x(t) over an array of times (any excitation)."""
    x0 = p.L if p.x0 is None else p.x0
    fo = _forcing(p)
    with np.errstate(all="ignore"):
        if fo is not None:
            return forced.response(t, m=p.m, omega_n=R["omega_n"], zeta=R["zeta"], L=p.L, x0=x0, v0=p.v0,
                                   F0=fo[0], Om=fo[1])[0]
        s0, Om = (p.base.amplitude, p.base.omega) if p.base is not None else (0.0, 0.0)
        return cf.response(t, omega_n=R["omega_n"], zeta=R["zeta"], L=p.L, x0=x0, v0=p.v0, s0=s0, Omega=Om)[0]


def _response(p, R) -> Plot:
    wn, zeta, L = R["omega_n"], R["zeta"], p.L
    x0 = L if p.x0 is None else p.x0
    s0, Om = (p.base.amplitude, p.base.omega) if p.base is not None else (0.0, _omega(p))
    T = _time_span(p, R)
    fastest = max(wn, Om)
    n = int(min(MAX_POINTS, max(MIN_POINTS, PER_PERIOD * fastest * T / (2 * math.pi))))
    t = np.linspace(0.0, T, n)
    x = _x(p, R, t)
    ts = t.tolist()
    lines = [Line(ts, x.tolist(), "x(t), exact total response", style="-")]
    hlines: list[tuple[float, str | None]] = []
    decays = np.exp(-zeta * wn * t)
    if _forcing(p) is not None:
        title = ("rotating-unbalance" if p.unbalance is not None else "force-excited") + " vibration x(t)"
        if R.get("X") is not None:
            hlines += [(L + R["X"], "steady state L ± X"), (L - R["X"], None)]
        else:
            title += ": undamped resonance, the amplitude grows linearly"
    elif p.base is None:
        title = "free vibration x(t)"
        A = R.get("A")
        swing = float(np.max(np.abs(x - L))) if x.size else 0.0
        if R["regime"] in ("undamped", "underdamped") and A and A > ENVELOPE_MAX * swing:
            # ζ just below 1: ω* → 0 makes A huge while the motion creeps back
            # like the critical one; the envelope would squash x(t) to a line
            title += f" (envelope A = {A:.3g} m ≫ the motion, not drawn: ζ ≈ 1)"
        elif R["regime"] in ("undamped", "underdamped") and A:
            lines.append(_band(t, L, A * decays, "envelope L ± A e^(−ζωₙt) (17.22a)"))
            title += " with its envelope"
        else:
            title += f" ({R['regime']}: no oscillation, no envelope)"
    else:
        title = "base-excited vibration x(t) (17.31)"
        if Om > 0 and s0 != 0:
            lines.append(Line(ts, (L + s0 * np.sin(Om * t)).tolist(), "base L + s(t) (17.26)", style=":"))
        g = R.get("g")
        if Om == 0 or s0 == 0:
            title += ": the base does not move (s0·sin(ωt) ≡ 0)"
        elif g is not None:
            band = abs(s0) * g
            hlines += [(L + band, "steady state L ± s0·g (17.32)"), (L - band, None)]
            B = _transient_amplitude(p, R, x0)
            if B is not None and B > 0:
                lines.append(_band(t, L, band + B * decays, "envelope L ± (s0·g + B e^(−ζωₙt))"))
                title += " with its envelope"
        else:
            title += ": undamped resonance, the amplitude grows linearly"
    if p.at:
        xs = R.get("x")
        if xs:
            lines.append(Line(list(p.at), list(xs), "requested times (at)", style="", marker="o"))
    return Plot(title, "t [s]", "x, position of the mass [m]", lines, hlines=hlines)


def _band(t, L, half, label) -> Line:
    """L ± half(t) as ONE curve (upper, a gap, lower): one style, one legend entry."""
    nan = [float("nan")]
    return Line(t.tolist() + nan + t.tolist(), (L + half).tolist() + nan + (L - half).tolist(), label, style="--")


def _transient_amplitude(p, R, x0):
    """B: the amplitude of the free part w_h = w − w_p of the response, from
    the solver's amplitude–phase function (17.22c) applied to w_h(0), ẇ_h(0)
    (nothing is solved again); None when the free part has no amplitude form
    (ζ ≥ 1)."""
    if R["regime"] not in ("undamped", "underdamped"):
        return None
    from dyncli.topics.vibration.closed_form import amplitude_phase

    s0, Om = p.base.amplitude, p.base.omega
    G, phi = R["G"], R["phi"]
    wp0, wpd0 = G * s0 * math.sin(phi), G * s0 * Om * math.cos(phi)      # (17.28) at t = 0
    wh0 = x0 - p.L - wp0
    whd0 = p.v0 - s0 * Om - wpd0                                          # ẇ(0) = v0 − ṡ(0)
    A, _, _ = amplitude_phase(wh0, whd0, R["omega_n"], R["zeta"], R["omega_d"], R["regime"])
    return A


def _amplification(p, R) -> Plot:
    zeta = R["zeta"]
    r0 = R.get("r")
    logx = False
    if p.sweep is not None:
        lo, hi = p.sweep.ratio
        logx = p.sweep.spacing == "log"
    else:
        lo, hi = 0.0, max(3.0, 1.5 * r0)
    r = np.geomspace(lo, hi, SWEEP_POINTS) if logx else np.linspace(lo, hi, SWEEP_POINTS)
    extra = [x for x in (1.0, r0, (cf.peak_G(zeta) or (None,))[0], (cf.peak_g(zeta) or (None,))[0])
             if x is not None and lo <= x <= hi]
    r = np.unique(np.concatenate([r, extra]))
    with np.errstate(all="ignore"):
        G, _, g, _ = cf.amplification(r, zeta)
    G = np.where(np.isfinite(G), G, np.nan)
    g = np.where(np.isfinite(g), g, np.nan)
    rs = r.tolist()
    lines = [Line(rs, G.tolist(), "G, relative motion w (17.30b)", style="-"),
             Line(rs, g.tolist(), "g, absolute motion x (17.34b)", style="--")]
    vlines = []
    if r0 is not None and lo <= r0 <= hi:
        w = _omega(p)
        vlines.append((r0, f"chosen r = {r0:.4g} (ω = {w:.4g} rad/s)"))
        if R.get("G") is not None:
            lines.append(Line([r0, r0], [R["G"], R["g"]], f"G = {R['G']:.4g}, g = {R['g']:.4g} at the chosen r",
                              style="", marker="o"))
    finite = np.concatenate([G[np.isfinite(G)], g[np.isfinite(g)]])
    logy = bool(finite.size and zeta > 0 and finite.max() > 50)
    if zeta == 0:
        # unbounded at r = 1: clip the vertical range for a readable picture
        for ln in lines[:2]:
            ln.y = [v if v <= 20 else float("nan") for v in ln.y]
    return Plot(f"amplification functions G and g over r = ω/ωₙ, ζ = {zeta:.4g} (Fig. 17.4)",
                "r = ω/ωₙ, frequency ratio [–]", "G, g, amplification [–]", lines,
                vlines=vlines, logx=logx, logy=logy)
