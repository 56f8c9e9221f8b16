"""The plain-float Jacobi eigensolver of symmetric 3×3 tensors (dyncli.topics.inertia.eigen3)
and the polar factor of a user's rotation matrix (mat3.polar_rotation)
against mpmath's eigsy at 40 digits and numpy.linalg.eigh: a backward-stable method gives each
eigenvalue within a few ulp × ‖A‖ (the guarantee, not a fit to one run), residuals
‖A v − λ v‖ and ‖VᵀV − 1‖ of a few ulp × ‖A‖ and a few ulp, at every scale (entries near
1e±300) and for repeated, zero and nearly-diagonal spectra."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncli.topics.inertia.eigen3 import eigh3, eigvalsh3, inertia_defect

EPS = 2.220446049250313e-16
ULPS = 16        # a few ulp per rotation, over the handful of rotations a 3×3 needs

entry = st.floats(-1.0, 1.0, allow_nan=False)
scale_exp = st.sampled_from([0, 0, 0, -1000, -500, 500, 1000, -30, 30])


def _sym(a, k):
    (a00, a01, a02, a11, a12, a22) = (math.ldexp(x, k) for x in a)
    return [[a00, a01, a02], [a01, a11, a12], [a02, a12, a22]]


def _norm(A) -> float:
    """‖A‖_F, scaled by the largest entry (no overflow or underflow of the squares)."""
    m = max(abs(x) for r in A for x in r)
    return m * math.sqrt(sum((x / m) ** 2 for r in A for x in r)) if m else 0.0


def _check(A):
    import mpmath

    w, V = eigh3(A)
    nA = _norm(A)
    tol = ULPS * EPS * nA
    with mpmath.workdps(40):
        ref = sorted(float(x) for x in mpmath.eigsy(mpmath.matrix(A), eigvals_only=True))
    assert all(abs(a - b) <= tol for a, b in zip(w, ref)), (A, w, ref)
    if 1e-100 <= nA <= 1e100:
        # LAPACK as a second route where its own scaling is not in question (the 40-digit mpmath
        # reference above is the authority: a fresh lowest-version CI run once got an eigvalsh
        # beyond this bound for a 2.6e135 matrix that LAPACK solves correctly elsewhere)
        lapack = np.linalg.eigvalsh(np.array(A))
        assert all(abs(a - b) <= tol for a, b in zip(w, lapack)), (A, w, lapack)
    assert w == sorted(w)
    for k in range(3):
        v = [V[i][k] for i in range(3)]
        res = max(abs(math.fsum(A[i][j] * v[j] for j in range(3)) - w[k] * v[i]) for i in range(3))
        assert res <= tol + 1e-300, (A, k, res, tol)      # + the underflow of tiny products
        for m in range(3):
            g = math.fsum(V[i][k] * V[i][m] for i in range(3))
            assert abs(g - (k == m)) <= ULPS * EPS, (A, k, m, g)


@settings(max_examples=300, deadline=None)
@given(st.tuples(*[entry] * 6), scale_exp)
def test_random_symmetric_any_scale(a, k):
    _check(_sym(a, k))


@pytest.mark.parametrize("A", [
    [[0.0] * 3] * 3,
    [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]],                             # a sphere: every direction
    [[2.0, 0, 0], [0, 1.0, 0], [0, 0, 3.0]],                             # diagonal, out of order
    [[1.0, 1e-200, 0], [1e-200, 1.0, 0], [0, 0, 2.0]],                   # repeated, off-diagonal underflowing
    [[1.0, 1e-9, 0], [1e-9, 1.0 + 1e-17, 0], [0, 0, 1.0]],               # nearly repeated
    [[1.0, 1.0, 1.0], [1.0, 1.0, 1.0], [1.0, 1.0, 1.0]],                 # rank 1: collinear masses
    [[1e300, 1e300, 0], [1e300, 1e300, 0], [0, 0, 1e-300]],              # huge and tiny together
    [[5e-324, 0, 0], [0, 5e-324, 5e-324], [0, 5e-324, 0]],                # subnormal
])
def test_special_spectra(A):
    _check(A)


def test_inertia_defect_of_a_rod_and_an_impossible_tensor():
    """A rod along e3: I = diag(1, 1, 0), defect I3 − I1 − I2 = 1 − 0 − 1 = 0; diag(1, 1, 3)
    violates the triangle inequality by 1 (ascending moments 1, 1, 3)."""
    assert inertia_defect([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 0.0]]) == (0.0, 0.0, 1.0)
    assert inertia_defect([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 3.0]]) == (1.0, 1.0, 3.0)


def test_non_finite_tensor_gives_nan():
    """As numpy.linalg.eigvalsh does for an infinite entry: the callers' checks then see nan."""
    assert all(math.isnan(x) for x in eigvalsh3([[math.inf, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]))
    assert all(math.isnan(x) for x in inertia_defect([[1.0, math.nan, 0], [math.nan, 1.0, 0], [0, 0, 1.0]]))


@settings(max_examples=200, deadline=None)
@given(st.tuples(*[st.floats(-math.pi, math.pi)] * 3), st.tuples(*[st.floats(-1e-6, 1e-6)] * 9))
def test_polar_factor_of_a_nearly_orthogonal_matrix_equals_the_svds(angles, noise):
    """A user matrix with rounded entries (|RᵀR − 1| ≤ ~1e-6) is replaced by its orthogonal polar
    factor U Vᵀ (the nearest rotation): Newton's iteration gives mpmath's SVD route at 40 digits to
    a few ulp (the polar factor is perfectly conditioned for a nearly orthogonal matrix; numpy's
    double-precision SVD is itself off by up to ~20 ulp here, so it is not the reference)."""
    import mpmath

    from dyncli.topics.inertia import mat3
    from dyncli.topics.inertia.rotations import euler313

    M = [[x + noise[3 * i + j] for j, x in enumerate(r)] for i, r in enumerate(euler313(*angles))]
    Q = mat3.polar_rotation(M)
    with mpmath.workdps(40):
        U, _, V = mpmath.svd_r(mpmath.matrix(M))
        P = U * V
        ref = [[float(P[i, j]) for j in range(3)] for i in range(3)]
    assert max(abs(Q[i][j] - ref[i][j]) for i in range(3) for j in range(3)) <= ULPS * EPS
    assert np.max(np.abs(np.array(Q).T @ np.array(Q) - np.eye(3))) <= ULPS * EPS
