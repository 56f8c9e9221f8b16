"""One-degree-of-freedom conservative motion by quadrature of the energy integral (notes §34,
(34.20): T + V = E, so ṡ² = K(s) = 2 (E − V(s)) / M(s)).  Topic-agnostic, in plain floats.

* Turning points: K's sign change on each side of s0 (a march outward in growing steps, then
  Brent); a local minimum of K that touches zero to rounding, or a root where K' = 0 (K_prime
  when given, else a central difference and its error), is a double root: an unstable
  equilibrium that the motion approaches in infinite time and never reaches.
* Time: t(s) = ∫ ds/√K piece by piece, each piece with its own variable x ≥ 0, chosen so that
  the integrand is smooth (dyncli/quadrature.gauss_kronrod does the sums):
  at a simple turning point a, s = a + σx² (dt = 2 √((s − a)/K) dx, the inverse square root
  absorbed exactly, with s − a recomputed from the stored s so its rounding cancels);
  towards a double root e, s = e − σ r0 e^(−x) (dt = |e − s|/√K dx → constant: t grows like
  x, the motion never arrives); elsewhere s = anchor + σx.  A motion between two turning points
  is split at their midpoint, two 'turn' pieces; it is periodic, period = 2 ∫_a^b ds/√K.
* s(t): Brent on x within a piece (x ↦ t is smooth and monotonic there); a piece that runs to
  infinity is integrated outward in doubling steps as far as t asks.
* ``error_estimate`` (relative, docs/accuracy.md): the quadratures' own error estimates summed
  over the legs, relative to the motion's time scale (the period, else the time of the legs
  integrated), times 2π (a time error δt moves s by ṡ δt and ṡ by K'/2 δt: ~2π δt/T of their
  scales), plus the uncertainty of the turning points (Brent's tolerance and |K(a)|/|K'(a)|)
  relative to the extent of the motion, at least 100 ε.  Accuracy near a turning point is also
  bounded by the caller's K: its rounding δK moves the root by δK/K'.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import InputError, NumericalError
from dyncli.quadrature import gauss_kronrod

try:                                    # one Brent: dyncli/rootfind.py (issue #26)
    from dyncli.rootfind import brent
except ImportError:                     # pragma: no cover - until issue #26 lands
    from dyncli.topics.top.rootfind import brent

_EPS = float(np.finfo(float).eps)
_INF = math.inf
_MODEL = 1e-8          # below this fraction of a piece, K is replaced by its local model at the root
_GROW = 1.2            # the turning-point march: step growth
_STEPS = 400           # ... and its length (1.2^400 ≈ 1e31 times the first step)


def _vectorised(K, s0):
    """K on numpy arrays: K itself if it maps an array elementwise, else element by element."""
    try:
        y = np.asarray(K(np.array([s0, s0], dtype=float)), dtype=float)
        if y.shape == (2,):
            return lambda s: np.asarray(K(s), dtype=float).reshape(np.shape(s))
    except Exception:           # a K written with math functions: one float at a time
        pass
    return lambda s: np.array([float(K(float(v))) for v in np.ravel(s)], dtype=float).reshape(np.shape(s))


class _Piece:
    """A stretch of the coordinate with its own variable x ≥ 0 (x = 0 at ``anchor``):
    'turn' s = anchor + σx², 'line' s = anchor + σx, 'double' s = e − σ r0 e^(−x) (anchor = s(0),
    e = anchor + σ r0 never reached).  ``c``: K ≈ c (s − a) at a turn, K ≈ c (s − e)² at a double.
    τ(x) = ∫_0^x dt, tabulated at growing x (xs, ts) and integrated between table points."""

    def __init__(self, em, kind, anchor, sig, X, c=0.0, e=None):
        self.em, self.kind, self.anchor, self.sig, self.X, self.c = em, kind, anchor, sig, X, c
        self.e, self.r0 = e, (abs(e - anchor) if e is not None else 0.0)
        self.xs, self.ts, self.errs = [0.0], [0.0], [0.0]
        if kind == "double":            # beyond x_lin, K = c r²: t grows linearly in x
            self.X, self.r_sw, self.rtol = _INF, _MODEL * self.r0, em.rtol
        self.step = {"turn": math.sqrt(em.L), "line": em.L, "double": 1.0}[kind]
        self.ext = em.L if math.isinf(self.X) else (self.X ** 2 if kind == "turn" else self.X)
        self.rtol, self.k_a = em.rtol, 0.0
        if kind == "double":
            # K's rounding δK = 4 ε K(anchor) is δK/(c r²) of K at r = |s − e|: the model K = c r²
            # (its error ~ r/r0) takes over where the two are equal, and no tolerance below that noise
            dK = 4 * _EPS * em.K1(anchor)
            self.r_sw = max(self.r_sw, (dK * self.r0 / c) ** (1 / 3))
            self.rtol = max(em.rtol, min(dK / (c * self.r_sw ** 2), 1e-3))
            self.x_lin = math.log(self.r0 / self.r_sw)
            r10 = min(10 * self.r_sw, 0.5 * self.r0)   # the model's error, measured where it is ~10× larger
            self.model_err = abs(em.K1(e - sig * r10) / (c * r10 * r10) - 1) * self.r_sw / r10
        if kind == "turn":              # K − K(a): its root is a itself (K(a) is rounding: an ε change of E)
            self.k_a = em.K1(anchor)
            k2 = max(em._curv(anchor), 1e-300)
            self.ext = min(self.ext, c / k2)    # the linear model K = c (s − a) holds while |K''| u ≪ c
            # s − a is known to ε|a|: dt/dx is noisy at 8 ε |a| K''/c near a (near a separatrix, where
            # c → 0); no tolerance below that can be met
            self.rtol = max(em.rtol, 8 * _EPS * abs(anchor) * k2 / max(c, 1e-300))
        if math.isfinite(self.X):
            self._grow(self.X)

    def noise(self):
        """The time error from K's rounding δK = 4 ε max K near a turning point: ∫ δK/(2 K^1.5) ds
        from the quadrature's nodes nearest to it, at x ≈ x1/250 (x1: the first panel's end)."""
        if self.kind == "double":       # the model's error beyond x_lin, ~ r_sw/r0 of dt/dx there
            return (self.model_err + self.rtol) / math.sqrt(self.c)
        if self.kind != "turn" or len(self.xs) < 2:
            return 0.0
        dK = 4 * _EPS * max(self.em.K1(self.em.s0), self.c * self.xs[1] ** 2)
        return 250 * dK / (self.c ** 1.5 * self.xs[1])

    def s(self, x):
        if self.kind == "turn":
            return self.anchor + self.sig * x * x
        if self.kind == "line":
            return self.anchor + self.sig * x
        return self.e - self.sig * self.r0 * np.exp(-x)

    def x_of(self, s):
        if math.isinf(s) or (self.kind == "double" and s == self.e):
            return _INF
        u = abs(s - self.anchor)
        if self.kind == "turn":
            return math.sqrt(u)
        if self.kind == "line":
            return u
        return math.log(self.r0 / abs(self.e - s))

    def _g(self, x):
        """dt/dx on an array of x (smooth: the singular factor is taken out exactly)."""
        s = self.s(x)
        k = self.em.Kv(s) - self.k_a
        if np.any(np.isnan(k)):        # +inf (an escape to infinity) gives dt/dx = 0
            raise InputError(f"K(s) is not finite at s = {float(np.ravel(s)[np.isnan(np.ravel(k))][0]):.9g}")
        if self.kind == "line":
            bad = ~(k > 0)
            g = 1.0 / np.sqrt(np.where(bad, 1.0, k))
        elif self.kind == "turn":
            u = np.abs(s - self.anchor)
            bad = ~(k > 0) & (u > _MODEL * self.ext)
            g = np.where(k > 0, 2.0 * np.sqrt(u / np.where(k > 0, k, 1.0)), 2.0 / math.sqrt(self.c))
            g = np.where(u <= _MODEL * self.ext, 2.0 / math.sqrt(self.c), g)
        else:
            r = np.abs(self.e - s)
            bad = ~(k > 0) & (r > self.r_sw)
            g = np.where(r > self.r_sw, r / np.sqrt(np.where(k > 0, k, 1.0)), 1.0 / math.sqrt(self.c))
        if np.any(bad):
            s_bad = float(np.ravel(s)[np.ravel(bad)][0])
            raise NumericalError(f"K(s) ≤ 0 at s = {s_bad:.9g} inside the motion: a turning point there was "
                                 "missed by the search (K dips below zero between its samples)")
        return g

    def _quad(self, x0, x1):
        I, err, ok = gauss_kronrod(self._g, x0, x1, self.rtol, 0.0, max_steps=self.em.max_steps,
                                   what="the time integrand 1/√K")
        if not ok:
            self.em.warnings.append(f"the time integral on x ∈ [{x0:.6g}, {x1:.6g}] did not converge "
                                    "(rounding of the integrand)")
        self.em.err_max = max(self.em.err_max, err)
        return I, err

    def _grow(self, x_to):
        """Extend the table up to x_to (doubling steps; a finite piece in one step)."""
        while self.xs[-1] < x_to:
            x0 = self.xs[-1]
            x1 = min(x_to, x0 + max(x0, self.step)) if math.isinf(self.X) else x_to
            if self.kind == "double":
                x1 = min(x1, self.x_lin)
            I, err = self._quad(x0, x1)
            self.xs.append(x1)
            self.ts.append(self.ts[-1] + I)
            self.errs.append(self.errs[-1] + err)
            if self.kind == "double" and x1 >= self.x_lin:
                return

    def tau(self, x):
        """The time from x = 0 to x (inf at x = inf)."""
        if math.isinf(x):
            return _INF
        if self.kind == "double" and x >= self.x_lin:
            self._grow(self.x_lin)
            return self.ts[-1] + (x - self.x_lin) / math.sqrt(self.c)
        self._grow(x)
        k = int(np.searchsorted(self.xs, x, side="right")) - 1
        if self.xs[k] == x:
            return self.ts[k]
        return self.ts[k] + self._quad(self.xs[k], x)[0]

    def x_at(self, target):
        """x where τ(x) = target (≥ 0)."""
        if self.kind == "double" and target >= self.tau(self.x_lin):
            return self.x_lin + (target - self.ts[-1]) * math.sqrt(self.c)
        if math.isfinite(self.X):
            target = min(target, self.ts[-1])
        while self.ts[-1] < target:
            if not (self.xs[-1] < 1e300 and len(self.xs) < 2100):
                raise NumericalError(f"s runs to infinity at t ≈ {self.ts[-1]:.9g} (K grows too fast): no state "
                                     f"at t = {target:.9g}")
            self._grow(self.xs[-1] + max(self.xs[-1], self.step))
        k = max(int(np.searchsorted(self.ts, target, side="left")) - 1, 0)
        x0, x1, t0 = self.xs[k], self.xs[k + 1], self.ts[k]
        f = lambda x: t0 + self._quad(x0, x)[0] - target if x > x0 else t0 - target  # noqa: E731
        return brent(f, x0, x1, 4 * _EPS * abs(x1), 4 * _EPS, 200)

    def speed(self, x):
        """|ṡ| at x: √K, or the local model √(c|s − a|), c|s − e|, very near a root (K's rounding)."""
        s = float(self.s(x))
        if self.kind == "turn" and abs(s - self.anchor) <= _MODEL * self.ext:
            return math.sqrt(self.c * abs(s - self.anchor))
        if self.kind == "double" and abs(self.e - s) <= self.r_sw:
            return math.sqrt(self.c) * self.r0 * math.exp(-x)
        return math.sqrt(max(self.em.K1(s) - self.k_a, 0.0))


class EnergyMotion:
    """s(t), ṡ(t) of a motion with ṡ² = K(s) (notes (34.20)), from s0 with velocity sdot0.

    ``K`` maps s (a float, or a numpy array elementwise) to ṡ²; K(s0) = sdot0² (checked to 1e-8).
    ``K_prime``: dK/ds, optional (sharpens the classification of a double root and locates it).
    ``lo``, ``hi``: the ends of the coordinate's range (walls: states past them are refused).
    Attributes: ``turning_points`` (the roots of K bounding the motion, double roots included),
    ``period`` (between two simple turning points, else None), ``kind`` ('rest', 'oscillation',
    'asymptotic': approaches the double root ``asymptote`` in infinite time, 'wall': reaches
    ``lo``/``hi`` at ``t_wall``, 'runaway': s unbounded), ``error_estimate``, ``warnings``.

    >>> m = EnergyMotion(lambda s: 1.0 - s * s, 1.0, 0.0)          # s = cos t
    >>> round(m.period, 12), [round(v, 12) for v in m.state(1.0)]
    (6.28318530718, [0.540302305868, -0.841470984808])
    """

    def __init__(self, K, s0: float, sdot0: float, *, K_prime=None, lo=None, hi=None, rtol=1e-10,
                 max_steps=None):
        self.s0, self.sdot0 = float(s0), float(sdot0)
        self.lo, self.hi = (None if lo is None else float(lo)), (None if hi is None else float(hi))
        if not (math.isfinite(self.s0) and math.isfinite(self.sdot0)):
            raise InputError(f"s0 = {s0!r} and sdot0 = {sdot0!r} must be finite numbers")
        if (self.lo is not None and self.s0 < self.lo) or (self.hi is not None and self.s0 > self.hi):
            raise InputError(f"s0 = {self.s0:.9g} lies outside the coordinate's range [{lo}, {hi}]")
        if not (2.2e-14 <= float(rtol) < 1):
            raise InputError(f"rtol = {rtol!r} must lie in [2.2e-14, 1) (docs/accuracy.md)")
        self.rtol, self.max_steps = float(rtol), max_steps
        self._K, self.Kp = K, K_prime
        self.Kv = _vectorised(K, self.s0)
        self.warnings: list[str] = []
        self.err_max = self.dpos = self._t_max = 0.0
        k0 = self.K1(self.s0)
        if k0 < 0:
            raise InputError(f"K(s0) = {k0:.6g} < 0 at s0 = {self.s0:.9g}: ṡ² = K cannot be negative "
                             "(the energy is below the potential there)")
        if abs(k0 - self.sdot0 ** 2) > 1e-8 * max(k0, self.sdot0 ** 2):
            raise InputError(f"K(s0) = {k0:.12g} differs from sdot0² = {self.sdot0 ** 2:.12g}: K must be ṡ²")
        self.kref, self.L = k0, max(abs(self.s0), 1.0)   # kref: K's scale (its rounding: 4 ε kref)
        if self.lo is not None and self.hi is not None:
            self.L = min(self.L, self.hi - self.lo)
        self._plan()

    # -- K and its derivatives ------------------------------------------------
    def K1(self, s: float) -> float:
        v = float(self._K(s))
        if not math.isfinite(v):
            raise InputError(f"K(s) is not finite at s = {s:.9g} (the energy integral is undefined there)")
        return v

    def _slope(self, s):
        """K'(s) and the error of that value (K_prime's rounding, or a central difference's)."""
        if self.Kp is not None:
            v = float(self.Kp(s))
            if not math.isfinite(v):
                raise InputError(f"K_prime(s) is not finite at s = {s:.9g}")
            return v, 64 * _EPS * (abs(v) + abs(s) * self._curv(s))
        h = _EPS ** (1 / 3) * max(abs(s), self.L)
        kp, km, kp2, km2 = (self.K1(s + h), self.K1(s - h), self.K1(s + 2 * h), self.K1(s - 2 * h))
        d1, d2 = (kp - km) / (2 * h), (kp2 - km2) / (4 * h)
        return d1, abs(d1 - d2) + 4 * _EPS * max(abs(kp), abs(km), abs(kp2), abs(km2), self.kref) / h

    def _curv(self, s):
        """|K''(s)| by a central difference (of K_prime when given)."""
        h = _EPS ** 0.25 * max(abs(s), self.L)
        if self.Kp is not None:
            return abs(float(self.Kp(s + h)) - float(self.Kp(s - h))) / (2 * h)
        return abs(self.K1(s + h) - 2 * self.K1(s) + self.K1(s - h)) / (h * h)

    def _is_double(self, c):
        v, err = self._slope(c)
        return abs(v) <= err + 64 * _EPS * abs(c) * self._curv(c)

    # -- the ends of the motion ---------------------------------------------------
    def _root(self, a, b):
        x = brent(self.K1, a, b, 4 * _EPS * max(abs(a), abs(b), 1e-300), 4 * _EPS, 200)
        kx = self.K1(x)
        if kx != 0:
            self.dpos = max(self.dpos, abs(kx) / max(abs(self._slope(x)[0]), 1e-300) + 4 * _EPS * abs(x))
        return x

    def _classify(self, c):
        if self._is_double(c):
            return ("double", c)
        return ("turn", c)

    def _march(self, s0, d, at_rest):
        """The end of the motion from s0 in the direction d: ('turn', a) a simple root of K,
        ('double', e), ('wall', w) or ('open', None).  Growing steps; a sign change of K is
        refined by Brent, a local minimum of K by :meth:`_dip`."""
        wall = self.hi if d > 0 else self.lo
        h = 1e-2 * self.L
        sp, kp = s0, self.K1(s0)
        if at_rest:                     # K(s0) = 0: the first step must land where K > 0
            for _ in range(200):
                s = s0 + d * h if wall is None else (min(s0 + h, wall) if d > 0 else max(s0 - h, wall))
                if s != s0 and self.K1(s) > 0:
                    break
                h /= 2
            else:
                raise NumericalError(f"released from rest at s0 = {s0:.9g}, the body cannot move: "
                                     "K ≤ 0 on the side where K' says it should grow")
            sp, kp = s, self.K1(s)
            if wall is not None and s == wall:
                return ("wall", wall)
        spp = kpp = None
        kmax = kp
        for _ in range(_STEPS):
            s = sp + d * h
            at_wall = wall is not None and d * (s - wall) >= 0
            s = wall if at_wall else s
            if float(self._K(s)) == _INF:   # K overflows far out: no turning point ahead
                return ("open", None)
            k = self.K1(s)
            if k <= 0:
                return self._classify(s if k == 0 else self._root(sp, s))
            if spp is not None and kp < kpp and kp <= k:
                found = self._dip(spp, s, kmax)
                if found:
                    return found
            if at_wall:
                return ("wall", wall)
            kmax = self.kref = max(kmax, k, self.kref)
            spp, kpp, sp, kp = sp, kp, s, k
            h *= _GROW
        return ("open", None)

    def _dip(self, a, b, kmax):
        """A local minimum of K inside (a, b): a root pair (returns the first root) or a double
        root (K touches zero to rounding), else None."""
        x = None
        if self.Kp is not None and float(self.Kp(a)) * float(self.Kp(b)) < 0:
            x = brent(lambda s: float(self.Kp(s)), a, b, 4 * _EPS * max(abs(a), abs(b)), 4 * _EPS, 200)
        else:                           # golden section
            g, u, v = (math.sqrt(5) - 1) / 2, a, b
            for _ in range(200):
                c1, c2 = v - g * (v - u), u + g * (v - u)
                if self.K1(c1) < self.K1(c2):
                    v = c2
                else:
                    u = c1
                if abs(v - u) <= 4 * _EPS * max(abs(u), abs(v)):
                    break
            x = 0.5 * (u + v)
        kx = self.K1(x)
        if kx < 0:                      # a pair of simple roots (or double ones): the first one
            return self._classify(self._root(a, x))
        if kx <= 64 * _EPS * kmax:      # K touches zero to rounding: a double root
            if self.Kp is None:         # the golden section's resolution of a flat minimum
                self.dpos = max(self.dpos, abs(v - u))
            return ("double", x)
        return None

    # -- the plan: pieces, legs, period ---------------------------------------------
    def _piece(self, kind, end, m, sig):
        """The piece from m towards ``end`` (direction sig) for an end of that kind."""
        if kind == "turn":
            return _Piece(self, "turn", end, -sig, math.sqrt(abs(m - end)), c=abs(self._slope(end)[0]))
        if kind == "double":
            return _Piece(self, "double", m, sig, _INF, c=0.5 * self._curv(end), e=end)
        return _Piece(self, "line", m, sig, abs(end - m) if kind == "wall" else _INF)

    def _track(self, behind, ahead):
        """The pieces from the end behind s0 to the end ahead (in the direction d)."""
        (kb, sb), (ka, sa), d = behind, ahead, self.d
        if kb == "turn" and ka == "open":
            return [_Piece(self, "turn", sb, d, _INF, c=abs(self._slope(sb)[0]))]
        if ka == "turn" and kb == "open":
            return [_Piece(self, "turn", sa, -d, _INF, c=abs(self._slope(sa)[0]))]
        m = 0.5 * (sb + sa) if "open" not in (kb, ka) else self.s0
        return [self._piece(kb, sb, m, -d), self._piece(ka, sa, m, d)]

    @staticmethod
    def _span(p):
        a = float(p.s(0.0))
        b = p.e if p.kind == "double" else (float(p.s(p.X)) if math.isfinite(p.X) else p.sig * _INF)
        return min(a, b), max(a, b)

    def _path(self, track, s_from, s_to):
        """Segments (piece, x_from, x_to) from s_from to s_to along the track."""
        pieces = track if (s_to - s_from) * self.d > 0 else track[::-1]
        lo, hi = min(s_from, s_to), max(s_from, s_to)
        out = []
        for p in pieces:
            p_lo, p_hi = self._span(p)
            if min(hi, p_hi) <= max(lo, p_lo):
                continue
            x0, x1 = (p.x_of(min(max(v, p_lo), p_hi)) for v in (s_from, s_to))
            if x0 != x1:
                out.append((p, x0, x1))
        return out

    def _plan(self):
        """The legs of the motion after t = 0 and its periodic cycle (None if not periodic)."""
        s0, v0 = self.s0, self.sdot0
        self.turning_points, self.period, self.asymptote, self.t_wall = [], None, None, None
        self._legs, self._durs, self._cycle, self._track_ = [], [], None, []
        rest = v0 == 0.0
        if rest and self._is_double(s0):
            self.kind = "rest"
            return
        self.d = d = math.copysign(1.0, v0 if not rest else self._slope(s0)[0])
        ahead = self._march(s0, d, rest)
        behind = ("turn", s0) if rest else (self._march(s0, -d, False) if ahead[0] == "turn" else ("open", None))
        track = self._track_ = self._track(behind, ahead)
        end = {True: ahead[1] if ahead[0] != "open" else d * _INF,
               False: behind[1] if behind[0] != "open" else -d * _INF}
        legs = self._path(track, s0, end[True])
        final = ahead
        if ahead[0] == "turn":
            back = self._path(track, ahead[1], end[False])
            if behind[0] == "turn":
                self._cycle = back + self._path(track, behind[1], ahead[1])
            else:
                legs, final = legs + back, behind
        self._legs = legs
        self._durs = [self._duration(seg) for seg in legs]
        reached = [ahead] + ([behind] if rest or ahead[0] == "turn" else [])
        self.turning_points = sorted(e[1] for e in reached if e[0] in ("turn", "double"))
        if self._cycle is not None:
            self._cdurs = [self._duration(seg) for seg in self._cycle]
            self.period = sum(self._cdurs)
            self.kind = "oscillation"
        else:
            self.kind = {"double": "asymptotic", "wall": "wall", "open": "runaway"}[final[0]]
            if final[0] == "double":
                self.asymptote = final[1]
            if final[0] == "wall":
                self.t_wall, self._wall = sum(self._durs), final[1]

    @staticmethod
    def _duration(seg):
        p, x0, x1 = seg
        if math.isinf(x0) or math.isinf(x1):
            return _INF
        return abs(p.tau(x1) - p.tau(x0))

    # -- the motion ---------------------------------------------------------------
    def state(self, t: float) -> tuple[float, float]:
        """(s, ṡ) at the time t ≥ 0."""
        t = float(t)
        if not (t >= 0 and math.isfinite(t)):
            raise InputError(f"t = {t!r}: the state is defined for finite t ≥ 0")
        if self.kind == "rest":
            return self.s0, 0.0
        self._t_max, tt = max(self._t_max, t), t
        for seg, dur in zip(self._legs, self._durs):
            if tt <= dur:
                return self._at(seg, tt)
            tt -= dur
        if self._cycle is None:
            raise NumericalError(f"the motion reaches the end of its range (s = {self._wall:.9g}) at t = {self.t_wall:.9g}: "
                                 f"no state at t = {t:.9g} past it")
        tt = math.fmod(tt, self.period)
        for seg, dur in zip(self._cycle, self._cdurs):
            if tt <= dur:
                return self._at(seg, tt)
            tt -= dur
        return self._at(self._cycle[-1], self._cdurs[-1])

    def _at(self, seg, tt):
        p, x0, x1 = seg
        sgn = 1.0 if x1 > x0 else -1.0
        x = p.x_at(max(p.tau(x0) + sgn * tt, 0.0))
        return float(p.s(x)), p.speed(x) * p.sig * sgn

    def breaks(self, t_end: float) -> list[float]:
        """The times up to t_end at which a leg ends: the turning points, the junctions of the
        pieces (midway between two turning points) and the arrival at a wall."""
        out, t = [], 0.0
        for dur in self._durs:
            t += dur
            if not t <= t_end:
                return out
            out.append(t)
        if self._cycle is None:
            return out
        if (t_end - t) / self.period * len(self._cycle) > 1e6:
            raise InputError(f"t_end = {t_end:.6g} spans more than 1e6 legs of the period {self.period:.6g}")
        n = 0
        while True:
            base = t + n * self.period
            for c in np.cumsum(self._cdurs):
                if not base + c <= t_end:
                    return out
                out.append(float(base + c))
            n += 1

    @property
    def error_estimate(self) -> float:
        """Relative: 2π × the quadratures' summed error estimates over the time scale, plus the
        turning points' uncertainty over the motion's extent, at least 100 ε; it covers every
        state evaluated so far (a piece running outward adds its steps as they are made)."""
        if self.kind == "rest":
            return 0.0
        pieces = self._track_
        err = sum(p.errs[-1] + p.noise() for p in pieces) + self.err_max
        T = self.period or (sum(d for d in self._durs if math.isfinite(d))
                            + max((p.ts[-1] for p in pieces if math.isinf(p.X)), default=0.0))
        ext = (max(self.turning_points) - min(self.turning_points)) if len(self.turning_points) == 2 else self.L
        rel = 2 * math.pi * err / T * max(1.0, self._t_max / T) if T > 0 else 0.0   # phase errors add up
        return max(rel + self.dpos / ext, 100 * _EPS)
