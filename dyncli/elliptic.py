"""Elliptic functions and integrals without scipy: Jacobi sn, cn, dn and the complete
integral K by the arithmetic-geometric mean, and Carlson's symmetric integrals R_F, R_J, R_C.
Each takes plain floats (math only: numpy is not imported) or arrays (numpy, vectorised).

Topic-agnostic numerics: what a problem type does with them is its own business.

* :func:`ellipj`, :func:`ellipK` take the parameter m *and* its complement m1 = 1 − m given
  exactly, so they stay accurate next to m = 1 (the AGM is run in terms of m1).
* :func:`elliprf`, :func:`elliprj` are B. C. Carlson's duplication algorithms ("Numerical
  computation of real or complex elliptic integrals", Numer. Algorithms 10 (1995) 13-26),
  their series carried to degree 7 (DLMF 19.36.1-19.36.2) and stopped when the duplicated
  arguments agree to within ``(3ε)^(1/8)`` (R_F) or ``(ε/5)^(1/8)`` (R_J) of their mean, so
  the truncation is below ε.  Inside R_J the terms R_C(1, 1 + e_m) are elementary; 1 + e_m is
  formed as 2√p(p + λ)/d (a sum of positive terms) and e_m as a product of three factors each
  in [−1, 1], so neither cancels nor overflows (p ≪ x, y, z; arguments near 1e±300).
* :func:`elliprc` is elementary (DLMF 19.2.17-19.2.19), each branch free of cancellation;
  y < 0 gives the Cauchy principal value (DLMF 19.2.20).

Domains (real arguments): R_F with x, y, z ≥ 0, at most one zero (two zeros: inf);
R_J with p > 0 (p = 0: inf; p < 0, the Cauchy principal value, is not implemented: nan);
R_C with x ≥ 0, y ≠ 0.  Outside: nan.  Arguments may be floats (plain-float path, no numpy
call) or arrays (broadcast, vectorised); arguments whose largest is beyond 2^1000 (R_F) or
2^660 (R_J), or below its inverse, are rescaled by a power of 4 (the integrals are
homogeneous), so the range is that of the results.

Accuracy (tests/foundation/test_elliptic.py, against mpmath at 50 digits): at most 2.2 ε for
R_F (arguments 1e-300 to 1e300, one may be 0), 1.9 ε for R_C (principal value included) and
3.8 ε for R_J (1e-150 to 1e150, p next to x, p ≪ x, y, z); the tests allow 8 ε (1 + κ), κ the
condition number (1/2 for R_F and R_C, 3/2 for R_J).
"""

from __future__ import annotations

import math

from dyncli.backends import FLOAT_OPS, array_ops

EPS = 2.0 ** -52
#: Carlson's stopping rule for the degree-7 series: truncation error below ε
_Q_RF = (3.0 * EPS) ** (-1.0 / 8.0)
_Q_RJ = (EPS / 5.0) ** (-1.0 / 8.0)
#: arrays at most this long go through the plain-float path (numpy's per-call cost dominates)
SMALL = 32


# ---------------------------------------------------------------- Jacobi sn, cn, dn; K

def agm_table(m: float, m1: float):
    """AGM sequences (a, c) for parameter m (complement m1); K = π/(2 a_N).

    Stops at c_N ≤ ε a_N: the next c is c_N²/(4 a) ≤ ε² a/4, below the rounding of a_N and
    of the phase it would correct (a − b stalls at an ulp there, so a smaller bound would
    run all 60 steps without changing a digit)."""
    a = [1.0]
    c = [math.sqrt(m)]
    b = math.sqrt(m1)
    for _ in range(60):
        if abs(c[-1]) <= EPS * a[-1]:
            break
        an = 0.5 * (a[-1] + b)
        cn = 0.5 * (a[-1] - b)
        b = math.sqrt(a[-1] * b)
        a.append(an)
        c.append(cn)
    return a, c


def ellipK(m: float, m1: float) -> float:
    """Complete elliptic integral K(m), m1 = 1 − m given exactly (inf at m1 = 0)."""
    if m1 == 0.0:
        return math.inf
    a, _ = agm_table(m, m1)
    return math.pi / (2.0 * a[-1])


