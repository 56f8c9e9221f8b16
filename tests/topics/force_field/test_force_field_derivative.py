"""x'(t) of a force-field path by the rules of calculus on the expression IR (no sympy)
against sympy's derivative of the same expression (the oracle), at points of the path;
and min/max, which keep sympy's route."""

from __future__ import annotations

import math
import os

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, reject, settings
from hypothesis import strategies as st

from dyncli import symbolic
from dyncli.expr import ExpressionError, parse
from dyncli.expr.derivative import d_ir, derivative

_FUNCS = ["sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "log", "log10", "sqrt", "abs",
          "sign"]
_leaf = st.one_of(st.just("t"), st.integers(-5, 5).map(str), st.sampled_from(["0.5", "1.5", "pi", "k"]))


def _grow(c):
    return st.one_of(
        st.tuples(c, st.sampled_from(["+", "-", "*", "/", "**"]), c).map(lambda x: f"({x[0]} {x[1]} {x[2]})"),
        st.tuples(st.sampled_from(_FUNCS), c).map(lambda x: f"{x[0]}({x[1]})"),
        st.tuples(c, c).map(lambda x: f"atan2({x[0]}, {x[1]})"),
        c.map(lambda x: f"-{x}"),
    )


path_text = st.recursive(_leaf, _grow, max_leaves=6)
T = np.linspace(0.13, 0.91, 7)          # away from the special points 0, ±1 of the functions' domains


@settings(max_examples=int(os.environ.get("DYNCLI_FF_EXAMPLES", "150")), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=path_text)
def test_derivative_agrees_with_sympy(text):
    try:
        e = parse(text, ("t",), {"k": 0.7})
        ref = symbolic.diff(e, "t")
    except (ExpressionError, ValueError, TypeError):   # a constant outside its domain (log(0)); sympy: piecewise, NaN
        reject()
    if symbolic.sym(e).has(sp.nan):     # sympy's atan2(0, 0) or 0/0 is nan where numpy's evaluator differs
        reject()
    d = derivative(e, "t")
    with np.errstate(all="ignore"):
        a, b = d.evaluate(t=T), ref.evaluate(t=T)
        # the two forms of the same derivative round differently: compare to the size of the terms
        x = e.evaluate(t=T)
        size = np.abs(b) + np.abs(x) + 1.0
    both = np.isfinite(a) & np.isfinite(b) & np.isfinite(x)        # where the path x(t) itself is defined
    assert np.all(np.abs(a[both] - b[both]) <= 1e-9 * size[both]), (text, a, b)


@pytest.mark.parametrize("text, want", [("3*sin(2*t) + t**2", lambda t: 6 * math.cos(2 * t) + 2 * t),
                                        ("t**t", lambda t: t ** t * (math.log(t) + 1)),
                                        ("atan2(t, 1 - t)", lambda t: 1 / ((1 - t) ** 2 + t ** 2)),
                                        ("log10(t)/sqrt(t)", lambda t: (1 / math.log(10) - math.log10(t) / 2) / t ** 1.5),
                                        ("5", lambda t: 0.0)])
def test_closed_forms(text, want):
    d = derivative(parse(text, ("t",)), "t")
    for t in (0.2, 0.7):
        assert float(d.evaluate(t=t)) == pytest.approx(want(t), rel=1e-14, abs=1e-15)


def test_min_max_keep_sympys_route():
    e = parse("max(t, 1 - t)", ("t",))
    with pytest.raises(Exception):
        d_ir(e.ir, "t")
    assert float(derivative(e, "t").evaluate(t=0.8)) == 1.0
