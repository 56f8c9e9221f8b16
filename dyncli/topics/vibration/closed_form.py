"""Closed-form response of the spring-mass-damper of notes §17: one set of formulas, evaluated
on numpy arrays (plots, sweeps; numpy imported there) or on plain floats and cmath (``*_at``:
the few times of a problem, no numpy).

Everything here is uniform in the damping ratio ζ ≥ 0: one formulation is
continuous through ζ = 1 and free of cancellation for large ζ, and the forced
response is free of cancellation at and near resonance.

Free response (homogeneous solution of (17.17) with w(0) = w0, ẇ(0) = ẇ0):

* ζ < 1:  w = e^{-ζωt} [w0 cos(ω*t) + (ẇ0 + ζω w0) t sinc(ω*t)]
* ζ ≥ 1:  w = e^{-λ₁t} [w0 + (ẇ0 + λ₁ w0) τ(t)],
  λ₁ = ω / (ζ + √(ζ²-1)) (the slow root, computed without cancellation),
  τ(t) = (1 - e^{-2ω*t}) / (2ω*) = t·φ₁(2ω*t), φ₁(z) = -expm1(-z)/z.

  This equals e^{-ζωt}[w0 cosh(ω*t) + (ẇ0 + ζω w0) t sinhc(ω*t)] (the same
  form as ζ < 1, with cosh/sinh) but never forms e^{-ζωt}·cosh(ω*t), which
  under/overflows for large ζ; at ζ = 1 it is (17.23) exactly.

  The velocity is the same form applied to (ẇ0, ẅ0) for ζ < 1 and
  ẇ = e^{-λ₁t} [B e^{-2ω*t} - λ₁ (w0 + B τ)], B = ẇ0 + λ₁ w0, for ζ ≥ 1.

Forced response (zero initial conditions) to ẅ + 2ζωẇ + ω²w = F sin(Ωt):
with the characteristic roots s₁, s₂ of z² + 2ζωz + ω² and the second
divided difference E(t) = e^{zt}[iΩ, s₁, s₂] of z ↦ e^{zt},

    w_f(t) = F Im E(t),      ẇ_f(t) = F Ω Re E(t).

The divided difference is evaluated with the two most distant nodes as the
outer pair, first differences in the form e^{(a+b)t/2} t sinhc((a-b)t/2)
when the nodes are close, and a power series when all three nodes are within
1/t of each other, so it stays accurate at exact resonance (repeated node:
the secular term) and near it.
"""

from __future__ import annotations

import math
from fractions import Fraction
from types import SimpleNamespace

from dyncli.exact import INPUT_ROUNDING, cmp_sqrt
from dyncli.topics.vibration.backends import FLOATS as _FLOATS
from dyncli.topics.vibration.backends import arrays as _arrays

_SERIES_TERMS = 24


# ---------------------------------------------------------------------------
# characteristic quantities


def roots(omega_n: float, zeta: float):
    """(omega_star, lam1, lam2) with the roots s = -lam (real, ζ ≥ 1) or
    s = -ζω ± iω* (ζ < 1; lam1 = lam2 = ζω then)."""
    if zeta < 1.0:
        ws = omega_n * math.sqrt((1.0 - zeta) * (1.0 + zeta))
        return ws, zeta * omega_n, zeta * omega_n
    ws = omega_n * math.sqrt(zeta - 1.0) * math.sqrt(zeta + 1.0)
    lam1 = omega_n / (zeta + math.sqrt(zeta - 1.0) * math.sqrt(zeta + 1.0))
    lam2 = zeta * omega_n + ws
    return ws, lam1, lam2


def char_roots(omega_n: float, zeta: float) -> tuple[complex, complex]:
    ws, lam1, lam2 = roots(omega_n, zeta)
    if zeta < 1.0:
        return complex(-zeta * omega_n, ws), complex(-zeta * omega_n, -ws)
    return complex(-lam1, 0.0), complex(-lam2, 0.0)


# ---------------------------------------------------------------------------
# free response


