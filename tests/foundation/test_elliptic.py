"""dyncli.elliptic (Carlson R_F, R_J, R_C; Jacobi sn, cn, dn and K by the AGM; floats or arrays) against
an independent route: mpmath's elliprf/elliprj/elliprc/elliprd/ellipk at 50 digits, confirmed at
90 (more where the two disagree: mpmath loses digits for p ≪ x, y, z).

Tolerance: |f − f_ref| ≤ k ε (1 + κ) |f_ref|, κ the condition number of f in its arguments
(Σ |x_i ∂f/∂x_i| / |f|).  R_F, R_J and R_C (y > 0) are homogeneous of degree −1/2, −3/2, −1/2 with
every partial derivative negative, so κ = 1/2, 3/2, 1/2 exactly; the Cauchy principal value of R_C
(y < 0) has mixed signs and its κ is computed (mpmath).  k = 8 ulp: Carlson's stopping rule makes the
series' truncation < ε, and the duplication steps are sums and products of positive terms (each
rounding ≤ ½ ulp, the differences from the mean contracting by 4 each step), the R_C terms of R_J
elementary functions of arguments formed without cancellation; R_F and R_C stay within ~2 ulp and
R_J within ~6 ulp (with p ≫ x, y, z: log₄(p/x) steps) on the grids and properties below.
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncli import elliptic as E

EPS = 2.0 ** -52
K_ULP = 8
MP = {"rf": mp.elliprf, "rj": mp.elliprj, "rc": mp.elliprc}
FN = {"rf": E.elliprf, "rj": E.elliprj, "rc": E.elliprc}
KAPPA = {"rf": 0.5, "rj": 1.5, "rc": 0.5}


def reference(name, args):
    """mpmath's value at 50 digits, confirmed to 1e-30 at 90 (else at 200 and 450 digits)."""
    prev = None
    for dps in (50, 90, 200, 450):
        with mp.workdps(dps):
            r = MP[name](*(mp.mpf(a) for a in args))
            r = r.real if isinstance(r, mp.mpc) else r
            if prev is not None and mp.isfinite(r) and abs(r - prev) <= mp.mpf("1e-30") * abs(r):
                return r
            prev = r
    raise AssertionError(f"mpmath does not settle on {name}{tuple(args)}")


def kappa(name, args):
    if name != "rc" or args[1] > 0:
        return KAPPA[name]
    with mp.workdps(40):                     # the Cauchy principal value: κ computed
        x, y = (mp.mpf(a) for a in args)
        f = mp.elliprc(x, y)
        dx = mp.diff(lambda u: mp.elliprc(u, y), x) if x > 0 else 0
        dy = mp.diff(lambda u: mp.elliprc(x, u), y)
        return float((abs(x * dx) + abs(y * dy)) / abs(f))


def ulps(got, ref):
    """Relative error in units of ε."""
    return float(abs(mp.mpf(float(got)) - ref) / abs(ref)) / EPS


def check(name, *args):
    """Both paths (plain floats, and a vectorised array longer than SMALL) within k ε (1 + κ)."""
    ref = reference(name, args)
    bound = K_ULP * (1.0 + kappa(name, args))
    got = FN[name](*args)
    arr = FN[name](*(np.full(E.SMALL + 3, a) for a in args))
    assert isinstance(got, float) and arr.shape == (E.SMALL + 3,)
    for g in (got, arr[0], arr[-1]):
        assert ulps(g, ref) <= bound, (name, args, float(g), ulps(g, ref), bound)
    return max(ulps(got, ref), ulps(arr[0], ref))


GRID = [0.0, 1e-300, 1e-30, 1e-8, 0.25, 1.0, 3.0, 1e8, 1e30, 1e300]
GRID_J = [0.0, 1e-8, 0.3, 7.0, 1e8]          # R_J to 1e±150: the properties below, and the slow grid
GRID_P = [1e-8, 1e-3, 0.3, 1.0, 7.0, 1e8]
WIDE_J = [0.0, 1e-40, 1e-8, 0.3, 1.0, 7.0, 1e8, 1e40]


def _rj_grid(xs, ps):
    for p in ps:
        for x in xs:
            for y in xs[1:]:
                for z in (1e-8, 1.0, 1e8):
                    if y >= x:               # symmetric in x, y, z
                        check("rj", x, y, z, p)


@pytest.mark.parametrize("z", GRID[1:])
def test_rf_on_a_grid(z):
    for x in GRID:
        for y in GRID[1:]:
            if y >= x:                       # R_F is symmetric: x ≤ y covers the grid
                check("rf", x, y, z)


def test_rj_on_a_grid():
    _rj_grid(GRID_J, GRID_P)


@pytest.mark.slow
@pytest.mark.parametrize("p", [1e-40, 1e40])
def test_rj_on_a_wide_grid(p):
    _rj_grid(WIDE_J, [p])


def test_rc_on_a_grid():
    for x in GRID:
        for y in GRID[1:]:
            check("rc", x, y)
            if y <= 1e150 and 1e-150 <= x:
                check("rc", x, -y)           # Cauchy principal value


