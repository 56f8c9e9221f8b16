"""Spinning arms on a shaft (notes §36, Table 36.1): the closed forms as pure functions on plain
floats at one time (no numpy, no pydantic, no renderer).

A mass m at x = L (sin α e'₁ + cos α e'₂) on a shaft turning with ω = ω e'₂; s = sin α,
c = cos α, ad = α̇, add = α̈, wd = ω̇.  Components are on the turning basis e'ᵢ; vectors are
3-tuples.
"""

from __future__ import annotations

from dyncli.vec3 import cross, sub


def arm_velocity(L, s, c, ad, w):
    """v = δx/δt + ω×x = [L α̇ cos α, −L α̇ sin α, −ω L sin α] [m/s] (Table 36.1, 11.4).

    >>> arm_velocity(2.0, 1.0, 0.0, 3.0, 5.0)
    (0.0, -6.0, -10.0)
    """
    return (L * ad * c, -L * ad * s, -w * L * s)


def arm_velocity_rate(L, s, c, ad, add, w, wd):
    """δv/δt [m/s²]: the rate of the components of v of :func:`arm_velocity`.

    >>> arm_velocity_rate(1.0, 0.0, 1.0, 0.0, 2.0, 3.0, 0.0)
    (2.0, -0.0, -0.0)
    """
    return (L * (add * c - ad * ad * s), -L * (add * s + ad * ad * c), -L * (wd * s + w * ad * c))


def arm_angular_momentum(mL2, s, c, ad, w):
    """x × m v = m L² [−ω sin α cos α, ω sin²α, −α̇] [kg·m²/s] (Table 36.1, 36.14); mL2 = m L².

    >>> arm_angular_momentum(2.0, 1.0, 0.0, 3.0, 5.0)
    (-0.0, 10.0, -6.0)
    """
    return (mL2 * (-w * s * c), mL2 * (w * s * s), mL2 * -ad)


def arm_angular_momentum_rate(mL2, s, c, ad, add, w, wd):
    """δ(x × m v)/δt [N·m]: the rate of the components of :func:`arm_angular_momentum`.

    >>> arm_angular_momentum_rate(1.0, 1.0, 0.0, 0.0, 1.0, 2.0, 3.0)
    (-0.0, 3.0, -1.0)
    """
    return (mL2 * -(wd * s * c + w * ad * (c * c - s * s)), mL2 * (wd * s * s + 2.0 * w * ad * s * c), mL2 * -add)


def spin_cross(w, X):
    """ω e'₂ × X (the second term of the general operator, 11.4).

    >>> spin_cross(2.0, (1.0, 5.0, 3.0))
    (6.0, 0.0, -2.0)
    """
    return (w * X[2], 0.0, -w * X[0])


def free_shaft_rate(H, I):
    """ω = H/I [rad/s] (36.22): H_O·e'₂ = I ω is constant when M_O·e'₂ = 0 (36.19, 36.21).

    >>> free_shaft_rate(6.0, 2.0)
    3.0
    """
    return H / I


def bearing_moment(M, x1, F):
    """M₁ = M_O − x₁ × F₁ [N·m] (36.16b): the moment the bearing at x₁ carries, F₁ = F.

    >>> bearing_moment((0.0, 0.0, 0.0), (0.0, -1.0, 0.0), (1.0, 0.0, 0.0))
    (0.0, 0.0, -1.0)
    """
    return sub(M, cross(x1, F))


def turn_about_axis(X, cb, sb):
    """X from the arm's own plane basis (u, e'₂, u × e'₂), u = cos β e'₁ + sin β e'₃, to e'ᵢ: a
    rotation about the spin axis, so it commutes with δ/δt and ω e'₂ × (cb = cos β, sb = sin β).

    >>> turn_about_axis((1.0, 2.0, 3.0), 0.0, 1.0)
    (-3.0, 2.0, 1.0)
    """
    return (cb * X[0] - sb * X[2], X[1], sb * X[0] + cb * X[2])


def two_bearings(F, M, yA, yB):
    """(F_A, F_B) [N]: the forces of two bearings at y_A e'₂, y_B e'₂ (y_A ≠ y_B) that together
    apply the force F and, about O, the moment M transverse to the shaft:
    F_A + F_B = F and y_A e'₂ × F_A + y_B e'₂ × F_B = (M₁, 0, M₃), with e'₂ × F = (F₃, 0, −F₁);
    A takes the axial component F₂ (a thrust bearing), M₂ is the drive's torque.

    >>> two_bearings((10.0, 0.0, 0.0), (0.0, 0.0, -5.0), 0.0, 1.0)
    ((5.0, 0.0, 0.0), (5.0, 0.0, 0.0))
    """
    d = yB - yA
    b3 = (M[0] - yA * F[2]) / d
    b1 = (-M[2] - yA * F[0]) / d
    return (F[0] - b1, F[1], F[2] - b3), (b1, 0.0, b3)
