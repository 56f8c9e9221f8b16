"""The Kepler problem (notes §21-§22 with the inverse-square force 19.18): conic elements from a
state, Kepler's equation and the state at any time, as pure functions of plain numbers and arrays.

mu = g R0² [m³/s²] is the attraction per unit mass times R²; r, v are the position from the
centre and the velocity.  Every formula is written to keep its accuracy on very eccentric
orbits: the perigee distance r_p = p/(1 + e), p = h²/mu, is formed without 1 − e, and so are
the radius a(1 − e cos E) = r_p + 2 a e sin²(E/2) and Kepler's equation
M = (1 − e) E + e (E − sin E) (with 1 − e = r_p/a); the anomaly is counted from the initial
position, so a circular orbit (no perigee) needs no special case.

* elliptic (e < 1): E − e sin E = M, Newton on a bracket (always converges, e up to 1 − 1e-15);
* hyperbolic (e > 1): e sinh H − H = M, the same;
* parabolic (|1 − e| within rounding, :data:`PARABOLIC`): Barker's equation
  D + D³/3 = 2 sqrt(mu/p³) (t − t_p), D = tan(ν/2), solved in closed form.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import NumericalError

EPS = 2.220446049250313e-16
#: |1 − e| below this is a parabola (Barker's equation): a few roundings of v0²r0/(2 mu)
PARABOLIC = 16 * EPS
_SERIES = 0.3       # below this |E|, E − sin E and sinh H − H by their series
#: beyond this mean anomaly [rad] (1e15 revolutions) M mod 2π keeps no correct digit: no phase
PHASE_LOST = 2 * math.pi * 1e15


def e_minus_sin(E):
    """E − sin E without cancellation (series for small |E|).

    >>> round(float(e_minus_sin(1e-3)) / (1e-9 / 6 - 1e-15 / 120), 14)
    1.0
    """
    E = np.asarray(E, float)
    E2 = E * E
    small = E * E2 / 6 * (1 - E2 / 20 * (1 - E2 / 42 * (1 - E2 / 72 * (1 - E2 / 110 * (1 - E2 / 156)))))
    return np.where(np.abs(E) < _SERIES, small, E - np.sin(E))


def sinh_minus(H):
    """sinh H − H without cancellation (series for small |H|)."""
    H = np.asarray(H, float)
    H2 = H * H
    small = H * H2 / 6 * (1 + H2 / 20 * (1 + H2 / 42 * (1 + H2 / 72 * (1 + H2 / 110 * (1 + H2 / 156)))))
    return np.where(np.abs(H) < _SERIES, small, np.sinh(H) - H)


def kepler_E(M, e: float, one_minus_e: float | None = None):
    """The eccentric anomaly E of E − e sin E = M (elliptic, 0 <= e < 1), M any real (array).

    M is reduced to [−π, π]; on that range E − M = e sin E lies between 0 and e·sign(M), a bracket
    on which Newton's steps are kept (a step leaving it bisects), so it converges from any start
    for any e < 1.  ``one_minus_e`` (1 − e formed without cancellation) keeps the equation
    accurate near the perigee of a very eccentric orbit.

    >>> E = float(kepler_E(1.0, 0.5)); round(E - 0.5 * math.sin(E), 15)
    1.0
    """
    M = np.asarray(M, float)
    if M.size and not float(np.max(np.abs(M))) < PHASE_LOST:
        raise NumericalError(f"the orbit's phase is lost to rounding at a mean anomaly of {float(np.max(np.abs(M))):.3g} "
                             "rad (more than 1e15 revolutions from its start): ask for earlier times")
    ome = 1.0 - e if one_minus_e is None else one_minus_e
    k = np.round(M / (2 * np.pi))
    m = M - 2 * np.pi * k
    s = np.where(m < 0, -1.0, 1.0)
    m = np.abs(m)
    lo, hi = m.copy(), np.minimum(m + e, np.pi)
    E = np.where(e > 0.8, np.minimum(m + 0.85 * e, np.pi), m + e * np.sin(m))     # Danby's start
    E = np.clip(E, lo, hi)

    E = _newton(lambda E: ome * E + e * e_minus_sin(E) - m,
                lambda E: ome + e * (1 - np.cos(E)), E, lo, hi, 100)        # 1 − e cos E
    return s * E + 2 * np.pi * k


def kepler_H(M, e: float, e_minus_one: float | None = None):
    """The hyperbolic anomaly H of e sinh H − H = M (e > 1), M any real (array); Newton kept on the
    bracket [asinh(M/e), asinh(M/(e − 1))] (for M >= 0; odd in M).

    >>> H = float(kepler_H(2.0, 1.5)); round(1.5 * math.sinh(H) - H, 14)
    2.0
    """
    M = np.asarray(M, float)
    emo = e - 1.0 if e_minus_one is None else e_minus_one
    s = np.where(M < 0, -1.0, 1.0)
    m = np.abs(M)
    lo, hi = np.arcsinh(m / e), np.arcsinh(m / emo)
    E = np.clip(np.log1p(2 * m / e) if e > 0 else m, lo, hi)

    E = _newton(lambda H: emo * np.sinh(H) + sinh_minus(H) - m,
                lambda H: emo * np.cosh(H) + (np.cosh(H) - 1), E, lo, hi, 200)   # e cosh H − 1
    return s * E


def _newton(f, df, x, lo, hi, maxit: int):
    """The roots of an increasing ``f`` (arrays), each bracketed by [lo, hi]: Newton from ``x``,
    a step that leaves the bracket replaced by bisection, until the step or the bracket is at
    the rounding of x — the one safeguarded iteration of Kepler's and the hyperbolic equation."""
    for _ in range(maxit):
        fx = f(x)
        lo, hi = np.where(fx < 0, x, lo), np.where(fx > 0, x, hi)
        d = df(x)
        xn = x - np.where(d > 0, fx / np.where(d > 0, d, 1.0), 0.0)
        xn = np.where((xn >= lo) & (xn <= hi), xn, 0.5 * (lo + hi))
        done = np.abs(xn - x) <= 4 * EPS * np.maximum(np.abs(xn), 1e-300)
        x = xn
        if np.all(done | (hi - lo <= 2 * EPS * np.maximum(hi, 1e-300))):
            break
    return x


