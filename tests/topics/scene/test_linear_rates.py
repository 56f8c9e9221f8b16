"""The closed-form route's rates on an array of times (Linear1.rates, which the distance integrates)
against mpmath's Taylor ODE solver at 30 digits for s̈ = A0 + A1 (s − s0) + A2 ṡ: every regime the
route meets — free fall (A1 = A2 = 0), a damped drift (A1 = 0), under-, critically and overdamped
springs — to the ulps of the formulas (they are the scalar route's formulas on arrays)."""

import mpmath
import numpy as np
import pytest

from dyncli.topics.scene.motion import Linear1

TIMES = [0.0, 0.05, 0.3, 0.77, 1.5, 3.0]


@pytest.mark.parametrize("A0, A1, A2", [(-9.81, 0.0, 0.0), (2.0, 0.0, -0.7), (1.0, -250 / 3, 0.0),
                                        (0.3, -4.0, -0.5), (0.3, -4.0, -4.0), (0.3, -4.0, -9.0)])
def test_rates_against_mpmath(A0, A1, A2):
    s0, sd0 = 0.2, -0.4
    with mpmath.workdps(30):
        f = mpmath.odefun(lambda t, y: [y[1], A0 + A1 * (y[0] - s0) + A2 * y[1]], 0, [mpmath.mpf(s0), mpmath.mpf(sd0)])
        ref = np.array([float(f(t)[1]) for t in TIMES])
    lin = Linear1(np.zeros(1), np.ones(1), 0, A0, A1, A2)
    got = lin.rates(TIMES, s0, sd0)
    scale = np.max(np.abs(ref))
    assert np.max(np.abs(got - ref)) <= 64 * np.finfo(float).eps * scale
    # and the scalar route's own rate at each time, to an ulp or two (numpy's and libm's exp, cos)
    one = np.array([lin.motion(t, s0, sd0)[1] for t in TIMES])
    assert np.max(np.abs(got - one)) <= 8 * np.finfo(float).eps * scale
