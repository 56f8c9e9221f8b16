"""Curved surfaces in scenes: the rows of a contact and of rolling on a curve against
differences (as the straight elements' tests), and the motions against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import ROOT, error_of, solve_one_text
from tests.topics.scene.test_engine import _fd_check

ELLIPSE = """\
type: scene
title: curved rows
surfaces:
  rim: {curve: {x1: "2*sin(q)", x2: "1 - cos(q) + 0.3*q**2"}}
bodies:
  block: {shape: box, mass: 1, size: [0.2, 0.1], angle: 0.2}
  wheel: {shape: disk, mass: 2, radius: 0.15, angle: 0.1}
joints:
  c: {contact: [block.corner, rim], at: 0.2}
  r: {rolls: [wheel, rim], at: -0.6}
at: [0]
"""


def _scene(text: str):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver

    problems, diags = split_problems("t.yaml", text.encode(), ROOT)
    assert not diags
    validate(problems[0])
    return prepare.setup(solver._plan(problems[0].model))


def test_curved_rows_against_differences():
    """J by central differences of φ, γ by the second difference of φ along q + vτ + ½aτ²
    (J a = γ), at states off the curve too (the rows are exact functions of q, not only on it)."""
    text = ELLIPSE.replace("size: [0.2, 0.1],", "size: [0.2, 0.1], points: {corner: [0.1, -0.05]},")
    sc = _scene(text)
    rng = np.random.default_rng(3)
    for _ in range(6):
        q = sc.q0 + rng.normal(scale=0.02, size=sc.system.n)
        v = rng.normal(size=sc.system.n)
        _fd_check(sc.system, q, v)


def test_curved_contact_hessian_against_differences():
    from dyncli.topics.scene import curvature

    text = ELLIPSE.replace("size: [0.2, 0.1],", "size: [0.2, 0.1], points: {corner: [0.1, -0.05]},")
    s = _scene(text).system
    q = _scene(text).q0 + 0.01
    h = 1e-6
    for name, w in (("c", np.array([1.7])), ("r", np.array([0.8, -1.3]))):
        el = next(e for e in s.elements if e.name == name)
        H = el.hessian(q, w, s.n)
        for j in range(s.n):
            dq = np.zeros(s.n)
            dq[j] = h
            col = (el.jac(q + dq) - el.jac(q - dq)).T @ w / (2 * h)
            assert H[:, j] == pytest.approx(col, abs=1e-6), name
    assert curvature.rows_hessian(s, q, np.zeros(s.m)).shape == (s.n, s.n)
