"""The force terms of a particle problem compiled for the integrator (notes §19, §20).

Conservative terms (their potential is in V, 20.5): gravity near the earth (V = m g x3, 19.23),
inverse-square gravity (V = -m g R0²/R, 19.18, 19.20b), linear springs (V = k (R - L)²/2, 19.26).
Every other term (uniform, damper, drag, friction, custom) is part of F̄ of (20.2) and its work
is W_nc.  The formulas are those of :mod:`dyncli.topics.particle.equations`; the right-hand side
of the integrator inlines them in plain float arithmetic (it is called once per stage).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import InputError
from dyncli.topics.particle import equations as eq


class NonFiniteForce(Exception):
    """Raised by the right-hand side when the force is inf or NaN."""

    def __init__(self, t: float, x):
        super().__init__(t)
        self.t, self.x = t, np.array(x, float)


class Forces:
    """The force terms of a problem compiled into numpy-friendly pieces.

    Vectors are handled as arrays of shape (3,) or (3, n)."""

    def __init__(self, p):
        self.m = m = float(p.m)
        self.uniform = np.zeros(3)
        self.weight = 0.0            # m g for each gravity term
        self.inv: list[tuple[np.ndarray, float, float]] = []      # (centre, m g R0², R0)
        self.springs: list[tuple[np.ndarray, float, float, str | None]] = []  # (anchor, k, L, one_sided)
        self.c_lin = 0.0             # dampers + linear drag
        self.c_quad = 0.0            # quadratic drag
        self.muN = 0.0               # sum of mu N over friction terms
        self.custom: list[tuple] = []
        self.kinds: list[str] = []
        for f in p.forces:
            k = f.kind
            self.kinds.append(k)
            if k == "uniform":
                self.uniform = self.uniform + np.asarray(f.F, float)
            elif k == "gravity":
                self.weight += m * p.g
            elif k == "inverse-square":
                g = p.g if f.g is None else f.g
                R0 = float(f.R0)
                mu = m * g * R0 * R0        # float products give inf, never OverflowError
                if not math.isfinite(mu):
                    raise InputError(f"the inverse-square field is too strong to compute: m g R0² = "
                                     f"{m:g} kg · {g:g} m/s² · ({R0:g} m)² overflows", f"forces.{len(self.kinds) - 1}.R0")
                self.inv.append((np.asarray(f.center, float), mu, R0))
            elif k == "spring":
                self.springs.append((np.asarray(f.anchor, float), float(f.k), float(f.L), f.one_sided))
            elif k == "damper":
                self.c_lin += f.c
            elif k == "drag":
                if f.power == 1:
                    self.c_lin += f.c
                else:
                    self.c_quad += f.c
            elif k == "friction":
                self.muN += f.mu * f.N
            elif k == "custom":
                self.custom.append(tuple(f.F))
            else:  # pragma: no cover - the model's union forbids it
                raise InputError(f"unknown force kind {k!r}", "forces")
        self.time_dependent = any("t" in e.variables for F in self.custom for e in F)
        #: the longest step over a one-sided spring's engagement (a kink in the force): an eighth of its
        #: half period, so that no step leaps over the contact and the error control sees the kink
        self.kink_step = min([math.pi * math.sqrt(m / k) / 8 for _, k, _, side in self.springs if side] + [math.inf])

    def symmetric_about(self, k) -> bool:
        """Whether the field turns with every rotation Q about the unit axis k through the origin:
        F(t, Q x, Q v) = Q F(t, x, v) (a uniform force and gravity along k, centres and anchors on
        the axis, dampers and drag; a custom force never counts as symmetric).  Decided exactly
        (a cross product that is not exactly zero counts as off the axis)."""
        k1, k2, k3 = (float(c) for c in k)

        def on_axis(a) -> bool:
            a1, a2, a3 = (float(c) for c in a)
            return k2 * a3 - k3 * a2 == 0.0 and k3 * a1 - k1 * a3 == 0.0 and k1 * a2 - k2 * a1 == 0.0

        return (not self.custom and on_axis(self.uniform) and (not self.weight or on_axis((0.0, 0.0, 1.0)))
                and all(on_axis(c) for c, _, _ in self.inv) and all(on_axis(a) for a, _, _, _ in self.springs))

    # -- forces -------------------------------------------------------------
    def conservative(self, x):
        """Gravity + inverse-square + springs (position only)."""
        F = np.zeros_like(x, dtype=float)
        if self.weight:
            F[2] = F[2] - self.weight
        for c, mu, _ in self.inv:
            F = F + eq.inverse_square_force(mu, x - _col(c, x))     # (19.18)
        for a, k, L, side in self.springs:
            F = F + eq.spring_force(k, L, x - _col(a, x), side)     # (19.26a)
        return F

    def nonconservative(self, t, x, v):
        """Uniform, damper, drag and custom terms (everything except friction)."""
        F = _col(self.uniform, x) * np.ones_like(x)
        if self.c_lin:
            F = F - self.c_lin * v
        if self.c_quad:
            F = F - self.c_quad * np.sqrt(np.sum(v * v, axis=0)) * v
        if self.custom:
            env = {"t": t, "x1": x[0], "x2": x[1], "x3": x[2], "v1": v[0], "v2": v[1], "v3": v[2]}
            for comps in self.custom:
                if np.ndim(x) == 1:     # one state (the integrator): the cheap scalar call
                    F = F + np.array([float(e(**env)) for e in comps])
                else:
                    F = F + np.stack([e.evaluate(**env) for e in comps])
        return F

    def make_rhs(self, d):  # over 60 lines: the integrator's hot loop, inlined in plain floats on purpose
        """The right-hand side y' = f(t, y) of one phase, y = [x, v, W_nc],
        as a tuple of 7 floats, in plain float arithmetic (the integrator calls it for one state at a
        time; the same forces as conservative() + nonconservative(), with
        the friction continuation -mu N sign(v.d) v/|v| of the phase).
        A non-finite force raises NonFiniteForce at once."""
        m, muN, weight = self.m, self.muN, self.weight
        u1, u2, u3 = self.uniform.tolist()
        c_lin, c_quad = self.c_lin, self.c_quad
        d1, d2, d3 = np.asarray(d, float).tolist()
        inv = [(float(c[0]), float(c[1]), float(c[2]), mu) for c, mu, _ in self.inv]
        springs = [(float(a[0]), float(a[1]), float(a[2]), k, L, {None: 0, "compression": -1, "tension": 1}[side])
                   for a, k, L, side in self.springs]
        custom = [tuple(e.scalar_fn() for e in comps) for comps in self.custom]
        sqrt, isfinite = math.sqrt, math.isfinite

        def rhs(t, y):
            x1, x2, x3, v1, v2, v3, _ = y.tolist()
            f1, f2, f3 = u1, u2, u3              # the non-conservative force
            if c_lin:
                f1, f2, f3 = f1 - c_lin * v1, f2 - c_lin * v2, f3 - c_lin * v3
            if c_quad:
                cs = c_quad * sqrt(v1 * v1 + v2 * v2 + v3 * v3)
                f1, f2, f3 = f1 - cs * v1, f2 - cs * v2, f3 - cs * v3
            if custom:
                env = {"t": float(t), "x1": x1, "x2": x2, "x3": x3, "v1": v1, "v2": v2, "v3": v3}
                with np.errstate(all="ignore"):
                    for e1, e2, e3 in custom:
                        f1, f2, f3 = f1 + float(e1(env)), f2 + float(e2(env)), f3 + float(e3(env))
            if muN:
                sp = sqrt(v1 * v1 + v2 * v2 + v3 * v3)
                if sp > 0.0:
                    k = muN / sp if v1 * d1 + v2 * d2 + v3 * d3 >= 0.0 else -muN / sp
                    f1, f2, f3 = f1 - k * v1, f2 - k * v2, f3 - k * v3
                else:
                    f1, f2, f3 = f1 - muN * d1, f2 - muN * d2, f3 - muN * d3
            g1, g2, g3 = 0.0, 0.0, -weight       # the conservative force
            for c1, c2, c3, mu in inv:
                r1, r2, r3 = x1 - c1, x2 - c2, x3 - c3
                R2 = r1 * r1 + r2 * r2 + r3 * r3
                den = R2 * sqrt(R2)
                if den == 0.0:
                    raise NonFiniteForce(t, (x1, x2, x3))
                k = mu / den
                g1, g2, g3 = g1 - k * r1, g2 - k * r2, g3 - k * r3
            for a1, a2, a3, ks, L, side in springs:
                r1, r2, r3 = x1 - a1, x2 - a2, x3 - a3
                if L == 0.0:
                    if side <= 0:                  # one-sided compression is refused at L = 0
                        g1, g2, g3 = g1 - ks * r1, g2 - ks * r2, g3 - ks * r3
                else:
                    R = sqrt(r1 * r1 + r2 * r2 + r3 * r3)
                    if side * (R - L) < 0.0:       # a one-sided spring that is slack
                        continue
                    if R == 0.0:
                        raise NonFiniteForce(t, (x1, x2, x3))
                    k = ks * (R - L) / R
                    g1, g2, g3 = g1 - k * r1, g2 - k * r2, g3 - k * r3
            a1, a2, a3 = (f1 + g1) / m, (f2 + g2) / m, (f3 + g3) / m
            w = f1 * v1 + f2 * v2 + f3 * v3
            if not isfinite(a1 + a2 + a3 + w) and not (isfinite(a1) and isfinite(a2) and isfinite(a3)
                                                     and isfinite(w)):
                raise NonFiniteForce(t, (x1, x2, x3))
            return v1, v2, v3, a1, a2, a3, w         # a tuple: scipy makes it an array once

        return rhs

    def accelerations(self, d, t, X, V):
        """The acceleration a = f(t, y)[3:6] of :meth:`make_rhs` (one phase, friction direction
        ``d``) at many states at once, X and V (3, N): the same formulas with the same operations
        in the same order on whole arrays (so the same doubles as the integrator's calls, a custom
        term's expressions evaluated on the arrays).  A non-finite force raises NonFiniteForce at
        the first state where it is."""
        m, muN = self.m, self.muN
        x1, x2, x3 = X
        v1, v2, v3 = V
        u1, u2, u3 = self.uniform.tolist()
        n = X.shape[1]
        with np.errstate(all="ignore"):
            f1, f2, f3 = np.full(n, u1), np.full(n, u2), np.full(n, u3)
            if self.c_lin:
                c = self.c_lin
                f1, f2, f3 = f1 - c * v1, f2 - c * v2, f3 - c * v3
            if self.c_quad:
                cs = self.c_quad * np.sqrt(v1 * v1 + v2 * v2 + v3 * v3)
                f1, f2, f3 = f1 - cs * v1, f2 - cs * v2, f3 - cs * v3
            if self.custom:
                env = {"t": np.asarray(t, float), "x1": x1, "x2": x2, "x3": x3, "v1": v1, "v2": v2, "v3": v3}
                for e1, e2, e3 in self.custom:
                    f1, f2, f3 = f1 + e1.evaluate(**env), f2 + e2.evaluate(**env), f3 + e3.evaluate(**env)
            if muN:
                d1, d2, d3 = np.asarray(d, float).tolist()
                sp = np.sqrt(v1 * v1 + v2 * v2 + v3 * v3)
                k = np.where(v1 * d1 + v2 * d2 + v3 * d3 >= 0.0, muN / sp, -muN / sp)
                moving = sp > 0.0
                f1 = np.where(moving, f1 - k * v1, f1 - muN * d1)
                f2 = np.where(moving, f2 - k * v2, f2 - muN * d2)
                f3 = np.where(moving, f3 - k * v3, f3 - muN * d3)
            g1, g2, g3 = np.zeros(n), np.zeros(n), np.full(n, -self.weight)
            for c, mu, _ in self.inv:
                r1, r2, r3 = x1 - float(c[0]), x2 - float(c[1]), x3 - float(c[2])
                R2 = r1 * r1 + r2 * r2 + r3 * r3
                k = mu / (R2 * np.sqrt(R2))             # den = 0: inf, refused below as the scalar call is
                g1, g2, g3 = g1 - k * r1, g2 - k * r2, g3 - k * r3
            for a, ks, L, side in self.springs:
                side = {None: 0, "compression": -1, "tension": 1}[side]
                r1, r2, r3 = x1 - float(a[0]), x2 - float(a[1]), x3 - float(a[2])
                if L == 0.0:
                    if side <= 0:
                        g1, g2, g3 = g1 - ks * r1, g2 - ks * r2, g3 - ks * r3
                    continue
                R = np.sqrt(r1 * r1 + r2 * r2 + r3 * r3)
                k = np.where(side * (R - L) < 0.0, 0.0, ks * (R - L) / R)
                on = side * (R - L) >= 0.0                  # (a slack one-sided spring adds nothing)
                g1, g2, g3 = np.where(on, g1 - k * r1, g1), np.where(on, g2 - k * r2, g2), np.where(on, g3 - k * r3, g3)
            A = np.array([(f1 + g1) / m, (f2 + g2) / m, (f3 + g3) / m]).reshape(3, n)
            w = f1 * v1 + f2 * v2 + f3 * v3
        bad = ~(np.isfinite(A).all(axis=0) & np.isfinite(w))
        if bad.any():
            j = int(np.argmax(bad))
            raise NonFiniteForce(float(np.asarray(t, float).reshape(-1)[j] if np.ndim(t) else t), X[:, j])
        return A

    def plain(self):
        """conservative() and nonconservative() of one state in plain floats, for a right-hand side
        called once per stage: ``f(t, x1, x2, x3, v1, v2, v3) -> (Fc1, Fc2, Fc3, Fn1, Fn2, Fn3)``
        (the same formulas, 19.18 and 19.26a inlined; a singular force comes out inf or nan; a custom
        term's expressions give numpy scalars: call it inside one ``np.errstate``)."""
        u1, u2, u3 = self.uniform.tolist()
        c_lin, c_quad, weight = self.c_lin, self.c_quad, self.weight
        inv = [(float(c[0]), float(c[1]), float(c[2]), mu) for c, mu, _ in self.inv]
        springs = [(float(a[0]), float(a[1]), float(a[2]), k, L, {None: 0, "compression": -1, "tension": 1}[side])
                   for a, k, L, side in self.springs]
        custom = [tuple(e.scalar_fn() for e in comps) for comps in self.custom]
        sqrt, inf = math.sqrt, math.inf

        def forces(t, x1, x2, x3, v1, v2, v3):
            f1, f2, f3 = u1, u2, u3
            if c_lin:
                f1, f2, f3 = f1 - c_lin * v1, f2 - c_lin * v2, f3 - c_lin * v3
            if c_quad:
                cs = c_quad * sqrt(v1 * v1 + v2 * v2 + v3 * v3)
                f1, f2, f3 = f1 - cs * v1, f2 - cs * v2, f3 - cs * v3
            if custom:                           # numpy scalars: the caller runs inside one np.errstate
                env = {"t": float(t), "x1": x1, "x2": x2, "x3": x3, "v1": v1, "v2": v2, "v3": v3}
                for e1, e2, e3 in custom:
                    f1, f2, f3 = f1 + float(e1(env)), f2 + float(e2(env)), f3 + float(e3(env))
            g1, g2, g3 = 0.0, 0.0, -weight if weight else 0.0
            for c1, c2, c3, mu in inv:
                r1, r2, r3 = x1 - c1, x2 - c2, x3 - c3
                R2 = r1 * r1 + r2 * r2 + r3 * r3
                k = mu / (R2 * sqrt(R2)) if R2 else inf
                g1, g2, g3 = g1 - k * r1, g2 - k * r2, g3 - k * r3
            for a1, a2, a3, ks, L, side in springs:
                r1, r2, r3 = x1 - a1, x2 - a2, x3 - a3
                if L == 0.0:
                    k = ks                          # -k r (a one-sided spring at L = 0 is refused or acts for R > 0)
                else:
                    R = sqrt(r1 * r1 + r2 * r2 + r3 * r3)
                    k = 0.0 if side * (R - L) < 0.0 else (ks * (R - L) / R if R else inf)
                g1, g2, g3 = g1 - k * r1, g2 - k * r2, g3 - k * r3
            return g1, g2, g3, f1, f2, f3

        return forces

    def other(self, t, x):
        """All forces except friction, at rest (v = 0): the static condition."""
        v = np.zeros_like(x)
        return self.conservative(x) + self.nonconservative(t, x, v)

    def potential(self, x):
        """V of the conservative terms (19.23, 19.20b, 19.26b)."""
        V = [eq.gravity_potential(self.weight, x[2])] if self.weight else []
        V += [eq.inverse_square_potential(mu, x - _col(c, x)) for c, mu, _ in self.inv]
        V += [eq.spring_potential(k, L, x - _col(a, x), side) for a, k, L, side in self.springs]
        if not V:
            return np.zeros(np.shape(x)[1:]) if np.ndim(x) > 1 else 0.0
        total = V[0]
        for term in V[1:]:
            total = total + term
        return total


def _col(c, x):
    return c if np.ndim(x) == 1 else c[:, None]


# ---------------------------------------------------------------------------
# phases of the motion