def ellipj(u, m: float, m1: float | None = None):
    """sn, cn, dn of u (a float: floats; else an array) for parameter m, 0 <= m <= 1, given
    m1 = 1 − m exactly.  One algorithm for both (the descending Landen/AGM recursion, u reduced
    modulo 4K), on the backend of u."""
    if isinstance(u, (float, int)):
        xp = FLOAT_OPS
        u = float(u)
    else:
        xp = array_ops()
        u = xp.asarray(u, dtype=float)
    if m1 is None:
        m1 = 1.0 - m
    if m1 == 0.0:
        with xp.errstate(over="ignore"):
            sech = 1.0 / xp.cosh(u)
        return xp.tanh(u), sech, sech
    if m == 0.0:
        return xp.sin(u), xp.cos(u), xp.ones_like(u)
    a, c = agm_table(m, m1)
    N = len(a) - 1
    K = math.pi / (2.0 * a[N])
    four_k = 4.0 * K
    u = u - four_k * xp.round(u / four_k)
    phi = (2.0**N) * a[N] * u
    for i in range(N, 0, -1):
        phi = 0.5 * (xp.arcsin(xp.clip(c[i] * xp.sin(phi) / a[i], -1.0, 1.0)) + phi)
    sn, cn = xp.sin(phi), xp.cos(phi)
    dn = xp.sqrt(m1 + m * cn * cn)
    return sn, cn, dn


def ellipj_half(r: float, m: float, m1: float, K: float):
    """sn, cn, dn of a float |r| <= K, m1 = 1 − m exactly, each to a few ε relative even where
    cn, dn are tiny next to m = 1: past K/2 from the reflection ρ = K − |r| (sn = cd ρ,
    cn = √m1 sd ρ, dn = √m1 nd ρ), and on [0, K/2] by the descending Landen (Gauss)
    transformation carried back up as products (DLMF 22.7.1-22.7.3; dn = √(m1 + m cn²) at
    each level), from sin, cos of w <= π/4 (no cancellation anywhere)."""
    a, far = abs(r), abs(r) > 0.5 * K
    top, bot, ks, m1s = 1.0, math.sqrt(m1), [], [m1]
    while top - bot > EPS * top:
        ks.append((top - bot) / (top + bot))
        top, bot = 0.5 * (top + bot), math.sqrt(top * bot)
        m1s.append((bot / top) ** 2)
    w = (K - a if far else a) * top
    s1, c1, d1 = math.sin(w), math.cos(w), 1.0
    for k, mc in zip(reversed(ks), reversed(m1s[:-1])):
        d = 1.0 + k * s1 * s1
        s1, c1 = (1.0 + k) * s1 / d, c1 * d1 / d
        d1 = math.sqrt(mc + (m if mc is m1 else 1.0 - mc) * c1 * c1)
    q = math.copysign(1.0, r)
    return (q * c1 / d1, math.sqrt(m1) * s1 / d1, math.sqrt(m1) / d1) if far else (q * s1, c1, d1)


def legendre_F(s, c, d2):
    """F(φ | m) for |φ| <= π/2 from s = sin φ, c = cos φ >= 0 and d2 = 1 − m sin²φ (formed by the
    caller without cancellation): s·R_F(c², d2, 1)."""
    return s * elliprf(c * c, d2, 1.0)


# ---------------------------------------------------------------- Carlson's duplication
# Each step x ← (x + λ)/4 (λ = √x√y + √x√z + √y√z) leaves the integral unchanged and shrinks the
# spread of the arguments about their mean A by 4; once 4^(−n) Q < A the degree-7 series in the
# scaled deviations X = 4^(−n)(A0 − x)/A_n (DLMF 19.36.1-2) is exact to ε.  The loops end because
# 4^(−n) reaches 0 (after 537 steps at most; p ≫ x, y, z takes log₄(p/x) of them).

def _rf_series(X, Y):
    Z = -(X + Y)
    e2, e3 = X * Y - Z * Z, X * Y * Z
    return 1.0 + e2 * (-1.0 / 10 + e2 / 24 - 3.0 * e3 / 44 - 5.0 * e2 * e2 / 208 + e2 * e3 / 16) \
        + e3 * (1.0 / 14 + 3.0 * e3 / 104)


