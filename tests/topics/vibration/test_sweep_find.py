"""A sweep's points with ``find`` answer each its own queries: the parsed queries are shared by
the points only when the queries and the params they read are the same (issue #31's sweep cost),
so a swept param read by a query gives each point its own answer — the one a solve of that point
alone gives — and the answer is exact: x(t) = VALUE at the time found (to a few ulp of x)."""

from __future__ import annotations

import math

import dyncli

DOC = {"type": "vibration", "m": 2, "k": 200, "zeta": 0.1, "L": 0.3, "x0": 0.35, "params": {"V": 0.31},
       "at": [0, 3], "find": [{"when": {"x": "V"}}, {"min": "x"}]}


def _x(t: float, k: float = 200.0) -> float:
    """x(t) of DOC in closed form (17.22): released from rest, underdamped."""
    wn = math.sqrt(k / 2.0)
    z, w0 = 0.1, 0.05
    wd = wn * math.sqrt(1.0 - z * z)
    return 0.3 + math.exp(-z * wn * t) * (w0 * math.cos(wd * t) + z * wn * w0 / wd * math.sin(wd * t))


def test_swept_param_read_by_a_query_is_each_points_own():
    values = [0.30, 0.31, 0.32, 0.33]
    sols = dyncli.sweep(DOC, {"params.V": values})
    times = [s.results["find"][0]["t"] for s in sols]
    assert len(set(times)) == len(values)              # no point took another's answer
    for v, s, t in zip(values, sols, times):
        alone = dyncli.solve(dict(DOC, params={"V": v}))[0].results["find"]
        assert s.results["find"] == alone
        assert abs(_x(t) - v) <= 64 * 2.220446049250313e-16 * 0.35      # the crossing, exact to rounding


def test_same_queries_shared_by_the_points_of_a_k_sweep():
    sols = dyncli.sweep(DOC, {"k": [150.0, 200.0, 250.0]})
    for k, s in zip([150.0, 200.0, 250.0], sols):
        alone = dyncli.solve(dict(DOC, k=k))[0].results["find"]
        assert s.results["find"] == alone
        t_min = s.results["find"][1]["t"]
        wd = math.sqrt(k / 2.0) * math.sqrt(1 - 0.01)
        assert abs(t_min - math.pi / wd) <= 1e-12         # the first turning point: ω*t = π
