"""The joints of a scene as blocks of constraint rows (docs/types/scene.md).

Each element holds rows φ(q, t) = 0 with their analytic Jacobian J = ∂φ/∂q and
γ = −J̇ v − φ_tt (so that J q̈ = γ), and the velocity term φ_t (J q̇ + φ_t = 0).  The
equations of motion M q̈ = f + Jᵀ λ then make the multipliers λ the joint forces of the
free-body diagrams (16.7, 29.5, 32.15, 36); each element reads its own λ back in the
contract's terms and signs (on the first-named body, by the second).  One-sided elements
list the quantities that must stay ≥ 0 (``watch``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from dyncli.errors import NumericalError

from .system import BodyData, BodyPoint, Point, SurfaceData, perp

EPS = float(np.finfo(float).eps)


@dataclass
class Element:
    name: str
    kind: str
    n: int                          # size of q
    path: str = ""                  # the field path in the file, for messages

    rows = 0
    linear = True                   # rows affine in q with a constant Jacobian (closed-form test)

    def phi(self, q, t) -> np.ndarray:
        raise NotImplementedError

    def jac(self, q) -> np.ndarray:
        raise NotImplementedError

    def gamma(self, q, v, t) -> np.ndarray:
        return np.zeros(self.rows)

    def phi_t(self, t) -> np.ndarray:
        return np.zeros(self.rows)

    # --- the same rows in plain floats (q, v: lists; the right-hand side of the ODE route and the
    # projections, where numpy's cost per small array is most of the work).  The common joints
    # compute their arrays from these (the same numbers); these defaults go through the arrays.
    def phi_list(self, q, t) -> list:
        return self.phi(np.asarray(q, dtype=float), t).tolist()

    def jac_list(self, q) -> list:
        """The rows' Jacobian: a list of ``rows`` lists of n floats."""
        return self.jac(np.asarray(q, dtype=float)).tolist()

    def gamma_list(self, q, v, t) -> list:
        return self.gamma(np.asarray(q, dtype=float), np.asarray(v, dtype=float), t).tolist()

    def kkt_lists(self, q, v, t) -> tuple[list, list]:
        """(jac_list, gamma_list) together (an element may share their geometry)."""
        return self.jac_list(q), self.gamma_list(q, v, t)

    def phi_t_list(self, t) -> list:
        if type(self).phi_t is Element.phi_t:       # rows that do not move in time
            return [0.0] * self.rows
        return self.phi_t(t).tolist()

    # --- many states at once (X: a system.Stack of k states, V: (k, n); ``td``: the element's data at the
    # states' times, from :meth:`at_times`).  These defaults call the one-state forms state by
    # state; the common joints override them with column arithmetic (the same numbers).
    def at_times(self, T) -> np.ndarray:
        """What the rows need of the times T (k,): the times themselves (a drive: its f(t))."""
        return T

    def phi_many(self, X, td) -> np.ndarray:
        return np.array([self.phi(q, float(t)) for q, t in zip(X.Q, td)]).reshape(X.k, self.rows)

    def jac_many(self, X, J) -> None:
        """J (k, rows, n), zero on entry: filled with the rows' Jacobian at every state."""
        for k, q in enumerate(X.Q):
            J[k] = self.jac(q)

    def gamma_many(self, X, V, td) -> np.ndarray:
        return np.array([self.gamma(q, v, float(t)) for q, v, t in zip(X.Q, V, td)]).reshape(X.k, self.rows)

    def phi_t_many(self, td) -> np.ndarray:
        return np.array([self.phi_t(float(t)) for t in td]).reshape(len(td), self.rows)

    def report(self, lam, q, v, t) -> dict:
        return {}

    def watch(self, lam, q, v, t) -> list[tuple[str, float]]:
        """(what, g): the event ``what`` happens where g crosses zero from above."""
        return []

    def reads_forces(self) -> bool:
        """Whether :meth:`watch` reads the element's multipliers in its current phase (an element
        that watches anything: yes, unless it says otherwise)."""
        return type(self).watch is not Element.watch

    def phase(self):
        """The element's state in the current phase (one-sided joints: made, released, sliding,
        slack ...); None for a joint that never changes."""
        return None

    def set_phase(self, state) -> None:
        pass


def _two(P: Point, Q: Point, q, n):
    return P.jac(q, n) - Q.jac(q, n)


@dataclass(kw_only=True)
class ListRows(Element):
    """An element whose rows are written in plain floats (its ``phi_list``, ``jac_list`` and
    ``gamma_list``): the arrays are made from them (the same numbers)."""

    def phi(self, q, t):
        return np.array(self.phi_list(q, t))

    def jac(self, q):
        return np.array(self.jac_list(q)).reshape(self.rows, self.n)

    def gamma(self, q, v, t):
        return np.array(self.gamma_list(q, v, t))


def keeps_arm(P: Point, N) -> bool:
    """Whether the point's arm from its body's centre stays put along the motion q0 + s N: it
    does not turn with its body, or N does not turn that body (its angle's component exactly 0:
    a joint that holds the angle gives an exact 0).  A row that is affine in the positions at
    fixed angles (a pin, a contact on a fixed line) is then affine along N, with a constant
    Jacobian and no velocity-squared term."""
    return not P.turns_with_body or P.body is None or N[P.body.index[2]] == 0.0


@dataclass(kw_only=True)
class Pin(ListRows):
    P: Point
    Q: Point
    rows = 2

    @property
    def linear(self):
        return not (self.P.turns_with_body or self.Q.turns_with_body)

    def straight_along(self, q, N) -> bool:
        """Affine along N when neither point turns along it (a car's axles on its body)."""
        return keeps_arm(self.P, N) and keeps_arm(self.Q, N)

    def phi_list(self, q, t):
        (p1, p2), (q1, q2) = self.P.xy(q), self.Q.xy(q)
        return [p1 - q1, p2 - q2]

    def jac_list(self, q):
        r1, r2 = [0.0] * self.n, [0.0] * self.n
        self.P.add_jac2(r1, r2, q, 1.0)
        self.Q.add_jac2(r1, r2, q, -1.0)
        return [r1, r2]

    def gamma_list(self, q, v, t):
        (p1, p2), (q1, q2) = self.P.bias_xy(q, v), self.Q.bias_xy(q, v)
        return [q1 - p1, q2 - p2]

    def kkt_lists(self, q, v, t):
        *_, pb1, pb2, pa = self.P.kin(q, v)
        *_, qb1, qb2, qa = self.Q.kin(q, v)
        r1, r2 = [0.0] * self.n, [0.0] * self.n
        self.P.add_jac2_arm(r1, r2, pa, 1.0)
        self.Q.add_jac2_arm(r1, r2, qa, -1.0)
        return [r1, r2], [qb1 - pb1, qb2 - pb2]

    def phi_many(self, X, td):
        (p1, p2), (q1, q2) = self.P.xy_many(X), self.Q.xy_many(X)
        return np.stack((p1 - q1, p2 - q2), axis=1)

    def jac_many(self, X, J):
        self.P.add_jac2_many(J, X, 1.0)
        self.Q.add_jac2_many(J, X, -1.0)

    def gamma_many(self, X, V, td):
        (p1, p2), (q1, q2) = self.P.bias_many(X, V), self.Q.bias_many(X, V)
        return np.stack((q1 - p1, q2 - p2), axis=1)

    def phi_t_many(self, td):
        return np.zeros((len(td), 2))

    def report(self, lam, q, v, t):
        return {"R": [float(lam[0]), float(lam[1]), 0.0]}


