"""Inertia of simple shapes and composite bodies (notes §30, §31): pure functions on plain floats,
3-vectors and 3×3 matrices as lists of rows (no numpy, no pydantic, no renderer).

The principal moments of the standard shapes are about the shape's own center of mass, on its
own axes with e3 the axis of symmetry [kg·m²]; the composite body is assembled in
:mod:`dyncli.topics.inertia.solver` with the transfer theorem (31.7) of
:func:`dyncli.topics.inertia.rotations.transfer_term`.
"""

from __future__ import annotations

import math

from dyncli.topics.inertia import mat3


def rod_moments(m: float, L: float):
    """(mL²/12, mL²/12, 0): a slender rod of length L [m] along e3.

    >>> rod_moments(12.0, 1.0)
    (1.0, 1.0, 0.0)
    """
    t = m * L**2 / 12.0
    return (t, t, 0.0)


def box_moments(m: float, a: float, b: float, c: float):
    """(m(b² + c²)/12, m(a² + c²)/12, m(a² + b²)/12): a box with edges a, b, c [m] along e1, e2, e3.

    >>> box_moments(12.0, 1.0, 2.0, 3.0)
    (13.0, 10.0, 5.0)
    """
    return (m * (b * b + c * c) / 12.0, m * (a * a + c * c) / 12.0, m * (a * a + b * b) / 12.0)


def cylinder_moments(m: float, r: float, h: float):
    """(m(3r² + h²)/12, same, mr²/2): a solid cylinder of radius r and height h [m], axis e3.

    >>> cylinder_moments(12.0, 1.0, 3.0)
    (12.0, 12.0, 6.0)
    """
    t = m * (3.0 * r * r + h * h) / 12.0
    return (t, t, m * r * r / 2.0)


def disk_moments(m: float, r: float):
    """(mr²/4, mr²/4, mr²/2): a thin disk of radius r [m] in the e1-e2 plane.

    >>> disk_moments(4.0, 1.0)
    (1.0, 1.0, 2.0)
    """
    r2 = r**2
    return (m * r2 / 4.0, m * r2 / 4.0, m * r2 / 2.0)


def ring_moments(m: float, r: float):
    """(mr²/2, mr²/2, mr²): a thin ring of radius r [m] in the e1-e2 plane.

    >>> ring_moments(2.0, 1.0)
    (1.0, 1.0, 2.0)
    """
    r2 = r**2
    return (m * r2 / 2.0, m * r2 / 2.0, m * r2)


def sphere_moments(m: float, r: float):
    """(2mr²/5,) × 3: a solid sphere of radius r [m].

    >>> sphere_moments(5.0, 1.0)
    (2.0, 2.0, 2.0)
    """
    t = 2.0 * m * r**2 / 5.0
    return (t, t, t)


def shell_moments(m: float, r: float):
    """(2mr²/3,) × 3: a thin spherical shell of radius r [m].

    >>> shell_moments(3.0, 1.0)
    (2.0, 2.0, 2.0)
    """
    t = 2.0 * m * r**2 / 3.0
    return (t, t, t)


def rotated(R, I):
    """I' = R I Rᵀ (30.37): a tensor given on a part's axes (the columns of R) expressed on the
    body axes; with R = Aᵀ the change of basis I'' = A I' Aᵀ (30.36).

    >>> R = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    >>> [row[i] for i, row in enumerate(rotated(R, mat3.diag([1.0, 2.0, 3.0])))]
    [2.0, 1.0, 3.0]
    """
    return mat3.matmul(mat3.matmul(R, I), mat3.transpose(R))


def center_of_mass(signed_masses, xs, m: float):
    """x̄ = Σ ±mᵢ xᵢ / m [m] (holes count with negative mass, 31.3), m = Σ ±mᵢ.

    >>> center_of_mass([1.0, 3.0], [[0.0, 0, 0], [4.0, 0, 0]], 4.0)
    [3.0, 0.0, 0.0]
    """
    return [sum(sm * x[i] for sm, x in zip(signed_masses, xs)) / m for i in range(3)]


def radius_of_gyration(I: float, m: float) -> float:
    """k = (I/m)^½ [m] (30.8); 0 for a zero moment.

    >>> radius_of_gyration(8.0, 2.0)
    2.0
    """
    return math.sqrt(I / m) if I > 0 else 0.0
