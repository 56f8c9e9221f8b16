"""Surfaces carried by a body (a wedge free to slide on the floor, a block on a cart, a plank
under another block): a straight line fixed to a body, moving and turning with it, and the
contact of a point of another body on it (docs/types/scene.md: surfaces on a body).

The line is given in ground coordinates as drawn at t = 0, with its body where the file puts
it; it keeps its place on the body: its origin o and direction d̂ₗ on the body's e'1, e'2.  At
(q) the body W is at x_W turned by θ_W, so d̂ = Q(θ_W) d̂ₗ and n = e3 × d̂, and for a point P of
another body, ρ = r_P − x_W:

* the gap g = n·ρ − n_l·o (the height of P over the line), and its place along the line
  s = d̂·ρ − d̂ₗ·o (from the line's origin, as on a fixed line);
* their rates ġ = n·ρ̇ − ω (d̂·ρ) and ṡ = d̂·ρ̇ + ω (n·ρ), ω = θ̇_W: ṡ is P's slip over the
  line's material point under it, so kinetic friction −μ_k N sign(ṡ) d̂ on P, and its opposite
  on W at that point, has the power −μ_k N |ṡ| (the pair the multipliers carry, 16.7);
* their second derivatives g̈ = [∂g/∂q] q̈ + n·b_P − 2ω d̂·ρ̇ − ω² n·ρ and
  s̈ = [∂s/∂q] q̈ + d̂·b_P + 2ω n·ρ̇ − ω² d̂·ρ (ṅ = −ω d̂, ḋ = ω n; b_P: P's own −ω_P² Q p), so
  the rows' γ are the negated rest.

A contact (or a stop) on such a line is a :class:`~.contacts.Contact` whose rows are these (N
along n on P, −N on W; friction along d̂).  A slider keeps a body's centre at its t = 0 offset
from the line, and a rigid body's angle to W.  A rolling disk keeps its centre R off the line
and rolls on W's material point: ṡ + R (ω_B − ω_W) = 0, i.e. s + R (θ_B − θ_W) = const (15.8
relative to W).  Their rows are affine in q when W cannot turn (its angle held by two-sided
joints: a wedge on a slider) and P does not turn with its body (``fixed_angle``, set once the
scene is assembled): the closed forms then apply as on a fixed line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .contacts import Contact, Rolls
from .elements import ListRows, RunsOffEnds
from .system import BodyData, BodyPoint, Point, SurfaceData


@dataclass(frozen=True)
class CarriedLine(SurfaceData):
    """A straight surface fixed to ``body``: ``origin``, ``d``, ``n`` are its place at t = 0 (for
    messages); ``o``, ``dl`` its origin and direction on the body's axes."""

    body: BodyData = field(kw_only=True, compare=False)
    o: tuple[float, float] = field(kw_only=True)
    dl: tuple[float, float] = field(kw_only=True)
    carried = True

    def frame(self, q) -> tuple[float, float, float, float, float, float, float]:
        """(x_W1, x_W2, d̂1, d̂2, n_l·o, d̂ₗ·o, θ_W) at q: the body's centre, the line's direction
        turned with it, the two constants of the gap and the place along the line, its angle."""
        b = self.body
        i = b.index
        th = float(q[i[2]]) if b.rigid else 0.0
        c, s = math.cos(th), math.sin(th)
        d1, d2 = c * self.dl[0] - s * self.dl[1], s * self.dl[0] + c * self.dl[1]
        o1, o2 = self.o
        return float(q[i[0]]), float(q[i[1]]), d1, d2, -self.dl[1] * o1 + self.dl[0] * o2, self.dl[0] * o1 + self.dl[1] * o2, th

    def ends_margin(self, r) -> float | None:       # on a carried line the margin is the contact's
        raise AssertionError("a carried line's ends are read through its contact")