class PinBlock:
    """The rows of every pin of a scene at many states at once, in a few array operations for
    all of them (the pins are most of a linkage's rows): the constant entries (±1) placed
    together, the arms Q(θ) p of all the turning points from one cos and one sin, each entry by
    the same operations as Pin.jac_many, phi_many, gamma_many (equal to them bit for bit); ``ok`` is
    False when two entries of the block share a place (then each pin fills its own rows)."""

    def __init__(self, pins, offsets):
        self.members = {id(p) for p in pins}
        self.rows0 = np.array(offsets, dtype=int)
        cr, cc, cv = [], [], []                   # constant entries: row, column, value
        cols, p1, p2 = [], [], []                 # turning points: angle column, p
        ar, ac, at, asg = [], [], [], []          # arm entries of row o (−sign a2); row o + 1 (+sign a1) alike
        # positions: per pin and side, the column of x1 (or a constant) and the turning point (or −1)
        side = {"x": ([], []), "y": ([], []), "const": ([], []), "turn": ([], [])}
        for pin, o in zip(pins, offsets):
            for k, (pt, sign) in enumerate(((pin.P, 1.0), (pin.Q, -1.0))):
                b = pt.body
                if b is None:
                    side["x"][k].append(-1)
                    side["y"][k].append(-1)
                    side["const"][k].append((float(pt.p[0]), float(pt.p[1])))
                    side["turn"][k].append(-1)
                    continue
                i = b.index
                cr += [o, o + 1]
                cc += [i[0], i[1]]
                cv += [sign, sign]
                side["x"][k].append(i[0])
                side["y"][k].append(i[1])
                side["const"][k].append((0.0, 0.0))
                if b.inertia is not None and (pt.p[0] or pt.p[1]):
                    side["turn"][k].append(len(cols))
                    ar.append(o)
                    ac.append(i[2])
                    at.append(len(cols))
                    asg.append(sign)
                    cols.append(i[2])
                    p1.append(float(pt.p[0]))
                    p2.append(float(pt.p[1]))
                else:
                    side["turn"][k].append(-1)
        places = list(zip(cr, cc)) + [(r, c) for r, c in zip(ar, ac)] + [(r + 1, c) for r, c in zip(ar, ac)]
        self.ok = len(set(places)) == len(places)
        self.cr, self.cc, self.cv = np.array(cr, dtype=int), np.array(cc, dtype=int), np.array(cv)
        self.cols, self.p1, self.p2 = np.array(cols, dtype=int), np.array(p1), np.array(p2)
        self.ar, self.ac, self.at, self.asg = (np.array(ar, dtype=int), np.array(ac, dtype=int),
                                               np.array(at, dtype=int), np.array(asg))
        # the four coordinates (side P, Q × x1, x2) of every pin, in one row of columns
        npt = len(cols)
        xs = [side["x" if c == 0 else "y"][k] for k in (0, 1) for c in (0, 1)]
        self.all_cols = np.maximum(np.array(sum(xs, []), dtype=int), 0)
        self.ground = np.array(sum(xs, []), dtype=int) < 0
        self.const = np.array([cst[c] for k in (0, 1) for c in (0, 1) for cst in side["const"][k]])
        turn = np.array([t for k in (0, 1) for _c in (0, 1) for t in side["turn"][k]], dtype=int)
        coord = np.array([c for k in (0, 1) for c in (0, 1) for _ in side["turn"][k]], dtype=int)
        self.turning = turn >= 0
        self.turn_idx = np.maximum(turn, 0) + coord * npt      # into the arms' two blocks side by side
        self.npins = len(pins)

    def _arms(self, Q):
        th = Q[:, self.cols]
        c, s = np.cos(th), np.sin(th)
        return c * self.p1 - s * self.p2, s * self.p1 + c * self.p2

    def jac(self, Q, J) -> None:
        """The pins' entries of J (k, m, n), zero there on entry."""
        J[:, self.cr, self.cc] = self.cv
        if self.cols.size:
            a1, a2 = self._arms(Q)
            J[:, self.ar, self.ac] = np.subtract(0.0, self.asg * a2[:, self.at])
            J[:, self.ar + 1, self.ac] = np.add(0.0, self.asg * a1[:, self.at])

    def _four(self, x, arms):
        """(k, 2 sides, 2 coordinates, pins) from the columns ``x`` and the arms' two blocks."""
        if arms is not None:
            x = np.where(self.turning, x + np.concatenate(arms, axis=1)[:, self.turn_idx], x)
        return x.reshape(len(x), 2, 2, self.npins)

    def phi(self, Q) -> tuple[np.ndarray, np.ndarray]:
        """The pins' two rows at every state: (k, pins) each, rows o and o + 1."""
        r = self._four(np.where(self.ground, self.const, Q[:, self.all_cols]),
                       self._arms(Q) if self.cols.size else None)
        return r[:, 0, 0] - r[:, 1, 0], r[:, 0, 1] - r[:, 1, 1]

    def gamma(self, Q, V) -> tuple[np.ndarray, np.ndarray]:
        """The pins' γ at every state: (k, pins) each, rows o and o + 1 (J̇ v of Q's side minus P's)."""
        b = np.zeros((len(Q), 4 * self.npins))
        if self.cols.size:
            a1, a2 = self._arms(Q)
            w = V[:, self.cols]
            ww = -w * w
            b = np.where(self.turning, np.concatenate((ww * a1, ww * a2), axis=1)[:, self.turn_idx], b)
        r = b.reshape(len(Q), 2, 2, self.npins)
        return r[:, 1, 0] - r[:, 0, 0], r[:, 1, 1] - r[:, 0, 1]


class RunsOffEnds:
    """A slider's phases (mode "on", or "off" past an end of its surface: no rows) and its watch
    (the event ``leaves`` where ``end_margin``, the distance to the nearer end, crosses 0)."""

    mode: str

    def phase(self):
        return self.mode

    def set_phase(self, state) -> None:
        self.mode = state

    def end_margin(self, q) -> float | None:
        raise NotImplementedError

    def watch(self, lam, q, v, t):
        m = None if self.mode == "off" else self.end_margin(q)
        return [] if m is None else [("leaves", m)]

    def reads_forces(self) -> bool:
        return False


@dataclass(kw_only=True)
class Slider(RunsOffEnds, ListRows):
    """The body's centre stays on the line through its position at t = 0 parallel to the
    surface; a rigid body keeps its angle.  On a surface with ends (``length``) the body leaves
    it where its centre passes an end (the event ``leaves``; mode "off": no rows, free from then
    on, as a collar run off the end of its rod)."""

    body_point: BodyPoint
    surface: SurfaceData
    c0: float = 0.0
    theta0: float | None = None
    mode: str = "on"

    @property
    def rows(self):
        return 0 if self.mode == "off" else 1 if self.theta0 is None else 2

    def end_margin(self, q) -> float | None:
        return self.surface.ends_margin(self.body_point.xy(q))

    def phi_list(self, q, t):
        if self.mode == "off":
            return []
        n1, n2 = self.surface.n
        x1, x2 = self.body_point.xy(q)
        out = [n1 * x1 + n2 * x2 - self.c0]
        if self.theta0 is not None:
            out.append(float(q[self.body_point.body.index[2]]) - self.theta0)
        return out

    def jac_list(self, q):
        rows = [[0.0] * self.n for _ in range(self.rows)]
        if not rows:
            return rows
        self.body_point.add_jac(rows[0], q, *self.surface.n)
        if self.theta0 is not None:
            rows[1][self.body_point.body.index[2]] = 1.0
        return rows

    def gamma_list(self, q, v, t):
        return [0.0] * self.rows

    def phi_many(self, X, td):
        if self.mode == "off":
            return np.zeros((X.k, 0))
        n1, n2 = self.surface.n
        x1, x2 = self.body_point.xy_many(X)
        cols = [n1 * x1 + n2 * x2 - self.c0]
        if self.theta0 is not None:
            cols.append(X.Q[:, self.body_point.body.index[2]] - self.theta0)
        return np.stack(cols, axis=1)

    def jac_many(self, X, J):
        if self.mode == "off":
            return
        n1, n2 = self.surface.n
        self.body_point.add_jac_many(J[:, 0], X, n1, n2)
        if self.theta0 is not None:
            J[:, 1, self.body_point.body.index[2]] = 1.0

    def gamma_many(self, X, V, td):
        return np.zeros((X.k, self.rows))

    def phi_t_many(self, td):
        return np.zeros((len(td), self.rows))

    def report(self, lam, q, v, t):
        off = self.mode == "off"
        out = {"N": 0.0 if off else float(lam[0])}
        if self.theta0 is not None:
            out["M"] = [0.0, 0.0, 0.0 if off else float(lam[1])]
        return out


def span_row(P: Point, Q: Point, q, n: int) -> list:
    """∂|r_P − r_Q|/∂q: the row of a length held between two points (a link, a string)."""
    (p1, p2), (q1, q2) = P.xy(q), Q.xy(q)
    d1, d2 = p1 - q1, p2 - q2
    ln = math.hypot(d1, d2)
    e1, e2 = d1 / ln, d2 / ln
    row = [0.0] * n
    P.add_jac(row, q, e1, e2)
    Q.add_jac(row, q, -e1, -e2)
    return row


def span_gamma(P: Point, Q: Point, q, v) -> float:
    """−(the part of d²|r_P − r_Q|/dt² that is not the row times q̈): e·(b_P − b_Q) (the points'
    velocity-squared terms) and the turning of e, (|ḋ|² − (e·ḋ)²)/|d|."""
    (p1, p2), (q1, q2) = P.xy(q), Q.xy(q)
    d1, d2 = p1 - q1, p2 - q2
    ln = math.hypot(d1, d2)
    e1, e2 = d1 / ln, d2 / ln
    (pv1, pv2), (qv1, qv2) = P.vel_xy(q, v), Q.vel_xy(q, v)
    (pb1, pb2), (qb1, qb2) = P.bias_xy(q, v), Q.bias_xy(q, v)
    dv1, dv2 = pv1 - qv1, pv2 - qv2
    ev = e1 * dv1 + e2 * dv2
    return -((e1 * (pb1 - qb1) + e2 * (pb2 - qb2)) + (dv1 * dv1 + dv2 * dv2 - ev * ev) / ln)