def _free(t, w0: float, wd0: float, omega_n: float, zeta: float, X: SimpleNamespace):
    wn = omega_n
    ws, lam1, _ = roots(wn, zeta)
    if zeta < 1.0:
        y = ws * t
        ex = X.exp(-zeta * wn * t)
        c = X.cos(y)
        ts = t * X.sinc(y)
        w = ex * (w0 * c + (wd0 + zeta * wn * w0) * ts)
        # the velocity obeys the same equation with (ẇ0, ẅ0), ẅ0 = -2ζωẇ0 - ω²w0
        v = ex * (wd0 * c - (wn * (wn * w0) + zeta * wn * wd0) * ts)
        return w, v
    y = ws * t
    e1 = X.exp(-lam1 * t)
    tau = t * X.phi1(2.0 * y)
    big_e = X.exp(-2.0 * y)
    b = wd0 + lam1 * w0
    inner = w0 + b * tau
    w = e1 * inner
    v = e1 * (b * big_e - lam1 * inner)
    return w, v


def free(t, w0: float, wd0: float, omega_n: float, zeta: float):
    """Homogeneous solution of (17.17) with w(0) = w0, ẇ(0) = wd0.
    Returns (w, ẇ) as float arrays over t ≥ 0."""
    import numpy as np

    return _free(np.asarray(t, dtype=float), w0, wd0, omega_n, zeta, _arrays())


def free_at(t: float, w0: float, wd0: float, omega_n: float, zeta: float) -> tuple[float, float]:
    """:func:`free` at one time, in plain floats.

    >>> free_at(math.pi / 2, 1.0, 0.0, 1.0, 0.0)      # cos t, -sin t
    (6.123233995736766e-17, -1.0)
    """
    return _free(float(t), w0, wd0, omega_n, zeta, _FLOATS)


# ---------------------------------------------------------------------------
# divided differences of z -> exp(z t)


def _dd1_direct(a: complex, b: complex, t, X):
    return (X.cexp(a * t) - X.cexp(b * t)) / (a - b)


def _dd1_symmetric(a: complex, b: complex, t, X):
    return X.cexp(0.5 * (a + b) * t) * t * X.sinhc(0.5 * (a - b) * t)


def dd1(a: complex, b: complex, t):
    """e^{zt}[a, b] = (e^{at} - e^{bt})/(a - b) (t e^{at} when a == b), t ≥ 0 array.

    Uses e^{(a+b)t/2} t sinhc((a-b)t/2) unless the real parts are so far
    apart that the two exponentials differ by more than a factor e (then the
    plain difference has no cancellation and the symmetric form could
    overflow)."""
    import numpy as np

    X = _arrays()
    t = np.asarray(t, dtype=float)
    out = np.empty(t.shape, dtype=complex)
    direct = abs((a - b).real) * t > 1.0
    _put(out, direct, lambda td: _dd1_direct(a, b, td, X), t)
    _put(out, ~direct, lambda ts: _dd1_symmetric(a, b, ts, X), t)
    return out


def dd1_at(a: complex, b: complex, t: float) -> complex:
    """:func:`dd1` at one time, in plain floats (cmath).

    >>> dd1_at(0j, 0j, 2.0)
    (2+0j)
    """
    if abs((a - b).real) * t > 1.0:
        return _dd1_direct(a, b, t, _FLOATS)
    return _dd1_symmetric(a, b, t, _FLOATS)


def _put(out, mask, fn, t):
    """out[mask] = fn(t[mask]), without the indexing when the mask is all or nothing
    (the usual case for the few times of a problem; a sweep evaluates thousands)."""
    if mask.all():
        out[...] = fn(t)
    elif mask.any():
        out[mask] = fn(t[mask])


def _outer_pair(a: complex, b: complex, c: complex) -> tuple[complex, complex, complex]:
    """(a, b, c) reordered so that the outer pair a, c are the two most distant nodes."""
    nodes = [a, b, c]
    pairs = [(0, 2, 1), (0, 1, 2), (1, 2, 0)]
    i, k, j = max(pairs, key=lambda p: abs(nodes[p[0]] - nodes[p[1]]))
    return nodes[i], nodes[j], nodes[k]


def dd2(a: complex, b: complex, c: complex, t):
    """e^{zt}[a, b, c] (second divided difference), t ≥ 0 array."""
    import numpy as np

    X = _arrays()
    t = np.asarray(t, dtype=float)
    a, b, c = _outer_pair(a, b, c)
    span = abs(a - c)
    out = np.empty(t.shape, dtype=complex)
    far = span * t > 1.0
    _put(out, far, lambda tf: (dd1(a, b, tf) - dd1(b, c, tf)) / (a - c), t)
    near = ~far
    zero = near & (t == 0.0)
    if zero.any():        # the series is exactly +0 at t = 0 (t² e^{bt} Σ…): skip its 24 terms there
        out[zero] = 0j
        near &= ~zero
    _put(out, near, lambda tn: _dd2_series(a, b, c, tn, X), t)
    return out