def barker_D(B):
    """D = tan(ν/2) of Barker's equation D + D³/3 = B (a parabola, B = 2 sqrt(mu/p³)(t − t_p)): the
    real root of D³ + 3D − 3B = 0, D = 2 sinh(asinh(3B/2)/3) (no cancellation at any B).

    >>> D = float(barker_D(4 / 3)); round(D, 14)
    1.0
    """
    return 2 * np.sinh(np.arcsinh(1.5 * np.asarray(B, float)) / 3)


def inverse_a(mu: float, r, v) -> float:
    """1/a = 2/R − v²/mu (vis-viva) without its cancellation near a parabola: the numerator of
    (4 mu² − R² v⁴)/((2 mu + R v²) R mu) in exact rational arithmetic of the given doubles (R² = r·r
    and v² are exact there), so 1/a keeps its relative accuracy when v is near the escape speed.

    >>> inverse_a(1.0, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    1.0
    """
    from fractions import Fraction as Fr

    R2 = sum(Fr(float(c)) ** 2 for c in r)
    V2 = sum(Fr(float(c)) ** 2 for c in v)
    num = 4 * Fr(mu) ** 2 - R2 * V2 * V2
    R, v2 = math.sqrt(float(R2)), float(V2)
    return float(num) / ((2 * mu + R * v2) * R * mu)


