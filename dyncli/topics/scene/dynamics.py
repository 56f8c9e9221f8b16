"""The equations of motion of a scene in maximal coordinates, one linear solve per evaluation.

    [ M   −Jᵀ − Φ ] [ q̈ ]   [ f(q, q̇, t) ]
    [ J      0    ] [ λ ] = [ γ(q, q̇, t) ]

M is diagonal (m, m, Ī₃₃ per rigid body: 16.7, 29.5, 32.15), f the applied loads (gravity −g e2,
springs, dampers, forces, couples) as generalized forces, J the joints' rows, γ = −J̇q̇ − φ_tt,
and Φ the columns of kinetic friction (−μ_k N sign d̂ at a sliding contact: a force
proportional to that contact's own multiplier).  The multipliers λ are the joint forces.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from dyncli.errors import NumericalError

from .contacts import Contact, Rolls
from .elements import Element, Pin, PinBlock
from .system import BodyData, Point, Stack

EPS = float(np.finfo(float).eps)
#: the most joint rows solved by the Schur complement in plain floats (:func:`schur_solve`; three
#: only with the complement symmetric): beyond them LAPACK's LU of the whole matrix is cheaper
#: (measured, docs/accuracy.md)
SCHUR_ROWS = 3
#: a pivot of the Schur complement below this part of its row's largest entry (the rows close
#: to dependent: the complement's rounding ~ ε/PIVOT) sends the solve to the LU of the whole matrix
PIVOT = 2.0 ** -10


def schur_solve(minv: list, rows: list, cols: list, f: list, gam: list) -> tuple[list, list] | None:
    """(q̈, λ) of M q̈ = f + Σ_k cols_k λ_k, rows q̈ = γ (M = diag(1/minv); at most SCHUR_ROWS
    rows), in plain floats: λ from the Schur complement (:func:`complement_solve`)
    W λ = γ − rows M⁻¹ f, then q̈ = M⁻¹ f + Σ_k (M⁻¹ cols_k) λ_k.  ``cols``: the rows themselves,
    or with a sliding contact's friction column added to its normal row (−Jᵀ − Φ of the whole
    matrix).  None where the complement is close to singular."""
    mul = operator.mul
    Mf = list(map(mul, minv, f))
    if not rows:
        return Mf, []
    if len(rows) == 1 or cols is rows and len(rows) <= 3:
        return _symmetric_solve(minv, rows, cols[0], Mf, gam)
    got = complement_solve(minv, rows, cols, [g - sum(map(mul, Ji, Mf)) for Ji, g in zip(rows, gam)])
    if got is None:
        return None
    lam, Y = got
    if len(lam) == 1:
        l0, = lam
        return [x + l0 * y for x, y in zip(Mf, Y[0])], lam
    if len(lam) == 2:
        l0, l1 = lam
        return [x + l0 * y0 + l1 * y1 for x, y0, y1 in zip(Mf, *Y)], lam
    l0, l1, l2 = lam
    return [x + l0 * y0 + l1 * y1 + l2 * y2 for x, y0, y1, y2 in zip(Mf, *Y)], lam


def _symmetric_solve(minv: list, rows: list, c0: list, Mf: list, gam: list) -> tuple[list, list] | None:
    """:func:`schur_solve` where the complement is symmetric (``cols is rows``; one row: its column
    ``c0``), its steps written out: the operations of :func:`complement_solve` and schur_solve's in
    the same order (the same doubles), without their intermediate lists (a solve per evaluation of
    the right-hand side: most of its cost)."""
    mul = operator.mul
    if len(rows) == 1:
        J0, = rows
        Y0 = list(map(mul, minv, c0))
        w = sum(map(mul, J0, Y0))
        if not (w != 0 and math.isfinite(w)):
            return None
        l0 = (gam[0] - sum(map(mul, J0, Mf))) / w
        return [x + l0 * y for x, y in zip(Mf, Y0)], [l0]
    if len(rows) == 2:
        J0, J1 = rows
        r0, r1 = gam[0] - sum(map(mul, J0, Mf)), gam[1] - sum(map(mul, J1, Mf))
        Y0, Y1 = list(map(mul, minv, J0)), list(map(mul, minv, J1))
        got2 = ldl2(sum(map(mul, J0, Y0)), sum(map(mul, J0, Y1)), sum(map(mul, J1, Y1)), r0, r1)
        if got2 is None:
            return None
        l0, l1 = got2
        return [x + l0 * y0 + l1 * y1 for x, y0, y1 in zip(Mf, Y0, Y1)], [l0, l1]
    J0, J1, J2 = rows
    r0, r1, r2 = (gam[0] - sum(map(mul, J0, Mf)), gam[1] - sum(map(mul, J1, Mf)),
                  gam[2] - sum(map(mul, J2, Mf)))
    Y0, Y1, Y2 = list(map(mul, minv, J0)), list(map(mul, minv, J1)), list(map(mul, minv, J2))
    got3 = ldl3(sum(map(mul, J0, Y0)), sum(map(mul, J0, Y1)), sum(map(mul, J0, Y2)),
                sum(map(mul, J1, Y1)), sum(map(mul, J1, Y2)), sum(map(mul, J2, Y2)), r0, r1, r2)
    if got3 is None:
        return None
    l0, l1, l2 = got3
    return [x + l0 * y0 + l1 * y1 + l2 * y2 for x, y0, y1, y2 in zip(Mf, Y0, Y1, Y2)], [l0, l1, l2]


def ldl2(w00: float, w01: float, w11: float, r0: float, r1: float) -> tuple[float, float] | None:
    """x of the symmetric [[w00, w01], [w01, w11]] x = r by W = L D Lᵀ (d0 = w00, l = w01/w00,
    d1 = w11 − l w01); None when a pivot is below PIVOT of its row's largest entry."""
    a01 = abs(w01)
    if not w00 > PIVOT * max(w00, a01):
        return None
    el = w01 / w00
    d1 = w11 - el * w01
    if not d1 > PIVOT * max(w11, a01):
        return None
    x1 = (r1 - el * r0) / d1
    return r0 / w00 - el * x1, x1


