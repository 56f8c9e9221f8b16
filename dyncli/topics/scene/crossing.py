"""The first crossing of a watched quantity of a scene over a span of its motion, decided by
sign analysis, never by samples (docs/types/scene.md: which events are found).

A watched quantity g (motion.watches: a normal force, a tension, a friction margin μ_s N ∓ F, a
gap, a slip speed, a one-sided spring's stretch) is a smooth function of t within a phase.  Its
roots are the sign changes found by :func:`dyncli.rootfind.all_roots` (Chebyshev cells halved
until resolved; between the critical points of a cell's interpolant at most one root).  g is
known to its rounding only (:func:`rounding`): an event is g passing below minus its rounding,
then located on g itself, so that a gap at 0 as a body leaves its surface is not read as impacts
in the noise.  The exact routes search whole pieces (routes.py); the ODE route screens each
step's interpolant (:func:`step_screen`) and searches the steps the screen cannot clear.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from dyncli.errors import NumericalError
from dyncli.rootfind import all_roots, brent

from . import assembly

EPS = float(np.finfo(float).eps)


def rounding(s, q, v, t: float, v_end) -> dict[str, float]:
    """The rounding of each kind of watched quantity over a span that starts at (q, v, t) and
    ends with the velocities ``v_end``: 64 ε of the scene's lengths (gaps, margins, stretches:
    its positions, sizes and the lengths its cords hold),
    of its forces (the applied loads and the multipliers at the start) and of its speeds (at both
    ends)."""
    f, _P = s.applied(q, v, t)
    lam = s.solve(q, v, t)[1]
    big = lambda *xs: max([float(np.max(np.abs(x), initial=0.0)) for x in xs] + [1e-300])   # noqa: E731
    # a length a joint holds (a cord's runs) is a scale of its gap's rounding too
    held = [abs(float(c)) for e in s.elements for c in (getattr(e, "consts", None) or ())]
    L, F, V = max([assembly.length_scale(q, s)] + held), big(f, lam), big(v, v_end)
    lengths, speeds = ("impact", "leaves", "switch", "taut", "wraps", "unwraps", "reaches", "turns"), ("sticks",)
    return {what: 64 * EPS * (L if what in lengths else V if what in speeds else F) for what in WATCHED}


#: the watched quantities (motion.watches): lengths (impact, leaves, switch, taut, wraps, unwraps, reaches,
#: turns: a cord's arc on its pulley three eighths of a turn on, a new phase without an event),
#: a speed (sticks) and forces (separates, slips, slack, and reverses: the normal force of a
#: sliding two-sided rough guide changing sign, a new phase without an event)
WATCHED = ("impact", "leaves", "switch", "taut", "wraps", "unwraps", "reaches", "turns", "sticks", "separates",
           "slips", "slack", "reverses")
#: the watched quantities that are forces of the joints (functions of the multipliers alone)
FORCES = ("separates", "slips", "slack", "reverses")


def first_crossing(g, a: float, b: float, what: str, tol: float, start: bool, cells: int) -> float | None:
    """The first time in [a, b] where ``g`` (on arrays; known to ``tol``) crosses its event, or
    None: down through −tol, then located on g itself (a one-sided spring's stretch, "switch",
    either way).  At a phase's start (``start``) a quantity on its band of rounding goes off it
    first (a force at 0 that goes negative is where the last phase ended; a stretch at 0 is where
    the spring switched), except that a gap, a slip speed or an end's margin at 0 that goes
    negative is an event there (a block started at a table's edge, moving off it); elsewhere a quantity on its band comes from its side of 0 (a search resumed)."""
    g0 = float(g(np.array([a]))[0])
    if what == "switch" or abs(g0) <= tol and start and what not in ("sticks", "impact", "taut", "leaves", "reaches"):
        if abs(g0) <= tol and start:    # off the band first: g² reaches (2 tol)²
            off = _first_down(lambda ts: 4 * tol * tol - g(ts) ** 2, a, b, tol * tol, cells)
            if off is None:
                return None
            a = off[0]
            g0 = float(g(np.array([a]))[0])
        sign = 1.0 if what != "switch" or g0 > 0 else -1.0
    else:
        sign = 1.0
    got = _first_down(lambda ts: sign * g(ts) + tol, a, b, tol, cells)
    if got is None:
        return None
    r, x = got                      # g's own root is the last before r: from x (g on the far side)
    gr, gx = sign * float(g(np.array([r]))[0]), sign * float(g(np.array([x]))[0])
    if not gr < 0 < gx:
        return r
    near = r - 2 * (r - x) * gr / (gr - gx)     # (the secant's root of g, twice as far: a tight bracket)
    if x < near < r and sign * float(g(np.array([near]))[0]) > 0:
        x = near
    return brent(lambda t: sign * float(g(np.array([t]))[0]), x, r, 4 * EPS * abs(r), 4 * EPS, 200)


#: what :func:`quadratic_crossing` returns when the quadratic's picture is too close to call
UNDECIDED = "undecided"


def quadratic_crossing(g, a: float, b: float, tol: float, err):
    """The first crossing in [a, b] of a watched quantity that is a quadratic in t by structure
    (a gap affine in the positions, over a phase of constant accelerations: routes.py), decided
    from the quadratic itself instead of a search: g read at a, the midpoint and b gives its
    coefficients, known to 2 ``err(a, b)`` (the rounding of a reading over [a, b]).  Where
    g + tol stays above that over [a, b], the answer is None.  Where it turns negative at a
    simple root, the span is first narrowed to just past that root while the quadratic's error
    (of the largest coordinates over the span) exceeds tol/2, then: the root must move it by
    8 × its error within a bracket that readings of g itself confirm (g > 0 at the bracket's
    start, g + tol < 0 at its end, the quadratic + tol above its error from a to there); the
    answer is g's own root before it (the last root of the quadratic), bracketed the same way and
    located by Brent on g itself — the event of :func:`first_crossing` for the quantities of
    kinds "impact" and "taut" (no band rule at a start).  Anything closer to call (a graze, a
    start below the band, a root at an end) is UNDECIDED: the caller searches as before."""
    b0 = b
    for _ in range(4):
        if not b > a:
            return UNDECIDED
        h = b - a
        g0, gm, g1 = (float(x) for x in g(np.array([a, a + 0.5 * h, b])))
        c2 = 2.0 * (g0 - 2.0 * gm + g1)           # S(u) = g0 + c1 u + c2 u², u = (t − a)/h
        c1 = g1 - g0 - c2
        e = 2.0 * err(a, b)                         # the quadratic's error (1.25 × a reading's, rounded up)
        if not g0 + tol > 2 * e:
            return UNDECIDED
        if _low(g0, c1, c2, 1.0) + tol > 2 * e:
            return None if b == b0 else UNDECIDED
        u_f = _first_root(c2, c1, g0 + tol)        # where S + tol turns negative
        if u_f is None or not 0 < u_f <= 1:
            return UNDECIDED
        if e <= tol / 2:
            break
        b = a + h * min(1.0, u_f + max(16 * e / max(-(c1 + 2 * c2 * u_f), 1e-300), 1 / 16))
    else:
        return UNDECIDED
    u_g = _first_root(c2, c1, g0)                  # S's own root before it
    if u_g is None or not 0 < u_g <= u_f:
        return UNDECIDED
    slope_f, slope_g = c1 + 2 * c2 * u_f, c1 + 2 * c2 * u_g
    if not (slope_f < 0 and slope_g < 0):
        return UNDECIDED
    w_f, w_g = 8 * e / -slope_f, 8 * e / -slope_g
    x, r = a + h * (u_g - w_g), a + h * min(u_f + w_f, 1.0)
    if not (a < x and _low(g0, c1, c2, u_g - w_g) + tol > 2 * e):
        return UNDECIDED
    gx, gr = (float(v) for v in g(np.array([x, r])))
    if not (gx > 0 and gr + tol < 0):
        return UNDECIDED
    r_g = a + h * min(u_g + w_g, 1.0)
    if float(g(np.array([r_g]))[0]) < 0:
        r = r_g
    return brent(lambda t: float(g(np.array([t]))[0]), x, r, 4 * EPS * abs(r), 4 * EPS, 200)


class Sinusoid:
    """f(t) = c0 + c1 τ + c2 τ² + P cos φ + Q sin φ with φ = θ0 + ω τ, τ = t − t0: a body point's
    coordinate along a fixed direction over a phase of constant accelerations in which its body
    turns at a constant rate (no angular acceleration: a free rigid body under gravity) — its
    centre's coordinate a quadratic, its arm Q(φ) p turning uniformly.  Its critical points are
    decided from the form, not by samples: f'' = 2 c2 − ω² |p| cos(φ − ψ) vanishes where
    cos(φ − ψ) = 2 c2 / (ω² |p|), in closed form (two per turn at most); between two of those
    f' is monotone, so it has at most one root there, located by Brent where its ends' signs
    differ: between consecutive critical points f is monotone."""

    def __init__(self, t0: float, c0: float, c1: float, c2: float, P: float, Q: float, th0: float, w: float):
        self.t0, self.c0, self.c1, self.c2, self.P, self.Q, self.th0, self.w = t0, c0, c1, c2, P, Q, th0, w

    def __call__(self, t: float) -> float:
        tau = t - self.t0
        ph = self.th0 + self.w * tau
        return self.c0 + self.c1 * tau + self.c2 * tau * tau + self.P * math.cos(ph) + self.Q * math.sin(ph)

    def rate(self, t: float) -> float:
        tau = t - self.t0
        ph = self.th0 + self.w * tau
        return self.c1 + 2.0 * self.c2 * tau + self.w * (self.Q * math.cos(ph) - self.P * math.sin(ph))

    def inflections(self, a: float, b: float, most: int = 4096) -> list[float] | None:
        """The zeros of f'' inside (a, b), sorted (None: more than ``most``)."""
        amp = math.hypot(self.P, self.Q)
        scale = self.w * self.w * amp
        if not scale > 0.0:
            return []                               # f'' = 2 c2 (ω² |p| below the doubles): one sign
        kappa = 2.0 * self.c2 / scale
        if not abs(kappa) < 1.0:
            return []                               # f'' of one sign (touching 0 at most)
        psi, alpha = math.atan2(self.Q, self.P), math.acos(kappa)
        pa, pb = sorted((self.th0 + self.w * (a - self.t0), self.th0 + self.w * (b - self.t0)))
        if not ((pb - pa) / math.pi <= most and max(abs(pa), abs(pb)) <= 1e12):
            return None                             # (too many turns, or angles past a turn's resolution)
        out = []
        for base in (psi + alpha, psi - alpha):
            k = math.floor((pa - base) / (2 * math.pi))
            while True:
                ph = base + 2 * math.pi * k
                if ph > pb:
                    break
                t = self.t0 + (ph - self.th0) / self.w
                if a < t < b:
                    out.append(t)
                k += 1
        return sorted(out)

    def monotone(self, a: float, b: float) -> list[float] | None:
        """[a, ..., b]: the critical points of f inside (a, b) (and the zeros of f''), between any
        two consecutive of which f is monotone; None when there are too many to list."""
        inf = self.inflections(a, b)
        if inf is None:
            return None
        cuts = [a] + inf + [b]
        out = [a]
        for u, w in zip(cuts[:-1], cuts[1:]):
            du, dw = self.rate(u), self.rate(w)
            if du * dw < 0:                         # f' monotone on [u, w]: its one root there
                out.append(brent(self.rate, u, w, 4 * EPS * max(abs(u), abs(w)), 4 * EPS, 200))
            out.append(w)
        return out

    def roots(self, level: float, a: float, b: float) -> list[float] | None:
        """The times in (a, b) where f crosses ``level`` (one per monotone piece whose ends lie
        on either side), sorted; None when the pieces are too many to list."""
        cuts = self.monotone(a, b)
        if cuts is None:
            return None
        out = []
        for u, w in zip(cuts[:-1], cuts[1:]):
            fu, fw = self(u) - level, self(w) - level
            if fu * fw < 0:
                out.append(brent(lambda t: self(t) - level, u, w, 4 * EPS * max(abs(u), abs(w)), 4 * EPS, 200))
        return out


def sinusoid_crossing(G: Sinusoid, S: Sinusoid | None, length: float | None, g, a: float, b: float,
                      tol: float, e: float):
    """The first impact in [a, b] of a body point that turns with its body at a constant rate
    over a line (a gap ``G`` of the form :class:`Sinusoid`; ``S``, its place along the line from
    the line's origin, ``length`` its extent, None for none), decided from the form instead of
    a search — the event of :func:`first_crossing` for a gap ("impact": the gap passing below
    −tol over the line's extent, located on the gap itself).  ``g`` is the watched quantity as
    the scene computes it (on arrays), ``e`` the forms' error (of a reading, rounded up).  The
    forms are first checked against ``g`` at a, b and the midpoint.  The extent is widened by
    2e (the times where the scene's own margin may be ≥ 0); over it G + tol must stay above 2e
    until the first monotone piece of G where G + tol goes from above 2e to below −2e, whose
    crossing and G's own root before it (G above 2e at the piece's start) are bracketed as in
    :func:`quadratic_crossing`, the bracket confirmed by readings of g (g > 0 at its start,
    g + tol < 0 at its end) and the root located by Brent on g itself.  Anything closer to call
    (a graze, an entry onto the line's extent below the band, a start below it) is UNDECIDED:
    the caller searches as before."""
    def watch(t: float) -> float:
        gap = G(t)
        if S is None or length is None:
            return gap
        s = S(t)
        m = min(s, length - s)
        return gap if m >= 0 else abs(gap) - m

    ts = [a, 0.5 * (a + b), b]
    got = [float(x) for x in g(np.array(ts))]
    if any(not abs(watch(t) - x) <= 2 * e and not (S is not None and _near_end(S, length, t, 2 * e))
           for t, x in zip(ts, got)):
        return UNDECIDED
    if not got[0] + tol > 2 * e:
        return UNDECIDED
    # the times the scene's margin may be >= 0: the extent widened by 2e on either side
    if S is None or length is None:
        spans = [(a, b)]
    else:
        lo, hi = S.roots(-2 * e, a, b), S.roots(length + 2 * e, a, b)
        if lo is None or hi is None:
            return UNDECIDED
        B = [a] + sorted(lo + hi) + [b]
        spans = [(u, w) for u, w in zip(B[:-1], B[1:]) if -2 * e <= S(0.5 * (u + w)) <= length + 2 * e]
    for u, w in spans:
        if not G(u) + tol > 2 * e:                  # (entering the extent below the band)
            return UNDECIDED
        cuts = G.monotone(u, w)
        if cuts is None:
            return UNDECIDED
        for p0, p1 in zip(cuts[:-1], cuts[1:]):
            v1 = G(p1) + tol
            if v1 > 2 * e:
                continue
            if not (v1 < -2 * e and G(p0) > 2 * e):
                return UNDECIDED
            u_f = brent(lambda t: G(t) + tol, p0, p1, 4 * EPS * abs(p1), 4 * EPS, 200)
            u_g = brent(G, p0, u_f, 4 * EPS * abs(u_f), 4 * EPS, 200)
            slope_f, slope_g = G.rate(u_f), G.rate(u_g)
            if not (slope_f < 0 and slope_g < 0):
                return UNDECIDED
            x, r = max(p0, u_g - 8 * e / -slope_g), min(u_f + 8 * e / -slope_f, p1)
            if S is not None and length is not None and not all(2 * e < S(t) < length - 2 * e
                                                                 for t in (x, u_g, u_f, r)):
                return UNDECIDED            # (an event at the extent's end: the search decides)
            gx, gr = (float(v) for v in g(np.array([x, r])))
            if not (x > a and gx > 0 and gr + tol < 0):
                return UNDECIDED
            r_g = min(u_g + 8 * e / -slope_g, r)
            if float(g(np.array([r_g]))[0]) < 0:
                r = r_g
            return brent(lambda t: float(g(np.array([t]))[0]), x, r, 4 * EPS * abs(r), 4 * EPS, 200)
    return None


def _near_end(S, length, t: float, e: float) -> bool:
    """Whether the place ``S`` at t is within e of an end of the extent (where the scene's own
    margin and the form's may have opposite signs)."""
    s = S(t)
    return abs(s) <= e or abs(length - s) <= e


def _low(c0: float, c1: float, c2: float, u: float) -> float:
    """The least value of c0 + c1 x + c2 x² over x in [0, u]."""
    m = min(c0, c0 + c1 * u + c2 * u * u)
    if c2 > 0 and 0 < -c1 / (2 * c2) < u:
        m = min(m, c0 - c1 * c1 / (4 * c2))
    return m


def _first_root(c2: float, c1: float, c0: float) -> float | None:
    """The smaller real root of c2 u² + c1 u + c0 where the quadratic goes from positive to
    negative (c0 > 0: the first root in u > 0 with a negative slope), by the stable formula;
    None when it has none."""
    if c2 == 0:
        return -c0 / c1 if c1 < 0 else None
    disc = c1 * c1 - 4 * c2 * c0
    if disc < 0:
        return None
    sq = disc ** 0.5
    q = -0.5 * (c1 + (sq if c1 >= 0 else -sq))
    roots = sorted(x for x in ((q / c2) if q != 0 else None, (c0 / q) if q != 0 else None) if x is not None)
    down = [x for x in roots if x > 0 and c1 + 2 * c2 * x < 0]
    return down[0] if down else None


def _first_down(f, a: float, b: float, floor: float, cells: int) -> tuple[float, float] | None:
    """The first root r in (a, b] where ``f`` (on arrays, smooth) turns negative, and a time
    before it where f > 0 (the midpoint from the root before), or None; all_roots (``floor``:
    the rounding of f) asked for the roots of its first cell that holds one, resumed after them
    while none is r."""
    lo = prev = a
    while True:
        roots, touches, bad = all_roots(f, lo, b, cells=cells, limit=FIRST_ROOTS, floor=floor, batch=1)
        best = None
        for r in sorted(r for r in roots if r > lo):
            if float(f(np.array([0.5 * (prev + r)]))[0]) > 0:
                best = (r, 0.5 * (prev + r))
                break
            prev = r
        # a cell still unresolved at the depth limit (2^-48 of its window) is a kink of g (a gap
        # watched as |gap| − margin past a surface's end): no root where g is far off its rounding
        bad = [m for m in bad if not abs(float(f(np.array([m]))[0])) > 2.0 ** 20 * floor]
        if bad and (best is None or bad[0] < best[0]):
            raise NumericalError(f"the forces of the joints could not be resolved near t = {bad[0]:.6g} s")
        done = max(roots + touches, default=lo)
        if best is not None or len(roots) + len(touches) <= FIRST_ROOTS or done <= lo:
            return best
        lo = done


#: how many roots of a watched quantity one call of all_roots finds before the event is looked
#: for: none beyond the first cell that holds one (cells are resolved from the left), since the
#: first root is the event unless the quantity starts below it; resumed after it otherwise
FIRST_ROOTS = 0
#: the first window (s) of that search (at most, in motion), each next one 16 times wider:
#: all_roots resolves a cell to 2^-48 of its starting width, so a load's period must not be lost
#: in a window of 1e300 s
FIRST_WINDOW = 64.0


# ----------------------------------------------------------------------------- an ODE step

#: the screen of an ODE step reads each watched quantity at the SCREEN + 1 Chebyshev–Lobatto
#: points of the step (its ends included: the step's own two)
SCREEN = 4
_X = -np.cos(np.pi * np.arange(SCREEN + 1) / SCREEN)


@functools.cache
def _screen_matrices() -> tuple[np.ndarray, np.ndarray]:
    """(values at the Lobatto points -> Chebyshev coefficients, coefficients -> values at 65
    points): made on the first screened step (numpy.polynomial is not imported by a scene that
    has none)."""
    from numpy.polynomial import chebyshev

    return np.linalg.inv(chebyshev.chebvander(_X, SCREEN)), chebyshev.chebvander(np.linspace(-1.0, 1.0, 65), SCREEN)


def screen_times(a: float, b: float) -> list[float]:
    """The step's inner screening times (its Lobatto points but the ends)."""
    return [float(0.5 * (a + b) + 0.5 * (b - a) * x) for x in _X[1:-1]]


def step_screen(values, tol: float) -> str:
    """What a watched quantity, known at the step's Lobatto points (``values``, ends included),
    may do inside the step, from its interpolant p of degree SCREEN widened by the interpolation
    error its last two Chebyshev coefficients show, by the most p changes between two of 65
    points and by the quantity's rounding: "clear" (p stays off 0 by more than that: no root),
    "monotone" (p changes sign once and is monotone: the one root, by Brent on the ends), else
    "search" (:func:`first_crossing`)."""
    to_coefficients, fine = _screen_matrices()
    c = to_coefficients @ np.asarray(values, dtype=float)
    p = fine @ c
    d = np.diff(p)
    err = 2.0 * (abs(float(c[-1])) + abs(float(c[-2]))) + float(np.max(np.abs(d))) + tol
    if not float(np.min(p)) - err <= 0.0 <= float(np.max(p)) + err:
        return "clear"
    if p[0] * p[-1] < 0 and (np.all(d < 0) or np.all(d > 0)):
        return "monotone"
    return "search"
