"""The odometer's stops decided exactly: a speed exactly 0 at a piece's end (a start from rest) is
not searched, and the distance still matches an independent closed form / mpmath quadrature; the
10-point Gauss–Legendre rule it integrates with, kept as a table, is checked against mpmath."""

import math

import mpmath
import numpy as np
import pytest

from dyncli.motion_find import Odometer

G = 9.81


@pytest.mark.parametrize("v0", [0.0, 7.0, -3.0])
def test_vertical_throw_distance_against_mpmath(v0):
    """|v| = |v0 − g t| on [0, 2]: a start from rest (v0 = 0) has its zero at t0 exactly; a throw
    upward stops at the apex v0/g inside a piece (a kink found by the search)."""
    calls = []

    def speeds(ts):
        calls.append(len(ts))
        return np.abs(v0 - G * np.asarray(ts, dtype=float))

    odo = Odometer(speeds, [0.0, 0.5, 1.0, 2.0], arrays=True)
    built = len(calls)
    for t in (0.3, 0.9, 2.0):
        ref = mpmath.quad(lambda s: abs(v0 - G * s), [0, *( [v0 / G] if 0 < v0 / G < t else []), t])
        assert odo.at([t])[0] == pytest.approx(float(ref), rel=1e-12, abs=1e-13)
    # the nodes, then one call for the interpolants of |v|² on the pieces that dip (from rest, or
    # the apex inside a piece), then the nodes of the pieces a stop cuts and one call for their
    # interpolants (no stop left inside): no golden-section search (~40 calls)
    assert built == {0.0: 2, 7.0: 4, -3.0: 1}[v0]


@pytest.mark.parametrize("unit", [1e-170, 1e150])
def test_stop_found_at_speeds_whose_square_leaves_the_doubles(unit):
    """A throw at speeds of 1e-170 m/s (|v|² underflows) or 1e150 m/s (it overflows): the stop
    is still found (|v|² is taken in units of the piece's largest speed), the distance as the
    closed form's to 1e-12 (fuzz seed 3001495: an all-zero series raised inside numpy)."""
    v0 = 7.0
    odo = Odometer(lambda ts: unit * np.abs(v0 - G * np.asarray(ts, dtype=float)), [0.0, 0.5, 1.0, 2.0], arrays=True)
    apex = v0 / G
    ref = unit * (0.5 * v0 * apex + 0.5 * G * (1.5 - apex) ** 2)
    assert odo.at([1.5])[0] == pytest.approx(ref, rel=1e-12)


def test_smooth_minima_against_closed_forms():
    """rootfind.smooth_minima: every interior local minimum of each function from its resolved
    Chebyshev interpolant of degree 20, in one call — |v|² of a degree-7 velocity (exactly a
    polynomial of degree 14, as on a DOP853 step), an analytic dip, two stops in one piece
    (both), a least at an end and a constant (none), and a function the degree-20 series cannot
    resolve (handed back unresolved)."""
    from dyncli.rootfind import smooth_minima

    def f(u, k):
        u, k = np.asarray(u, dtype=float), np.asarray(k)
        v7 = (u - 0.3) * (1 + u ** 6)                 # v = 0 at u = 0.3: |v|² has its least there
        two = ((u - 0.25) * (u - 0.75)) ** 2
        return np.select([k == 0, k == 1, k == 2, k == 3, k == 4],
                         [v7 * v7, np.cosh(3 * (u - 0.61)), 2 + u, 0 * u, two], np.abs(np.sin(200 * u)))

    calls = []
    got, ok = smooth_minima(lambda u, k: calls.append(1) or f(u, k), 6)
    assert len(calls) == 1
    assert ok.tolist() == [True, True, True, True, True, False]
    assert got[0] == pytest.approx([0.3], abs=1e-9)   # (a double root: located to ~sqrt of the rounding)
    assert got[1] == pytest.approx([0.61], abs=1e-12)
    assert got[2].size == 0 and got[3].size == 0
    assert got[4] == pytest.approx([0.25, 0.75], abs=1e-9)


def test_from_rest_closed_form_distance():
    """s(t) = g t² / 2 for a drop from rest (the notes' closed form)."""
    odo = Odometer(lambda ts: G * np.asarray(ts, dtype=float), [0.0, 1.0, 3.0], arrays=True)
    got = odo.at([0.25, 1.0, 2.5])
    assert got == pytest.approx([0.5 * G * t * t for t in (0.25, 1.0, 2.5)], rel=1e-13)
    assert math.isfinite(got[0])


def test_the_ten_point_rule_table_is_gauss_legendre():
    """motion_find.LEGGAUSS_10 (the distance's rule, kept as a table so that numpy.polynomial is
    not imported by every scene): the nodes are the doubles nearest the roots of P10 and the
    weights 2/((1 − x²) P10'(x)²) to 8 units in the last place (mpmath, 40 digits; numpy's
    leggauss, whose doubles the table holds, rounds its weights that far)."""
    import mpmath as mp

    from dyncli.motion_find import LEGGAUSS_10

    with mp.workdps(40):
        def P(x):
            return mp.legendre(10, x)
        grid = [mp.mpf(-1) + mp.mpf(2) * i / 2000 for i in range(2001)]
        roots = [mp.findroot(P, (a, b), solver="anderson") for a, b in zip(grid, grid[1:]) if P(a) * P(b) < 0]
        assert len(roots) == 10
        for x, node, weight in zip(roots, *LEGGAUSS_10):
            assert node == float(x)
            w = 2 / ((1 - x ** 2) * mp.diff(P, x) ** 2)
            assert abs(mp.mpf(weight) - w) <= 8 * mp.mpf(2) ** (mp.floor(mp.log(w, 2)) - 52)


def test_many_kinks_in_one_piece_are_resolved():
    """|sin 20 t| on one piece [0, 3] (nine kinks in it: one found as a stop, the rest left to the
    resolution check, which halves the pieces whose Legendre tail has not decayed to rtol):
    the closed form ∫|sin ωt| = (2n + 1 − cos(ωt − nπ))/ω, n = ⌊ωt/π⌋, to 1e-10."""
    w = 20.0
    odo = Odometer(lambda ts: np.abs(np.sin(w * np.asarray(ts, dtype=float))), [0.0, 3.0], arrays=True, rtol=1e-11)
    assert odo.resolved
    for t in (0.5, 1.7, 3.0):
        n = math.floor(w * t / math.pi)
        ref = (2 * n + 1 - math.cos(w * t - n * math.pi)) / w
        assert odo.at([t])[0] == pytest.approx(ref, rel=1e-10)


def test_noise_that_no_halving_resolves_is_said():
    """A speed that is rounding noise never resolves: the odometer stops at its budget, says so
    (``resolved`` False) and check_resolved warns once (never silently)."""
    from dyncli.motion_find import check_resolved

    rnd = np.random.default_rng(1)
    odo = Odometer(lambda ts: 1.0 + 1e-3 * rnd.random(np.asarray(ts).shape), [0.0, 1.0], arrays=True, rtol=1e-12)
    assert not odo.resolved
    said = []
    check_resolved(odo, said.append)
    assert len(said) == 1 and "distance" in said[0] and "accuracy.rtol" in said[0]
    assert odo.at([1.0])[0] == pytest.approx(1.0005, rel=1e-3)