def ldl3(w00: float, w01: float, w02: float, w11: float, w12: float, w22: float,
         r0: float, r1: float, r2: float) -> tuple[float, float, float] | None:
    """x of the symmetric 3 × 3 W x = r by W = L D Lᵀ written out; None as :func:`ldl2`."""
    a01, a02, a12 = abs(w01), abs(w02), abs(w12)
    if not w00 > PIVOT * max(w00, a01, a02):
        return None
    l10, l20 = w01 / w00, w02 / w00
    d1 = w11 - l10 * w01
    if not d1 > PIVOT * max(w11, a01, a12):
        return None
    u21 = w12 - l20 * w01
    l21 = u21 / d1
    d2 = w22 - l20 * w02 - l21 * u21
    if not d2 > PIVOT * max(w22, a02, a12):
        return None
    z1 = r1 - l10 * r0
    x2 = (r2 - l20 * r0 - l21 * z1) / d2
    x1 = z1 / d1 - l21 * x2
    return r0 / w00 - l10 * x1 - l20 * x2, x1, x2


def complement_solve(minv: list, rows: list, cols: list, r: list) -> tuple[list, list] | None:
    """(x, Y) of W x = r, W = rows diag(minv) colsᵀ (one to three rows; Y = the lists minv ⊙ cols_k),
    in plain floats: ``cols is rows`` (W symmetric positive definite) by W = L D Lᵀ, else (one or
    two rows) by Gaussian elimination with partial pivoting.  None when a pivot is below PIVOT of
    its row's largest entry of W (rows close to dependent, singular, or not finite), or for three
    rows that are not symmetric."""
    mul = operator.mul
    if len(rows) == 3:              # L D Lᵀ written out (symmetric only: else the whole matrix's LU)
        if cols is not rows:
            return None
        (J0, J1, J2), Y = rows, [list(map(mul, minv, c)) for c in rows]
        Y0, Y1, Y2 = Y
        got3 = ldl3(sum(map(mul, J0, Y0)), sum(map(mul, J0, Y1)), sum(map(mul, J0, Y2)),
                    sum(map(mul, J1, Y1)), sum(map(mul, J1, Y2)), sum(map(mul, J2, Y2)), *r)
        return None if got3 is None else (list(got3), Y)
    if len(rows) == 1:
        Y0 = list(map(mul, minv, cols[0]))
        w = sum(map(mul, rows[0], Y0))
        if not (w != 0 and math.isfinite(w)):
            return None
        return [r[0] / w], [Y0]
    (J0, J1), (C0, C1) = rows, cols
    Y0, Y1 = list(map(mul, minv, C0)), list(map(mul, minv, C1))
    w00, w01, w11 = sum(map(mul, J0, Y0)), sum(map(mul, J0, Y1)), sum(map(mul, J1, Y1))
    r0, r1 = r
    if cols is rows:                # L D Lᵀ
        got2 = ldl2(w00, w01, w11, r0, r1)
        return None if got2 is None else (list(got2), [Y0, Y1])
    got = solve2(w00, w01, sum(map(mul, J1, Y0)), w11, r0, r1)
    return None if got is None else (list(got), [Y0, Y1])


def solve2(a: float, b: float, c: float, d: float, r0: float, r1: float) -> tuple[float, float] | None:
    """x of [[a, b], [c, d]] x = (r0, r1) by Gaussian elimination with partial pivoting; None
    when a pivot is below PIVOT of its row's largest entry (or not finite)."""
    if abs(c) > abs(a):             # the pivot row first
        a, b, c, d, r0, r1 = c, d, a, b, r1, r0
    if not abs(a) > PIVOT * max(abs(a), abs(b)):
        return None
    k = c / a
    p = d - k * b
    if not abs(p) > PIVOT * max(abs(c), abs(d)):
        return None
    x1 = (r1 - k * r0) / p
    return (r0 - b * x1) / a, x1