def dd2_at(a: complex, b: complex, c: complex, t: float) -> complex:
    """:func:`dd2` at one time, in plain floats (cmath).

    >>> dd2_at(0j, 0j, 0j, 2.0)       # t²/2 e^{0}
    (2+0j)
    """
    a, b, c = _outer_pair(a, b, c)
    if abs(a - c) * t > 1.0:
        return (dd1_at(a, b, t) - dd1_at(b, c, t)) / (a - c)
    if t == 0.0:
        return 0j
    return _dd2_series(a, b, c, t, _FLOATS)


def _dd2_series(a: complex, b: complex, c: complex, tn, X):
    """e^{zt}[a, b, c] by its Taylor series (nodes within 1/t of each other)."""
    al = (a - b) * tn
    ga = (c - b) * tn
    # e^{u}[al, 0, ga] = sum_k h_k(al, ga) / (k+2)!,  h_k = al h_{k-1} + ga^k
    h = X.ones(al)
    gk = X.ones(ga)
    total = h / 2.0
    fact = 2.0
    for kk in range(1, _SERIES_TERMS):
        gk = gk * ga
        h = al * h + gk
        fact *= kk + 2
        total = total + h / fact
    return X.cexp(b * tn) * tn * tn * total


def forced(t, force: float, Omega: float, omega_n: float, zeta: float):
    """Zero-initial-condition response of ẅ + 2ζωẇ + ω²w = F sin(Ωt):
    (w_f, ẇ_f) as float arrays."""
    import numpy as np

    t = np.asarray(t, dtype=float)
    if force == 0.0 or Omega == 0.0:
        z = np.zeros_like(t)
        return z, z.copy()
    s1, s2 = char_roots(omega_n, zeta)
    e = dd2(complex(0.0, Omega), s1, s2, t)
    return force * e.imag, force * Omega * e.real


def forced_at(t: float, force: float, Omega: float, omega_n: float, zeta: float) -> tuple[float, float]:
    """:func:`forced` at one time, in plain floats.

    >>> w, v = forced_at(1.0, 1.0, 2.0, 1.0, 0.0)     # (sin 2t − 2 sin t)/(1 − 4)
    >>> abs(w - (math.sin(2.0) - 2 * math.sin(1.0)) / -3) < 1e-15
    True
    """
    if force == 0.0 or Omega == 0.0:
        return 0.0, 0.0
    s1, s2 = char_roots(omega_n, zeta)
    e = dd2_at(complex(0.0, Omega), s1, s2, float(t))
    return force * e.imag, force * Omega * e.real


def _response(t, wh, vh, wf, vf, L: float, s0: float, Omega: float, X):
    w = wh + wf
    wdot = vh + vf
    if s0 != 0.0 and Omega != 0.0:
        th = Omega * t
        s = s0 * X.sin(th)
        sd = s0 * Omega * X.cos(th)
    else:
        s = X.zeros(t)
        sd = X.zeros(t)
    return w + s + L, wdot + sd, w


def response(t, *, omega_n: float, zeta: float, L: float, x0: float, v0: float,
             s0: float = 0.0, Omega: float = 0.0):
    """Total response of (17.15a) with s(t) = s0 sin(Ωt), x(0) = x0, ẋ(0) = v0.
    Returns (x, v, w) float arrays."""
    import numpy as np

    t = np.asarray(t, dtype=float)
    w0 = x0 - L                      # s(0) = 0
    wd0 = v0 - s0 * Omega            # ẇ(0) = v0 - ṡ(0)
    wh, vh = free(t, w0, wd0, omega_n, zeta)
    wf, vf = forced(t, s0 * Omega * Omega, Omega, omega_n, zeta)
    return _response(t, wh, vh, wf, vf, L, s0, Omega, _arrays())


