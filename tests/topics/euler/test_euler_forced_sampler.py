"""Euler's equations with an applied moment: the plain-float right-hand side against an
independent numpy route (scipy at rtol 1e-13), and the plot sampler (which re-runs the
integration only when first asked) against the reported ω."""

from __future__ import annotations

import numpy as np

from dyncli.loader import split_problems, validate
from dyncli import registry
from tests.conftest import ROOT
from tests.topics.euler.test_euler import scipy_reference

TEXT = ("type: euler\nI: [1, 2, 3]\nomega0: [0.1, 0.2, 2]\nM: ['0.1*sin(t)', '0', '0.05']\n"
        "at: [0, 1, 5, 10]\naccuracy: {rtol: 1.0e-10, atol: 1.0e-12}\n")


def _solve():
    (lp,), _ = split_problems("forced.yaml", TEXT.encode(), ROOT)
    validate(lp)
    return registry.solver("euler")(lp.model)


def test_forced_rates_against_scipy_and_the_sampler():
    res = _solve()
    W = np.array(res.results["omega"])
    times = [0, 1, 5, 10]
    ref = scipy_reference([1, 2, 3], [0.1, 0.2, 2], times, M=lambda t: np.array([0.1 * np.sin(t), 0.0, 0.05]))
    scale = np.max(np.linalg.norm(ref, axis=1))
    # DOP853 at rtol 1e-10 over 10 s: global error well inside 100 x rtol of |ω|
    assert np.max(np.abs(W - ref)) <= 100 * 1e-10 * scale
    # the sampler interpolates the same run: at the reported times it gives the reported ω
    # (the step interpolant at a step's interior point: to the interpolant's error, ~rtol)
    S = res.extra["sample"](np.array(times, float))
    assert np.max(np.abs(S - W)) <= 100 * 1e-10 * scale
    mid = res.extra["sample"](np.array([2.5]))
    assert np.all(np.isfinite(mid))