def _rj_series(X, Y, Z):
    P = -0.5 * (X + Y + Z)
    xyz, p2 = X * Y * Z, P * P
    e2 = X * Y + X * Z + Y * Z - 3.0 * p2
    e3 = xyz + 2.0 * e2 * P + 4.0 * P * p2
    e4 = (2.0 * xyz + e2 * P + 3.0 * P * p2) * P
    e5 = xyz * p2
    return (1.0 - 3.0 * e2 / 14 + e3 / 6 + 9.0 * e2 * e2 / 88 - 3.0 * e4 / 22 - 9.0 * e2 * e3 / 52
            + 3.0 * e5 / 26 - e2 * e2 * e2 / 16 + 3.0 * e3 * e3 / 40 + 3.0 * e2 * e4 / 20
            + 45.0 * e2 * e2 * e3 / 272 - 9.0 * (e3 * e4 + e2 * e5) / 68)


def _rc1p(e, y1):
    """R_C(1, 1 + e) in plain floats (y1 = 1 + e formed without cancellation)."""
    if e > 0.0:
        t = math.sqrt(e)
        return math.atan(t) / t
    if e == 0.0:
        return 1.0
    t = math.sqrt(-e)
    return math.atanh(t) / t if e > -0.5 else math.log((1.0 + t) / math.sqrt(y1)) / t


def _rc1p_arrays(e, y1):
    """:func:`_rc1p` on arrays (``y1()`` gives 1 + e, formed only where e < 0 needs it)."""
    import numpy as np

    # t floored at 1e-200: atan(t)/t = atanh(t)/t = 1 there, as for any e below 1e-32
    t = np.maximum(np.sqrt(np.abs(e)), 1e-200)
    if bool(np.all(e >= 0.0)):
        return np.arctan(t) / t
    with np.errstate(divide="ignore", invalid="ignore"):
        low = np.log((1.0 + t) / np.sqrt(y1()))
    return np.where(e >= 0.0, np.arctan(t), np.where(e > -0.5, np.arctanh(np.minimum(t, 0.75)), low)) / t


def _rf_floats(x, y, z):
    """R_F on its domain (at most one zero), plain floats."""
    sqrt = math.sqrt
    a0 = a = (x + y + z) / 3.0
    q = _Q_RF * max(abs(a0 - x), abs(a0 - y), abs(a0 - z))
    x0, y0, f = x, y, 1.0
    while q * f >= a:
        sx, sy, sz = sqrt(x), sqrt(y), sqrt(z)
        lam = sx * (sy + sz) + sy * sz
        a, x, y, z, f = 0.25 * (a + lam), 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam), 0.25 * f
    g = f / a
    return _rf_series((a0 - x0) * g, (a0 - y0) * g) / sqrt(a)


def _rf_arrays(x, y, z):
    """R_F on arrays (valid elements only; one step count for all, the largest)."""
    import numpy as np

    a0 = (x + y + z) / 3.0
    q = _Q_RF * np.maximum(np.maximum(np.abs(a0 - x), np.abs(a0 - y)), np.abs(a0 - z))
    a, f, v = a0, 1.0, np.stack([x, y, z])
    while not bool(np.all(q * f < a)):
        sx, sy, sz = np.sqrt(v)
        lam = sx * (sy + sz) + sy * sz
        v = 0.25 * (v + lam)
        a, f = 0.25 * (a + lam), 0.25 * f
    return _rf_series(f * (a0 - x) / a, f * (a0 - y) / a) / np.sqrt(a)


def _rj_floats(x, y, z, p):
    """R_J on its domain (p > 0, at most one of x, y, z zero), plain floats."""
    sqrt = math.sqrt
    a0 = a = (x + y + z + 2.0 * p) / 5.0
    q = _Q_RJ * max(abs(a0 - x), abs(a0 - y), abs(a0 - z), abs(a0 - p))
    x0, y0, z0 = x, y, z
    dx, dy, dz = p - x, p - y, p - z
    f, total = 1.0, 0.0
    while q * f >= a:
        sx, sy, sz, sp = sqrt(x), sqrt(y), sqrt(z), sqrt(p)
        lam = sx * (sy + sz) + sy * sz
        bx, by, bz = sp + sx, sp + sy, sp + sz
        d = bx * by * bz
        # e_m = 4^(−3m) δ/d_m², δ = (p−x)(p−y)(p−z): three factors (√p − √x)/(√p + √x) in [−1, 1]
        e = (f * dx / (bx * bx)) * (f * dy / (by * by)) * (f * dz / (bz * bz))
        total += f * _rc1p(e, 2.0 * sp * (p + lam) / d) / d
        a, x, y, z, p, f = (0.25 * (a + lam), 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam),
                            0.25 * (p + lam), 0.25 * f)
    g = f / a
    return f * _rj_series((a0 - x0) * g, (a0 - y0) * g, (a0 - z0) * g) / (a * sqrt(a)) + 6.0 * total


