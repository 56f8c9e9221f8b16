"""Joints on curved surfaces in the ``--symbolic`` equations (see :mod:`.symbolic`).

A contact or rolling joint on a curve y(q) gets a coordinate of its own, the curve's parameter
q_NAME of the contact point (mass 0), and position rows the notes write:

* ``contact: [P, CURVE]`` — r_P − y(q_NAME) = 0; its multipliers are the curve's force on P,
  which the equation of q_NAME (0 = −λ·y′) makes normal: λ = N n, n = e3 × y′/|y′|;
* ``rolls: [BODY, CURVE]`` — x̄ − y(q_NAME) − r n(q_NAME) = 0 (the centre on the offset curve)
  and the rolling row ∫ (1 − r k)|y′| dq + r θ = const (the offset curve's arc, integrated by
  sympy; where it has no closed form the scene is not written out); λ = N n + F t̂ on the
  centre's rows and F on the rolling row, so that the equation of q_NAME holds identically.

Eliminating the body's coordinates then leaves the bead-on-a-wire form in q_NAME (the
reduced equation of the ``constrained-particle`` type) or, rolling, its rigid-body analogue.
"""

from __future__ import annotations

import sympy as sp

from .symbolic_rows import exact


def _exact_floats(x):
    return x.xreplace({f: exact(float(f)) for f in x.atoms(sp.Float)})


def curve_of(curve, qc):
    """y(q_c) as a sympy 2-vector from the curve's expressions (the file's numbers exact)."""
    from dyncli import symbolic

    out = []
    for e in curve.y0:
        x = symbolic.sym(e).subs(symbolic.symbol("q"), qc)
        out.append(_exact_floats(sp.Integer(0) + x))
    return sp.Matrix(out)


def frame(y, qc):
    """(y′, |y′|, t̂, n, k|y′|) of the curve at q_c, each simplified."""
    d1 = y.diff(qc)
    d2 = d1.diff(qc)
    speed = sp.trigsimp(sp.sqrt(sp.expand(d1[0] ** 2 + d1[1] ** 2)))
    t = d1 / speed
    n = sp.Matrix([-t[1], t[0]])
    k_speed = sp.trigsimp((d1[0] * d2[1] - d1[1] * d2[0]) / sp.expand(d1[0] ** 2 + d1[1] ** 2))
    return d1, speed, t, n, k_speed


def add_coordinate(e, S, C, P, D, q0: list, v0: list) -> int:
    """The curve parameter of joint ``e`` as a coordinate (mass 0); its value and rate at t = 0."""
    import numpy as np

    name = e.name
    tex = r"\mathrm{" + name.replace("_", r"\_") + "}" if len(name) > 1 else name
    for lst, dots, tdot in ((C.q, "", ""), (C.qd, "\u0307", r"\dot"), (C.qdd, "\u0308", r"\ddot")):
        text = f"q{dots}_{name}"
        lst.append(S.new(text, text, (f"{tdot}{{q}}" if tdot else "q") + f"_{{{tex}}}"))
    P.M.append(sp.Integer(0))
    P.f.append(sp.Integer(0))
    point = e.P if e.kind == "contact" else e.body_point
    sys_q, sys_v = np.asarray(D.state[0]), np.asarray(D.state[1])
    qf, t, _n, k, d, speed = e.foot.at(point.pos(sys_q))
    q0.append(qf)
    v0.append(float(t @ point.vel(sys_q, sys_v)) / ((1 - k * d) * speed))
    return len(C.q) - 1


def rows(e, G, S, j: int):
    """(rows, multipliers in the joint forces, force symbols) of a joint on a curve."""
    qc = G.C.q[j]
    y = curve_of(e.surface, qc)
    _d1, speed, t, n, k_speed = frame(y, qc)
    N = S.force("N", e.name)
    if e.kind == "contact":
        return list(G.pos(e.P) - y), [N * n[0], N * n[1]], [N]
    b = e.body_point.body
    r = G.radius(b)
    F = S.force("F", e.name)
    lam = N * n + F * t
    integrand = sp.trigsimp(sp.expand(speed - r * k_speed))
    s = sp.Symbol("s", real=True)
    arc = sp.integrate(integrand.subs(qc, s), (s, exact(e.q_ref), qc))
    if arc.has(sp.Integral):
        raise ValueError(f"the arc of the curve {e.surface.name!r} has no closed form")
    roll = sp.expand(arc) + r * G.C.q[b.index[2]] - exact(e.c0)
    return list(G.centre(b) - y - r * n) + [roll], [lam[0], lam[1], F], [N, F]
