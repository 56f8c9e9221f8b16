"""A particle under forces (notes §16, §19-§21): the equations as pure functions on arrays.

Vectors are numpy arrays of shape (3,) or (3, n) (one column per time); no pydantic, no
renderer.  :mod:`dyncli.topics.particle.forces` assembles the force terms of a problem from
these, and the solver reports the energies and the angular momentum through them.
"""

from __future__ import annotations

import numpy as np


def distance(r):
    """R = |r| [m] of a vector or of each column of a 3 × n array.

    >>> float(distance(np.array([3.0, 4.0, 0.0])))
    5.0
    """
    return np.sqrt((r * r).sum(axis=0))


def gravity_potential(weight: float, x3):
    """V = m g x3 [J] (19.23), with weight = m g [N] and x3 the height [m].

    >>> gravity_potential(19.62, 2.0)
    39.24
    """
    return weight * x3


def inverse_square_force(mu: float, r):
    """F = −μ r/R³ [N] (19.18) with μ = m g R0² [N·m²] and r the position from the centre.

    >>> inverse_square_force(8.0, np.array([2.0, 0.0, 0.0])).tolist()
    [-2.0, -0.0, -0.0]
    """
    R = distance(r)
    return -(mu * r / R ** 3)


def inverse_square_potential(mu: float, r):
    """V = −μ/R [J] (19.20b), μ = m g R0².

    >>> float(inverse_square_potential(8.0, np.array([0.0, 2.0, 0.0])))
    -4.0
    """
    return -(mu / distance(r))


def spring_force(k: float, L: float, r, side: str | None = None):
    """F = −k (R − L) r/R [N] (19.26a): a linear spring of stiffness k [N/m] and free length
    L [m], r from the anchor; −k r when L = 0 (no division by R, so R = 0 is fine).  A one-sided
    spring (``side``) acts only while it is compressed (R < L) or stretched (R > L): its force is
    continuous (zero at R = L).

    >>> spring_force(10.0, 1.0, np.array([0.0, 0.0, 3.0])).tolist()
    [-0.0, -0.0, -20.0]
    >>> spring_force(10.0, 0.0, np.array([0.0, 0.0, 0.0])).tolist()
    [-0.0, -0.0, -0.0]
    >>> spring_force(10.0, 1.0, np.array([0.0, 0.0, 3.0]), "compression").tolist()
    [-0.0, -0.0, -0.0]
    """
    if L == 0.0:
        return -(k * r) * engaged(side, distance(r), L)
    R = distance(r)
    return -(k * (R - L) * r / R) * engaged(side, R, L)


def spring_potential(k: float, L: float, r, side: str | None = None):
    """V = ½ k (R − L)² [J] (19.26b); of a one-sided spring only while it acts (zero beyond).

    >>> float(spring_potential(10.0, 1.0, np.array([0.0, 0.0, 3.0])))
    20.0
    >>> float(spring_potential(10.0, 1.0, np.array([0.0, 0.0, 0.5]), "compression"))
    1.25
    """
    R = distance(r)
    return 0.5 * k * (R - L) ** 2 * engaged(side, R, L)


def engaged(side: str | None, R, L: float):
    """1 where a spring acts, 0 where a one-sided one is slack: ``compression`` acts for R < L
    (it only pushes), ``tension`` for R > L (it only pulls, an elastic cord); None: always.

    >>> engaged("compression", np.array([0.5, 1.5]), 1.0).tolist()
    [1.0, 0.0]
    """
    if side is None:
        return 1.0
    return np.where(R < L, 1.0, 0.0) if side == "compression" else np.where(R > L, 1.0, 0.0)


def kinetic_energy(m: float, v):
    """T = ½ m v·v [J] (20.4) of each column of v [m/s].

    >>> kinetic_energy(2.0, np.array([[3.0, 0.0], [4.0, 1.0], [0.0, 0.0]])).tolist()
    [25.0, 1.0]
    """
    return 0.5 * m * (v * v).sum(axis=0)


def angular_momentum(m: float, x, v):
    """H_O = x × m v [kg·m²/s] (21.3) for 3 × n arrays of positions and velocities.

    >>> angular_momentum(2.0, np.array([[1.0], [0.0], [0.0]]), np.array([[0.0], [3.0], [0.0]])).ravel().tolist()
    [0.0, 0.0, 6.0]
    """
    x1, x2, x3 = x
    v1, v2, v3 = v
    return m * np.array([x2 * v3 - x3 * v2, x3 * v1 - x1 * v3, x1 * v2 - x2 * v1])


def energy_residual(E, E1: float, W_nc):
    """max |E − E₁ − W̄| [J]: the departure from the work-energy equation E − E₁ = W̄ (20.4),
    zero for the exact motion.

    >>> energy_residual(np.array([1.0, 0.5]), 1.0, np.array([0.0, -0.25]))
    0.25
    """
    return float(abs(E - E1 - W_nc).max())
