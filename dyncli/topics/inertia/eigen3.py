"""The symmetric 3×3 eigenproblem in plain floats (no numpy): cyclic Jacobi rotations.

Jacobi's method is backward stable: each computed eigenvalue is within a few ulp × ‖A‖ of the
exact one (the bound ``numpy.linalg.eigh`` also gives), and the eigenvectors are orthonormal to
a few ulp.  The tensor is scaled by its largest entry first, so entries near the overflow or
underflow thresholds (1e±300 kg·m²) are as accurate as moderate ones.  Standard library only:
the closed forms that only check or use the principal moments (``rigid-energy``, the
positive-semidefinite check of an inertia tensor) need no numpy.
"""

from __future__ import annotations

import math

Matrix = tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float]]

#: sweeps of the cyclic Jacobi method: it converges quadratically, 3-6 sweeps in double precision
MAX_SWEEPS = 30
_PAIRS = ((0, 1), (0, 2), (1, 2))


def sym3(T) -> Matrix:
    """½ (T + Tᵀ) as a tuple of row tuples.

    >>> sym3([[1, 2, 0], [0, 1, 0], [0, 0, 1]])
    ((1.0, 1.0, 0.0), (1.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    """
    return tuple(tuple(0.5 * (float(T[i][j]) + float(T[j][i])) for j in range(3)) for i in range(3))  # type: ignore[return-value]  # 3 rows of 3: mypy reads tuple(generator) as tuple[float, ...]


def _rotation(app: float, aqq: float, apq: float) -> tuple[float, float]:
    """(c, s) of the Jacobi rotation that annihilates apq (the smaller angle, |θ| ≤ π/4)."""
    theta = (aqq - app) / (2.0 * apq)
    if abs(theta) > 1e150:                     # θ² would overflow: t = 1/(2θ) to full precision
        t = 0.5 / theta
    else:
        t = math.copysign(1.0, theta) / (abs(theta) + math.sqrt(theta * theta + 1.0))
    c = 1.0 / math.sqrt(t * t + 1.0)
    return c, t * c


def eigh3(T) -> tuple[list[float], list[list[float]]]:
    """Eigenvalues (ascending) and orthonormal eigenvectors (the columns of V, as rows V[i][k]:
    component i of vector k) of the symmetric part of T; all nan when an entry is not finite.

    >>> w, V = eigh3([[2.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 5.0]])
    >>> [round(x, 15) for x in w]
    [1.0, 3.0, 5.0]
    """
    A = [list(r) for r in sym3(T)]
    if not all(math.isfinite(x) for r in A for x in r):
        return [math.nan] * 3, [[math.nan] * 3 for _ in range(3)]
    top = max(abs(x) for r in A for x in r)
    V = [[1.0 if i == k else 0.0 for k in range(3)] for i in range(3)]
    if top == 0.0:
        return [0.0, 0.0, 0.0], V
    big = math.ldexp(1.0, math.frexp(top)[1])  # a power of two: the scaling is exact
    A = [[x / big for x in r] for r in A]      # |entries| < 1: no overflow or underflow of the squares
    for _ in range(MAX_SWEEPS):
        if all(abs(A[p][q]) <= 1e-18 * (abs(A[p][p]) + abs(A[q][q])) or abs(A[p][q]) < 1e-300 for p, q in _PAIRS):
            break
        for p, q in _PAIRS:
            apq = A[p][q]
            if apq == 0.0:
                continue
            c, s = _rotation(A[p][p], A[q][q], apq)
            t = s / c
            r = 3 - p - q                      # the third index
            arp, arq = A[r][p], A[r][q]
            A[p][p] -= t * apq
            A[q][q] += t * apq
            A[p][q] = A[q][p] = 0.0
            A[r][p] = A[p][r] = c * arp - s * arq
            A[r][q] = A[q][r] = s * arp + c * arq
            for row in V:
                vp, vq = row[p], row[q]
                row[p], row[q] = c * vp - s * vq, s * vp + c * vq
    order = sorted(range(3), key=lambda k: A[k][k])
    w = [A[k][k] * big for k in order]
    return w, [[row[k] for k in order] for row in V]


def eigvalsh3(T) -> list[float]:
    """The eigenvalues (ascending) of the symmetric part of T.

    >>> eigvalsh3([[3e200, 0.0, 0.0], [0.0, -1e200, 0.0], [0.0, 0.0, 2e200]])
    [-1e+200, 2e+200, 3e+200]
    """
    return eigh3(T)[0]


def inertia_defect(T) -> tuple[float, float, float]:
    """For a symmetric tensor, return (smallest eigenvalue, triangle defect,
    scale): the tensor is a physical inertia tensor when the smallest
    eigenvalue is >= 0 and the triangle defect max(I3 − I1 − I2, 0) is 0
    (eigenvalues ascending); ``scale`` is the largest |eigenvalue|.

    >>> inertia_defect([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 3.0]])
    (1.0, 1.0, 3.0)
    """
    w = eigvalsh3(T)
    if math.isnan(w[0]):
        return math.nan, math.nan, math.nan
    return w[0], w[2] - w[0] - w[1], max(abs(x) for x in w)
