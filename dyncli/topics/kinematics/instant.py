"""Kinematics of a point at one instant, from the numbers a textbook gives (notes §5, §7, §8, §12):
the coordinates and their first and second rates (polar, cylindrical, spherical), or the speed,
its rate and the radius of curvature on the path (§5).

The coordinate systems go through the same rotating-basis route as functions of t
(:func:`dyncli.topics.kinematics.motion.motion_of_jets`: v = δx/δt + ω×x, a = δv/δt + ω×v, 11.4),
with (q, q̇, q̈) given instead of differentiated; every result is a single value instead of a list.
On the path (5.14b): v = ṡ e_t, a = s̈ e_t + (ṡ²/ρ) e_n, components on (e_t, e_n, e_b).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from dyncli.result import Result, SolveOptions
from dyncli.topics.kinematics import frame

#: what the frame table and the warnings call the instant
WHEN = "at the instant"


@dataclass(frozen=True, slots=True)
class Instant:
    """The state at one instant as a textbook gives it, in SI floats: ``coordinates`` polar,
    cylindrical or spherical with ``jets`` ((name, (q, q̇, q̈)) per coordinate, absent rates 0),
    or ``path`` with the speed ``v``, its rate ``v_dot`` and the radius of curvature ``rho``
    (None: a straight path); ``m`` the mass (None: no force)."""

    coordinates: str
    jets: tuple[tuple[str, tuple[float, float, float]], ...] = ()
    v: float = 0.0
    v_dot: float = 0.0
    rho: float | None = None
    m: float | None = None


def path_state(v: float, v_dot: float, rho: float | None) -> tuple[float, float, float | None]:
    """(a_t, a_n, ρ) on a path from the speed v = ṡ, its rate v̇ = s̈ and the radius of curvature
    (5.14b): a_t = s̈, a_n = ṡ²/ρ, formed as (ṡ/ρ)·ṡ; a straight path (ρ absent or infinite)
    has a_n = 0 and ρ null.

    >>> path_state(20.0, -3.0, 50.0)
    (-3.0, 8.0, 50.0)
    >>> path_state(5.0, 1.0, math.inf)
    (1.0, 0.0, None)
    """
    if rho is None or math.isinf(rho):
        return v_dot, 0.0, None
    return v_dot, (v / rho) * v, rho


def solve(p: Instant, options: SolveOptions) -> Result:
    res = _path(p) if p.coordinates == "path" else _coordinates(p)
    if options.symbolic:
        res.warn("--symbolic: no formulas at one instant (the state is given as numbers)"
                 + ("" if p.coordinates == "path" else "; the frame table shows the numbers"))
    return res


def _coordinates(p: Instant) -> Result:
    from dyncli.topics.kinematics import motion

    coords = p.coordinates
    J = {n: tuple(np.array([x], dtype=float) for x in q) for n, q in p.jets}
    with np.errstate(all="ignore"):
        rows = motion.motion_of_jets(coords, J, (1,))
    out, rest, straight, undefined = motion.per_time(rows, [0.0])
    res = Result({k: v[0] for k, v in out.items()}, method="closed-form",
                 equations=list(motion.EQUATIONS[coords]) + ["5.3", "5.5", "5.14b"])
    if undefined:
        res.warn("the state is not finite at the instant (numbers beyond the floating-point range): "
                 "those entries are null")
    if rest:
        res.warn("the point is at rest at the instant: the tangent e_t is undefined, so "
                 "e_t, e_n, a_t, a_n and rho are null")
    if straight:
        res.warn(f"zero curvature at the instant (|v×a| <= {motion.STRAIGHT_TOL:g}·|v||a|: the "
                 "acceleration is along the velocity): rho and e_n are null and a_n = 0")
    _force(p, res, cartesian=True)
    table = [(lab, [[float(rows[key][k][0]) for k in range(3)]]) for lab, key in motion.ROW_LABELS]
    res.views = [*frame.numeric_tables(f"{coords} basis", [WHEN], table, motion.BASIS_LABELS[coords])]
    return res


def _path(p: Instant) -> Result:
    v, v_dot = p.v, p.v_dot
    a_t, a_n, rho = path_state(v, v_dot, p.rho)
    R = {"speed": v, "a_t": a_t, "a_n": a_n, "rho": rho,
         "v_basis": [v, 0.0, 0.0], "a_basis": [a_t, a_n, 0.0]}
    if not math.isfinite(a_n):
        R["a_n"] = None
    res = Result(R, method="closed-form", equations=["5.3", "5.5", "5.14b"])
    if rho is None:
        res.warn("a straight path (no rho, or rho: .inf): a_n = 0 and rho is null")
    _force(p, res, cartesian=False)
    return res


def _force(p: Instant, res, cartesian: bool) -> None:
    """F = m a (16.1) with a mass: on the own basis, and in Cartesian components when the
    coordinates give them."""
    if p.m is None:
        return
    R, m = res.results, p.m
    if cartesian:
        R["F"] = None if R["a"] is None else [m * c for c in R["a"]]
    R["F_basis"] = None if R["a_basis"] is None else [m * c for c in R["a_basis"]]
    res.equations.append("16.1")
