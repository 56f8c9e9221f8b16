"""The turning points of a vibration decided exactly, never by sampling (issue #28).

w = x − s − L obeys ẅ + 2ζωₙẇ + ωₙ²w = g(t) = F sin(Ωt) (17.15a: F = F0/m for a force on the
mass, s0Ω² for the base motion s = s0 sin(Ωt)).  w and ẇ are the exact closed form of
:mod:`.closed_form` (free part plus the divided-difference forced part: no cancellation at or
near resonance), every higher derivative follows from the equation of motion,
u⁽ᵏ⁺¹⁾ = g⁽ᵏ⁻¹⁾ − 2ζωₙu⁽ᵏ⁾ − ωₙ²u⁽ᵏ⁻¹⁾, and x⁽ⁿ⁾ = w⁽ⁿ⁾ + s⁽ⁿ⁾.  Each pair (u⁽ⁿ⁻¹⁾, u⁽ⁿ⁾) obeys
the same equation with the forcing g⁽ⁿ⁻¹⁾ (|g⁽ⁿ⁻¹⁾| ≤ FΩⁿ⁻¹ = G), so its energy
E = ωₙ²u⁽ⁿ⁻¹⁾² + u⁽ⁿ⁾² has E' = −4ζωₙu⁽ⁿ⁾² + 2u⁽ⁿ⁾g⁽ⁿ⁻¹⁾: over [m − h, m + h],
|u⁽ⁿ⁾| ≤ (√E(m) + Gh) e^{2ζωₙh} — a bound of |x⁽ⁿ⁾| on a cell from its middle alone.

The roots of f = x⁽ᵈ⁾ (d = 1: the turning points of x; d = 2: of v) on a cell [a, b] with
middle m and half-width h are decided by the sign analysis of f' = x⁽ᵈ⁺¹⁾ with J ≥ |f''| on the
cell: |f'(m)| > hJ proves f' has no root there, so f is monotone and its end values decide its
one root (a proven bracket, refined by Newton with the exact slope); |f(m)| > h|f'(m)| + h²J/2
proves f has no root (as does f = f' = J = 0: f ≡ 0, a mass at rest with nothing forcing it);
otherwise the cell is halved.  Two roots closer than the rounding of f
(a tangency: an inflection with a level tangent, or a pair of turning points that cancel to
rounding) end in cells of a few ulp: they are reported as ``touches`` (they move x by nothing
that a double can hold).  The cells start on the grid of breaks (a fraction of the shortest
period); a vectorised pass on numpy arrays for long grids, plain floats for short ones.  Each root
the arrays find is then re-found by the float search's own cells and Newton (:func:`float_root`):
the two routes give the same doubles (numpy's sin and exp need not round as the C library's do).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from . import closed_form as cf

_EPS = 2.220446049250313e-16
#: the most cells a search examines (beyond: the undecided cells are decided by their end signs);
#: a grid of 20,000 eighths of a period whose every root is of high order (~50 halvings each) needs
#: ~250,000; only inputs far outside the doubles' comfort reach it (Ω = 3e17 rad/s: ~0.3 s; ζ = 5e14
#: over 5e299 s, whose stiff derivatives leave every cell undecided: ~1.5 s)
MAX_CELLS = 400_000
#: the most roots of a free vibration listed in closed form
MAX_FREE_ROOTS = 16_000_000
#: |D| = |1 − r² + 2iζr| from which w, ẇ are the steady state plus a free part (their sum loses at
#: most a factor 1/|D| = 10 of relative accuracy); nearer resonance the divided-difference form
FAR = 0.1


@dataclass(frozen=True, slots=True)
class Motion:
    """ẅ + 2ζωₙẇ + ωₙ²w = F sin(Ωt), w(0) = w0, ẇ(0) = wd0; x = w + s0 sin(Ωt) + L (SI floats;
    s0 = 0 for a force on the mass, F = 0 without an excitation)."""
    omega_n: float
    zeta: float
    w0: float
    wd0: float
    F: float = 0.0
    Om: float = 0.0
    s0: float = 0.0


def jets(mo: Motion, t, d: int, X=None):
    """(x⁽ᵈ⁾, x⁽ᵈ⁺¹⁾, a bound of |x⁽ᵈ⁺²⁾| over [t − h, t + h] as a function of h, the rounding of
    x⁽ᵈ⁾) at t (a float, or an array with ``X = numpy``)."""
    wn, z, F, Om = mo.omega_n, mo.zeta, mo.F, mo.Om
    th = Om * t
    c, s = (math.cos(th), math.sin(th)) if X is None else (X.cos(th), X.sin(th))
    r = Om / wn
    D = complex((1.0 - r) * (1.0 + r), 2.0 * z * r)
    P = F / (wn * wn) / D if F != 0.0 and Om != 0.0 and abs(D) >= FAR else 0j
    if P != 0.0 and math.isfinite(abs(P)):        # the steady state plus the free part
        # (no cancellation); a steady amplitude beyond the doubles (F/ωₙ² overflows while the
        # motion itself does not) takes the divided-difference form, finite wherever the motion is
        w0, wd0 = mo.w0 - P.imag, mo.wd0 - Om * P.real
        u = [P.imag * c + P.real * s, Om * (P.real * c - P.imag * s)]
        Fh, amp = 0.0, abs(P) * (Om ** d + wn ** d)
    else:                                         # the divided-difference form (at and near resonance)
        w0, wd0, u, Fh, amp = mo.w0, mo.wd0, [0.0, 0.0], F, 0.0
    if X is None:
        X = math
        wh, vh = cf.free_at(t, w0, wd0, wn, z)
        wf, vf = cf.forced_at(t, Fh, Om, wn, z)
    else:
        wh, vh = cf.free(t, w0, wd0, wn, z)
        wf, vf = cf.forced(t, Fh, Om, wn, z)
    u = [wh + wf + u[0], vh + vf + u[1]]
    trig = (s, c, -s, -c)                          # sin(θ + kπ/2)
    for k in range(1, d + 2):                      # u⁽ᵏ⁺¹⁾ from the equation of motion
        u.append(F * Om ** (k - 1) * trig[(k - 1) % 4] - 2.0 * z * wn * u[k] - wn * wn * u[k - 1])
    n = d + 2
    f = u[d] + mo.s0 * Om ** d * trig[d % 4]
    fd = u[d + 1] + mo.s0 * Om ** (d + 1) * trig[(d + 1) % 4]
    noise = 16 * _EPS * (abs(u[d]) + 2.0 * z * wn * abs(u[d - 1]) + wn * wn * abs(u[max(d - 2, 0)])
                         + abs(F) * Om ** max(d - 2, 0) + abs(mo.s0) * Om ** d + amp)
    root_e = _root(X, wn * wn * u[n - 1] * u[n - 1] + u[n] * u[n], wn * u[n - 1], u[n])
    G, grow, sn = abs(F) * Om ** (n - 1), 2.0 * z * wn, abs(mo.s0) * Om ** n

    def bound(h):
        return ((root_e + G * h) * X.exp(grow * h) + sn) * (1.0 + 1e-9)
    return f, fd, bound, noise


def _root(X, s, a, b):
    """√s of s = a² + b² (as the caller rounded it): its doubles wherever s is finite, and where s
    overflows (a motion of ~1e300: a bound of inf left every cell undecided, halved to the budget
    of cells) m √((a/m)² + (b/m)²), m = max(|a|, |b|): the same operations on floats and on
    arrays, so both searches keep making the same doubles."""
    if X is math:
        if s < math.inf:
            return math.sqrt(s)
        m = max(abs(a), abs(b))
        if not m < math.inf:
            return m
        p, q = a / m, b / m
        return m * math.sqrt(p * p + q * q)
    np = getattr(X, "np", X)                        # (the C library's functions on arrays, or numpy)
    s, a, b = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (s, a, b)))
    r = np.sqrt(s)
    big = ~(s < np.inf)
    if big.any():
        a, b = a[big], b[big]
        m = np.maximum(np.abs(a), np.abs(b))
        with np.errstate(invalid="ignore", divide="ignore"):
            p, q = a / m, b / m
            scaled = m * np.sqrt(p * p + q * q)
        r = r.copy()
        r[big] = np.where(m < np.inf, scaled, m)
    return r


def _fast_jets(mo: Motion, d: int, X=math):
    """:func:`jets` with its constants hoisted (the steady state plus an underdamped free part: a
    few floating operations per time), or None where that form does not apply (ζ ≥ 1, no
    excitation, near resonance): in plain floats (no numpy), or with ``X = numpy`` on arrays of
    times (the same operations, element by element)."""
    wn, z, F, Om = mo.omega_n, mo.zeta, mo.F, mo.Om
    r = Om / wn
    D = complex((1.0 - r) * (1.0 + r), 2.0 * z * r)
    if not (0.0 <= z < 1.0 and F != 0.0 and Om != 0.0 and abs(D) >= FAR):
        return None
    P = F / (wn * wn) / D
    Pr, Pi = P.real, P.imag
    a0, b0 = mo.w0 - Pi, mo.wd0 - Om * Pr
    ws, sig = cf.roots(wn, z)[0], z * wn
    q0, q1 = (b0 + sig * a0) / ws, (-2.0 * sig * b0 - wn * wn * a0 + sig * b0) / ws
    if not all(map(math.isfinite, (a0, b0, q0, q1, Pr, Pi))):
        return None
    n, wn2, two = d + 2, wn * wn, 2.0 * z * wn
    G, sn = abs(F) * Om ** (n - 1), abs(mo.s0) * Om ** n
    base = 16 * _EPS * (abs(F) * Om ** max(d - 2, 0) + abs(mo.s0) * Om ** d + abs(P) * (Om ** d + wn ** d))
    Fk = [F * Om ** (k - 1) for k in range(1, d + 2)]
    sd, sd1 = mo.s0 * Om ** d, mo.s0 * Om ** (d + 1)
    exp, cos, sin = X.exp, X.cos, X.sin

    def derivatives(t: float):
        ex, y, th = exp(-sig * t), ws * t, Om * t
        cy, sy, c, s = cos(y), sin(y), cos(th), sin(th)
        u = [ex * (a0 * cy + q0 * sy) + Pi * c + Pr * s, ex * (b0 * cy + q1 * sy) + Om * (Pr * c - Pi * s)]
        trig = (s, c, -s, -c)
        for k in range(1, d + 2):
            u.append(Fk[k - 1] * trig[(k - 1) % 4] - two * u[k] - wn2 * u[k - 1])
        return u, u[d] + sd * trig[d % 4], u[d + 1] + sd1 * trig[(d + 1) % 4]

    def slope(t: float):
        _, f, fd = derivatives(t)
        return f, fd

    def jet(t: float):
        u, f, fd = derivatives(t)
        noise = 16 * _EPS * (abs(u[d]) + two * abs(u[d - 1]) + wn2 * abs(u[max(d - 2, 0)])) + base
        root_e = _root(X, wn2 * u[n - 1] * u[n - 1] + u[n] * u[n], wn * u[n - 1], u[n])

        def bound(h):
            return ((root_e + G * h) * exp(two * h) + sn) * (1.0 + 1e-9)
        return f, fd, bound, noise
    setattr(jet, "slope", slope)        # (f, f') alone, the same doubles: Newton's steps need no bound
    return jet


def roots(mo: Motion, breaks: list[float], d: int = 1, on_arrays: bool = False):
    """(the roots of x⁽ᵈ⁾ in [breaks[0], breaks[-1]], sorted; the touches; whether the cell
    budget ran out), decided by sign analysis on cells starting at the breaks."""
    if len(breaks) < 2 or breaks[-1] <= breaks[0]:
        return [], [], False
    f, fd, bound, _ = jets(mo, breaks[0], d)
    if f == 0.0 and fd == 0.0 and bound(breaks[-1] - breaks[0]) == 0.0:
        return [], [], False                     # x⁽ᵈ⁾ ≡ 0: at rest, nothing forcing it (no isolated root)
    if on_arrays:
        return _roots_arrays(mo, breaks, d)
    return _roots_floats(mo, breaks, d)


def free_roots(mo: Motion, d: int, t_end: float) -> list[float] | None:
    """The roots of x⁽ᵈ⁾ in (0, t_end) of an underdamped free vibration in closed form (None
    otherwise): x⁽ᵈ⁾ = e^{−ζωₙt}(c cos ω*t + q sin ω*t) = 0 at ω*t = α + π/2 + kπ, α = atan2(q, c),
    c = x⁽ᵈ⁾(0), q = (x⁽ᵈ⁺¹⁾(0) + ζωₙc)/ω*."""
    wn, z = mo.omega_n, mo.zeta
    if mo.F != 0.0 or mo.s0 != 0.0 or not 0.0 <= z < 1.0:
        return None
    u = [mo.w0, mo.wd0]
    for k in range(1, d + 1):
        u.append(-2.0 * z * wn * u[k] - wn * wn * u[k - 1])
    c, e = u[d], u[d + 1]
    ws = cf.roots(wn, z)[0]
    if (c == 0.0 and e == 0.0) or not (ws > 0 and math.isfinite(c) and math.isfinite(e)):
        return []
    first = (math.atan2((e + z * wn * c) / ws, c) + 0.5 * math.pi) % math.pi
    first = first or math.pi
    n = math.floor((t_end * ws - first) / math.pi) + 1
    if n > MAX_FREE_ROOTS:
        return None
    return [t for t in ((first + k * math.pi) / ws for k in range(max(n, 0))) if 0.0 < t < t_end]


def _classify(f, fd, bound, noise, h):
    """+1 monotone (at most one root: the end signs decide it), 0 no root, -1 undecided."""
    J = bound(h)
    if f == 0.0 and fd == 0.0 and J == 0.0:        # f ≡ 0 on the cell (at rest, nothing forcing it)
        return 0
    if abs(fd) > h * J:
        return 1
    if abs(f) > h * abs(fd) + 0.5 * h * h * J + noise:
        return 0
    return -1


def _roots_floats(mo: Motion, breaks: list[float], d: int):
    jet = _fast_jets(mo, d) or (lambda t: jets(mo, t, d))
    F = [jet(t)[0] for t in breaks]
    out: list[float] = [t for t, f in zip(breaks[1:-1], F[1:-1]) if f == 0.0]
    stack = [(a, b, fa, fb) for a, b, fa, fb in zip(breaks, breaks[1:], F, F[1:])][::-1]
    got, touches, cells = _cells_floats(jet, stack, breaks[0], breaks[-1], 0)
    return sorted(set(out + got)), touches, cells >= MAX_CELLS


def _cells_floats(jet, stack: list, lo: float, hi: float, cells: int):
    """(the roots, the touches, the cells examined so far) of the cells (a, b, f(a), f(b)) on
    ``stack`` (the last first) of the search over [lo, hi], in plain floats."""
    span = hi - lo                          # cells below its rounding are not halved further
    out: list[float] = []
    touches: list[float] = []
    while stack:
        a, b, fa, fb = stack.pop()
        m, h = 0.5 * (a + b), 0.5 * (b - a)
        cells += 1
        f, fd, bound, noise = jet(m)
        kind = _classify(f, fd, bound, noise, h) if cells < MAX_CELLS else 1
        if kind == 1 or (kind == -1 and (m <= a or m >= b or h <= 4 * _EPS * max(abs(m), span))):
            if fa * fb < 0:
                out.append(_newton(jet, a, b, fa, fb))
            elif kind == -1 and abs(f) <= noise and lo < a and b < hi:
                touches.append(m)
        elif kind == -1:
            if f == 0.0:
                out.append(m)
            stack += [(m, b, f, fb), (a, m, fa, f)]
    return out, touches, cells


#: when this few cells are left undecided, the array search finishes them in plain floats (a cell
#: at a root of high order, such as a start from rest, is halved some 40 times: one float
#: evaluation each instead of a round of array operations)
FEW_CELLS = 8


def _newton(jet, a: float, b: float, fa: float, fb: float) -> float:
    """The one root of f = x⁽ᵈ⁾ in a proven bracket: Newton with the exact slope, bisection when
    a step leaves the bracket, to a step below 4 ulp."""
    slope = getattr(jet, "slope", None) or (lambda t: jet(t)[:2])
    t = a - fa * (b - a) / (fb - fa)
    for _ in range(200):
        f, fd = slope(t)
        if f == 0.0:
            return t
        if (f > 0) == (fa > 0):
            a, fa = t, f
        else:
            b, fb = t, f
        step = t - f / fd if fd else math.nan
        t_new = step if a <= step <= b else 0.5 * (a + b)
        if abs(t_new - t) <= 4 * _EPS * abs(t) or b - a <= 4 * _EPS * abs(b):
            return t_new
        t = t_new
    return t


class _LibmArrays:
    """numpy's arithmetic with the C library's exp, sin and cos element by element: the array
    search then makes the plain-float search's very doubles (+ − × / and √ round correctly in
    both; numpy's own exp need not round as the C library's does)."""

    def __init__(self, np):
        self.np, self.sqrt = np, np.sqrt

    def _each(self, fn, t):
        return self.np.fromiter(map(fn, self.np.asarray(t, dtype=float).ravel().tolist()), float)

    def exp(self, t):
        return self._each(math.exp, t)

    def sin(self, t):
        return self._each(math.sin, t)

    def cos(self, t):
        return self._each(math.cos, t)


def _roots_arrays(mo: Motion, breaks: list[float], d: int):
    import numpy as np

    jet = _fast_jets(mo, d, _LibmArrays(np))
    if jet is None:                     # (the general form: numpy's own functions, then each root re-found)
        jf = lambda t: jets(mo, t, d)   # noqa: E731
        got, touches, more = _search_arrays(mo, lambda t: jets(mo, t, d, np), breaks, d, np)
        return sorted({float_root(jf, breaks, r) for r in got}), touches, more
    return _search_arrays(mo, jet, breaks, d, np)


def _search_arrays(mo: Motion, jet, breaks: list[float], d: int, np):
    """:func:`_roots_floats` cell by cell on arrays (``jet`` on arrays of times), each root then
    refined by the same :func:`_newton` in plain floats."""
    jf = _fast_jets(mo, d) or (lambda t: jets(mo, t, d))
    T = np.asarray(breaks, dtype=float)
    F = jet(T)[0]
    found = [T[1:-1][F[1:-1] == 0.0].tolist()]
    a, b, fa, fb = T[:-1], T[1:], F[:-1], F[1:]
    touches: list = []
    ends: list[list] = [[], [], [], []]
    cells = 0
    while a.size:
        if a.size <= FEW_CELLS and cells:
            got, more, cells = _cells_floats(jf, list(zip(a.tolist(), b.tolist(), fa.tolist(), fb.tolist()))[::-1],
                                             breaks[0], breaks[-1], cells)
            found.append(got)
            touches += more
            break
        m, h = 0.5 * (a + b), 0.5 * (b - a)
        cells += a.size
        f, fd, bound, noise = jet(m)
        J = bound(h)
        mono = np.abs(fd) > h * J
        und = ~mono & ~(np.abs(f) > h * np.abs(fd) + 0.5 * h * h * J + noise) & ~((f == 0) & (fd == 0) & (J == 0))
        tiny = (m <= a) | (m >= b) | (h <= 4 * _EPS * np.maximum(np.abs(m), T[-1] - T[0])) | (cells >= MAX_CELLS)
        end = mono | (und & tiny)
        touches += m[und & tiny & (fa * fb >= 0) & (np.abs(f) <= noise) & (a > T[0]) & (b < T[-1])].tolist()
        for lst, arr in zip(ends, (a, b, fa, fb)):
            lst.append(arr[end])
        split = und & ~tiny
        found.append(m[split & (f == 0.0)].tolist())
        a, b, fa, fb, m, f = a[split], b[split], fa[split], fb[split], m[split], f[split]
        a, b, fa, fb = np.concatenate([a, m]), np.concatenate([m, b]), np.concatenate([fa, f]), np.concatenate([f, fb])
    A, B, FA, FB = (np.concatenate(x) for x in ends)
    k = FA * FB < 0
    out = [t for got in found for t in got]
    slope = getattr(jet, "slope", None)
    if slope is not None and k.sum() > MANY_ROOTS:
        out += _newton_arrays(slope, A[k], B[k], FA[k], FB[k], np).tolist()
    else:
        out += [_newton(jf, *c) for c in zip(A[k].tolist(), B[k].tolist(), FA[k].tolist(), FB[k].tolist())]
    return sorted(set(out)), sorted(touches), cells >= MAX_CELLS


#: from this many brackets on, Newton runs on arrays (below: a call per bracket costs less than a
#: round of array operations)
MANY_ROOTS = 48


def _newton_arrays(slope, a, b, fa, fb, np):
    """:func:`_newton` on many brackets at once (``slope``: (f, f') on an array of times), each
    element by the same operations in the same order: the same doubles as one call per bracket."""
    t = a - fa * (b - a) / (fb - fa)
    out = np.empty_like(t)
    idx = np.arange(t.size)
    for _ in range(200):
        if not idx.size:
            break
        f, fd = slope(t)
        zero = f == 0.0
        out[idx[zero]] = t[zero]
        keep = ~zero
        idx, a, b, fa, fb, t, f, fd = (x[keep] for x in (idx, a, b, fa, fb, t, f, fd))
        same = (f > 0) == (fa > 0)
        a, fa = np.where(same, t, a), np.where(same, f, fa)
        b, fb = np.where(same, b, t), np.where(same, fb, f)
        with np.errstate(all="ignore"):
            step = np.where(fd != 0, t - f / fd, np.nan)
        t_new = np.where((a <= step) & (step <= b), step, 0.5 * (a + b))
        done = (np.abs(t_new - t) <= 4 * _EPS * np.abs(t)) | (b - a <= 4 * _EPS * np.abs(b))
        out[idx[done]] = t_new[done]
        keep = ~done
        idx, a, b, fa, fb, t = (x[keep] for x in (idx, a, b, fa, fb, t_new))
    out[idx] = t
    return out


def float_root(jet, breaks: list[float], r: float) -> float:
    """The root near ``r`` (found on arrays) as the plain-float search finds it, bit for bit: the
    cells of :func:`_cells_floats` that hold ``r`` followed from its break cell, halved as it
    halves them, then the same :func:`_newton` on the first cell it decides — so the answer does
    not depend on the route (numpy's sin and exp may differ from the C library's in the last bit,
    and the vectorised Newton steps from other ends).  ``r`` itself where the float search would
    not end at a sign change around it (a root at a break or a midpoint, a cell the float sign
    analysis calls rootless: only at a tangency, within the rounding of x⁽ᵈ⁾)."""
    import bisect

    i = bisect.bisect_right(breaks, r) - 1
    if not 0 <= i < len(breaks) - 1 or breaks[i] == r:
        return r
    lo, hi = breaks[0], breaks[-1]
    span = hi - lo
    a, b = breaks[i], breaks[i + 1]
    fa, fb = jet(a)[0], jet(b)[0]
    while True:
        m, h = 0.5 * (a + b), 0.5 * (b - a)
        f, fd, bound, noise = jet(m)
        kind = _classify(f, fd, bound, noise, h)
        if kind == 1 or (kind == -1 and (m <= a or m >= b or h <= 4 * _EPS * max(abs(m), span))):
            return _newton(jet, a, b, fa, fb) if fa * fb < 0 else r
        if kind == 0 or f == 0.0 or r == m:
            return m if f == 0.0 else r
        a, b, fa, fb = (a, m, fa, f) if r < m else (m, b, f, fb)
