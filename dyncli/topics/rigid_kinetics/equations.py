"""Rigid-body kinetics (notes §13, §29, §32, §34): planar moments, kinetic energy, momentum
about a point and power as pure functions on floats and numpy arrays (no pydantic, no
renderer).  Components are on the body axes e'ᵢ of the inertia tensor Ī.  numpy is imported by
the functions that take arrays only: planar-moments' closed form needs none.
"""

from __future__ import annotations


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


def translational_kinetic_energy(m: float, v) -> float:
    """½ m v̄·v̄ [J] (34.6).

    >>> import numpy as np
    >>> translational_kinetic_energy(2.0, np.array([3.0, 4.0, 0.0]))
    25.0
    """
    return 0.5 * m * float(v @ v)


def rotational_kinetic_energy(w, H) -> float:
    """T̄ = ½ ω·Īω = ½ ω·H̄ [J] (34.7).

    >>> import numpy as np
    >>> rotational_kinetic_energy(np.array([0.0, 0.0, 2.0]), np.array([0.0, 0.0, 6.0]))
    6.0
    """
    return 0.5 * float(w @ H)


def angular_momentum_about(x, O, m: float, v, H):
    """(H_O, (x̄ − O) × m v̄) [kg·m²/s]: H_O = (x̄ − O) × m v̄ + H̄ (29.25).

    >>> import numpy as np
    >>> HO, orbit = angular_momentum_about(np.array([1.0, 0, 0]), np.zeros(3), 2.0, np.array([0, 1.0, 0]), np.zeros(3))
    >>> HO.tolist()
    [0.0, 0.0, 2.0]
    """
    import numpy as np

    orbit = np.cross(x - O, m * v)
    return orbit + H, orbit


def point_velocity(v, w, xi, x):
    """vᵢ = v̄ + ω × (xᵢ − x̄) [m/s] (13.8): the velocity of the body point xᵢ.

    >>> import numpy as np
    >>> point_velocity(np.zeros(3), np.array([0, 0, 1.0]), np.array([1.0, 0, 0]), np.zeros(3)).tolist()
    [0.0, 1.0, 0.0]
    """
    import numpy as np

    return v + np.cross(w, xi - x)


def kinetic_energy_and_rate(m: float, I, v, vd, w, wd):
    """(T, Ṫ) over time for v̄, dv̄/dt, ω, dω/dt of shape (3, n): T = ½ m v̄·v̄ + ½ ω·Īω and
    Ṫ = m v̄·dv̄/dt + ω·Ī dω/dt (34.13, 34.15), the power the loads must supply (34.16).

    >>> import numpy as np
    >>> T, Td = kinetic_energy_and_rate(2.0, np.eye(3), np.array([[1.0], [0], [0]]), np.array([[3.0], [0], [0]]),
    ...                                 np.zeros((3, 1)), np.zeros((3, 1)))
    >>> T.tolist(), Td.tolist()
    ([1.0], [6.0])
    """
    import numpy as np

    Iw, Iwd = I @ w, I @ wd
    T = 0.5 * m * np.einsum("it,it->t", v, v) + 0.5 * np.einsum("it,it->t", w, Iw)
    Td = m * np.einsum("it,it->t", v, vd) + np.einsum("it,it->t", w, Iwd)
    return T, Td
