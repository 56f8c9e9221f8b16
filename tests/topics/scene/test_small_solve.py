"""The scene's solve in plain floats (the Schur complement of M for one or two joint rows,
dynamics.schur_solve) against the LU of the whole matrix [[M, −Jᵀ − Φ], [J, 0]] by numpy — a
second formulation of the same equations, built here from the rows, γ and the loads:

* q̈ and λ agree to 1e-13 of their largest entry at random states of scenes with each kind of
  row (pin, link, cord and guide, slider, rolling, a point contact, a curve contact; one to
  three rows) and with the kinetic friction columns of a sliding contact, a slipping disk and a
  sliding point on a curve (the complement then not symmetric); the complement of rows
  accepted by its pivot test loses at most log2(1/PIVOT) bits, far below; scenes with more rows
  (or three with friction) take the whole matrix's LU;
* rows close to dependent go to the whole matrix's LU (the same numbers as numpy's);
* the stacked solve of many states is the one-state solve bit for bit;
* the projections leave the velocity on the joints (J q̇ + φ_t = 0 to rounding) by the
  mass-weighted least change (q̇ − q̇₀ = W⁻¹ Jᵀ μ).
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import PROBLEMS, ROOT

SCENES = PROBLEMS / "scenes"


def _scene(name: str):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver

    problems, diags = split_problems(name, (SCENES / name).read_bytes(), ROOT)
    assert not diags
    validate(problems[0])
    return prepare.setup(solver._plan(problems[0].model))


def _kkt(s, q, v, t):
    """q̈, λ by numpy's LU of the whole matrix (the rows, γ and loads as arrays)."""
    A = s.kkt_matrix(q, s.jac(q))
    x = np.linalg.solve(A, np.concatenate([s.applied(q, v, t)[0], s.gamma(q, v, t)]))
    return x[:s.n], x[s.n:]


def _close(got, ref, rel=1e-13):
    scale = max(float(np.max(np.abs(ref), initial=0.0)), 1e-300)
    return float(np.max(np.abs(np.asarray(got) - ref), initial=0.0)) <= rel * scale


def _slide(e, sign=1.0, mu_k=0.3):
    """A contact set sliding (or a disk slipping) with kinetic friction: its friction column on."""
    from dyncli.topics.scene.contacts import Rolls

    e.mu_k = mu_k
    if isinstance(e, Rolls):
        e.mode, e.sign = "slip", sign
    else:
        e.mode, e.sign = "slide", sign


# (file, how its joints are set before the states: None, or a function of the system, and the
# path expected: "schur" every state by the complement, "lu" every state by the whole matrix)
CASES = [
    ("compound-pendulum.yaml", None, "schur"),                      # a pin: 2 rows
    ("double-pendulum.yaml", None, "schur"),                        # two links
    ("yo-yo.yaml", None, "schur"),                                  # a cord on a disk and its guide
    ("two-mass-three-springs.yaml", None, "schur"),                 # two sliders, springs
    ("cart-pendulum.yaml", None, "schur"),                          # slider and link: 3 rows
    ("pulled-spool.yaml", None, "schur"),                           # rolling: 2 rows, a force
    ("falling-rod.yaml", None, "schur"),                            # a point contact of a turning rod
    ("stick-slip-periodic.yaml", lambda s: _slide(s.elements[0], -1.0), "schur"),     # sliding: 1 row + friction
    ("bowling-ball-skids.yaml", lambda s: _slide(s.elements[0], 1.0, 0.2), "schur"),  # slipping disk + friction
    ("sliding-ladder.yaml", lambda s: _slide(s.elements[0], 1.0, 0.4), "schur"),      # 2 rows, one with friction
    ("block-in-rough-bowl.yaml", lambda s: _slide(s.elements[0], 1.0), "schur"),      # a point on a curve, sliding
    ("ball-in-bowl.yaml", None, "schur"),                           # a disk rolling in a curve
    ("incline-pulley-slides.yaml", lambda s: _slide(s.elements[0], 1.0, 0.2), "lu"),  # 3 rows with friction
    ("atwood-massive-pulley.yaml", None, "lu"),                     # pin, cord runs, guides: 6 rows
]


