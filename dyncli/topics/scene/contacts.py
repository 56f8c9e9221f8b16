"""The one-sided contacts of a scene and their phases (docs/types/scene.md: phases and impacts).

A ``Contact`` (and a ``stop``, a contact made only at the instant of an impact) holds a body
point on a surface while it pushes; its ``mode`` is the phase it is in:

* "smooth" (made, no friction), "slide" (made, kinetic friction −μ_k N sign(v_t) d̂),
  "stick" (made, a second row holds the point's place along d̂);
* "shared" (made and held, its place along d̂ held by the row of the contact named ``holder``:
  rough contacts of one body on one line held at rest together, whose sticking rows would be
  the same row — two feet of a crate on a floor.  Only the sum of their friction is determined
  (statically indeterminate); each reads its share in proportion to μ_s N, the split at which
  all reach their limits together, and the group holds while |ΣF| ≤ Σ μ_s N.  The system hands
  each member of a group its multipliers followed by the group's: ΣF and every N, the holder's
  first (SceneSystem.lam_of));
* "off" (released: no row; watched for the point's return to the surface, an impact).

A ``Rolls`` joint is "roll" (two rows, 15.8), "slip" (the normal row and kinetic friction at the
contact point) or "off" (the disk has left the surface).  Each element reads its multipliers
back in the contract's terms (N along n, F along d̂) and lists the quantities that must stay
≥ 0 in its phase (``watch``): the event of that name happens where one crosses 0 downwards.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .elements import Element, ListRows, keeps_arm
from .system import BodyPoint, Point, SurfaceData

EPS = float(np.finfo(float).eps)


def _gap_watch(gap: float, margin: float | None) -> float:
    """The released point's height over the surface, watched for an impact only over the
    surface's extent (beyond an end the point passes it: the value stays positive)."""
    if margin is None or margin >= 0:
        return gap
    return abs(gap) - margin


#: a contact's joint rows by its mode (any other mode: one, the normal)
_MODE_ROWS = {"off": 0, "stick": 2}
#: a rolling body's joint rows by its mode (off the surface: none)
_ROLL_ROWS = {"roll": 2, "slip": 1}