def _rj_arrays(x, y, z, p):
    """R_J on arrays (valid elements only; one step count for all, the largest)."""
    import numpy as np

    a0 = (x + y + z + 2.0 * p) / 5.0
    q = _Q_RJ * np.max(np.abs(a0 - np.stack([x, y, z, p])), axis=0)
    delta = np.stack([p - x, p - y, p - z])
    a, f, total, v = a0, 1.0, 0.0, np.stack([x, y, z, p])
    while not bool(np.all(q * f < a)):
        sq = np.sqrt(v)
        sx, sy, sz, sp = sq
        lam = sx * (sy + sz) + sy * sz
        b = sp + sq[:3]
        d = np.prod(b, axis=0)
        e = np.prod((f * delta) / (b * b), axis=0)        # as in _rj_floats
        total = total + _rc1p_arrays(e, lambda: 2.0 * sp * (v[3] + lam) / d) * (f / d)
        v = 0.25 * (v + lam)
        a, f = 0.25 * (a + lam), 0.25 * f
    g = f / a
    return f * _rj_series((a0 - x) * g, (a0 - y) * g, (a0 - z) * g) / (a * np.sqrt(a)) + 6.0 * total


# ---------------------------------------------------------------- public R_F, R_J, R_C

def _scale(big, hi):
    """k such that big·4^(−k) is at most 2^hi (big beyond it) or near 1 (big below 2^−hi), else 0:
    the least rescaling, so that the small arguments keep their digits (plain floats)."""
    if big > 2.0 ** hi and big != math.inf:
        return (math.frexp(big)[1] - hi + 1) // 2
    if 0.0 < big < 2.0 ** -hi:
        return math.frexp(big)[1] // 2
    return 0


