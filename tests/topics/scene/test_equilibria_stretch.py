"""The equilibrium search's two shortcuts (dyncli/topics/scene/equilibria.py):

* with one degree of freedom the force along a walk is decided over *stretches* of many steps
  (``stretch_roots``: the path as a graph over the stretch's chord, one all_roots with adaptive
  cells) — compared with the step-by-step decision (a second formulation of the same roots: the
  same Search with the stretches switched off) and with closed forms (a bead on a wavy rail: every
  crest and trough within reach, x = nπ/k, ω² = ±g A k²);
* a step whose interpolant stays clear of zero has no root (``away_from_zero``) — against
  polynomials whose roots are known exactly (sympy), including a touch within the rounding."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import PROBLEMS, ROOT, solve_one_text
from tests.topics.scene.test_modes import SNAP

WAVY = """
type: scene
title: bead on a wavy rail
params: {A: 0.02, k: 10}
surfaces:
  rail: {curve: {x1: "q", x2: "A*cos(k*q)"}, q_range: [-8, 8]}
bodies:
  bead: {shape: point, mass: 1}
joints:
  j: {contact: [bead, rail], at: 0.1}
at: [0]
linearize: true
"""


def _scene(name: str, text: bytes):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver

    problems, diags = split_problems(name, text, ROOT)
    assert not diags
    validate(problems[0])
    return prepare.setup(solver._plan(problems[0].model))


def _walk_roots(scene, stretches: bool):
    """The roots and touches of the walks from the initial configuration and from every
    equilibrium found (no fifth-point starts)."""
    from dyncli.topics.scene import assembly, equilibria

    s = scene.system
    S = equilibria.Search(s, scene.q0)
    assert S.dof == 1
    preferred = [s.names.index(c) for c in scene.coords]
    froms = [scene.q0] + [q for q, _ in equilibria.find(s, scene.q0, preferred, lambda msg: None)]
    if not stretches:
        S.dof = 0                     # the step-by-step decision of every step
    every, equilibria.EVERY = equilibria.EVERY, 10**9
    out = []
    try:
        for q in froms:
            Z = equilibria.null_basis(s.jac(q), s.n, assembly.independent(s.jac(q), s.n))
            out += S.path_starts(q, Z[:, 0])
    finally:
        equilibria.EVERY = every
    return S, out


@pytest.mark.parametrize("name, text", [
    ("ball-in-bowl", (PROBLEMS / "scenes" / "ball-in-bowl.yaml").read_bytes()),
    ("compound-pendulum", (PROBLEMS / "scenes" / "compound-pendulum.yaml").read_bytes()),
    ("sliding-ladder", (PROBLEMS / "scenes" / "sliding-ladder.yaml").read_bytes()),
    ("snap", SNAP.encode()),
    ("wavy", WAVY.encode()),
])
def test_stretch_roots_equal_the_steps(name, text):
    """The same configurations (each root polished by Brent on its own parametrization: agreement
    to the rounding of the positions, 1e-12 of the scene's size) from stretches and from steps."""
    scene = _scene(name + ".yaml", text)
    S, fast = _walk_roots(scene, True)
    _, slow = _walk_roots(scene, False)

    def nearest(x, ys):
        return min((float(np.max(np.abs((x - y) / S.scale))) for y in ys), default=math.inf)

    assert [nearest(x, slow) for x in fast] == pytest.approx([0.0] * len(fast), abs=1e-12)
    assert [nearest(y, fast) for y in slow] == pytest.approx([0.0] * len(slow), abs=1e-12)
    if name == "wavy":
        assert len(fast) >= 8          # many rests within one stretch


def test_wavy_rail_every_rest_in_reach():
    """A bead on y = A cos(k x) under gravity: rests at x = nπ/k, troughs (odd n) stable and
    crests unstable with ω² = ±g A k² (V = m g A cos k x, the arc's slope 0 there).  The reach:
    every rest between the first and the last found is found (no gap), and there are at least
    eight of them around the start x = 0.1."""
    A, k, g = 0.02, 10.0, 9.81
    eqs = sorted(solve_one_text(WAVY)["results"]["equilibria"], key=lambda e: e["x"]["bead"][0])
    xs = [e["x"]["bead"][0] for e in eqs]
    n = [round(x * k / math.pi) for x in xs]
    assert len(eqs) >= 8 and n == list(range(n[0], n[0] + len(n)))
    assert n[0] * math.pi / k < 0.1 < n[-1] * math.pi / k
    assert xs == pytest.approx([j * math.pi / k for j in n], abs=1e-12)
    for j, e in zip(n, eqs):
        assert e["x"]["bead"][1] == pytest.approx(A * math.cos(j * math.pi), abs=1e-12)
        assert e["stability"] == ("stable" if j % 2 else "unstable")
        assert e["omega2"][0] == pytest.approx((1 if j % 2 else -1) * g * A * k * k, rel=1e-9)


@pytest.mark.parametrize("expr, clear", [
    ("exp(x)", True),                       # no root on [0, 1]
    ("x - 1/3", False),                     # a root inside
    ("(x - 1/2)**2 + 1/10", True),          # a minimum 0.1 above 0
    ("(x - 1/2)**2", False),                # a touch
    ("(x - 1/2)**2 + 10**-14", False),      # a touch within the rounding: all_roots decides it
    ("x + 10**-3", True),                   # a root just outside the step
    ("x", False),                           # a root at its end
])
def test_away_from_zero_against_exact_roots(expr, clear):
    """The exclusion agrees with the exact roots (sympy) on [0, 1], and is never claimed where a
    root or a touch is within 4x the interpolant's resolution (floor 1e-10)."""
    import sympy as sp

    from dyncli.topics.scene import equilibria

    x = sp.symbols("x", real=True)
    f = sp.sympify(expr, locals={"x": x})
    roots = [r for r in sp.solveset(f, x, sp.Interval(-0.01, 1.01)) if r.is_real]
    near = min([float(sp.Abs(f.subs(x, sp.Rational(j, 1000)))) for j in range(1001)])
    fn = sp.lambdify(x, f, "numpy")
    got = equilibria.away_from_zero(fn(equilibria.NODES), 1e-10)
    assert got == clear
    if got:
        assert not any(0 <= float(r) <= 1 for r in roots) and near > 4e-10
