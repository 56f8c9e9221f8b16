"""Kinematics of a point constrained to a curve that is fixed or turns about a
fixed axis (notes §5, §11, §18).

The curve y(q) is given on its own frame; the frame turns about the fixed
unit axis k through the origin by the angle φ(t), φ̇ = ω(t), so the position
is x = Q(φ) y(q) with Q the rotation about k (Rodrigues).  With the tangent
τ = Q y'(q) (not of unit length) and the relative velocity τ q̇,

    v = τ q̇ + ω k × x,                                             (11.11)
    a = τ q̈ + b,  b = Q y'' q̇² + 2 ω k × τ q̇ + ω̇ k × x + ω² k × (k × x),

so the tangential part of m a = F + N + f fixes q̈ and the part normal to τ
gives the constraint force N = P⊥(m b − F) (P⊥ the projector normal to τ),
independently of q̈.  The path's own basis {e_t, e_n, e_b} is the Frenet
basis of the curve y(q) on its frame (turned with it); where the curve is
straight (κ = 0) the principal normal is not defined and e_n is the axis k
(or e3, e1) with its e_t part removed.
"""

from __future__ import annotations

import numpy as np

from dyncli.expr.derivative import derivative
from dyncli.direction import norm_rows, unit_rows


def rotation(k, phi):
    """Rotation matrices about the unit axis k by the angles phi: (n, 3, 3)."""
    phi = np.atleast_1d(np.asarray(phi, float))
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]], float)
    s, c = np.sin(phi)[:, None, None], np.cos(phi)[:, None, None]
    return np.eye(3)[None] + s * K[None] + (1 - c) * (K @ K)[None]


