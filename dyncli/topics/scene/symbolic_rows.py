"""A scene's elements as sympy objects (``--symbolic`` only; sympy is imported by the caller).

The same bodies, points and joints as the numeric engine (:mod:`.elements`), written with
symbols: every coordinate q_i, its rate and its acceleration is a plain symbol (``x_A1``,
``θ̇_rod``, ``θ̈_rod``; time derivatives by the chain rule), every mass ``m_A``, central moment
``Ī_rod``, rod length ``L_rod``, rolling or pulley radius ``r_disk``, spring constant ``k_s``
and free length ``L_s``, damping ``c_d`` and ``g`` is a symbol with its value kept beside it,
and the rest of the geometry (surfaces' directions, named points, the cords' directions of
t = 0) is exact where a short fraction or a square root of 2 or 3 gives it, else a decimal.

Each joint gives its rows φ(q, t) and its multipliers λ written with the joint forces by
name, the contract's signs (pin ``R``, slider ``N``, ``M``, contact ``N``, rolling ``N``,
``F``, cord and link ``T`` = −λ, drive the driver's force or couple).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
import sympy as sp


#: a float within this relative distance of a short exact form is shown as that form (the
#: rounding of the sums that made it: a cord's constant 0.0999999999999999 is 1/10)
TOL = 1e-13


def exact(x: float):
    """A float as an exact number where a short form gives it to rounding (0.3 -> 3/10,
    0.8660254037844386 -> √3/2), else a sympy Float."""
    x = float(x)
    if x == 0 or x.is_integer() and abs(x) < 1e15:
        return sp.Integer(int(x))
    f = Fraction(x).limit_denominator(1000)
    if abs(float(f) - x) <= TOL * abs(x):
        return sp.Rational(f.numerator, f.denominator)
    h = Fraction(x / math.pi).limit_denominator(360)         # an angle: a fraction of π
    if h and abs(float(h) * math.pi - x) <= TOL * abs(x):
        return sp.Rational(h.numerator, h.denominator) * sp.pi
    for root in (2, 3, 6):
        g = Fraction(x / math.sqrt(root)).limit_denominator(100)
        if g and abs(float(g) * math.sqrt(root) - x) <= TOL * abs(x):
            return sp.Rational(g.numerator, g.denominator) * sp.sqrt(root)
    return sp.Float(x, 15)


def _tex_name(name: str) -> str:
    return name if len(name) == 1 else r"\mathrm{" + name.replace("_", r"\_") + "}"


@dataclass
class Symbols:
    """Every symbol with its text (the notes' letters), its LaTeX and its value."""

    text: dict = field(default_factory=dict)
    tex: dict = field(default_factory=dict)
    values: dict = field(default_factory=dict)

    def new(self, key: str, text: str, tex: str, value=None, positive=False):
        s = sp.Symbol(key, positive=True) if positive else sp.Symbol(key, real=True)
        self.text[s], self.tex[s] = text, tex
        if value is not None:
            self.values[s] = float(value)
        return s

    def param(self, letter: str, tex_letter: str, owner: str, value: float):
        """m_A, Ī_rod, L_rod, k_s: a positive constant named after its owner."""
        return self.new(f"{letter}_{owner}", f"{letter}_{owner}", f"{tex_letter}_{{{_tex_name(owner)}}}", value,
                        positive=True)

    def force(self, letter: str, owner: str, comp: str = ""):
        sub = owner + ("," + comp if comp else "")
        return self.new(f"{letter}_{owner}{comp}", f"{letter}_{sub}", f"{letter}_{{{_tex_name(owner)}"
                        + (f",{comp}" if comp else "") + "}")


@dataclass
class Coords:
    """q, q̇, q̈ as symbols, named after the engine's coordinates (x.A.0 -> x_A1, angle.rod -> θ_rod)."""

    q: list
    qd: list
    qdd: list

    @classmethod
    def of(cls, names: list[str], S: Symbols) -> "Coords":
        q: list = []
        qd: list = []
        qdd: list = []
        for nm in names:
            head, body, *comp = nm.split(".")
            if head == "x":
                k = str(int(comp[0]) + 1)
                base, tb, sub, tsub = "x", "x", f"{body}{k}", f"{_tex_name(body)},{k}"
            else:
                base, tb, sub, tsub = "θ", r"\theta", body, _tex_name(body)
            for dots, out, tdot in (("", q, ""), ("\u0307", qd, r"\dot"), ("\u0308", qdd, r"\ddot")):
                text = f"{base}{dots}_{sub}"
                tex = (f"{tdot}{{{tb}}}" if tdot else tb) + f"_{{{tsub}}}"
                out.append(S.new(f"{base}{dots}_{sub}", text, tex))
        return cls(q, qd, qdd)

    def dt(self, expr):
        """d/dt of an expression in q and q̇ (the chain rule)."""
        return sum((sp.diff(expr, a) * b for a, b in zip(self.q, self.qd)), sp.Integer(0)) + \
            sum((sp.diff(expr, a) * b for a, b in zip(self.qd, self.qdd)), sp.Integer(0))


class Geometry:
    """Symbolic positions of the engine's points."""

    def __init__(self, S: Symbols, C: Coords, bodies: list):
        self.S, self.C, self.bodies = S, C, bodies
        self.lengths: dict = {}
        self.radii: dict = {}

    def rod_length(self, b):
        if b.name not in self.lengths:
            self.lengths[b.name] = self.S.param("L", "L", b.name, b.length)
        return self.lengths[b.name]

    def radius(self, b):
        if b.name not in self.radii:
            self.radii[b.name] = self.S.param("r", "r", b.name, b.radius)
        return self.radii[b.name]

    def offset(self, P):
        """p on the body's e'1, e'2: a rod's ends ±L/2, a named point exactly."""
        b = P.body
        if b.shape == "rod" and P.p[1] == 0 and abs(abs(P.p[0]) - b.length / 2) <= 1e-15 * b.length:
            return (sp.sign(P.p[0]) * self.rod_length(b) / 2, sp.Integer(0))
        return (exact(P.p[0]), exact(P.p[1]))

    def pos(self, P):
        if P.body is None:
            return sp.Matrix([exact(P.p[0]), exact(P.p[1])])
        i = P.body.index
        x = sp.Matrix([self.C.q[i[0]], self.C.q[i[1]]])
        if not P.turns_with_body:
            return x
        p1, p2 = self.offset(P)
        th = self.C.q[i[2]]
        return x + sp.Matrix([sp.cos(th) * p1 - sp.sin(th) * p2, sp.sin(th) * p1 + sp.cos(th) * p2])

    def centre(self, b):
        i = b.index
        return sp.Matrix([self.C.q[i[0]], self.C.q[i[1]]])


def vec(a) -> "sp.Matrix":
    """A direction or point: a component that is rounding beside the other (cos 90°) is 0."""
    big = max(abs(float(a[0])), abs(float(a[1])))
    return sp.Matrix([exact(c) if abs(float(c)) > 1e-14 * big else sp.Integer(0) for c in (a[0], a[1])])


def _signed_radius(G: Geometry, b, k: float):
    return G.radius(b) * (1 if k > 0 else -1) if abs(abs(k) - b.radius) <= 1e-12 * b.radius else exact(k)


def _turning_length(seg, G: Geometry):
    """A turning segment's part of its cord (elements.Turning): √(D² − ρ²) + c (ψ − ψ0), d the
    vector from the end point to the pulley's centre (or back), ψ = angle(d) − asin(δ/D) its
    direction (δ = ±ρ), c = ±ρ the arc's sign; √D for a point pulley.  Over a disk on a fixed
    axle: its centre's coordinates and radius as symbols, less c (θ − θ0), the disk's turn."""
    import math

    t = seg.turning
    disk = seg.pulley[3] if seg.pulley is not None and t.angle is not None else None
    pos = G.pos(seg.point())
    C = G.centre(disk) if disk is not None else vec(t.C)    # a disk's centre: its axle's reaction
    d = pos - C if t.end == "b" else C - pos
    D2 = d[0] ** 2 + d[1] ** 2
    if not t.rho:
        return sp.sqrt(D2)
    rho = _signed_radius(G, disk, t.rho) if disk is not None else exact(t.rho)
    c = _signed_radius(G, disk, t.c) if disk is not None else exact(t.c)
    delta = rho if t.end == "b" else -rho
    psi = sp.atan2(d[1], d[0]) - sp.asin(delta / sp.sqrt(D2))
    psi0 = t.alpha0 - math.copysign(math.pi / 2, t.rho)
    total = sp.sqrt(D2 - rho ** 2) + c * (psi - exact(psi0))
    if disk is not None:                # the disk turns under the cord (no slip): −c (θ − θ0)
        total -= c * (G.C.q[t.angle] - exact(t.theta0))
    return total


def _spanning_length(seg, G: Geometry):
    """A segment that turns with both its ends (elements.Spanning): ℓ + (ρ_b − ρ_a)(ψ − ψ0)
    − ρ_b (θ_b − θ_b0) + ρ_a (θ_a − θ_a0), with d = X_b − X_a, ℓ = √(|d|² − (ρ_a − ρ_b)²) and
    ψ = angle(d) − asin((ρ_a − ρ_b)/|d|); a disk's radius is its symbol."""
    t = seg.spanning
    ends = []
    for P, rho, k in ((t.A, t.ra, t.angle_a), (t.B, t.rb, t.angle_b)):
        b = P.body
        r = _signed_radius(G, b, rho) if (b is not None and b.radius and k is not None) else exact(rho)
        ends.append((G.pos(P), r, k))
    (Xa, ra, ka), (Xb, rb, kb) = ends
    d = Xb - Xa
    D2 = d[0] ** 2 + d[1] ** 2
    delta = ra - rb
    total = sp.sqrt(D2 - delta ** 2)
    if t.ra != t.rb:
        psi = sp.atan2(d[1], d[0]) - sp.asin(delta / sp.sqrt(D2))
        total += (rb - ra) * (psi - exact(t.psi0))
    if kb is not None:
        total -= rb * (G.C.q[kb] - exact(t.th0b))
    if ka is not None:
        total += ra * (G.C.q[ka] - exact(t.th0a))
    return total


def _cord(e, G: Geometry, S: Symbols):
    """Rows Σ u·(X_b − X_a) = const per run; λ = −T per run (a string between two points: its
    length |r_b − r_a| = const, as a link's)."""
    if hasattr(e, "ends"):
        b, a = e.ends()
        d = G.pos(b) - G.pos(a)
        T = S.force("T", e.name, "")
        return [sp.sqrt(d[0] ** 2 + d[1] ** 2) - exact(e.consts[0])], [-T], [T]
    phis, tens = [], []
    for r, run in enumerate(e.runs):
        total = sp.Integer(0)
        for seg in run:
            if seg.spanning is not None:
                total += _spanning_length(seg, G)
                continue
            if seg.turning is not None:
                total += _turning_length(seg, G)
                continue
            u = vec(seg.u)
            for end, sgn in ((seg.b, 1), (seg.a, -1)):
                if end.point is not None:
                    total += sgn * (u.T * G.pos(end.point))[0]
                elif end.centre is not None:
                    b = end.centre.body
                    total += sgn * ((u.T * G.centre(b))[0] + _signed_radius(G, b, end.k) * G.C.q[b.index[2]])
        phis.append(total - exact(e.consts[r]))
        tens.append(S.force("T", e.name, str(r + 1) if len(e.runs) > 1 else ""))
    return phis, [-T for T in tens], tens


class CarriedFrame:
    """A straight line carried by a body W (carried.py): its direction d̂ = Q(θ_W) d̂ₗ and normal
    n = e3 × d̂ turned with W, and for a point r the gap n·(r − x_W) − n_l·o and the place along
    it d̂·(r − x_W) − d̂ₗ·o (from the line's origin on W)."""

    def __init__(self, surface, G: Geometry):
        W = surface.body
        self.W, self.C = W, G.C
        self.theta = G.C.q[W.index[2]] if W.rigid else sp.Integer(0)
        c, s = sp.cos(self.theta), sp.sin(self.theta)
        dl = vec(surface.dl)
        o1, o2 = exact(surface.o[0]), exact(surface.o[1])
        self.d = sp.Matrix([c * dl[0] - s * dl[1], s * dl[0] + c * dl[1]])
        self.n = sp.Matrix([-self.d[1], self.d[0]])
        self.cn, self.cd = -dl[1] * o1 + dl[0] * o2, dl[0] * o1 + dl[1] * o2
        self.x = G.centre(W)

    def gap(self, r):
        return (self.n.T * (r - self.x))[0] - self.cn

    def along(self, r):
        return (self.d.T * (r - self.x))[0] - self.cd

    def turned(self, b):
        """θ_B − θ_W: the rigid body b's turn relative to the carrier."""
        return self.C.q[b.index[2]] - self.theta


def _carried_rows(e, G: Geometry, S: Symbols):
    """The rows of a contact, slider or rolling body on a carried line (carried.py): the gap (N
    along n on the point, −N on W), a slider's turn relative to W (M), a rolling body's
    no-slip over W's material point s + R (θ_B − θ_W) = const (F)."""
    k, L = e.kind, CarriedFrame(e.surface, G)
    if k == "contact":
        N = S.force("N", e.name)
        if not e.rough:
            return [L.gap(G.pos(e.P))], [N], [N], None
        F = S.force("F", e.name)
        return [L.gap(G.pos(e.P))], [N], [N, F], (F, N, e)
    if k == "slider":
        N = S.force("N", e.name)
        rows = [L.gap(G.pos(e.P)) - exact(e.c0)]
        if e.dtheta is None:
            return rows, [N], [N], None
        M = S.force("M", e.name)
        return rows + [L.turned(e.P.body) - exact(e.dtheta)], [N, M], [N, M], None
    if k == "rolls":
        N, F = S.force("N", e.name), S.force("F", e.name)
        b = e.body_point.body
        x = G.centre(b)
        return [L.gap(x) - G.radius(b), L.along(x) + G.radius(b) * L.turned(b) - exact(e.c0)], [N, F], [N, F], None
    raise ValueError(f"the {k} {e.name!r} on {e.surface.name!r}, a surface carried by {e.surface.body.name!r}, has no "
                     "symbolic form in this release")


def element_rows(e, G: Geometry, S: Symbols, drive_expr=None):
    """(rows φ, multipliers λ in the joint forces, the force symbols, friction load or None)."""
    k, C = e.kind, G.C
    if getattr(getattr(e, "surface", None), "carried", False):
        return _carried_rows(e, G, S)
    if k == "pin":
        R1, R2 = S.force("R", e.name, "1"), S.force("R", e.name, "2")
        return list(G.pos(e.P) - G.pos(e.Q)), [R1, R2], [R1, R2], None
    if k == "slider":
        N = S.force("N", e.name)
        rows = [(vec(e.surface.n).T * G.pos(e.body_point))[0] - exact(e.c0)]
        if e.theta0 is None:
            return rows, [N], [N], None
        M = S.force("M", e.name)
        return rows + [C.q[e.body_point.body.index[2]] - exact(e.theta0)], [N, M], [N, M], None
    if k == "contact":
        N = S.force("N", e.name)
        rows = [(vec(e.surface.n).T * (G.pos(e.P) - vec(e.surface.origin)))[0]]
        if not e.rough:
            return rows, [N], [N], None
        F = S.force("F", e.name)
        return rows, [N], [N, F], (F, N, e)
    if k == "rolls":
        N, F = S.force("N", e.name), S.force("F", e.name)
        b = e.body_point.body
        x = G.centre(b)
        return [(vec(e.surface.n).T * (x - vec(e.surface.origin)))[0] - G.radius(b),
                (vec(e.surface.d).T * x)[0] + G.radius(b) * C.q[b.index[2]] - exact(e.c0)], [N, F], [N, F], None
    if k == "link":
        T = S.force("T", e.name)
        d = G.pos(e.P) - G.pos(e.Q)
        return [sp.sqrt(d[0] ** 2 + d[1] ** 2) - exact(e.L)], [-T], [T], None
    if k == "drive":
        letter = "M" if any(b.rigid and b.index[2] == e.index for b in G.bodies) else "F"
        D = S.force(letter, e.name)
        return [C.q[e.index] - drive_expr], [D], [D], None
    if k == "cord":
        phis, lams, tens = _cord(e, G, S)
        return phis, lams, tens, None
    if k == "gear" and hasattr(e, "d"):            # a gear on a fixed rack: d̂·x + R θ = c0
        F = S.force("F", e.name)
        x = G.centre(e.body)
        return [(vec(e.d).T * x)[0] + exact(e.R) * C.q[e.body.index[2]] - exact(e.c0)], [F], [F], None
    if k == "gear":
        F = S.force("F", e.name)
        d = G.centre(e.B) - G.centre(e.A)
        return [exact(e.RA) * C.q[e.A.index[2]] + exact(e.s * e.RB) * C.q[e.B.index[2]]
                - exact(e.D) * sp.atan2(d[1], d[0]) - exact(e.c0)], [F], [F], None
    if k == "guide":
        owner = e.name.split(":")[0] + "," + e.P.body.name
        N = S.new(f"N_{owner}", f"N_{owner}", f"N_{{{_tex_name(e.name.split(':')[0])},{_tex_name(e.P.body.name)}}}")
        return [(vec(e.w).T * G.pos(e.P))[0] - exact(e.c0)], [N], [N], None
    raise ValueError(f"no symbolic form for a {k} joint")  # pragma: no cover - every engine element is above


#: entries with more operations than this skip trigsimp (seconds on long entries)
SIMPLIFY_MAX_OPS = 80


@dataclass
class Eq:
    label: str
    lhs: object
    rhs: object
    rel: str = "="
    terms: list | None = None       # the left side as (coefficient, symbol) pairs: printed coefficient first


def tidy(x):
    """A bounded, readable simplification (:func:`dyncli.symbolic.shortest`)."""
    from dyncli.symbolic import shortest

    return shortest(x, SIMPLIFY_MAX_OPS)


def numeric_jacobian(rows, C, values: dict, q0) -> np.ndarray:
    """J = ∂φ/∂q at the state q0 with the symbols' values (floats)."""
    sub = {**values, **{q: float(x) for q, x in zip(C.q, q0)}}
    J = sp.Matrix(rows).jacobian(C.q) if rows else sp.zeros(0, len(C.q))
    return np.array(J.subs(sub).evalf(), dtype=float) if rows else np.zeros((0, len(C.q)))
