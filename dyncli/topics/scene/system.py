"""A scene in plain numbers: bodies in maximal coordinates and the kinematics of their points.

Every body keeps its own coordinates (a point: x1, x2; a rigid body: x1, x2, θ), stacked in
one vector q; the mass matrix is diagonal (m, m, Ī₃₃ per rigid body, 29.5 and 32.15).  A point
of a body is r = x + Q(θ) p with p on the body's e'1, e'2; its velocity v = ẋ + ω e3 × Q p (13.8)
and acceleration a = ẍ + α e3 × Q p − ω² Q p (14.8).  Nothing here knows the input model.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np


@dataclass
class BodyData:
    name: str
    mass: float
    inertia: float | None        # Ī₃₃ about the centre; None for a point body
    index: tuple[int, ...]       # (i_x1, i_x2) or (i_x1, i_x2, i_θ) in q
    points: dict[str, tuple[float, float]] = field(default_factory=dict)
    shape: str = "point"
    length: float = 0.0          # rod
    radius: float = 0.0          # disk, ring
    size: tuple[float, float] = (0.0, 0.0)   # box

    @property
    def rigid(self) -> bool:
        return self.inertia is not None


@dataclass(frozen=True)
class Point:
    """A point: on a body (``body`` set, ``p`` on its e'1, e'2) or on the ground (``p`` fixed)."""

    label: str
    body: BodyData | None
    p: tuple[float, float]

    def xy(self, q) -> tuple[float, float]:
        """r as two floats (the position without an array: the inner loop's form)."""
        b = self.body
        if b is None:
            return float(self.p[0]), float(self.p[1])
        i = b.index
        x1, x2 = float(q[i[0]]), float(q[i[1]])
        if b.inertia is not None and (self.p[0] or self.p[1]):
            a1, a2 = self._arm(float(q[i[2]]))
            return x1 + a1, x2 + a2
        return x1, x2

    def pos(self, q) -> np.ndarray:
        return np.array(self.xy(q), dtype=float)

    def kin(self, q: list, v: list) -> tuple:
        """(r1, r2, v1, v2, b1, b2, arm) in plain floats (q, v: lists of floats), the arm Q(θ) p
        computed once (None for a point that does not turn): what xy, vel_xy and bias_xy give,
        by the same operations."""
        b = self.body
        if b is None:
            return self._ground_kin
        i = b.index
        if self.turns_with_body:
            th, w = q[i[2]], v[i[2]]
            c, s = math.cos(th), math.sin(th)
            p1, p2 = self.p
            a1, a2 = c * p1 - s * p2, s * p1 + c * p2
            return q[i[0]] + a1, q[i[1]] + a2, v[i[0]] - w * a2, v[i[1]] + w * a1, -w * w * a1, -w * w * a2, (a1, a2)
        return q[i[0]], q[i[1]], v[i[0]], v[i[1]], 0.0, 0.0, None

    def add_jac_arm(self, row, arm, w1: float, w2: float) -> None:
        """:meth:`add_jac` with the arm of :meth:`kin` (not computed again)."""
        b = self.body
        if b is None:
            return
        i = b.index
        row[i[0]] += w1
        row[i[1]] += w2
        if arm is not None:
            row[i[2]] += arm[0] * w2 - arm[1] * w1

    def _arm(self, th: float) -> tuple[float, float]:
        c, s = math.cos(th), math.sin(th)
        p1, p2 = self.p
        return c * p1 - s * p2, s * p1 + c * p2

    def arm(self, q) -> np.ndarray:
        """Q(θ) p: the point's offset from its body's centre on the fixed basis."""
        if self.body is None or not self.body.rigid:
            return np.zeros(2)
        return np.array(self._arm(float(q[self.body.index[2]])))

    def jac(self, q, n: int) -> np.ndarray:
        """∂r/∂q, 2 × n."""
        J = np.zeros((2, n))
        if self.body is not None:
            self.add_jac(J[0], q, 1.0, 0.0)
            self.add_jac(J[1], q, 0.0, 1.0)
        return J

    def add_jac(self, row, q, w1: float, w2: float) -> None:
        """row += w·∂r/∂q for the fixed vector w = (w1, w2), in place (no array built: one row of
        a joint's Jacobian from the points it joins)."""
        b = self.body
        if b is None:
            return
        i = b.index
        row[i[0]] += w1
        row[i[1]] += w2
        if b.inertia is not None and (self.p[0] or self.p[1]):
            a1, a2 = self._arm(float(q[i[2]]))
            row[i[2]] += a1 * w2 - a2 * w1          # w·(e3 × Q p)

    def add_jac2_arm(self, r1, r2, arm, sign: float) -> None:
        """:meth:`add_jac2` with the arm of :meth:`kin` (not computed again)."""
        b = self.body
        if b is None:
            return
        i = b.index
        r1[i[0]] += sign
        r2[i[1]] += sign
        if arm is not None:
            r1[i[2]] -= sign * arm[1]
            r2[i[2]] += sign * arm[0]

    def add_jac2(self, r1, r2, q, sign: float) -> None:
        """(r1, r2) += sign · ∂r/∂q, in place (a pin's two rows: arrays or lists)."""
        b = self.body
        if b is None:
            return
        turns = b.inertia is not None and (self.p[0] or self.p[1])
        self.add_jac2_arm(r1, r2, self._arm(float(q[b.index[2]])) if turns else None, sign)

    def vel_xy(self, q, v) -> tuple[float, float]:
        b = self.body
        if b is None:
            return 0.0, 0.0
        i = b.index
        v1, v2 = float(v[i[0]]), float(v[i[1]])
        if b.inertia is not None and (self.p[0] or self.p[1]):
            a1, a2 = self._arm(float(q[i[2]]))
            w = float(v[i[2]])
            return v1 - w * a2, v2 + w * a1
        return v1, v2

    def vel(self, q, v) -> np.ndarray:
        return np.array(self.vel_xy(q, v), dtype=float)

    def bias_xy(self, q, v) -> tuple[float, float]:
        """J̇ v: the part of the acceleration not linear in q̈ (−ω² Q p, 14.8)."""
        b = self.body
        if b is None or b.inertia is None or not (self.p[0] or self.p[1]):
            return 0.0, 0.0
        i = b.index
        w = float(v[i[2]])
        a1, a2 = self._arm(float(q[i[2]]))
        return -w * w * a1, -w * w * a2

    def bias(self, q, v) -> np.ndarray:
        return np.array(self.bias_xy(q, v), dtype=float)

    # --- many states at once (X: a Stack of k states): the same operations in the same order as
    # the one-state forms above, on columns (equal to them bit for bit)
    def arms_many(self, X) -> tuple[np.ndarray, np.ndarray] | None:
        """Q(θ) p at every state, two columns (None for a point that does not turn with a body)."""
        b = self.body
        if b is None or b.inertia is None or not (self.p[0] or self.p[1]):
            return None
        got = X.arms.get(id(self))
        if got is None:
            c, s = X.trig(b.index[2])
            p1, p2 = self.p
            got = X.arms[id(self)] = (c * p1 - s * p2, s * p1 + c * p2)
        return got

    def xy_many(self, X) -> tuple[np.ndarray, np.ndarray]:
        """r at every state: two columns (a ground point's broadcast to the states)."""
        b = self.body
        if b is None:
            return np.full(X.k, float(self.p[0])), np.full(X.k, float(self.p[1]))
        i = b.index
        x1, x2 = X.Q[:, i[0]], X.Q[:, i[1]]
        a = self.arms_many(X)
        if a is not None:
            return x1 + a[0], x2 + a[1]
        return x1, x2

    def add_jac_many(self, rows, X, w1, w2) -> None:
        """rows (k, n) += w·∂r/∂q at every state (w1, w2: numbers or columns)."""
        b = self.body
        if b is None:
            return
        i = b.index
        rows[:, i[0]] += w1
        rows[:, i[1]] += w2
        a = self.arms_many(X)
        if a is not None:
            rows[:, i[2]] += a[0] * w2 - a[1] * w1

    def add_jac2_many(self, J, X, sign: float) -> None:
        """J[:, :2] += sign · ∂r/∂q at every state (a pin's two rows; J is (k, 2, n))."""
        b = self.body
        if b is None:
            return
        i = b.index
        J[:, 0, i[0]] += sign
        J[:, 1, i[1]] += sign
        a = self.arms_many(X)
        if a is not None:
            J[:, 0, i[2]] -= sign * a[1]
            J[:, 1, i[2]] += sign * a[0]

    def vel_many(self, X, V) -> tuple[np.ndarray, np.ndarray]:
        b = self.body
        if b is None:
            z = np.zeros(X.k)
            return z, z
        i = b.index
        v1, v2 = V[:, i[0]], V[:, i[1]]
        a = self.arms_many(X)
        if a is not None:
            w = V[:, i[2]]
            return v1 - w * a[1], v2 + w * a[0]
        return v1, v2

    def bias_many(self, X, V) -> tuple[np.ndarray, np.ndarray]:
        """J̇ v at every state, two columns (zeros for a point not turning)."""
        a = self.arms_many(X)
        if a is None or self.body is None:
            z = np.zeros(X.k)
            return z, z
        w = V[:, self.body.index[2]]
        return -w * w * a[0], -w * w * a[1]

    @functools.cached_property
    def _ground_kin(self) -> tuple:
        """:meth:`kin` of a point of the ground (made once: it never moves)."""
        return float(self.p[0]), float(self.p[1]), 0.0, 0.0, 0.0, 0.0, None

    @functools.cached_property
    def turns_with_body(self) -> bool:
        """True when r depends on the body's angle (a rigid body's point off its centre)."""
        return self.body is not None and self.body.rigid and (self.p[0] != 0 or self.p[1] != 0)


@dataclass(frozen=True)
class BodyPoint(Point):
    """A point of a body (never of the ground): a body's centre held by a slider, a rolling
    disk's centre, a cord's disk."""

    body: BodyData

    @property
    def angle_index(self) -> int:
        """The index of its body's angle in q (a rigid body)."""
        return self.body.index[2]


@dataclass(frozen=True)
class SurfaceData:
    name: str
    origin: tuple[float, float]
    d: tuple[float, float]       # unit direction
    n: tuple[float, float]       # e3 × d̂: the side the bodies are on
    length: float | None = None  # it runs from origin to origin + length d̂ (None: no end)

    def ends_margin(self, r) -> float | None:
        """How far the point r (on the line) is from the nearer end; None without ends."""
        if self.length is None:
            return None
        s = (r[0] - self.origin[0]) * self.d[0] + (r[1] - self.origin[1]) * self.d[1]
        return float(min(s, self.length - s))


class Stack:
    """Many states of a scene at once: Q (k, n), one state a row, with the cos and sin of each
    body's angle and each point's arm Q(θ) p computed once for all the rows that use them."""

    def __init__(self, Q):
        self.Q = Q
        self.k = len(Q)
        self._trig: dict[int, tuple[np.ndarray, np.ndarray]] = {}
        self.arms: dict[int, tuple[np.ndarray, np.ndarray]] = {}    # by id of the Point

    def trig(self, i: int) -> tuple[np.ndarray, np.ndarray]:
        """(cos, sin) of the coordinate i (a body's angle) at every state."""
        got = self._trig.get(i)
        if got is None:
            th = self.Q[:, i]
            got = self._trig[i] = (np.cos(th), np.sin(th))
        return got


def perp(a) -> np.ndarray:
    """e3 × a."""
    return np.array([-a[1], a[0]], dtype=float)