def _scaled(args, hi):
    """Arrays rescaled by 4^(−k) (as :func:`_scale`, per element) and k (0 when none needs it)."""
    import numpy as np

    big = np.max(args, axis=0)
    e = np.frexp(big)[1]
    k = np.where((big > 2.0 ** hi) & np.isfinite(big), (e - hi + 1) // 2,
                 np.where((big > 0.0) & (big < 2.0 ** -hi), e // 2, 0))
    if not k.any():
        return args, 0
    return [np.ldexp(v, -2 * k) for v in args], k


def _float_path(core, args, hi, degree, special):
    """One evaluation in plain floats by ``core``: ``special(args)`` (after rescaling) is the value
    outside its domain, or None."""
    k = _scale(max(args), hi)
    if k:
        args = tuple(math.ldexp(v, -2 * k) for v in args)
    value = special(*args)
    if value is not None:
        return value
    out = core(*args)
    return math.ldexp(out, degree * k) if k else out


def _apply(cores, args, hi, degree, special, invalid):
    """Plain floats, a short array element by element (``cores[0]``), or the vectorised
    ``cores[1]`` on the valid elements (``invalid(arrays)`` → (mask, value) for the rest);
    R(4^k x) = 2^(degree·k) R(x)."""
    core, core_arrays = cores
    if all(isinstance(v, (float, int)) for v in args):
        return _float_path(core, tuple(float(v) for v in args), hi, degree, special)
    import numpy as np

    arrs = [np.asarray(v, dtype=float) for v in args]
    shape = max((a.shape for a in arrs), key=len)
    if any(a.shape != shape and a.shape != () for a in arrs):
        shape = np.broadcast_shapes(*(a.shape for a in arrs))
    n = math.prod(shape)
    if n <= SMALL:
        cols = [a.ravel().tolist() if a.shape == shape else
                ([a.item()] * n if a.size == 1 else np.broadcast_to(a, shape).ravel().tolist()) for a in arrs]
        flat = [_float_path(core, vals, hi, degree, special) for vals in zip(*cols)]
        return np.array(flat, dtype=float).reshape(shape)
    arrs = np.broadcast_arrays(*arrs)
    arrs, k = _scaled(arrs, hi)
    mask, value = invalid(*arrs)
    out = core_arrays(*(np.where(mask, 1.0, v) for v in arrs))
    if not isinstance(k, int):
        out = np.ldexp(out, degree * k)
    return np.where(mask, value, out)


def _rf_special(x, y, z):
    if not (x >= 0.0 and y >= 0.0 and z >= 0.0):
        return math.nan
    if (x == 0.0) + (y == 0.0) + (z == 0.0) >= 2:
        return math.inf
    return 0.0 if math.inf in (x, y, z) else None


def _rf_invalid(x, y, z):
    import numpy as np

    zeros = (x == 0.0).astype(int) + (y == 0.0) + (z == 0.0)
    bad = ~((x >= 0.0) & (y >= 0.0) & (z >= 0.0))
    inf = np.isinf(x) | np.isinf(y) | np.isinf(z)
    return bad | (zeros >= 2) | inf, np.where(bad, np.nan, np.where(zeros >= 2, np.inf, 0.0))


def elliprf(x, y, z):
    """Carlson's R_F(x, y, z) = ½∫₀^∞ dt/√((t+x)(t+y)(t+z)) (float for floats, else array)."""
    return _apply((_rf_floats, _rf_arrays), (x, y, z), 1000, -1, _rf_special, _rf_invalid)


def _rj_special(x, y, z, p):
    if not (x >= 0.0 and y >= 0.0 and z >= 0.0 and p >= 0.0):
        return math.nan
    if p == 0.0 or (x == 0.0) + (y == 0.0) + (z == 0.0) >= 2:
        return math.inf
    return 0.0 if math.inf in (x, y, z, p) else None


def _rj_invalid(x, y, z, p):
    import numpy as np

    zeros = (x == 0.0).astype(int) + (y == 0.0) + (z == 0.0)
    bad = ~((x >= 0.0) & (y >= 0.0) & (z >= 0.0) & (p >= 0.0))
    sing = (p == 0.0) | (zeros >= 2)
    inf = np.isinf(x) | np.isinf(y) | np.isinf(z) | np.isinf(p)
    return bad | sing | inf, np.where(bad, np.nan, np.where(sing, np.inf, 0.0))


def elliprj(x, y, z, p):
    """Carlson's R_J(x, y, z, p) = 3/2 ∫₀^∞ dt/((t+p)√((t+x)(t+y)(t+z))), p > 0."""
    return _apply((_rj_floats, _rj_arrays), (x, y, z, p), 660, -3, _rj_special, _rj_invalid)


def _rc_float(x, y):
    """R_C(x, y) by its elementary forms (DLMF 19.2.17-19.2.20)."""
    if not x >= 0.0 or math.isnan(y):
        return math.nan
    if y < 0.0:                                     # Cauchy principal value
        return 0.0 if x == 0.0 else math.sqrt(x / (x - y)) * _rc_float(x - y, -y)
    if y == 0.0:
        return math.inf
    if math.isinf(x) or math.isinf(y):
        return 0.0
    if x == y:
        return 1.0 / math.sqrt(x)
    if x < y:
        g = math.sqrt(y - x)
        return math.atan2(g, math.sqrt(x)) / g
    g = math.sqrt(x - y)
    if 2.0 * y >= x:
        return math.atanh(g / math.sqrt(x)) / g
    return math.log((math.sqrt(x) + g) / math.sqrt(y)) / g


def elliprc(x, y):
    """Carlson's R_C(x, y) = ½∫₀^∞ dt/((t+y)√(t+x)), x ≥ 0 (y < 0: Cauchy principal value)."""
    if isinstance(x, (float, int)) and isinstance(y, (float, int)):
        return _rc_float(float(x), float(y))
    import numpy as np

    x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
    if x.size <= SMALL:
        return np.array([_rc_float(float(a), float(b)) for a, b in zip(x.ravel(), y.ravel())]).reshape(x.shape)
    neg, bad = y < 0.0, ~(x >= 0.0) | np.isnan(y)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        pre = np.where(neg, np.sqrt(x / (x - y)), 1.0)
        x, y = np.where(neg, x - y, x), np.abs(y)
        sx, g = np.sqrt(x), np.sqrt(np.abs(y - x))
        out = np.where(y > x, np.arctan2(g, sx),
                       np.where(2.0 * y >= x, np.arctanh(np.minimum(g / sx, 1.0)), np.log((sx + g) / np.sqrt(y)))) / g
        out = np.where(x == y, 1.0 / sx, out)
        out = np.where(np.isinf(x) | np.isinf(y), 0.0, np.where(y == 0.0, np.inf, out))
        return np.where(neg & (pre == 0.0), 0.0, np.where(bad, np.nan, pre * out))
