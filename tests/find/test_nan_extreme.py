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


@pytest.mark.parametrize("kind", ["max", "min"])
def test_extreme_beyond_the_doubles_is_a_numerical_error(kind):
    """An extreme at ±inf has no time to speak of (fuzz seed 3404059: the largest tension of a
    1.8e308-kg bob, inf, tied with nothing — ``min() arg is an empty sequence``, exit 3)."""
    motion = StateMotion(lambda t: {"x": (1 if kind == "max" else -1) * math.inf}, 0.0, 2.0, breaks=[0.5, 1.0, 1.5])
    with pytest.raises(NumericalError, match=f"the {kind} of x between t = 0 and 2 s is beyond the range of a double"):
        answer_find([{kind: "x"}], motion, float)


def test_an_infinite_sample_does_not_hide_a_finite_extreme():
    """x = t(2 − t) up to t = 1.2, −inf after: its largest value is 1 at t = 1 (an infinite sample
    must not make every candidate tie with it: the answer was t = 0, x = 0, silently)."""
    motion = StateMotion(lambda t: {"x": t * (2 - t) if t <= 1.2 else -math.inf}, 0.0, 2.0, breaks=[0.5, 1.0, 1.5])
    got = answer_find([{"max": "x"}], motion, float)[0]
    assert got["x"] == 1.0 and got["t"] == pytest.approx(1.0, abs=1e-7)
