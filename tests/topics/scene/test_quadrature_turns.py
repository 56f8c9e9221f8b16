"""The energy quadrature of a scene (``accuracy.method: quadrature``) on motions it has no turning
point to integrate between: a rod whirling about its pin and a ball rolling round a post are
refused at ``accuracy.method`` (exit 2: the motion goes round on joints that repeat every turn)
once its march has passed a whole turn, and a runaway (a disk rolling down an endless incline)
stops at the solve's CPU budget with its message — both used to run on for minutes (the march
followed the angle out to 10³¹ rad, summing the work over every turn)."""

from __future__ import annotations

import pytest

from tests.conftest import PROBLEMS, solve_one_text, solve_text
from tests.topics.scene.test_refusals import refusal

SCENES = PROBLEMS / "scenes"

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


def _compound() -> str:
    """The gallery's compound pendulum (problems/scenes/compound-pendulum.yaml) by the quadrature,
    followed to 2.5 s (past its period)."""
    text = (SCENES / "compound-pendulum.yaml").read_text().replace("t_end: 1.6", "t_end: 2.5")
    assert "t_end: 2.5" in text
    return text + "\naccuracy: {method: quadrature}\n"


def test_a_compound_pendulum_by_the_quadrature_against_the_elliptic_closed_form():
    """A uniform bar (2 kg, 1.2 m) pinned at its end, released 60° from the bottom, by the energy
    quadrature within the default CPU budget (before: out of it, the time read by a new
    quadrature at every state).  φ from the downward vertical: φ = 2 asin(k sn(K − ω0 t, k)),
    k = sin 30°, ω0² = 3g/(2L); the bottom at T/4, the far turning point at T/2 and back at T
    (T = 4K/ω0: mpmath at 30 digits), found exactly at the turning points' times (a flat minimum
    read from its values is good to √ε of its time only); the pin at the bottom carries
    m g + m (L/2) ω², ω² = 3g (1 − cos 60°)/L."""
    import math

    import mpmath as mp

    rec = solve_one_text(_compound())
    r = rec["results"]
    assert r["route"] == "quadrature", r["route"]
    g, L, m = 9.81, 1.2, 2.0
    with mp.workdps(30):
        k = mp.sin(mp.pi / 6)
        w0 = mp.sqrt(3 * mp.mpf("9.81") / (2 * mp.mpf("1.2")))
        K = mp.ellipk(k * k)
        T = float(4 * K / w0)

        def phi(t):
            return float(2 * mp.asin(k * mp.ellipfun("sn", K - w0 * mp.mpf(t), m=k * k)))
    tol = 2 * rec["error_estimate"]         # the route's own bound covers the error (docs/accuracy.md)
    for i, t in enumerate(r["t"]):
        assert r["angle"]["bar"][i] + math.pi / 2 == pytest.approx(phi(t), abs=tol * math.pi), t
    f = r["find"]                           # the bottom, the far turning point, the bottom, back
    assert [x["t"] for x in f] == pytest.approx([T / 4, T / 2, 3 * T / 4, T], rel=tol)
    w2 = 3 * g * (1 - math.cos(math.pi / 3)) / L
    assert f[0]["reaction"]["pivot"]["R"][:2] == pytest.approx([0.0, m * g + m * L / 2 * w2], abs=tol * m * g * 3)


def test_a_coordinate_that_turns_back_is_refused_by_the_quadrature():
    """A block sliding off a smooth dome, followed along its x: at the dome's side x stops
    growing (the joints cannot be placed past it), so x does not parametrize the motion there:
    refused at accuracy.method naming the coordinate, not as a locked mechanism (exit 1)."""
    text = (SCENES / "block-off-dome.yaml").read_text() + "\naccuracy: {method: quadrature}\n"
    refusal(text, "accuracy.method", "follows the motion along x.", "turns back", "method auto")