def radial_fall_time(mu: float, R: float, rdot: float):
    """The time after which a particle on a radial line (h = 0) at distance R with radial speed
    ṙ reaches the centre, or None when it escapes (ṙ >= 0 at or above the escape speed).
    Bound (energy < 0): r = a(1 − cos E), t = sqrt(a³/mu)(E − sin E), the centre at E = 2π;
    unbound falling in: r = A(cosh H − 1), t = sqrt(A³/mu)(sinh H − H), the centre at H = 0;
    at the escape speed exactly: t = (2/3) R^1.5/sqrt(2 mu).

    >>> round(radial_fall_time(1.0, 1.0, 0.0) / (math.pi / 2 / math.sqrt(2)), 14)   # from rest
    1.0
    """
    eps = rdot * rdot / 2 - mu / R
    if eps < 0:
        a = -mu / (2 * eps)
        E0 = math.acos(min(max(1 - R / a, -1.0), 1.0))
        E0 = E0 if rdot >= 0 else 2 * math.pi - E0
        return math.sqrt(a ** 3 / mu) * (2 * math.pi - E0 + math.sin(E0))
    if rdot >= 0:
        return None
    if eps == 0:
        return 2 / 3 * R ** 1.5 / math.sqrt(2 * mu)
    A = mu / (2 * eps)
    H0 = math.acosh(1 + R / A)
    return math.sqrt(A ** 3 / mu) * float(sinh_minus(H0))


