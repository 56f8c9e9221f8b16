"""A corner of a scene: a fixed point C where two faces meet (the edge of a curb or a step, the
top of a post, a peg), touched by the rim of a round body — a wheel striking a curb and climbing
it about the edge, a ball rolling over a post (docs/types/scene.md, "Corners").

With x̄ the body's centre, r = x̄ − C, d = |r|, the normal n = r/d (the corner pushes the body
along n) and t̂ = (n₂, −n₁) (so that n = e3 × t̂, the bodies on the left of t̂ as on a line),
φ = atan2(n₂, n₁):

* the rim on the corner: φ₁ = d − R, J₁ = nᵀ on x̄, γ₁ = −(t̂·ẋ)²/d (d̈ = n·ẍ + (t̂·ẋ)²/d);
* no slip at the corner (15.8 about a point: the rim's point at C at rest, t̂·ẋ + R ω = 0 with
  t̂·ẋ = −d φ̇), integrated exactly: φ₂ = R (θ − φ) − c₀ (φ on the turn the body has rolled to),
  J₂ = (R/d) t̂ᵀ on x̄ and R on θ,
  γ₂ = 2 R (t̂·ẋ)(n·ẋ)/d²;
* their Hessians (the equilibria's and linearization's curvature terms): ∇²d = t̂t̂ᵀ/d,
  ∇²(−R φ) = −R (t̂nᵀ + nt̂ᵀ)/d².

These are the rows of rolling on a curve (curved.py) in the limit of a curve of radius 0 (its
offset curve a circle of radius R about C), written exactly.  The phases are those of rolling
(contacts.Rolls): "roll", "slip" (the distance row, kinetic friction at the corner), "off" (the
gap d − R watched for an impact of the rim).  A corner given the outward normals of its two
faces touches the rim only while n lies between them (the event ``leaves`` where n reaches
one: the body passes onto that face, or off the corner's side); without them, from any side.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .contacts import TurningRolls


class CornerData:
    """A fixed corner C; ``normals``: the outward unit normals (a, b) of its two faces, or None."""

    curved = True           # (its normal turns with the body: the paths that read a line's n skip it)
    corner = True
    length = None
    q_range = None

    def __init__(self, name: str, at, normals=None):
        self.name = name
        self.C = (float(at[0]), float(at[1]))
        self.normals = None
        if normals is not None:
            a, b = (np.asarray(u, float) / math.hypot(u[0], u[1]) for u in normals)
            s = 1.0 if a[0] * b[1] - a[1] * b[0] > 0 else -1.0      # a → b counter-clockwise: s = 1
            self.normals = (a, b, s)

    def margins(self, n) -> tuple[float, float] | None:
        """sin of the angle of n inside the faces' normals from each (both ≥ 0 inside; a → b
        the short way round), or None without normals."""
        if self.normals is None:
            return None
        a, b, s = self.normals
        n1, n2 = float(n[0]), float(n[1])
        return s * (a[0] * n2 - a[1] * n1), s * (n1 * b[1] - n2 * b[0])

    def drawing(self) -> dict:
        """Its drawing (plots): the corner and the direction of each face from it (along the face,
        away from the other face's normal)."""
        faces = []
        if self.normals is not None:
            a, b, _ = self.normals
            for u, other in ((a, b), (b, a)):
                f = (float(-u[1]), float(u[0]))
                if f[0] * other[0] + f[1] * other[1] > 0:
                    f = (-f[0], -f[1])
                faces.append(f)
        return {"name": self.name, "corner": self.C, "faces": faces}


@dataclass(kw_only=True)
class CornerRolls(TurningRolls):
    """The rim of a disk or ring of radius R on a corner: rolls about it (no slip), slips with
    kinetic friction, or is off it (a stop's rim before it strikes)."""

    surface: CornerData  # type: ignore[assignment]  # a corner where Rolls has a line: the geometry is all overridden here

    def _geom(self, q):
        """(d, n, t̂, ψ) of the centre from the corner, ψ = atan2(n₂, n₁) in (−π, π]."""
        i = self.body_point.body.index
        r1, r2 = float(q[i[0]]) - self.surface.C[0], float(q[i[1]]) - self.surface.C[1]
        d = math.hypot(r1, r2)
        if not d > 0:
            from dyncli.errors import NumericalError

            raise NumericalError(f"the centre of {self.body_point.body.name!r} reached the corner "
                                 f"{self.surface.name!r}: its normal is not defined there")
        n = np.array([r1 / d, r2 / d])
        return d, n, np.array([n[1], -n[0]]), math.atan2(r2, r1)

    def _turned(self, q) -> float:
        """R (θ − ψ) − c₀ with ψ on the turn the body has rolled to (the branch of atan2 that
        makes it nearest 0: rolling on a corner keeps θ − ψ, so the residual stays within half
        a turn of it whatever the number of turns), a function of q alone."""
        i = self.body_point.body.index
        w = float(q[i[2]]) - self._geom(q)[3] - self.c0 / self.R
        return self.R * (w - 2 * math.pi * round(w / (2 * math.pi)))

    def gap(self, q) -> float:
        return self._geom(q)[0] - self.R

    def normal(self, q) -> np.ndarray:
        return self._geom(q)[1]

    def gap_acceleration(self, q, v, a) -> float:
        """d̈ at the accelerations a: n·ẍ + (t̂·ẋ)²/d."""
        i = self.body_point.body.index
        d, n, tt, _ = self._geom(q)
        vc, ac = np.array([v[i[0]], v[i[1]]], float), np.array([a[i[0]], a[i[1]]], float)
        return float(n @ ac) + float(tt @ vc) ** 2 / d

    def tangent(self, q) -> np.ndarray:
        return self._geom(q)[2]

    def roll_const(self, q) -> float:
        i = self.body_point.body.index
        return self.R * (float(q[i[2]]) - self._geom(q)[3])

    def phi(self, q, t):
        if not self.rows:
            return np.zeros(0)
        return np.array([self._geom(q)[0] - self.R, self._turned(q)])[:self.rows]

    def jac(self, q):
        i = self.body_point.body.index
        d, n, tt, _ = self._geom(q)
        J = np.zeros((2, self.n))
        J[0, i[0]], J[0, i[1]] = n
        J[1, i[0]], J[1, i[1]] = self.R / d * tt
        J[1, i[2]] = self.R
        return J[:self.rows]

    def gamma(self, q, v, t):
        i = self.body_point.body.index
        d, n, tt, _ = self._geom(q)
        vc = np.array([v[i[0]], v[i[1]]], float)
        a, b = float(tt @ vc), float(n @ vc)
        return np.array([-a * a / d, 2 * self.R * a * b / (d * d)])[:self.rows]

    def hessian(self, q, w, n: int) -> np.ndarray:
        """Σ w ∇²φ on the centre's block: w₁ t̂t̂ᵀ/d − w₂ R (t̂nᵀ + nt̂ᵀ)/d²."""
        i = self.body_point.body.index
        H = np.zeros((n, n))
        if not self.rows:
            return H
        w = list(w) + [0.0] * (2 - len(w))
        d, nn, tt, _ = self._geom(q)
        Hx = w[0] / d * np.outer(tt, tt) - w[1] * self.R / (d * d) * (np.outer(tt, nn) + np.outer(nn, tt))
        H[np.ix_([i[0], i[1]], [i[0], i[1]])] = Hx
        return H

    def watch(self, lam, q, v, t):
        d, n, _, _ = self._geom(q)
        m = self.surface.margins(n)
        if self.mode == "off":          # in flight: the rim strikes the corner (between its faces)
            g = d - self.R
            if m is not None and min(m) < 0:
                g = abs(g) - self.R * min(m)
            return [("impact", g)]
        out = self.touching_watches(lam, q, v, None)
        if m is not None:               # (first: at t = 0 a rim outside the faces is refused as such)
            out[:0] = [("leaves", self.R * m[0]), ("leaves", self.R * m[1])]
        return out

    # ------------------------------------------------------------------ refusals at t = 0
    def _who(self) -> str:
        return f"the rim of {self.body_point.body.name!r}"

    def _where(self) -> str:
        return f"the corner {self.surface.name!r} at [{self.surface.C[0]:g}, {self.surface.C[1]:g}]"

    def refuse_gap(self, q, placed: str) -> str:
        """The message for a rim given off the corner (rolls) or over it (rolls or stop)."""
        gap = self.gap(q)
        if gap > 0:
            return (f"the positions given violate the {self.kind} joint {self.name!r}: {self._who()} is {gap:.6g} m "
                    f"from {self._where()} (a body rolling on a corner starts touching it){placed}: place its centre "
                    f"R = {self.R:g} m from the corner, or leave its position out so that the joint places it; for a "
                    f"body that reaches the corner later, make the joint a stop (stop: "
                    f"[{self.body_point.body.name}, {self.surface.name}], e: E), made where the rim strikes")
        return (f"{self._where()} is {-gap:.6g} m inside {self._who()} at t = 0{placed}: place its centre at least "
                f"R = {self.R:g} m from the corner (exactly R where it touches)")

    def refuse_pull(self, q, N: float) -> str:
        b = self.body_point.body
        ring = (f"; a ring hanging on a peg inside it (a hoop on a knife edge) is a pin at its point on the peg, "
                f"pin: [{b.name}.POINT, [{self.surface.C[0]:g}, {self.surface.C[1]:g}]] — rolling on a point keeps the "
                "same point of the rim on it" if b.shape == "ring" else "")
        return (f"at t = 0 {self._where()} would have to pull {self._who()}: N = {N:.6g} N (a corner pushes along "
                "the direction from it to the centre, from outside the rim): the loads take the body away from the "
                f"corner; start it where it presses on the corner, or make the joint a stop, made where the rim "
                f"strikes{ring}")

    def refuse_outside(self, q) -> str:
        n = [0.0 if abs(c) < 1e-12 else float(c) for c in self.normal(q)]
        assert self.surface.normals is not None, "refused outside only where the faces are given"
        a, b, _ = self.surface.normals
        return (f"at t = 0 the direction from {self._where()} to the centre of {self.body_point.body.name!r}, "
                f"[{n[0]:.4g}, {n[1]:.4g}], is not between its faces' normals [{a[0]:.4g}, {a[1]:.4g}] and "
                f"[{b[0]:.4g}, {b[1]:.4g}]: there the rim would touch a face, not the corner; place the body "
                "between them (a wheel against a curb met from the left: its centre left of and above the edge), "
                "or check the normals")


def corner_rolls(name, kind, n, path, body_point, corner: CornerData, R: float, j: dict, q, mode: str = "roll",
                 mu=None) -> CornerRolls:
    """A round body on a corner: rolling (``rolls``, μ_s/μ_k from the joint) or a stop's rim
    (mode "off", kinetic friction ``mu`` once made)."""
    if mu is not None:
        mu_s = mu_k = mu
    else:
        mu_s = j["mu_s"]
        mu_k = j["mu_k"] if j.get("mu_k") is not None else mu_s
    el = CornerRolls(name, kind, n, path, body_point=body_point, surface=corner, R=R, mu_s=mu_s, mu_k=mu_k,
                     e=float(j.get("e") or 0.0), mode=mode)
    el.c0 = el.roll_const(q)
    return el