@dataclass(kw_only=True)
class Link(ListRows):
    """A massless rigid link (36): |r_P − r_Q| = L; T tension positive."""

    P: Point
    Q: Point
    L: float = 1.0
    rows = 1
    linear = False

    def _d(self, q):
        (p1, p2), (q1, q2) = self.P.xy(q), self.Q.xy(q)
        d1, d2 = p1 - q1, p2 - q2
        return (d1, d2), math.hypot(d1, d2)

    def phi_list(self, q, t):
        _, ln = self._d(q)
        return [ln - self.L]

    def jac_list(self, q):
        return [span_row(self.P, self.Q, q, self.n)]

    def gamma_list(self, q, v, t):
        return [span_gamma(self.P, self.Q, q, v)]

    def kkt_lists(self, q, v, t):
        p1, p2, pv1, pv2, pb1, pb2, pa = self.P.kin(q, v)
        q1, q2, qv1, qv2, qb1, qb2, qa = self.Q.kin(q, v)
        d1, d2 = p1 - q1, p2 - q2
        ln = math.hypot(d1, d2)
        e1, e2 = d1 / ln, d2 / ln
        row = [0.0] * self.n
        self.P.add_jac_arm(row, pa, e1, e2)
        self.Q.add_jac_arm(row, qa, -e1, -e2)
        dv1, dv2 = pv1 - qv1, pv2 - qv2
        ev = e1 * dv1 + e2 * dv2
        return [row], [-((e1 * (pb1 - qb1) + e2 * (pb2 - qb2)) + (dv1 * dv1 + dv2 * dv2 - ev * ev) / ln)]

    def _d_many(self, X):
        (p1, p2), (q1, q2) = self.P.xy_many(X), self.Q.xy_many(X)
        d1, d2 = p1 - q1, p2 - q2
        ln = np.fromiter(map(math.hypot, d1.tolist(), d2.tolist()), float, len(d1))
        return d1, d2, ln

    def phi_many(self, X, td):
        return (self._d_many(X)[2] - self.L)[:, None]

    def jac_many(self, X, J):
        d1, d2, ln = self._d_many(X)
        e1, e2 = d1 / ln, d2 / ln
        self.P.add_jac_many(J[:, 0], X, e1, e2)
        self.Q.add_jac_many(J[:, 0], X, -e1, -e2)

    def gamma_many(self, X, V, td):
        d1, d2, ln = self._d_many(X)
        e1, e2 = d1 / ln, d2 / ln
        (pv1, pv2), (qv1, qv2) = self.P.vel_many(X, V), self.Q.vel_many(X, V)
        (pb1, pb2), (qb1, qb2) = self.P.bias_many(X, V), self.Q.bias_many(X, V)
        dv1, dv2 = pv1 - qv1, pv2 - qv2
        ev = e1 * dv1 + e2 * dv2
        return (-((e1 * (pb1 - qb1) + e2 * (pb2 - qb2)) + (dv1 * dv1 + dv2 * dv2 - ev * ev) / ln))[:, None]

    def phi_t_many(self, td):
        return np.zeros((len(td), 1))

    def report(self, lam, q, v, t):
        return {"T": -float(lam[0])}


@dataclass(kw_only=True)
class Gear(ListRows):
    """Two gears in mesh: their pitch circles (radii R_A, R_B) roll on each other without slip.
    With φ the angle of the line of centres A → B, the contact point's velocities agree along
    t = e3 × n̂ (n̂ = (x_B − x_A)/D): R_A ω_A + s R_B ω_B = D φ̇, s = +1 for an external mesh
    (D = R_A + R_B), −1 for B inside A's ring gear (D = R_A − R_B); with D held by the other
    joints (pins, a carrier arm), integrated: R_A θ_A + s R_B θ_B − D φ = c0 (a planet gear's
    rolling included).  λ is the tooth force on A by B along t (on B: −λ t), at the pitch point."""

    A: BodyData
    B: BodyData
    RA: float
    RB: float
    s: float = 1.0
    D: float = 0.0
    c0: float = 0.0
    #: what tells the branch of φ = atan2: "ground" (both centres pinned to the ground: φ = φ0),
    #: the angle index of a carrier both centres are pinned to (φ turns with it), or None (the φ
    #: the row itself holds: a gear on its own has the row's windings as branches)
    carrier: str | int | None = None
    phi0: float = 0.0               # φ at t = 0 (less the carrier's angle then)
    rows = 1
    linear = False

    def _d(self, q):
        a, b = self.A.index, self.B.index
        return float(q[b[0]]) - float(q[a[0]]), float(q[b[1]]) - float(q[a[1]])

    def angle_sum(self, q) -> float:
        return self.RA * float(q[self.A.index[2]]) + self.s * self.RB * float(q[self.B.index[2]])

    def _near(self, q) -> float:
        """The φ whose branch of atan2 the row reads (continuous along the motion)."""
        if self.carrier == "ground":
            return self.phi0
        if isinstance(self.carrier, int):
            return self.phi0 + float(q[self.carrier])
        return (self.angle_sum(q) - self.c0) / self.D

    def phi_list(self, q, t):
        d1, d2 = self._d(q)
        near = self._near(q)
        phi = near + math.remainder(math.atan2(d2, d1) - near, 2 * math.pi)
        return [self.angle_sum(q) - self.D * phi - self.c0]

    def jac_list(self, q):
        d1, d2 = self._d(q)
        k = self.D / (d1 * d1 + d2 * d2)
        a, b = self.A.index, self.B.index
        row = [0.0] * self.n
        row[a[0]] -= k * d2
        row[a[1]] += k * d1
        row[b[0]] += k * d2
        row[b[1]] -= k * d1
        row[a[2]] += self.RA
        row[b[2]] += self.s * self.RB
        return [row]

    def gamma_list(self, q, v, t):
        d1, d2 = self._d(q)
        a, b = self.A.index, self.B.index
        e1, e2 = float(v[b[0]]) - float(v[a[0]]), float(v[b[1]]) - float(v[a[1]])
        dd = d1 * d1 + d2 * d2
        return [-2.0 * self.D * (d1 * e2 - d2 * e1) * (d1 * e1 + d2 * e2) / (dd * dd)]

    def phi_grad(self, q) -> np.ndarray:
        """∇φ of the line of centres' angle (the row's centre entries over −D)."""
        row = np.array(self.jac_list(q)[0])
        row[self.A.index[2]] = row[self.B.index[2]] = 0.0
        return row / -self.D

    def straight_along(self, q, N) -> bool:
        """Whether the line of centres keeps its direction along the motion N (pinned gears): the
        row is then affine along it."""
        grad, N = self.phi_grad(q), np.ravel(np.asarray(N, float))
        return abs(float(grad @ N)) <= 1e-12 * float(np.linalg.norm(grad)) * float(np.linalg.norm(N))

    def hessian(self, q, w, n: int) -> np.ndarray:
        """w ∇²(−D φ): φ = atan2(d2, d1) of d = x_B − x_A, ∂²φ/∂d² = [[2 d1 d2, d2² − d1²], [d2² − d1², −2 d1 d2]]/|d|⁴."""
        d1, d2 = self._d(q)
        dd = d1 * d1 + d2 * d2
        Hd = np.array([[2 * d1 * d2, d2 * d2 - d1 * d1], [d2 * d2 - d1 * d1, -2 * d1 * d2]]) / (dd * dd)
        Dq = np.zeros((2, n))
        a, b = self.A.index, self.B.index
        Dq[0, b[0]], Dq[1, b[1]], Dq[0, a[0]], Dq[1, a[1]] = 1.0, 1.0, -1.0, -1.0
        return -float(w[0]) * self.D * (Dq.T @ Hd @ Dq)

    def distance_terms(self, q, n: int):
        """(∇D, ∇²D) of the centres' distance D = |x_B − x_A| (prepare.py: held by the other joints)."""
        d1, d2 = self._d(q)
        D = math.hypot(d1, d2)
        Dq = np.zeros((2, n))
        a, b = self.A.index, self.B.index
        Dq[0, b[0]], Dq[1, b[1]], Dq[0, a[0]], Dq[1, a[1]] = 1.0, 1.0, -1.0, -1.0
        nrm = np.array([d1, d2]) / D
        return nrm @ Dq, Dq.T @ ((np.eye(2) - np.outer(nrm, nrm)) / D) @ Dq

    def report(self, lam, q, v, t):
        return {"F": float(lam[0])}


@dataclass(kw_only=True)
class Rack(ListRows):
    """A gear (pitch radius R) on a fixed rack whose pitch line is the surface: the pitch circle
    rolls on the line, d̂·x + R θ = c0 (15.8, two-sided: the teeth push both ways); the centre is
    held R off the line by the other joints.  λ is the tooth force on the gear along d̂."""

    body: BodyData
    d: tuple[float, float]
    R: float
    c0: float = 0.0
    rows = 1
    linear = True

    def _row(self) -> list:
        i = self.body.index
        row = [0.0] * self.n
        row[i[0]], row[i[1]] = self.d
        row[i[2]] = self.R
        return row

    def roll_const(self, q) -> float:
        i = self.body.index
        return self.d[0] * float(q[i[0]]) + self.d[1] * float(q[i[1]]) + self.R * float(q[i[2]])

    def phi_list(self, q, t):
        return [self.roll_const(q) - self.c0]

    def jac_list(self, q):
        return [self._row()]

    def gamma_list(self, q, v, t):
        return [0.0]

    def distance_terms(self, q, n: int):
        """(∇g, ∇²g = 0) of the centre's distance from the pitch line, n·x."""
        i = self.body.index
        grad = np.zeros(n)
        grad[i[0]], grad[i[1]] = -self.d[1], self.d[0]
        return grad, np.zeros((n, n))

    def report(self, lam, q, v, t):
        return {"F": float(lam[0])}


