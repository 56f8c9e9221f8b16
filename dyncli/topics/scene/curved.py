"""Curved surfaces of a scene: a contact and rolling on a curve y(q) (docs/types/scene.md).

The curve is y(q) = x1(q) e1 + x2(q) e2 with exact derivatives y′, y″ (dyncli's own rules on the
expression IR, as the ``constrained-particle`` type); its unit tangent t̂ = y′/|y′|, the normal
n = e3 × t̂ (the bodies' side, as for a straight surface) and the signed curvature
k = (y′₁y″₂ − y′₂y″₁)/|y′|³ (k > 0 where the curve turns towards n: inside a bowl or a loop),
so that dt̂/ds = k n and dn/ds = −k t̂.

A point r has its foot q*(r) on the curve ((r − y)·y′ = 0, Newton from the last foot) and the
signed distance d(r) = n·(r − y(q*)); ∇d = n, and the foot moves at ṡ = t̂·ṙ/(1 − k d).

* :class:`CurveContact` — P on the curve: φ = d(r_P) = 0, J = nᵀ J_P,
  γ = k (t̂·v_P)²/(1 − k d) − n·(J̇_P v); N = λ along n (≥ 0).
* :class:`CurveRolls` — a disk of radius R rolls on it: its centre on the offset curve,
  φ₁ = d(x) − R; and no slip, t̂·ẋ + R ω = 0, integrated exactly:
  φ₂ = ∫ |y′| (1 − R k) dq (from the foot of t = 0 to the foot now; the offset curve's arc
  length) + R θ − c₀, J₂ = (1 − R k)/(1 − k d) t̂ᵀ on x and R on θ (γ₂ with the curvature's
  rate dk/ds from y‴).  N along n, F along t̂ at the contact, as on a line.
  Its phases are those of rolling on a line (contacts.py): "roll" (both rows), "slip" (the
  distance row and kinetic friction −μ_k N sign along t̂ at the contact point, whose speed is
  t̂·ẋ + R ω: the generalized direction [t̂; R]), "off" (in flight: the gap d − R watched for
  an impact); a return to rolling restarts φ₂'s constant at that instant.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from dyncli.errors import NumericalError
from dyncli.expr.derivative import derivative
from dyncli.quadrature import gauss_kronrod
from dyncli.rootfind import all_roots

from .contacts import Contact, TurningRolls
from .elements import Element

EPS = float(np.finfo(float).eps)
#: a search of the nearest point (rootfind.all_roots of (r − y)·y′): its starting cells, the most
#: cells and the most roots it takes — at t = 0 (once), and when Newton from the last foot fails
#: during the motion or the assembly (a curve of a few turns takes a few dozen cells and roots; a
#: q_range of thousands of laps is searched only that far)
NEAREST_FIRST, NEAREST_AGAIN = (64, 4000, 2000), (8, 256, 64)
#: the arcs of rolling (CurveRolls.arc) kept per element, by foot (then forgotten all at once)
ARC_MEMO = 4096


class CurveData:
    """A fixed curve y(q); ``q_range`` its ends (None: none)."""

    curved = True
    length = None

    def __init__(self, name: str, x1, x2, q_range=None):
        self.name = name
        self.y0 = (x1, x2)
        self.y1 = tuple(derivative(e, "q") for e in self.y0)
        self.y2 = tuple(derivative(e, "q") for e in self.y1)
        self.y3 = tuple(derivative(e, "q") for e in self.y2)
        self.q_range = tuple(q_range) if q_range is not None else None
        self._fns: tuple | None = None

    # ------------------------------------------------------------------ geometry at q
    def _ev(self, order: int, q: float) -> np.ndarray:
        """y (order 0) or its ``order``-th derivative at one q, in plain floats (the expressions'
        closures over floats, :mod:`dyncli.expr.floateval`: about 10x cheaper than an array of
        one; the frame is read thousands of times a solve)."""
        f1, f2 = self._closures()[order]
        return np.array((f1(q), f2(q)))

    def _closures(self) -> tuple:
        """((x1, x2) of y, y′, y″, y‴) as float closures, made once."""
        if self._fns is None:
            from dyncli.expr.floateval import float_fn

            self._fns = tuple(tuple(float_fn(e, "q") for e in es) for es in (self.y0, self.y1, self.y2, self.y3))
        return self._fns

    def frame(self, q: float):
        """(y, y′, t̂, n, k, |y′|) at q."""
        y, d1, d2 = self._ev(0, q), self._ev(1, q), self._ev(2, q)
        sp = math.hypot(d1[0], d1[1])
        if not sp > 0:
            raise NumericalError(f"the curve {self.name!r} has no tangent at q = {q:.6g} (y′ = 0)")
        t = d1 / sp
        k = (d1[0] * d2[1] - d1[1] * d2[0]) / sp ** 3
        return y, d1, t, np.array([-t[1], t[0]]), k, sp

    def offset_speeds(self, qs, R: float) -> np.ndarray:
        """|y′|(1 − R k) at each q of ``qs``: the rate of the offset curve's arc (a rolling disk's
        φ₂ integrand), in plain floats — the same operations as :meth:`frame`, without its
        arrays (the arc's quadrature reads it at every node)."""
        (a1, b1), (a2, b2) = self._closures()[1:3]
        out = np.empty(len(qs))
        for j, qq in enumerate(qs):
            qq = float(qq)
            x1, y1, x2, y2 = a1(qq), b1(qq), a2(qq), b2(qq)
            sp = math.hypot(x1, y1)
            if not sp > 0:
                raise NumericalError(f"the curve {self.name!r} has no tangent at q = {qq:.6g} (y′ = 0)")
            out[j] = sp * (1 - R * ((x1 * y2 - y1 * x2) / sp ** 3))
        return out

    def _newton(self, r, q: float):
        """Newton on (r − y)·y′ = 0 from q: the foot q* when it converges to a nearest point
        (|r − y|² a minimum there), else None.  Each step moves the foot at most a quarter of
        min(|r − y|, 1/|k|) + 1/|k| along the curve, so that from a guess far away (a state asked
        out of order) it walks to the nearest foot on its side instead of jumping to another lap
        of a closed curve (where the arc of rolling, φ₂, would be a lap off); for a point far
        from a bend (|r − y| ≫ 1/|k|) the step stays within half the bend's radius, inside
        Newton's basin there (a step of |r − y|/4 jumps across the bend and back forever)."""
        (f0, h0), (f1, h1), (f2, h2) = self._closures()[:3]     # plain floats: no array a step
        r0, r1 = float(r[0]), float(r[1])
        for _ in range(200):
            a1, b1, a2, b2 = f1(q), h1(q), f2(q), h2(q)
            w0, w1 = r0 - f0(q), r1 - h0(q)
            g = w0 * a1 + w1 * b1
            dd = a1 * a1 + b1 * b1
            gp = (w0 * a2 + w1 * b2) - dd
            if not gp < 0:
                return None
            step = g / gp
            sp = math.sqrt(dd)
            rho = sp ** 3 / max(abs(a1 * b2 - b1 * a2), 1e-300)
            cap = 0.25 * (min(math.sqrt(w0 * w0 + w1 * w1), rho) + rho)
            if abs(step) * sp > cap:
                step = math.copysign(cap / sp, step)
            q -= step
            if abs(step) <= 4 * EPS * max(1.0, abs(q)):
                return q
        return None

    def dk_ds(self, q: float) -> float:
        """The rate of the curvature along the arc, dk/ds = (dk/dq)/|y′|."""
        d1, d2, d3 = self._ev(1, q), self._ev(2, q), self._ev(3, q)
        sp = math.hypot(d1[0], d1[1])
        cross = d1[0] * d2[1] - d1[1] * d2[0]
        dk = (d1[0] * d3[1] - d1[1] * d3[0]) / sp ** 3 - 3 * cross * float(d1 @ d2) / sp ** 5
        return dk / sp

    def foot(self, r, guess: float) -> float:
        """q* with (r − y(q*))·y′(q*) = 0, a nearest point: Newton from ``guess``, else from the
        nearest point over q_range (or guess ± 10), decided exactly (:meth:`_nearest`)."""
        got = self._newton(r, float(guess))
        if got is not None and (self.q_range is None or
                                self.q_range[0] - 0.5 <= got <= self.q_range[1] + 0.5):
            return got                  # (a foot well beyond the curve's ends is another lap: searched)
        a, b = self.q_range if self.q_range is not None else (guess - 10.0, guess + 10.0)
        got = self._newton(r, self._nearest(r, a, b, *NEAREST_AGAIN))
        if got is None:
            raise NumericalError(f"no nearest point on the curve {self.name!r} for the point {list(map(float, r))}")
        return got

    def _nearest(self, r, a: float, b: float, start: int, cells: int, most: int) -> float:
        """The nearest point of the curve to r over [a, b]: every root of g(q) = (r − y)·y′ (the
        critical points of |r − y|², by the sign analysis of :func:`dyncli.rootfind.all_roots`,
        each cell's interpolant of g resolved to its rounding) and the ends, the nearest of them —
        an exact critical point for Newton to start from, not the best of a table of samples
        (beside a sharp bend the best sample can start Newton off the curve)."""
        r0, r1 = float(r[0]), float(r[1])

        def on(es, qs):
            return [e.evaluate(q=qs) if e.variables else np.full(qs.shape, float(e.value())) for e in es]

        def g(qs):
            if qs.size == 1:            # (Brent's steps: the float closures)
                (y0, y1), (d0, d1) = self._ev(0, float(qs[0])), self._ev(1, float(qs[0]))
                return np.array([(r0 - y0) * d0 + (r1 - y1) * d1])
            (y0, y1), (d0, d1) = on(self.y0, qs), on(self.y1, qs)
            return (r0 - y0) * d0 + (r1 - y1) * d1

        # bounded for a q_range of many laps (each lap's roots are found): past the budget the
        # cells not searched count as candidates by their midpoints
        roots, touches, bad = all_roots(g, a, b, cells=start, budget=cells, limit=most)
        qs = np.array([a, b, *roots, *touches, *bad], dtype=float)
        with np.errstate(all="ignore"):
            y0, y1 = on(self.y0, qs)
            d2 = (y0 - r0) ** 2 + (y1 - r1) ** 2
        d2 = np.where(np.isfinite(d2), d2, np.inf)
        return float(qs[int(np.argmin(d2))])

    def first_foot(self, r, at: float | None) -> float:
        """The foot of r at t = 0: from ``at``, else the nearest point over q_range (or
        [−10, 10])."""
        if at is not None:
            return self.foot(r, at)
        a, b = self.q_range if self.q_range is not None else (-10.0, 10.0)
        return self.foot(r, self._nearest(r, a, b, *NEAREST_FIRST))

    def ends_margin(self, q: float) -> float | None:
        if self.q_range is None:
            return None
        return float(min(q - self.q_range[0], self.q_range[1] - q))

    def drawing(self) -> dict:
        return {"name": self.name, "points": self.polyline()}

    def polyline(self, n: int = 200) -> list[tuple[float, float]]:
        a, b = self.q_range if self.q_range is not None else (-math.pi, math.pi)
        qs = np.linspace(a, b, n)           # the drawing's points (plots), never a decision
        ys = np.stack([e.evaluate(q=qs) if e.variables else np.full(n, float(e.value())) for e in self.y0])
        return [(float(u), float(v)) for u, v in zip(ys[0], ys[1])]


class _Foot:
    """The foot of one point, cached for the last position asked."""

    def __init__(self, curve: CurveData, q0: float):
        self.curve, self.q, self._key = curve, q0, None

    def at(self, r):
        key = (float(r[0]), float(r[1]))
        if key != self._key:
            self.q = self.curve.foot(r, self.q)
            self._key = key
            self._frame = self.curve.frame(self.q)
        y, _d1, t, n, k, sp = self._frame
        d = float(n @ (np.asarray(r, float) - y))
        return self.q, t, n, k, d, sp


@dataclass(kw_only=True)
class CurveContact(Contact):
    """P on a curve, pushing only; Coulomb friction along t̂ at the foot (kinetic −μ_k N sign
    while sliding; sticking holds P where it stopped: the second row t̂ₛ·r_P = const with the
    tangent t̂ₛ of that point, exact while P stays there)."""

    surface: CurveData  # type: ignore[assignment]  # a curve where Contact has a line: the geometry is all overridden here
    foot: _Foot
    stick_t: tuple = (1.0, 0.0)

    # the curve's own rows (not the line's list forms of Contact): through the arrays
    phi_list = Element.phi_list
    jac_list = Element.jac_list
    gamma_list = Element.gamma_list
    kkt_lists = Element.kkt_lists

    def phase(self):
        return (self.mode, self.sign, self.stick_at, self.stick_t)

    def set_phase(self, state) -> None:
        self.mode, self.sign, self.stick_at, self.stick_t = state

    def stick_here(self, q) -> None:
        r = self.P.pos(q)
        tt = self.foot.at(r)[1]
        self.stick_t = (float(tt[0]), float(tt[1]))
        self.stick_at = float(tt @ r)

    def tangent_jac(self, q) -> np.ndarray:
        return self.foot.at(self.P.pos(q))[1] @ self.P.jac(q, self.n)

    @property
    def linear(self):
        return False

    def gap(self, q) -> float:
        return float(self.foot.at(self.P.pos(q))[4])

    def normal(self, q) -> np.ndarray:
        return self.foot.at(self.P.pos(q))[2]

    def phi(self, q, t):
        out = [self.gap(q)]
        if self.mode == "stick":
            out.append(float(np.array(self.stick_t) @ self.P.pos(q)) - self.stick_at)
        return np.array(out[:self.rows])

    def jac(self, q):
        if not self.rows:                                   # released (a phase in flight): no row
            return np.zeros((0, self.n))
        n = self.foot.at(self.P.pos(q))[2]
        JP = self.P.jac(q, self.n)
        return np.array([n @ JP, np.array(self.stick_t) @ JP][:self.rows])

    def gamma(self, q, v, t):
        if not self.rows:
            return np.zeros(0)
        _, tt, n, k, d, _ = self.foot.at(self.P.pos(q))
        vp = self.P.vel(q, v)
        b = self.P.bias(q, v)
        out = [k * float(tt @ vp) ** 2 / (1 - k * d) - float(n @ b), -float(np.array(self.stick_t) @ b)]
        return np.array(out[:self.rows])

    def slip_speed(self, q, v) -> float:
        return float(self.foot.at(self.P.pos(q))[1] @ self.P.vel(q, v))

    def hessian(self, q, w, n: int) -> np.ndarray:
        """∇²(w d(r_P)): the distance's own −k/(1 − k d) t̂t̂ᵀ through J_P, plus n's turn of P's arm."""
        from .curvature import point_hessian

        _, tt, nn, k, d, _ = self.foot.at(self.P.pos(q))
        JP = self.P.jac(q, n)
        Hr = -k / (1 - k * d) * np.outer(tt, tt)
        H = w[0] * (JP.T @ Hr @ JP + point_hessian(self.P, q, nn, n))
        if len(w) > 1:                                      # sticking: the held row's arm
            H = H + point_hessian(self.P, q, w[1] * np.array(self.stick_t), n)
        return H

    def watch(self, lam, q, v, t):
        m = self.surface.ends_margin(self.foot.at(self.P.pos(q))[0])
        if self.mode == "off":                              # in flight: it strikes the curve again
            return [("impact", self.gap(q) if m is None or m >= 0 else abs(self.gap(q)) - m)]
        return self.touching_watches(lam, q, v, m)


@dataclass(kw_only=True)
class CurveRolls(TurningRolls):
    """A disk of radius R rolling on a curve without slipping."""

    surface: CurveData  # type: ignore[assignment]  # a curve where Rolls has a line: the geometry is all overridden here
    foot: _Foot
    q_ref: float = 0.0

    def _centre(self, q):
        """Where the foot is read: the centre (a carried curve's subclass: the centre in its drawing)."""
        i = self.body_point.body.index
        return np.array([q[i[0]], q[i[1]]], float)

    def _turn(self, q) -> float:
        """The angle the body has rolled through on the curve: its own (on a carried curve: relative
        to the carrier)."""
        return float(q[self.body_point.body.index[2]])

    def arc(self, qf: float) -> float:
        """∫ |y′|(1 − R k) dq from the foot of t = 0 to qf: the offset curve's arc length (each
        foot's value kept: a search of equilibria along a free translation, or a state asked
        again, reads the same feet many times — the same double, one quadrature)."""
        if qf == self.q_ref:
            return 0.0
        memo = self.__dict__.setdefault("_arcs", {})
        got = memo.get(qf)
        if got is None:
            c, R = self.surface, self.R
            got = float(gauss_kronrod(lambda x: c.offset_speeds(x, R), self.q_ref, qf, 1e-14, 1e-15)[0])
            if len(memo) >= ARC_MEMO:
                memo.clear()
            memo[qf] = got
        return got

    def gap(self, q) -> float:
        return float(self.foot.at(self._centre(q))[4]) - self.R

    def normal(self, q) -> np.ndarray:
        return self.foot.at(self._centre(q))[2]

    def tangent(self, q) -> np.ndarray:
        return self.foot.at(self._centre(q))[1]

    def roll_const(self, q) -> float:
        return self.arc(self.foot.at(self._centre(q))[0]) + self.R * self._turn(q)

    def phi(self, q, t):
        if not self.rows:
            return np.zeros(0)
        qf, _, _, _, d, _ = self.foot.at(self._centre(q))
        if self.rows == 1:
            return np.array([d - self.R])
        roll = self.arc(qf) + self.R * self._turn(q) - self.c0
        if abs(roll) > 0.5 * self.R:        # the foot on another lap of a closed curve: the one θ rolled to
            qf, d = self._lap(q)
            roll = self.arc(qf) + self.R * self._turn(q) - self.c0
        return np.array([d - self.R, roll])

    def _lap(self, q):
        """The foot on the lap the body has rolled to: Newton on arc(q) = c₀ − R θ (the arc
        grows with q at |y′|(1 − R k) > 0), then the nearest point from there."""
        want, qq = self.c0 - self.R * self._turn(q), self.foot.q
        for _ in range(60):
            _, _, _, _, k, sp = self.surface.frame(qq)
            step = (self.arc(qq) - want) / (sp * (1 - self.R * k))
            qq -= step
            if abs(step) <= 1e-12 * max(1.0, abs(qq)):
                break
        self.foot.q, self.foot._key = qq, None
        got = self.foot.at(self._centre(q))
        return got[0], got[4]

    def jac(self, q):
        i = self.body_point.body.index
        _, tt, n, k, d, _ = self.foot.at(self._centre(q))
        J = np.zeros((2, self.n))
        J[0, i[0]], J[0, i[1]] = n
        f = (1 - self.R * k) / (1 - k * d)
        J[1, i[0]], J[1, i[1]] = f * tt
        J[1, i[2]] = self.R
        return J[:self.rows]

    def gamma(self, q, v, t):
        """−J̇ẋ: row 1 k a²/(1 − k d); row 2 −(ḟ a + f k a b/(1 − k d)) with a = t̂·ẋ, b = n·ẋ,
        f = (1 − R k)/(1 − k d), ḟ = (k̇ (d − R) + (1 − R k) k b)/(1 − k d)², k̇ = dk/ds · a/(1 − k d)."""
        i = self.body_point.body.index
        qf, tt, n, k, d, _ = self.foot.at(self._centre(q))
        vc = np.array([v[i[0]], v[i[1]]], float)
        a, b = float(tt @ vc), float(n @ vc)
        w = 1 - k * d
        kdot = self.surface.dk_ds(qf) * a / w
        f = (1 - self.R * k) / w
        fdot = (kdot * (d - self.R) + (1 - self.R * k) * k * b) / (w * w)
        return np.array([k * a * a / w, -(fdot * a + f * k * a * b / w)])[:self.rows]

    def hessian(self, q, w, n: int) -> np.ndarray:
        """Σ w ∇²φ on the centre's block: −w₁ k/(1 − k d) t̂t̂ᵀ for the distance, and for the arc
        row w₂ (t̂ ∇fᵀ + f k/(1 − k d) n t̂ᵀ), the derivatives of its Jacobian f t̂ (γ's terms)."""
        i = self.body_point.body.index
        H = np.zeros((n, n))
        if not self.rows:
            return H
        w = list(w) + [0.0] * (2 - len(w))             # slipping: the distance row alone
        qf, tt, nn, k, d, _ = self.foot.at(self._centre(q))
        wd = 1 - k * d
        f = (1 - self.R * k) / wd
        grad_f = (self.surface.dk_ds(qf) * (d - self.R) / wd * tt + (1 - self.R * k) * k * nn) / (wd * wd)
        Hx = -w[0] * k / wd * np.outer(tt, tt) + w[1] * (np.outer(tt, grad_f) + f * k / wd * np.outer(nn, tt))
        H[np.ix_([i[0], i[1]], [i[0], i[1]])] = Hx
        return H

    def watch(self, lam, q, v, t):
        m = self.surface.ends_margin(self.foot.at(self._centre(q))[0])
        if self.mode == "off":                              # in flight: it lands on the curve again
            return [("impact", self.gap(q) if m is None or m >= 0 else abs(self.gap(q)) - m)]
        return self.touching_watches(lam, q, v, m)


def contact_on(name, kind, n, path, P, curve: CurveData, j: dict, q, cls=None) -> CurveContact:
    """A contact on a curve, with its friction coefficients (mu for both, or mu_s / mu_k; one
    given stands for the other, as on a line); ``cls``: CurveContact, or a kind of it."""
    mu_s = j["mu"] if j["mu"] is not None else (j.get("mu_s") or 0.0)
    mu_k = j["mu"] if j["mu"] is not None else (j["mu_k"] if j.get("mu_k") is not None else mu_s)
    if j.get("mu_k") is not None and j.get("mu_s") is None:
        mu_s = mu_k
    foot = _Foot(curve, curve.first_foot(P.pos(q), j["at"]))
    kw = dict(P=P, surface=curve, mu_s=mu_s, mu_k=mu_k, mode="slide" if (mu_s or mu_k) else "smooth", foot=foot,
              e=float(j.get("e") or 0.0))
    return CurveContact(name, kind, n, path, **kw) if cls is None else cls(name, kind, n, path, **kw)


def rolls_on(name, kind, n, path, body_point, curve: CurveData, R: float, j: dict, q, cls=None) -> CurveRolls:
    """A disk rolling on a curve (``cls``: CurveRolls, or a kind of it): the foot of its centre at
    t = 0 (at t = 0 a carried curve's drawing is the ground), the arc measured from there."""
    i = body_point.body.index
    x = np.array([q[i[0]], q[i[1]]], float)
    q0 = curve.first_foot(x, j["at"])
    mu_k = j["mu_k"] if j.get("mu_k") is not None else j["mu_s"]
    kw = dict(body_point=body_point, surface=curve, R=R, c0=0.0, mu_s=j["mu_s"], mu_k=mu_k, foot=_Foot(curve, q0),
              q_ref=q0, e=j.get("e") or 0.0)
    el = CurveRolls(name, kind, n, path, **kw) if cls is None else cls(name, kind, n, path, **kw)
    el.c0 = R * el._turn(q)
    return el


def place_on(curve: CurveData, at: float, offset: float) -> np.ndarray:
    """The point at distance ``offset`` on the bodies' side of the curve at q = at."""
    y, _, _, n, _, _ = curve.frame(at)
    return y + offset * n
