"""dyncli.rootfind.all_roots (issue #28): every root of a smooth function, decided by the sign
of f at the critical points of its resolved Chebyshev interpolant — not by sampling.  References
are closed forms (and mpmath for the clustered roots)."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from dyncli.rootfind import all_roots

EPS = 2.220446049250313e-16


@pytest.mark.parametrize("w", [1e-3, 1e-6, 1e-9])
def test_a_narrow_pair_of_roots_between_any_grid_points_is_found(w):
    # f = (x − c)² − w²: two roots 2w apart, at c = 0.3217 (no cell edge near them)
    c = 0.3217
    roots, touches, bad = all_roots(lambda x: (x - c) ** 2 - w * w, -2.0, 3.0)
    assert not bad and not touches
    assert roots == pytest.approx([c - w, c + w], abs=8 * EPS)


def test_a_double_root_is_a_touch_not_a_missed_pair():
    # (10x − π)²: zero only to rounding at x = π/10, never negative: a touch (to f's rounding, ~√ε)
    roots, touches, bad = all_roots(lambda x: (10 * x - math.pi) ** 2, -2.0, 3.0)
    assert sorted(roots + touches) == pytest.approx([math.pi / 10], abs=1e-7) and not bad


@pytest.mark.parametrize("delta", [1e-2, 1e-6, 1e-10, 1e-12])
def test_the_pitchfork_just_past_the_bifurcation(delta):
    # sin q (cos q − 1/(1 + δ)): roots 0 and ±acos(1/(1 + δ)) ≈ ±√(2δ) (mpmath at 30 digits, from the
    # double c the function uses); the root carries f's rounding ~ε/q* (cos q − c cancels)
    c = 1 / (1 + delta)
    roots, touches, bad = all_roots(lambda q: np.sin(q) * (np.cos(q) - c), -math.pi, math.pi)
    with mp.workdps(30):
        qs = float(mp.acos(mp.mpf(c)))
    assert len(roots) == 3 and roots[1] == 0.0 and not touches and not bad
    assert roots[2] == pytest.approx(qs, abs=4 * EPS / qs) and roots[0] == pytest.approx(-qs, abs=4 * EPS / qs)


def test_non_finite_values_are_reported_not_guessed():
    with np.errstate(invalid="ignore"):
        roots, touches, bad = all_roots(lambda x: np.sqrt(x - 0.5) - 1.0, 0.0, 2.0)
    assert roots == pytest.approx([1.5], abs=4 * EPS) and bad and max(bad) < 0.5


def test_a_cell_not_resolved_within_the_depth_limit_is_bad_not_guessed():
    # sin(2π x) over [0, 1e30]: a cell 2^-48 of its starting width is still ~1e14 periods wide, so
    # nothing is decided there; before, such a cell was read as resolved and gave roots of noise
    roots, touches, bad = all_roots(lambda x: np.sin(2 * math.pi * x), 0.0, 1e30, cells=2, max_depth=8)
    assert bad and not roots


def test_limit_gives_the_first_roots_in_order():
    # the cells are worked through from the left: stopping early keeps a sorted prefix of the roots
    roots, _, bad = all_roots(lambda x: np.sin(x), 0.5, 1000.0, limit=3)
    assert not bad and len(roots) >= 4
    assert roots[:4] == pytest.approx([math.pi * k for k in (1, 2, 3, 4)], rel=4 * EPS)
