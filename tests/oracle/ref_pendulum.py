"""Oracle cases: the simple pendulum (θ̈ = −(g/l) sin θ) at small amplitude, near the separatrix
and over the top.  From rest at θ0: k = sin(θ0/2), period 4 K(k²)/ωₙ, θ(t) = 2 asin(k cd(ωₙt | k²));
from the bottom with θ̇0 > 2ωₙ (over the top): k = θ̇0/(2ωₙ) > 1, one turn takes 2 K(1/k²)/(k ωₙ) and
θ = 2 am(k ωₙ t | 1/k²).  mpmath's ellipk/ellipfun at 40 digits, from the inputs' doubles."""

from __future__ import annotations

import math

import mpmath as mp

from tests.oracle.common import case, closed, same, x

L, G = 1.0, 9.81


def _swing(theta0, times, cond_period=16, cond_theta=64):
    T0, l, g = x(theta0), x(L), x(G)
    wn = mp.sqrt(g / l)
    k = mp.sin(T0 / 2)
    m = k ** 2
    P = 4 * mp.ellipk(m) / wn
    th = lambda t: 2 * mp.asin(k * mp.ellipfun("cd", wn * t, m=m))     # noqa: E731
    checks = [closed("period", P, cond=cond_period, reason="K(m) formed from cos²(θ0/2) = 1 − m"),
              closed("period_small", 2 * mp.pi / wn)]
    checks += [closed(f"theta.{i}", th(x(t)), scale=T0, cond=cond_theta * (1 + float(wn * x(t))),
                      reason="the phase ωₙt carried through sn: condition ~ (1 + ωₙ t)")
               for i, t in enumerate(times)]
    return case(f"pendulum from rest at {theta0:.6g} rad", "pendulum",
                {"l": L, "theta0": theta0, "at": times}, checks,
                f"swing: period {mp.nstr(P, 8)} s, {mp.nstr(P * wn / (2 * mp.pi), 8)} × the small-angle period",
                same_=[same("regime", "swing")])


def _over_the_top(ratio, times):
    l, g = x(L), x(G)
    wn = mp.sqrt(g / l)
    td0 = float(ratio * math.sqrt(G / L))
    k = x(td0) / (2 * wn)
    P = 2 * mp.ellipk(1 / k ** 2) / (k * wn)
    checks = [closed("period", P, cond=16, reason="K(1/k²) of the turn")]
    m = 1 / k ** 2
    for i, t in enumerate(times):
        u = k * wn * x(t)
        # θ/2 = am(u | m): the φ with F(φ | m) = u (θ/2 grows monotonically over the top)
        phi = mp.findroot(lambda f: mp.ellipf(f, m) - u, u * mp.pi / (2 * mp.ellipk(m)))
        checks.append(closed(f"theta.{i}", 2 * phi, scale=max(abs(2 * phi), 1), cond=64 * (1 + float(u)),
                             reason="the unwrapped angle 2 am(k ωₙ t | 1/k²)"))
    return case(f"pendulum over the top at θ̇0 = {ratio:g} ωₙ", "pendulum",
                {"l": L, "theta0": 0, "theta_dot0": td0, "at": times}, checks,
                f"rotating: one turn in {mp.nstr(P, 8)} s", same_=[same("regime", "rotating")])


def cases():
    return [_swing(1e-8, [0, 1.3]), _swing(2 * math.pi / 3, [0, 0.5, 1, 100]),
            _swing(math.pi - 1e-6, [0, 2, 10], cond_period=64, cond_theta=1e7),
            _over_the_top(2.5, [0, 0.3, 1.1])]
