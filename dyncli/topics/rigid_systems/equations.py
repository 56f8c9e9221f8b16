"""Systems of point masses and rigid bodies with massless links (notes §36): the closed forms
as pure functions on plain floats and tuples (no numpy, no pydantic, no renderer).
"""

from __future__ import annotations

from dyncli.direction import norm


def distance_from_axis(x, e) -> float:
    """d = |x − (x·e) e| [m]: the distance of the point x from the axis through the origin along
    the unit vector e (scaled norm: no overflow of d² before the square root; inf on overflow).

    >>> distance_from_axis((3.0, 4.0, 7.0), (0.0, 0.0, 1.0))
    5.0
    """
    xe = x[0] * e[0] + x[1] * e[1] + x[2] * e[2]      # overflow -> inf (never raises), checked by the caller
    return norm([xi - xe * ei for xi, ei in zip(x, e)])   # math.hypot of the normal component: no overflow of |perp|²


def spin_after(omega0: float, I_before: float, I_after: float) -> float:
    """ω₂ = ω₁ I₁/I₂ [rad/s] (36.22): H·e = I ω is conserved when no moment acts about the axis
    (36.11, 36.20-36.21).

    >>> spin_after(2.0, 3.0, 1.5)
    4.0
    """
    return omega0 * (I_before / I_after)


def axial_kinetic_energy(H: float, omega: float) -> float:
    """T = ½ I ω² = ½ H ω [J] (36.22), without overflow of ω² where T is representable.

    >>> axial_kinetic_energy(6.0, 2.0)
    6.0
    """
    return 0.5 * H * omega


def motor_axis_inertia(IA1: float, IA2: float, IB2: float, mA: float, L: float, s: float, c: float):
    """(mA L² + IA2, IA1 sin²α + (mA L² + IA2) cos²α + IB2) [kg·m²]: the inertia of body A about
    the orbit axis and of the whole system about the fixed axis e''₂ with A locked (36.39);
    s = sin α, c = cos α.

    >>> motor_axis_inertia(2.0, 1.0, 3.0, 1.0, 1.0, 1.0, 0.0)
    (2.0, 5.0)
    """
    I_orbit = mA * L * L + IA2                        # finite or inf, never raises
    return I_orbit, IA1 * s * s + I_orbit * c * c + IB2


def motor_base_spin(IA1: float, p: float, s: float, I_axis: float) -> float:
    """Ω = −IA1 p sin α / I_axis [rad/s] (36.40): H_O·e''₂ = 0 (36.31) with the motor spinning
    at p relative to the base.

    >>> motor_base_spin(2.0, 10.0, 0.5, 4.0)
    -2.5
    """
    return -IA1 * p * s / I_axis


def motor_angular_velocity(Omega: float, p: float, s: float, c: float) -> list[float]:
    """ω_A = [Ω sin α + p, Ω cos α, 0] [rad/s] on e'''ᵢ (36.25).

    >>> motor_angular_velocity(2.0, 1.0, 0.0, 1.0)
    [1.0, 2.0, 0.0]
    """
    return [Omega * s + p, Omega * c, 0.0]
