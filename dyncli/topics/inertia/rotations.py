"""Rotations and symmetric-tensor helpers for inertia problems, in plain floats (no numpy:
matrices are lists of rows, :mod:`dyncli.topics.inertia.mat3`; the eigenproblem is
:mod:`dyncli.topics.inertia.eigen3`'s Jacobi method).

Every rotation here is a 3x3 matrix ``R`` whose COLUMNS are the rotated
axes expressed in the components of the reference basis (the body basis
e'_i).  A tensor with components ``T_part`` on the rotated axes has body
components ``R T_part Rᵀ``; conversely the components on a basis
e''_i = columns of ``R`` are ``Rᵀ T R`` (30.36: A = Rᵀ).
"""

from __future__ import annotations

import math

from dyncli.topics.inertia import mat3
from dyncli.topics.inertia.eigen3 import eigh3, sym3
from dyncli.topics.inertia.eigen3 import inertia_defect  # noqa: F401  (one definition, plain floats)
from dyncli.vec3 import cross

EPS = 2.220446049250313e-16
#: largest admissible deviation max|RᵀR − 1| of a user-given rotation matrix
ORTHONORMAL_TOL = 1e-6
Matrix = list  # 3 rows of 3 floats


def rot_axis(axis, angle: float) -> Matrix:
    """Right-handed rotation by ``angle`` about ``axis`` (Rodrigues).

    >>> [[round(x, 15) + 0.0 for x in r] for r in rot_axis([0, 0, 2], math.pi / 2)]
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    """
    from dyncli.direction import unit

    k = unit(axis, what="rotation axis")    # scaled: [1e200, 0, 0] and [1e-200, 0, 0] are e1
    c, s = math.cos(angle), math.sin(angle)
    K = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]]
    return [[(c * (i == j) + s * K[i][j]) + (1.0 - c) * (k[i] * k[j]) for j in range(3)] for i in range(3)]


def rot_x(a: float) -> Matrix:
    c, s = math.cos(a), math.sin(a)
    return [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]


def rot_z(a: float) -> Matrix:
    c, s = math.cos(a), math.sin(a)
    return [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]


def euler313(psi: float, theta: float, phi: float) -> Matrix:
    """The notes' 3-1-3 sequence (38.3)-(38.5): ψ about e3, θ about e'''_1,
    φ about e''_3.  Columns of the result are the final axes e'_i in the
    components of the starting basis, i.e. the transpose of the product of
    the matrices (38.6a-c)."""
    return mat3.matmul(mat3.matmul(rot_z(psi), rot_x(theta)), rot_z(phi))


def check_rotation(R) -> Matrix:
    """Validate a user matrix (columns = axes).  Returns the nearest exact
    rotation (polar factor) or raises ValueError with a clear message."""
    if len(R) != 3 or any(len(r) != 3 for r in R) or not mat3.finite(R):
        raise ValueError("a rotation matrix must be a 3x3 list of finite numbers")
    M = [[float(x) for x in r] for r in R]
    MtM = mat3.matmul(mat3.transpose(M), M)
    dev = max(abs(MtM[i][j] - (i == j)) for i in range(3) for j in range(3))
    if dev > ORTHONORMAL_TOL:
        norms = [math.hypot(*mat3.column(M, j)) for j in range(3)]
        bad = [f"column {j + 1} has length {norms[j]:.6g}" for j in range(3) if abs(norms[j] - 1.0) > ORTHONORMAL_TOL]
        for i in range(3):
            for j in range(i + 1, 3):
                d = sum(a * b for a, b in zip(mat3.column(M, i), mat3.column(M, j)))
                if abs(d) > ORTHONORMAL_TOL:
                    bad.append(f"columns {i + 1} and {j + 1} have dot product {d:.6g}")
        raise ValueError(
            "matrix is not orthonormal (max |RᵀR − 1| = "
            f"{dev:.3g} > {ORTHONORMAL_TOL:g}): " + "; ".join(bad)
            + ". Its columns must be unit, mutually perpendicular axes; write exact entries such as \"sqrt(2)/2\" or \"cos(30*deg)\""
        )
    det = mat3.det(M)
    if det < 0:
        raise ValueError(
            f"matrix has determinant {det:.6g}: it is a reflection, not a rotation; "
            "its columns must form a right-handed set (e3 = e1 × e2)"
        )
    return mat3.polar_rotation(M)     # nearest proper rotation (removes the rounding of typed entries)


def sym(T) -> Matrix:
    """½ (T + Tᵀ) as a list of rows."""
    return [list(r) for r in sym3(T)]


def transfer_term(m: float, p) -> Matrix:
    """m[(p·p)1 − p⊗p] (31.7); inf or nan on overflow (checked by the caller).

    >>> transfer_term(2.0, (0.0, 0.0, 1.0))
    [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 0.0]]
    """
    pp = p[0] * p[0] + p[1] * p[1] + p[2] * p[2]
    return [[m * (pp * (i == j) - p[i] * p[j]) for j in range(3)] for i in range(3)]


