"""One-degree-of-freedom conservative motion by quadrature of the energy integral (notes §34,
(34.20): T + V = E, so ṡ² = K(s) = 2 (E − V(s)) / M(s)).  Topic-agnostic, in plain floats.

* Turning points: K's sign change on each side of s0 (a march outward in growing steps, then
  Brent); a local minimum of K touching zero to rounding, or a root where K' = 0 (K_prime, else
  a central difference), is a double root: an unstable equilibrium, approached in infinite time.
* t = ∫ ds/√K piece by piece (dyncli/quadrature.gauss_kronrod), each in a variable x ≥ 0 that
  makes the integrand smooth: s = a + σx² from a simple turning point a (dt = 2 √((s − a)/K) dx:
  the inverse square root absorbed exactly), s = e − σ r0 e^(−x) towards a double root e (dt →
  constant: e is never reached), else s = anchor + σx.  An oscillation is split at the midpoint
  of its turning points; period = 2 ∫_a^b ds/√K.  Each quadrature keeps its panels' interpolants
  (quadrature.Antiderivative): τ(x) between the table's points and s(t) (Newton on τ, bracketed)
  cost no further evaluation of K; a piece running to infinity is integrated outward in
  doubling steps as far as t asks.
* ``error_estimate`` (relative, docs/accuracy.md): 2π × (the quadratures' error estimates + the
  time error of K's rounding and of the local models near the roots) / the time scale (period,
  else time integrated) × the periods evaluated, + the roots' uncertainty / the extent, ≥ 100 ε.
  K's rounding is measured: a K that cancels near a turning point close to a separatrix
  (cos θ − cos θ0, θ0 → π) is reported as less accurate for it (write it as a product).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import InputError, NumericalError
from dyncli.quadrature import gauss_kronrod
from dyncli.rootfind import brent       # one Brent: dyncli/rootfind.py (issue #26)
from dyncli.runner import floor_rtol    # the one rtol floor (100 ε)

_EPS, _INF = float(np.finfo(float).eps), math.inf
_MODEL = 1e-8          # the local models near a root take over at least below this fraction
_GROW, _STEPS = 1.2, 400   # the turning-point march: step growth and length (1.2^400 ≈ 1e31)


def _vectorised(K, s0):
    """K on numpy arrays: K itself if it maps an array elementwise, else element by element."""
    try:                        # (a K written with math functions: one float at a time)
        if np.asarray(K(np.array([s0, s0], dtype=float)), dtype=float).shape == (2,):
            return lambda s: np.asarray(K(s), dtype=float).reshape(np.shape(s))
    except Exception:
        pass
    return lambda s: np.array([float(K(float(v))) for v in np.ravel(s)], dtype=float).reshape(np.shape(s))


class _Piece:
    """A stretch of the coordinate with its own variable x ≥ 0 (x = 0 at ``anchor``): 'turn'
    s = anchor + σx², 'line' s = anchor + σx, 'double' s = e − σ r0 e^(−x) (e = anchor + σ r0).
    ``c``: K ≈ c |s − a| at a turn, c (s − e)² at a double.  τ(x) = ∫_0^x dt is tabulated at
    growing x (xs, ts, errs: the summed error estimates) and integrated between table points."""

    def __init__(self, em, kind, anchor, sig, X, c=0.0, e=None):
        self.em, self.kind, self.anchor, self.sig, self.X, self.c, self.e = em, kind, anchor, sig, X, c, e
        self.r0, self.xs, self.ts, self.errs = 0.0 if e is None else abs(e - anchor), [0.0], [0.0], [0.0]
        self.dense: list = []           # each table step's antiderivative (quadrature.Antiderivative)
        self.step = {"turn": math.sqrt(em.L), "line": em.L, "double": 1.0}[kind]
        self.rtol, self.k_a, self.u_sw = em.rtol, 0.0, 0.0
        if kind == "double":
            # K's rounding δK is δK/(c r²) of K = c r²: the model takes over where that meets r/r0
            dK = 4 * _EPS * em.K1(anchor)
            self.r_sw = max(_MODEL * self.r0, (dK * self.r0 / c) ** (1 / 3))
            self.rtol = max(em.rtol, min(dK / (c * self.r_sw ** 2), 1e-3))
            self.x_lin = math.log(self.r0 / self.r_sw)
            r10 = min(10 * self.r_sw, 0.5 * self.r0)   # the model's error, measured where ~10× larger
            self.model_err = abs(em.K1(e - sig * r10) / (c * r10 * r10) - 1) * self.r_sw / r10
        if kind == "turn":
            self._turn_model(em.L if math.isinf(X) else X * X)
        if math.isfinite(X):
            self._grow(X)

    def _turn_model(self, ext):
        """Near a turning point a, K − K(a) (its root is a itself: K(a) is rounding, an ε change of E)
        is replaced below u_sw = |s − a| by its model c u + K''(a) u²/2, where K's measured rounding
        δK (the scatter of 8 nearby values about a parabola) would reach the model's error (u/u_c)²,
        u_c = c/|K''|; dt/dx keeps a noise δK/(c u_sw) that no tolerance can go below."""
        em, a, sg, c = self.em, self.anchor, self.sig, max(self.c, 1e-300)
        self.k_a = em.K1(a)
        h = _EPS ** 0.25 * max(abs(a), em.L)
        try:
            self.k2 = (em.K1(a + sg * h) + em.K1(a - sg * h) - 2 * self.k_a) / (h * h)
        except InputError:              # K undefined beyond a (a wall): one-sided, second order
            k1, k2, k3 = (em.K1(a + j * sg * h) for j in (1, 2, 3))
            self.k2 = (2 * self.k_a - 5 * k1 + 4 * k2 - k3) / (h * h)
        u_c = min(c / max(abs(self.k2), 1e-300), ext)
        z = np.linspace(-1.0, 1.0, 8)
        ks = em.Kv(a + sg * 1e-3 * u_c * (1.01 + 0.01 * z)) - self.k_a
        resid = ks - np.polyval(np.polyfit(z, ks, 2), z)
        # (K flat to rounding there: its quantum exceeds the change over the 8 values)
        self.dK = max(4 * float(np.max(np.abs(resid))) + 4 * _EPS * float(np.max(np.abs(ks))),
                      4 * c * 2e-5 * u_c if np.ptp(ks) == 0 else 0.0)
        self.u_sw = max(min(max((self.dK * u_c * u_c / c) ** (1 / 3), _MODEL * u_c), 1e-2 * u_c), 1e-300)
        self.rtol = min(max(self.rtol, 0.2 * self.dK / (c * self.u_sw)), 1e-3)

    def noise(self):
        """The time error the quadratures cannot see: K's rounding near a root, the models' error."""
        if self.kind == "double":
            return (self.model_err + self.rtol) / math.sqrt(self.c)
        return self.dK / (self.c ** 1.5 * math.sqrt(self.u_sw)) if self.kind == "turn" else 0.0

    def s(self, x):
        if self.kind == "double":
            return self.e - self.sig * self.r0 * np.exp(-x)
        return self.anchor + self.sig * (x * x if self.kind == "turn" else x)

    def x_of(self, s):
        if math.isinf(s) or (self.kind == "double" and s == self.e):
            return _INF
        if self.kind == "double":
            return math.log(self.r0 / abs(self.e - s))
        return math.sqrt(abs(s - self.anchor)) if self.kind == "turn" else abs(s - self.anchor)

    def span(self):
        a = float(self.s(0.0))
        b = self.e if self.kind == "double" else (float(self.s(self.X)) if math.isfinite(self.X) else self.sig * _INF)
        return min(a, b), max(a, b)

    def _g(self, x):
        """dt/dx on an array of x (smooth: the singular factor is taken out exactly)."""
        s = self.s(x)
        k = self.em.Kv(s) - self.k_a
        if np.any(np.isnan(k)):        # +inf (an escape to infinity) gives dt/dx = 0
            raise InputError(f"K(s) is not finite at s = {float(np.ravel(s)[np.isnan(np.ravel(k))][0]):.9g}")
        if self.kind == "line":
            bad, g = ~(k > 0), 1.0 / np.sqrt(np.where(k > 0, k, 1.0))
        elif self.kind == "turn":
            u = np.abs(s - self.anchor)
            k = np.where(model := u <= self.u_sw, self.c * u + 0.5 * self.k2 * u * u, k)
            bad = ~(k > 0) & ~model
            g = np.where(k > 0, 2.0 * np.sqrt(u / np.where(k > 0, k, 1.0)), 2.0 / math.sqrt(self.c))
        else:
            bad = ~(k > 0) & ((r := np.abs(self.e - s)) > self.r_sw)
            g = np.where(r > self.r_sw, r / np.sqrt(np.where(k > 0, k, 1.0)), 1.0 / math.sqrt(self.c))
        if np.any(bad):
            raise NumericalError(f"K(s) ≤ 0 at s = {float(np.ravel(s)[np.ravel(bad)][0]):.9g} inside the "
                                 "motion: a turning point missed by the search (K dips below zero between samples)")
        return g

    def _quad(self, x0, x1):
        """∫_{x0}^{x1} dt/dx, its error, and its antiderivative (the quadrature's dense output:
        a time between the table's points, and its inverse, with no further evaluation of K)."""
        I, err, ok, F = gauss_kronrod(self._g, x0, x1, self.rtol, 0.0, max_steps=self.em.max_steps,
                                      what="the time integrand 1/√K", dense=True)
        self.em.warnings += [] if ok else [f"the time integral on x ∈ [{x0:.6g}, {x1:.6g}] did not converge"]
        self.em.err_max = max(self.em.err_max, err)
        return I, err, F

    def _grow(self, x_to):
        """Extend the table up to x_to (doubling steps; a finite piece in one step)."""
        if self.kind == "double":
            x_to = min(x_to, self.x_lin)
        while self.xs[-1] < x_to:
            x0 = self.xs[-1]
            x1 = min(x_to, x0 + max(x0, self.step)) if math.isinf(self.X) else x_to
            I, err, F = self._quad(x0, x1)
            self.xs, self.ts, self.errs = self.xs + [x1], self.ts + [self.ts[-1] + I], self.errs + [self.errs[-1] + err]
            self.dense.append(F)

    def tau(self, x):
        """The time from x = 0 to x (inf at x = inf)."""
        if math.isinf(x):
            return _INF
        self._grow(x)
        if self.kind == "double" and x >= self.x_lin:
            return self.ts[-1] + (x - self.x_lin) / math.sqrt(self.c)
        k = int(np.searchsorted(self.xs, x, side="right")) - 1
        return self.ts[k] if self.xs[k] == x else self.ts[k] + self.dense[k](x)

    def x_at(self, target):
        """x where τ(x) = target (≥ 0)."""
        if self.kind == "double" and target >= self.tau(self.x_lin):
            return self.x_lin + (target - self.ts[-1]) * math.sqrt(self.c)
        if math.isfinite(self.X):
            target = min(target, self.ts[-1])
        while self.ts[-1] < target or len(self.xs) < 2:
            if not (self.xs[-1] < 1e300 and len(self.xs) < 2100):
                raise NumericalError(f"s runs to infinity at t ≈ {self.ts[-1]:.9g} (K grows too fast): no state "
                                     f"at t = {target:.9g}")
            self._grow(self.xs[-1] + max(self.xs[-1], self.step))
        k = max(int(np.searchsorted(self.ts, target, side="left")) - 1, 0)
        return self.dense[k].inverse(target - self.ts[k])

    def speed(self, x):
        """|ṡ| at x: √K, or the local model very near a root (where K is its rounding); near a
        turning point, where √K's rounding (δK/2K) exceeds the time integrand's interpolant's
        error (the quadrature's rtol), 2x / (dt/dx) from that interpolant: ṡ = (ds/dx)/(dt/dx)
        carries no cancellation, so the rate crosses zero at the turning point's time."""
        s = float(self.s(x))
        u = x * x if self.kind == "turn" else abs(s - self.anchor)
        if self.kind == "turn" and u <= self.u_sw:
            return math.sqrt(max(self.c * u + 0.5 * self.k2 * u * u, 0.0))
        if self.kind == "turn" and self.dense and x <= self.xs[-1]:
            k = self.em.K1(s) - self.k_a
            if k * self.rtol < self.dK:
                j = min(int(np.searchsorted(self.xs, x, side="right")) - 1, len(self.dense) - 1)
                return 2.0 * x / self.dense[j].f(x)
            return math.sqrt(max(k, 0.0))
        if self.kind == "double" and abs(self.e - s) <= self.r_sw:
            return math.sqrt(self.c) * self.r0 * math.exp(-x)
        return math.sqrt(max(self.em.K1(s) - self.k_a, 0.0))


class EnergyMotion:
    """s(t), ṡ(t) of a motion with ṡ² = K(s) (notes (34.20)), from s0 with velocity sdot0.

    ``K`` maps s (a float, or a numpy array elementwise) to ṡ²; K(s0) = sdot0² (checked to 1e-8);
    ``K_prime``: dK/ds, optional (classifies and locates a double root the better); ``lo``, ``hi``:
    the ends of the coordinate's range (walls: states past them are refused).
    ``turning_points``: the roots of K bounding the motion (double ones too); ``period`` (between
    two simple turning points, else None); ``kind``: 'rest', 'oscillation', 'asymptotic' (towards
    the double root ``asymptote``, never reached), 'wall' (reaches it at ``t_wall``), 'runaway'.

    >>> m = EnergyMotion(lambda s: 1.0 - s * s, 1.0, 0.0)          # s = cos t
    >>> round(m.period, 12), [round(v, 12) for v in m.state(1.0)]
    (6.28318530718, [0.540302305868, -0.841470984808])
    """

    def __init__(self, K, s0: float, sdot0: float, *, K_prime=None, lo=None, hi=None, rtol=1e-10,
                 max_steps=None):
        self.s0, self.sdot0, self.lo, self.hi = float(s0), float(sdot0), lo, hi
        if not (math.isfinite(self.s0) and math.isfinite(self.sdot0)):
            raise InputError(f"s0 = {s0!r} and sdot0 = {sdot0!r} must be finite numbers")
        if not (-_INF if lo is None else lo) <= self.s0 <= (_INF if hi is None else hi):
            raise InputError(f"s0 = {self.s0:.9g} lies outside the coordinate's range [{lo}, {hi}]")
        if not (0 < float(rtol) < 1):
            raise InputError(f"rtol = {rtol!r} must lie in (0, 1)")
        self.rtol, self.max_steps, self._K, self.Kp = floor_rtol(float(rtol)), max_steps, K, K_prime
        self.warnings: list[str]
        self.Kv, self.warnings, self.err_max, self.dpos, self._t_max = _vectorised(K, self.s0), [], 0.0, 0.0, 0.0
        k0 = self.K1(self.s0)
        if k0 < 0:
            raise InputError(f"K(s0) = {k0:.6g} < 0 at s0 = {self.s0:.9g}: ṡ² = K cannot be negative "
                             "(the energy is below the potential there)")
        if abs(k0 - self.sdot0 ** 2) > 1e-8 * max(k0, self.sdot0 ** 2):
            raise InputError(f"K(s0) = {k0:.12g} differs from sdot0² = {self.sdot0 ** 2:.12g}: K must be ṡ²")
        # kref: K's scale (its rounding: 4 ε kref); L: the length scale of the searches
        self.kref, self.L = k0, min(max(abs(self.s0), 1.0), _INF if None in (lo, hi) else hi - lo)
        self._plan()

    def K1(self, s: float) -> float:
        v = float(self._K(s))
        if not math.isfinite(v):
            raise InputError(f"K(s) is not finite at s = {s:.9g} (the energy integral is undefined there)")
        return v

    def _slope(self, s):
        """K'(s) and the error of that value (K_prime's rounding, or a central difference's)."""
        if self.Kp is not None:
            if not math.isfinite(v := float(self.Kp(s))):
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

    def _kind(self, c):
        """A root c of K: 'double' if K'(c) = 0 within its error, else 'turn'."""
        v, err = self._slope(c)
        return ("double" if abs(v) <= err + 64 * _EPS * abs(c) * self._curv(c) else "turn"), c

    def _root(self, a, b):
        x = brent(self.K1, a, b, 4 * _EPS * max(abs(a), abs(b), 1e-300), 4 * _EPS, 200)
        if (kx := self.K1(x)) != 0:
            self.dpos = max(self.dpos, abs(kx) / max(abs(self._slope(x)[0]), 1e-300) + 4 * _EPS * abs(x))
        return x

    def _march(self, s0, d, at_rest):
        """The end of the motion from s0 in the direction d: ('turn', a) a simple root of K,
        ('double', e), ('wall', w) or ('open', None).  Growing steps; a sign change of K is
        refined by Brent, a local minimum of K by :meth:`_dip`."""
        wall, h, sp = (self.hi if d > 0 else self.lo), 1e-2 * self.L, s0
        while at_rest and wall != s0 and not (sp != s0 and self.K1(sp) > 0):   # a first step where K > 0
            if h < 1e-300:
                raise NumericalError(f"released from rest at s0 = {s0:.9g}, the body cannot move: K ≤ 0 on the "
                                     "side where K' says it should grow")
            sp, h = (s0 + d * h if wall is None or d * (wall - s0 - d * h) > 0 else wall), h / 2
        if (at_rest and sp == wall) or wall == s0:   # (starting against the wall: refused at once)
            return ("wall", wall)
        dk_of = (lambda x: d * float(self.Kp(x))) if self.Kp is not None else (lambda x: None)   # noqa: E731
        kmax, spp, kpp, dp = (kp := self.K1(sp)), None, None, dk_of(sp)
        for _ in range(_STEPS):
            at_wall = wall is not None and d * (sp + d * h - wall) >= 0
            s = wall if at_wall else sp + d * h
            if float(self._K(s)) == _INF:   # K overflows far out: no turning point ahead
                return ("open", None)
            k = self.K1(s)
            if k <= 0:
                return self._kind(s if k == 0 else self._root(sp, s))
            dk = dk_of(s)       # a minimum of K inside the step: K' − to + along d (issue #28), or 3 values of K
            found = (self._dip(sp, s, kmax) if dp is not None and dp < 0 <= dk else None) or \
                (self._dip(spp, s, kmax) if spp is not None and kp < kpp and kp <= k else None)
            if found or at_wall:
                return found or ("wall", wall)
            kmax = self.kref = max(kmax, k, self.kref)
            spp, kpp, sp, kp, h, dp = sp, kp, s, k, h * _GROW, dk
        return ("open", None)

    def _dip(self, a, b, kmax):
        """A local minimum of K inside (a, b): a root pair (returns the first root) or a double
        root (K touches zero to rounding), else None."""
        u, v = a, b
        if self.Kp is not None and float(self.Kp(a)) * float(self.Kp(b)) < 0:
            u = v = brent(lambda s: float(self.Kp(s)), a, b, 4 * _EPS * max(abs(a), abs(b)), 4 * _EPS, 200)
        for _ in range(0 if u == v else 200):   # else a golden section
            c1, c2 = v - 0.618033988749895 * (v - u), u + 0.618033988749895 * (v - u)
            u, v = (u, c2) if self.K1(c1) < self.K1(c2) else (c1, v)
            if abs(v - u) <= 4 * _EPS * max(abs(u), abs(v)):
                break
        if (kx := self.K1(x := 0.5 * (u + v))) < 0:    # a pair of simple roots: the first one
            return self._kind(self._root(a, x))
        if kx <= 64 * _EPS * kmax:      # K touches zero to rounding: a double root
            self.dpos = max(self.dpos, abs(v - u))   # the golden section's resolution of a flat minimum
            return ("double", x)
        return None

    def _track(self, behind, ahead):
        """The pieces from the end behind s0 to the end ahead (in the direction d): from their
        midpoint m (s0 if one end is open) towards each end, as its kind asks; one 'turn' piece
        from a turning point to infinity."""
        (kb, sb), (ka, sa), d = behind, ahead, self.d
        if {kb, ka} == {"turn", "open"}:
            a, sig = (sb, d) if kb == "turn" else (sa, -d)
            return [_Piece(self, "turn", a, sig, _INF, c=abs(self._slope(a)[0]))]
        m = 0.5 * (sb + sa) if "open" not in (kb, ka) else self.s0
        return [_Piece(self, "turn", end, -sig, math.sqrt(abs(m - end)), c=abs(self._slope(end)[0])) if kind == "turn"
                else _Piece(self, "double", m, sig, _INF, c=0.5 * self._curv(end), e=end) if kind == "double"
                else _Piece(self, "line", m, sig, abs(end - m) if kind == "wall" else _INF)
                for kind, end, sig in ((kb, sb, -d), (ka, sa, d))]

    def _path(self, track, s_from, s_to):
        """Segments (piece, x_from, x_to, duration) from s_from to s_to along the track."""
        lo, hi, out = min(s_from, s_to), max(s_from, s_to), []
        for p in (track if (s_to - s_from) * self.d > 0 else track[::-1]):
            p_lo, p_hi = p.span()
            if min(hi, p_hi) > max(lo, p_lo):
                x0, x1 = (p.x_of(min(max(v, p_lo), p_hi)) for v in (s_from, s_to))
                if x0 != x1:
                    dur = _INF if _INF in (x0, x1) else abs(p.tau(x1) - p.tau(x0))
                    out.append((p, x0, x1, dur))
        return out

    def _plan(self):
        """The legs of the motion after t = 0 and its periodic cycle (None if not periodic)."""
        s0, v0, self.turning_points, self.period, self.asymptote = self.s0, self.sdot0, [], None, None
        self._legs, self._cycle, self._track_, self.kind, self.t_wall = [], None, [], "rest", None
        rest = v0 == 0
        if rest and self._kind(s0)[0] == "double":
            return
        self.d = d = math.copysign(1.0, v0 if not rest else self._slope(s0)[0])
        ahead = self._march(s0, d, rest)
        behind = ("turn", s0) if rest else (self._march(s0, -d, False) if ahead[0] == "turn" else ("open", None))
        track = self._track_ = self._track(behind, ahead)
        end_a, end_b = (e[1] if e[0] != "open" else sg * _INF for e, sg in ((ahead, d), (behind, -d)))
        legs, final = self._path(track, s0, end_a), ahead
        if ahead[0] == "turn":
            back = self._path(track, ahead[1], end_b)
            if behind[0] == "turn":
                self._cycle = back + self._path(track, behind[1], ahead[1])
            else:
                legs, final = legs + back, behind
        self._legs = legs
        reached = [ahead] + ([behind] if rest or ahead[0] == "turn" else [])
        self.turning_points = sorted(e[1] for e in reached if e[0] in ("turn", "double"))
        self.kind = {"turn": "oscillation", "double": "asymptotic", "wall": "wall", "open": "runaway"}[final[0]]
        self.period = sum(seg[3] for seg in self._cycle) if self._cycle else None
        self.asymptote = final[1] if final[0] == "double" else None
        if final[0] == "wall":
            self.t_wall, self._wall = float(sum(seg[3] for seg in legs)), final[1]

    def state(self, t: float) -> tuple[float, float]:
        """(s, ṡ) at the time t ≥ 0."""
        if not (0 <= (t := float(t)) < _INF):
            raise InputError(f"t = {t!r}: the state is defined for finite t ≥ 0")
        if self.kind == "rest" or t == 0:
            return self.s0, self.sdot0
        self._t_max, tt = max(self._t_max, t), t
        past = sum(seg[3] for seg in self._legs)
        if tt > past and self._cycle is None:
            raise NumericalError(f"the motion reaches the end of its range (s = {self._wall:.9g}) at "
                                 f"t = {self.t_wall:.9g}: no state at t = {t:.9g} past it")
        legs = self._legs if tt <= past else self._cycle
        tt = tt if tt <= past else math.fmod(tt - past, self.period)
        for p, x0, x1, dur in legs:
            if tt <= dur or (p, x0, x1, dur) == legs[-1]:
                sgn = 1.0 if x1 > x0 else -1.0
                x = p.x_at(max(p.tau(x0) + sgn * min(tt, dur), 0.0))
                return float(p.s(x)), p.speed(x) * p.sig * sgn
            tt -= dur
        raise AssertionError("unreachable: the last leg returns")

    def breaks(self, t_end: float) -> list[float]:
        """The times up to t_end at which a leg ends: the turning points, the junctions of the
        pieces (midway between two turning points) and the arrival at a wall."""
        ends = np.cumsum([seg[3] for seg in self._legs]).tolist()
        if self._cycle is not None:
            t0 = ends[-1] if ends else 0.0
            n = math.floor(max(t_end - t0, 0.0) / self.period) + 1
            if n * len(self._cycle) > 1e6:
                raise InputError(f"t_end = {t_end:.6g} spans more than 1e6 legs of the period {self.period:.6g}")
            cyc = np.cumsum([seg[3] for seg in self._cycle])
            ends += (t0 + np.add.outer(self.period * np.arange(n), cyc).ravel()).tolist()
        return [float(t) for t in ends if t <= t_end]

    def turning_times(self, t_end: float) -> list[float]:
        """The times up to t_end at which the motion reaches a turning point (ṡ = 0, s at an
        extreme): the ends of the legs that arrive at a simple root of K."""
        def arrive(segs):
            return [seg[0].kind == "turn" and seg[2] == 0.0 for seg in segs]
        ends = self.breaks(t_end)
        flags = arrive(self._legs)
        if self._cycle is not None:
            flags += arrive(self._cycle) * (max(len(ends) - len(flags), 0) // max(len(self._cycle), 1) + 1)
        return [t for t, turn in zip(ends, flags) if turn]

    @property
    def error_estimate(self) -> float:
        """Relative (the module's docstring); it covers every state evaluated so far."""
        if (pieces := self._track_) == []:
            return 0.0                  # at rest: exact
        err = sum(p.errs[-1] + p.noise() for p in pieces) + self.err_max
        T = self.period or (sum(seg[3] for seg in self._legs if math.isfinite(seg[3]))
                            + max((p.ts[-1] for p in pieces if math.isinf(p.X)), default=0.0))
        ext = (max(self.turning_points) - min(self.turning_points)) if len(self.turning_points) == 2 else self.L
        rel = 2 * math.pi * err / T * max(1.0, self._t_max / T) if T > 0 else 0.0   # phase errors add up
        return max(rel + self.dpos / ext, 100 * _EPS)