def response_at(t: float, *, omega_n: float, zeta: float, L: float, x0: float, v0: float,
                s0: float = 0.0, Omega: float = 0.0) -> tuple[float, float, float]:
    """:func:`response` at one time, in plain floats: (x, v, w).

    >>> response_at(0.0, omega_n=20.0, zeta=0.05, L=0.25, x0=0.5, v0=0.0, s0=0.002, Omega=30.0)
    (0.5, 0.0, 0.25)
    """
    t = float(t)
    w0, wd0 = x0 - L, v0 - s0 * Omega
    wh, vh = free_at(t, w0, wd0, omega_n, zeta)
    wf, vf = forced_at(t, s0 * Omega * Omega, Omega, omega_n, zeta)
    return _response(t, wh, vh, wf, vf, L, s0, Omega, _FLOATS)


def free_response_fn(omega_n: float, zeta: float, L: float, x0: float, v0: float):
    """t -> (x, v, w) of a free vibration (no base motion, no force) below critical damping, in
    plain floats with its constants hoisted: the operations of :func:`free_at` and
    :func:`response_at` one by one, so the same doubles at a fraction of the cost (a ``find``
    search evaluates the motion a few hundred times, a sweep once per point and time); None for
    ζ ≥ 1.

    >>> free_response_fn(20.0, 0.05, 0.25, 0.5, 0.0)(0.3) == response_at(0.3, omega_n=20.0, zeta=0.05, L=0.25, x0=0.5, v0=0.0)
    True
    """
    wn, z = omega_n, zeta
    if not 0.0 <= z < 1.0:
        return None
    w0, wd0 = x0 - L, v0
    ws = roots(wn, z)[0]
    a, b, K = -z * wn, wd0 + z * wn * w0, wn * (wn * w0) + z * wn * wd0
    exp, cos, sin = math.exp, math.cos, math.sin

    def at(t: float) -> tuple[float, float, float]:
        try:
            y = ws * t
            ex, c = exp(a * t), cos(y)
            ts = t * (sin(y) / y) if y != 0 else t
        except (ValueError, OverflowError):    # beyond the float range: numpy's conventions
            return response_at(t, omega_n=omega_n, zeta=zeta, L=L, x0=x0, v0=v0)
        w = ex * (w0 * c + b * ts) + 0.0
        return w + L, ex * (wd0 * c - K * ts) + 0.0, w
    return at


def free_quantity_fn(omega_n: float, zeta: float, L: float, x0: float, v0: float, which: int):
    """t -> x (``which`` 0), v (1) or w (2) alone of :func:`free_response_fn` (the same operations,
    so the same doubles, without computing the other two: a search asks for one quantity at a
    time); None for ζ ≥ 1.

    >>> f, g = free_quantity_fn(20.0, 0.05, 0.25, 0.5, 0.0, 1), free_response_fn(20.0, 0.05, 0.25, 0.5, 0.0)
    >>> all(f(t) == g(t)[1] for t in (0.0, 0.3, 7.5))
    True
    """
    full = free_response_fn(omega_n, zeta, L, x0, v0)
    if full is None:
        return None
    wn, z = omega_n, zeta
    w0, wd0 = x0 - L, v0
    ws = roots(wn, z)[0]
    a, b, K = -z * wn, wd0 + z * wn * w0, wn * (wn * w0) + z * wn * wd0
    exp, cos, sin = math.exp, math.cos, math.sin

    # each written out (no shared helper call: a search evaluates one of them hundreds of times)
    def x(t: float) -> float:
        try:
            y = ws * t
            ex, c = exp(a * t), cos(y)
            ts = t * (sin(y) / y) if y != 0 else t
        except (ValueError, OverflowError):
            return full(t)[0]
        return (ex * (w0 * c + b * ts) + 0.0) + L

    def v(t: float) -> float:
        try:
            y = ws * t
            ex, c = exp(a * t), cos(y)
            ts = t * (sin(y) / y) if y != 0 else t
        except (ValueError, OverflowError):
            return full(t)[1]
        return ex * (wd0 * c - K * ts) + 0.0

    def w(t: float) -> float:
        try:
            y = ws * t
            ex, c = exp(a * t), cos(y)
            ts = t * (sin(y) / y) if y != 0 else t
        except (ValueError, OverflowError):
            return full(t)[2]
        return ex * (w0 * c + b * ts) + 0.0
    return (x, v, w)[which]


# ---------------------------------------------------------------------------
# steady-state amplification functions (17.30), (17.33), (17.34)


