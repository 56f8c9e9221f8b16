"""Rigid-body kinematics (notes §13-§15): the closed forms as pure functions on 3-tuples of
floats (plain Python: no numpy, no pydantic, no renderer).
"""

from __future__ import annotations

import math
from typing import Sequence, cast

Vec = tuple[float, float, float]


def add(a: Sequence[float], b: Sequence[float]) -> Vec:
    """a + b.

    >>> add((1.0, 2.0, 3.0), (1.0, 1.0, 1.0))
    (2.0, 3.0, 4.0)
    """
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a: Sequence[float], b: Sequence[float]) -> Vec:
    """a − b.

    >>> sub((1.0, 2.0, 3.0), (1.0, 1.0, 1.0))
    (0.0, 1.0, 2.0)
    """
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(k: float, a: Sequence[float]) -> Vec:
    """k a.

    >>> mul(2.0, (1.0, -2.0, 0.5))
    (2.0, -4.0, 1.0)
    """
    return (k * a[0], k * a[1], k * a[2])


def dot(a: Sequence[float], b: Sequence[float]) -> float:
    """a·b (plain sum: the rounding the tolerances of this topic were set for).

    >>> dot((1.0, 2.0, 3.0), (4.0, 5.0, 6.0))
    32.0
    """
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a: Sequence[float], b: Sequence[float]) -> Vec:
    """a × b.

    >>> cross((1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    (0.0, 0.0, 1.0)
    """
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a: Sequence[float]) -> float:
    """|a| (hypot: no overflow of the squares).

    >>> norm((3e300, 4e300, 0.0))
    5e+300
    """
    return math.hypot(a[0], a[1], a[2])


def unit(a: Sequence[float], path: str | None = None, what: str = "the direction") -> Vec:
    """a/|a| scaled by max|aᵢ| first (dyncli.direction): no 1/|a| overflow; a zero or
    non-finite a is an input error on ``path``.

    >>> unit((0.0, 0.0, 1e-200))
    (0.0, 0.0, 1.0)
    """
    from dyncli.direction import unit as scaled_unit

    return cast(Vec, tuple(float(c) for c in scaled_unit(a, path, what)))


def rigid_velocity(vB, w, x) -> Vec:
    """v_P = v_B + ω × x_P/B [m/s] (13.8).

    >>> rigid_velocity((1.0, 0.0, 0.0), (0.0, 0.0, 2.0), (1.0, 0.0, 0.0))
    (1.0, 2.0, 0.0)
    """
    return add(vB, cross(w, x))


def rigid_acceleration(aB, alpha, w, x) -> Vec:
    """a_P = a_B + α × x_P/B + ω × (ω × x_P/B) [m/s²] (13.9).

    >>> rigid_acceleration((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 2.0), (1.0, 0.0, 0.0))
    (-4.0, 0.0, 0.0)
    """
    return add(add(aB, cross(alpha, x)), cross(w, cross(w, x)))


def normal_angular_velocity(x, v) -> Vec:
    """ωₙ = x_A/B × v_A/B / |x_A/B|² [rad/s] (13.20): the part of ω normal to the line of two
    points, formed with 1/|x| twice so that |x|² cannot underflow.

    >>> normal_angular_velocity((2.0, 0.0, 0.0), (0.0, 4.0, 0.0))
    (0.0, 0.0, 2.0)
    """
    L = norm(x)                       # |x|² may underflow (points 1e-300 apart)
    return cast(Vec, tuple(c / L for c in cross(unit(x), v)))


def three_point_angular_velocity(xA, xC, vA, vC, N, nN: float) -> Vec:
    """ω [rad/s] from two relative positions and velocities (13.13-13.17): on the basis
    (x_A/B, x_C/B, N = x_A/B × x_C/B), ω·N = v_A/B·x_C/B (13.14) and the in-plane part from the
    N-components of v_A/B, v_C/B (13.15-13.16); nN = |N| > 0.

    >>> three_point_angular_velocity((1.0, 0, 0), (0, 1.0, 0), (0, 1.0, 0), (-1.0, 0, 0), (0, 0, 1.0), 1.0)
    (0.0, 0.0, 1.0)
    """
    D = dot(vA, xC)
    Nh = unit(N)                       # unit normal: nN² may underflow (points 1e-300 apart)
    return add(add(mul(dot(vC, Nh) / nN, xA), mul(-dot(vA, Nh) / nN, xC)), mul(D / nN, Nh))