def _cross(a, b):
    """a × b of columns (3, n) (a (3, 1) column broadcasts), as numpy's cross computes it."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


class Curve:
    def __init__(self, p):
        comps = tuple(p.curve)
        self.y0 = comps
        # exact derivatives by the rules of calculus on the expression IR (sympy only for min/max)
        self.y1 = tuple(derivative(e, "q") for e in comps)
        self.y2 = tuple(derivative(e, "q") for e in self.y1)
        self._speed = None
        rot = p.rotation
        self.k = np.asarray(rot.axis, float) if rot else np.array([0.0, 0.0, 1.0])
        # no omega: only steady queries, which find the rate (the curve's geometry is all they use)
        self.omega_expr = rot.omega if rot else None
        self.rotating = rot is not None
        self.omega_const = (None if self.omega_expr is None or "t" in rot.omega.variables
                            else float(rot.omega.value()))
        if self.omega_expr is not None and self.omega_const is None:
            self.omega_dot_expr = derivative(rot.omega, "t")

    def speed(self, q: float) -> float:
        """|y'(q)| at one float q in plain floats (the arc length's integrand): the first
        derivatives of one jet of each component (:func:`dyncli.expr.jet.compile_jet`)."""
        fn = self._speed
        if fn is None:
            import math

            from dyncli.expr import floatmath
            from dyncli.expr.jet import compile_jet

            j1, j2, j3 = (compile_jet(e.ir, "q", floatmath) for e in self.y0)

            def fn(q):
                env = {"q": q}
                a, b, c = j1(env)[1], j2(env)[1], j3(env)[1]
                return math.sqrt(a * a + b * b + c * c)
            self._speed = fn
        return fn(q)

    def float_jet(self):
        """``q -> (y, y', y'')``, the nine components at one float q in plain floats (the right-hand
        side's curve): each component's derivatives differentiated once, on the expression IR
        (:func:`dyncli.expr.derivative.derivative`), and compiled into float closures
        (:func:`dyncli.expr.floateval.float_fn`: a component free of q returns its value).  One call each:
        cheaper than a loop over the components that vary; a curve in a coordinate plane (one
        component constant, e.g. a hoop) gives that component's three values without a call."""
        from dyncli.expr.floateval import float_fn

        fns = [float_fn(e, "q") for e in self.y0 + self.y1 + self.y2]
        f1, f2, f3, g1, g2, g3, h1, h2, h3 = fns
        flat = [i for i in range(3) if not any("q" in e.variables for e in (self.y0[i], self.y1[i], self.y2[i]))]
        if len(flat) == 1:
            c, d, e = (fns[flat[0] + 3 * j](0.0) for j in range(3))    # the constant's value, its derivatives 0
            if flat == [0]:
                return lambda q: (c, f2(q), f3(q), d, g2(q), g3(q), e, h2(q), h3(q))
            if flat == [1]:
                return lambda q: (f1(q), c, f3(q), g1(q), d, g3(q), h1(q), e, h3(q))
            return lambda q: (f1(q), f2(q), c, g1(q), g2(q), d, h1(q), h2(q), e)
        return lambda q: (f1(q), f2(q), f3(q), g1(q), g2(q), g3(q), h1(q), h2(q), h3(q))

    @staticmethod
    def _ev(es, q):
        """The components ``es`` at the parameters q, rows (len(es), n): each one's compiled
        evaluator on the array (``Expr.evaluate``'s values, without its per-call error state and
        broadcast: a component free of q is spread over the row here)."""
        q = np.atleast_1d(np.asarray(q, float))
        out = np.empty((len(es), q.size))
        env = {"q": q}
        with np.errstate(all="ignore"):
            for i, e in enumerate(es):
                out[i] = e.scalar_fn()(env)
        return out

    def y(self, q):
        return self._ev(self.y0, q)

    def dy(self, q):
        return self._ev(self.y1, q)

    def ddy(self, q):
        return self._ev(self.y2, q)

    def omega(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        if self.omega_expr is None:
            return np.zeros_like(t), np.zeros_like(t)
        if self.omega_const is not None:
            return np.full_like(t, self.omega_const), np.zeros_like(t)
        return self.omega_expr.evaluate(t=t), self.omega_dot_expr.evaluate(t=t)

    def state(self, t, q, qd, phi, jet=False):
        """Fixed-frame x, v, τ and b (see the module docstring), arrays (3, n), and the rotations Q;
        ``jet``: also y' and y'' on the curve's frame (for :meth:`frenet`, not evaluated twice)."""
        t, q, qd, phi = (np.atleast_1d(np.asarray(a, float)) for a in (t, q, qd, phi))
        Q = rotation(self.k, phi)
        y, y1, y2 = self.y(q), self.dy(q), self.ddy(q)
        x = np.einsum("nij,jn->in", Q, y)
        tau = np.einsum("nij,jn->in", Q, y1)
        w, wd = self.omega(t)
        k = self.k[:, None]
        kx = _cross(k, x)
        v = tau * qd + w * kx
        ktau = _cross(k, tau)
        kkx = _cross(k, kx)
        b = np.einsum("nij,jn->in", Q, y2) * qd ** 2 + 2 * w * ktau * qd + wd * kx + w ** 2 * kkx
        return (x, v, tau, b, Q, y1, y2) if jet else (x, v, tau, b, Q)

    def motion(self, t, q, qd, phi):
        """Fixed-frame x and v alone (:meth:`state`'s values, without τ's rate b)."""
        t, q, qd, phi = (np.atleast_1d(np.asarray(a, float)) for a in (t, q, qd, phi))
        Q = rotation(self.k, phi)
        x = np.einsum("nij,jn->in", Q, self.y(q))
        tau = np.einsum("nij,jn->in", Q, self.dy(q))
        w = self.omega(t)[0]
        return x, tau * qd + w * _cross(self.k[:, None], x)

    def frenet(self, q, Q, y1=None, y2=None):
        """e_t, e_n, e_b (fixed-frame components, (3, n) each) and κ (``y1``, ``y2``: y' and y'' at q
        when they are known)."""
        if y1 is None:
            y1, y2 = self.dy(q), self.ddy(q)
        sp = norm_rows(y1.T)                      # lengths and directions scaled first (dyncli.direction)
        et = np.nan_to_num(unit_rows(y1.T).T)     # a zero tangent stays 0
        c = _cross(y1, y2)
        kappa = np.linalg.norm(c, axis=0) / np.where(sp > 0, sp, 1.0) ** 3
        n_raw = y2 - np.sum(y2 * et, axis=0) * et
        nn = norm_rows(n_raw.T)
        straight = kappa <= 1e-12 * np.maximum(1.0, np.linalg.norm(y2, axis=0) / np.where(sp > 0, sp, 1.0) ** 2)
        en = np.nan_to_num(unit_rows(n_raw.T).T)
        for j in np.flatnonzero(straight | (nn == 0)):
            for cand in (self.k, np.array([0.0, 0, 1]), np.array([1.0, 0, 0])):
                w = cand - (cand @ et[:, j]) * et[:, j]
                if np.linalg.norm(w) > 1e-6:
                    en[:, j] = w / np.linalg.norm(w)
                    break
        eb = _cross(et, en)
        turn = lambda e: np.einsum("nij,jn->in", Q, e)  # noqa: E731
        return turn(et), turn(en), turn(eb), np.where(straight, 0.0, kappa), bool(straight.any())