class Orbit:
    """The conic of a state (r, v) about the centre under mu = g R0²; ``state(t)`` at any time.

    Attributes: ``e``, ``a`` (inf on a parabola, < 0 on a hyperbola), ``p`` (semi-latus rectum),
    ``r_p``, ``r_a`` (None open), ``period`` (None open), ``h`` (|r × v|), ``kind``
    (``"elliptic"``, ``"parabolic"``, ``"hyperbolic"``), ``M0`` (the mean anomaly at t = 0; the
    eccentric / hyperbolic anomaly or Barker's D at t = 0 in ``anom0``)."""

    def __init__(self, mu: float, r, v):
        r, v = np.asarray(r, float), np.asarray(v, float)
        self.mu, self.r0, self.v0 = mu, r, v
        R, V2 = float(np.linalg.norm(r)), float(v @ v)
        hv = np.cross(r, v)
        h = float(np.linalg.norm(hv))
        self.R0, self.h = R, h
        self.radial = not h > 1e-13 * R * math.sqrt(V2 + mu / R)
        if self.radial:
            return
        self.W = hv / h                                  # the normal of the plane of the orbit
        self.P = r / R                                   # the initial direction
        self.Q = np.cross(self.W, self.P)
        self.p = h * h / mu
        sigma = float(r @ v)                             # r ṙ
        self.ecos = self.p / R - 1.0                     # e cos ν0
        self.esin = sigma * h / (mu * R)                # e sin ν0 = ṙ0 sqrt(p/mu)
        self.e = e = math.hypot(self.ecos, self.esin)
        alpha = inverse_a(mu, r, v)                      # 1/a (vis-viva)
        self.r_p = self.p / (1.0 + e)
        self.nu0 = math.atan2(self.esin, self.ecos)      # the true anomaly at t = 0
        self.r_a: float | None = None                   # (an ellipse's)
        self.period: float | None = None
        if abs(alpha) * R <= PARABOLIC * max(1.0, V2 * R / mu):
            self._parabola()
        elif alpha > 0:
            self._ellipse(1.0 / alpha)
        else:
            self._hyperbola(1.0 / alpha)
        # the angle is counted from the anomaly the same formulas give at t = 0 (so the state at
        # t = 0 is the input to rounding even where the perigee's direction is undefined, e -> 0)
        self.nu0 = 0.0
        self.nu0 = float(self.anomalies(np.zeros(1))[1][0])

    # -- the three conics --------------------------------------------------------------------------

    def _ellipse(self, a):
        self.kind, self.a = "elliptic", a
        self.ome = min(max(self.r_p / a, 0.0), 1.0)       # 1 − e without cancellation
        self.r_a = 2 * a - self.r_p
        self.n = math.sqrt(self.mu / a) / a
        self.period = 2 * math.pi / self.n
        # e sin E0 = r ṙ / sqrt(mu a), e cos E0 = 1 − r/a
        E0 = math.atan2(float(self.r0 @ self.v0) / math.sqrt(self.mu * a), 1.0 - self.R0 / a)
        self.anom0 = E0
        self.M0 = float(self.ome * E0 + self.e * e_minus_sin(E0))

    def _hyperbola(self, a):
        self.kind, self.a = "hyperbolic", a
        A = -a
        self.emo = self.r_p / A                          # e − 1
        self.n = math.sqrt(self.mu / A) / A
        H0 = math.asinh(float(self.r0 @ self.v0) / math.sqrt(self.mu * A) / self.e)
        self.anom0 = H0
        self.M0 = float(self.emo * math.sinh(H0) + sinh_minus(H0))

    def _parabola(self):
        self.kind, self.a, self.e = "parabolic", math.inf, 1.0
        self.r_p = self.p / 2
        self.n = 2 * math.sqrt(self.mu / self.p) / self.p     # B = n (t − t_p)
        D0 = math.tan(self.nu0 / 2)
        self.anom0 = D0
        self.M0 = D0 + D0 ** 3 / 3

    # -- the state at any time ---------------------------------------------------------------------

    def anomalies(self, t):
        """(r, ν − ν0, ṙ) at times t (arrays): the radius, the angle swept from the initial
        position in the plane of the orbit, and the radial speed."""
        t = np.asarray(t, float)
        M = self.M0 + self.n * t
        mu, e, p = self.mu, self.e, self.p
        if self.kind == "elliptic":
            a = self.a
            E = kepler_E(M, e, self.ome)
            s2 = np.sin(E / 2) ** 2
            r = self.r_p + 2 * a * e * s2
            nu = 2 * np.arctan2(math.sqrt(1 + e) * np.sin(E / 2), math.sqrt(self.ome) * np.cos(E / 2))
            esin = e * np.sqrt(a * p) * np.sin(E) / r           # e sin ν
            turns = np.round((E - nu) / (2 * np.pi))             # ν continuous with E
            nu = nu + 2 * np.pi * turns
        elif self.kind == "hyperbolic":
            A = -self.a
            H = kepler_H(M, e, self.emo)
            r = self.r_p + 2 * A * e * np.sinh(H / 2) ** 2
            nu = 2 * np.arctan2(math.sqrt(e + 1) * np.sinh(H / 2), math.sqrt(self.emo) * np.cosh(H / 2))
            esin = e * np.sqrt(A * p) * np.sinh(H) / r
        else:
            D = barker_D(M)
            r = p * (1 + D * D) / 2
            nu = 2 * np.arctan(D)
            esin = 2 * D / (1 + D * D)
        rdot = math.sqrt(mu / p) * esin
        return r, nu - self.nu0, rdot

    def state(self, t):
        """(x, v) at times t: arrays 3 × n (from the centre)."""
        r, dnu, rdot = self.anomalies(t)
        c, s = np.cos(dnu), np.sin(dnu)
        er = np.outer(self.P, c) + np.outer(self.Q, s)
        et = np.outer(self.Q, c) - np.outer(self.P, s)
        return er * r, er * rdot + et * (self.h / r)

    def time_at_radius(self, R: float, t_end: float):
        """The first time in [0, t_end] at which the distance from the centre is R (r_p <= R),
        or None: the anomalies of r = R on the way out and on the way in, as times after t = 0."""
        e = self.e
        if self.kind == "elliptic":
            c = (1.0 - R / self.a) / e if e > 0 else 2.0
            if abs(c) > 1:
                return None
            Es = (math.acos(c), -math.acos(c))
            Ms = [float(self.ome * E + e * e_minus_sin(E)) for E in Es]
            ts = [((M - self.M0) % (2 * math.pi)) / self.n for M in Ms]
        else:
            if self.kind == "hyperbolic":
                H = math.acosh(max((1.0 + R / -self.a) / e, 1.0))
                MR = float(self.emo * math.sinh(H) + sinh_minus(H))
            else:
                D = math.sqrt(max(2 * R / self.p - 1, 0.0))
                MR = D + D ** 3 / 3
            ts = [(M - self.M0) / self.n for M in (MR, -MR)]
        ts = [t for t in ts if 0 <= t <= t_end]
        return min(ts) if ts else None

    def perigee_time(self):
        """The first time >= 0 of the perigee passage (None on an open orbit moving away)."""
        if self.kind == "elliptic":
            return ((-self.M0) % (2 * math.pi)) / self.n
        return -self.M0 / self.n if self.M0 <= 0 else None