def screw_axis_offset(e, vB, wn: float) -> Vec:
    """x_D/B = ω × v_B / ω² [m] (14.7c), with e = ω/|ω| and wn = |ω|: the point of the screw
    axis nearest B.

    >>> screw_axis_offset((0.0, 0.0, 1.0), (1.0, 0.0, 0.0), 2.0)
    (0.0, 0.5, 0.0)
    """
    return cast(Vec, tuple(c / wn for c in cross(e, vB)))


def contact_split(vM1, vM2, n):
    """(v_M'/M'', approach speed v_M'/M''·n, slip velocity) [m/s] (15.8, 15.9) of the material
    points in contact, n the unit normal.

    >>> contact_split((1.0, 2.0, 0.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    ((1.0, 2.0, 0.0), 2.0, (1.0, 0.0, 0.0))
    """
    vrel = sub(vM1, vM2)
    approach = dot(vrel, n)
    return vrel, approach, sub(vrel, mul(approach, n))


def rolling_rates(vB, aB, c) -> tuple[Vec, Vec]:
    """(ω, ω̇) [rad/s, rad/s²] of a body rolling without slip, in plane motion, on a fixed surface,
    from the motion of the centre B of its rolling profile: the contact material point C (at
    x_C/B = c) has v_C = v_B + ω × c = 0 (15.9 with ωr = v), so with ω ⟂ c,
    ω = (v_B × c)/|c|²; and since |c| is constant and c turns with the contact,
    ω̇ = (a_B × c)/|c|² (the component of a_B along c, the centripetal part on a curved
    surface, drops out).  Formed as ((v_B × ĉ)/|c|): |c|² cannot underflow.

    >>> rolling_rates((2.0, 0.0, 0.0), (0.5, 0.0, 0.0), (0.0, -0.5, 0.0))
    ((0.0, 0.0, -4.0), (0.0, 0.0, -1.0))
    """
    r = norm(c)
    ch = unit(c)
    return mul(1.0 / r, cross(vB, ch)), mul(1.0 / r, cross(aB, ch))


def nested_rates(rotations) -> tuple[Vec, Vec, Vec]:
    """(ω, ω̇, Σ W × ω_k) [rad/s, rad/s², rad/s²] of a body turning in a chain of frames: frame 1
    turns at ω_1 relative to the fixed frame, each next frame (the last is the body) at ω_k relative
    to the one before, and ω̇_k is the rate of ω_k seen in that frame before (δω_k/δt, 11.10; for
    k = 1 the absolute ω̇_1).  ω = Σ ω_k (angular velocities of nested frames add), and by (11.7)
    on each term dω_k/dt = δω_k/δt + W_{k−1} × ω_k, W_{k−1} = ω_1 + … + ω_{k−1} the frame's own angular velocity:
    ω̇ = Σ ω̇_k + Σ W_{k−1} × ω_k.  ``rotations``: [(ω_k, ω̇_k)], every vector on one basis.

    A disk spinning at ω_rel on an axle turning at Ω: ω = Ω + ω_rel, ω̇ = Ω̇ + ω̇_rel + Ω × ω_rel.

    >>> nested_rates([((0.0, 0.0, 2.0), (0.0, 0.0, 0.0)), ((10.0, 0.0, 0.0), (3.0, 0.0, 0.0))])
    ((10.0, 0.0, 2.0), (3.0, 20.0, 0.0), (0.0, 20.0, 0.0))
    """
    W: Vec = (0.0, 0.0, 0.0)
    rates: Vec = (0.0, 0.0, 0.0)
    coupling: Vec = (0.0, 0.0, 0.0)
    for w, wd in rotations:
        coupling = add(coupling, cross(W, w))
        rates = add(rates, wd)
        W = add(W, w)
    return W, add(rates, coupling), coupling
