"""dyncli.expr.floateval (an expression's value as a plain-float function of t, for right-hand
sides) gives what the numpy evaluation of the same expression gives — the independent route —
at ordinary points to a few ulps (libm and numpy may round a transcendental function differently
in the last bit) and the same inf/nan out of range."""

from __future__ import annotations

import math

import pytest

from dyncli.expr import parse
from dyncli.expr.floateval import float_fn

EXPRS = [
    "0.1*sin(t)", "0.2*cos(2*t) + 0.05", "-t**3 + 2*t - 1", "t**0.5", "1/t", "exp(t) - exp(-t)",
    "log(t)", "log10(t)", "atan2(t, 1 - t)", "sqrt(t**2 + 1)*tanh(t)", "abs(t - 1)*sign(t)",
    "min(t, 1, 2*t)", "max(t, -t)", "asin(t/4)", "acos(t/2)", "atan(t)", "sinh(t)/cosh(t)", "tan(t)",
    "k*t + pi", "(2 + 3)*t", "exp(1000*t)", "(-8)**t", "t**-1",
]
TIMES = [0.0, -0.0, 0.3, 1.0, -1.7, 2.5, 1e-300, 1e300, math.inf, -math.inf, math.nan]


def _same(a: float, b: float) -> bool:
    if math.isnan(b):
        return math.isnan(a)
    if math.isinf(b) or b == 0.0:
        return a == b
    return abs(a - b) <= 4 * math.ulp(b)


@pytest.mark.parametrize("text", EXPRS)
def test_float_fn_matches_numpy_evaluation(text):
    e = parse(text, ("t",), params={"k": 3.0}) if "k" in text else parse(text, ("t",))
    f = float_fn(e)
    for t in TIMES:
        got, want = f(t), float(e(t=t))
        assert isinstance(got, float), (text, t)
        assert _same(got, want), f"{text} at t = {t}: {got!r} != numpy's {want!r}"


def test_other_variables_are_refused():
    with pytest.raises(ValueError, match="x1"):
        float_fn(parse("t*x1", ("t", "x1")))


@pytest.mark.parametrize("c, inner", [(-0.5, "sin(t)"), (2.0, "cos(t)"), (3.0, "t"), (-2.0, "t - 1")])
def test_a_sign_moved_onto_a_constant_factor_changes_no_bit(c, inner):
    """c·(−u) is compiled as (−c)·u: the double of c·(−u) for every u (IEEE products are symmetric
    in sign), signed zeros, infinities and nan included."""
    u = float_fn(parse(inner, ("t",)), "t")
    for text in (f"({c})*(-({inner}))", f"(-({inner}))*({c})"):
        f = float_fn(parse(text, ("t",)), "t")
        for t in TIMES:
            got, want = f(t), c * (-u(t))
            assert (math.isnan(got) and math.isnan(want)) or (got == want and math.copysign(1, got) == math.copysign(1, want))
