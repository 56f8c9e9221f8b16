"""A steady circular motion of a free particle about a fixed axis, solved for its rate (notes §16,
§19, §21): at x0 the forces must be the centripetal force alone, F = −m ω² ρ (ρ from the axis to the
particle, normal to it), so their part along the axis and their part along e_θ = k × ρ̂ vanish and

    ω² = −F·ρ̂ / (m |ρ|),   v = ω |ρ|,   period 2π/ω

(a circular orbit: ω² = g R0²/r³; a puck on a spring from the axis: ω² = k (r − L)/(m r)).  Forces
of the position only.  A particle held by a constraint (a string, a track, a banked road) is a
``constrained-particle`` with ``steady``: there the constraint takes the unbalanced part.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import InputError, NumericalError

REL = 1e-9          # an unbalanced part above this fraction of |F| refuses (typed numbers' rounding)


def answers(p, F, warn) -> list[dict]:
    """One entry per query; where the forces at x0 do not hold a circular motion about the axis, an
    entry with ``exists: false`` and a warning saying which part is unbalanced (a physical "no
    solution": exit 0)."""
    for i, f in enumerate(p.forces):
        if f.kind in ("damper", "drag", "friction") or (
                f.kind == "custom" and set(v for e in f.F for v in e.variables) - {"x1", "x2", "x3"}):
            raise InputError(f"steady: a {f.kind} force depends on the velocity or the time; the steady rate is "
                             "found for forces of the position only: leave it out of this problem", f"forces.{i}")
    x = np.asarray(p.x0, float)
    Fx = np.asarray(F.conservative(x) + F.nonconservative(0.0, x, np.zeros(3)), float)
    return [_one(p, Fx, x, np.asarray(s, float), f"steady.{i}", warn) for i, s in enumerate(p.steady)]


def _one(p, Fx, x, k, where, warn) -> dict:
    rho = x - (x @ k) * k
    r = float(np.linalg.norm(rho))
    if r == 0:
        raise InputError("x0 is on the axis: a circular motion about it needs the particle off the axis", where)
    e_r = rho / r
    e_th = np.cross(k, e_r)
    Fr, Fth, Fk = float(Fx @ e_r), float(Fx @ e_th), float(Fx @ k)
    size = float(np.linalg.norm(Fx))
    base = {"axis": [float(c) + 0.0 for c in k], "x": [float(c) + 0.0 for c in x], "rho": r,
            "F": [float(c) + 0.0 for c in Fx]}
    for part, value, name in ((Fk, "along the axis", "F·k"), (Fth, "along e_θ (round the axis)", "F·e_θ")):
        if abs(part) > REL * size:
            return _none(base, f"{where}: no circular motion about this axis at x0: the forces there have a part "
                               f"{value} ({name} = {part:.6g} N) that nothing balances — a particle held by a "
                               "string, a track or a road is a constrained-particle with steady (the conical "
                               "pendulum is the bead on a hoop)", warn)
    if not Fr < 0:
        return _none(base, f"{where}: no circular motion about this axis at x0: the force there points away from "
                           f"the axis (F·ρ̂ = {Fr:.6g} N), and the centripetal force must point towards it", warn)
    w = math.sqrt(-Fr / (float(p.m) * r))
    if not (w > 0.0 and math.isfinite(w * r) and math.isfinite(2 * math.pi / w)):
        raise NumericalError(f"{where}: the circular motion's angular speed ω = √(−F·ρ̂ / (m ρ)) = {w:.6g} rad/s "
                             "leaves the doubles (its period or its speed is beyond ~1e308): rescale the units "
                             "(m, x0, the forces)")
    return {**base, "exists": True, "omega": w, "v": w * r, "period": 2 * math.pi / w}


def _none(base: dict, why: str, warn) -> dict:
    """The entry of a query the forces cannot answer: a physical "no solution" (exit 0), said why."""
    warn(why)
    return {**base, "exists": False, "omega": None, "v": None, "period": None}
