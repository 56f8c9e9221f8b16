"""A curve carried by a body (a smooth quarter-circle groove in a block free to slide, a bowl on a
cart), and the contact of a point of another body on it (docs/types/scene.md: surfaces on a body).

The curve is written as drawn at t = 0, in ground coordinates, with its body W where the file
puts it (at x_W0, turned by θ_W0): its geometry — foot, tangent, normal, curvature — is that of
the fixed curve (curved.py) in that drawing's frame.  At (q) W is at x_W turned by φ = θ_W − θ_W0
from the drawing; a point P of another body, ρ = r_P − x_W, is at r_d = x_W0 + Q(−φ) ρ in the
drawing, where its foot q*, tangent t_d, normal n_d, curvature k and distance d are read; on the
ground t = Q(φ) t_d, n = Q(φ) n_d.  With J = e3 × (a quarter turn) and ω = θ̇_W:

* the gap d(q) has the row n·(J_P − J_{x_W}) − (n·Jρ) on θ_W and, from
  d̈ = n·(ρ̈ − ω̇ Jρ − 2ω Jρ̇ − ω² ρ) − k/(1 − k d) (t·(ρ̇ − ω Jρ))² (ρ's drawing-frame
  acceleration, and the fixed curve's ∇²d = −k/(1 − k d) t̂t̂ᵀ),
  γ = −n·b_P + 2ω n·Jρ̇ + ω² n·ρ + k (t·(ρ̇ − ωJρ))²/(1 − k d);
* the slip of P over W's material point under it is t·(ρ̇ − ω Jρ): kinetic friction −μ_k N
  sign along t on P, and its opposite on W there (the generalized direction is the tangent row,
  t·(J_P − J_{x_W}) − (t·Jρ) on θ_W);
* sticking holds P on W's material point along the tangent t_s of where it stopped (fixed in
  the drawing): t_s·r_d = const, a row of the same form with γ = −c·b_P + 2ω c·Jρ̇ + ω² c·ρ,
  c = Q(φ) t_s.

A disk of radius R rolling on a carried curve (a cylinder inside a pipe that rolls or slides)
is the fixed curve's rolling (curved.CurveRolls) in the drawing, with its turn relative to the
carrier, θ_B − θ_W: the distance row d − R and the arc row arc(q*) + R (θ_B − θ_W) = const.  In
the drawing the centre moves at u = Q(−φ)(ρ̇ − ω Jρ) with the acceleration
Q(−φ)(ρ̈ − ω̇ Jρ − 2ω Jρ̇ − ω² ρ), so each row is the fixed curve's with its centre block read
through that map — ∂r_d/∂q = Q(−φ)[J_c − J_{x_W} − Jρ e_θW] — and its γ the fixed curve's at u
plus the frame's 2ω c·Jρ̇ + ω² c·ρ along the row's direction c (n, and f t for the arc row).
The contact point's slip over the carrier's material point is t·(ρ̇ − ωJρ) + R (θ̇_B − ω).

For a carried line (k = 0) these are carried.py's rows.  The rows are never affine (the foot
moves): the route is the ODE.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .curvature import point_hessian
from .curved import CurveContact, CurveData, CurveRolls
from .system import BodyData


def _turned(vec, c: float, sn: float) -> tuple[float, float]:
    """The drawing's vector on the ground: Q(φ) vec (c, sn = cos φ, sin φ)."""
    a, b = float(vec[0]), float(vec[1])
    return (c * a - sn * b, sn * a + c * b)


def _carried_row(n: int, P, W: BodyData, q, c, rho) -> np.ndarray:
    """∂(c·ρ)/∂q, ρ = r_P − x_W, for a direction c fixed in W: P's row, −c on W's centre,
    −(c·Jρ) on W's angle."""
    row = [0.0] * n
    P.add_jac(row, q, c[0], c[1])
    row[W.index[0]] -= c[0]
    row[W.index[1]] -= c[1]
    if W.rigid:
        row[W.index[2]] -= rho[0] * c[1] - rho[1] * c[0]
    return np.array(row)


