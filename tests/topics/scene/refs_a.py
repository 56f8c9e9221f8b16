"""Independent references for the scene gallery A (``test_gallery_a.py``).

Nothing here comes from dyncli.  Each scene of ``problems/scenes/`` that the gallery tests check
has two routes written in this file:

* the hand derivation of the file's header (free-body diagrams, the balance laws (29.5) and
  (32.15), the cord and rolling kinematics), evaluated with mpmath at 30 digits; where the motion
  has no closed form, its energy integral (34.20) by tanh-sinh quadrature and its equation of
  motion by mpmath's Taylor-series ODE solver (``mpmath.odefun``);
* a second formulation: Lagrange's equations with multipliers in maximal coordinates,
  ``M q̈ = Q + Σ λ_j ∇φ_j`` with ``φ_j(q) = 0``, set up by sympy from the positions of the points
  (sympy in the tests only).  Each row φ_j is written with the orientation that makes its
  multiplier the joint force the contract reports (the force on the first-named body, along the
  row's gradient), so the multipliers are the reactions without any sign fixing afterwards.

The scene data below restate the files' ``params`` (``test_gallery_a`` checks that they agree).
"""

from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

G = sp.Rational(981, 100)           # g = 9.81 m/s², the default of every file
DPS = 30


def mpf(x) -> mp.mpf:
    """A sympy number (or int / str) as an mpmath number at the working precision."""
    if isinstance(x, sp.Basic):
        return mp.mpf(sp.N(x, DPS + 10))
    return mp.mpf(x)


def g() -> mp.mpf:
    return mpf(G)


def deg(x) -> mp.mpf:
    return mpf(x) * mp.pi / 180


# ---------------------------------------------------------------------------------------------
# the second formulation: Lagrange's equations with multipliers

class Multipliers:
    """``M q̈ − Σ λ_j (∇φ_j + c_j) = Q̃``, ``∇φ_j · q̈ = −(d/dt ∇φ_j) · q̇`` for rows ``φ_j(q) = 0``.

    ``mass``: the diagonal of M (m, m per body, Ī₃₃ for a rigid body's angle); ``V``: the
    potential energy (gravity, springs); ``Q``: further generalized forces (the virtual work of an
    applied load per unit δq); ``rows``: ``{name: φ(q)}``; ``coupled``: ``{name: c}``, a generalized
    force per unit of that row's multiplier (kinetic friction −μ_k N sign d̂ at a contact,
    proportional to the contact's N).  ``solve(q, q̇)`` returns (q̈, {name: λ}) at 30 digits.
    """

    def __init__(self, q, mass, V, rows: dict, Q=None, coupled: dict | None = None):
        n = len(q)
        qd = sp.symbols(f"qd0:{n}")
        names = list(rows)
        A = sp.Matrix([[sp.diff(rows[k], qi) for qi in q] for k in names])
        b = -(A * sp.Matrix(qd)).jacobian(q) * sp.Matrix(qd)
        Qt = -sp.Matrix([sp.diff(V, qi) for qi in q])
        if Q is not None:
            Qt += sp.Matrix(Q)
        C = A.T.copy()
        for k, col in (coupled or {}).items():
            C[:, names.index(k)] += sp.Matrix(col)
        K = sp.zeros(n + len(names), n + len(names))
        K[:n, :n] = sp.diag(*mass)
        K[:n, n:] = -C
        K[n:, :n] = A
        rhs = sp.Matrix.vstack(Qt, b)
        self.n, self.names = n, names
        self._K = sp.lambdify([q, qd], K, "mpmath")
        self._rhs = sp.lambdify([q, qd], rhs, "mpmath")

    def solve(self, qv, qdv):
        qv, qdv = [mpf(x) for x in qv], [mpf(x) for x in qdv]
        sol = mp.lu_solve(mp.matrix(self._K(qv, qdv)), mp.matrix(self._rhs(qv, qdv)))
        return [sol[i] for i in range(self.n)], {k: sol[self.n + j] for j, k in enumerate(self.names)}


