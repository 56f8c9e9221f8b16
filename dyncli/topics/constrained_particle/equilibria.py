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

The roots are decided exactly (dyncli.rootfind.all_roots: the sign of G at the critical points of
its resolved Chebyshev interpolant, sign changes and tangencies — never by sampling; a closed
curve also at its seam).  Stability from G's sign on either side of q* (exact, also at a
degenerate root such as the bifurcation ω² = g/R of the hoop, where G'(q*) = 0: there q* ≈ 0 is
stable by its cubic term); G' (for omega_small) is a Richardson-extrapolated central difference
on a step below the gap to the next root (q* ≈ ±√(2δ) just past the bifurcation).  Needs: q_range, a constant ω
(or a fixed curve), forces that do not depend on t, and forces symmetric
about the axis of a turning curve (G the same at every angle of the curve);
otherwise ``equilibria`` is null with a warning.  Friction is ignored here
(with friction the particle can also stay wherever |G| ≤ μ|N|).
"""

from __future__ import annotations

import numpy as np

N_CHECK = 400            # points of the symmetry check of a turning curve (not a root search)
MAX_EQUILIBRIA = 100      # more on one q_range: refused (give a shorter q_range)


def _G(model, q, phi=0.0):
    """G and |τ| at rest at the parameters ``q``, the curve turned by ``phi`` (a number, or one a q)."""
    q = np.atleast_1d(np.asarray(q, float))
    Y = np.vstack([q, np.zeros_like(q), np.broadcast_to(np.asarray(phi, float), q.shape), np.zeros_like(q),
                   np.zeros_like(q)])
    e = model.evaluate(np.zeros_like(q), Y, ("stick", 0))
    return e["G"], e["speed"]


def _plain_G(model):
    """A float function of q with the sign of G (q̈ = G/(m |τ|) at rest at t = 0 from the
    integrator's plain-float right-hand side, a few µs where G on an array costs ~0.1 ms) for the
    roots' Brent steps, G itself where that side is not finite (a force singular at a point);
    None with friction (the right-hand side's sliding friction is not G's)."""
    if model.mu:
        return None
    from dyncli.errors import NumericalError

    rhs = model.rhs_for(("slide", 1.0))
    y = np.zeros(6)

    def g(q):
        y[0] = q
        try:
            return rhs(0.0, y)[1]
        except NumericalError:
            return float(_G(model, q)[0][0])
    return g


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
    from dyncli.rootfind import all_roots

    lo, hi = (float(v) for v in p.q_range)
    qs = np.linspace(lo, hi, N_CHECK + 1)        # the symmetry check only (no root is decided here)
    # a turning curve: the field symmetric about the axis by its terms (exact), else G the same
    # with the curve turned by two more angles (a check, not a search)
    symmetric = not model.curve.rotating or model.compiled.symmetric_about(model.curve.k)
    turns = (0.0,) if symmetric else (0.0, 1.0, 2.5)
    with np.errstate(all="ignore"):          # (the curve turned by each angle, in one call)
        G, *G2 = _G(model, np.tile(qs, len(turns)), np.repeat(turns, len(qs)))[0].reshape(len(turns), len(qs))
        if any(not np.allclose(G, g2, rtol=1e-9, atol=1e-12 * max(1.0, float(np.nanmax(np.abs(G))))) for g2 in G2):
            return None, "the forces are not symmetric about the axis of rotation: no relative equilibria"
    scale = float(np.nanmax(np.abs(G))) if np.any(np.isfinite(G)) else 0.0
    if scale == 0.0:
        return None, "no tangential force anywhere on q_range: every point is a (neutral) relative equilibrium"
    g = lambda q: _G(model, q)[0]            # noqa: E731
    roots, touches, _bad = all_roots(g, lo, hi, limit=MAX_EQUILIBRIA, f1=_plain_G(model))
    ends = G[[0, -1]]                         # (q_range's ends: the check's first and last points)
    roots += [e for e, v in zip((lo, hi), ends) if abs(v) <= 64 * np.finfo(float).eps * scale]
    if model.closed and ends[0] * ends[1] <= 0:
        roots.append(lo)                      # G changes sign across the seam of a closed curve
    roots = sorted(set(roots + touches))
    if model.closed and roots and roots[-1] == hi and roots[0] == lo:
        roots.pop()          # the ends of a closed curve are one point
    if len(roots) > MAX_EQUILIBRIA:
        return None, (f"more than {MAX_EQUILIBRIA} relative equilibria on q_range: give a shorter q_range "
                      "to list them")
    regular = [q for q, sp in zip(roots, _G(model, roots)[1] if roots else []) if sp > 0]
    out = _classify_all(model, regular, lo, hi)
    if len(regular) < len(roots):
        bad = ", ".join(f"{q:.6g}" for q in roots if q not in regular)
        return out, (f"the curve's tangent dy/dq vanishes at q = {bad} (not a regular point of the parameter): "
                     "left out of equilibria")
    return out, None


def _neighbours(model, qs, j, lo, hi):
    """The roots either side of the root qs[j] (across the seam of a closed curve), None where
    the wire ends."""
    q, L = qs[j], hi - lo
    nb = []
    for k, end in ((j - 1, lo), (j + 1, hi)):
        if 0 <= k < len(qs):
            nb.append(qs[k])
        elif model.closed:
            nb.append(qs[k % len(qs)] + (L if k >= len(qs) else -L) if len(qs) > 1 else q + (L if k > j else -L))
        else:
            nb.append(end if end != q else None)
    return nb


def _classify_all(model, qs, lo, hi):
    """Each root's entry of ``equilibria``, G read at every point the roots need in one call.
    Stable when G is restoring on both sides (G > 0 below, < 0 above, read at the midpoints to
    the neighbouring roots: no root between, so the sign there is the sign on that whole side; a
    minimum of V_eff; exact, also at a degenerate root where G'(q*) = 0); omega_small from G'(q*)
    (a Richardson central difference on a step below the gap to the next root), 0 when G'(q*) is
    0 within its error."""
    if not qs:
        return []
    plan, pts = [], []
    for j, q in enumerate(qs):
        nb = _neighbours(model, qs, j, lo, hi)
        gap = min((abs(v - q) for v in nb if v is not None and v != q), default=hi - lo)
        h = min(1e-4 * (hi - lo), 0.125 * gap)
        sides = [None if v is None else len(pts) + k for k, v in enumerate(nb)]
        plan.append((q, h, sides, len(pts) + 2))
        pts += [0.5 * (q + v) if v is not None else q for v in nb] + [q + h, q - h, q + h / 2, q - h / 2, q]
    G, sp = _G(model, np.array(pts))
    out = []
    for q, h, sides, k in plan:
        gl, gr = (None if s is None else float(G[s]) for s in sides)
        gp, gm, gp2, gm2 = (float(v) for v in G[k:k + 4])
        d1, d2 = (gp - gm) / (2 * h), (gp2 - gm2) / h
        dG = (4 * d2 - d1) / 3          # Richardson: error O(h⁴)
        x = model.curve.state(0.0, q, 0.0, 0.0)[0][:, 0]
        err = abs(d2 - d1) + 64 * np.finfo(float).eps * (abs(gp) + abs(gm) + abs(dG) * h) / h
        if gl is not None and gr is not None:
            stable = bool(gl > 0 > gr)
        else:                            # at the end of an open wire: the linearisation, if it decides
            stable = None if abs(dG) <= err else bool(dG < 0)
        kk = -dG / (model.m * float(sp[k + 4]))
        omega = (float(np.sqrt(kk)) if dG < -err else 0.0) if stable else None
        out.append({"q": float(q) + 0.0, "x": [float(c) + 0.0 for c in x], "stable": stable, "omega_small": omega})
    return out


def add(res, p, model) -> None:
    why = _why_not(p, model)
    if why is None:
        eq, why = find(p, model)
    else:
        eq = None
    res.results["equilibria"] = eq
    if why and p.q_range is not None:
        res.warn(f"equilibria is null: {why}" if eq is None else f"equilibria: {why}")