POS = st.floats(1e-300, 1e300)
POS_J = st.floats(1e-150, 1e150)


@settings(max_examples=60, deadline=None)
@given(x=st.one_of(st.just(0.0), POS), y=POS, z=POS)
def test_rf_property(x, y, z):
    check("rf", x, y, z)


@settings(max_examples=60, deadline=None)
@given(x=st.one_of(st.just(0.0), POS_J), y=POS_J, z=POS_J, p=POS_J)
def test_rj_property(x, y, z, p):
    check("rj", x, y, z, p)


@settings(max_examples=40, deadline=None)
@given(v=st.floats(1e-150, 1e150), rel=st.one_of(st.floats(-1e-15, 1e-15), st.floats(-0.9, 9.0)),
       y=st.floats(1e-20, 1e20), zero=st.booleans())
def test_rj_near_singular_p_and_equal_arguments(v, rel, y, zero):
    """p next to x (rel → 0), x = y = z = p (RJ = v^(−3/2)), one argument zero with p ≪ the others."""
    check("rj", v, y, 1.0, v * (1.0 + rel))
    check("rj", v, v, v, v * (1.0 + rel))
    check("rj", 0.0 if zero else v, y, 1.0, y * 1e-12)


@settings(max_examples=60, deadline=None)
@given(x=st.one_of(st.just(0.0), st.floats(1e-300, 1e300)), y=st.floats(1e-300, 1e300),
       near=st.floats(-0.5, 1e-8), neg=st.booleans())
def test_rc_property(x, y, near, neg):
    check("rc", x, -y if neg and y < 1e150 and x >= 1e-150 else y)
    if x > 0:
        check("rc", x, x * (1.0 + near))      # y next to x


@settings(max_examples=60, deadline=None)
@given(v=st.floats(1e-300, 1e300), rel=st.floats(0.0, 1e-10))
def test_equal_arguments(v, rel):
    check("rf", v, v, v * (1.0 + rel))
    check("rf", v, v * (1.0 + rel), 0.0)
    assert abs(E.elliprf(v, v, v) * math.sqrt(v) - 1.0) <= 2 * EPS
    if 1e-200 <= v <= 1e200:
        assert abs(E.elliprj(v, v, v, v) * v * math.sqrt(v) - 1.0) <= 4 * EPS


@pytest.mark.parametrize("m1", [1.0, 0.5, 1e-3, 1e-12, 1e-100, 1e-300, 5e-324])
def test_rf_is_the_complete_integral(m1):
    """R_F(0, 1 − m, 1) = K(m): against the AGM (ellipK, m1 given exactly) and mpmath."""
    with mp.workdps(400):                    # 1 − m1 exact down to m1 = 5e-324
        ref = mp.ellipk(1 - mp.mpf(m1))
    k = E.elliprf(0.0, m1, 1.0)
    assert ulps(k, ref) <= K_ULP * 1.5
    assert ulps(E.ellipK(1.0 - m1, m1), ref) <= K_ULP * 1.5 + 4     # the AGM: a few ulp more


def test_identities():
    for x, y in ((0.3, 2.0), (5.0, 0.1), (0.0, 1.0), (1e-10, 1e10)):
        assert abs(E.elliprc(x, y) - E.elliprf(x, y, y)) <= K_ULP * EPS * E.elliprc(x, y)        # DLMF 19.2.17
    for x, y, z in ((0.3, 2.0, 1.0), (0.0, 0.5, 1.0), (1e-8, 3.0, 1e5)):
        with mp.workdps(50):
            rd = mp.elliprd(x, y, z)                                                           # R_J(x,y,z,z)
        assert ulps(E.elliprj(x, y, z, z), rd) <= K_ULP * 2.5


def test_domain_edges():
    inf, nan = math.inf, math.nan
    cases = [(E.elliprf, (0.0, 0.0, 1.0), inf), (E.elliprf, (-1.0, 1.0, 1.0), nan), (E.elliprf, (1.0, 2.0, inf), 0.0),
             (E.elliprj, (0.0, 1.0, 2.0, 0.0), inf), (E.elliprj, (0.0, 0.0, 2.0, 1.0), inf),
             (E.elliprj, (1.0, 2.0, 3.0, -0.5), nan), (E.elliprj, (1.0, 2.0, 3.0, inf), 0.0),
             (E.elliprc, (1.0, 0.0), inf), (E.elliprc, (0.0, -2.0), 0.0), (E.elliprc, (-1.0, 2.0), nan)]
    for fn, args, want in cases:
        for got in (fn(*args), fn(*(np.full(E.SMALL + 1, a) for a in args))[0],
                    fn(*(np.full(2, a) for a in args))[0]):
            assert (math.isnan(got) and math.isnan(want)) or got == want, (fn.__name__, args, got)