def _q(names):
    return sp.symbols(names)


# ---------------------------------------------------------------------------------------------
# 1. atwood-massive-pulley.yaml

ATWOOD = {"m1": 3, "m2": 2, "M": 1, "R": sp.Rational(1, 10)}


def atwood(m1, m2, M, R, I=None):
    """Closed form (exact, sympy rationals): A (m1) on the left goes down with a.

    Disk (29.5, 32.15): I α = (T1 − T2) R, R_axle = M g + T1 + T2; A: m1 a = m1 g − T1;
    B: m2 a = T2 − m2 g; no slip: a = R α."""
    m1, m2, M, R = (sp.nsimplify(x) for x in (m1, m2, M, R))
    I = M * R**2 / 2 if I is None else sp.nsimplify(I)
    a = (m1 - m2) * G / (m1 + m2 + I / R**2)
    T1, T2 = m1 * (G - a), m2 * (G + a)
    return {"a": a, "alpha": a / R, "T1": T1, "T2": T2, "R_axle": M * G + T1 + T2, "I": I}


def atwood_multipliers(m1, m2, M, R, I=None):
    """q = (xA, yA, xB, yB, xp, yp, θ); rows: the cord's left and right runs (no slip on the
    disk: yA − yp + Rθ and yB − yp − Rθ, their multipliers the tensions T1, T2), the pin
    (xp, yp: the force on the pulley by the ground), the hanging masses guided on their
    verticals (xA, xB)."""
    m1, m2, M, R = (sp.nsimplify(x) for x in (m1, m2, M, R))
    I = M * R**2 / 2 if I is None else sp.nsimplify(I)
    xA, yA, xB, yB, xp, yp, th = q = _q("xA yA xB yB xp yp th")
    return Multipliers(q, [m1, m1, m2, m2, M, M, I], G * (m1 * yA + m2 * yB + M * yp),
                       {"T1": yA - yp + R * th, "T2": yB - yp - R * th, "R1": xp, "R2": yp,
                        "gA": xA, "gB": xB})


# ---------------------------------------------------------------------------------------------
# 2., 3. incline-pulley-slides.yaml, incline-pulley-sticks.yaml

SLIDES = {"m1": 2, "m2": 3, "mu_s": sp.Rational(3, 10), "mu_k": sp.Rational(1, 5), "beta": 30}
STICKS = {"m1": 4, "m2": 3, "mu_s": sp.Rational(7, 20), "mu_k": sp.Rational(3, 10), "beta": 30}


def incline(m1, m2, mu_s, mu_k, beta_deg):
    """Block A (m1) on the slope, tied over a light pulley at the top to B (m2) hanging.

    A along d̂: m1 s̈ = T − m1 g sin β + F, along n: N = m1 g cos β; B: m2 s̈ = m2 g − T
    (s̈ the common rate: A up the slope, B down).  At rest the static test: the friction needed
    to hold A, F0 = −(m2 − m1 sin β) g, against μ_s N.  Returns exact sympy values."""
    b = sp.rad(beta_deg)
    N = m1 * G * sp.cos(b)
    F0 = -(m2 - m1 * sp.sin(b)) * G
    if abs(F0) <= mu_s * N:       # holds: no motion
        return {"stuck": True, "a": sp.Integer(0), "T": m2 * G, "N": N, "F": F0, "limit": mu_s * N}
    sgn = sp.sign(-F0)            # slides the way the unbalanced load pulls
    F = -mu_k * N * sgn
    a = (m2 * G - m1 * G * sp.sin(b) + F) / (m1 + m2)
    return {"stuck": False, "a": a, "T": m2 * (G - a), "N": N, "F": F, "limit": mu_s * N, "sign": sgn}


