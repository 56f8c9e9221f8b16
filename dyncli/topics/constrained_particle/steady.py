"""Steady motions solved for what holds them (notes §16, §18, §19.27): the rate ω at which a
particle stays at rest at q on a curve turning uniformly about a fixed axis — the bead's relative
equilibrium on a turning hoop, the conical pendulum (the string is the hoop), the car on a banked
curve (the bank's line turning with the car) — and, with friction, the range of rates.

At rest relative to the curve at x = y(q) the acceleration is the centripetal one,
a = ω² k × (k × x) = −u ρ (u = ω², ρ the position measured from the axis, normal to it), so
m a = F + N + f e_t splits (e_t the unit tangent) into

    f = α u + β,   α = −m ρ·e_t,  β = −F·e_t          (the tangential force the wire must give)
    N = u A + B,   A = −m ρ⊥,     B = −F⊥             (the normal force; ⊥: the part normal to e_t)

for forces of the position only.  Without friction f = 0: u = −β/α = F·e_t/(−m ρ·e_t), i.e.
ω² = (dV/ds)/(m ρ dρ/ds): the stationary points of the effective potential V − ½ m ω² ρ² (for the
circular hoop of radius R with gravity, ω² = g/(R cos q)).  With static friction μ the particle is
held while |f| ≤ μ|N|: (α u + β)² − μ²|u A + B|² ≤ 0, a quadratic inequality in u solved in closed
form (for the banked curve of angle β_b: v² = r g (sin β_b ∓ μ cos β_b)/(cos β_b ± μ sin β_b), no
upper limit when μ ≥ cot β_b).  Stability of the frictionless rest (as equilibria.py):
G(q) = F·e_t + u m ρ·e_t restoring about q*, small oscillations at sqrt(−G′/(m|y′|)).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dyncli.errors import InputError

EPS = np.finfo(float).eps


def rate_range(a2: float, a1: float, a0: float, scale: float) -> list[tuple[float, float]]:
    """The intervals of u ≥ 0 where a2 u² + a1 u + a0 ≤ 0 (closed form; ``math.inf`` for no upper
    end).  ``scale`` sets what counts as a zero coefficient (the size of the terms)."""
    tiny = 64 * EPS * scale
    if abs(a2) <= tiny:                        # linear: a1 u + a0 ≤ 0
        if abs(a1) <= tiny:
            return [(0.0, math.inf)] if a0 <= tiny else []
        r = -a0 / a1
        if a1 > 0:
            return [(0.0, r)] if r >= 0 else []
        return [(max(r, 0.0), math.inf)]
    disc = a1 * a1 - 4 * a2 * a0
    if disc < 0:
        return [] if a2 > 0 else [(0.0, math.inf)]
    sq = math.sqrt(disc)
    qq = -0.5 * (a1 + math.copysign(sq, a1))   # the stable pair of roots
    r1, r2 = sorted((qq / a2, a0 / qq if qq != 0 else 0.0))
    if a2 > 0:                                  # between the roots
        return [(max(r1, 0.0), r2)] if r2 >= 0 else []
    out = [(0.0, r1)] if r1 >= 0 else []        # outside the roots
    return out + [(max(r2, 0.0), math.inf)]


def _forces(p, model):
    def F(x):
        x = np.asarray(x, float).reshape(3, 1)
        Fc, Fn = model.forces(np.zeros(1), x, np.zeros_like(x))
        return (Fc + Fn)[:, 0]
    return F


def check(p) -> None:
    """Refuse what has no steady rate to find (exit 2, naming the field)."""
    if p.rotation is None:
        raise InputError("steady motions need the axis the curve turns about: add rotation: {axis: [0, 0, 1]} "
                         "(the rate ω is what steady finds)", "steady")
    for i, f in enumerate(p.forces):
        moving = f.kind in ("damper", "drag") or (
            f.kind == "custom" and set(v for e in f.F for v in e.variables) - {"x1", "x2", "x3"})
        if moving:
            raise InputError(f"steady: a {f.kind} force depends on the velocity or the time; the steady rate is "
                             "found for forces of the position only (and friction): leave it out of this problem",
                             f"forces.{i}")


def answers(p, model) -> tuple[list[dict], list[str]]:
    """One entry per ``steady`` query (see the module docstring) and the warnings a student can act
    on; where no steady motion exists, an entry with ``exists: false`` and a warning saying why (a
    physical "no solution": exit 0)."""
    check(p)
    F = _forces(p, model)
    entries, warnings = [], []
    for i, s in enumerate(p.steady):
        entry, notes = _entry(p, model, F, float(s), f"steady.{i}.q")
        entries.append(entry)
        warnings += [f"steady.{i}: {n}" for n in notes]
    return entries, warnings


def add(res, answered) -> None:
    entries, warnings = answered
    res.results["steady"] = entries
    for w in warnings:
        res.warn(w)


def _geometry(p, model, q: float, where: str):
    curve = model.curve
    if p.q_range is not None and not p.q_range[0] <= q <= p.q_range[1]:
        raise InputError(f"q = {q:g} is outside q_range [{p.q_range[0]:g}, {p.q_range[1]:g}]", where)
    x, y1 = curve.y(q)[:, 0], curve.dy(q)[:, 0]
    sp = float(np.linalg.norm(y1))
    if not (np.all(np.isfinite(x)) and math.isfinite(sp)):
        raise InputError(f"the curve is not defined at q = {q:g}", where)
    if sp == 0:
        raise InputError(f"the curve's tangent dy/dq vanishes at q = {q:g}: q is not a regular parameter there", where)
    k = curve.k
    rho = x - (x @ k) * k                      # from the axis to the particle, normal to the axis
    return x, y1 / sp, sp, rho


def _coefficients(m, F, x, et, rho):
    Fx = F(x)
    alpha, beta = -m * float(rho @ et), -float(Fx @ et)
    A, B = -m * (rho - (rho @ et) * et), -(Fx - (Fx @ et) * et)
    return alpha, beta, A, B, Fx


def _entry(p, model, F, q: float, where: str) -> tuple[dict, list[str]]:
    """(the entry, warnings) of one query."""
    m, mu = model.m, model.mu
    x, et, sp, rho = _geometry(p, model, q, where)
    alpha, beta, A, B, Fx = _coefficients(m, F, x, et, rho)
    r = float(np.linalg.norm(rho))
    scale_f = max(abs(beta), float(np.linalg.norm(Fx)), 1e-300)
    scale_a = m * max(r, float(np.linalg.norm(x)), 1e-300) or 5e-324    # (m·1e-300 underflows: fuzz 1413356)
    held_anyhow = abs(alpha) <= 64 * EPS * scale_a and abs(beta) <= 64 * EPS * scale_f
    u = None
    if not held_anyhow and abs(alpha) > 64 * EPS * scale_a and -beta / alpha >= 0:
        u = -beta / alpha
    ranges = _friction_ranges(alpha, beta, A, B, mu, scale_f, scale_a)
    out: dict[str, Any] = {"q": q + 0.0, "x": [float(c) + 0.0 for c in x], "rho": r, "exists": True,
           "omega": None if u is None else math.sqrt(u), "v": None, "period": None,
           "N": None, "stable": None, "omega_small": None}
    if u is None and not held_anyhow and not ranges:       # a physical "no solution": exit 0, said why
        out["exists"] = False
        if mu:
            out.update(omega_min=None, omega_max=None, v_min=None, v_max=None)
        return out, [_why_not(q, alpha, beta, mu, scale_a)]
    if u is not None:
        w = math.sqrt(u)
        out.update(v=w * r, period=2 * math.pi / w if w > 0 else None,
                   N=_on_path_basis(model, q, u * A + B), **_stability(model, F, q, u))
    elif held_anyhow:
        out.update(N=_on_path_basis(model, q, B))
    lo, hi = ranges[0] if ranges else ((0.0, math.inf) if held_anyhow or u is None else (u, u))   # (u None: returned above)
    out.update(omega_min=math.sqrt(lo), omega_max=None if hi == math.inf else math.sqrt(hi))
    out.update(v_min=out["omega_min"] * r, v_max=None if out["omega_max"] is None else out["omega_max"] * r)
    notes = _degrees(model, q, x)
    if held_anyhow:
        notes.append(f"the particle stays at q = {q:g} at every rate (no force along the curve to balance "
                     "there); omega is null")
    elif out["omega_max"] is None:
        notes.append(f"omega_max and v_max are null — no upper limit: friction holds the particle at every rate "
                     f"above omega_min = {out['omega_min']:.6g} rad/s (on a banked curve: μ ≥ cot β)")
    if len(ranges) > 1:
        notes.append(f"friction also holds the particle at every rate above {math.sqrt(ranges[1][0]):.6g} rad/s")
    return out, notes


def _degrees(model, q: float, x) -> list[str]:
    """``q: 30`` meant as degrees on a hoop: a q beyond a full turn on a curve that repeats every 2π."""
    if abs(q) <= 2 * math.pi:
        return []
    back = model.curve.y(q - 2 * math.pi)[:, 0]
    if not np.all(np.abs(back - x) <= 1e-9 * max(1.0, float(np.max(np.abs(x))))):
        return []
    return [f"q = {q:g} is read in radians ({math.degrees(q):.4g}°, more than a full turn of a curve that repeats "
            f"every 2π); if you meant degrees, write {q:g}*deg"]


def _friction_ranges(alpha, beta, A, B, mu, scale_f, scale_a):
    """The intervals of u where |f| ≤ μ|N| (friction), or [] without friction."""
    if mu == 0:
        return []
    a2 = alpha * alpha - mu * mu * float(A @ A)
    a1 = 2 * (alpha * beta - mu * mu * float(A @ B))
    a0 = beta * beta - mu * mu * float(B @ B)
    # (divided one scale at a time: the square of a scale of 1e-305 underflows to 0)
    ranges = rate_range(a2 / scale_a / scale_a, a1 / scale_a / scale_f, a0 / scale_f / scale_f, 1.0)
    return [(lo * scale_f / scale_a, hi * scale_f / scale_a if hi != math.inf else hi) for lo, hi in ranges]


def _why_not(q, alpha, beta, mu, scale_a) -> str:
    held = f" (and friction μ = {mu:g} cannot hold it at any rate)" if mu else ""
    if abs(alpha) <= 64 * EPS * scale_a:
        return (f"no steady motion at q = {q:g}{held}: the curve's tangent there is normal to the direction from "
                "the axis, so turning gives no force along the curve to balance the applied force's part along "
                f"it ({-beta:.6g} N); choose another q")
    return (f"no steady motion at q = {q:g}{held}: it would need ω² = {-beta / alpha:.6g} rad²/s² < 0 — the "
            "applied force along the curve points away from the axis there, and turning can only push the "
            "particle outward (a conical pendulum's angle must be below 90°); choose a q where the force "
            "along the curve points towards the axis")


def _on_path_basis(model, q, N) -> list[float]:
    from .curve import rotation

    et, en, eb, _, _ = model.curve.frenet(np.array([q]), rotation(model.curve.k, [0.0]))
    return [0.0, float(N @ en[:, 0]) + 0.0, float(N @ eb[:, 0]) + 0.0]


def _stability(model, F, q, u) -> dict:
    """stable and omega_small of the frictionless rest at the rate sqrt(u) (G = F·e_t + u m ρ·e_t
    restoring on both sides; G′ by a Richardson central difference)."""
    p = model.p

    def G(qq):                               # G and the size of its terms (its rounding)
        x, et, _, rho = _geometry(p, model, qq, "steady")
        a, b = float(F(x) @ et), u * model.m * float(rho @ et)
        return a + b, abs(a) + abs(b)

    h = 1e-4 * max(1.0, abs(q))
    try:
        (gp, sp), (gm, sm) = G(q + h), G(q - h)
        d1 = (gp - gm) / (2 * h)
        d2 = (G(q + h / 2)[0] - G(q - h / 2)[0]) / h
    except InputError:                       # the curve ends or is singular next to q
        return {"stable": None, "omega_small": None}
    dG = (4 * d2 - d1) / 3
    err = abs(d2 - d1) + 64 * EPS * (sp + sm) / h
    if abs(dG) <= err:
        return {"stable": None, "omega_small": None}
    speed = float(np.linalg.norm(model.curve.dy(q)[:, 0]))
    return {"stable": bool(dG < 0), "omega_small": math.sqrt(-dG / (model.m * speed)) if dG < 0 else None}
