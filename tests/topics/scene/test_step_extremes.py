"""The find queries over an ODE route read each coordinate's extremes off the DOP853 steps'
interpolants (queries.step_extremes: the roots of a degree-7 polynomial's derivative per step),
checked against the pendulum's elliptic closed form in mpmath: two pendulums side by side (two
degrees of freedom: the ODE route integrates them); A's height x.A.1 = −L cos θ reaches its least
−L at T/4 (the bottom) and its largest −L cos θ0 again at T/2 (the other turning point),
T = 4 √(L/g) K(sin²(θ0/2))."""

from __future__ import annotations

import math

import mpmath
import pytest

from tests.conftest import solve_text

DOC = """type: scene
params: {{L: 1.3, p0: "{deg}*deg"}}
bodies:
  A: {{shape: point, mass: 1, x: ["L*sin(p0)", "-L*cos(p0)"]}}
  B: {{shape: point, mass: 2, x: ["2 + L*sin(p0/3)", "-L*cos(p0/3)"]}}
joints:
  a: {{link: [[0, 0], A], length: L}}
  b: {{link: [[2, 0], B], length: L}}
at: [0]
t_end: {t_end}
find: [{{min: x.A.1}}, {{max: x.A.1, within: [0.1, {t_end}]}}, {{min: v.A.0}}]
accuracy: {{rtol: 1e-10, atol: 1e-13}}
"""


@pytest.mark.parametrize("deg", [10.0, 120.0, 179.0])
def test_pendulum_extremes_against_the_elliptic_period(deg):
    g, L, th0 = 9.81, 1.3, math.radians(deg)
    with mpmath.workdps(30):
        T = float(4 * mpmath.sqrt(L / g) * mpmath.ellipk(mpmath.sin(th0 / 2) ** 2))
    rec = solve_text(DOC.format(deg=deg, t_end=1.2 * T), "pendulums.yaml")[0]
    assert rec["results"]["route"] == "ode"
    lo, hi, vmin = rec["results"]["find"]
    # the times to the ODE's global error over a period (an extreme is flat: its time is read
    # as a root of the rate), the values to the motion's
    assert lo["t"] == pytest.approx(T / 4, rel=1e-7)
    assert lo["x"]["A"][1] == pytest.approx(-L, rel=1e-8)
    assert hi["t"] == pytest.approx(T / 2, rel=1e-7)
    assert hi["x"]["A"][1] == pytest.approx(-L * math.cos(th0), rel=1e-8, abs=1e-8 * L)
    # the horizontal velocity is least (most negative) on the first swing, at most the speed at
    # the bottom, √(2gL(1 − cos θ0)), in size
    assert 0 < vmin["t"] < T / 2
    assert -math.sqrt(2 * g * L * (1 - math.cos(th0))) * (1 + 1e-8) <= vmin["v"]["A"][0] < 0