@dataclass(kw_only=True)
class Drive(ListRows):
    """A prescribed coordinate q_i = f(t); λ is the force or couple the driver applies."""

    index: int = 0
    f: Callable[[float], tuple[float, float, float]]     # f(t) -> (value, rate, second rate)
    f_many: Callable | None = None                       # f at an array of times -> 3 arrays (the same numbers)
    rows = 1
    _last: tuple = field(default=(None, None), repr=False, compare=False)   # (t, f(t)): φ, φ_t, γ asked at one t

    def _at(self, t):
        if self._last[0] != t:
            self._last = (t, self.f(t))
        return self._last[1]

    def phi_list(self, q, t):
        return [float(q[self.index]) - self._at(t)[0]]

    def jac_list(self, q):
        row = [0.0] * self.n
        row[self.index] = 1.0
        return [row]

    def gamma_list(self, q, v, t):
        return [self._at(t)[2]]

    def phi_t(self, t):
        return np.array([-self._at(t)[1]])

    def at_times(self, T):
        """f(t) at each time: (k, 3) rows (value, rate, second rate)."""
        if self.f_many is not None:
            return np.stack(self.f_many(T), axis=1)
        return np.array([self.f(float(t)) for t in T], dtype=float).reshape(len(T), 3)

    def phi_many(self, X, td):
        return (X.Q[:, self.index] - td[:, 0])[:, None]

    def jac_many(self, X, J):
        J[:, 0, self.index] = 1.0

    def gamma_many(self, X, V, td):
        return td[:, 2:3].copy()

    def phi_t_many(self, td):
        return -td[:, 1:2]

    def report(self, lam, q, v, t):
        return {"drive": float(lam[0])}


@dataclass
class CordEnd:
    """One end of a straight cord segment: a point (``point``), or a tangent point on a disk
    body turning with it (``body`` with ``k`` = u·(e3 × (T − C)) per unit rotation), or a
    fixed light pulley (``fixed``: a constant)."""

    point: Point | None = None
    centre: BodyPoint | None = None   # disk body centre (tangent ends)
    k: float = 0.0
    fixed: np.ndarray | None = None

    def proj(self, u, q) -> float:
        u1, u2 = float(u[0]), float(u[1])
        if self.point is not None:
            x1, x2 = self.point.xy(q)
            return u1 * x1 + u2 * x2
        if self.centre is not None:
            x1, x2 = self.centre.xy(q)
            return u1 * x1 + u2 * x2 + self.k * float(q[self.centre.angle_index])
        assert self.fixed is not None, "a cord end is a point, a disk or a fixed pulley"
        return u1 * float(self.fixed[0]) + u2 * float(self.fixed[1])

    def jac(self, u, q, n) -> np.ndarray:
        J = np.zeros(n)
        self.add_jac(J, u, q, 1.0)
        return J

    def add_jac(self, row, u, q, sign: float) -> None:
        """row += sign · ∂(u·X)/∂q, in place."""
        if self.point is not None:
            self.point.add_jac(row, q, sign * float(u[0]), sign * float(u[1]))
        elif self.centre is not None:
            self.centre.add_jac(row, q, sign * float(u[0]), sign * float(u[1]))
            row[self.centre.angle_index] += sign * self.k

    def bias(self, u, q, v) -> float:
        if self.point is None:
            return 0.0
        b1, b2 = self.point.bias_xy(q, v)
        return float(u[0]) * b1 + float(u[1]) * b2

    @property
    def turns(self) -> bool:
        return self.point is not None and self.point.turns_with_body

    def drawn(self, u, q) -> tuple[float, float]:
        """Where the segment of direction u ends at q: the point, the tangent point on the disk
        (T − C = −k e3 × u, kept on the disk's centre), or the fixed pulley's tangent point."""
        if self.point is not None:
            x1, x2 = self.point.xy(q)
            return float(x1), float(x2)
        if self.centre is not None:
            c1, c2 = self.centre.xy(q)
            return float(c1) + self.k * float(u[1]), float(c2) - self.k * float(u[0])
        assert self.fixed is not None, "a cord end is a point, a disk or a fixed pulley"
        return float(self.fixed[0]), float(self.fixed[1])


#: where a cord's end is taken to reach its pulley (the event ``reaches``): its segment's straight
#: part down to this fraction of the cord's length — at 0 the segment's direction is not defined,
#: and near it √(D² − ρ²) keeps only ε ρ²/ℓ² of its digits (a millionth: six digits of ℓ kept)
REACH = 1e-6


def unwound(ref: float, angle: float) -> float:
    """``angle`` on its branch within half a turn of ``ref`` (an arc's angle counted on past ±π)."""
    return ref + math.remainder(angle - ref, 2 * math.pi)


def signed_root(w: float) -> float:
    """√|w| with the sign of w: a straight part √(D² − δ²) that goes negative past its end."""
    return math.copysign(math.sqrt(abs(w)), w)


def turning_gamma(u1: float, u2: float, ell: float, dv, db) -> float:
    """γ of a straight part of length ℓ along u whose ends move apart at dv (their velocity-squared
    terms db): −(u·db + (n·dv)²/ℓ), the last the turning of u (0 at ℓ = 0, a trial state)."""
    across = u1 * dv[1] - u2 * dv[0]
    return -(u1 * db[0] + u2 * db[1] + (across * across / ell if ell > 0 else 0.0))


@dataclass
class Turning:
    """A cord segment between a fixed light pulley (centre C, signed radius ρ as
    :func:`segment_tangents` takes it; 0: a point pulley) and a body point at its end ``end``
    ("a" or "b") that no guide holds along it: its direction turns with the point.  Its part of
    the cord's length is ℓ + c (α − α0): the straight part ℓ = |P − T| from the tangent point T
    and the arc that T runs over on the pulley (α its angle about C, c = u·(e3 × (T − C)) = ±|ρ|
    from t = 0), whose gradient is the unit vector e from T to P — so the row, γ and curvature are
    a string's from T held fixed (T moves along the segment's own line)."""

    end: str
    C: tuple[float, float]
    rho: float
    c: float
    alpha0: float
    angle: int | None = None        # a disk body's angle index (the pulley a disk on a fixed axle)
    theta0: float = 0.0             # its angle at t = 0
    centre: tuple[int, int] | None = None   # that disk's centre indices: the pull on its axle
    reach: tuple = (0.0, 0.0, 1.0, 0.0)     # (T, e) at the phase's start: the watch ``reaches``
    ref: float = 0.0                # α at the phase's start, unwound (whole turns counted): the arc's branch

    def angle_of(self, P: Point, q) -> float:
        """α, the tangent point's angle about C, on its branch near ``ref`` (within half a turn)."""
        t1, t2, *_ = self.tangent(P, q)
        return self._unwound(t1, t2)

    def _unwound(self, t1: float, t2: float) -> float:
        return unwound(self.ref, math.atan2(t2 - self.C[1], t1 - self.C[0]))

    def mark(self, P: Point, q) -> None:
        """Keep the tangent point and direction at q (a phase's start) for :meth:`reach_gap`, and
        α there as the arc's branch (the watch ``turns`` starts a phase before it is half a turn
        away)."""
        t1, t2, e1, e2, _l = self.tangent(P, q)
        self.reach = (t1, t2, e1, e2)
        if self.c:
            self.ref = self.angle_of(P, q)

    def reach_gap(self, P: Point, q) -> float:
        """Signed, how far P is from reaching its pulley: with w = P − T_s and e_s the tangent point
        and direction at the phase's start, w·e_s + (|w| − w·e_s)/4 — |w| along e_s, −|w|/2 past
        T_s on its line (an end that runs onto the pulley along its own segment, as a block on a
        table level with the pulley's top: its straight part only touches 0 there), and positive
        for an end that has turned less than 109° about T_s (a swing is not a reach)."""
        (p1, p2), (t1, t2, e1, e2) = P.xy(q), self.reach
        w1, w2 = p1 - t1, p2 - t2
        along = w1 * e1 + w2 * e2
        return along + 0.25 * (math.hypot(w1, w2) - along)

    def tangent(self, P: Point, q) -> tuple[float, float, float, float, float]:
        """(T1, T2, e1, e2, ℓ) at q: the tangent point, the unit vector from it to P, their distance."""
        (p1, p2), (c1, c2), rho = P.xy(q), self.C, self.rho
        if self.end == "b":             # from the pulley (a) to P: d = P − C, δ = ρ
            d1, d2, delta = p1 - c1, p2 - c2, rho
        else:                           # from P (a) to the pulley: d = C − P, δ = −ρ
            d1, d2, delta = c1 - p1, c2 - p2, -rho
        D = math.hypot(d1, d2)
        # (inside the rim, a trial state of a step that the event ``reaches`` will cut: ℓ = 0 and
        # the limit direction, so that the step is rejected or cut rather than the solve lost)
        if not D > 0.5 * abs(rho) or not D > 0:
            raise NumericalError(f"a cord's end reached its pulley at [{c1:g}, {c2:g}] (the segment has no straight "
                                 "part left): the motion is not solved past it")
        psi = math.atan2(d2, d1) - math.asin(max(-1.0, min(1.0, delta / D)))
        u1, u2 = math.cos(psi), math.sin(psi)
        t1, t2 = c1 - rho * u2, c2 + rho * u1           # T = C + ρ (e3 × u)
        ell = math.sqrt(max(D * D - rho * rho, 0.0))
        return (t1, t2, u1, u2, ell) if self.end == "b" else (t1, t2, -u1, -u2, ell)

    def length(self, P: Point, q) -> float:
        """ℓ + c (α − α0), less c (θ − θ0) on a disk that turns (the arc from the tangent point to
        the disk's material point where the cord leaves it: no slip)."""
        t1, t2, _e1, _e2, ell = self.tangent(P, q)
        if not self.c:
            return ell
        out = ell + self.c * (self._unwound(t1, t2) - self.alpha0)
        if self.angle is not None:
            out -= self.c * (float(q[self.angle]) - self.theta0)
        return out


