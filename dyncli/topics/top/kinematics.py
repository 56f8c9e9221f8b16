"""Kinematics of the heavy symmetric top's representation (notes §38): the unit
quaternion of the 3-1-3 Euler angles, body components of ω, the constants and
right-hand side of the spin-free equations (:mod:`dyncli.topics.top.integrator`),
and the nutation bounds.

Nutation bounds: with u = cosθ, the energy and the two momentum integrals
(H·e3 and ω3 = ψ̇ cosθ + φ̇) give u̇² = f(u) = (α − βu)(1 − u²) − (b − cu)²,
a cubic; θ_min, θ_max are its roots around u0 = cosθ0.  The cubic is formed
about u0 (its constant term (θ̇0 sinθ0)² exact), solved with numpy.roots and
polished in v = 1 − u or w = 1 + u near the poles.  Plain floats except the root finding
(numpy, imported there: the exact route of a top without times never needs it).
"""

from __future__ import annotations

from dataclasses import dataclass

import math
import sys

TWO_PI = 2.0 * math.pi
EPS = sys.float_info.epsilon
#: sinθ below this: ψ and φ individually undefined (only ψ ± φ)
S_TINY = 1e-12


def wrap_angle(x: float) -> float:
    """The angle x reduced to (−π, π] (``math.remainder`` by 2π, −π sent to π): the step
    between two angles taken the short way round."""
    r = math.remainder(x, TWO_PI)
    return math.pi if r == -math.pi else r


# ---------------------------------------------------------------------------
# kinematics of the representation


def quat_from_euler(psi: float, theta: float, phi: float) -> tuple[float, float, float, float]:
    """Unit quaternion of Rz(ψ) Rx(θ) Rz(φ) (columns = body axes, 38.6-38.7)."""
    ch, sh = math.cos(theta / 2), math.sin(theta / 2)
    s2, d2 = (psi + phi) / 2, (psi - phi) / 2
    return (ch * math.cos(s2), sh * math.cos(d2), sh * math.sin(d2), ch * math.sin(s2))


def body_omega(theta, phi, psi_dot, theta_dot, phi_dot) -> tuple[float, float, float]:
    """Body components of ω = θ̇ e''_1 + ψ̇ sinθ e''_2 + (ψ̇ cosθ + φ̇) e''_3 (38.11b)."""
    o1, o2, o3 = theta_dot, psi_dot * math.sin(theta), psi_dot * math.cos(theta) + phi_dot
    c, s = math.cos(phi), math.sin(phi)
    return (o1 * c + o2 * s, -o1 * s + o2 * c, o3)


def gamma(q) -> tuple[float, float, float]:
    """Body components of the fixed e3 (third row of the rotation)."""
    q0, q1, q2, q3 = q
    return 2.0 * (q1 * q3 - q0 * q2), 2.0 * (q2 * q3 + q0 * q1), q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3


def half_angles(q):
    """(θ, sinθ, cosθ, a, b) with ψ ≡ a + b, φ ≡ a − b (mod 2π)."""
    q0, q1, q2, q3 = q
    n03, n12 = math.hypot(q0, q3), math.hypot(q1, q2)
    n2 = n03 * n03 + n12 * n12
    return (2.0 * math.atan2(n12, n03), 2.0 * n03 * n12 / n2, (n03 - n12) * (n03 + n12) / n2,
            math.atan2(q3, q0), math.atan2(q2, q1))


@dataclass(frozen=True, slots=True)
class Controls:
    """The solve's accuracy controls as plain values: ``method`` (auto, exact, DOP853, RK45,
    Radau, LSODA, projected), the tolerances, the step budget (None: the runner's) and whether a
    check solve estimates the error."""

    method: str = "auto"
    rtol: float = 1e-10
    atol: float = 1e-12
    max_steps: int | None = None
    estimate: bool = False


