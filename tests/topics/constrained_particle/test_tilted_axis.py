"""The ODE route's right-hand side works on the curve's own frame and turns the forces only when
the field is not symmetric about the axis (dynamics.Model.rhs_for): each of its three paths — the
vertical axis with a symmetric field, a tilted axis with a symmetric field (dampers, drag), a tilted
axis with gravity and a custom force (turned to the fixed frame and back) — against an independent
reference: Lagrange's equation of the bead, derived here by sympy from L = ½ m |v|² − m g x3 with
v = d/dt (Q(φ) y(q)) on the fixed frame and the generalised force of the other forces F·∂x/∂q,
integrated by scipy at rtol 1e-12.  q, q̇ within the route's promise (100 × rtol of their scale),
and the energy balance E − E1 = W̄ + W_N held (20.4 with the work of N)."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from tests.conftest import solve_one_text

TIMES = [0.0, 0.4, 0.8, 1.2, 1.6, 2.0]
RTOL = 1e-9
BETA = 0.4                      # the axis tilted by β from e3 in the (e2, e3) plane
AXIS = (0.0, math.sin(BETA), math.cos(BETA))
CASES = {
    # name: (axis, forces as YAML, damper c, custom force (F1, F2, F3) as sympy of x1, x2, x3, v1, v2, v3)
    "vertical-symmetric": ((0.0, 0.0, 1.0), "[{kind: gravity}, {kind: damper, c: 0.05}]", 0.05, None),
    "tilted-symmetric": (AXIS, "[{kind: damper, c: 0.05}]", 0.05, None),
    "tilted-turned": (AXIS, '[{kind: gravity}, {kind: custom, F: ["0.2", "-0.1*x1", "0.05*v3"]}]', 0.0,
                      ("0.2", "-0.1*x1", "0.05*v3")),
}
M, R, G = 0.1, 0.5, 9.81


def _text(axis, forces):
    return (f'type: constrained-particle\nm: {M}\ncurve: {{x1: "{R}*sin(q)", x2: "0.1*q", x3: "-{R}*cos(q)"}}\n'
            f'rotation: {{axis: [{axis[0]!r}, {axis[1]!r}, {axis[2]!r}], omega: "3 + 0.5*t"}}\nq0: 0.3\nq_dot0: 1.0\n'
            f"forces: {forces}\nat: {TIMES}\naccuracy: {{rtol: {RTOL}, atol: {RTOL * 1e-3}, method: ode}}\n")


@functools.lru_cache(maxsize=None)
def reference(name):
    axis, _, c, custom = CASES[name]
    t, q, qd, phi = sp.symbols("t q qd phi", real=True)
    k = sp.Matrix(axis)
    K = sp.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    Q = sp.eye(3) + sp.sin(phi) * K + (1 - sp.cos(phi)) * K * K
    y = sp.Matrix([R * sp.sin(q), sp.Rational(1, 10) * q, -R * sp.cos(q)])
    w = 3 + t / 2
    x = Q * y
    v = x.diff(q) * qd + x.diff(phi) * w                      # φ̇ = ω
    L = M * (v.T * v)[0] / 2 - (M * G * x[2] if "gravity" in CASES[name][1] else 0)
    F = -c * v
    if custom:
        env = {s: val for s, val in zip(sp.symbols("x1 x2 x3 v1 v2 v3"), list(x) + list(v))}
        F = F + sp.Matrix([sp.sympify(e).subs(env) for e in custom])
    gen = (F.T * x.diff(q))[0]
    p = L.diff(qd)
    # d/dt p = ∂p/∂q q̇ + ∂p/∂q̇ q̈ + ∂p/∂φ ω + ∂p/∂t
    # (linear in q̈: its coefficient and the rest, evaluated numerically — no symbolic solve)
    both = sp.lambdify((t, q, qd, phi), [p.diff(qd), L.diff(q) + gen - p.diff(q) * qd - p.diff(phi) * w
                                         - p.diff(t)], "math", cse=True)

    def f(tt, a, b, c):
        coef, rest = both(tt, a, b, c)
        return rest / coef
    sol = solve_ivp(lambda tt, s: [s[1], f(tt, s[0], s[1], s[2]), 3 + tt / 2], (0, TIMES[-1]), [0.3, 1.0, 0.0],
                    method="DOP853", rtol=1e-12, atol=1e-14, t_eval=TIMES)
    return sol.y[0], sol.y[1]


@pytest.mark.parametrize("name", sorted(CASES))
def test_each_path_of_the_rhs_against_lagrange(name):
    axis, forces, _, _ = CASES[name]
    r = solve_one_text(_text(axis, forces))["results"]
    q_ref, qd_ref = reference(name)
    for got, ref in ((r["q"], q_ref), (r["q_dot"], qd_ref)):
        scale = float(np.max(np.abs(ref)))
        assert np.max(np.abs(np.array(got) - ref)) <= 100 * RTOL * scale
    E = np.array(r["E"])
    assert np.max(np.abs(E - E[0] - np.array(r["W_nc"]) - np.array(r["W_N"]))) <= 100 * RTOL * np.max(np.abs(r["T"]))