@dataclass(kw_only=True)
class Contact(ListRows):
    """P on the surface, pushing only; Coulomb friction with the computed N."""

    P: Point
    surface: SurfaceData
    mu_s: float = 0.0
    mu_k: float = 0.0
    mode: str = "smooth"
    sign: float = 0.0               # direction of sliding along d̂ in mode "slide"
    stick_at: float = 0.0           # d̂·r_P held in mode "stick"
    e: float = 0.0                  # coefficient of restitution of an impact on this surface
    stop: bool = False              # a stop: made only at the instant of an impact
    holder: str | None = None       # mode "shared": the contact whose row holds the group
    group_mu: tuple = ()            # μ_s of a group's contacts, the holder's first (SceneSystem)
    two_sided: bool = False         # a rough slider: the line holds the point both ways (N signed)
    nsign: float = 1.0              # two-sided, sliding: the sign of N its friction column assumes

    @property
    def rows(self):
        return _MODE_ROWS.get(self.mode, 1)

    @property
    def linear(self):
        return not self.P.turns_with_body

    @property
    def rough(self) -> bool:
        return self.mu_s > 0 or self.mu_k > 0

    def straight_along(self, q, N) -> bool:
        """On a fixed straight line, affine along N when its point does not turn along it (a
        crate's corner on the floor while the crate slides)."""
        sf = self.surface
        plain = not any(getattr(sf, flag, False) for flag in ("curved", "carried", "corner", "pair"))
        return plain and type(self).gap is Contact.gap and keeps_arm(self.P, N)

    def phase(self):
        return (self.mode, self.sign, self.stick_at, self.holder, self.nsign)

    def set_phase(self, state) -> None:
        self.mode, self.sign, self.stick_at, self.holder, self.nsign = state

    def made(self) -> str:
        """The mode of the contact once made: smooth, or (rough) stick until decided."""
        return "stick" if self.rough else "smooth"

    def stick_here(self, q) -> None:
        """Hold the point where it is now (mode "stick"'s second row)."""
        self.stick_at = float(np.array(self.surface.d) @ self.P.pos(q))

    def gap(self, q) -> float:
        (n1, n2), (o1, o2) = self.surface.n, self.surface.origin
        x1, x2 = self.P.xy(q)
        return n1 * (x1 - o1) + n2 * (x2 - o2)

    def normal(self, q) -> np.ndarray:
        """The surface's unit normal at the contact (a plane's own; a curve's at the foot of P)."""
        return np.array(self.surface.n)

    def normal_speed(self, q, v) -> float:
        return float(self.normal(q) @ self.P.vel(q, v))

    def phi_list(self, q, t):
        if self.mode == "off":
            return []
        out = [self.gap(q)]
        if self.mode == "stick":
            d1, d2 = self.surface.d
            x1, x2 = self.P.xy(q)
            out.append(d1 * x1 + d2 * x2 - self.stick_at)
        return out

    def jac_list(self, q):
        rows = []
        for k, (w1, w2) in enumerate((self.surface.n, self.surface.d)[:self.rows]):
            row = [0.0] * self.n
            self.P.add_jac(row, q, w1, w2)
            rows.append(row)
        return rows

    def gamma_list(self, q, v, t):
        b1, b2 = self.P.bias_xy(q, v)
        return [-(w1 * b1 + w2 * b2) for w1, w2 in (self.surface.n, self.surface.d)[:self.rows]]

    def kkt_lists(self, q, v, t):
        *_, b1, b2, arm = self.P.kin(q, v)
        rows, gam = [], []
        for w1, w2 in (self.surface.n, self.surface.d)[:self.rows]:
            row = [0.0] * self.n
            self.P.add_jac_arm(row, arm, w1, w2)
            rows.append(row)
            gam.append(-(w1 * b1 + w2 * b2))
        return rows, gam

    def tangent_jac(self, q) -> np.ndarray:
        row = [0.0] * self.n
        self.P.add_jac(row, q, *self.surface.d)
        return np.array(row)

    def friction_column(self, q):
        """Generalized force per unit N of the kinetic friction −μ_k N sign d̂ at P."""
        if self.mode != "slide" or self.mu_k == 0:
            return None
        return -self.mu_k * self.sign * self.nsign * self.tangent_jac(q)

    def holds(self, N: float, F: float) -> bool:
        """The static test |F| ≤ μ_s N (|N| for a two-sided guide); the boundary, within the
        rounding of the linear solve that gave N and F (64 ε of the larger), holds: friction
        exactly at the limit sticks."""
        muN = self.mu_s * (abs(N) if self.two_sided else N)
        return abs(F) - muN <= 64 * EPS * max(abs(F), abs(muN), 1e-300)

    def grip(self, lam) -> tuple[float, float]:
        """(the static limit, the friction it must give) from the multipliers ``lam`` as the
        system hands them: μ_s N and F, or for the holder of a group Σ μ_s N and ΣF."""
        if self.group_mu and self.mode == "stick":
            r = self.rows
            return sum(m * float(N) for m, N in zip(self.group_mu, lam[r + 1:])), float(lam[r])
        N = float(lam[0])
        return self.mu_s * (abs(N) if self.two_sided else N), float(lam[1])

    def held(self, lam) -> bool:
        """:meth:`holds` of the contact, or of its whole group (:meth:`grip`)."""
        limit, F = self.grip(lam)
        return abs(F) - limit <= 64 * EPS * max(abs(F), abs(limit), 1e-300)

    def _share(self, lam) -> float:
        """A grouped contact's part of the group's friction ΣF: in proportion to μ_s N (all at
        their limits together), equal parts where no contact presses."""
        r = self.rows
        F, Ns = float(lam[r]), [float(N) for N in lam[r + 1:]]
        limit = sum(m * N for m, N in zip(self.group_mu, Ns))
        return F * self.mu_s * float(lam[0]) / limit if limit > 0 else F / len(Ns)

    def slip_speed(self, q, v) -> float:
        d1, d2 = self.surface.d
        v1, v2 = self.P.vel_xy(q, v)
        return d1 * v1 + d2 * v2

    def slip_rate(self, q, v, a) -> float:
        """d/dt of :meth:`slip_speed` at the accelerations q̈ = a (a line's)."""
        d1, d2 = self.surface.d
        b1, b2 = self.P.bias_xy(q, v)
        return float(self.tangent_jac(q) @ a) + d1 * b1 + d2 * b2

    def gap_acceleration(self, q, v, a) -> float:
        """d²/dt² of the gap at the accelerations q̈ = a: n·(P's acceleration)."""
        return float(self.normal(q) @ (self.P.jac(q, self.n) @ a + self.P.bias(q, v)))

    def friction(self, lam) -> float:
        if self.group_mu and self.mode in ("stick", "shared"):
            return self._share(lam)
        if self.mode == "stick":
            return float(lam[1])
        if self.mode == "slide":
            return -self.mu_k * self.sign * self.nsign * float(lam[0])
        return 0.0

    def report(self, lam, q, v, t):
        if self.mode == "off":
            return {"N": 0.0, "F": 0.0}
        return {"N": float(lam[0]), "F": self.friction(lam)}

    def reads_forces(self) -> bool:
        """Released, it watches its gap alone (no multiplier)."""
        return self.mode != "off"

    def watch(self, lam, q, v, t):
        m = self.surface.ends_margin(self.P.xy(q))      # (two floats: no array per watch)
        if self.mode == "off":
            return [("impact", _gap_watch(self.gap(q), m))]
        return self.touching_watches(lam, q, v, m)

    def touching_watches(self, lam, q, v, m):
        """The events watched while the point touches (on a line or a curve): N turning to pull,
        the surface's end (margin ``m``, None for none), and sliding that stops or sticking that
        would need more than μ_s N."""
        if not self.two_sided:
            out = [("separates", float(lam[0]))]
        elif self.mode == "slide":      # a two-sided guide never lets go; where N changes sign its
            out = [("reverses", self.nsign * float(lam[0]))]    # friction turns with it: a kink, no event
        else:
            out = []
        if m is not None:
            out.append(("leaves", m))
        if self.mode == "slide":
            out.append(("sticks", self.sign * self.slip_speed(q, v)))
        elif self.mode == "stick":
            out += _slip_watches(*self.grip(lam))
        return out