def _dot(a, b) -> float:
    """Σ a_k b_k of two sequences of floats (lists: no array made)."""
    return float(sum(map(operator.mul, a, b)))


def _uses_off_centre(item, bodies) -> bool:
    """Whether a joint or load reads the angle of one of ``bodies`` through what it holds: a
    point of it off its centre, a surface it carries, a torque or a wound string on it (its
    attributes and the lists among them, one level down)."""
    ids = {id(b) for b in bodies}
    values = list(vars(item).values())
    for v in list(values):
        if isinstance(v, (list, tuple)):
            values += [x for x in v if hasattr(x, "__dict__")]
    for v in values:
        if isinstance(v, Point) and v.body is not None and id(v.body) in ids and (v.p[0] or v.p[1]):
            return True
        if id(getattr(v, "body", None)) in ids and not isinstance(v, Point):
            return True                 # a surface carried by it
    if isinstance(item, Load) and item.body is not None and id(item.body) in ids:
        return item.kind == "torque" or item.wound is not None
    return False


@dataclass
class Load:
    """An applied element: spring, damper, force or torque (``name`` reported as force.NAME)."""

    kind: str
    name: str | None
    P: Point | None = None
    Q: Point | None = None
    k: float = 0.0
    L: float = 0.0
    one_sided: str | None = None
    c: float = 0.0
    F: Callable[[float], tuple[float, float]] | None = None    # t -> (F1, F2)
    M: Callable[[float], float] | None = None                  # t -> M
    body: BodyData | None = None
    constant: bool = True   # F or M does not depend on t
    #: a force through a string wound on P's body: the signed radius ρ (+r: the string leaves
    #: from the left of F̂, seen from the body, at ρ e3 × F̂ from the centre), so the force's line
    #: stays tangent to the circle: F on the centre and the couple (ρ e3 × F̂) × F = −ρ |F| e3
    wound: float | None = None
    mode: str | None = None     # a one-sided spring held "on" or "off" for an ODE phase (else by sign)

    def _ends(self) -> tuple[Point, Point]:
        assert self.P is not None and self.Q is not None, "a spring or damper has two ends"
        return self.P, self.Q

    def _d(self, q) -> tuple[float, float, float]:
        P, Q = self._ends()
        (p1, p2), (q1, q2) = P.xy(q), Q.xy(q)
        d1, d2 = p1 - q1, p2 - q2
        return d1, d2, math.hypot(d1, d2)

    def ties(self, axis: int) -> bool:
        """Whether it ties the scene to the ground along e_axis: a spring or damper to a ground
        point, a force with a component along it (or one that changes in time)."""
        if self.kind in ("spring", "damper"):
            return self.P is None or self.Q is None or self.P.body is None or self.Q.body is None
        if self.kind == "force":
            return not (self.constant and self.F is not None and self.F(0.0)[axis] == 0)
        return False

    def spring_tension(self, q) -> float:
        return self._tension(self._d(q)[2])

    def _tension(self, ln: float) -> float:
        T = self.k * (ln - self.L)
        if self.mode is not None:       # held for an ODE phase: smooth across its switch
            return T if self.mode == "on" else 0.0
        if self.one_sided == "compression" and T > 0 or self.one_sided == "tension" and T < 0:
            return 0.0
        return T

    def hold_mode(self, q, v) -> None:
        """A one-sided spring's state for one phase of the ODE route: on or off as at (q, v) (at
        its free length, as its stretch rate takes it), kept through the phase, so that a step
        across the switch integrates the phase's own smooth equations — read by sign, a step
        that straddles it bends the interpolant the switch is then located on (two carts and a
        bumper: the spring came on 0.02 s early, 1 % of the energy lost).  The phase ends at the
        switch (the watch "switch"), and the next one holds the other state."""
        P, Q = self._ends()
        d1, d2, ln = self._d(q)
        s = ln - self.L
        if abs(s) <= 1e-12 * max(ln, self.L) and ln > 0:
            (pv1, pv2), (qv1, qv2) = P.vel_xy(q, v), Q.vel_xy(q, v)
            s = (d1 * (pv1 - qv1) + d2 * (pv2 - qv2)) / ln
        self.mode = "on" if (s < 0 if self.one_sided == "compression" else s > 0) else "off"

    def stretch(self, q) -> float:
        return self._d(q)[2] - self.L

    def generalized(self, q, v, t, n: int) -> tuple[np.ndarray, float, object]:
        """(generalized force, its power if non-conservative else 0, the reported value)."""
        g, power, value = self.generalized_list(q, v, t, n)
        return np.array(g, dtype=float), power, value

    def generalized_list(self, q, v, t, n: int) -> tuple[list, float, object]:
        """:meth:`generalized` with the force a list of n floats (q, v: lists or arrays)."""
        if self.kind in ("spring", "damper"):
            d1, d2, ln = self._d(q)
            if ln == 0:
                raise NumericalError(f"the ends of {self.label} coincide: its direction is undefined")
            e1, e2 = d1 / ln, d2 / ln
            P, Q = self._ends()
            if self.kind == "spring":
                T = self._tension(ln)
            else:
                (pv1, pv2), (qv1, qv2) = P.vel_xy(q, v), Q.vel_xy(q, v)
                T = self.c * (e1 * (pv1 - qv1) + e2 * (pv2 - qv2))
            g = [0.0] * n                         # −T e·∂(r_P − r_Q)/∂q
            P.add_jac(g, q, -T * e1, -T * e2)
            Q.add_jac(g, q, T * e1, T * e2)
            return g, (0.0 if self.kind == "spring" else _dot(g, v)), T
        g = [0.0] * n
        if self.kind == "force":
            assert self.P is not None and self.F is not None, "a force has its point and its F(t)"
            F1, F2 = (float(c) for c in self.F(t))
            self.P.add_jac(g, q, F1, F2)
            if self.wound is not None:
                assert self.P.body is not None, "a wound string's body"
                g[self.P.body.index[2]] -= self.wound * math.hypot(F1, F2)
            return g, _dot(g, v), [F1, F2, 0.0]
        assert self.body is not None and self.M is not None, "a torque has its body and its M(t)"
        M = float(self.M(t))
        g[self.body.index[2]] = M
        return g, M * float(v[self.body.index[2]]), M

    @property
    def label(self) -> str:
        return f"the {self.kind}" + (f" {self.name!r}" if self.name else "")