def incline_multipliers(m1, m2, mu_k, beta_deg, mode):
    """q = (xA, yA, xB, yB); rows: the contact n·r_A (multiplier N), the cord d̂·r_A + yB (its
    length d̂·(P − r_A) + (P2 − yB) is constant; multiplier T: T d̂ on A, T e2 on B), B guided on
    its vertical (xB); ``mode`` "stick" adds d̂·r_A (multiplier: the friction F along d̂),
    "up" the kinetic friction −μ_k N d̂ on A sliding up the slope."""
    b = sp.rad(beta_deg)
    d, n = (sp.cos(b), sp.sin(b)), (-sp.sin(b), sp.cos(b))
    xA, yA, xB, yB = q = _q("xA yA xB yB")
    rows = {"N": n[0] * xA + n[1] * yA, "T": d[0] * xA + d[1] * yA + yB, "gB": xB}
    coupled = None
    if mode == "stick":
        rows["F"] = d[0] * xA + d[1] * yA
    else:
        coupled = {"N": [-mu_k * d[0], -mu_k * d[1], 0, 0]}
    return Multipliers(q, [m1, m1, m2, m2], G * (m1 * yA + m2 * yB), rows, coupled=coupled)


def block_limit(m, beta_deg):
    """A block alone on a slope with μ_s = tan β exactly: N = m g cos β, F = m g sin β (up)."""
    b = sp.rad(beta_deg)
    return {"N": m * G * sp.cos(b), "F": m * G * sp.sin(b)}


# ---------------------------------------------------------------------------------------------
# 4. sliding-ladder.yaml  (θ from the floor; the rod's angle ψ = π − θ: e'1 from foot to top)

LADDER = {"m": 10, "L": 5, "theta0": 60}


def ladder_rates(theta, theta0, L):
    """θ̇² and θ̈ while both contacts hold (energy 34.20: ½(mL²/3)θ̇² = mg(L/2)(sin θ0 − sin θ))."""
    k = 3 * g() / L
    return -mp.sqrt(k * (mp.sin(theta0) - mp.sin(theta))), -k / 2 * mp.cos(theta)


def ladder_reactions(theta, theta0, m, L):
    """Hand route (29.5): N_w = m ẍ̄1 = (3mg/4) cos θ (3 sin θ − 2 sin θ0),
    N_f = m g + m ẍ̄2 = mg − (3mg/4)(cos²θ + 2 sin θ sin θ0 − 2 sin²θ)."""
    c = 3 * m * g() / 4
    s, s0 = mp.sin(theta), mp.sin(theta0)
    return c * mp.cos(theta) * (3 * s - 2 * s0), m * g() - c * (mp.cos(theta) ** 2 + 2 * s * s0 - 2 * s * s)


def ladder_time(theta, theta0, L):
    """t(θ) = ∫_θ^θ0 dθ / sqrt((3g/L)(sin θ0 − sin θ)), with sin θ0 − sin θ = w² (the square-root
    singularity at the release removed): dθ = −2w dw / cos θ."""
    k = 3 * g() / L
    s0 = mp.sin(theta0)
    wmax = mp.sqrt(s0 - mp.sin(theta))
    f = lambda w: 2 / mp.sqrt(k) / mp.sqrt(1 - (s0 - w * w) ** 2)   # noqa: E731
    # near the vertical the integrand peaks at w ~ cos θ0: split there (tanh-sinh on each piece)
    pts = [mp.mpf(0)] + [p for p in (mp.cos(theta0) * 10 ** j for j in range(0, 8)) if p < wmax] + [wmax]
    return mp.quad(f, pts)


def ladder_release(theta0, L):
    """The wall lets go at sin θ* = (2/3) sin θ0: (θ*, t*)."""
    ths = mp.asin(mp.mpf(2) / 3 * mp.sin(theta0))
    return ths, ladder_time(ths, theta0, L)