@dataclass
class Spanning:
    """A cord segment that turns with both its ends, between two circles that may move: each end
    a point (ρ = 0), a disk body's centre (a moving pulley or one on a fixed axle; the cord does
    not slip on it) or a fixed light pulley's centre, with the signed radii of
    :func:`segment_tangents`.  With d = C_b − C_a = ℓ u − (ρ_b − ρ_a) n (n = e3 × u), its part of
    the cord's length is ℓ + (ρ_b − ρ_a)(ψ − ψ0) − ρ_b (θ_b − θ_b0) + ρ_a (θ_a − θ_a0) (ψ the
    angle of u; the arcs that the tangent points run over, less the turn of a disk the cord is
    wound on), whose gradient is u·(X_b − X_a) plus the disks' ∓ρ: the row of a segment kept
    straight, with u the segment's own direction at q.  Its γ adds the turning of u,
    (n·(V_b − V_a))²/ℓ, its curvature n nᵀ/ℓ on X_b − X_a."""

    A: Point                        # the centre (or point) at end a
    B: Point
    ra: float
    rb: float
    psi0: float = 0.0
    angle_a: int | None = None      # a disk body's angle index at that end
    angle_b: int | None = None
    th0a: float = 0.0
    th0b: float = 0.0
    ref: float = 0.0                # ψ at the phase's start, unwound: the arcs' branch (as Turning.ref)

    def angle_of(self, q) -> float:
        """ψ, the segment's direction, on its branch near ``ref`` (within half a turn)."""
        u1, u2, *_ = self.geometry(q)
        return unwound(self.ref, math.atan2(u2, u1))

    def mark(self, q) -> None:
        if self.rb != self.ra:
            self.ref = self.angle_of(q)

    def geometry(self, q) -> tuple[float, float, float, float, float, float, float]:
        """(u1, u2, ℓ, T_a1, T_a2, T_b1, T_b2) at q."""
        (a1, a2), (b1, b2) = self.A.xy(q), self.B.xy(q)
        d1, d2 = b1 - a1, b2 - a2
        D = math.hypot(d1, d2)
        delta = self.ra - self.rb
        if not D > 0.5 * abs(delta) or not D > 0:     # (overlapping: a trial state, as Turning.tangent's)
            raise NumericalError(f"a cord's segment lost its straight part (its ends at [{a1:.6g}, {a2:.6g}] and "
                                 f"[{b1:.6g}, {b2:.6g}] overlap): the motion is not solved past it")
        psi = math.atan2(d2, d1) - math.asin(max(-1.0, min(1.0, delta / D)))
        u1, u2 = math.cos(psi), math.sin(psi)
        ell = math.sqrt(max(D * D - delta * delta, 0.0))
        return u1, u2, ell, a1 - self.ra * u2, a2 + self.ra * u1, b1 - self.rb * u2, b2 + self.rb * u1

    def length(self, q) -> float:
        u1, u2, ell, *_ = self.geometry(q)
        out = ell
        if self.rb != self.ra:
            out += (self.rb - self.ra) * (unwound(self.ref, math.atan2(u2, u1)) - self.psi0)
        if self.angle_b is not None:
            out -= self.rb * (float(q[self.angle_b]) - self.th0b)
        if self.angle_a is not None:
            out += self.ra * (float(q[self.angle_a]) - self.th0a)
        return out

    def add_row(self, row, q) -> None:
        u1, u2, *_ = self.geometry(q)
        self.B.add_jac(row, q, u1, u2)
        self.A.add_jac(row, q, -u1, -u2)
        if self.angle_b is not None:
            row[self.angle_b] -= self.rb
        if self.angle_a is not None:
            row[self.angle_a] += self.ra

    def gamma(self, q, v) -> float:
        u1, u2, ell, *_ = self.geometry(q)
        (av1, av2), (bv1, bv2) = self.A.vel_xy(q, v), self.B.vel_xy(q, v)
        (ab1, ab2), (bb1, bb2) = self.A.bias_xy(q, v), self.B.bias_xy(q, v)
        return turning_gamma(u1, u2, ell, (bv1 - av1, bv2 - av2), (bb1 - ab1, bb2 - ab2))

    def straight_along(self, q, N, n: int) -> bool:
        """Whether u stays put along the motion q + N s: its ends move apart along u."""
        u1, u2, *_ = self.geometry(q)
        w = self.B.jac(q, n) @ N - self.A.jac(q, n) @ N
        return abs(u1 * float(w[1]) - u2 * float(w[0])) <= 1e-12 * max(math.hypot(float(w[0]), float(w[1])), 1e-300)


@dataclass
class Segment:
    a: CordEnd
    b: CordEnd
    u: np.ndarray                   # unit direction a -> b, kept from t = 0
    pulley: tuple | None = None     # (the end at a point, C, ρ, the disk body or None) when its other end is a pulley
    turning: Turning | None = None  # set when its direction turns with the point (Cord.let_turn)
    spanning: Spanning | None = None    # set when it turns with both ends (Cord.let_span)
    centres: tuple | None = None    # (C_a, ρ_a, C_b, ρ_b) at t = 0 as build placed them (ρ signed; C of a fixed pulley)

    def point(self) -> Point:
        """The body point at its turning end."""
        assert self.turning is not None
        P = (self.a if self.turning.end == "a" else self.b).point
        assert P is not None, "a turning segment ends at a point"
        return P

    def anchor(self, q) -> tuple[Point, Point, tuple[float, float, float, float, float]]:
        """(its point, a ground point at the tangent point held fixed, (T1, T2, e1, e2, ℓ))."""
        P, t = self.point(), self.turning
        assert t is not None, "only a turning segment has an anchor"
        got = t.tangent(P, q)
        return P, Point("the cord's tangent point", None, (got[0], got[1])), got


