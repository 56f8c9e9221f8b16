"""The physics below ``solver.py`` called with plain numbers (issue #26 item 3): a Setup built by
hand gives the closed form of the notes, and the same results as the problem file it mirrors."""

from __future__ import annotations

import math

from dyncli.expr import parse
from dyncli.topics.constrained_particle import solver as cp_solver
from dyncli.topics.constrained_particle.setup import Rotation, Setup as CurveSetup
from dyncli.topics.particle import solver
from dyncli.topics.particle.setup import Accuracy, ForceTerm, Setup
from tests.conftest import solve_one_text

M, C, G = 0.5, 0.1, 9.81
V0 = (20.0, 0.0, 20.0)
TIMES = (1.0, 2.0, 3.0)


def _drag_exact(t: float):
    """Gravity + linear drag F = −c v (m a = −m g e3 − c v): x(t) with τ = m/c (exponential decay)."""
    tau = M / C
    e = 1.0 - math.exp(-t / tau)
    return (V0[0] * tau * e, 0.0, (V0[2] + G * tau) * tau * e - G * tau * t)


def test_particle_setup_by_hand_gives_the_closed_form():
    s = Setup(m=M, v0=V0, forces=(ForceTerm("gravity"), ForceTerm("drag", c=C, power=1)), t_end=3.0, at=TIMES,
              accuracy=Accuracy(rtol=1e-10, atol=1e-12))
    res = solver.solve_setup(s)
    scale = max(abs(c) for t in TIMES for c in _drag_exact(t))
    for x, t in zip(res.results["x"], TIMES):
        # the route's promise: within 100 × rtol of the scale (docs/accuracy.md)
        assert max(abs(a - b) for a, b in zip(x, _drag_exact(t))) <= 100 * 1e-10 * scale


def test_particle_setup_matches_the_problem_file():
    text = ("type: particle\nm: 0.5\nv0: [20, 0, 20]\nforces: [{kind: gravity}, {kind: drag, c: 0.1, power: 1}]\n"
            "t_end: 3\nat: [1, 2, 3]\n")
    rec = solve_one_text(text)
    s = Setup(m=M, v0=V0, forces=(ForceTerm("gravity"), ForceTerm("drag", c=C, power=1)), t_end=3.0, at=TIMES)
    res = solver.solve_setup(s)
    for k in ("x", "v", "a", "W_nc", "distance"):
        assert res.results[k] == rec["results"][k], k


def test_constrained_setup_matches_the_problem_file():
    text = ("type: constrained-particle\nm: 0.1\ncurve: {x1: '0.5*sin(q)', x2: 0, x3: '-0.5*cos(q)'}\n"
            "rotation: {axis: [0, 0, 1], omega: 6}\nq0: 0.3\nforces: [{kind: gravity}]\nat: [0.5, 1, 2]\n")
    rec = solve_one_text(text)
    curve = tuple(parse(e, ("q",)) for e in ("0.5*sin(q)", "0", "-0.5*cos(q)"))
    s = CurveSetup(m=0.1, curve=curve, rotation=Rotation((0.0, 0.0, 1.0), parse("6", ("t",))), q0=0.3,
                   forces=(ForceTerm("gravity"),), t_end=2.0, at=(0.5, 1.0, 2.0))
    res = cp_solver.solve_setup(s)
    for k in ("q", "q_dot", "x", "N", "W_N", "distance"):
        assert res.results[k] == rec["results"][k], k
