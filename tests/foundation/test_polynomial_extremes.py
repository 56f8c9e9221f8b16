"""dyncli.rootfind.polynomial_extremes (issue #28): the critical points of a polynomial curve (an
ODE step's dense output) decided from its exact Chebyshev series, never by samples; between two
of them every component is monotone.  References: closed forms (the roots of the derivative)."""

from __future__ import annotations

import numpy as np
import pytest

from dyncli.rootfind import polynomial_extremes

EPS = 2.220446049250313e-16


@pytest.mark.parametrize("w", [1e-2, 1e-4, 1e-6])
def test_a_narrow_excursion_inside_one_step_is_cut_at_both_ends(w):
    # s' = (t − c)(t − c − w)(t + 2): s has a maximum at c and a minimum at c + w, w apart
    c = 0.3217

    def s(t):
        t = np.asarray(t, dtype=float)
        u = t - c
        return u ** 4 / 4 + (2 - w) * u ** 3 / 3 - 2 * w * u ** 2 / 2 + 0 * t       # ∫ u (u − w)(u + c + 2) du

    def curve(t):
        return np.array([s(t), 0 * s(t) + 1.0])                                     # (s, a constant)

    (got_s, got_const), = polynomial_extremes([(curve, 0.0, 1.0)])
    assert got_const == []                                  # constant to rounding: no extremes
    # a critical point is known to the rounding of the series (4·15² eps |s|) over |s''| there,
    # and the value of s there to rounding
    s2 = w * (c + 2)                                        # |s''| at both critical points (to w²)
    tol = 4 * 15 ** 2 * EPS * float(np.max(np.abs(s(np.linspace(0, 1, 9))))) / s2
    assert got_s == pytest.approx([c, c + w], abs=tol)
    assert s(np.array(got_s)) == pytest.approx(s(np.array([c, c + w])), abs=4 * EPS)
    # monotone between the cuts: the samples of each piece are sorted one way
    cuts = [0.0] + got_s + [1.0]
    for a, b in zip(cuts, cuts[1:]):
        y = s(np.linspace(a, b, 201))
        assert np.all(np.diff(y) >= -1e-15) or np.all(np.diff(y) <= 1e-15)


def test_a_derivative_bounded_away_from_zero_has_none():
    # s = 3t + t³/3 on [−1, 1]: s' = 3 + t² > 0 (the constant coefficient dominates the rest)
    assert polynomial_extremes([(lambda t: np.atleast_2d(3 * t + t ** 3 / 3), -1.0, 1.0)]) == [[[]]]


def test_a_degree_seven_step_has_all_its_critical_points():
    # s' = Π (t − r_k) for six roots inside the step, one outside: exactly those six
    r = [0.05, 0.2, 0.21, 0.5, 0.77, 0.9, 1.5]
    P = np.polynomial.Polynomial.fromroots(r).integ()
    (got,), = polynomial_extremes([(lambda t: np.atleast_2d(P(t)), 0.0, 1.0)])
    assert got == pytest.approx(r[:6], abs=1e-9)