class Top:
    """Constants of one top and the right-hand side of the body equations."""

    def __init__(self, m, L, A, C, g):
        self.m, self.L, self.A, self.C, self.g = m, L, A, C, g
        self.mgL = m * g * L
        self.k1 = (A - C) / A
        self.kg = self.mgL / A
        self.kc = C / A

    def rhs_spinfree(self, t, y):
        """Equations in the spin-free frame (q = p ⊗ r(ω3 t), module docstring): state
        (p, v1, v2, ω3); p turns with (v1, v2, 0), v turns at I33 ω3/I11 plus gravity."""
        p0, p1, p2, p3, v1, v2, w3 = y.tolist()
        g1 = 2.0 * (p1 * p3 - p0 * p2)
        g2 = 2.0 * (p2 * p3 + p0 * p1)
        kc, kg = self.kc * w3, self.kg
        return [
            -0.5 * (p1 * v1 + p2 * v2),
            0.5 * (p0 * v1 - p3 * v2),
            0.5 * (p0 * v2 + p3 * v1),
            0.5 * (p1 * v2 - p2 * v1),
            -kc * v2 + kg * g2,
            kc * v1 - kg * g1,
            0.0,
        ]

    def invariants(self, q, w):
        """E, H·e3, ω3 of a state (body components)."""
        g1, g2, g3 = gamma(q)
        w1, w2, w3 = w
        A, C = self.A, self.C
        E = 0.5 * (A * (w1 * w1 + w2 * w2) + C * w3 * w3) + self.mgL * g3
        H = A * (w1 * g1 + w2 * g2) + C * w3 * g3
        return E, H, w3

    def project(self, y, E0, H0, W3, S):
        """Move y onto E = E0, H·e3 = H0, ω3 = W3, |q| = 1 (minimum-norm
        Gauss-Newton in (√I11 w1, √I11 w2, S δ), δ a small body rotation)."""
        A, C, mgL = self.A, self.C, self.mgL
        q0, q1, q2, q3, w1, w2, w3 = (float(v) for v in y)
        n = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
        q0, q1, q2, q3 = q0 / n, q1 / n, q2 / n, q3 / n
        w3 = W3
        rA = math.sqrt(A)
        for _ in range(2):
            g1, g2, g3 = gamma((q0, q1, q2, q3))
            c1 = 0.5 * (A * (w1 * w1 + w2 * w2) + C * w3 * w3) + mgL * g3 - E0
            c2 = A * (w1 * g1 + w2 * g2) + C * w3 * g3 - H0
            h0, h1, h2 = A * w1, A * w2, C * w3
            # rows of the Jacobian in the scaled variables
            J1 = (h0 / rA, h1 / rA, -mgL * g2 / S, mgL * g1 / S, 0.0)
            J2 = (A * g1 / rA, A * g2 / rA, (h1 * g3 - h2 * g2) / S, (h2 * g1 - h0 * g3) / S, (h0 * g2 - h1 * g1) / S)
            a = sum(x * x for x in J1)
            b = sum(x * z for x, z in zip(J1, J2))
            d = sum(x * x for x in J2)
            det = a * d - b * b
            if det > 1e-12 * a * d and det > 0:
                l1 = (d * c1 - b * c2) / det
                l2 = (a * c2 - b * c1) / det
            elif a >= d and a > 0:      # (nearly) one constraint direction: use the larger row
                l1, l2 = c1 / a, 0.0
            elif d > 0:
                l1, l2 = 0.0, c2 / d
            else:
                break
            dz = [-(l1 * x + l2 * z) for x, z in zip(J1, J2)]
            w1 += dz[0] / rA
            w2 += dz[1] / rA
            d1, d2, d3 = 0.5 * dz[2] / S, 0.5 * dz[3] / S, 0.5 * dz[4] / S
            # q <- q ⊗ (1, δ/2), renormalised
            q0, q1, q2, q3 = (q0 - q1 * d1 - q2 * d2 - q3 * d3, q1 + q0 * d1 + q2 * d3 - q3 * d2,
                              q2 + q0 * d2 + q3 * d1 - q1 * d3, q3 + q0 * d3 + q1 * d2 - q2 * d1)
            n = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
            q0, q1, q2, q3 = q0 / n, q1 / n, q2 / n, q3 / n
        import numpy as np

        return np.array([q0, q1, q2, q3, w1, w2, w3])


# ---------------------------------------------------------------------------
# nutation bounds (semi-analytic)


