"""3×3 matrices and 3-vectors as lists of plain floats (rows), for the inertia closed forms:
a composite body's tensor, its rotations and the change of basis need a few dozen products,
far cheaper than importing numpy.  Overflow gives inf or nan (Python's float arithmetic never
raises for + − ×), which the callers check.  Standard library only.
"""

from __future__ import annotations

import math


def eye() -> list[list[float]]:
    """The identity.

    >>> eye()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    """
    return [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]


def diag(d) -> list[list[float]]:
    """The diagonal matrix of d.

    >>> diag((1.0, 2.0, 3.0))[1]
    [0.0, 2.0, 0.0]
    """
    return [[float(d[i]) if i == j else 0.0 for j in range(3)] for i in range(3)]


def transpose(A) -> list[list[float]]:
    """Aᵀ.

    >>> transpose([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [7.0, 8.0, 9.0]])[0]
    [1.0, 4.0, 7.0]
    """
    return [[A[j][i] for j in range(3)] for i in range(3)]


def matmul(A, B) -> list[list[float]]:
    """A B, each entry summed in order.

    >>> matmul([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], diag((1.0, 2.0, 3.0)))[0]
    [0.0, -2.0, 0.0]
    """
    return [[A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j] for j in range(3)] for i in range(3)]


def matvec(A, x) -> list[float]:
    """A x.

    >>> matvec([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], (1.0, 2.0, 3.0))
    [-2.0, 1.0, 3.0]
    """
    return [A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2] for i in range(3)]


def column(A, k: int) -> list[float]:
    """The k-th column of A.

    >>> column(eye(), 2)
    [0.0, 0.0, 1.0]
    """
    return [A[i][k] for i in range(3)]


def det(A) -> float:
    """The determinant (cofactors along the first row).

    >>> det(diag((2.0, 3.0, -1.0)))
    -6.0
    """
    return (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
            - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
            + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))


def inverse_transpose(A) -> list[list[float]]:
    """A⁻ᵀ = cof(A)/det(A) (A invertible).

    >>> inverse_transpose(diag((2.0, 4.0, 0.5)))
    [[0.5, 0.0, 0.0], [0.0, 0.25, 0.0], [0.0, 0.0, 2.0]]
    """
    d = det(A)
    return [[(A[(i + 1) % 3][(j + 1) % 3] * A[(i + 2) % 3][(j + 2) % 3]
              - A[(i + 1) % 3][(j + 2) % 3] * A[(i + 2) % 3][(j + 1) % 3]) / d for j in range(3)] for i in range(3)]


def polar_rotation(M) -> list[list[float]]:
    """The orthogonal polar factor of a nearly orthogonal M (the nearest orthogonal matrix,
    U Vᵀ of the SVD): Newton's iteration Q ← ½(Q + Q⁻ᵀ), quadratically convergent from
    |MᵀM − 1| ≪ 1 (three or four steps to rounding).

    >>> Q = polar_rotation([[1.0, 1e-7, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    >>> max(abs(x - y) for r, s in zip(matmul(transpose(Q), Q), eye()) for x, y in zip(r, s)) < 1e-15
    True
    """
    Q = [[float(x) for x in r] for r in M]
    for _ in range(10):
        Qi = inverse_transpose(Q)
        new = [[0.5 * (Q[i][j] + Qi[i][j]) for j in range(3)] for i in range(3)]
        step = max(abs(new[i][j] - Q[i][j]) for i in range(3) for j in range(3))
        Q = new
        if step <= 4 * 2.220446049250313e-16:
            break
    return Q


def max_abs(x) -> float:
    """The largest |entry| of a (nested) list; 0 for an empty one.

    >>> max_abs([[1.0, -3.0], [2.0]])
    3.0
    """
    if isinstance(x, (list, tuple)):
        return max((max_abs(c) for c in x), default=0.0)
    return abs(x)


def finite(x) -> bool:
    """Every entry of a (nested) list is finite.

    >>> finite([[1.0, 2.0], [math.inf]])
    False
    """
    if isinstance(x, (list, tuple)):
        return all(finite(c) for c in x)
    return math.isfinite(x)
