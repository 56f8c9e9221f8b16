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