def amplification(r, zeta: float):
    """G, φ, g, Φ over ratios r = Ω/ωₙ ≥ 0 (arrays; G, g are inf at undamped
    resonance).  Written with D = (1-r)(1+r) + 2iζr, the complex
    denominator, so there is no cancellation near r = 1:

    G = r²/|D|, φ = -arg D, g = |1 + 2iζr|/|D|,
    Φ = arg((1 + 2iζr) conj(D)) = atan2(-2ζr³, (1-r)(1+r) + (2ζr)²).
    Phases are in (-π, π]."""
    import numpy as np

    r = np.asarray(r, dtype=float)
    # for r > 2 divide D by r² (no overflow for large r; no cancellation there)
    big = r > 2.0
    rb = np.where(big, r, 1.0)
    inv = 1.0 / rb
    re = np.where(big, (inv - 1.0) * (inv + 1.0), (1.0 - r) * (1.0 + r))
    im = np.where(big, 2.0 * zeta * inv, 2.0 * zeta * r)
    num_G = np.where(big, 1.0, r * r)                           # r² (/r²)
    num_g = np.where(big, np.hypot(inv * inv, im), np.hypot(1.0, im))   # |1 + 2iζr| (/r²)
    mod = np.hypot(re, im)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):   # G, g beyond a double: inf
        safe = np.where(mod > 0, mod, 1.0)
        G = np.where(mod > 0, num_G / safe, np.inf)
        g = np.where(mod > 0, num_g / safe, np.inf)
    # "+ 0.0" turns -0.0 into +0.0, so the negative real axis gives +π:
    # phases in (-π, π] without moving values just above -π
    phi = np.arctan2(-im + 0.0, re)
    # Φ = arg((1 + 2iζr) conj D) = atan2(-2ζr³, (1-r)(1+r) + (2ζr)²)  (both divided by r² when r > 2)
    Phi = np.where(big, np.arctan2(-2.0 * zeta * rb + 0.0, re + 4.0 * zeta * zeta),
                   np.arctan2(-im * r * r + 0.0, re + im * im))
    res = (mod == 0)
    # undamped resonance: phase of the secular term (limit ζ -> 0+)
    phi = np.where(res, -0.5 * np.pi, phi)
    Phi = np.where(res, -0.5 * np.pi, Phi)
    phi = phi + 0.0
    Phi = Phi + 0.0
    return G, phi, g, Phi


def amplification_at(r: float, zeta: float) -> tuple[float, float, float, float]:
    """:func:`amplification` at one ratio, the same operations on Python
    floats (one branch instead of both under ``np.where``; hypot as the C
    library's, through ``abs(complex)``, and atan2, so every value is the
    array version's, bit for bit): a sweep evaluates it thousands of times,
    and a problem without a sweep needs no numpy."""
    if r > 2.0:
        inv = 1.0 / r
        re = (inv - 1.0) * (inv + 1.0)
        im = 2.0 * zeta * inv
        num_G, num_g = 1.0, abs(complex(inv * inv, im))
    else:
        re = (1.0 - r) * (1.0 + r)
        im = 2.0 * zeta * r
        num_G, num_g = r * r, abs(complex(1.0, im))
    mod = abs(complex(re, im))
    if mod > 0:
        G, g = num_G / mod, num_g / mod
    else:
        G = g = math.inf
    if mod == 0:
        phi = Phi = -0.5 * math.pi
    else:
        phi = math.atan2(-im + 0.0, re)
        Phi = (math.atan2(-2.0 * zeta * r + 0.0, re + 4.0 * zeta * zeta) if r > 2.0
               else math.atan2(-im * r * r + 0.0, re + im * im))
    return G, phi + 0.0, g, Phi + 0.0


def peak_G(zeta: float, rel: float = INPUT_ROUNDING):
    """(r, G_max) of the maximum of G for 0 < ζ < 1/√2: r = 1/√(1-2ζ²),
    G = 1/(2ζ√(1-ζ²)); None when G has no finite interior maximum, i.e. when
    ζ >= 1/√2 to within ``rel`` (decided exactly, :mod:`dyncli.exact`)."""
    if not (0.0 < zeta) or cmp_sqrt(zeta, Fraction(1, 2), rel) >= 0:
        return None
    r = 1.0 / math.sqrt(float(1 - 2 * Fraction(zeta) ** 2))     # 1 − 2ζ² exact, rounded once
    gm = 1.0 / (2.0 * zeta * math.sqrt((1.0 - zeta) * (1.0 + zeta)))
    return r, gm