def carried_line(name: str, s: dict, body: BodyData, q) -> CarriedLine:
    """The line ``s`` (through, direction in ground coordinates at t = 0) fixed to ``body`` at its
    place q."""
    d = np.array(s["direction"], float)
    d = d / math.hypot(d[0], d[1])
    i = body.index
    th = float(q[i[2]]) if body.rigid else 0.0
    c, sn = math.cos(th), math.sin(th)
    rel = np.array(s["through"], float) - np.array([q[i[0]], q[i[1]]], float)
    o = (c * rel[0] + sn * rel[1], -sn * rel[0] + c * rel[1])
    dl = (c * d[0] + sn * d[1], -sn * d[0] + c * d[1])
    return CarriedLine(name, tuple(s["through"]), (float(d[0]), float(d[1])), (float(-d[1]), float(d[0])),
                       s.get("length"), body=body, o=(float(o[0]), float(o[1])), dl=(float(dl[0]), float(dl[1])))


class _OnLine:
    """The geometry of a point ``P`` over a carried line ``surface`` (module docstring): its gap,
    its place along the line, their rows and γ, and their curvature."""

    surface: CarriedLine
    n: int

    def point(self) -> Point:
        """The point on the line (a contact's P, a slider's or a rolling disk's centre)."""
        return self.P       # type: ignore[attr-defined]  # (each element names its point)

    # --- the geometry at q (and v)
    def _geometry(self, q, v=None):
        """(d̂, n, ρ, ρ̇ (None without v), ω_W (0 without v), W's angle index (None for a point
        carrier), n_l·o, d̂ₗ·o)."""
        xw1, xw2, d1, d2, cn, cd, _th = self.surface.frame(q)
        p1, p2 = self.point().xy(q)
        rho = (p1 - xw1, p2 - xw2)
        W = self.surface.body
        ia = W.index[2] if W.rigid else None
        if v is None:
            return (d1, d2), (-d2, d1), rho, None, 0.0, ia, cn, cd
        pv1, pv2 = self.point().vel_xy(q, v)
        rhod = (pv1 - float(v[W.index[0]]), pv2 - float(v[W.index[1]]))
        w = float(v[ia]) if ia is not None else 0.0
        return (d1, d2), (-d2, d1), rho, rhod, w, ia, cn, cd

    def gap(self, q) -> float:
        (d1, d2), (n1, n2), (r1, r2), *_, cn, _cd = self._geometry(q)
        return n1 * r1 + n2 * r2 - cn

    def along(self, q) -> float:
        """s: the contact point's place along the line from its origin."""
        (d1, d2), _n, (r1, r2), *_, _cn, cd = self._geometry(q)
        return d1 * r1 + d2 * r2 - cd

    def normal(self, q) -> np.ndarray:
        _d, n, *_ = self._geometry(q)
        return np.array(n)

    def _row(self, q, w1: float, w2: float, k_theta: float) -> list:
        """∂(w·ρ)/∂q with the line's turn k_theta on W's angle (w = n: −d̂·ρ; w = d̂: n·ρ)."""
        W = self.surface.body
        row = [0.0] * self.n
        self.point().add_jac(row, q, w1, w2)
        row[W.index[0]] -= w1
        row[W.index[1]] -= w2
        if W.rigid:
            row[W.index[2]] += k_theta
        return row

    def jac_lines(self, q) -> list:
        """[∂g/∂q, ∂s/∂q]: the rows of the gap and of the place along the line."""
        (d1, d2), (n1, n2), (r1, r2), *_ = self._geometry(q)
        return [self._row(q, n1, n2, -(d1 * r1 + d2 * r2)), self._row(q, d1, d2, n1 * r1 + n2 * r2)]

    def _rows_gammas(self, q, v):
        (d1, d2), (n1, n2), (r1, r2), (rd1, rd2), w, _ia, _cn, _cd = self._geometry(q, v)
        b1, b2 = self.point().bias_xy(q, v)
        n_rho, d_rho = n1 * r1 + n2 * r2, d1 * r1 + d2 * r2
        n_rhod, d_rhod = n1 * rd1 + n2 * rd2, d1 * rd1 + d2 * rd2
        rows = [self._row(q, n1, n2, -d_rho), self._row(q, d1, d2, n_rho)]
        gams = [-(n1 * b1 + n2 * b2 - 2 * w * d_rhod - w * w * n_rho),
                -(d1 * b1 + d2 * b2 + 2 * w * n_rhod - w * w * d_rho)]
        return rows, gams

    def gap_rate(self, q, v) -> float:
        """ġ = n·ρ̇ − ω (d̂·ρ)."""
        (d1, d2), (n1, n2), (r1, r2), (rd1, rd2), w, *_ = self._geometry(q, v)
        return n1 * rd1 + n2 * rd2 - w * (d1 * r1 + d2 * r2)

    def along_rate(self, q, v) -> float:
        """ṡ = d̂·ρ̇ + ω (n·ρ): the slip of P over the line's material point under it."""
        (d1, d2), (n1, n2), (r1, r2), (rd1, rd2), w, *_ = self._geometry(q, v)
        return d1 * rd1 + d2 * rd2 + w * (n1 * r1 + n2 * r2)

    def gap_acceleration(self, q, v, a) -> float:
        """g̈ at the accelerations q̈ = a."""
        rows, gams = self._rows_gammas(q, v)
        return float(np.array(rows[0]) @ a) - gams[0]

    def line_watch(self, lam, q, v, t):
        """A one-sided element's watch (a contact's, a rolling disk's): off the line, its gap
        (past the line's ends, as on a fixed line: |gap| − margin); on it, what it watches there."""
        m = self._margin(q)
        if self.mode == "off":           # (the one-sided elements have modes and their watches on it)
            g = self.gap(q)
            return [("impact", g if m is None or m >= 0 else abs(g) - m)]
        return self.touching_watches(lam, q, v, m)

    def turn_row(self, B: BodyData) -> list:
        """∂(θ_B − θ_W)/∂q: the rigid body B turning relative to the carrier."""
        row = [0.0] * self.n
        row[B.index[2]] = 1.0
        W = self.surface.body
        if W.rigid:
            row[W.index[2]] -= 1.0
        return row

    def turned(self, q, B: BodyData) -> float:
        """θ_B − θ_W of the rigid body B (θ_W = 0 for a point carrier)."""
        W = self.surface.body
        return float(q[B.index[2]]) - (float(q[W.index[2]]) if W.rigid else 0.0)

    def _margin(self, q) -> float | None:
        """How far P's place along the line is from its nearer end (None: no ends)."""
        L = self.surface.length
        if L is None:
            return None
        s = self.along(q)
        return float(min(s, L - s))

    def hessian(self, q, w, n: int) -> np.ndarray:
        """Σ w ∇² of the rows (curvature.py): P's own arm turning (n·∂²r_P), the line turning
        with W (∂n/∂θ = −d̂, ∂d̂/∂θ = n) against P's and W's motion, and −(n·ρ), −(d̂·ρ) on
        W's angle twice."""
        from .curvature import point_hessian

        (d1, d2), (n1, n2), (r1, r2), *_ = self._geometry(q)
        W = self.surface.body
        H = np.zeros((n, n))
        dirs = [((n1, n2), (-d1, -d2), -(n1 * r1 + n2 * r2)), ((d1, d2), (n1, n2), -(d1 * r1 + d2 * r2))]
        for wk, ((c1, c2), (t1, t2), diag) in zip(w, dirs):
            H += wk * point_hessian(self.point(), q, (c1, c2), n)
            if not W.rigid:
                continue
            ia = W.index[2]
            row = np.array(self._row(q, t1, t2, 0.0))      # ∂(turned w)·ρ/∂q, but W's angle
            H[ia, :] += wk * row
            H[:, ia] += wk * row
            H[ia, ia] += wk * diag
        return H


