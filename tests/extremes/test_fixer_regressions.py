"""Regression tests for the fixes of the fuzz findings (beyond the documents in
test_fuzz_findings.py): the underlying helpers at their limits."""

from __future__ import annotations

import math

import pytest

from tests.conftest import error_of, solve_one_text


def test_rectilinear_brentq_finds_a_root_far_below_the_bracket_width():
    from dyncli.rootfind import root_in_bracket as brentq

    calls = []

    def g(x):
        calls.append(x)
        return 3 * x * x - 1e-200          # root 5.77e-101 in [0, 1]

    r = brentq(g, 0.0, 1.0)
    assert math.isclose(r, math.sqrt(1e-200 / 3), rel_tol=1e-14)
    assert len(calls) < 300      # Brent (maxiter 200), then bisection on the doubles + polish


def test_a_bracket_given_by_values_summed_another_way_is_one_up_to_rounding():
    # fuzz seed 1313963: the caller's end values (cumulative sums) bracket a root, the function's
    # own at the right end has the other sign by a rounding: the end nearer zero, not a ValueError
    from dyncli.rootfind import NotANumber, root_in_bracket

    def g(x):
        return x - 1.0 - 2e-16                # at x = 1 the function gives -2e-16

    assert root_in_bracket(g, 0.0, 1.0, -1.0, 1e-300) == 1.0
    with pytest.raises(NotANumber):          # a NaN is still refused, not read as a rounding
        root_in_bracket(lambda x: math.nan if x > 0.5 else x - 1.0, 0.0, 1.0, -1.0, 1e-300)


def test_rectilinear_case2_grazing_zero_of_v_is_fast_and_right():
    # v = 1.5 (1 - cos 2t) touches 0 at t = kπ: s = 1.5 t - 0.75 sin 2t
    rec = solve_one_text("type: rectilinear\na: 3*sin(2*t)\nfind: [{s: 10}, {v: 10}]\n")
    f = rec["results"]["find"]
    t = f[0]["t"]
    assert math.isclose(1.5 * t - 0.75 * math.sin(2 * t), 10, rel_tol=1e-9)
    assert f[1]["reached"] is False


def test_rectilinear_case4_s1_beyond_tracked_positions_is_input_error():
    msg = error_of("type: rectilinear\na: -s\ns1: 1.0e+200\nv1: 1\nfind: [{t: 1}]\n")
    assert ":3:1: s1:" in msg and "1e+100" in msg


def test_rectilinear_case4_far_query_does_not_spoil_the_orbit():
    # a = -ω² s, ω = 0.5: the far query is unreachable; the t query keeps its accuracy
    rec = solve_one_text("type: rectilinear\na: -0.25*s\ns1: 1\nv1: 0\nfind: [{t: 2}, {s: 2.0e+299}]\n")
    f = rec["results"]["find"]
    assert math.isclose(f[0]["s"], math.cos(1.0), rel_tol=1e-8)
    assert f[1]["reached"] is False
