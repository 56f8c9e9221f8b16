"""The path length of a point under a constant acceleration, ∫₀^τ |v0 + a s| ds, in closed form
(dyncli.motion_find.uniform_path_length) against mpmath's quadrature at 40 digits, split at the
least speed (where |v| has its kink on a straight line): at every scale of speed, acceleration
and time — a tiny acceleration beside a fast motion, a turning point inside the piece, a piece
that ends or starts at it, a straight line through rest.  The closed form is written without
cancellation: its error is a few roundings of the result, whatever the scales."""

from __future__ import annotations

import math

import mpmath as mp
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncli.motion_find import uniform_path_length

#: a handful of roundings of each operation of the closed form (hypot, log1p, asinh, the sums)
REL = 32 * 2.0 ** -52


def reference(v0, a, tau) -> float:
    """τ c ∫₀¹ |v0 + a τ x|/c dx by mpmath at 40 digits (c the largest speed component: mpmath's
    tolerance is absolute), split at the least speed."""
    with mp.workdps(40):
        tau = mp.mpf(tau)
        v = [mp.mpf(x) for x in v0]
        w = [mp.mpf(x) * tau for x in a]
        c = max(abs(x) for x in v + w)
        if c == 0 or tau == 0:
            return 0.0
        v, w = [x / c for x in v], [x / c for x in w]

        def speed(x):
            return mp.sqrt((v[0] + w[0] * x) ** 2 + (v[1] + w[1] * x) ** 2)
        pts = [mp.mpf(0), mp.mpf(1)]
        A = w[0] ** 2 + w[1] ** 2
        if A:
            x_min = -(v[0] * w[0] + v[1] * w[1]) / A
            if 0 < x_min < 1:
                pts = [pts[0], x_min, pts[1]]
        return float(c * tau * mp.quad(speed, pts))


def scaled(lo: int, hi: int):
    return st.builds(lambda m, e: m * 10.0 ** e, st.floats(-5, 5, allow_nan=False), st.integers(lo, hi))


@settings(max_examples=300, deadline=None)
@given(vx=scaled(-8, 3), vy=scaled(-8, 3), ax=scaled(-12, 3), ay=scaled(-12, 3),
       tau=st.builds(lambda m, e: m * 10.0 ** e, st.floats(0, 3), st.integers(-6, 2)))
def test_against_mpmath_at_every_scale(vx, vy, ax, ay, tau):
    ref = reference((vx, vy), (ax, ay), tau)
    assert uniform_path_length((vx, vy), (ax, ay), tau) == pytest.approx(ref, rel=REL, abs=1e-300)


@settings(max_examples=200, deadline=None)
@given(v=scaled(-6, 3), a=scaled(-9, 3), tau=st.floats(0, 50), angle=st.floats(0, 2 * math.pi))
def test_straight_line_through_rest(v, a, tau, angle):
    """v0 ∥ a (k = 0): |v0 + a s| is piecewise linear, its integral by hand — v0²/(2|a|) to the
    turn and |a| (s − s*)²/2 after it when a opposes v0."""
    c, s = math.cos(angle), math.sin(angle)
    got = uniform_path_length((v * c, v * s), (a * c, a * s), tau)
    if a == 0:
        ref = abs(v) * tau
    else:
        turn = -v / a                       # where v + a s = 0
        if 0 < turn < tau:
            ref = 0.5 * abs(v) * turn + 0.5 * abs(a) * (tau - turn) ** 2
        else:
            ref = abs(v * tau + 0.5 * a * tau * tau)
    assert got == pytest.approx(ref, rel=REL * 4, abs=1e-300)


@pytest.mark.parametrize("v0, a, tau", [((3.0, 4.0), (0.0, -9.81), 0.0), ((0.0, 0.0), (0.0, 0.0), 5.0),
                                        ((2.0, 0.0), (0.0, 0.0), 1.5)])
def test_degenerate(v0, a, tau):
    assert uniform_path_length(v0, a, tau) == pytest.approx(math.hypot(*v0) * tau, abs=0)


def test_additive_over_a_split():
    """The length to τ is the length to τ/3 plus the rest from the state there (a projectile
    through its apex)."""
    v0, a, tau = (1.5, 7.0), (0.0, -9.81), 1.3
    cut = tau / 3
    v1 = (v0[0] + a[0] * cut, v0[1] + a[1] * cut)
    whole = uniform_path_length(v0, a, tau)
    assert whole == pytest.approx(uniform_path_length(v0, a, cut) + uniform_path_length(v1, a, tau - cut), rel=REL)
    assert whole == pytest.approx(reference(v0, a, tau), rel=REL)