@dataclass(kw_only=True)
class CarriedContact(_OnLine, Contact):
    """A point of one body on a line carried by another (module docstring)."""

    surface: CarriedLine            # a carried line: the geometry is all overridden here
    fixed_angle: bool = False       # the carrying body cannot turn (prepare.py, once assembled)

    @property
    def linear(self):
        return self.fixed_angle and not self.P.turns_with_body

    def phi_list(self, q, t):
        if self.mode == "off":
            return []
        out = [self.gap(q)]
        if self.mode == "stick":
            out.append(self.along(q) - self.stick_at)
        return out

    def jac_list(self, q):
        return self.jac_lines(q)[:self.rows]

    def gamma_list(self, q, v, t):
        return self._rows_gammas(q, v)[1][:self.rows]

    def kkt_lists(self, q, v, t):
        rows, gams = self._rows_gammas(q, v)
        return rows[:self.rows], gams[:self.rows]

    def tangent_jac(self, q) -> np.ndarray:
        return np.array(self.jac_lines(q)[1])

    def stick_here(self, q) -> None:
        self.stick_at = self.along(q)

    def normal_speed(self, q, v) -> float:
        return self.gap_rate(q, v)

    def slip_speed(self, q, v) -> float:
        return self.along_rate(q, v)

    def slip_rate(self, q, v, a) -> float:
        rows, gams = self._rows_gammas(q, v)
        return float(np.array(rows[1]) @ a) - gams[1]

    watch = _OnLine.line_watch