def _slip_watches(muN: float, F: float) -> list[tuple[str, float]]:
    """Sticking holds while |F| ≤ μ_s N: watched as the two smooth margins μ_s N ∓ F (their
    minimum is μ_s N − |F|, whose kink where F changes sign would cost a root search that
    assumes smoothness its finest cells)."""
    return [("slips", muN - F), ("slips", muN + F)]


@dataclass(kw_only=True)
class Rolls(ListRows):
    """A disk or ring of radius R rolls on the surface without slipping (15.8):
    n·(x − O) = R and d̂·x + R θ = const; it slips with kinetic friction μ_k N when rolling
    would need more than μ_s N, and leaves the surface when N would turn negative."""

    body_point: BodyPoint
    surface: SurfaceData
    R: float = 0.0
    c0: float = 0.0
    mu_s: float | None = None
    mu_k: float | None = None
    mode: str = "roll"
    sign: float = 0.0               # direction of the contact point's slip along d̂ ("slip")
    e: float = 0.0                  # coefficient of restitution when it lands on the surface again

    @property
    def rows(self):
        return _ROLL_ROWS.get(self.mode, 0)

    @property
    def rough(self) -> bool:
        return True

    def phase(self):
        return (self.mode, self.sign, self.c0)

    def set_phase(self, state) -> None:
        self.mode, self.sign, self.c0 = state

    def made(self) -> str:
        return "roll"

    def _x(self, q) -> np.ndarray:
        i = self.body_point.body.index
        return np.array([q[i[0]], q[i[1]]], dtype=float)

    def gap(self, q) -> float:
        i = self.body_point.body.index
        (n1, n2), (o1, o2) = self.surface.n, self.surface.origin
        return n1 * (float(q[i[0]]) - o1) + n2 * (float(q[i[1]]) - o2) - self.R

    def normal_speed(self, q, v) -> float:
        i = self.body_point.body.index
        n1, n2 = self.surface.n
        return n1 * float(v[i[0]]) + n2 * float(v[i[1]])

    def slip_speed(self, q, v) -> float:
        """d̂ · (velocity of the contact point) = d̂·ẋ + R ω."""
        i = self.body_point.body.index
        d1, d2 = self.surface.d
        return d1 * float(v[i[0]]) + d2 * float(v[i[1]]) + self.R * float(v[i[2]])

    def roll_const(self, q) -> float:
        i = self.body_point.body.index
        d1, d2 = self.surface.d
        return d1 * float(q[i[0]]) + d2 * float(q[i[1]]) + self.R * float(q[i[2]])

    def phi_list(self, q, t):
        if not self.rows:
            return []
        return [self.gap(q), self.roll_const(q) - self.c0][:self.rows]

    def _tangent_row(self) -> list:
        i = self.body_point.body.index
        row = [0.0] * self.n
        row[i[0]], row[i[1]] = self.surface.d
        row[i[2]] = self.R
        return row

    def jac_list(self, q):
        i = self.body_point.body.index
        row = [0.0] * self.n
        row[i[0]], row[i[1]] = self.surface.n
        return [row, self._tangent_row()][:self.rows]

    def gamma_list(self, q, v, t):
        return [0.0] * self.rows

    def tangent_jac(self, q) -> np.ndarray:
        return np.array(self._tangent_row())

    def gamma(self, q, v, t):
        return np.zeros(self.rows)

    def friction_column(self, q):
        if self.mode != "slip" or not self.mu_k:
            return None
        return -self.mu_k * self.sign * self.tangent_jac(q)

    def holds(self, N: float, F: float) -> bool:
        if self.mu_s is None:
            return True
        return abs(F) - self.mu_s * N <= 64 * EPS * max(abs(F), abs(self.mu_s * N), 1e-300)

    def grip(self, lam) -> tuple[float, float]:
        """(the static limit μ_s N, ∞ without μ_s; the friction F it must give), as a contact's."""
        return (math.inf if self.mu_s is None else self.mu_s * float(lam[0])), float(lam[1])

    def held(self, lam) -> bool:
        """:meth:`holds` at the multipliers ``lam`` (as a contact's)."""
        return self.holds(float(lam[0]), float(lam[1]))

    def friction(self, lam) -> float:
        if self.mode == "roll":
            return float(lam[1])
        if self.mode == "slip":
            return -(self.mu_k or 0.0) * self.sign * float(lam[0])
        return 0.0

    def report(self, lam, q, v, t):
        if self.mode == "off":
            return {"N": 0.0, "F": 0.0, "slip_margin": None}
        N, F = float(lam[0]), self.friction(lam)
        margin = None if self.mu_s is None or self.mode != "roll" else self.mu_s * N - abs(F)
        return {"N": N, "F": F, "slip_margin": margin}

    def reads_forces(self) -> bool:
        """Off the surface, it watches its gap alone (no multiplier)."""
        return self.mode != "off"

    def watch(self, lam, q, v, t):
        i = self.body_point.body.index
        m = self.surface.ends_margin((float(q[i[0]]), float(q[i[1]])))
        if self.mode == "off":
            return [("impact", _gap_watch(self.gap(q), m))]
        return self.touching_watches(lam, q, v, m)

    def touching_watches(self, lam, q, v, m):
        """The events watched while the body rolls or slips on the surface (a line or a curve): N
        turning to pull, the surface's end (margin ``m``, None for none), slip that stops or rolling
        that would need more than μ_s N."""
        out = [("separates", float(lam[0]))]
        if m is not None:
            out.append(("leaves", m))
        if self.mode == "slip":
            out.append(("sticks", self.sign * self.slip_speed(q, v)))
        elif self.mu_s is not None:
            out += _slip_watches(self.mu_s * float(lam[0]), float(lam[1]))
        return out