@functools.lru_cache(maxsize=None)
def ladder_floor_phase(theta0_deg, m, L):
    """After the wall lets go, the rod on the smooth floor alone (a second, independent
    formulation): no horizontal force, so ẋ̄1 = const (36.10); the foot on the floor gives
    x̄2 = (L/2) sin θ, and Lagrange's equation in θ with M(θ) = m(L²/4) cos²θ + mL²/12,
    V = m g (L/2) sin θ: M θ̈ − (mL²/4) cos θ sin θ θ̇² + m g (L/2) cos θ = 0, from the state at
    the separation (θ*, θ̇* from the energy integral of the first phase).  Returns
    (t*, ẋ̄1, θ(t), θ̇(t) as mpmath's Taylor ODE solver, N_f(θ, θ̇))."""
    th0 = deg(theta0_deg)
    ths, ts = ladder_release(th0, L)
    thd_s = ladder_rates(ths, th0, L)[0]
    vx = -L / 2 * mp.sin(ths) * thd_s
    m, L = mpf(m), mpf(L)

    def acc(th, thd):
        M = m * L**2 / 4 * mp.cos(th) ** 2 + m * L**2 / 12
        return (m * L**2 / 4 * mp.cos(th) * mp.sin(th) * thd**2 - m * g() * L / 2 * mp.cos(th)) / M

    def floor(th, thd):          # N_f = m g + m ẍ̄2, x̄2 = (L/2) sin θ
        return m * g() + m * L / 2 * (mp.cos(th) * acc(th, thd) - mp.sin(th) * thd**2)

    sol = mp.odefun(lambda t, y: [y[1], acc(y[0], y[1])], ts, [ths, thd_s])
    return ts, vx, sol, floor


@functools.lru_cache(maxsize=None)
def ladder_motion(theta0_deg, L):
    """θ(t), θ̇(t) by mpmath's Taylor ODE solver on θ̈ = −(3g/2L) cos θ (a second route beside the
    quadrature)."""
    k = 3 * g() / L
    th0 = deg(theta0_deg)
    return mp.odefun(lambda t, y: [y[1], -k / 2 * mp.cos(y[0])], 0, [th0, mp.mpf(0)])


def ladder_multipliers(m, L):
    """q = (x, y, ψ) of the rod (ψ of e'1, foot end1 → top end2); rows: the floor under end1
    (e2·r_end1, multiplier N_f), the wall at end2 (e1·r_end2, multiplier N_w)."""
    m, L = sp.nsimplify(m), sp.nsimplify(L)
    x, y, psi = q = _q("x y psi")
    return Multipliers(q, [m, m, m * L**2 / 12], G * m * y,
                       {"N_f": y - L / 2 * sp.sin(psi), "N_w": x + L / 2 * sp.cos(psi)})


# ---------------------------------------------------------------------------------------------
# 5. rolling-disk-spring.yaml

DISK = {"m": 2, "R": sp.Rational(1, 5), "k": 250, "L0": sp.Rational(1, 2), "beta": 30, "at": 2,
        "mu_s": sp.Rational(1, 2)}


def disk_closed_form(t, m, R, k, beta, **_):
    """Rolling (15.8) with the spring at its free length at t = 0, from rest.  s down the slope:
    (m + I/R²) s̈ = m g sin β − k s, I = mR²/2 → s = δ(1 − cos ωt), ω² = 2k/(3m), δ = m g sin β/k.
    Friction (32.15 about the centre): I ω̇ = R F with ω̇ = s̈/R → F = (m/2) s̈ (up the slope
    when positive); N = m g cos β."""
    m, R, k = mpf(m), mpf(R), mpf(k)
    b = deg(beta)
    w = mp.sqrt(2 * k / (3 * m))
    dl = m * g() * mp.sin(b) / k
    s, sd, sdd = dl * (1 - mp.cos(w * t)), dl * w * mp.sin(w * t), dl * w * w * mp.cos(w * t)
    return {"omega_n": w, "delta": dl, "s": s, "sd": sd, "sdd": sdd, "F": m / 2 * sdd,
            "N": m * g() * mp.cos(b), "spring": k * s}


