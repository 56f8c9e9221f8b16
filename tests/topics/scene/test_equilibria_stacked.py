"""The equilibrium search's stacked evaluation (dyncli/topics/scene/equilibria.py, ``first_cells``):
g at every step's first Chebyshev nodes and ends, evaluated in one stacked call per walk, must be
the very values of one call a step (each row's Gauss–Newton, solves and tangent are its own) — a
second formulation of the same numbers, compared exactly (no tolerance: the same operations on the
same row), on a scene of links (the double pendulum) and one rolling on a curve (the ball in the
bowl, whose foot and arc are evaluated point by point)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import PROBLEMS, ROOT
from tests.topics.scene.common import walk_steps


def _scene(name: str):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver

    problems, diags = split_problems(name, (PROBLEMS / "scenes" / name).read_bytes(), ROOT)
    assert not diags
    validate(problems[0])
    return prepare.setup(solver._plan(problems[0].model))


@pytest.mark.parametrize("name", ["double-pendulum-modes.yaml", "ball-in-bowl.yaml"])
def test_stacked_first_cells_equal_one_call_a_step(name):
    S, steps = walk_steps(_scene(name), 6)
    known = S.first_cells(steps)
    assert len(known) == len(steps)
    for (qa, qb), got in zip(steps, known):
        taus = np.array(list(got))
        one = S.along(qa + taus[:, None] * (qb - qa), qb - qa)
        assert np.all(np.isfinite(one))
        assert np.array_equal(np.array(list(got.values())), one)
        assert {0.0, 1.0} <= set(got)