@dataclass
class SceneSystem:
    bodies: list[BodyData]
    elements: list[Element]
    loads: list[Load]
    g: float
    n: int
    names: list[str] = field(default_factory=list)     # coordinate names, e.g. "x.A.0", "angle.rod"

    def __post_init__(self):
        m = np.zeros(self.n)
        for b in self.bodies:
            m[b.index[0]] = m[b.index[1]] = b.mass
            if b.rigid:
                m[b.index[2]] = b.inertia
        self.mass = m
        self._weights = None
        self._winv = None               # 1 / weights() as a list (the projections in plain floats)
        self._pin_block = None          # (the elements' rows, their PinBlock) for the stacked forms
        self.linsolve = np.linalg.solve
        self.grav = np.zeros(self.n)
        for b in self.bodies:
            self.grav[b.index[1]] = -b.mass * self.g
        self._grav_list = self.grav.tolist()
        # the small solves in plain floats (:meth:`solve_lists`): every mass and inertia positive
        minv = [1.0 / x if x > 0 else math.inf for x in m.tolist()]
        self._minv = minv if all(map(math.isfinite, minv)) else None
        self._offsets()

    def use_lapack(self) -> None:
        """Solve the KKT systems by LAPACK's dgesv directly (the same LU with partial pivoting as
        ``numpy.linalg.solve``, without its wrapper's cost: a quarter of a small solve): for the
        ODE route, which has scipy loaded already (the closed forms stay numpy-only)."""
        from scipy.linalg.lapack import dgesv

        def linsolve(A, b):
            x, info = dgesv(A, b)[2:]
            if info != 0:
                raise np.linalg.LinAlgError("singular matrix")
            return x
        self.linsolve = linsolve

    def _groups(self) -> None:
        """The groups of rough contacts held together (contacts.py, mode "shared"): a member
        whose holder no longer sticks follows it — sliding with it, or (the holder released or
        gone) the first member holds the group's row itself; each group's μ_s on its contacts
        (the holder's first) and, for :meth:`lam_of`, the rows of ΣF and every N."""
        named = {e.name: e for e in self.elements if isinstance(e, Contact)}
        members: dict[str, list[Contact]] = {}
        for e in named.values():
            e.group_mu = ()
            if e.mode == "shared" and e.holder is not None:
                members.setdefault(e.holder, []).append(e)
        self._held = []
        for name, ms in members.items():
            h = named.get(name)
            if h is not None and h.mode == "slide":
                for e in ms:
                    e.mode, e.sign, e.holder = "slide", h.sign, None
                continue
            if h is None or h.mode != "stick":
                h, ms = ms[0], ms[1:]
                h.mode, h.holder = "stick", None
                for e in ms:
                    e.holder = h.name
            if ms:
                group = [h] + ms
                mus = tuple(float(e.mu_s) for e in group)
                for e in group:
                    e.group_mu = mus
                self._held.append(group)            # (their rows, once the offsets are known)

    def _offsets(self):
        self._held: list[list[Contact]] = []
        self._ext: dict[int, list[int]] = {}
        if any(isinstance(e, Contact) and (e.mode == "shared" or e.group_mu) for e in self.elements):
            self._groups()
        self.offsets, k = [], 0
        for e in self.elements:
            self.offsets.append(k)
            k += e.rows
        self.m = k
        # the solve's fixed parts, rebuilt with the rows: the matrix with M on its diagonal (copied
        # per solve), the elements with friction columns, the drives (their power)
        n = self.n
        self._template = np.zeros((n + k, n + k))
        self._template[:n, :n] = np.diag(self.mass)
        self._friction = [i for i, e in enumerate(self.elements) if isinstance(e, (Contact, Rolls))]
        self._drives = [i for i, e in enumerate(self.elements) if e.kind == "drive"]
        # whether an element's watch reads its multipliers in the current phases (motion.watches:
        # else no multiplier is solved for)
        self.watching = any(e.reads_forces() for e in self.elements)
        if self._held:                  # each grouped contact's extra multipliers: ΣF, then every N
            index = {id(e): i for i, e in enumerate(self.elements)}
            for group in self._held:
                h = index[id(group[0])]
                rows = [self.offsets[h] + 1] + [self.offsets[index[id(e)]] for e in group]
                for e in group:
                    self._ext[index[id(e)]] = rows

    def refresh(self):
        """Recompute the row offsets after an element changed its rows (a contact's mode)."""
        self._offsets()

    # ------------------------------------------------------------------ rows
    # φ, J and γ are built in plain floats element by element (Element.*_list: numpy's cost per
    # small array would be most of the work) and made arrays once
    def phi(self, q, t) -> np.ndarray:
        ql, out = q.tolist(), []
        for e in self.elements:
            out += e.phi_list(ql, t)
        return np.array(out, dtype=float)

    def jac(self, q) -> np.ndarray:
        return self._jac(q.tolist())

    def _jac(self, ql) -> np.ndarray:
        rows = []
        for e in self.elements:
            if e.rows:
                rows += e.jac_list(ql)
        return np.array(rows, dtype=float).reshape(len(rows), self.n)

    def gamma(self, q, v, t) -> np.ndarray:
        return np.array(self._gamma(q.tolist(), v.tolist(), t), dtype=float)

    def _gamma(self, ql, vl, t) -> list:
        out = []
        for e in self.elements:
            if e.rows:
                out += e.gamma_list(ql, vl, t)
        return out

    def phi_t(self, t) -> np.ndarray:
        out = []
        for e in self.elements:
            out += e.phi_t_list(t)
        return np.array(out, dtype=float)

    # the rows at many states at once (X: a system.Stack of k states, V: (k, n), ``td``: from
    # :meth:`at_times`): the same numbers as the one-state forms above, row by row
    def stack(self, Q) -> Stack:
        """The states Q (k, n) for the forms below (their trigonometry computed once)."""
        return Stack(Q)

    def at_times(self, T) -> list:
        """Each element's data at the times T (a drive's f(t)): ``td`` of the forms below."""
        return [e.at_times(T) for e in self.elements]

    def _pins(self):
        """The PinBlock of the current rows (None without pins or where it cannot be one block)."""
        rows = tuple(e.rows for e in self.elements)
        if self._pin_block is None or self._pin_block[0] != rows:
            pins, offsets, o = [], [], 0
            for e, r in zip(self.elements, rows):
                if isinstance(e, Pin):
                    pins.append(e)
                    offsets.append(o)
                o += r
            block = PinBlock(pins, offsets) if pins else None
            self._pin_block = (rows, block if block is not None and block.ok else None)
        return self._pin_block[1]

    def phi_many(self, X, td) -> np.ndarray:
        block = self._pins()
        out = np.empty((X.k, sum(e.rows for e in self.elements)))
        o = 0
        for e, d in zip(self.elements, td):
            if e.rows and (block is None or id(e) not in block.members):
                out[:, o:o + e.rows] = e.phi_many(X, d)
            o += e.rows
        if block is not None:
            out[:, block.rows0], out[:, block.rows0 + 1] = block.phi(X.Q)
        return out

    def jac_many(self, X) -> np.ndarray:
        block = self._pins()
        rows = [e.rows for e in self.elements]
        J = np.zeros((X.k, sum(rows), self.n))
        o = 0
        for e, r in zip(self.elements, rows):
            if r and (block is None or id(e) not in block.members):
                e.jac_many(X, J[:, o:o + r])
            o += r
        if block is not None:
            block.jac(X.Q, J)
        return J

    def gamma_many(self, X, V, td) -> np.ndarray:
        block = self._pins()
        out = np.empty((X.k, sum(e.rows for e in self.elements)))
        o = 0
        for e, d in zip(self.elements, td):
            if e.rows and (block is None or id(e) not in block.members):
                out[:, o:o + e.rows] = e.gamma_many(X, V, d)
            o += e.rows
        if block is not None:
            out[:, block.rows0], out[:, block.rows0 + 1] = block.gamma(X.Q, V)
        return out

    def phi_t_many(self, td) -> np.ndarray:
        return np.concatenate([e.phi_t_many(d) for e, d in zip(self.elements, td)], axis=1)

    def lam_of(self, lam, i: int):
        """The multipliers of element i (a grouped contact's followed by its group's: ΣF and every
        N, the holder's first; contacts.py)."""
        o = self.offsets[i]
        own = lam[o:o + self.elements[i].rows]
        if self._ext and i in self._ext:
            more = [lam[k] for k in self._ext[i]]
            return own + more if isinstance(own, list) else np.concatenate([own, np.asarray(more, dtype=float)])
        return own

    # ------------------------------------------------------------------ loads
    def applied(self, q, v, t) -> tuple[np.ndarray, float]:
        """Generalized applied force and the power of the non-conservative loads."""
        f, power = self.applied_list(q, v, t)
        return np.array(f, dtype=float), power

    def applied_list(self, q, v, t) -> tuple[list, float]:
        """:meth:`applied` with the force a list of floats (q, v: lists or arrays)."""
        f = self._grav_list.copy()
        power = 0.0
        for ld in self.loads:
            g, p, _ = ld.generalized_list(q, v, t, self.n)
            f = [a + b for a, b in zip(f, g)]
            power += p
        return f, power

    # ------------------------------------------------------------------ the solve
    def kkt_matrix(self, q, J) -> np.ndarray:
        """[[M, −Jᵀ − friction columns], [J, 0]]: the matrix of the accelerations and multipliers
        (and, with velocity jumps and impulses for them, of an impact)."""
        n = self.n
        if self._template.shape[0] != n + J.shape[0]:     # an element changed its rows without a refresh
            self._offsets()
        A = self._template.copy()
        A[:n, n:] = -J.T
        A[n:, :n] = J
        for i in self._friction:
            col = self.elements[i].friction_column(q)
            if col is not None:
                A[:n, n + self.offsets[i]] -= col
        return A

    def solve(self, q, v, t) -> tuple[np.ndarray, np.ndarray, float]:
        """(q̈, λ, power of the non-conservative loads incl. friction)."""
        a, lam, power = self.solve_lists(q.tolist(), v.tolist(), t)
        return np.array(a, dtype=float), np.array(lam, dtype=float), power

    def solve_lists(self, q: list, v: list, t) -> tuple[list, list, float]:
        """:meth:`solve` in plain floats (q, v: lists; q̈ and λ lists).  A small system whose
        masses are all positive by the Schur complement of M (:func:`schur_solve`); a larger one,
        or one whose joint rows are close to dependent there, by the LU of the whole matrix
        (:meth:`kkt_matrix`, LAPACK)."""
        n = self.n
        f, power = self.applied_list(q, v, t)
        rows, gam = [], []
        for e in self.elements:
            if e.rows:
                r, g = e.kkt_lists(q, v, t)
                rows += r
                gam += g
        if len(rows) != self.m:         # an element changed its rows without a refresh
            self._offsets()
        got = None
        if self._minv is not None and len(rows) <= SCHUR_ROWS:
            got = schur_solve(self._minv, rows, self.force_columns(rows, q) if self._friction else rows, f, gam)
        if got is None:
            A = self.kkt_matrix(q, np.array(rows, dtype=float).reshape(len(rows), n))
            try:
                x = self.linsolve(A, np.array(f + gam, dtype=float))
            except np.linalg.LinAlgError:
                raise NumericalError(f"the equations of motion are singular at t = {t:.6g} s (a massless body with a "
                                     "free motion, or joints that lock each other)") from None
            x = x.tolist()
            got = x[:n], x[n:]
        a, lam = got
        return a, lam, (self._power(power, lam, q, v) if self._friction or self._drives else power)

    def force_columns(self, rows: list, q) -> list:
        """The generalized force per unit multiplier, row by row: the row itself, or with a
        sliding contact's friction column added (−Jᵀ − Φ of :meth:`kkt_matrix`); ``rows``
        itself when no friction column is active."""
        cols = rows
        for i in self._friction:
            col = self.elements[i].friction_column(q)
            if col is not None:     # the multiplier's force: (J_o + col)ᵀ λ_o
                o = self.offsets[i]
                cols = cols.copy() if cols is rows else cols
                cols[o] = [x + y for x, y in zip(rows[o], col.tolist())]
        return cols

    def _power(self, power: float, lam, q, v) -> float:
        """The applied loads' power plus the kinetic friction's and the drives'."""
        for i in self._friction:
            e = self.elements[i]
            if e.mode in ("slide", "slip") and e.mu_k:
                power += e.friction(self.lam_of(lam, i)) * e.slip_speed(q, v)
        for i in self._drives:
            power += float(self.lam_of(lam, i)[0]) * float(v[self.elements[i].index])
        return power

    def constant_matrix(self) -> bool:
        """Whether the matrix of :meth:`solve` is one over the current joint set (every made row
        linear: a constant Jacobian and constant friction columns), for :meth:`solve_many`."""
        return all(e.linear for e in self.elements if e.rows)

    def solve_many(self, states) -> list[tuple[np.ndarray, np.ndarray, float]]:
        """:meth:`solve` at many states [(q, v, t)] of a joint set whose matrix is the same at
        all of them (:meth:`constant_matrix`, or one q held): the right-hand sides stacked and
        solved in one call, each by the same LU as :meth:`solve` (equal to it bit for bit)."""
        n = self.n
        if self._minv is not None and self.m <= SCHUR_ROWS:
            got = self._schur_many(states)
            if got is not None:
                return got
        q0 = states[0][0]
        A = self.kkt_matrix(q0, self.jac(q0))
        R = np.empty((len(states), A.shape[0], 1))
        powers = []
        for k, (q, v, t) in enumerate(states):
            f, power = self.applied(q, v, t)
            R[k, :n, 0] = f
            R[k, n:, 0] = self.gamma(q, v, t)
            powers.append(power)
        try:
            if self.linsolve is np.linalg.solve:
                X = np.linalg.solve(np.broadcast_to(A, (len(states),) + A.shape), R)[:, :, 0]
            else:                       # LAPACK's own dgesv (the ODE route's): one call per state
                X = [self.linsolve(A, R[k, :, 0]) for k in range(len(states))]
        except np.linalg.LinAlgError:
            raise NumericalError(f"the equations of motion are singular at t = {states[0][2]:.6g} s (a massless body "
                                 "with a free motion, or joints that lock each other)") from None
        return [(x[:n], x[n:], self._power(P, x[n:], q, v)) for (q, v, _t), x, P in zip(states, X, powers)]

    def _schur_many(self, states) -> list | None:
        """:meth:`solve_many` by :func:`schur_solve` on columns: each state's force and γ a
        column entry (numpy's elementwise operations: the same doubles as the one-state lists,
        operation by operation); None where the complement is close to singular."""
        q0, v0, t0 = states[0]
        ql0, vl0 = q0.tolist(), v0.tolist()
        rows = []
        for e in self.elements:
            if e.rows:
                rows += e.kkt_lists(ql0, vl0, t0)[0]
        F, G, powers = [], [], []
        for q, v, t in states:
            ql, vl = q.tolist(), v.tolist()
            f, power = self.applied_list(ql, vl, t)
            F.append(f)
            G.append(self._gamma(ql, vl, t))
            powers.append(power)
        k = len(states)
        got = schur_solve(self._minv, rows, self.force_columns(rows, ql0), list(np.array(F).reshape(k, self.n).T),
                          list(np.array(G, dtype=float).reshape(k, len(rows)).T))
        if got is None:
            return None
        A = np.array(got[0]).reshape(self.n, k).T
        L = np.array(got[1], dtype=float).reshape(len(rows), k).T
        return [(a, lam, self._power(P, lam, q, v)) for (q, v, _t), a, lam, P in zip(states, A, L, powers)]

    def translation(self, axis: int) -> np.ndarray:
        """q̇ of the whole scene translating along e_axis at unit speed."""
        T = np.zeros(self.n)
        for b in self.bodies:
            T[b.index[axis]] = 1.0
        return T

    def translations(self, q) -> list[int]:
        """The axes i (0: e1, 1: e2) along which the whole scene may translate as one by its
        structure at q: every made row allows it (the joint forces have no net e_i component),
        gravity has none (e1, or g = 0), and no load or friction ties the scene to the ground
        along e_i (a spring or damper to a ground point, a force along e_i, kinetic friction on
        a fixed line along it).  Momentum along e_i is then conserved (36.10), and at rest a
        translation along it is a free motion (ω = 0)."""
        made = [e for e in self.elements if e.rows]
        surfaces = [getattr(e, "surface", None) for e in made]
        if any(getattr(sf, "curved", False) and not getattr(sf, "carried", False) for sf in surfaces):
            return []                   # (a fixed curve's normal turns: J at one q says nothing; a
            #                             carried one's rows read the point from its carrier only)
        J = self.jac(q)
        out = []
        for axis in (0, 1):
            if axis == 1 and self.g != 0:
                continue
            T = self.translation(axis)
            if J.size and float(np.max(np.abs(J @ T))) > 1e-12 * max(float(np.max(np.abs(J))), 1.0):
                continue
            if any(ld.ties(axis) for ld in self.loads):
                continue
            if any(isinstance(e, (Contact, Rolls)) and e.mu_k and not getattr(e.surface, "carried", False)
                   and e.surface.d[axis] != 0 for e in made):    # (on a carried surface: internal)
                continue
            out.append(axis)
        return out

    def rolling_translations(self, q) -> list[np.ndarray]:
        """q̇ of each free motion of the whole scene along e_i (0: e1, 1: e2) in which the disks
        rolling on fixed straight lines turn as they roll (ω = −d̂_i/R) and everything else
        translates as one: a wheel on a floor with a pendulum from its axle.  Free by its
        structure, as :meth:`translations` (every made row allows it, no load or friction ties
        the scene along e_i, gravity has none), and besides: a turning body's angle enters no
        other row (every point of it that a joint or load uses is its centre, no surface rides on
        it, no other row's Jacobian reads its angle) — so the scene at any point of the motion is
        the scene at q moved along e_i.  Scenes without such a disk: none (see translations)."""
        rollers = [e for e in self.elements if type(e) is Rolls and e.rows and e.mode == "roll"
                   and not getattr(e.surface, "curved", False) and not getattr(e.surface, "carried", False)]
        if not rollers:
            return []
        J = self.jac(q)
        own: set[int] = set()           # the rows of the rollers
        for e in rollers:
            k = self.offsets[self.elements.index(e)]
            own.update(range(k, k + e.rows))
        others = [k for k in range(J.shape[0]) if k not in own]
        out = []
        for axis in (0, 1):
            if axis == 1 and self.g != 0 or any(ld.ties(axis) for ld in self.loads):
                continue
            if any(isinstance(e, (Contact, Rolls)) and e.mu_k and not getattr(e.surface, "carried", False)
                   and e.surface.d[axis] != 0 and e.rows and e not in rollers for e in self.elements):
                continue
            T = self.translation(axis)
            turning = {}
            for e in rollers:
                b = e.body_point.body
                turning[b.index[2]] = b
                T[b.index[2]] = -e.surface.d[axis] / e.R
            if J.size and float(np.max(np.abs(J @ T))) > 1e-12 * max(float(np.max(np.abs(J))), 1.0):
                continue
            if any(J[k, i] != 0.0 for k in others for i in turning):
                continue
            if any(_uses_off_centre(item, list(turning.values())) for item in [*self.elements, *self.loads]
                   if item not in rollers):
                continue
            out.append(T)
        return out

    # ------------------------------------------------------------------ energy
    def kinetic(self, v) -> float:
        return 0.5 * float(self.mass @ (v * v))

    def potential(self, q) -> float:
        V = -float(self.grav @ q)
        for ld in self.loads:
            if ld.kind == "spring":
                s = ld.stretch(q)
                if ld.one_sided == "compression" and s > 0 or ld.one_sided == "tension" and s < 0:
                    continue
                V += 0.5 * ld.k * s * s
        return V

    # ------------------------------------------------------------------ projection
    def weights(self) -> np.ndarray:
        """The masses, each at least 1e-12 of the largest (the projections' metric; fixed per scene)."""
        if self._weights is None:
            w = self.mass.copy()
            floor = max(float(np.max(w)), 1e-300) * 1e-12
            self._weights = np.maximum(w, floor)
        return self._weights

    def project_position(self, q, t, iters: int = 4) -> np.ndarray:
        if self.m == 0:
            return q
        return np.array(self.project_position_list(q.tolist(), t, iters), dtype=float)

    def project_position_list(self, ql: list, t, iters: int = 4) -> list:
        """:meth:`project_position` in plain floats (q a list; the same operations)."""
        if self.m == 0:
            return ql
        tol = 8 * EPS * max(1.0, *map(abs, ql))
        for _ in range(iters):
            ph = []
            for e in self.elements:
                ph += e.phi_list(ql, t)
            if all(abs(x) <= tol for x in ph):      # on the joints to rounding: Newton has converged
                break
            ql = self._least_step(ql, self._jac_rows(ql), ph)
        return ql

    def project_velocity(self, q, v, t) -> np.ndarray:
        if self.m == 0:
            return v
        vl = v.tolist()
        got = self.project_velocity_list(q.tolist(), vl, t)
        return v if got is vl else np.array(got, dtype=float)

    def project_velocity_list(self, ql: list, vl: list, t) -> list:
        """:meth:`project_velocity` in plain floats (q, v lists; ``vl`` itself when it is on the
        joints' velocity rows exactly)."""
        if self.m == 0:
            return vl
        J = self._jac_rows(ql)
        r = []
        for e in self.elements:
            r += e.phi_t_list(t)
        r = [sum(map(operator.mul, Ji, vl)) + x for Ji, x in zip(J, r)]
        if not any(r):
            return vl
        return self._least_step(vl, J, r)

    def _jac_rows(self, ql) -> list:
        rows = []
        for e in self.elements:
            if e.rows:
                rows += e.jac_list(ql)
        return rows

    def _least_step(self, x: list, J: list, r: list) -> list:
        """x − W⁻¹ Jᵀ (J W⁻¹ Jᵀ)⁻¹ r (W: :meth:`weights`): the step of least mass-weighted size
        that takes the rows' values J x by −r; up to SCHUR_ROWS rows by :func:`complement_solve` in
        plain floats, more (or rows close to dependent) by LAPACK as the whole solve."""
        if self._winv is None:
            self._winv = (1.0 / self.weights()).tolist()
        got = complement_solve(self._winv, J, J, r) if len(J) <= SCHUR_ROWS else None
        if got is not None:
            mu, Y = got
            for mk, Yk in zip(mu, Y):
                x = [a - mk * y for a, y in zip(x, Yk)]
            return x
        Winv = 1.0 / self.weights()
        Ja = np.array(J, dtype=float).reshape(len(J), self.n)
        S = (Ja * Winv) @ Ja.T
        return (np.array(x) - Winv * (Ja.T @ self.linsolve(S, np.array(r, dtype=float)))).tolist()