@pytest.mark.parametrize("name,setup,path", CASES, ids=[c[0] for c in CASES])
def test_small_solve_matches_the_whole_matrix(name, setup, path, monkeypatch):
    from dyncli.topics.scene import dynamics

    sc = _scene(name)
    s = sc.system
    if setup is not None:
        setup(s)
        s.refresh()
    small = dynamics.schur_solve
    used = []
    monkeypatch.setattr(dynamics, "schur_solve", lambda *a: used.append(small(*a)) or used[-1])
    rng = np.random.default_rng(7)
    for _ in range(20):
        q = sc.q0 + rng.normal(scale=0.05, size=s.n)
        v = rng.normal(size=s.n)
        t = float(rng.uniform(0, 1))
        a, lam, _P = s.solve(q, v, t)
        a_ref, lam_ref = _kkt(s, q, v, t)
        assert _close(a, a_ref) and _close(lam, lam_ref), (name, a, a_ref, lam, lam_ref)
    if path == "schur":                 # every state by the complement (none sent to the whole matrix)
        assert len(used) == 20 and None not in used
    else:
        assert s.m >= 3 and all(u is None for u in used)


def test_a_friction_column_makes_the_complement_unsymmetric():
    """The sliding ladder's first contact sliding: its force column is J + Φ, not J."""
    from dyncli.topics.scene import dynamics

    sc = _scene("sliding-ladder.yaml")
    s = sc.system
    _slide(s.elements[0], 1.0, 0.4)
    s.refresh()
    rows = s.jac(sc.q0).tolist()
    assert len(rows) == 2 and s.force_columns(rows, sc.q0.tolist()) is not rows
    assert dynamics.complement_solve([1.0] * s.n, rows, s.force_columns(rows, sc.q0.tolist()), [1.0, 1.0]) is not None


def test_rows_close_to_dependent_go_to_the_whole_matrix(monkeypatch):
    from dyncli.topics.scene import dynamics

    # singular and nearly singular complements are refused by the small solve
    assert dynamics.complement_solve([1.0, 1.0], [[1.0, 1.0], [1.0, 1.0]], [[1.0, 1.0], [1.0, 1.0]], [1.0, 2.0]) is None
    near = [[1.0, 0.0], [1.0, 1e-4]]
    assert dynamics.complement_solve([1.0, 1.0], near, near, [1.0, 2.0]) is None
    assert dynamics.solve2(1.0, 1.0, 1.0, 1.0 + 1e-6, 1.0, 2.0) is None
    # with every complement refused, the solve is numpy's LU of the whole matrix to rounding
    sc = _scene("double-pendulum.yaml")
    s = sc.system
    q, v = sc.q0 + 0.01, np.full(s.n, 0.3)
    monkeypatch.setattr(dynamics, "PIVOT", 2.0)
    a, lam, _ = s.solve(q, v, 0.0)
    a_ref, lam_ref = _kkt(s, q, v, 0.0)
    assert _close(a, a_ref, 1e-14) and _close(lam, lam_ref, 1e-14)


@pytest.mark.parametrize("name,setup,path", [CASES[0], CASES[3], CASES[4], CASES[7], CASES[9], CASES[12]],
                         ids=["pin", "sliders", "three rows", "slide", "ladder", "whole matrix"])
def test_many_states_are_the_one_state_solve_bit_for_bit(name, setup, path):
    sc = _scene(name)
    s = sc.system
    if setup is not None:
        setup(s)
        s.refresh()
    rng = np.random.default_rng(3)
    q = sc.q0.copy()                     # one q held (the stacked solve's use), many v and t
    states = [(q, rng.normal(size=s.n), float(t)) for t in rng.uniform(0, 1, 9)]
    for (a, lam, P), (q1, v1, t1) in zip(s.solve_many(states), states):
        a1, lam1, P1 = s.solve(q1, v1, t1)
        assert a.tolist() == a1.tolist() and lam.tolist() == lam1.tolist() and P == P1


@pytest.mark.parametrize("name", ["double-pendulum.yaml", "compound-pendulum.yaml", "cart-pendulum.yaml"])
def test_projected_velocity_is_on_the_joints_by_the_least_weighted_change(name):
    sc = _scene(name)
    s = sc.system
    rng = np.random.default_rng(5)
    q = s.project_position(sc.q0 + rng.normal(scale=1e-3, size=s.n), 0.0)
    assert float(np.max(np.abs(s.phi(q, 0.0)))) <= 1e-14 * max(1.0, float(np.max(np.abs(q))))
    v0 = rng.normal(size=s.n)
    v = s.project_velocity(q, v0, 0.0)
    J = s.jac(q)
    assert float(np.max(np.abs(J @ v + s.phi_t(0.0)))) <= 1e-14 * float(np.max(np.abs(v0)))
    # the change is W⁻¹ Jᵀ μ: the mass-weighted change lies in the rows' span
    dv = s.weights() * (v - v0)
    mu = np.linalg.lstsq(J.T, dv, rcond=None)[0]
    assert np.allclose(J.T @ mu, dv, rtol=0, atol=1e-13 * float(np.max(np.abs(dv))))
