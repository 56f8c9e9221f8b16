"""The energy quadrature of a scene (``accuracy.method: quadrature``) on motions it has no turning
point to integrate between: a rod whirling about its pin and a ball rolling round a post are
refused at ``accuracy.method`` (exit 2: the motion goes round on joints that repeat every turn)
once its march has passed a whole turn, and a runaway (a disk rolling down an endless incline)
stops at the solve's CPU budget with its message — both used to run on for minutes (the march
followed the angle out to 10³¹ rad, summing the work over every turn)."""

from __future__ import annotations

import pytest

from tests.conftest import solve_text
from tests.topics.scene.test_refusals import refusal

WHIRL = """
type: scene
bodies:
  rod: {shape: rod, mass: 1, length: 1, x: [0.5, 0], angle: 0, omega: OMEGA}
joints:
  p: {pin: [rod.end1, [0, 0]]}
at: [0, 0.5]
accuracy: {method: quadrature}
"""

POST = """
type: scene
surfaces:
  post: {corner: [0, 0]}
bodies:
  ball: {shape: sphere, mass: 2, radius: 0.1, x: [0, 0.1], angle: 0, v: [0.5, 0], omega: -5}
joints:
  top: {rolls: [ball, post]}
at: [0, 0.5]
accuracy: {method: quadrature}
"""


@pytest.mark.parametrize("text, coord", [(WHIRL.replace("OMEGA", "10"), "angle.rod"), (POST, "angle.ball")])
def test_a_motion_that_goes_round_is_refused_by_the_quadrature(text, coord):
    refusal(text, "accuracy.method", "goes round", f"{coord} passes a whole turn", "method auto")


def test_a_runaway_stops_at_the_cpu_budget_with_its_message():
    rec = solve_text("""
type: scene
params: {beta: "30*deg"}
surfaces:
  slope: {through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}
bodies:
  disk: {shape: disk, mass: 2, radius: 0.2, angle: 0}
joints:
  roll: {rolls: [disk, slope], at: 2}
at: [0, 1]
accuracy: {method: quadrature, max_cpu: 0.3}
""")[0]
    err = rec.get("error") or {}
    assert "CPU budget of 0.3 s" in str(err) and "accuracy.method: auto" in str(err), err