@dataclass
class Cord(Element):
    """A taut inextensible cord: one row per run between disk bodies (no slip on a disk: one
    tension per side), each the run's length Σ u·(X_b − X_a) = const; T = −λ ≥ 0 per run,
    reported once per straight segment.  A run that goes slack (``slack``) has no row until
    its length is back to the cord's: then it is jerked taut (an impulse, motion.py)."""

    runs: list[list[Segment]] = field(default_factory=list)
    consts: list[float] = field(default_factory=list)
    slack: frozenset = frozenset()

    @property
    def taut(self) -> list[int]:
        return [r for r in range(len(self.runs)) if r not in self.slack]

    @property
    def rows(self):
        return len(self.runs) - len(self.slack)

    @property
    def linear(self):
        return not any(s.a.turns or s.b.turns or s.turning is not None or s.spanning is not None
                       for run in self.runs for s in run)

    def straight_along(self, q, N) -> bool:
        """Affine along N when no end turns with its body and every turning segment's point moves
        along the segment (its tangent point stays: an end pulled straight toward its pulley)."""
        for run in self.runs:
            for s in run:
                if s.a.turns or s.b.turns:
                    return False
                if s.spanning is not None and not s.spanning.straight_along(q, N, self.n):
                    return False
                if s.turning is not None:
                    P, _T, (_t1, _t2, e1, e2, _l) = s.anchor(q)
                    w = P.jac(q, self.n) @ N
                    if abs(e1 * float(w[1]) - e2 * float(w[0])) > 1e-12 * math.hypot(float(w[0]), float(w[1])):
                        return False
        return True

    def let_turn(self, seg: Segment, q) -> None:
        """Let the segment ``seg`` (its ``pulley`` set: a body point and a fixed pulley) turn with
        its point from here on (:class:`Turning`, from its geometry at q)."""
        assert seg.pulley is not None, "a turning segment runs between a pulley and a point"
        end, C, rho, disk = seg.pulley
        t = Turning(end, (float(C[0]), float(C[1])), float(rho), 0.0, 0.0)
        P = (seg.a if end == "a" else seg.b).point
        assert P is not None
        t1, t2, e1, e2, _ell = t.tangent(P, q)
        w1, w2 = t1 - t.C[0], t2 - t.C[1]
        t.alpha0 = t.ref = math.atan2(w2, w1) if rho else 0.0
        # c = u·(e3 × (T − C)) with u from T toward P for the length's growth as T runs on: the
        # gradient of ℓ + c α is then e (its tangential part cancels)
        t.c = (e1 * -w2 + e2 * w1) if rho else 0.0
        if disk is not None:            # a disk on a fixed axle: the cord goes round with it
            t.angle = disk.index[2]
            t.theta0 = float(q[t.angle])
            t.centre = (disk.index[0], disk.index[1])
        t.mark(P, q)
        before = self.lengths(q) if self.consts else None
        seg.turning = t
        if before is not None:          # the held lengths, now measured the turning way
            self.consts = [c + a - b for c, a, b in zip(self.consts, self.lengths(q), before)]

    def drawn(self, q) -> list[list[tuple[float, float]]]:
        """The cord at q as polylines, one per straight segment from tangent point to tangent point
        (for the plots: the pulleys and disks it wraps are drawn as circles)."""
        out = []
        for run in self.runs:
            for s in run:
                if s.spanning is not None:
                    _u1, _u2, _l, a1, a2, b1, b2 = s.spanning.geometry(q)
                    out.append([(a1, a2), (b1, b2)])
                    continue
                if s.turning is not None:
                    P = s.point()
                    t1, t2, *_ = s.turning.tangent(P, q)
                    p = P.xy(q)
                    out.append([(t1, t2), p] if s.turning.end == "b" else [p, (t1, t2)])
                    continue
                out.append([s.a.drawn(s.u, q), s.b.drawn(s.u, q)])
        return out

    def _arcs(self) -> list:
        """The turning and spanning segments, in order: each keeps its arc's branch."""
        return [s.turning or s.spanning for run in self.runs for s in run if s.turning or s.spanning]

    def phase(self):
        """(the slack runs, each arc's branch and a turning segment's reach at the phase's start)."""
        return self.slack, tuple((a.ref, getattr(a, "reach", None)) for a in self._arcs())

    def set_phase(self, state) -> None:
        self.slack, refs = state
        for a, (ref, reach) in zip(self._arcs(), refs):
            a.ref = ref
            if reach is not None:
                a.reach = reach

    def let_span(self, seg: Segment, q) -> None:
        """Let the segment ``seg`` turn with both its ends from here on (:class:`Spanning`, from
        the circles build placed at its ends: a moving pulley, a rigid body's point)."""
        assert seg.centres is not None and seg.turning is None, "a spanning segment has its ends' circles"
        _Ca, ra, _Cb, rb = seg.centres
        refs: list[tuple[Point, int | None]] = []
        for end, (C, _r) in ((seg.a, seg.centres[:2]), (seg.b, seg.centres[2:])):
            if end.point is not None:
                refs.append((end.point, None))
            elif end.centre is not None:
                refs.append((end.centre, end.centre.angle_index))
            else:
                refs.append((Point("a fixed pulley's centre", None, (float(C[0]), float(C[1]))), None))
        (A, ia), (B, ib) = refs
        sp = Spanning(A, B, float(ra), float(rb), angle_a=ia, angle_b=ib)
        u1, u2, *_ = sp.geometry(q)
        sp.psi0 = sp.ref = math.atan2(u2, u1)
        sp.th0a = float(q[ia]) if ia is not None else 0.0
        sp.th0b = float(q[ib]) if ib is not None else 0.0
        before = self.lengths(q) if self.consts else None
        seg.spanning = sp
        if before is not None:
            self.consts = [c + a - b for c, a, b in zip(self.consts, self.lengths(q), before)]

    def _part(self, s: Segment, q) -> float:
        if s.spanning is not None:
            return s.spanning.length(q)
        if s.turning is not None:
            return s.turning.length(s.point(), q)
        return s.b.proj(s.u, q) - s.a.proj(s.u, q)

    def lengths(self, q) -> np.ndarray:
        return np.array([sum(self._part(s, q) for s in run) for run in self.runs])

    def phi(self, q, t):
        return (self.lengths(q) - np.array(self.consts))[self.taut]

    def _run_row(self, q, r: int) -> list:
        row = [0.0] * self.n
        for s in self.runs[r]:
            if s.spanning is not None:
                s.spanning.add_row(row, q)
            elif s.turning is not None:
                P, _T, (_t1, _t2, e1, e2, _l) = s.anchor(q)
                P.add_jac(row, q, e1, e2)
                if s.turning.angle is not None:
                    row[s.turning.angle] -= s.turning.c
                if s.turning.centre is not None:    # the pulley moved by δC: ℓ changes by −e·δC (the
                    i1, i2 = s.turning.centre       # axle holds it: no motion, but the segment's pull
                    row[i1] -= e1                   # on the disk is in its axle's reaction)
                    row[i2] -= e2
            else:
                s.b.add_jac(row, s.u, q, 1.0)
                s.a.add_jac(row, s.u, q, -1.0)
        return row

    def jac_list(self, q):
        return [self._run_row(q, r) for r in self.taut]

    def gamma_list(self, q, v, t):
        out = []
        for r in self.taut:
            g = 0.0
            for s in self.runs[r]:
                if s.spanning is not None:
                    g += s.spanning.gamma(q, v)
                elif s.turning is not None:     # a string's from the tangent point held fixed
                    P, _T, (_t1, _t2, e1, e2, ell) = s.anchor(q)
                    g += turning_gamma(e1, e2, ell, P.vel_xy(q, v), P.bias_xy(q, v))
                else:
                    g -= s.b.bias(s.u, q, v) - s.a.bias(s.u, q, v)
            out.append(g)
        return out

    def jac(self, q):
        return np.array(self.jac_list(q)).reshape(self.rows, self.n)

    def gamma(self, q, v, t):
        return np.array(self.gamma_list(q, v, t))

    def run_rate(self, q, v, r: int) -> float:
        """d/dt of run r's length (its row's rate): negative while a slack run takes up slack."""
        return float(np.array(self._run_row(q, r)) @ v)

    def tensions(self, lam) -> list[float]:
        """T per run: −λ of a taut run, 0 of a slack one."""
        out, k = [], 0
        for r in range(len(self.runs)):
            if r in self.slack:
                out.append(0.0)
            else:
                out.append(-float(lam[k]))
                k += 1
        return out

    def report(self, lam, q, v, t):
        T = self.tensions(lam)
        return {"T": [T[r] for r, run in enumerate(self.runs) for _ in run]}

    def watch(self, lam, q, v, t):
        T, gap = self.tensions(lam), np.array(self.consts) - self.lengths(q)
        out = [("taut", float(gap[r])) if r in self.slack else ("slack", T[r]) for r in range(len(self.runs))]
        return out + [("reaches", g) for g in self.reach_gaps(q)] + [("turns", g) for g in self.turn_gaps(q)]

    def mark(self, q) -> None:
        """A phase starts at q: each turning segment keeps its tangent point and direction there,
        and each arc its branch."""
        for run in self.runs:
            for s in run:
                if s.turning is not None:
                    s.turning.mark(s.point(), q)
                elif s.spanning is not None:
                    s.spanning.mark(q)

    def turn_gaps(self, q) -> list[float]:
        """Per segment with an arc (a turning segment over a round pulley, a spanning one between
        circles of unequal signed radii): |c| (cos Δ + √½), Δ its angle from the phase's start —
        crossing 0 three eighths of a turn away (the watch ``turns``: a new phase, no event, the
        arc's branch moved on, so that a segment may go round its pulley any number of times)."""
        out = []
        for run in self.runs:
            for s in run:
                if s.turning is not None and s.turning.c:
                    c, d = s.turning.c, s.turning.angle_of(s.point(), q) - s.turning.ref
                elif s.spanning is not None and s.spanning.rb != s.spanning.ra:
                    c, d = s.spanning.rb - s.spanning.ra, s.spanning.angle_of(q) - s.spanning.ref
                else:
                    continue
                out.append(abs(c) * (math.cos(d) + math.sqrt(0.5)))
        return out

    def reach_gaps(self, q) -> list[float]:
        """Per segment of a taut run whose ends can move, crossing 0 where its end reaches its pulley
        (the event ``reaches``: the motion stops there); of a segment kept along its direction u
        of t = 0, the straight part u·(T_b − T_a); of one that turns, signed (√|D² − δ²| with
        the sign of D² − δ²: negative where the end would be inside its pulley, or two circles
        overlap), from a fixed pulley the smaller of it and Turning.reach_gap (an end that runs
        onto the pulley along its segment, where the straight part only touches 0) — each less
        :data:`REACH` of the cord's length (at 0 the segment's direction is not defined)."""
        out = []
        eps = REACH * max((abs(c) for c in self.consts), default=0.0)
        for r in self.taut:
            for s in self.runs[r]:
                if s.spanning is not None:
                    sp = s.spanning
                    (a1, a2), (b1, b2) = sp.A.xy(q), sp.B.xy(q)
                    out.append(signed_root((b1 - a1) ** 2 + (b2 - a2) ** 2 - (sp.ra - sp.rb) ** 2) - eps)
                elif s.turning is not None:
                    P, (c1, c2) = s.point(), s.turning.C
                    p1, p2 = P.xy(q)
                    straight = signed_root((p1 - c1) ** 2 + (p2 - c2) ** 2 - s.turning.rho ** 2)
                    out.append(min(s.turning.reach_gap(P, q), straight) - eps)
                elif s.a.fixed is None or s.b.fixed is None:
                    # kept along u (a hanging mass guided along its segment, a yo-yo's string):
                    # the straight part u·(T_b − T_a) between its ends' tangent points
                    (a1, a2), (b1, b2) = s.a.drawn(s.u, q), s.b.drawn(s.u, q)
                    out.append(float(s.u[0]) * (b1 - a1) + float(s.u[1]) * (b2 - a2) - eps)
        return out