def test_shapes_and_broadcasting():
    x = np.linspace(0.0, 2.0, 2 * E.SMALL).reshape(2, E.SMALL)
    for fn, args in ((E.elliprf, (x, 1.0, 2.0)), (E.elliprj, (x, 1.0, 2.0, 0.5)), (E.elliprc, (x, 2.0))):
        out = fn(*args)
        assert out.shape == x.shape
        one = [fn(*(float(a[i, j]) if isinstance(a, np.ndarray) else a for a in args))
               for i in range(2) for j in range(E.SMALL)]
        np.testing.assert_allclose(out.ravel(), one, rtol=4 * K_ULP * EPS, atol=0)
    assert E.elliprf(np.array([[0.5, 1.0]]), np.array([[1.0], [2.0]]), 1.0).shape == (2, 2)
    assert E.elliprj(np.float64(1.0), 2, 3, 4) == E.elliprj(1.0, 2.0, 3.0, 4.0)


@pytest.mark.parametrize("m1", ["1", "0.9", "0.5", "0.01", "1e-6", "1e-12", "0"])
def test_ellipj_one_float_against_mpmath_and_the_array_path(m1):
    """ellipj of one float (math only) against mpmath's ellipfun at 40 digits with m = 1 − m1
    exact, and against the array path (the same algorithm on numpy).  sn, cn, dn lie in [−1, 1]
    with |d/du| ≤ 1, and u is reduced modulo 4K (K to a few ulp), so the error bound is absolute,
    k ε (1 + |u|): k = 16 against mpmath (the recursion and the reduction; 6.7 observed), k = 2
    between the backends (libm's and numpy's sin/arcsin may differ by an ulp; 0.3 observed)."""
    us = [float(u) for u in np.linspace(-40.0, 40.0, 33)] + [1e-300, 3.0e4, -7.0e5]
    with mp.workdps(40):
        mm = 1 - mp.mpf(m1)
        m = float(mm)
        arrays = E.ellipj(np.array(us), m, float(m1))
        for i, u in enumerate(us):
            got = E.ellipj(u, m, float(m1))
            assert all(type(g) is float for g in got)
            for k, name in enumerate(("sn", "cn", "dn")):
                ref = float(mp.ellipfun(name, mp.mpf(u), m=mm))
                assert abs(got[k] - ref) <= 16 * EPS * (1 + abs(u)), (name, u)
                assert abs(got[k] - arrays[k][i]) <= 2 * EPS * (1 + abs(u)), (name, u)


def test_float_paths_import_no_numpy():
    import subprocess
    import sys

    code = ("import sys, dyncli.elliptic as E\nE.ellipj(3.0, 0.7, 0.3); E.ellipj(3.0, 1.0, 0.0); E.ellipK(0.5, 0.5)\n"
            "E.elliprf(1.0, 2.0, 3.0); E.elliprj(1.0, 2.0, 3.0, 4.0); E.elliprc(1.0, -2.0)\n"
            "print('numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.stdout.strip() == "False", out.stderr


def test_no_scipy():
    import subprocess
    import sys

    code = ("import sys, numpy as np, dyncli.elliptic as E\nE.elliprj(np.ones(50), 2.0, 3.0, 4.0)\n"
            "E.elliprf(1.0, 2.0, 3.0); E.elliprc(np.ones(50), 2.0)\nprint('scipy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.stdout.strip() == "False", out.stderr


# ---------------------------------------------------------------- sn, cn, dn next to m = 1

@pytest.mark.parametrize("m1", [1.0, 0.5, 1e-3, 1e-6, 1e-10, 1e-17, 2.5e-25, 1e-40])
def test_ellipj_half_keeps_relative_precision_next_to_m_1(m1):
    """sn, cn, dn of |u| <= K by the Landen products: a few ε relative, also where cn and dn are
    tiny (m1 → 0, u → K), against mpmath at 60 digits; the bound adds the conditioning of the
    argument itself (a double u carries ε·u, and cn(u) next to K changes by K/(K − u) relative)."""
    K = E.elliprf(0.0, m1, 1.0)
    for f in (0.0, 0.1, 0.3, 0.49, 0.5, 0.51, 0.7, 0.9, 0.999, -0.6):
        u = f * K
        got = E.ellipj_half(u, 1.0 - m1, m1, K)
        with mp.workdps(60):
            want = [float(mp.ellipfun(w, u, m=1 - mp.mpf(m1))) for w in ("sn", "cn", "dn")]
        bound = 32 * EPS * (1 + abs(u) + K / (K - abs(u)))
        for g, w in zip(got, want):
            assert abs(g - w) <= bound * abs(w) + 1e-50, (m1, f, g, w)     # (mpmath: sn(0) ~ 1e-64)


def test_legendre_F_is_the_incomplete_integral():
    for phi, m in ((0.3, 0.5), (1.5, 0.999999), (-1.2, 0.1)):
        s, c = math.sin(phi), math.cos(phi)
        got = E.legendre_F(s, c, c * c + (1 - m) * s * s)
        assert got == pytest.approx(float(mp.ellipf(phi, m)), rel=8 * EPS)