def peak_g(zeta: float):
    """(r, g_max) of the maximum of g for ζ > 0:
    r² = 2/(1 + √(1+8ζ²)); None when ζ = 0 (unbounded at r = 1)."""
    if not zeta > 0.0:
        return None
    r = math.sqrt(2.0 / (1.0 + math.sqrt(1.0 + 8.0 * zeta * zeta)))
    _, _, g, _ = amplification_at(r, zeta)
    return r, g


def angle(y: float, x: float) -> float:
    """atan2 in (−π, π]: a −0.0 ordinate counts as +0.0 (the negative real
    axis gives +π); values just above −π are kept."""
    return math.atan2(y + 0.0, x) + 0.0


def amplitude_phase(w0: float, wd0: float, omega_n: float, zeta: float, omega_d: float,
                    regime: str) -> tuple[float | None, float | None, str | None]:
    """(A, φ, why) of the free motion's amplitude–phase form (17.10)-(17.12), (17.22c-e),
    (17.24c-e) from w(0) = w0, ẇ(0) = wd0: A or φ None where the form does not exist, ``why``
    the warning that says so (None when both exist)."""
    b = wd0 + zeta * omega_n * w0          # ξ'(0) of (17.21d)
    if regime == "critical":
        return None, None, "A and phi are null: the critically damped motion (17.23) has no amplitude–phase form"
    if regime in ("undamped", "underdamped"):
        q = b / omega_d
        A = math.hypot(w0, q)
        if A == 0.0:
            return 0.0, None, "phi is null: the mass starts at rest in equilibrium (A = 0), so the phase is undefined"
        return A, angle(w0, q), None
    # overdamped: w = A e^{-ζωt} sinh(ω*t + φ) needs cosh φ = b/(Aω*) ≥ 1
    q = b / omega_d
    if math.isfinite(q) and abs(q) > abs(w0):
        A = math.sqrt((abs(q) - abs(w0)) * (abs(q) + abs(w0)))
        phi = math.atanh(w0 / q)
        if q > 0:
            return A, phi, None
        return None, None, ("A and phi are null: the overdamped amplitude–phase form (17.24) needs "
                            "v0 + ζωₙw0 > ω*|w0| (here v0 + ζωₙw0 < −ω*|w0|); the motion is "
                            f"w = −{A:.6g} e^(−ζωₙt) sinh(ω*t {'−' if phi < 0 else '+'} {abs(phi):.6g})")
    return None, None, ("A and phi are null: the overdamped amplitude–phase form (17.24) exists only when "
                        "|v0 + ζωₙw0| > ω*|w0| (here it is not; the motion is "
                        "w0 e^(−ζωₙt)cosh(ω*t) + ... , computed exactly)")


#: a reported x, ẋ or w whose rounding error exceeds this fraction of its scale is warned about
LOSS_FRACTION = 1e-6