@dataclass
class String(Cord):
    """A cord of one straight segment between two points, over no pulley (a ball whirled on a
    string, a mass hanging from a ceiling point): its length is |r_b − r_a| itself, its direction
    turning with the points — a link (36) that can only pull (T ≥ 0), goes slack and is jerked
    taut as any cord.  (A cord over pulleys keeps its segments' directions of t = 0.)"""

    linear = False                  # (Cord's is a property of its ends)

    def ends(self) -> tuple[Point, Point]:
        """(the point at its far end, the point at its first): its length is |r_b − r_a|."""
        seg = self.runs[0][0]
        assert seg.a.point is not None and seg.b.point is not None, "a string runs between two points"
        return seg.b.point, seg.a.point

    def span(self, q) -> tuple[Point, Point]:
        """(its far end, the point its straight part runs from) at q: its ends (a string over a
        round peg: the point where it leaves the peg, as if fixed there — its row, γ and
        curvature are those of a string from that point)."""
        return self.ends()

    def drawn(self, q) -> list[list[tuple[float, float]]]:
        P, Q = self.ends()
        (p1, p2), (q1, q2) = P.xy(q), Q.xy(q)
        return [[(float(q1), float(q2)), (float(p1), float(p2))]]

    def lengths(self, q) -> np.ndarray:
        P, Q = self.ends()
        (p1, p2), (q1, q2) = P.xy(q), Q.xy(q)
        return np.array([math.hypot(p1 - q1, p2 - q2)])

    def jac_list(self, q):
        return [span_row(*self.span(q), q, self.n)] if not self.slack else []

    def gamma_list(self, q, v, t):
        return [span_gamma(*self.span(q), q, v)] if not self.slack else []

    def run_rate(self, q, v, r: int) -> float:
        return float(np.array(span_row(*self.span(q), q, self.n)) @ v)

    def reach_gaps(self, q) -> list[float]:
        """None: a string's one straight part is its whole length, held by its row (a peg's
        wrapping has watches of its own)."""
        return []

    def straight_along(self, q, N) -> bool:
        """Whether its direction stays put along the motion q + N s (its ends on bodies that do
        not turn, moving apart along its own line: blocks tied in a row on a floor): its row is
        then affine along that motion, as a cord's over pulleys."""
        P, Q = self.ends()
        if P.turns_with_body or Q.turns_with_body:
            return False
        d = P.pos(q) - Q.pos(q)
        w = P.jac(q, self.n) @ N - Q.jac(q, self.n) @ N
        return abs(float(d[0] * w[1] - d[1] * w[0])) <= 1e-12 * math.hypot(*d) * math.hypot(*w)

    def hessian(self, q, w, n: int) -> np.ndarray:
        """Σ λ ∇²φ of its row (curvature.py: the equilibria's stiffness of a taut string)."""
        from .curvature import length_terms

        if self.slack:
            return np.zeros((n, n))
        return w[0] * length_terms(*self.span(q), q, n)[3]


@dataclass
class PeggedString(String):
    """A string from a fixed point to a body point that catches fixed smooth pegs: where its
    straight line sweeps onto a peg (the peg between its ends) it bends there — the event
    ``wraps``: from then on it is a string from that peg with the length left (the part to the peg
    is still), no impulse (the point's velocity is normal to the string both ways); where it swings
    back straight it leaves the peg (``unwraps``).  Its tension is the same on every part (smooth
    pegs): T is reported once.

    Each watch is one-sided (downwards through 0), its sign kept with the phase: a peg's signed
    distance from the free part's line, ``sides[i]`` · (d × (p − A))/|d|, crosses 0 where the line
    passes the peg — a wrap when the peg is between the ends (and the string taut), else only the
    side changes (a phase of its own, no event); the last wrapped peg's bend, s · |B − P| sin θ
    (θ from the part before it to the free part), crosses 0 at each half turn: back through θ = 0
    it leaves the peg, on through θ = kπ the free part has turned another half turn about it (a
    whirl about the nail, no event).

    A round peg (``radii[i]`` = ρ > 0, centre C) is caught where the line comes within ρ of C
    (the watch side·d − ρ; a line that sweeps over it beyond an end watches its far edge, side·d
    + ρ, and its near edge again, ρ − side·d, until it is past or back).  Wrapped, the string
    leaves it at the tangent point T from B: with r = B − C, the free part ℓ = √(|r|² − ρ²) and the
    wound angle β = s (ψ − s arccos(ρ/|r|) − α_in) (ψ the angle of r, α_in that of the point
    where it was caught, s = ±1 the sense it winds), its length ℓ + ρ β is held.  The row, γ and
    curvature are a string's from T held fixed (T moves along the free part's own line: d(ℓ +
    ρβ)/dr is the unit vector T → B).  β's half turns are counted as a point peg's (the watch
    (−1)^k ρ sin β, k the half turns: an event only back through β = 0, ``unwraps``); the string
    may wind many turns onto the post.  Its record in ``bends`` is (s, k, α_in, the point where
    it leaves the post once a later peg holds that point fixed, else None)."""

    pegs: list = field(default_factory=list)         # ground Points (a round peg: its centre)
    radii: list = field(default_factory=list)        # per peg: 0 (a point) or its radius
    wrapped: tuple = ()                              # indices into pegs, from the fixed end on
    sides: tuple = ()                                # per peg: the sign of its line watch (±2: passing over a round one)
    bends: tuple = ()                                # per wrapped peg: (the bend watch's sign, half turns), or a round one's

    def _end(self, which: str) -> Point:
        """The string's fixed end ("a") or its body point ("b")."""
        P = getattr(self.runs[0][0], which).point
        assert P is not None, "a string over pegs runs between two points"
        return P

    def _radius(self, i: int) -> float:
        return self.radii[i] if self.radii else 0.0

    def _winding(self) -> bool:
        """Whether the free part leaves a round peg (its length: the free part and the arc)."""
        return bool(self.wrapped) and self._radius(self.wrapped[-1]) > 0

    def anchor(self) -> Point:
        return self.pegs[self.wrapped[-1]] if self.wrapped else self._end("a")

    def ends(self) -> tuple[Point, Point]:
        return self._end("b"), self.anchor()

    def _departure(self, j: int, q) -> Point:
        """The point where the string leaves the j-th wrapped peg: the peg, or a round peg's
        tangent point (held where a later peg fixed it)."""
        i = self.wrapped[j]
        if not self._radius(i):
            return self.pegs[i]
        held = self.bends[j][3]
        if held is not None:
            return Point("the string's point off its peg", None, held)
        return Point("the string's point off its peg", None, self._wound(q)[0])

    def free_from(self, q) -> Point:
        """The point the free part of the string runs from at q."""
        return self._departure(len(self.wrapped) - 1, q) if self.wrapped else self._end("a")

    def _before(self, q) -> Point:
        """The point before the last wrapped peg (where it leaves the previous peg, or the fixed end)."""
        return self._departure(len(self.wrapped) - 2, q) if len(self.wrapped) > 1 else self._end("a")

    def _wound(self, q) -> tuple[tuple[float, float], float]:
        """(the tangent point T, the wound angle β) of the last wrapped peg, a round one."""
        i = self.wrapped[-1]
        rho, (c1, c2) = self._radius(i), self.pegs[i].p
        s, k, a_in, _held = self.bends[-1]
        b1, b2 = self._end("b").xy(q)
        r1, r2 = b1 - c1, b2 - c2
        d = math.hypot(r1, r2)
        if not d > rho:
            raise NumericalError(f"the end of the string {self.name!r} reached the round peg at [{c1:g}, {c2:g}] "
                                 "(the string wound up to it): the motion is not solved past it; ask for times before it (at, t_end)")
        at = math.atan2(r2, r1) - s * math.acos(rho / d)
        lo = k * math.pi - 0.5 * math.pi            # β in the phase's window, [kπ − π/2, kπ + 3π/2)
        beta = lo + (s * (at - a_in) - lo) % (2 * math.pi)
        return (c1 + rho * math.cos(at), c2 + rho * math.sin(at)), beta

    def span(self, q) -> tuple[Point, Point]:
        return self._end("b"), self.free_from(q)

    def drawn(self, q) -> list[list[tuple[float, float]]]:
        """One polyline from the fixed end over the wrapped pegs (a round one: the arc wound on it)
        to the body's point."""
        pts: list[tuple[float, float]] = [self._end("a").xy(q)]
        for j, i in enumerate(self.wrapped):
            rho = self._radius(i)
            if not rho:
                pts.append((float(self.pegs[i].p[0]), float(self.pegs[i].p[1])))
                continue
            (c1, c2), bend = self.pegs[i].p, self.bends[j]
            s, a_in, held = bend[0], bend[2], bend[3]
            if held is None:
                beta = self._wound(q)[1]
            else:
                beta = (s * (math.atan2(held[1] - c2, held[0] - c1) - a_in)) % (2 * math.pi)
            m = max(2, int(abs(beta) / (math.pi / 24)) + 2)
            pts += [(c1 + rho * math.cos(a_in + s * beta * k / (m - 1)), c2 + rho * math.sin(a_in + s * beta * k / (m - 1)))
                    for k in range(m)]
        pts.append(self._end("b").xy(q))
        return [pts]

    def lengths(self, q) -> np.ndarray:
        if not self._winding():
            return super().lengths(q)
        (t1, t2), beta = self._wound(q)
        b1, b2 = self._end("b").xy(q)
        return np.array([math.hypot(b1 - t1, b2 - t2) + self._radius(self.wrapped[-1]) * beta])

    def phase(self):
        return (self.slack, self.wrapped, self.sides, self.bends, tuple(self.consts))

    def set_phase(self, state) -> None:
        self.slack, self.wrapped, self.sides, self.bends, consts = state
        self.consts = list(consts)

    def straight_along(self, q, N) -> bool:
        return False

    def start_sides(self, q) -> None:
        """The sign of each peg's line watch at t = 0: positive on the peg's side (±2: a round peg
        the line passes over beyond an end, |d| < ρ)."""
        B, A = self.ends()
        sides = []
        for i, p in enumerate(self.pegs):
            o = self._offset(A, B, p, q)[0]
            sides.append((1.0 if o > 0 else -1.0) * (2.0 if abs(o) < self._radius(i) else 1.0))
        self.sides = tuple(sides)

    @staticmethod
    def _offset(A: Point, B: Point, P: Point, q) -> tuple[float, float]:
        """(the signed distance of P from the line A → B, positive on its left; P's place along
        A → B as a fraction of |B − A|)."""
        (a1, a2), (b1, b2), (p1, p2) = A.xy(q), B.xy(q), P.xy(q)
        d1, d2, w1, w2 = b1 - a1, b2 - a2, p1 - a1, p2 - a2
        dd = d1 * d1 + d2 * d2
        return (d1 * w2 - d2 * w1) / math.sqrt(dd), (d1 * w1 + d2 * w2) / dd

    def _bend(self, q) -> tuple[float, float]:
        """(|B − P| sin θ, cos θ) of the free part B − P against the part before, A' → P."""
        P, A, B = self.anchor(), self._before(q), self._end("b")
        (a1, a2), (p1, p2), (b1, b2) = A.xy(q), P.xy(q), B.xy(q)
        u1, u2, w1, w2 = p1 - a1, p2 - a2, b1 - p1, b2 - p2
        lu = math.hypot(u1, u2)
        return (u1 * w2 - u2 * w1) / lu, (u1 * w1 + u2 * w2) / (lu * math.hypot(w1, w2))

    def _line_watches(self, q) -> list[tuple[int, str, float]]:
        """(peg, "near" / "far" / "back", g) of every peg not wrapped: its line watch (a round peg
        passing over beyond an end: two)."""
        B, A = self._end("b"), self.free_from(q)
        out = []
        for i, p in enumerate(self.pegs):
            if i in self.wrapped:
                continue
            o, rho, side = self._offset(A, B, p, q)[0], self._radius(i), self.sides[i]
            if abs(side) < 1.5:
                out.append((i, "near", side * o - rho))
            else:
                out += [(i, "far", 0.5 * side * o + rho), (i, "back", rho - 0.5 * side * o)]
        return out

    def watch(self, lam, q, v, t):
        out = super().watch(lam, q, v, t)
        out += [("wraps", g) for _i, _kind, g in self._line_watches(q)]
        if self._winding():
            k = self.bends[-1][1]
            out.append(("unwraps", (-1.0) ** k * self._radius(self.wrapped[-1]) * math.sin(self._wound(q)[1])))
        elif self.wrapped:
            out.append(("unwraps", self.bends[-1][0] * self._bend(q)[0]))
        return out

    def _hold_departure(self, q) -> None:
        """A peg is caught after a round one: the point where the string leaves the round one stays."""
        if self._winding():
            s, k, a_in, _ = self.bends[-1]
            self.bends = self.bends[:-1] + ((s, k, a_in, self._wound(q)[0]),)

    def _free_departure(self) -> None:
        """The peg after a round one is left: the string leaves the round one where the free part goes."""
        if self._winding():
            s, k, a_in, _ = self.bends[-1]
            self.bends = self.bends[:-1] + ((s, k, a_in, None),)

    def turn(self, q, v, what: str) -> str | None:
        """The change at a located crossing of a ``wraps`` or ``unwraps`` watch: the event's name,
        or None for a crossing that only turns a watch's sign (no event)."""
        B, A = self._end("b"), self.free_from(q)
        vb1, vb2 = B.vel_xy(q, v)
        if what == "wraps":
            i, kind, _g = min(self._line_watches(q), key=lambda w: abs(w[2]))
            side, rho = self.sides[i], self._radius(i)
            if kind != "near":          # a line passing over a round peg beyond an end: past it, or back
                new = -0.5 * side if kind == "far" else 0.5 * side
                self.sides = self.sides[:i] + (new,) + self.sides[i + 1:]
                return None
            _, place = self._offset(A, B, self.pegs[i], q)
            if self.slack or not 0.0 < place < 1.0:
                # the line passed the peg beyond an end (or slack): its side only (over a round one: its far edge next)
                new = 2.0 * side if rho else -side
                self.sides = self.sides[:i] + (new,) + self.sides[i + 1:]
                return None
            if rho:
                self._catch_round(i, q, A, B, place)
                return "wraps"
            self.sides = self.sides[:i] + (-side,) + self.sides[i + 1:]
            (a1, a2), (p1, p2) = A.xy(q), self.pegs[i].xy(q)
            u1, u2 = p1 - a1, p2 - a2
            winding = self._winding()
            self._hold_departure(q)
            self.wrapped = self.wrapped + (i,)
            self.consts = [self.lengths(q)[0]] if winding else [self.consts[0] - math.hypot(u1, u2)]
            # the free part turns on about the peg the way it turned about A
            self.bends = self.bends + ((1.0 if u1 * vb2 - u2 * vb1 >= 0 else -1.0, 0),)
            return "wraps"
        if self._winding():
            return self._unwind(q, B)
        (sign, k), cos = self.bends[-1], self._bend(q)[1]
        if (cos > 0) == (k % 2 == 1):       # on through (k + 1)π: another half turn about the peg
            self.bends = self.bends[:-1] + ((-sign, k + 1),)
            return None
        if k > 0:                           # back through kπ
            self.bends = self.bends[:-1] + ((-sign, k - 1),)
            return None
        i, P = self.wrapped[-1], self.anchor()
        (a1, a2), (p1, p2) = self._before(q).xy(q), P.xy(q)
        self.wrapped, self.bends = self.wrapped[:-1], self.bends[:-1]
        self._free_departure()
        self.consts = [self.lengths(q)[0]] if self._winding() else [self.consts[0] + math.hypot(p1 - a1, p2 - a2)]
        # the peg left is on the free part's line again: its watch turns positive the way B goes,
        # d/dt (d × (p − A)) = v_B × (p − A) there
        (a1, a2) = self.free_from(q).xy(q)
        rate = vb1 * (p2 - a2) - vb2 * (p1 - a1)
        self.sides = self.sides[:i] + ((1.0 if rate >= 0 else -1.0),) + self.sides[i + 1:]
        return "unwraps"

    def _catch_round(self, i: int, q, A: Point, B: Point, place: float) -> None:
        """The free line A → B touches the round peg i at the foot T0 of its centre: it winds on
        from there, the way that leaves it from T0 toward B."""
        (a1, a2), (b1, b2) = A.xy(q), B.xy(q)
        (c1, c2), rho = self.pegs[i].p, self._radius(i)
        t1, t2 = a1 + place * (b1 - a1), a2 + place * (b2 - a2)
        a_in = math.atan2(t2 - c2, t1 - c1)
        psi, off = math.atan2(b2 - c2, b1 - c1), math.acos(min(1.0, rho / math.hypot(b1 - c1, b2 - c2)))

        def miss(s: float) -> float:
            return abs(math.remainder(psi - s * off - a_in, 2 * math.pi))
        s = 1.0 if miss(1.0) <= miss(-1.0) else -1.0
        self._hold_departure(q)
        self.wrapped = self.wrapped + (i,)
        self.bends = self.bends + ((s, 0, a_in, None),)
        self.consts = [self.lengths(q)[0]]

    def _unwind(self, q, B: Point) -> str | None:
        """A half turn of β on the last wrapped peg, a round one (no event), or β back through 0:
        the string leaves it (``unwraps``)."""
        s, k, a_in, _ = self.bends[-1]
        beta = self._wound(q)[1]
        if beta - k * math.pi > 0.5 * math.pi:          # on through (k + 1)π
            self.bends = self.bends[:-1] + ((s, k + 1, a_in, None),)
            return None
        if k > 0:
            self.bends = self.bends[:-1] + ((s, k - 1, a_in, None),)
            return None
        i = self.wrapped[-1]
        self.wrapped, self.bends = self.wrapped[:-1], self.bends[:-1]
        self._free_departure()
        self.consts = [self.lengths(q)[0]]
        # straight again from the point before: the peg touches the free line on the side it wound
        o = self._offset(self.free_from(q), B, self.pegs[i], q)[0]
        self.sides = self.sides[:i] + ((1.0 if o >= 0 else -1.0),) + self.sides[i + 1:]
        return "unwraps"