@dataclass(kw_only=True)
class CarriedSlider(RunsOffEnds, _OnLine, ListRows):
    """A body's centre on the line through its place at t = 0 parallel to a carried line (a
    collar on a turning rod, a slide block in a moving guide), two-sided and smooth; a rigid body
    keeps its angle to the carrier.  ``N`` is the force on the body along n (−N on the carrier),
    ``M`` the couple on it."""

    P: BodyPoint
    surface: CarriedLine
    c0: float = 0.0                 # its gap from the line at t = 0
    dtheta: float | None = None     # its angle less the carrier's at t = 0 (a rigid body)
    fixed_angle: bool = False       # the carrying body cannot turn (prepare.py, once assembled)
    mode: str = "on"                # "off" once its centre passed an end of the line (the event leaves)

    @property
    def rows(self):
        return 0 if self.mode == "off" else 1 if self.dtheta is None else 2

    def end_margin(self, q) -> float | None:
        return self._margin(q)

    @property
    def linear(self):
        return self.fixed_angle

    def phi_list(self, q, t):
        if self.mode == "off":
            return []
        out = [self.gap(q) - self.c0]
        if self.dtheta is not None:
            out.append(self.turned(q, self.P.body) - self.dtheta)
        return out

    def jac_list(self, q):
        if self.mode == "off":
            return []
        rows = self.jac_lines(q)[:1]
        return rows + [self.turn_row(self.P.body)] if self.dtheta is not None else rows

    def gamma_list(self, q, v, t):
        if self.mode == "off":
            return []
        return self._rows_gammas(q, v)[1][:1] + [0.0] * (self.rows - 1)

    def kkt_lists(self, q, v, t):
        if self.mode == "off":
            return [], []
        rows, gams = self._rows_gammas(q, v)
        if self.dtheta is None:
            return rows[:1], gams[:1]
        return [rows[0], self.turn_row(self.P.body)], [gams[0], 0.0]

    def hessian(self, q, w, n: int) -> np.ndarray:          # (the angle row is linear)
        if self.mode == "off":
            return np.zeros((n, n))
        return _OnLine.hessian(self, q, list(w[:1]), n)

    def report(self, lam, q, v, t):
        off = self.mode == "off"
        out = {"N": 0.0 if off else float(lam[0])}
        if self.dtheta is not None:
            out["M"] = [0.0, 0.0, 0.0 if off else float(lam[1])]
        return out