def _newton(coef, x, lo, hi):
    """Polish a root of the polynomial ``coef`` (highest first) within [lo, hi]."""
    import numpy as np

    p = np.poly1d(coef)
    dp = p.deriv()
    fx = abs(p(x))
    for _ in range(8):
        d = dp(x)
        if d == 0 or not math.isfinite(d):
            break
        xn = min(max(x - p(x) / d, lo), hi)
        fn = abs(p(xn))
        if not fn < fx:
            break
        x, fx = xn, fn
    return x


def nutation_cubic(A, C, mgL, theta0, theta_dot0, psi_dot0, omega3):
    """The coefficients [β, F2, F1, F0] of f about u0 (x = u − u0) and (u0, v0, w0, K, P, β, c);
    a coefficient that is not finite means the top overflows a double."""
    s0, u0 = math.sin(theta0), math.cos(theta0)
    v0 = 2.0 * math.sin(theta0 / 2) ** 2        # 1 − u0
    w0 = 2.0 * math.cos(theta0 / 2) ** 2        # 1 + u0
    K = _sq(theta_dot0) + _sq(psi_dot0 * s0)    # α − β u0 = |ω⊥|²
    P = psi_dot0 * s0 * s0                      # b − c u0
    beta = 2.0 * mgL / A
    c = C * omega3 / A
    F0 = _sq(theta_dot0 * s0)
    F1 = -beta * s0 * s0 - 2.0 * u0 * K + 2.0 * c * P
    F2 = 2.0 * beta * u0 - K - c * c
    return [beta, F2, F1, F0], (u0, v0, w0, K, P, beta, c)


def _sq(x: float) -> float:
    """x² (inf on overflow, where x ** 2 of a float raises)."""
    return x * x


def turning_points(A, C, mgL, theta0, theta_dot0, psi_dot0, omega3):
    """θ_min, θ_max of the nutation and the bound of |ω⊥|² over the motion.

    f(u) = (α − βu)(1 − u²) − (b − cu)², u = cosθ, with α = (2E − I33 ω3²)/I11,
    β = 2mgL/I11, b = H·e3/I11, c = I33 ω3/I11; the motion keeps f(u) = u̇² ≥ 0."""
    coef, (u0, v0, w0, K, P, beta, c) = nutation_cubic(A, C, mgL, theta0, theta_dot0, psi_dot0, omega3)
    if not all(math.isfinite(x) for x in coef):
        return math.nan, math.nan, math.nan     # the caller reports the overflow
    import numpy as np

    # a leading coefficient so small that the companion matrix overflows (β ~ 1e-315) belongs to a
    # root |x| ≫ 2, outside the physical range u ∈ [-1, 1]: drop it
    while coef and (coef[0] == 0.0 or not all(math.isfinite(x / coef[0]) for x in coef[1:])):
        coef = coef[1:]
    if len(coef) <= 1:
        return theta0, theta0, K
    r = np.roots(coef)
    x = np.sort(r.real)
    x1 = min(float(x[0]), 0.0)
    x2 = max(float(x[1]), 0.0) if len(x) > 1 else 0.0
    # upper root u2 = u0 + x2 (θ_min), in v = 1 − u
    D, B = K - beta * v0, P - c * v0
    v2 = min(max(v0 - x2, 0.0), v0)
    if v2 < 0.5:
        v2 = _newton([-beta, 2 * beta - D - c * c, 2 * D - 2 * B * c, -B * B], v2, 0.0, v0)
        th_min = 2.0 * math.asin(math.sqrt(v2 / 2.0))
    else:
        th_min = math.acos(min(max(u0 + x2, -1.0), 1.0))
    # lower root u1 = u0 + x1 (θ_max), in w = 1 + u
    Dp, Bp = K + beta * w0, P + c * w0
    w1 = min(max(w0 + x1, 0.0), w0)
    if w1 < 0.5:
        w1 = _newton([beta, -(Dp + 2 * beta + c * c), 2 * Dp + 2 * Bp * c, -Bp * Bp], w1, 0.0, w0)
        th_max = math.pi - 2.0 * math.asin(math.sqrt(w1 / 2.0))
    else:
        th_max = math.acos(min(max(u0 + x1, -1.0), 1.0))
    th_min, th_max = min(th_min, theta0), max(th_max, theta0)
    wperp2 = K + beta * max(u0 - math.cos(th_max), 0.0)
    return th_min, th_max, wperp2
