"""``closed_form.amplification_at`` (one ratio, plain floats: a problem without a sweep
imports no numpy) gives the array version's values, signs of zero included, at the
extremes of r and ζ (undamped resonance, r = 2 where the formula switches, huge and tiny r):
the same operations in the same order, G and g bit for bit (both hypot from the C library),
the phases within 4 ulp: math.atan2 and numpy's arctan2 are each within ~2 ulp of the exact
value and need not agree (numpy 2 differs from math by at most 1 ulp here, numpy 1.26 by 2:
found by the lowest-version run, r = 2, ζ = 1.09375)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncli.topics.vibration import closed_form as cf

ratio = st.one_of(st.floats(0.0, 1e12, allow_nan=False), st.sampled_from([0.0, 1.0, 2.0, math.nextafter(2.0, 3.0), 1e-300]))
zeta = st.one_of(st.floats(0.0, 1e6, allow_nan=False), st.sampled_from([0.0, 1.0, 1 / math.sqrt(2), 1e-12]))


def _same(a: float, b: float, ulps: int = 0) -> bool:
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    close = a == b or (math.isfinite(a) and abs(a - b) <= ulps * math.ulp(a))
    return close and math.copysign(1.0, a) == math.copysign(1.0, b)


@settings(max_examples=500, deadline=None)
@given(ratio, zeta)
def test_scalar_equals_array(r, z):
    arr = [float(v[0]) for v in cf.amplification(np.array([r]), z)]
    one = cf.amplification_at(r, z)
    assert all(_same(a, b, ulps) for a, b, ulps in zip(arr, one, (0, 4, 0, 4))), (r, z, arr, one)


def test_undamped_resonance():
    G, phi, g, Phi = cf.amplification_at(1.0, 0.0)
    assert G == g == math.inf and phi == Phi == -0.5 * math.pi
