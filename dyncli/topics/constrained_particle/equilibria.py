"""Relative equilibria of a particle on a fixed or uniformly turning curve and
their stability (notes §16, §18; the bead on a rotating hoop).

At rest relative to the curve (q̇ = 0, constant ω) the tangential equation is
m |τ| q̈ = G(q) with G = (F − m b)·e_t and b = ω² k × (k × x) (curve.py): the
relative equilibria are the roots q* of G on ``q_range``.  Linearised,
m |τ| δq̈ = G'(q*) δq (the Coriolis term 2ω k × τ q̇ is normal to the curve
and drops out), so q* is stable when G'(q*) < 0, with small oscillations of
angular frequency sqrt(−G'(q*)/(m |τ(q*)|)); unstable when G'(q*) > 0.  For
potential forces G = −dV_eff/ds with V_eff = V − ½ m ω² ρ² (ρ the distance
from the axis): stable at a minimum of V_eff.

Roots are bracketed on 4000 samples of q_range and refined with brentq; G' is
a Richardson-extrapolated central difference.  Needs: q_range, a constant ω
(or a fixed curve), forces that do not depend on t, and forces symmetric
about the axis of a turning curve (G the same at every angle of the curve);
otherwise ``equilibria`` is null with a warning.  Friction is ignored here
(with friction the particle can also stay wherever |G| ≤ μ|N|).
"""

from __future__ import annotations

import numpy as np

N_SAMPLES = 4000
MAX_EQUILIBRIA = 100      # more on one q_range: the sampling cannot resolve them


def _G(model, q, phi=0.0):
    q = np.atleast_1d(np.asarray(q, float))
    Y = np.vstack([q, np.zeros_like(q), np.full_like(q, phi), np.zeros_like(q), np.zeros_like(q)])
    e = model.evaluate(np.zeros_like(q), Y, ("stick", 0))
    return e["G"], e["speed"]


def _why_not(p, model) -> str | None:
    if p.q_range is None:
        return "give q_range (the ends of the wire) to search for relative equilibria"
    if model.curve.rotating and model.curve.omega_const is None:
        return "the rate ω depends on t: there are no relative equilibria"
    if any(f.kind == "custom" and any("t" in e.variables for e in f.F) for f in p.forces):
        return "a custom force depends on t: there are no relative equilibria"
    return None


def find(p, model):
    """A list of {q, x, stable, omega_small} or (None, reason)."""
    from dyncli.rootfind import brentq

    lo, hi = p.q_range
    qs = np.linspace(lo, hi, N_SAMPLES + 1)
    with np.errstate(all="ignore"):
        G, _ = _G(model, qs)
        if model.curve.rotating:
            for phi in (1.0, 2.5):
                G2, _ = _G(model, qs, phi)
                if not np.allclose(G, G2, rtol=1e-9, atol=1e-12 * max(1.0, float(np.nanmax(np.abs(G))))):
                    return None, "the forces are not symmetric about the axis of rotation: no relative equilibria"
    scale = float(np.nanmax(np.abs(G))) if np.any(np.isfinite(G)) else 0.0
    if scale == 0.0:
        return None, "no tangential force anywhere on q_range: every point is a (neutral) relative equilibrium"
    tol = 1e-12 * max(scale, 1e-300)
    roots = []
    for i in range(N_SAMPLES + 1):
        if np.isfinite(G[i]) and abs(G[i]) <= tol:
            roots.append(float(qs[i]))
        elif i < N_SAMPLES and np.isfinite(G[i]) and np.isfinite(G[i + 1]) and G[i] * G[i + 1] < 0 and abs(G[i + 1]) > tol:
            roots.append(brentq(lambda q: float(_G(model, q)[0][0]), qs[i], qs[i + 1], xtol=1e-15, rtol=1e-15))
        if len(roots) > MAX_EQUILIBRIA:
            return None, (f"more than {MAX_EQUILIBRIA} relative equilibria on q_range: give a shorter q_range "
                          "to list them")
    if model.closed and roots and abs(roots[-1] - hi) <= 1e-12 * max(1.0, abs(hi)) and abs(roots[0] - lo) <= 1e-12 * max(1.0, abs(lo)):
        roots.pop()          # the ends of a closed curve are one point
    h = 1e-4 * (hi - lo)
    k_ref = scale / (model.m * (hi - lo)) / max(float(np.nanmean(_G(model, qs[::100])[1])), 1e-300)
    regular = [q for q in roots if float(_G(model, q)[1][0]) > 0]
    if len(regular) < len(roots):
        bad = ", ".join(f"{q:.6g}" for q in roots if q not in regular)
        return [_classify(model, q, h, k_ref) for q in regular], (
            f"the curve's tangent dy/dq vanishes at q = {bad} (not a regular point of the parameter): "
            "left out of equilibria")
    return [_classify(model, q, h, k_ref) for q in regular], None


def _classify(model, q, h, k_ref):
    def d(hh):
        return (float(_G(model, q + hh)[0][0]) - float(_G(model, q - hh)[0][0])) / (2 * hh)

    dG = (4 * d(h / 2) - d(h)) / 3          # Richardson: error O(h⁴)
    _, sp = _G(model, q)
    x = model.curve.state(0.0, q, 0.0, 0.0)[0][:, 0]
    k = -dG / (model.m * float(sp[0]))
    if abs(k) <= 1e-8 * k_ref:     # G'(q*) = 0 to within the difference's error: the linearisation cannot tell
        return {"q": float(q) + 0.0, "x": [float(c) + 0.0 for c in x], "stable": None, "omega_small": 0.0}
    stable = bool(k > 0)
    return {"q": float(q) + 0.0, "x": [float(c) + 0.0 for c in x], "stable": stable,
            "omega_small": float(np.sqrt(k)) if stable else None}


def add(res, p, model) -> None:
    why = _why_not(p, model)
    if why is None:
        eq, why = find(p, model)
    else:
        eq = None
    res.results["equilibria"] = eq
    if why and p.q_range is not None:
        res.warn(f"equilibria is null: {why}" if eq is None else f"equilibria: {why}")
