"""The equilibrium search in rounds (dyncli/topics/scene/equilibria.py, ``find``): Newton from all the
queued starts at once (``Search.rests_from``, rootfind.newton_systems with the stacked Jacobian of
curvature.rest_hessians), the paths of a round walked together.  Each stacked form is compared
with a second formulation of the same numbers: numpy's own lstsq row by row, the one-state
Hessians (rows_hessian − potential_hessian, themselves checked against differences of the
Jacobians in test_modes.py), Newton from one start at a time (``Search.rest_from``: the scalar
rows and numpy's lstsq).  The work is counted, never timed: the 2-DOF double pendulum of
problems/scenes/double-pendulum-modes.yaml finds its four rests (closed form: each link straight
up or down) with a few dozen stacked Jacobians where one start at a time built one a Newton
iteration (over a thousand)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import PROBLEMS, ROOT
from tests.topics.scene.common import walk_steps

#: a rigid rod on a link from an off-centre point, a spring and a constant force on off-centre
#: points: every stacked branch of curvature.rest_hessians (links, springs, forces, arms that turn)
ROD = """
type: scene
title: rod on a link, a spring and a force
bodies:
  rod: {shape: rod, mass: 2, length: 1, angle: 0.4, points: {top: [0.5, 0], end: [-0.5, 0]}}
  bob: {shape: point, mass: 1}
joints:
  hang: {link: [[0, 0], rod.top], length: 0.8}
  tie: {link: [rod.end, bob], length: 0.9}
forces:
  - {spring: [[2, 0], rod.end], k: 30, L: 0.5}
  - {force: rod.top, F: [1.5, -0.5]}
at: [0]
linearize: true
"""


def _scene_text(text: str, k: int = 0):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver

    problems, diags = split_problems("scene.yaml", text.encode(), ROOT)
    assert not diags
    validate(problems[k])
    return prepare.setup(solver._plan(problems[k].model))


def _pendulum(k: int = 0):
    return _scene_text((PROBLEMS / "scenes" / "double-pendulum-modes.yaml").read_text(), k)


def test_lstsq_many_is_numpy_lstsq_row_by_row():
    from dyncli.rootfind import lstsq_many

    rng = np.random.default_rng(7)
    A = rng.normal(size=(6, 5, 5))
    A[1, :, 4] = A[1, :, 3]                    # rank 4: the minimum-norm solution
    A[2] = 0.0                                 # rank 0: zero
    A[3, 4] = 1e-15 * A[3, 0]                  # a row below rcond of the largest: cut as lstsq cuts it
    B = rng.normal(size=(6, 5))
    got = lstsq_many(A, B, rcond=1e-13)
    for k in range(6):
        want = np.linalg.lstsq(A[k], B[k], rcond=1e-13)[0]
        assert np.allclose(got[k], want, rtol=1e-10, atol=1e-12 * max(1.0, float(np.max(np.abs(want)))))
    R = rng.normal(size=(4, 6, 3))             # rectangular (the multipliers' Jᵀ λ = −f)
    b = rng.normal(size=(4, 6))
    got = lstsq_many(R, b, rcond=1e-15)
    for k in range(4):
        assert np.allclose(got[k], np.linalg.lstsq(R[k], b[k], rcond=None)[0], rtol=1e-12, atol=1e-13)


def test_a_matrix_beyond_the_doubles_is_refused_before_lapack_prints(tmp_path):
    """lstsq_many and newton_system raise LinAlgError, as lstsq would, for a matrix that is not
    finite, without handing it to LAPACK (whose DLASCL complaint went to stdout, behind the
    renderers: fuzz seed 3524030); the scene then exits 1 saying its numbers are beyond the
    doubles, with nothing else on stdout."""
    from dyncli.rootfind import lstsq_many, newton_system
    from tests.conftest import run_cli

    A = np.eye(3)[None].repeat(2, axis=0)
    A[1, 0, 0] = np.inf
    with pytest.raises(np.linalg.LinAlgError):
        lstsq_many(A, np.ones((2, 3)), rcond=1e-13)
    with pytest.raises(np.linalg.LinAlgError):
        newton_system(lambda x: x - 1.0, lambda x: np.diag([np.inf, 1.0]), [0.0, 0.0], scale=np.ones(2))
    f = tmp_path / "huge.yaml"
    f.write_text("""type: scene
params: {m: 1.0e+300, l: 1.0e-16, p1: 30*deg}
bodies:
  A: {shape: point, mass: m, x: [l*sin(p1), -l*cos(p1)]}
  B: {shape: point, mass: m, x: [l*sin(p1) + l*sin(sqrt(2)*p1), -l*cos(p1) - l*cos(sqrt(2)*p1)]}
joints:
  upper: {link: [[0, 1.0e-150], A], length: l}
  lower: {link: [A, B], length: l}