@dataclass(kw_only=True)
class TurningRolls(Rolls):
    """Rolling on a surface whose normal turns as the body moves (a curve, curved.py; a corner,
    corner.py): its rows written as arrays (``phi``, ``jac``, ``gamma``: not a line's list forms),
    its normal and its tangent t̂ at the contact given by the subclass (``normal``, ``tangent``)."""

    linear = False
    phi_list = Element.phi_list
    jac_list = Element.jac_list
    gamma_list = Element.gamma_list
    kkt_lists = Element.kkt_lists

    def normal(self, q) -> np.ndarray:
        raise NotImplementedError

    def tangent(self, q) -> np.ndarray:
        raise NotImplementedError

    def normal_speed(self, q, v) -> float:
        i = self.body_point.body.index
        return float(self.normal(q) @ np.array([v[i[0]], v[i[1]]], float))

    def tangent_jac(self, q) -> np.ndarray:
        """The contact point's speed along t̂ per unit rate: [t̂ on the centre; R on θ]."""
        i = self.body_point.body.index
        J = np.zeros(self.n)
        J[i[0]], J[i[1]] = self.tangent(q)
        J[i[2]] = self.R
        return J

    def slip_speed(self, q, v) -> float:
        return float(self.tangent_jac(q) @ np.asarray(v, float))
