"""The vectorised bracketed root searches of ``dyncli.rootfind`` against roots known in closed form
(evaluated in mpmath at 30 digits): ``roots_in_brackets`` (Illinois, no slope) and
``newton_in_brackets`` (Newton with the slope, kept in the bracket).  Both promise the root to
a few ulp of the abscissa for a simple root: f(x*) is ~ulp(f), so x* moves by ulp(f)/|f'|."""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest

from dyncli.rootfind import newton_in_brackets, roots_in_brackets

mp.mp.dps = 30


def _cos_brackets(n):
    k = np.arange(n)
    a, b = k * np.pi + 0.1, k * np.pi + 3.0           # each holds the one root (k + ½)π
    return a, b, np.cos(a), np.cos(b), [float(mp.pi * (j + mp.mpf(1) / 2)) for j in range(n)]


def test_newton_and_illinois_agree_with_the_closed_form():
    a, b, fa, fb, ref = _cos_brackets(200)
    calls = []

    def fd(x, k):
        calls.append(k.size)
        return np.cos(x), -np.sin(x)
    got = newton_in_brackets(fd, a, b, fa, fb)
    ill = roots_in_brackets(lambda x, k: np.cos(x), a, b, fa, fb)
    assert got == pytest.approx(ref, rel=8 * np.finfo(float).eps)
    assert ill == pytest.approx(ref, rel=8 * np.finfo(float).eps)
    assert len(calls) <= 8                           # quadratic: a handful of vectorised calls


def test_newton_bisects_where_a_step_leaves_the_bracket():
    # tanh is flat far from its root: Newton from an end overshoots, bisection keeps the bracket
    f = lambda x: np.tanh(x - 0.3)                     # noqa: E731
    fd = lambda x, k: (f(x), 1.0 / np.cosh(x - 0.3) ** 2)      # noqa: E731
    r = newton_in_brackets(fd, [-40.0, 0.29], [40.0, 60.0], f(np.array([-40.0, 0.29])), f(np.array([40.0, 60.0])))
    assert r == pytest.approx([0.3, 0.3], rel=4 * np.finfo(float).eps)


def test_newton_keeps_roots_at_the_ends_and_tangent_slopes():
    # an end that is a root is the answer; a zero slope falls back to bisection, never a nan
    r = newton_in_brackets(lambda x, k: (x ** 3, 0.0 * x), [0.0, -1.0], [1.0, 2.0], [0.0, -1.0], [1.0, 8.0])
    assert r[0] == 0.0
    assert abs(r[1]) < 1e-20                        # x³ has a triple root: bisection (100 halvings at most)


def test_fminbound_many_finds_kinks_smooth_minima_and_ends_at_once():
    """``fminbound_many`` (issue 29): the minimisers on [0, 1] of many unimodal functions in one
    vectorised call per iteration — a kink |u − c| (a speed through a stop) to the search's
    tolerance √eps·u + xatol, a smooth minimum (u − c)² + h to √eps (the values are flat within
    rounding there, as for Brent's minimiser), a minimum at an end to the same tolerance of it."""
    from dyncli.rootfind import fminbound_many

    c = np.array([0.0, 1.0] + np.linspace(0.013, 0.987, 40).tolist())
    smooth = np.arange(c.size) % 2 == 1
    calls = []

    def f(u, k):
        calls.append(k.size)
        return np.where(smooth[k], (u - c[k]) ** 2 + 0.25, np.abs(u - c[k]) * 3.0)
    u = fminbound_many(f, c.size, 1e-12)
    tol = np.sqrt(np.finfo(float).eps)
    kink = ~smooth
    assert np.all(np.abs(u[kink] - c[kink]) <= 2 * (tol * np.abs(c[kink]) + 1e-12 / 3) + 1e-15)
    assert np.all(np.abs(u[smooth] - c[smooth]) <= 4 * tol)
    assert len(calls) <= 60                                  # golden section: ~38 iterations to √eps
