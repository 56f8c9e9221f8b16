"""Rotations and symmetric-tensor helpers for inertia problems (numpy only).

Every rotation here is a 3x3 matrix ``R`` whose COLUMNS are the rotated
axes expressed in the components of the reference basis (the body basis
e'_i).  A tensor with components ``T_part`` on the rotated axes has body
components ``R @ T_part @ R.T``; conversely the components on a basis
e''_i = columns of ``R`` are ``R.T @ T @ R`` (30.36: A = R.T).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.topics.inertia.eigen3 import inertia_defect  # noqa: F401  (one definition, plain floats)

#: largest admissible deviation max|RᵀR − 1| of a user-given rotation matrix
ORTHONORMAL_TOL = 1e-6


def rot_axis(axis, angle: float) -> np.ndarray:
    """Right-handed rotation by ``angle`` about ``axis`` (Rodrigues)."""
    from dyncli.direction import unit

    k = unit(axis, what="rotation axis")    # scaled: [1e200, 0, 0] and [1e-200, 0, 0] are e1
    c, s = math.cos(angle), math.sin(angle)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return c * np.eye(3) + s * K + (1.0 - c) * np.outer(k, k)


def rot_x(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_z(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def euler313(psi: float, theta: float, phi: float) -> np.ndarray:
    """The notes' 3-1-3 sequence (38.3)-(38.5): ψ about e3, θ about e'''_1,
    φ about e''_3.  Columns of the result are the final axes e'_i in the
    components of the starting basis, i.e. the transpose of the product of
    the matrices (38.6a-c)."""
    return rot_z(psi) @ rot_x(theta) @ rot_z(phi)


def check_rotation(R) -> np.ndarray:
    """Validate a user matrix (columns = axes).  Returns the nearest exact
    rotation (polar factor) or raises ValueError with a clear message."""
    M = np.asarray(R, dtype=float)
    if M.shape != (3, 3) or not np.all(np.isfinite(M)):
        raise ValueError("a rotation matrix must be a 3x3 list of finite numbers")
    dev = float(np.max(np.abs(M.T @ M - np.eye(3))))
    if dev > ORTHONORMAL_TOL:
        norms = np.linalg.norm(M, axis=0)
        bad = [f"column {j + 1} has length {norms[j]:.6g}" for j in range(3) if abs(norms[j] - 1.0) > ORTHONORMAL_TOL]
        for i in range(3):
            for j in range(i + 1, 3):
                d = float(M[:, i] @ M[:, j])
                if abs(d) > ORTHONORMAL_TOL:
                    bad.append(f"columns {i + 1} and {j + 1} have dot product {d:.6g}")
        raise ValueError(
            "matrix is not orthonormal (max |RᵀR − 1| = "
            f"{dev:.3g} > {ORTHONORMAL_TOL:g}): " + "; ".join(bad)
            + ". Its columns must be unit, mutually perpendicular axes; write exact entries such as \"sqrt(2)/2\" or \"cos(30*deg)\""
        )
    det = float(np.linalg.det(M))
    if det < 0:
        raise ValueError(
            f"matrix has determinant {det:.6g}: it is a reflection, not a rotation; "
            "its columns must form a right-handed set (e3 = e1 × e2)"
        )
    # nearest proper rotation (removes the rounding of typed entries)
    U, _, Vt = np.linalg.svd(M)
    Q = U @ Vt
    if np.linalg.det(Q) < 0:  # pragma: no cover - excluded by the det check
        U[:, -1] = -U[:, -1]
        Q = U @ Vt
    return Q


def sym(T) -> np.ndarray:
    A = np.asarray(T, dtype=float)
    return 0.5 * (A + A.T)


def transfer_term(m: float, p) -> np.ndarray:
    """m[(p·p)1 − p⊗p] (31.7)."""
    p = np.asarray(p, dtype=float)
    with np.errstate(over="ignore", invalid="ignore"):   # overflow -> inf, checked by the caller
        return m * (float(p @ p) * np.eye(3) - np.outer(p, p))


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
    """
    S = sym(T)
    w, V = np.linalg.eigh(S)
    scale = float(np.max(np.abs(w)))
    if scale == 0.0:
        return np.zeros(3), np.eye(3), [[0, 1, 2]], 0.0
    tol = repeat_rtol * scale
    # snap eigenvalues that are zero to rounding (collinear masses)
    w = np.where(np.abs(w) <= 64 * np.finfo(float).eps * scale, 0.0, w)
    groups: list[list[int]] = [[0]]
    for k in range(1, 3):
        if w[k] - w[groups[-1][-1]] <= tol:
            groups[-1].append(k)
        else:
            groups.append([k])
    axes = V.copy()
    for g in groups:
        if len(g) == 1:
            continue
        if len(g) == 3:
            axes = np.eye(3)
            w[:] = np.mean(w)  # exactly repeated within the tolerance
            continue
        Vg = V[:, g]
        P = Vg @ Vg.T
        cols = []
        for _ in g:
            Pr = P - sum(np.outer(c, c) for c in cols) if cols else P
            norms = np.linalg.norm(Pr, axis=0)
            j = int(np.argmax(norms >= norms.max() * (1 - 1e-12)))
            cols.append(Pr[:, j] / norms[j])
        axes[:, g] = np.column_stack(cols)
        w[g] = np.mean(w[g])
    for k in (0, 1):
        c = axes[:, k]
        amax = np.max(np.abs(c))
        j = int(np.argmax(np.abs(c) >= amax * (1 - 1e-12)))
        if c[j] < 0:
            axes[:, k] = -c
    axes[:, 2] = np.cross(axes[:, 0], axes[:, 1])
    multi = [g for g in groups if len(g) > 1]
    return w, axes, multi, scale


def clean(x, scale: float, rel: float = 64 * np.finfo(float).eps):
    """Floats as plain Python lists with entries below rounding noise
    (``rel * scale``) set to 0.0 (also removes negative zeros)."""
    a = np.asarray(x, dtype=float)
    thr = rel * scale
    a = np.where(np.abs(a) <= thr, 0.0, a) + 0.0
    return a.tolist()


def from_fields(axis=None, angle=None, euler313=None, matrix=None) -> np.ndarray:
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
            raise ValueError("'angle' needs an 'axis' to rotate about")
        if angle is None:
            raise ValueError("'axis' needs an 'angle' (radians; e.g. \"30*deg\")")
        return rot_axis(axis, angle)
    if given[0] == "euler313":
        psi, theta, phi = (float(x) for x in euler313)
        return rot_z(psi) @ rot_x(theta) @ rot_z(phi)
    return check_rotation(matrix)
