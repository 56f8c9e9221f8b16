"""A scene in plain numbers: bodies in maximal coordinates and the kinematics of their points.

Every body keeps its own coordinates (a point: x1, x2; a rigid body: x1, x2, θ), stacked in
one vector q; the mass matrix is diagonal (m, m, Ī₃₃ per rigid body, 29.5 and 32.15).  A point
of a body is r = x + Q(θ) p with p on the body's e'1, e'2; its velocity v = ẋ + ω e3 × Q p (13.8)
and acceleration a = ẍ + α e3 × Q p − ω² Q p (14.8).  Nothing here knows the input model.
"""

from __future__ import annotations

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

    def pos(self, q) -> np.ndarray:
        if self.body is None:
            return np.array(self.p, dtype=float)
        i = self.body.index
        x1, x2 = float(q[i[0]]), float(q[i[1]])
        if self.body.rigid and (self.p[0] or self.p[1]):
            a1, a2 = self._arm(float(q[i[2]]))
            return np.array((x1 + a1, x2 + a2))
        return np.array((x1, x2))

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
        if self.body is None:
            return J
        i = self.body.index
        J[0, i[0]] = J[1, i[1]] = 1.0
        if self.body.rigid and (self.p[0] or self.p[1]):
            a1, a2 = self._arm(float(q[i[2]]))
            J[0, i[2]], J[1, i[2]] = -a2, a1          # e3 × Q p
        return J

    def vel(self, q, v) -> np.ndarray:
        if self.body is None:
            return np.zeros(2)
        i = self.body.index
        v1, v2 = float(v[i[0]]), float(v[i[1]])
        if self.body.rigid and (self.p[0] or self.p[1]):
            a1, a2 = self._arm(float(q[i[2]]))
            w = float(v[i[2]])
            return np.array((v1 - w * a2, v2 + w * a1))
        return np.array((v1, v2))

    def bias(self, q, v) -> np.ndarray:
        """J̇ v: the part of the acceleration not linear in q̈ (−ω² Q p, 14.8)."""
        if self.body is None or not self.body.rigid or not (self.p[0] or self.p[1]):
            return np.zeros(2)
        i = self.body.index
        w = float(v[i[2]])
        a1, a2 = self._arm(float(q[i[2]]))
        return np.array((-w * w * a1, -w * w * a2))

    @property
    def turns_with_body(self) -> bool:
        """True when r depends on the body's angle (a rigid body's point off its centre)."""
        return self.body is not None and self.body.rigid and (self.p[0] != 0 or self.p[1] != 0)


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


def perp(a) -> np.ndarray:
    """e3 × a."""
    return np.array([-a[1], a[0]], dtype=float)