def _frame_bias(c, rho, rhod, w: float) -> float:
    """2ω c·Jρ̇ + ω² c·ρ: what the carrier's turning adds to the γ of a direction c fixed in it."""
    return 2 * w * (rhod[0] * c[1] - rhod[1] * c[0]) + w * w * (c[0] * rho[0] + c[1] * rho[1])


class CarriedCurve(CurveData):
    """A curve fixed to ``body``: its expressions as drawn at t = 0 (ground coordinates), the
    body then at ``x0`` turned by ``th0``."""

    carried = True

    def __init__(self, name: str, x1, x2, q_range, body: BodyData, q0):
        super().__init__(name, x1, x2, q_range)
        i = body.index
        self.body = body
        self.x0 = (float(q0[i[0]]), float(q0[i[1]]))
        self.th0 = float(q0[i[2]]) if body.rigid else 0.0

    def placed(self, q) -> tuple[float, float, float, float]:
        """(x_W1, x_W2, cos φ, sin φ): the carrier's centre and its turn φ from the drawing."""
        W = self.body
        i = W.index
        ph = float(q[i[2]]) - self.th0 if W.rigid else 0.0
        return float(q[i[0]]), float(q[i[1]]), math.cos(ph), math.sin(ph)


@dataclass(kw_only=True)
class CarriedCurveContact(CurveContact):
    """A point of one body on a curve carried by another (module docstring)."""

    surface: CarriedCurve           # a carried curve: the geometry is all overridden here

    # --- the geometry at q (and v)
    def _geometry(self, q, v=None):
        """(q*, t, n, k, d, ρ, ρ̇ (None without v), ω): the foot and its frame on the ground."""
        s = self.surface
        rd, (r1, r2), c, sn = self._local(q)
        qf, td, nd, k, d, _ = self.foot.at(rd)
        t = _turned(td, c, sn)
        n = (-t[1], t[0])
        if v is None:
            return qf, t, n, k, d, (r1, r2), None, 0.0
        W = s.body
        pv1, pv2 = self.P.vel_xy(q, v)
        rhod = (pv1 - float(v[W.index[0]]), pv2 - float(v[W.index[1]]))
        w = float(v[W.index[2]]) if W.rigid else 0.0
        return qf, t, n, k, d, (r1, r2), rhod, w

    def _row(self, q, c, rho) -> np.ndarray:
        return _carried_row(self.n, self.P, self.surface.body, q, c, rho)

    def _bias(self, q, v, c, rho, rhod, w) -> float:
        """−c·b_P + 2ω c·Jρ̇ + ω² c·ρ: the γ of a direction c fixed in W."""
        b1, b2 = self.P.bias_xy(q, v)
        return -(c[0] * b1 + c[1] * b2) + _frame_bias(c, rho, rhod, w)

    def _relative(self, c, rho, rhod, w) -> float:
        """c·(ρ̇ − ω Jρ): P's velocity over W's material point under it, along c."""
        return c[0] * rhod[0] + c[1] * rhod[1] - w * (rho[0] * c[1] - rho[1] * c[0])

    def _stick_dir(self, q):
        """The held tangent t_s on the ground: Q(φ) t_s."""
        _x1, _x2, c, sn = self.surface.placed(q)
        return _turned(self.stick_t, c, sn)

    def _local(self, q):
        """(P in the drawing, ρ = r_P − x_W, cos φ, sin φ)."""
        s = self.surface
        xw1, xw2, c, sn = s.placed(q)
        p1, p2 = self.P.xy(q)
        r1, r2 = p1 - xw1, p2 - xw2
        return (s.x0[0] + c * r1 + sn * r2, s.x0[1] - sn * r1 + c * r2), (r1, r2), c, sn

    def _drawn(self, q) -> tuple[float, float]:
        return self._local(q)[0]

    # --- the contact's own quantities
    def stick_here(self, q) -> None:
        rd = self._drawn(q)
        td = self.foot.at(rd)[1]
        self.stick_t = (float(td[0]), float(td[1]))
        self.stick_at = float(td[0] * rd[0] + td[1] * rd[1])

    def gap(self, q) -> float:
        return float(self._geometry(q)[4])

    def normal(self, q) -> np.ndarray:
        return np.array(self._geometry(q)[2])

    def normal_speed(self, q, v) -> float:
        _, _t, n, _k, _d, rho, rhod, w = self._geometry(q, v)
        return self._relative(n, rho, rhod, w)

    def slip_speed(self, q, v) -> float:
        _, t, _n, _k, _d, rho, rhod, w = self._geometry(q, v)
        return self._relative(t, rho, rhod, w)

    def tangent_jac(self, q) -> np.ndarray:
        _, t, _n, _k, _d, rho, *_ = self._geometry(q)
        return self._row(q, t, rho)

    def phi(self, q, t):
        out = [self.gap(q)]
        if self.mode == "stick":
            rd = self._drawn(q)
            out.append(self.stick_t[0] * rd[0] + self.stick_t[1] * rd[1] - self.stick_at)
        return np.array(out[:self.rows])

    def jac(self, q):
        if not self.rows:
            return np.zeros((0, self.n))
        _, _t, n, _k, _d, rho, *_ = self._geometry(q)
        rows = [self._row(q, n, rho)]
        if self.rows > 1:
            rows.append(self._row(q, self._stick_dir(q), rho))
        return np.array(rows)

    def gamma(self, q, v, t):
        if not self.rows:
            return np.zeros(0)
        _, tt, n, k, d, rho, rhod, w = self._geometry(q, v)
        slip = self._relative(tt, rho, rhod, w)
        out = [self._bias(q, v, n, rho, rhod, w) + k * slip * slip / (1 - k * d)]
        if self.rows > 1:
            out.append(self._bias(q, v, self._stick_dir(q), rho, rhod, w))
        return np.array(out)

    def gap_acceleration(self, q, v, a) -> float:
        """d̈ at the accelerations q̈ = a (whatever the mode: the gap row and its γ)."""
        _, tt, n, k, d, rho, rhod, w = self._geometry(q, v)
        slip = self._relative(tt, rho, rhod, w)
        return float(self._row(q, n, rho) @ a) - (self._bias(q, v, n, rho, rhod, w) + k * slip * slip / (1 - k * d))

    def hessian(self, q, w, n: int) -> np.ndarray:
        """Σ w ∇² of the rows: the fixed curve's −k/(1 − k d) TTᵀ through the tangent row T, and
        for each row's direction c (n; the held t_s) fixed in W at this instant, ∇²(c·ρ) — P's
        own arm (point_hessian), c turning with W (∂c/∂θ_W = Jc) against P's and W's motion,
        and −(c·ρ) on W's angle twice (carried.py's, for a line)."""
        _, tt, nn, k, d, rho, *_ = self._geometry(q)
        T = self._row(q, tt, rho)
        H = -w[0] * k / (1 - k * d) * np.outer(T, T)
        dirs = [nn] + ([self._stick_dir(q)] if len(w) > 1 else [])
        W = self.surface.body
        for wk, c in zip(w, dirs):
            H = H + wk * point_hessian(self.P, q, c, n)
            if not W.rigid:
                continue
            ia = W.index[2]
            turned = (-c[1], c[0])                          # Jc
            row = self._row(q, turned, rho)
            row[ia] = 0.0
            H[ia, :] += wk * row
            H[:, ia] += wk * row
            H[ia, ia] += -wk * (c[0] * rho[0] + c[1] * rho[1])
        return H

    def watch(self, lam, q, v, t):
        m = self.surface.ends_margin(self._geometry(q)[0])
        if self.mode == "off":
            g = self.gap(q)
            return [("impact", g if m is None or m >= 0 else abs(g) - m)]
        return self.touching_watches(lam, q, v, m)


