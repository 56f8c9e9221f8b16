"""A result that is not a number along the motion has no largest or smallest value: the search
says so (a NumericalError naming the path, exit 1), never an internal error (fuzz seed 3037873:
``min() arg is an empty sequence`` from the extremes' candidates compared with NaN)."""

from __future__ import annotations

import math

import pytest

from dyncli.errors import NumericalError
from dyncli.motion_find import StateMotion, answer_find


@pytest.mark.parametrize("kind", ["max", "min"])
def test_extreme_of_nan_values_is_a_numerical_error(kind):
    motion = StateMotion(lambda t: {"x": math.nan, "y": t}, 0.0, 2.0, breaks=[0.5, 1.0, 1.5])
    with pytest.raises(NumericalError, match="x is not a number"):
        answer_find([{kind: "x"}], motion, float)
    got = answer_find([{kind: "y"}], motion, float)          # (a finite result next to it: answered)
    assert got[0]["t"] == (2.0 if kind == "max" else 0.0)