@dataclass(kw_only=True)
class CarriedRolls(_OnLine, Rolls):
    """A disk or ring rolling without slipping on a carried line (a cylinder on a plank pulled
    from under it): its centre R off the line, and no slip over the line's material point,
    ṡ + R (ω_B − ω_W) = 0, integrated as s + R (θ_B − θ_W) = const (15.8 relative to the
    carrier); past μ_s N it slips with kinetic friction against that slip, as on a fixed line."""

    surface: CarriedLine            # a carried line: the geometry is all overridden here
    fixed_angle: bool = False       # the carrying body cannot turn (prepare.py, once assembled)

    def point(self) -> Point:       # (the geometry's point: the centre)
        return self.body_point

    @property
    def linear(self):
        return self.fixed_angle

    def gap(self, q) -> float:
        return _OnLine.gap(self, q) - self.R

    def normal_speed(self, q, v) -> float:
        return self.gap_rate(q, v)

    def slip_speed(self, q, v) -> float:
        """The contact point's slip over the line: ṡ + R (ω_B − ω_W)."""
        return self.along_rate(q, v) + self.R * float(np.array(self.turn_row(self.body_point.body)) @ v)

    def roll_const(self, q) -> float:
        return self.along(q) + self.R * self.turned(q, self.body_point.body)

    def phi_list(self, q, t):
        if not self.rows:
            return []
        return [self.gap(q), self.roll_const(q) - self.c0][:self.rows]

    def _rolling_row(self, q) -> list:
        return [a + self.R * b for a, b in zip(self.jac_lines(q)[1], self.turn_row(self.body_point.body))]

    def jac_list(self, q):
        return [self.jac_lines(q)[0], self._rolling_row(q)][:self.rows]

    def gamma_list(self, q, v, t):
        return self._rows_gammas(q, v)[1][:self.rows]

    def gamma(self, q, v, t):
        return np.array(self.gamma_list(q, v, t))

    def kkt_lists(self, q, v, t):
        return self.jac_list(q), self.gamma_list(q, v, t)

    def tangent_jac(self, q) -> np.ndarray:
        return np.array(self._rolling_row(q))

    def slip_rate(self, q, v, a) -> float:
        return float(self.tangent_jac(q) @ a) - self._rows_gammas(q, v)[1][1]

    watch = _OnLine.line_watch


@dataclass(kw_only=True)
class CarriedRack(_OnLine, ListRows):
    """A gear on a rack carried by a body (the rack's pitch line is the carried line): the pitch
    circle rolls on it, s + R (θ_B − θ_W) = c0 (15.8 relative to the rack, two-sided); the gear's
    centre is held R off the line by the other joints (a pinned pinion, a slider for the rack).
    λ is the tooth force on the gear along the line's d̂ (on the rack: −λ d̂)."""

    P: BodyPoint                    # the gear's centre
    surface: CarriedLine
    R: float = 0.0
    c0: float = 0.0
    rows = 1
    linear = False

    def roll_const(self, q) -> float:
        return self.along(q) + self.R * self.turned(q, self.P.body)

    def phi_list(self, q, t):
        return [self.roll_const(q) - self.c0]

    def jac_list(self, q):
        return [[a + self.R * b for a, b in zip(self.jac_lines(q)[1], self.turn_row(self.P.body))]]

    def gamma_list(self, q, v, t):
        return [self._rows_gammas(q, v)[1][1]]

    def straight_along(self, q, N) -> bool:
        """Affine along the motion when the rack does not turn (its angle still along N)."""
        W = self.surface.body
        return not W.rigid or abs(float(np.ravel(N)[W.index[2]])) <= 1e-12 * float(np.linalg.norm(N))

    def hessian(self, q, w, n: int) -> np.ndarray:
        return _OnLine.hessian(self, q, [0.0, float(w[0])], n)

    def distance_terms(self, q, n: int):
        """(∇g, ∇²g) of the gear centre's distance from the pitch line (the check that other joints
        hold it)."""
        return np.array(self.jac_lines(q)[0]), _OnLine.hessian(self, q, [1.0, 0.0], n)

    def report(self, lam, q, v, t):
        return {"F": float(lam[0])}