def contact_on(name, kind, n, path, P, curve: CarriedCurve, j: dict, q) -> CarriedCurveContact:
    """A contact on a carried curve (curved.contact_on's, on the drawing: at t = 0 it is the ground)."""
    from . import curved

    if P.body is curve.body:
        from dyncli.errors import InputError

        raise InputError(f"{P.body.name!r} carries {curve.name!r}: a body cannot touch its own surface", path + ".0")
    got = curved.contact_on(name, kind, n, path, P, curve, j, q, cls=CarriedCurveContact)
    assert isinstance(got, CarriedCurveContact)
    return got


@dataclass(kw_only=True)
class CarriedCurveRolls(CurveRolls):
    """A disk rolling on a curve carried by another body (module docstring)."""

    surface: CarriedCurve           # a carried curve: the frame terms are added here

    def _frame(self, q, v=None):
        """(the centre in the drawing, ρ, ρ̇ (None without v), ω, cos φ, sin φ)."""
        s = self.surface
        xw1, xw2, c, sn = s.placed(q)
        i = self.body_point.body.index
        r1, r2 = float(q[i[0]]) - xw1, float(q[i[1]]) - xw2
        rd = np.array((s.x0[0] + c * r1 + sn * r2, s.x0[1] - sn * r1 + c * r2))
        if v is None:
            return rd, (r1, r2), None, 0.0, c, sn
        W = s.body
        rhod = (float(v[i[0]]) - float(v[W.index[0]]), float(v[i[1]]) - float(v[W.index[1]]))
        w = float(v[W.index[2]]) if W.rigid else 0.0
        return rd, (r1, r2), rhod, w, c, sn

    def _centre(self, q):
        return self._frame(q)[0]

    def _turn(self, q) -> float:
        W = self.surface.body
        own = float(q[self.body_point.body.index[2]])
        return own - (float(q[W.index[2]]) - self.surface.th0 if W.rigid else 0.0)

    def normal(self, q) -> np.ndarray:
        _rd, _rho, _rhod, _w, c, sn = self._frame(q)
        return np.array(_turned(self.foot.at(self._centre(q))[2], c, sn))

    def tangent(self, q) -> np.ndarray:
        _rd, _rho, _rhod, _w, c, sn = self._frame(q)
        return np.array(_turned(self.foot.at(self._centre(q))[1], c, sn))

    def _row(self, q, cvec, rho) -> np.ndarray:
        return _carried_row(self.n, self.body_point, self.surface.body, q, cvec, rho)

    def _turn_row(self) -> np.ndarray:
        """∂(θ_B − θ_W)/∂q."""
        W = self.surface.body
        row = np.zeros(self.n)
        row[self.body_point.body.index[2]] = 1.0
        if W.rigid:
            row[W.index[2]] -= 1.0
        return row

    def jac(self, q):
        rd, rho, _rhod, _w, c, sn = self._frame(q)
        _, tt, nn, k, d, _ = self.foot.at(rd)
        f = (1 - self.R * k) / (1 - k * d)
        t_w, n_w = _turned(tt, c, sn), _turned(nn, c, sn)
        rows = [self._row(q, n_w, rho), f * self._row(q, t_w, rho) + self.R * self._turn_row()]
        return np.array(rows[:self.rows])

    def gamma(self, q, v, t):
        """The fixed curve's γ at the centre's velocity in the drawing, u = Q(−φ)(ρ̇ − ωJρ), plus
        the frame's terms along n and f t."""
        rd, rho, rhod, w, c, sn = self._frame(q, v)
        qf, tt, nn, k, d, _ = self.foot.at(rd)
        t_w, n_w = _turned(tt, c, sn), _turned(nn, c, sn)
        rel = (rhod[0] + w * rho[1], rhod[1] - w * rho[0])          # ρ̇ − ω Jρ
        a = t_w[0] * rel[0] + t_w[1] * rel[1]
        b = n_w[0] * rel[0] + n_w[1] * rel[1]
        wd = 1 - k * d
        kdot = self.surface.dk_ds(qf) * a / wd
        f = (1 - self.R * k) / wd
        fdot = (kdot * (d - self.R) + (1 - self.R * k) * k * b) / (wd * wd)
        g1 = k * a * a / wd + _frame_bias(n_w, rho, rhod, w)
        g2 = -(fdot * a + f * k * a * b / wd) + f * _frame_bias(t_w, rho, rhod, w)
        return np.array([g1, g2])[:self.rows]

    def normal_speed(self, q, v) -> float:
        _rd, rho, rhod, w, c, sn = self._frame(q, v)
        n_w = _turned(self.foot.at(self._centre(q))[2], c, sn)
        return (n_w[0] * (rhod[0] + w * rho[1]) + n_w[1] * (rhod[1] - w * rho[0]))

    def tangent_jac(self, q) -> np.ndarray:
        """The contact point's slip over the carrier's material point per unit rate:
        t·(J_c − J_{x_W}) − (t·Jρ) on θ_W, and R (θ̇_B − ω)."""
        _rd, rho, _rhod, _w, c, sn = self._frame(q)
        t_w = _turned(self.foot.at(self._centre(q))[1], c, sn)
        return self._row(q, t_w, rho) + self.R * self._turn_row()

    def hessian(self, q, w, n: int) -> np.ndarray:
        """Σ w ∇² of the rows: the fixed curve's Hessian in the drawing (curved.CurveRolls), read
        through ∂r_d/∂q, plus ∇²(c·ρ) for each row's gradient c in the drawing (n, f t) turned to
        the ground (W's turn against the centre's and W's motion, −(c·ρ) on W's angle twice)."""
        H = np.zeros((n, n))
        if not self.rows:
            return H
        w = list(w) + [0.0] * (2 - len(w))
        rd, rho, _rhod, _w, c, sn = self._frame(q)
        qf, tt, nn, k, d, _ = self.foot.at(rd)
        wd = 1 - k * d
        f = (1 - self.R * k) / wd
        grad_f = (self.surface.dk_ds(qf) * (d - self.R) / wd * tt + (1 - self.R * k) * k * nn) / (wd * wd)
        Hx = -w[0] * k / wd * np.outer(tt, tt) + w[1] * (np.outer(tt, grad_f) + f * k / wd * np.outer(nn, tt))
        e1, e2 = _turned((1.0, 0.0), c, sn), _turned((0.0, 1.0), c, sn)
        Jd = np.array([self._row(q, e1, rho), self._row(q, e2, rho)])       # ∂r_d/∂q (drawing axes)
        H += Jd.T @ Hx @ Jd
        W = self.surface.body
        if not W.rigid:
            return H
        ia = W.index[2]
        for wk, g in ((w[0], nn), (w[1], f * tt)):
            if wk == 0.0:
                continue
            cw = _turned(g, c, sn)
            row = self._row(q, (-cw[1], cw[0]), rho)
            row[ia] = 0.0
            H[ia, :] += wk * row
            H[:, ia] += wk * row
            H[ia, ia] += -wk * (cw[0] * rho[0] + cw[1] * rho[1])
        return H


def rolls_on(name, kind, n, path, body_point, curve: CarriedCurve, R: float, j: dict, q) -> CarriedCurveRolls:
    """A disk rolling on a carried curve (curved.rolls_on's, on the drawing)."""
    from . import curved

    if body_point.body is curve.body:
        from dyncli.errors import InputError

        raise InputError(f"{body_point.body.name!r} carries {curve.name!r}: a body cannot roll on its own surface",
                         path + ".0")
    got = curved.rolls_on(name, kind, n, path, body_point, curve, R, j, q, cls=CarriedCurveRolls)
    assert isinstance(got, CarriedCurveRolls)
    return got

