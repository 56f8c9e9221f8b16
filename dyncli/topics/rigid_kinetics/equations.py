"""Rigid-body kinetics (notes §13, §29, §32, §34): planar moments, kinetic energy, momentum
about a point and power as pure functions on plain floats and 3-tuples (no numpy, no pydantic,
no renderer).  Components are on the body axes e'ᵢ of the inertia tensor Ī.
"""

from __future__ import annotations

from dyncli.vec3 import add, cross, scale, sub


def planar_angular_momentum(I13: float, I23: float, I33: float, w: float) -> list[float]:
    """H̄ = [Ī'13 ω, Ī'23 ω, Ī'33 ω] [kg·m²/s] (32.9) for ω = ω e'₃.

    >>> planar_angular_momentum(0.0, 1.0, 2.0, 3.0)
    [0.0, 3.0, 6.0]
    """
    return [I13 * w, I23 * w, I33 * w]


def planar_moments(I13: float, I23: float, I33: float, w: float, wd: float) -> list[float]:
    """M̄ = [Ī'13 ω̇ − Ī'23 ω², Ī'23 ω̇ + Ī'13 ω², Ī'33 ω̇] [N·m] (32.12, 32.13a-c): the moment about
    the center of mass that a planar motion about e'₃ needs.

    >>> planar_moments(1.0, 0.0, 2.0, 3.0, 0.5)
    [0.5, 9.0, 1.0]
    """
    return [I13 * wd - I23 * w * w, I23 * wd + I13 * w * w, I33 * wd]


def dot(a, b) -> float:
    """a·b, summed in order (inf or nan on overflow, never an exception).

    >>> dot((1.0, 2.0, 3.0), (4.0, 5.0, 6.0))
    32.0
    """
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def matvec(I, w) -> tuple[float, float, float]:
    """Ī ω: the rows of the 3×3 I dotted with ω (30.12a).

    >>> matvec(((2.0, 0.0, 0.0), (0.0, 3.0, 1.0), (0.0, 1.0, 4.0)), (1.0, 1.0, 1.0))
    (2.0, 4.0, 5.0)
    """
    return (dot(I[0], w), dot(I[1], w), dot(I[2], w))


def translational_kinetic_energy(m: float, v) -> float:
    """½ m v̄·v̄ [J] (34.6).

    >>> translational_kinetic_energy(2.0, (3.0, 4.0, 0.0))
    25.0
    """
    return 0.5 * m * dot(v, v)


def rotational_kinetic_energy(w, H) -> float:
    """T̄ = ½ ω·Īω = ½ ω·H̄ [J] (34.7).

    >>> rotational_kinetic_energy((0.0, 0.0, 2.0), (0.0, 0.0, 6.0))
    6.0
    """
    return 0.5 * dot(w, H)


def angular_momentum_about(x, O, m: float, v, H):
    """(H_O, (x̄ − O) × m v̄) [kg·m²/s]: H_O = (x̄ − O) × m v̄ + H̄ (29.25).

    >>> angular_momentum_about((1.0, 0.0, 0.0), (0.0, 0.0, 0.0), 2.0, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0))[0]
    (0.0, 0.0, 2.0)
    """
    orbit = cross(sub(x, O), scale(v, m))
    return add(orbit, H), orbit


def point_velocity(v, w, xi, x):
    """vᵢ = v̄ + ω × (xᵢ − x̄) [m/s] (13.8): the velocity of the body point xᵢ.

    >>> point_velocity((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    (0.0, 1.0, 0.0)
    """
    return add(v, cross(w, sub(xi, x)))


def kinetic_energy_and_rate(m: float, I, v, vd, w, wd) -> tuple[float, float]:
    """(T, Ṫ) at one time from v̄, dv̄/dt, ω, dω/dt: T = ½ m v̄·v̄ + ½ ω·Īω and
    Ṫ = m v̄·dv̄/dt + ω·Ī dω/dt (34.13, 34.15), the power the loads must supply (34.16).

    >>> kinetic_energy_and_rate(2.0, ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
    ...                         (1.0, 0.0, 0.0), (3.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    (1.0, 6.0)
    """
    T = 0.5 * m * dot(v, v) + 0.5 * dot(w, matvec(I, w))
    Td = m * dot(v, vd) + dot(w, matvec(I, wd))
    return T, Td