def phase_rounding(t: float, *, omega_n: float, zeta: float, L: float, w0: float, wd0: float,
                   f0: float = 0.0, Omega: float = 0.0):
    """Bounds on the errors of the closed form's (x, ẋ, w) at time t that come from its phases
    ω*·t and Ω·t held to one ulp — a free vibration (w0, ẇ0), plus a harmonic force f0 sin(Ωt)
    per unit mass — and the scales they are judged against: ((ex, ev, ew), (sx, sv, sw)).

    A phase error δ moves an oscillation of amplitude a by up to a·δ (and its rate by a·ω·δ): the
    free oscillation's amplitude decays as e^(−ζωₙt) (ζ < 1; no phase at all when ζ ≥ 1), the
    force's steady amplitude is f0/|ωₙ² − Ω² + 2iζωₙΩ| (growing as f0(1 + ωₙt)/(2ωₙ²) at undamped
    resonance) and the transient it starts is at most (1 + Ω/ωₙ) times that.  The scales are
    the a-priori sizes of the motion, not the computed values (garbage when digits are lost).

    >>> e, s = phase_rounding(1e17, omega_n=3 ** 0.5, zeta=0.0, L=0.5, w0=0.1, wd0=0.2)
    >>> e[0] > s[0]          # ωₙt ≈ 1.7e17 rad, held to ±32 rad: no digit left
    True
    >>> e, s = phase_rounding(1e3, omega_n=3 ** 0.5, zeta=0.0, L=0.5, w0=0.1, wd0=0.2)
    >>> e[0] < 1e-12 * s[0]
    True
    """
    c = 1.0 / math.sqrt(max(1.0 - zeta * zeta, 0.25))
    grow = math.exp(-zeta * omega_n * t) if zeta < 1.0 else 0.0   # an overdamped motion has no phase
    ah = (abs(w0) + abs(wd0) / omega_n) * c                        # the free oscillation's amplitude
    xp = r = 0.0
    if f0 != 0.0 and Omega != 0.0:
        r = Omega / omega_n
        den = omega_n * omega_n * math.hypot(1.0 - r * r, 2.0 * zeta * r)
        xp = abs(f0) * (1.0 + omega_n * t) / (2.0 * omega_n * omega_n) if den == 0.0 else abs(f0) / den
    at = (ah + xp * (1.0 + r) * c) * grow                           # everything oscillating at ω*
    # ωₙ = √(k/m) and Ω·t to half an ulp each; ω* = ωₙ√((1 − ζ)(1 + ζ)) two roundings more
    pf, ph = (1.0 if zeta == 0.0 else 3.0) * math.ulp(omega_n * t), math.ulp(Omega * t)
    ew = at * pf + xp * ph
    ev = at * omega_n * c * pf + xp * Omega * ph
    sw = ah + xp * (2.0 + r)
    sv = (ah + xp * (1.0 + r)) * omega_n * c + xp * Omega
    return (ew, ev, ew), (abs(L) + sw, sv, sw)


def base_rounding(t: float, *, omega_n: float, zeta: float, L: float, x0: float, v0: float,
                  s0: float, Omega: float, x: float, v: float, w: float):
    """Bounds on the rounding errors of the closed form's (x, ẋ, w) at time t under the base
    motion s = s0 sin(Ωt), and the scales they are judged against: ((ex, ev, ew), (sx, sv, sw)).

    The errors come from the magnitudes of the terms summed (x = w + s + L, ẋ = ẇ + ṡ, and w =
    w_h + w_f whose free part grows from w0 to the size |w0| + |ẇ0|/ωₙ, ẇ0 = v0 − s0Ω) and from the
    phases Ωt and ωₙt held to one ulp. The scales are the absolute motion's a-priori size
    (|x0 − L| + |v0|/ωₙ + 2 s0 T(r) with the transmissibility T, notes eq. 17.33), not the
    computed values (which are garbage when digits are lost).

    >>> e, s = base_rounding(0.1, omega_n=20.0, zeta=0.025, L=0.4, x0=0.2, v0=0.0, s0=0.002,
    ...                      Omega=3e17, x=0.0, v=0.0, w=0.0)
    >>> e[1] > s[1]          # ẋ: Y·Ω = 6e14 m/s cancels; nothing left
    True
    """
    eps = 2.0 ** -52
    th = Omega * t
    s, sd = s0 * math.sin(th), s0 * Omega * math.cos(th)
    w0, wd0 = x0 - L, v0 - s0 * Omega
    c = 1.0 / math.sqrt(max(1.0 - zeta * zeta, 0.25))
    ah = abs(w0) * c + abs(wd0) * min(t, 1.0 / omega_n)      # w_h's size by time t (w_h(0) = w0)
    av = abs(w0) * c * omega_n + abs(wd0)                     # ẇ_h's size (ẇ_h(0) = ẇ0)
    ph, pf = math.ulp(th), math.ulp(omega_n * t)
    wd = v - sd
    ew = eps * (abs(w) + 2 * ah) + 2 * s0 * ph + ah * pf
    ex = eps * (abs(s) + abs(w) + abs(L)) + ew + s0 * ph
    ev = eps * (abs(sd) + abs(wd) + 2 * av) + 3 * s0 * Omega * ph + av * pf
    r = Omega / omega_n
    den = math.hypot(1.0 - r * r, 2.0 * zeta * r)
    T = math.inf if den == 0.0 else math.hypot(1.0, 2.0 * zeta * r) / den
    y = abs(w0) + abs(v0) / omega_n + 2.0 * s0 * T
    sx = abs(L) + y
    sv = omega_n * (abs(w0) + 2.0 * s0 * T) + abs(v0) + s0 * T * Omega
    sw = y + s0
    return (ex, ev, ew), (sx, sv, sw)
