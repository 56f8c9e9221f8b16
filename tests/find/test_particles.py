"""``find`` in ``particles`` with motion: two bodies on a spring, against the relative coordinate's
simple harmonic motion with the reduced mass.

m1 = 1, m2 = 2 at rest, 1.2 m apart on a spring k = 6 N/m of free length 1: the centre of mass
stays at 0.8 m, r = x2 − x1 = 1 + 0.2 cos ωt with ω = √(k/μ) = 3 rad/s (μ = 2/3 kg); x1 = 0.8 −
(2/3) r, x2 = 0.8 + (1/3) r; the spring's energy ½k(r − 1)² vanishes at ωt = π/2 + nπ (a touch).
The ODE runs at accuracy.rtol = 1e-10: times and values to ``tolerances.ode(rtol)``.
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.tolerances import ode

from .refs import entry, solve

MPMATH_DPS = 30
TOL = ode(1e-10)

TWO_BODY = """
type: particles
particles:
  - {m: 1, x: [0, 0, 0], v: [0, 0, 0]}
  - {m: 2, x: [1.2, 0, 0], v: [0, 0, 0]}
pairs: [{between: [0, 1], kind: spring, k: 6, L: 1}]
t_end: 3
accuracy: {rtol: 1e-10}
find:
  - {max: x_motion.0.0}
  - {when: {x_motion.1.0: 1.1}}
  - {min: V_internal_motion}
  - {when: {x_motion.0.0: 0}, occurrence: 2}
  - {t: 3}
  - {max: T_motion, within: [0.2, 1]}
  - {when: {x_motion.0.0: 0.5}}
"""


def test_two_body_spring():
    r, warns = solve(TWO_BODY)
    w, pi = 3, mp.pi
    e = entry(r, 0)                                  # body 1 farthest right: r shortest, ωt = π
    assert e["t"] == pytest.approx(float(pi / w), rel=TOL)
    assert e["x_motion"]["0"][0] == pytest.approx(float(mp.mpf("0.8") - mp.mpf(2) / 3 * mp.mpf("0.8")), rel=TOL)
    assert e["at_end"] is False
    assert entry(r, 1)["t"] == pytest.approx(float(2 * pi / 9), rel=TOL)     # cos 3t = −1/2
    e = entry(r, 2)                                  # the spring at its free length: V = 0
    assert e["t"] == pytest.approx(float(pi / 6), rel=1e-7)                  # (a minimum found by Brent's minimiser)
    assert e["V_internal_motion"] == pytest.approx(0, abs=TOL)
    # x1 = 0 held at the start: reached again at ωt = 2π, 4π (the window of query 4 ends at 3 < 4π/3)
    assert r["find"][3]["reached"] is False
    amp1 = mp.mpf(2) / 3 * mp.mpf("0.2")
    x1 = lambda t: -amp1 * (mp.cos(w * t) - 1)       # noqa: E731
    e = entry(r, 4)
    dist = 2 * amp1 * 2 + abs(x1(3) - x1(2 * pi / 3))        # two half swings, then on to t = 3
    assert e["distance"]["0"] == pytest.approx(float(dist), rel=TOL)
    assert e["distance"]["1"] == pytest.approx(float(dist / 2), rel=TOL)
    e = entry(r, 5)                                  # fastest at the free length
    assert e["t"] == pytest.approx(float(pi / 6), rel=1e-7)
    assert r["find"][6]["reached"] is False and r["find"][6]["x_motion"] is None
    assert any("find.6" in x for x in warns)
