"""Shared by the scene gallery tests: each gallery file solved once per test session."""

from __future__ import annotations

import functools

from tests.conftest import PROBLEMS, solve_path

SCENES = PROBLEMS / "scenes"

#: the bodies and joints of a double pendulum of two point masses on massless links (its params
#: m1, m2, L1, L2, p1, p2 given by the test)
DOUBLE_PENDULUM = """bodies:
  A: {shape: point, mass: m1, x: ["L1*sin(p1)", "-L1*cos(p1)"]}
  B: {shape: point, mass: m2, x: ["L1*sin(p1) + L2*sin(p2)", "-L1*cos(p1) - L2*cos(p2)"]}
joints:
  upper: {link: [[0, 0], A], length: L1}
  lower: {link: [A, B], length: L2}
"""

#: a block A (2 kg) on a smooth table at x = (the first %s), tied over a light pulley of radius 0.1
#: centred at (0, the second %s) to B (1 kg) hanging below its right side; ``at`` the third
TABLE_PULLEY = """
type: scene
surfaces:
  table: {through: [-5, 0], direction: [1, 0]}
bodies:
  A: {shape: point, mass: 2, x: [%s, 0]}
  B: {shape: point, mass: 1, x: [0.1, -1]}
joints:
  on: {contact: [A, table]}
  rope: {cord: [A, {pulley: [0, %s], radius: 0.1}, B]}
at: %s
"""


@functools.lru_cache(maxsize=None)
def gallery(name: str) -> dict:
    """The record of ``problems/scenes/NAME`` (asserts one problem, solved without error)."""
    recs = solve_path(SCENES / name)
    assert len(recs) == 1
    rec = recs[0]
    assert rec.get("error") is None, rec.get("error")
    return rec


def walk_steps(scene, count: int):
    """(the equilibrium search of ``scene``, the first ``count`` steps (q_k, q_{k+1}) of its path
    along the first free direction from the start): what the search's path tests walk."""
    from dyncli.topics.scene import equilibria

    s = scene.system
    S = equilibria.Search(s, scene.q0)
    Z = equilibria.null_basis(s.jac(scene.q0), s.n, [s.names.index(c) for c in scene.coords])
    q, t = scene.q0.copy(), S._tangent(scene.q0, Z[:, 0])
    steps = []
    for _ in range(count):
        q_new = S._onto(q + equilibria.STEP * t)
        steps.append((q, q_new))
        q, t = q_new, S._tangent(q_new, t)
    return S, steps

