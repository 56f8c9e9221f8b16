"""The energy integral along a fixed curve and its turning points, decided exactly (notes §18-§20;
issue #28: never by sampling).

Along a fixed curve every force of the position only does work that depends on q alone,
W(q) = ∫ Q dq with the generalised force Q = F·y' (19.4), so T = K(q) = T1 + W(q) − W(q0) (20.1).

* Critical points of V = −W: every root of Q on q_range (dyncli.rootfind.all_roots: Q's sign at
  the critical points of its resolved Chebyshev interpolant decides, sign changes and tangencies;
  a closed curve also at its seam when Q changes sign across it).
* K between two consecutive critical points is monotone.  Walking from the start in the direction
  of motion, K at each critical point (a barrier's top when V has a maximum there) decides: K > 0
  the particle passes, K < 0 it turns before it — at the one root of K in that bracket (Brent) —
  and |K| within its rounding is undecided: refused with a message (never guessed).
* K is formed from the nearest point where it is known exactly (the start and, on a closed curve,
  its images q0 + kL; a turning point, K = 0) as K_ref + ∫_ref^q Q, composite Gauss–Legendre on
  cells laid from that point, so its rounding is relative to K itself (not to the work over the
  whole curve): a barrier 1e-12 rad above the start is resolved, and K is smooth to rounding.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.rootfind import NotANumber, all_roots, brent

N_CELLS = 1024
_EPS = float(np.finfo(float).eps)
_XG, _WG = np.polynomial.legendre.leggauss(8)


class Skip(Exception):
    """The energy route does not apply; the message says why."""


class Energy:
    def __init__(self, p, model):
        self.p, self.model, self.curve = p, model, model.curve
        # energies (and m) are held in a unit 2^k J that balances the work over the wire against
        # the mass term m|y'|²: scaling by a power of two is exact, and keeps K, M·du and their
        # roundings clear of the subnormals (a bead of 1e-301 kg); W() reports joules
        self.unit, self.m = 1.0, float(model.m)
        if p.q_range is None:
            raise Skip("the energy route needs q_range (the ends of the wire)")
        self.lo, self.hi = (float(v) for v in p.q_range)
        self.L, self.closed = self.hi - self.lo, model.closed
        edges = np.linspace(self.lo, self.hi, N_CELLS + 1)     # the table of W: cells, not a search
        self.edges, self.h = edges, edges[1] - edges[0]
        Qt, Qn = self._gen(self._nodes(edges[:-1], edges[1:]))
        w = _WG * (self.h / 2)
        self.cum = np.concatenate([[0.0], np.cumsum(Qt @ w)])
        self.cum_n = np.concatenate([[0.0], np.cumsum(Qn @ w)])
        self._in_unit(p)
        self.scale = max(float(np.max(np.abs(self.cum))), 1e-300)
        x6, w6 = np.polynomial.legendre.leggauss(6)   # the cells must resolve the forces along the curve
        Q6 = self._gen((0.5 * (edges[:-1] + edges[1:]))[:, None] + (0.5 * self.h) * x6[None, :])[0]
        if np.max(np.abs(self.cum[1:] - np.cumsum(Q6 @ (w6 * self.h / 2)))) > 1e-9 * self.scale:
            raise Skip(f"q_range is too long for the energy route's {N_CELLS} cells to resolve the curve")
        if self.closed and abs(self.cum[-1]) > 1e-10 * self.scale:
            raise Skip("the forces do net work around the closed curve")
        self.q0 = float(p.q0)
        self.T0 = 0.5 * float(self.M(np.array([self.q0]))[0]) * float(p.q_dot0) ** 2
        self.Q0 = float(self.Q(np.array([self.q0]))[0])
        self._integrals = {}
        self.crit = self._critical_points()
        inner = [c for c in self.crit if self.lo < c < self.hi or self.closed]   # (the wire's ends end the motion)
        if inner and not np.all(self.M(np.array(inner)) > 0):
            bad = next(c for c in inner if not float(self.M(np.array([c]))[0]) > 0)
            raise Skip(f"the curve's tangent dy/dq vanishes at q = {bad:.6g}, a critical point of the potential "
                       "(the speed q̇ is not finite there)")

    def _in_unit(self, p):
        """Choose the unit 2^k J at the geometric mean of the energy's size (the work over the
        wire, or the start's kinetic energy) and the mass term's (m|y'(q0)|²), so that both
        their ratio (q̇²) and each of them stay normal doubles, and express the table, m and
        the generalised forces in it."""
        y1 = self.curve.dy(np.array([float(p.q0)]))
        mass = self.m * float(np.sum(y1 * y1))
        size = max(float(np.max(np.abs(self.cum))), 0.5 * mass * float(p.q_dot0) ** 2)
        if not (0.0 < size < math.inf):
            return
        k = math.frexp(size)[1]
        if 0.0 < mass < math.inf:
            k = (k + math.frexp(mass)[1]) // 2
        self.unit = math.ldexp(1.0, -k)
        self.cum, self.cum_n, self.m = self.cum * self.unit, self.cum_n * self.unit, self.m * self.unit

    # -- the generalised force and the work ----------------------------------------------
    @staticmethod
    def _nodes(a, b):
        a, b = np.asarray(a, float), np.asarray(b, float)
        return (0.5 * (a + b))[..., None] + (0.5 * (b - a))[..., None] * _XG

    def _gen(self, q):
        """The generalised forces F·y' (total and of the non-potential terms) at q (any shape); on a
        curve turning at constant ω the total adds the centrifugal force's, m ω² (y − k (k·y))·y'
        (the relative motion's Jacobi integral: the Coriolis force and N do no work along the curve)."""
        shape, qf = np.shape(q), np.ravel(q)
        x = self.curve.y(qf)
        Fc, Fn = self.model.forces(np.zeros_like(qf), x, np.zeros_like(x))
        y1 = self.curve.dy(qf)
        u = self.unit
        total = np.sum((Fc + Fn) * y1, axis=0)
        w = self.curve.omega_const if self.curve.rotating else None
        if w:
            k = self.curve.k[:, None]
            total = total + float(self.model.m) * w * w * np.sum((x - k * np.sum(k * x, axis=0)) * y1, axis=0)
        return total.reshape(shape) * u, np.sum(Fn * y1, axis=0).reshape(shape) * u

    def Q(self, q):
        return self._gen(np.asarray(q, float))[0]

    def M(self, q):
        """m |y'(q)|²: T = ½ M q̇²."""
        y1 = self.curve.dy(np.ravel(q))
        return self.m * np.sum(y1 * y1, axis=0).reshape(np.shape(q))

    def W(self, q, which=0):
        """W(q) − W(lo) (which=0: all forces; 1: the non-potential ones), q anywhere (a closed
        curve is periodic), from the table."""
        q = np.asarray(q, float)
        loops = np.floor((q - self.lo) / self.L) if self.closed else np.zeros_like(q)
        qq = q - loops * self.L
        i = np.clip(((qq - self.lo) // self.h).astype(int), 0, N_CELLS - 1)
        a = self.edges[i]
        G = self._gen(self._nodes(np.ravel(a), np.ravel(qq)))[which]
        part = (G @ _WG) * (np.ravel(qq) - np.ravel(a)) / 2
        cum = self.cum if which == 0 else self.cum_n
        return ((cum[i] + part.reshape(np.shape(q))) + loops * cum[-1]) / self.unit

    def I(self, qa, q):
        """∫_qa^q Q (q an array) and its rounding, from qa's own table (:class:`Integral`)."""
        if qa not in self._integrals:
            self._integrals[qa] = Integral(self, qa)
        return self._integrals[qa](np.atleast_1d(np.asarray(q, float)))

    def ref_near(self, q, refs):
        """The reference (q_ref, K_ref) nearest q: refs, and the start's images on a closed curve."""
        cands = list(refs)
        if self.closed:
            k = round((q - self.q0) / self.L)
            cands += [(self.q0 + j * self.L, self.T0) for j in (k - 1, k, k + 1)]
        return min(cands, key=lambda r: abs(q - r[0]))

    def K(self, q, refs):
        """(K(q), its rounding) for a scalar q, from the nearest reference."""
        qr, kr = self.ref_near(q, refs)
        v, e = self.I(qr, np.array([q]))
        return kr + float(v[0]), float(e[0]) + 4 * _EPS * abs(kr)

    def K_from(self, q, ref):
        """K on an array of q from one reference (q_ref, K_ref)."""
        return ref[1] + self.I(ref[0], q)[0]

    # -- critical points and turning points ------------------------------------------------
    def _critical_points(self):
        roots, touches, bad = all_roots(self.Q, self.lo, self.hi)
        if bad:
            raise Skip(f"the generalised force F·dy/dq is not finite near q = {bad[0]:.6g}")
        crit = sorted(set(roots + touches))
        if self.closed:
            qe = self.Q(np.array([self.lo, self.hi]))
            crit = [c for c in crit if c < self.hi]
            if (qe[0] * qe[1] <= 0) and not (crit and crit[0] == self.lo):
                crit = [self.lo] + crit          # Q changes sign across the seam
        return crit

    def crit_between(self, s, end):
        """The critical points strictly between s and end, in the order of travel."""
        lo, hi = min(s, end), max(s, end)
        cs = []
        ks = range(math.floor((lo - self.lo) / self.L) - 1, math.ceil((hi - self.lo) / self.L) + 1) \
            if self.closed else [0]
        for k in ks:
            cs += [c + k * self.L for c in self.crit if lo < c + k * self.L < hi]
        return sorted(cs, reverse=end < s)

    def nearest_crit(self, q):
        cs = self.crit_between(q - self.L, q + self.L) if self.closed else self.crit
        return min(cs, key=lambda c: abs(c - q), default=None)

    def next_turn(self, s, d, refs):
        """(a, c): the first root a of K after s in the direction d and the critical point c
        beyond it (None at a wall), or None: no turning point (to the end of an open wire, or
        within one loop of a closed one)."""
        end = s + d * self.L if self.closed else (self.hi if d > 0 else self.lo)
        if end == s:
            return None
        prev = s
        for c in self.crit_between(s, end) + ([] if self.closed else [end]):
            k, err = self.K(c, refs)
            if k > err:
                prev = c
                continue
            if k >= -err and not (c == end and k <= 0):
                raise Skip(f"the energy equals the top of the barrier at q = {c:.9g} to within its rounding "
                           f"(T there = {k:.3g} ± {err:.2g} J): whether the particle passes it is not decided "
                           "in double precision; change q0 or q_dot0 so that the kinetic energy there differs "
                           f"from 0 by more than {err:.2g} J")
            if k == 0:
                return c, (None if c == end else c)
            try:
                a = brent(lambda q: self.K(q, refs)[0], prev, c, 4 * _EPS * max(abs(prev), abs(c)), 4 * _EPS, 200)
            except NotANumber as e:           # the energy integral overflows there (fuzz seed 1303530)
                raise Skip(f"the kinetic energy is not finite near q = {e.x:.6g} (its terms overflow)") from None
            return a, (None if c == end else c)
        return None

    def sensitivity(self, a, c):
        """|dτ/da|·δa: the time lost near a turning point a just short of a barrier's top c when a
        moves by its rounding (time ~ sqrt(M/Q'(c)) ln(1/|a − c|) there: the log of a separatrix)."""
        if c is None or a == c:
            return 0.0
        da = 4 * _EPS * max(abs(a), 1.0)
        hq = max(abs(a - c), 64 * _EPS * max(abs(c), 1.0))
        dQ = abs(float(self.Q(np.array([c + hq]))[0] - self.Q(np.array([c - hq]))[0])) / (2 * hq)
        return math.sqrt(float(self.M(np.array([c]))[0]) / max(dQ, 1e-300)) * da / abs(a - c)


class Integral:
    """∫_qa^q Q by 8-point Gauss–Legendre on cells of the table's width laid from qa on either
    side (cumulated lazily), the last cell partial: smooth in q, rounding ~ε ∫|Q|."""

    def __init__(self, E, qa):
        self.E, self.qa = E, qa
        self.tab = {1.0: (np.zeros(1), np.zeros(1)), -1.0: (np.zeros(1), np.zeros(1))}

    def _extend(self, side, j):
        cum, cab = self.tab[side]
        if len(cum) > j:
            return
        e = self.qa + side * self.E.h * np.arange(len(cum) - 1, j + 2)
        parts = (self.E.Q(Energy._nodes(e[:-1], e[1:])) @ _WG) * (e[1:] - e[:-1]) / 2
        self.tab[side] = (np.concatenate([cum, cum[-1] + np.cumsum(parts)]),
                          np.concatenate([cab, cab[-1] + np.cumsum(np.abs(parts))]))

    def __call__(self, q):
        out, err = np.zeros_like(q), np.zeros_like(q)
        for side in (1.0, -1.0):
            sel = (q - self.qa) * side > 0
            if not np.any(sel):
                continue
            j = np.floor(np.abs(q[sel] - self.qa) / self.E.h).astype(int)
            self._extend(side, int(j.max()))
            cum, cab = self.tab[side]
            edge = self.qa + side * self.E.h * j
            part = (self.E.Q(Energy._nodes(edge, q[sel])) @ _WG) * (q[sel] - edge) / 2
            out[sel] = cum[j] + part
            err[sel] = 32 * _EPS * (cab[j] + np.abs(part))
        return out, err