def _canonical_pair(V, g):
    """The canonical basis of a 2-dimensional eigenspace (columns g of V): the normalised
    projections of the reference axes onto it, largest first, orthogonalised."""
    P = [[sum(V[i][k] * V[j][k] for k in g) for j in range(3)] for i in range(3)]
    cols: list[list[float]] = []
    for _ in g:
        Pr = [[P[i][j] - sum(c[i] * c[j] for c in cols) for j in range(3)] for i in range(3)]
        norms = [math.sqrt(sum(Pr[i][j] * Pr[i][j] for i in range(3))) for j in range(3)]
        top = max(norms)
        j = next(k for k in range(3) if norms[k] >= top * (1 - 1e-12))
        cols.append([Pr[i][j] / norms[j] for i in range(3)])
    return cols


def _groups(w, tol: float) -> list[list[int]]:
    groups: list[list[int]] = [[0]]
    for k in range(1, 3):
        if w[k] - w[groups[-1][-1]] <= tol:
            groups[-1].append(k)
        else:
            groups.append([k])
    return groups


def principal(T, *, repeat_rtol: float = 1e-10):
    """Principal moments (ascending) and axes of a symmetric tensor.

    Axes are the columns of a proper rotation: columns 1 and 2 are signed so
    that their component of largest magnitude is positive (the first such
    component on a tie), and column 3 = column 1 × column 2.  Within a group
    of repeated moments (relative gap <= ``repeat_rtol``) the basis of the
    eigenspace is not unique; a canonical one is chosen: the normalised
    projections of the reference axes e_1, e_2, e_3 onto the eigenspace,
    largest first, orthogonalised.

    Returns (moments, axes, groups, scale) where ``groups`` lists the index
    groups of repeated moments (each a list of 0-based indices).

    >>> w, axes, groups, scale = principal([[2.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]])
    >>> w, axes, groups
    ([1.0, 1.0, 2.0], [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [[0, 1]])
    """
    w, V = eigh3(sym3(T))
    scale = max(abs(x) for x in w)
    if scale == 0.0:
        return [0.0, 0.0, 0.0], mat3.eye(), [[0, 1, 2]], 0.0
    # snap eigenvalues that are zero to rounding (collinear masses)
    w = [0.0 if abs(x) <= 64 * EPS * scale else x for x in w]
    groups = _groups(w, repeat_rtol * scale)
    axes = [list(r) for r in V]
    for g in groups:
        if len(g) == 3:
            axes = mat3.eye()
            w = [(w[0] + w[1] + w[2]) / 3.0] * 3  # exactly repeated within the tolerance
        elif len(g) == 2:
            for k, c in zip(g, _canonical_pair(V, g)):
                for i in range(3):
                    axes[i][k] = c[i]
            w[g[0]] = w[g[1]] = (w[g[0]] + w[g[1]]) / 2.0
    for k in (0, 1):
        c = mat3.column(axes, k)
        amax = max(abs(x) for x in c)
        j = next(i for i in range(3) if abs(c[i]) >= amax * (1 - 1e-12))
        if c[j] < 0:
            for i in range(3):
                axes[i][k] = -c[i]
    c3 = cross(mat3.column(axes, 0), mat3.column(axes, 1))
    for i in range(3):
        axes[i][2] = c3[i]
    return w, axes, [g for g in groups if len(g) > 1], scale


def clean(x, scale: float, rel: float = 64 * EPS):
    """Floats as plain Python lists with entries below rounding noise
    (``rel * scale``) set to 0.0 (also removes negative zeros).

    >>> clean([[1.0, -1e-20], [-0.0, 2.0]], 1.0)
    [[1.0, 0.0], [0.0, 2.0]]
    """
    if isinstance(x, (list, tuple)):
        return [clean(c, scale, rel) for c in x]
    x = float(x)
    return (0.0 if abs(x) <= rel * scale else x) + 0.0


def from_fields(axis=None, angle=None, euler313=None, matrix=None) -> Matrix:
    """Rotation from exactly one of the contract's forms:
    ``{axis, angle}``, ``{euler313: [psi, theta, phi]}``, ``{matrix: R}``."""
    given = [name for name, v in (("axis/angle", axis if axis is not None else angle),
                                  ("euler313", euler313), ("matrix", matrix)) if v is not None]
    if len(given) != 1:
        raise ValueError("an orientation is exactly one of {axis: [..], angle: ..}, "
                         "{euler313: [psi, theta, phi]} or {matrix: R}"
                         + (f" (got {' and '.join(given)})" if given else ""))
    if given[0] == "axis/angle":
        if axis is None:
            raise ValueError("'angle' needs an 'axis' to rotate about, e.g. axis: [0, 0, 1]")
        if angle is None:
            raise ValueError("'axis' needs an 'angle' (radians; e.g. \"30*deg\")")
        return rot_axis(axis, angle)
    if given[0] == "euler313":
        psi, theta, phi = (float(x) for x in euler313)
        return mat3.matmul(mat3.matmul(rot_z(psi), rot_x(theta)), rot_z(phi))
    return check_rotation(matrix)