@dataclass(kw_only=True)
class Guide(ListRows):
    """A point mass at a cord segment's end moves along the segment (its direction of t = 0)."""

    P: Point
    w: np.ndarray                   # unit normal of the segment
    c0: float = 0.0
    segment: Segment | None = None  # the cord's segment it guides along
    rows = 1

    def phi_list(self, q, t):
        x1, x2 = self.P.xy(q)
        return [float(self.w[0]) * x1 + float(self.w[1]) * x2 - self.c0]

    def jac_list(self, q):
        row = [0.0] * self.n
        self.P.add_jac(row, q, float(self.w[0]), float(self.w[1]))
        return [row]

    def gamma_list(self, q, v, t):
        return [0.0]

    def phi_many(self, X, td):
        x1, x2 = self.P.xy_many(X)
        return (float(self.w[0]) * x1 + float(self.w[1]) * x2 - self.c0)[:, None]

    def jac_many(self, X, J):
        self.P.add_jac_many(J[:, 0], X, float(self.w[0]), float(self.w[1]))


def segment_tangents(Ca, ra, Cb, rb):
    """The straight segment between two circles (centre, signed radius ρ: the cord runs with
    the circle's centre at ρ·(e3 × u) ... on its right for ρ > 0): returns (u, Ta, Tb) with
    T = C + ρ (e3 × u).  A point is a circle of radius 0."""
    d = np.asarray(Cb, float) - np.asarray(Ca, float)
    D = math.hypot(d[0], d[1])
    delta = ra - rb
    if D <= abs(delta):
        return None
    phi = math.atan2(d[1], d[0])
    psi = phi - math.asin(delta / D)
    u = np.array([math.cos(psi), math.sin(psi)])
    nrm = perp(u)
    return u, np.asarray(Ca, float) + ra * nrm, np.asarray(Cb, float) + rb * nrm
