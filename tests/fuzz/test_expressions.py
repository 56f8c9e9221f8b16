"""The expression language under fire: random and hostile expressions.

``dyncli.expr.parse`` either rejects an expression with an ExpressionError
(exit 2 with a message) or returns an Expr that evaluates — vectorised, on
arrays holding 0, ±inf, NaN, tiny and huge values — without raising; constant
expressions fold to a float or raise an ExpressionError, never anything else.
"""

from __future__ import annotations

import random

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncli.errors import InputError
from dyncli.expr import ExpressionError, parse
from tests.fuzz.harness import CORPUS, random_expression

VARS = ("t", "s", "v")
PROBE = np.array([0.0, -0.0, 1.0, -1.0, 1e-300, 1e300, -1e300, np.inf, -np.inf, np.nan, 0.5, 3.0])


def hostile_expressions() -> list[str]:
    lines = (CORPUS / "expressions.txt").read_text(encoding="utf-8").splitlines()
    return [ln for ln in lines if ln and not ln.startswith("# ")]


def _exercise(text) -> None:
    try:
        e = parse(text, VARS, {"k": 2.0, "m": 1e300})
    except ExpressionError as exc:
        assert exc.message
        return
    if e.is_constant:
        try:
            v = e.value()
            assert isinstance(v, float)
        except ExpressionError as exc:
            assert exc.message
    else:
        out = e.evaluate(t=PROBE, s=PROBE[::-1], v=PROBE)
        assert out.shape == PROBE.shape
        e(t=0.5, s=1.0, v=2.0)


@pytest.mark.parametrize("text", hostile_expressions())
def test_hostile_expression(text):
    _exercise(text)


@settings(max_examples=150, deadline=None, derandomize=True, database=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_random_expression(seed):
    _exercise(random_expression(random.Random(seed)))


@settings(max_examples=150, deadline=None, derandomize=True, database=None)
@given(text=st.text(alphabet=st.sampled_from(list("tsvk0123456789.eE+-*/() ,_^%<>=!~[]{}'\"xsincoqrtlgabp")),
                    max_size=40))
def test_random_text(text):
    _exercise(text)


@settings(max_examples=40, deadline=None, derandomize=True, database=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_exact_derivatives(seed):
    """Expressions that parse also convert to sympy and differentiate (the
    route of the types that need exact derivatives), or fail as input."""
    from dyncli import symbolic

    text = random_expression(random.Random(seed))
    try:
        e = parse(text, ("t",))
    except ExpressionError:
        return
    if e.is_constant:
        return
    try:
        d = symbolic.diff(e, "t", 2)
    except InputError as exc:
        assert exc.message
        return
    d.evaluate(t=PROBE)