at: [0]
linearize: true
""")
    code, out, err = run_cli("solve", str(f), "--format", "json")
    assert code == 1 and "beyond the doubles" in err
    assert "DLASCL" not in out and "DLASCL" not in err


@pytest.mark.parametrize("text", [ROD, None])
def test_rest_hessians_are_the_one_state_hessians(text):
    from dyncli.topics.scene import curvature

    scene = _scene_text(ROD) if text else _pendulum()
    s = scene.system
    rng = np.random.default_rng(3)
    Q = scene.q0 + 0.2 * rng.normal(size=(7, s.n))
    LAM = rng.normal(size=(7, s.m))
    LAM[2] = 0.0                               # no joint force: only the potential's curvature
    H = curvature.rest_hessians(s, Q, LAM)
    for k in range(len(Q)):
        want = curvature.rows_hessian(s, Q[k], LAM[k]) - curvature.potential_hessian(s, Q[k])
        assert np.allclose(H[k], want, rtol=1e-12, atol=1e-12 * max(1.0, float(np.max(np.abs(want)))))


@pytest.mark.parametrize("text", [ROD, None])
def test_newton_from_all_starts_is_newton_from_each(text):
    from dyncli.topics.scene import equilibria

    scene = _scene_text(ROD) if text else _pendulum()
    s = scene.system
    S = equilibria.Search(s, scene.q0)
    preferred = [s.names.index(c) for c in scene.coords]
    starts = [scene.q0] + equilibria._walks(S, [(scene.q0, preferred)])[0]
    assert len(starts) > 10
    together = S.rests_from(starts)
    for q0, got in zip(starts, together):
        one = S.rest_from(q0)
        assert (got is None) == (one is None)
        if got is not None:
            assert np.allclose(got[0], one[0], rtol=0, atol=1e-9 * S.L)
            assert np.allclose(got[1], one[1], rtol=1e-7, atol=1e-9 * S.F0)


@pytest.mark.parametrize("k", [0, 1])
def test_double_pendulum_rests_with_few_stacked_jacobians(k, monkeypatch):
    """The four rests of the double pendulum (l = 1: A at (0, ∓1), B a link above or below it),
    found from 3° and from 30° with at most 60 Jacobians of Newton's system (stacked; one start at
    a time built 1,029 from 3°, one a start's iteration) and at most 200 projections of a path's
    points onto the joints (stacked: one call a step of all the round's paths, where one path at a
    time made 640 calls from 3°)."""
    from dyncli.topics.scene import curvature, equilibria

    calls = {"jacobians": 0, "projections": 0}

    def counted(fn, what):
        def inner(*a, **kw):
            calls[what] += 1
            return fn(*a, **kw)
        return inner

    monkeypatch.setattr(curvature, "rows_hessian", counted(curvature.rows_hessian, "jacobians"))
    monkeypatch.setattr(curvature, "rest_hessians", counted(curvature.rest_hessians, "jacobians"))
    monkeypatch.setattr(equilibria.Search, "_onto", counted(equilibria.Search._onto, "projections"))
    monkeypatch.setattr(equilibria.Search, "_onto_many", counted(equilibria.Search._onto_many, "projections"))
    scene = _pendulum(k)
    s = scene.system
    found = equilibria.find(s, scene.q0, [s.names.index(c) for c in scene.coords], lambda msg: None)
    want = [(0, -1, 0, -2), (0, -1, 0, 0), (0, 1, 0, 0), (0, 1, 0, 2)]
    got = sorted(tuple(float(x) for x in np.round(q, 9) + 0.0) for q, _ in found)
    assert got == sorted(want)
    assert calls["jacobians"] <= 60
    assert calls["projections"] <= 200


def test_cell_values_isolate_a_singular_step(monkeypatch):
    """A step whose rows have a singular matrix (``along`` raises for any stack holding it) is left
    to its own call; every other step has the values ``along`` gives it alone."""
    from dyncli.topics.scene import equilibria

    S, steps = walk_steps(_pendulum(), 9)
    along = S.along
    bad = steps[5][0] + equilibria.FIRST[3] * (steps[5][1] - steps[5][0])      # a node inside step 5

    def singular(Q, D):
        if np.any(np.all(np.abs(np.asarray(Q) - bad) < 1e-12, axis=1)):
            raise np.linalg.LinAlgError("singular")
        return along(Q, D)

    monkeypatch.setattr(S, "along", singular)
    V, got = S.cell_values(steps, equilibria.FIRST)
    assert got.tolist() == [k != 5 for k in range(9)]
    for k, (qa, qb) in enumerate(steps):
        if k != 5:
            one = along(qa + equilibria.FIRST[:, None] * (qb - qa), qb - qa)
            assert np.array_equal(V[k], one)
