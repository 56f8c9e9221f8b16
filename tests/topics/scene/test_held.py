"""A phase held at rest under loads that change in time: its first event decided exactly
(docs/types/scene.md), by the sign analysis of the watched forces, not a grid of samples.

A block (m = 1 kg) at rest on a rough floor (μ_s = 0.5, μ_k = 0.4) is hit by a narrow pulse
F = 6 exp(−((t − c)/w)²) e1, c = 5.004 s, w = 2 ms: friction can hold it while F ≤ μ_s m g, so
it slips at t1 = c − w sqrt(ln(6/(μ_s m g))) (closed form), a window of 1.8 ms that a grid of
1024 samples over 10 s steps over.  It then slides with v(t) = (6 w √π/2)(erf((t − c)/w) −
erf((t1 − c)/w)) − μ_k g (t − t1) and sticks where v = 0 (mpmath findroot, 30 digits).
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL

G = 9.81


def test_a_narrow_pulse_between_grid_points_makes_the_block_slip():
    rec = solve_one_text("""
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  A: {shape: point, mass: 1, x: [0, 0]}
joints:
  rough: {contact: [A, floor], mu_s: 0.5, mu_k: 0.4}
forces:
  - {force: A, F: ["6*exp(-((t - 5.004)/0.002)**2)", 0]}
at: [0, 10]
""")
    assert rec.get("error") is None, rec.get("error")
    r = rec["results"]
    with mp.workdps(30):
        c, w = mp.mpf("5.004"), mp.mpf("0.002")
        t1 = c - w * mp.sqrt(mp.log(6 / (mp.mpf("0.5") * mp.mpf(G))))

        def v(t):
            return 6 * w * mp.sqrt(mp.pi) / 2 * (mp.erf((t - c) / w) - mp.erf((t1 - c) / w)) - mp.mpf("0.4") * G * (t - t1)

        t2 = mp.findroot(v, c + 2 * w)
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("rough", "slips"), ("rough", "sticks")]
    assert r["phases"][0]["route"] == "statics"
    # the held phase is exact: t1 to the double's resolution (Brent on the exact forces)
    assert abs(r["events"][0]["t"] - float(t1)) <= 1e-12 * float(t1)
    # the sliding phase is on the ODE route (a load varying in time): ODE_GLOBAL × rtol of its scale
    assert abs(r["events"][1]["t"] - float(t2)) <= ODE_GLOBAL * 1e-10 * float(t2)
    assert r["v"]["A"][1][0] == 0


PUSHED = """
type: scene
params: {F0: 4, w: 2*pi}
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  A: {shape: point, mass: 1, x: [0, 0]}
joints:
  rough: {contact: [A, floor], mu_s: 0.35, mu_k: 0.3}
forces:
  - {force: A, F: ["F0*sin(w*t)", 0]}
at: [0, %s]
"""


@pytest.mark.parametrize("span", ["10", "1.0e6", "1.0e12"])
def test_a_fading_periodic_push_slips_in_its_first_period_however_long_the_span(span):
    # F = 6 sin(2π t) e^-t: held while F ≤ μ_s m g, it slips at the first root t1 of
    # 6 sin(2π t) e^-t = μ_s g (mpmath, 30 digits) and is held again for ever after its last
    # slide.  The held forces are searched in windows from the start (not as one span of 1e12 s
    # whose cells would each hold many periods) and in the two smooth margins μ_s N ∓ F
    text = PUSHED.replace("F0*sin(w*t)", "F0*sin(w*t)*exp(-t)").replace("F0: 4", "F0: 6") % span
    rec = solve_one_text(text)
    with mp.workdps(30):
        t1 = mp.findroot(lambda t: 6 * mp.sin(2 * mp.pi * t) * mp.exp(-t) - mp.mpf("0.35") * mp.mpf(G), (0.01, 0.25),
                          solver="anderson")
    ev = rec["results"]["events"]
    assert ev[0]["what"] == "slips" and abs(ev[0]["t"] - float(t1)) <= 1e-12 * float(t1)
    assert ev[-1]["what"] == "sticks" and rec["results"]["phases"][-1]["route"] == "statics"


def test_a_periodic_push_over_1e299_s_is_refused_at_its_cost_not_followed_for_ever():
    # the fuzz document that ran for minutes: the held phase's search is bounded, and the sliding
    # phases' cost is projected and refused (exit 1, what to change) within the solve's CPU budget
    from tests.conftest import solve_text

    rec = solve_text(PUSHED % "5.0e299")[0]
    # over the CPU budget and the step budget both: the step budget's message, which the machine's
    # load does not change (dyncli.ode.Budget.tick)
    assert rec["exit_code"] == 1 and "needs about" in rec["error"] and "accuracy.max_steps" in rec["error"]
