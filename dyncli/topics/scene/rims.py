"""Two bodies touching rim to rim: two balls or disks (a ball striking another, a cylinder resting
on two others), or a point mass and a round body — ``stop: [A, B]`` or ``contact: [A, B]`` with
two body names (docs/types/scene.md, "Bodies striking bodies").

With the centres x̄_A, x̄_B and the radii R_A, R_B (0 for a point body), r = x̄_B − x̄_A, d = |r|,
n = r/d (from A to B) and t̂ = e3 × n:

* φ = d − (R_A + R_B) ≥ 0, J = [−nᵀ on x̄_A, nᵀ on x̄_B], γ = −(t̂·Δv)²/d with Δv = v̄_B − v̄_A
  (d̈ = n·Δa + (t̂·Δv)²/d), ∇²d = t̂t̂ᵀ/d on r;
* the multiplier λ is the push N ≥ 0 on A along −n (away from B; B gets N along n); smooth,
  the force between the rims passes through both centres and turns neither body;
* rough (``mu`` or ``mu_s``/``mu_k``): Coulomb friction along t̂ at the contact, kinetic −μ_k N
  against the rims' slip t̂·(v̄_A − v̄_B) + c_A ω_A − c_B ω_B (the contact point x̄ + c n on each),
  held (mode "stick") by the rims rolling on each other, c_A θ_A − c_B θ_B − D φ = const (φ the
  direction of n; the gears' row), while |F| ≤ μ_s N.

A ``stop`` starts open and is made at an impact (Newton's restitution e on the normal speed of
approach, 28.7: both bodies' velocities jump together, 28.11); a ``contact`` starts made (the
bodies touching at t = 0).  Either one separates where N reaches 0 and strikes again where the
rims meet.  Inside a ring (``inside``) the rows turn sign: the centres stay |R_A − R_B| apart.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .contacts import Contact
from .system import BodyData


@dataclass
class PairSurface:
    """The other body of a rim pair, where a contact has its surface (its name in messages)."""

    name: str
    curved = True           # (the normal turns: the paths that read a fixed line's n skip it)
    pair = True
    carried = False
    corner = False
    length = None
    q_range = None

    def ends_margin(self, *_args) -> None:
        return None


@dataclass(kw_only=True)
class RimContact(Contact):
    """Bodies A and B rim to rim (one row while made: the centres R_A + R_B apart, pushing)."""

    surface: PairSurface  # type: ignore[assignment]  # the other body where Contact has a line: the geometry is all overridden here
    A: BodyData
    B: BodyData
    RA: float = 0.0
    RB: float = 0.0
    inside: bool = False        # one of them inside the other, a ring (touching it from within)

    @property
    def D(self) -> float:
        """The distance of the centres where the rims touch: R_A + R_B, or |R_A − R_B| inside."""
        return abs(self.RA - self.RB) if self.inside else self.RA + self.RB

    @property
    def s(self) -> float:
        """+1 outside (the gap d − D), −1 inside (D − d)."""
        return -1.0 if self.inside else 1.0

    def _arms(self) -> tuple[float, float]:
        """(c_A, c_B): the contact point is x̄_A + c_A n and x̄_B + c_B n."""
        if not self.inside:
            return self.RA, -self.RB
        return (-self.RA, -self.RB) if self.RB > self.RA else (self.RA, self.RB)

    @property
    def linear(self):
        return False

    def stick_here(self, q) -> None:
        """Hold the rims rolling on each other from here (mode "stick"'s second row)."""
        self.stick_at = 0.0
        self.stick_at = self._rolled(q)

    def _rolled(self, q) -> float:
        """c_A θ_A − c_B θ_B − D φ − stick_at (φ the direction of n), on the turn nearest 0: the
        rims' rolling on each other, integrated (its rate is their slip at d = D)."""
        cA, cB = self._arms()
        r1, r2 = float(q[self.B.index[0]]) - float(q[self.A.index[0]]), float(q[self.B.index[1]]) - float(q[self.A.index[1]])
        w = -self.D * math.atan2(r2, r1) - self.stick_at
        if self.A.rigid:
            w += cA * float(q[self.A.index[2]])
        if self.B.rigid:
            w -= cB * float(q[self.B.index[2]])
        turn = 2 * math.pi * self.D
        return w - turn * round(w / turn) if turn > 0 else w

    def _geom(self, q):
        """(d, n, t̂) with n from A's centre to B's."""
        a, b = self.A.index, self.B.index
        r1, r2 = float(q[b[0]]) - float(q[a[0]]), float(q[b[1]]) - float(q[a[1]])
        d = math.hypot(r1, r2)
        if not d > 0:
            from dyncli.errors import NumericalError

            raise NumericalError(f"the centres of {self.A.name!r} and {self.B.name!r} coincide: the direction "
                                 "between their rims is not defined")
        return d, (r1 / d, r2 / d), (-r2 / d, r1 / d)

    def _dv(self, v) -> tuple[float, float]:
        a, b = self.A.index, self.B.index
        return float(v[b[0]]) - float(v[a[0]]), float(v[b[1]]) - float(v[a[1]])

    def gap(self, q) -> float:
        return self.s * (self._geom(q)[0] - self.D)

    def normal(self, q) -> np.ndarray:
        """The direction of the push on A (from B's centre to A's outside; towards it inside)."""
        n = self._geom(q)[1]
        return np.array([-self.s * n[0], -self.s * n[1]])

    def normal_speed(self, q, v) -> float:
        """The rate of the gap: ± n·(v̄_B − v̄_A)."""
        _, (n1, n2), _ = self._geom(q)
        d1, d2 = self._dv(v)
        return self.s * (n1 * d1 + n2 * d2)

    def gap_acceleration(self, q, v, a) -> float:
        d, (n1, n2), (t1, t2) = self._geom(q)
        a1, a2 = self._dv(a)
        v1, v2 = self._dv(v)
        return self.s * (n1 * a1 + n2 * a2 + (t1 * v1 + t2 * v2) ** 2 / d)

    def slip_speed(self, q, v) -> float:
        """The rims' relative speed along t̂ at the contact (A's point minus B's)."""
        return float(self.tangent_jac(q) @ np.asarray(v, float))

    def tangent_jac(self, q) -> np.ndarray:
        _, _, (t1, t2) = self._geom(q)
        J = np.zeros(self.n)
        a, b = self.A.index, self.B.index
        J[a[0]], J[a[1]], J[b[0]], J[b[1]] = t1, t2, -t1, -t2
        cA, cB = self._arms()
        if self.A.rigid:
            J[a[2]] = cA
        if self.B.rigid:
            J[b[2]] = -cB
        return J

    def phi_list(self, q, t):
        if self.mode == "off":
            return []
        return [self.gap(q), self._rolled(q)] if self.mode == "stick" else [self.gap(q)]

    def jac_list(self, q):
        if self.mode == "off":
            return []
        d, (n1, n2), (t1, t2) = self._geom(q)
        s = self.s
        row = [0.0] * self.n
        a, b = self.A.index, self.B.index
        row[a[0]], row[a[1]], row[b[0]], row[b[1]] = -s * n1, -s * n2, s * n1, s * n2
        if self.mode != "stick":
            return [row]
        roll = self.tangent_jac(q).tolist()         # the slip, with D/d on the centres' part (d = D made)
        f = self.D / d
        roll[a[0]], roll[a[1]], roll[b[0]], roll[b[1]] = f * t1, f * t2, -f * t1, -f * t2
        return [row, roll]

    def gamma_list(self, q, v, t):
        if self.mode == "off":
            return []
        d, (n1, n2), (t1, t2) = self._geom(q)
        v1, v2 = self._dv(v)
        A, B = t1 * v1 + t2 * v2, n1 * v1 + n2 * v2
        out = [-self.s * A * A / d]
        if self.mode == "stick":                    # −J̇v of c_A θ_A − c_B θ_B − D φ: φ̈ ∋ −2 (t̂·ṙ)(n·ṙ)/d²
            out.append(-2 * self.D * A * B / (d * d))
        return out

    def kkt_lists(self, q, v, t):
        return self.jac_list(q), self.gamma_list(q, v, t)

    def hessian(self, q, w, n: int) -> np.ndarray:
        """± w ∇²d on the two centres: (w/d) [[t̂t̂ᵀ, −t̂t̂ᵀ], [−t̂t̂ᵀ, t̂t̂ᵀ]]."""
        H = np.zeros((n, n))
        if self.mode == "off" or not len(w):
            return H
        d, _, tt = self._geom(q)
        T = self.s * float(w[0]) / d * np.outer(tt, tt)
        a, b = [self.A.index[0], self.A.index[1]], [self.B.index[0], self.B.index[1]]
        H[np.ix_(a, a)] += T
        H[np.ix_(b, b)] += T
        H[np.ix_(a, b)] -= T
        H[np.ix_(b, a)] -= T
        return H

    def watch(self, lam, q, v, t):
        if self.mode == "off":
            return [("impact", self.gap(q))]
        return self.touching_watches(lam, q, v, None)

    # ------------------------------------------------------------------ refusals at t = 0
    def refuse_gap(self, q, placed: str) -> str:
        gap = self.gap(q)
        who = f"the rims of {self.A.name!r} and {self.B.name!r}" if self.A.rigid and self.B.rigid else \
            f"{self.A.name!r} and the rim of {self.B.name!r}" if self.B.rigid else f"the rim of {self.A.name!r} and {self.B.name!r}"
        if gap > 0:
            return (f"the positions given violate the {self.kind} joint {self.name!r}: {who} are {gap:.6g} m apart (a "
                    f"contact starts touching: the centres {self._apart()} = {self.D:g} m apart){placed}: place "
                    f"them touching, or make the joint a stop (stop: [{self.A.name}, {self.B.name}], e: E), made where "
                    "they strike")
        where = (f"at most {self._apart()} = {self.D:g} m apart (inside the ring)" if self.inside else
                 f"at least {self._apart()} = {self.D:g} m apart")
        return (f"{who} overlap by {-gap:.6g} m at t = 0{placed}: place the centres {where} (exactly that where they "
                "touch)")

    def _apart(self) -> str:
        return ("R_B − R_A" if self.RB > self.RA else "R_A − R_B") if self.inside else "R_A + R_B"

    def refuse_pull(self, q, N: float) -> str:
        return (f"at t = 0 {self.B.name!r} would have to pull {self.A.name!r}: N = {N:.6g} N (touching rims only "
                "push): the loads take them apart; start them where they press on each other, or make the joint a "
                "stop, made where they strike")
