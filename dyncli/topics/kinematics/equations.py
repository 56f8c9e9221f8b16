"""Kinematics of a point (notes §4, §5, §7, §8, §12): the coordinate systems as rotating bases
and the tangential-normal quantities of §5, as pure functions (no pydantic, no renderer).

:func:`frame_rows` works on numpy arrays and on sympy objects alike (``m`` supplies sin/cos);
the §5 functions work on arrays of shape (n, 3), one row per time.
"""

from __future__ import annotations

import numpy as np

from dyncli.direction import norm_rows, unit_rows




def frame_rows(coords: str, J: dict, m) -> dict:
    """Basis and δ/δt rows for a coordinate system.

    ``J`` maps each coordinate name to ``(q, q̇, q̈)``; ``m`` is a module with
    ``sin``/``cos`` (numpy or sympy).  Returns a dict with ``basis`` (the
    three base vectors in Cartesian components) and the components on that
    basis of ``omega``, ``x``, ``dx`` (δx/δt), ``dv`` (δv/δt).

    >>> import math
    >>> rows = frame_rows("polar", {"r": (2.0, 0.0, 0.0), "theta": (0.0, 3.0, 0.0)}, math)
    >>> rows["omega"], rows["x"], rows["dv"]
    ((0.0, 0.0, 3.0), (2.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    """
    if coords == "cartesian":
        (x1, d1, a1), (x2, d2, a2), (x3, d3, a3) = J["x1"], J["x2"], J["x3"]
        z = 0 * x1
        return {
            "basis": ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
            "omega": (z, z, z), "x": (x1, x2, x3), "dx": (d1, d2, d3), "dv": (a1, a2, a3),
        }
    if coords in ("polar", "cylindrical"):
        r, rd, rdd = J["r"]
        th, thd, thdd = J["theta"]
        x3, x3d, x3dd = J.get("x3", (0 * r, 0 * r, 0 * r))
        c, s = m.cos(th), m.sin(th)
        z = 0 * r
        return {
            # e_r, e_θ (7.4a, 7.5a), e_3
            "basis": ((c, s, z), (-s, c, z), (z, z, z + 1)),
            "omega": (z, z, thd),                          # (10.10)
            "x": (r, z, x3),                               # (8.1)
            "dx": (rd, z, x3d),
            "dv": (rdd, rd * thd + r * thdd, x3dd),        # δ/δt of (ṙ, rθ̇, ẋ3)
        }
    if coords == "spherical":
        R, Rd, Rdd = J["R"]
        th, thd, thdd = J["theta"]
        ph, phd, phdd = J["phi"]
        ct, st, cp, sp = m.cos(th), m.sin(th), m.cos(ph), m.sin(ph)
        z = 0 * R
        return {
            # e_R, e_θ, e_φ (12.2a-c) with e_r = cosθ e1 + sinθ e2
            "basis": ((cp * ct, cp * st, sp), (-st, ct, z), (-sp * ct, -sp * st, cp)),
            "omega": (thd * sp, -phd, thd * cp),           # (12.8)
            "x": (R, z, z),                                # (12.1)
            "dx": (Rd, z, z),
            # δ/δt of v = (Ṙ, R θ̇ cosφ, R φ̇)
            "dv": (Rdd, Rd * thd * cp + R * thdd * cp - R * thd * phd * sp, Rd * phd + R * phdd),
        }
    raise AssertionError(coords)  # pragma: no cover


def to_cartesian(comps, basis):
    """Σ comps_i e'_i with the base vectors in Cartesian components.

    >>> to_cartesian((2.0, 0.0, 1.0), ((0.0, 1.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 0.0, 1.0)))
    (0.0, 2.0, 1.0)
    """
    return tuple(sum(comps[i] * basis[i][k] for i in range(3)) for k in range(3))


def tangential_normal(v, a):
    """(|v|, e_t, a_t, e_t×a, |a|) per row of v, a [m/s, m/s²]: v = ṡ e_t (5.14a), e_t = v/|v|,
    a_t = s̈ = a·e_t (5.14b).  e_t × a = (v×a)/|v| is formed from the scaled e_t, so a speed near
    the underflow (5e-324 m/s) keeps the digits of a_n and e_n.

    >>> sp, et, at, c, amag = tangential_normal(np.array([[2.0, 0, 0]]), np.array([[1.0, 3.0, 0]]))
    >>> sp.tolist(), at.tolist(), c.tolist()
    ([2.0], [1.0], [[0.0, 0.0, 3.0]])
    """
    speed = norm_rows(v)                       # lengths and directions scaled first (dyncli.direction)
    et = unit_rows(v)
    at = np.einsum("ij,ij->i", a, et)
    return speed, et, at, np.cross(et, a), norm_rows(a)


def normal_acceleration(c):
    """a_n = |e_t × a| = |v×a|/|v| = ṡ²/ρ [m/s²] (5.14b), from c = e_t × a (rows).

    >>> normal_acceleration(np.array([[0.0, 0.0, 3.0]])).tolist()
    [3.0]
    """
    return norm_rows(c)


def radius_of_curvature(speed, an):
    """ρ = ṡ²/a_n [m] (5.14b), formed as (|v|/a_n)|v| so that |v|² neither under- nor overflows.

    >>> radius_of_curvature(np.array([2.0]), np.array([3.0])).tolist()
    [1.3333333333333333]
    """
    return (speed / an) * speed


def principal_normal(c, an, et):
    """e_n = ((v×a)×v)/(|v×a||v|) = ((e_t×a)/a_n) × e_t, scaled first and normalised again (rows).

    >>> principal_normal(np.array([[0, 0, 3.0]]), np.array([3.0]), np.array([[1.0, 0, 0]])).tolist()
    [[0.0, 1.0, 0.0]]
    """
    return unit_rows(np.cross(c / an[:, None], et))
