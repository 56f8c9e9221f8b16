"""Run the impact solver directly (fast, for property tests) and compare."""

from __future__ import annotations

import math

EPS = 2.220446049250313e-16


def run_impact(**kw):
    from dyncli.topics.impact.model import Impact
    from dyncli.topics.impact.solver import solve

    p = Impact.model_validate({"type": "impact", **kw})
    res = solve(p)
    return res.results, res.warnings


def close(got, ref, rel=2e-15, abs_=0.0):
    """|got - ref| <= rel*|ref| + abs_ (componentwise for vectors)."""
    if isinstance(ref, (list, tuple)):
        assert len(got) == len(ref)
        return all(close(g, r, rel, abs_) for g, r in zip(got, ref))
    r = float(ref)
    return abs(got - r) <= rel * abs(r) + abs_


def assert_close(got, ref, rel=2e-15, abs_=0.0, what=""):
    assert close(got, ref, rel, abs_), f"{what}: got {got}, expected {[float(x) for x in ref] if isinstance(ref, (list, tuple)) else float(ref)}"


def vnorm(v):
    return math.sqrt(sum(float(c) ** 2 for c in v))