def disk_start(R, beta, at, L0, **_):
    """Centre at t = 0 (contact point `at` along d̂ from the origin, centre R along n) and the
    spring's anchor L0 up the slope from it."""
    b = deg(beta)
    d, n = (mp.cos(b), mp.sin(b)), (-mp.sin(b), mp.cos(b))
    c0 = [mpf(at) * d[i] + mpf(R) * n[i] for i in range(2)]
    return c0, [c0[i] + mpf(L0) * d[i] for i in range(2)], d, n


def disk_multipliers(m, R, k, L0, beta, at, **_):
    """q = (x, y, θ); rows: n·r − R (multiplier N), d̂·r + Rθ (no slip: the friction F along d̂ at
    the contact point has the moment R F about the centre, so its multiplier is F); the spring
    from the centre to the anchor in V."""
    m, R, k, L0 = (sp.nsimplify(v) for v in (m, R, k, L0))
    b = sp.rad(beta)
    d, n = (sp.cos(b), sp.sin(b)), (-sp.sin(b), sp.cos(b))
    anc = [(at + L0) * d[i] + R * n[i] for i in range(2)]
    x, y, th = q = _q("x y th")
    stretch = sp.sqrt((x - anc[0]) ** 2 + (y - anc[1]) ** 2) - L0
    return Multipliers(q, [m, m, m * R**2 / 2], G * m * y + k * stretch**2 / 2,
                       {"N": n[0] * x + n[1] * y - R, "F": d[0] * x + d[1] * y + R * th})


# ---------------------------------------------------------------------------------------------
# 6. pulled-spool.yaml  (a constant force P e1 at the material point `hub`, r above the centre
# at t = 0; the point turns with the spool)

SPOOL = {"m": 5, "I": sp.Rational(1, 5), "R": sp.Rational(3, 10), "r": sp.Rational(3, 20), "P": 20,
         "mu_s": sp.Rational(2, 5)}


def spool_accel(x, m, I, R, r, P, **_):
    """ẍ of the centre with the spool rolled on by x (angle −x/R, hub at r[sin(x/R), cos(x/R)]
    from the centre): (m + I/R²) ẍ = P (1 + (r/R) cos(x/R)); F = m ẍ − P; N = m g."""
    m, I, R, r, P = (mpf(v) for v in (m, I, R, r, P))
    return P * (1 + r / R * mp.cos(x / R)) / (m + I / R**2)


@functools.lru_cache(maxsize=None)
def spool_motion():
    return mp.odefun(lambda t, y: [y[1], spool_accel(y[0], **SPOOL)], 0, [mp.mpf(0), mp.mpf(0)])


def spool_time(X, m, I, R, r, P, **_):
    """The time to roll X from rest by the energy integral ½(m + I/R²) ẋ² = P (x + r sin(x/R))
    (the work of P at the hub, 34.20), with x = u² removing the square-root singularity."""
    m, I, R, r, P = (mpf(v) for v in (m, I, R, r, P))
    Me = m + I / R**2
    f = lambda u: 2 * u / mp.sqrt(2 * P * (u * u + r * mp.sin(u * u / R)) / Me) if u else 2 / mp.sqrt(2 * P * (1 + r / R) / Me)  # noqa: E731
    return mp.quad(f, [0, mp.sqrt(mpf(X))])


def spool_multipliers(m, I, R, r, P, **_):
    """q = (x, y, θ); rows: y − R (the floor: N), x + Rθ (no slip: F); the force P e1 at the hub
    r(−sin θ, cos θ) from the centre: Q = P e1 · ∂r_hub/∂q = (P, 0, −P r cos θ)."""
    m, I, R, r, P = (sp.nsimplify(v) for v in (m, I, R, r, P))
    x, y, th = q = _q("x y th")
    return Multipliers(q, [m, m, I], G * m * y, {"N": y - R, "F": x + R * th},
                       Q=[P, 0, -P * r * sp.cos(th)])
