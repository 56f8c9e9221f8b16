"""Massless bodies the joints carry with massive ones: the elliptic trammel — a uniform rod whose
ends are pinned to massless collars in a horizontal and a vertical slot (two-sided, smooth).
The rod's angle θ from the vertical obeys θ̈ = (3g/2L) sin θ for all time (the slots hold both
ends), θ̇² = (3g/L)(cos θ0 − cos θ) (energy, 34.20); at release the slots push with
N_wall = (3/4) m g sin θ0 cos θ0 and N_floor = m g − m (L/2) θ̈ sin θ0 (the free-body diagram
of the rod, by hand).  A massless collar in a slot alone, or two massless collars linked to each
other only, still has a motion that moves no mass: refused, naming a body."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_text

G, M, L, TH0 = 9.81, 2.0, 1.0, math.radians(20)

TRAMMEL = """type: scene
params: {m: 2, L: 1, th0: "20*deg"}
surfaces:
  hslot: {through: [0, 0], direction: [1, 0]}
  vslot: {through: [0, 0], direction: [0, 1]}
bodies:
  rod: {shape: rod, mass: m, length: L, x: ["L/2*sin(th0)", "L/2*cos(th0)"], angle: "90*deg + th0"}
  A: {shape: point, mass: 0, x: ["L*sin(th0)", 0]}
  B: {shape: point, mass: 0, x: [0, "L*cos(th0)"]}
joints:
  a: {slider: [A, hslot]}
  b: {slider: [B, vslot]}
  pa: {pin: [rod.end1, A]}
  pb: {pin: [rod.end2, B]}
at: [0, 0.3, 0.5]
accuracy: {rtol: 1e-10}
"""


def test_elliptic_trammel_with_massless_collars():
    rec = solve_text(TRAMMEL, "trammel.yaml")[0]
    assert rec.get("error") is None, rec.get("error")
    r = rec["results"]
    # at release, the slots' forces from the rod's free-body diagram
    th_dd = 1.5 * G / L * math.sin(TH0)
    assert abs(r["reaction"]["b"]["N"][0]) == pytest.approx(0.75 * M * G * math.sin(TH0) * math.cos(TH0), rel=1e-12)
    assert r["reaction"]["a"]["N"][0] == pytest.approx(M * G - M * L / 2 * th_dd * math.sin(TH0), rel=1e-12)
    # later, the angle and its rate on the energy integral (to the ODE's tolerance)
    for i in (1, 2):
        x1, x2, _ = r["x"]["rod"][i]
        th = math.atan2(x1, x2)
        w = r["omega"]["rod"][i][2]
        assert w * w == pytest.approx(3 * G / L * (math.cos(TH0) - math.cos(th)), rel=1e-8)
        # the collars stay on the rod's ends, in their slots
        assert r["x"]["A"][i][0] == pytest.approx(L * math.sin(th), rel=1e-9)
        assert r["x"]["B"][i][1] == pytest.approx(L * math.cos(th), rel=1e-9)
    # past 3 cos θ = 2 cos θ0 the vertical slot pulls on the rod's end (a wall would let go)
    assert r["reaction"]["b"]["N"][0] * r["reaction"]["b"]["N"][2] < 0


@pytest.mark.parametrize("text", [
    """type: scene
surfaces:
  slot: {through: [0, 0], direction: [1, 0]}
bodies:
  A: {shape: point, mass: 0, x: [0, 0]}
joints:
  a: {slider: [A, slot]}
at: [0, 1]
""",
    """type: scene
surfaces:
  h: {through: [0, 0], direction: [1, 0]}
  v: {through: [0, 0], direction: [0, 1]}
bodies:
  A: {shape: point, mass: 0, x: [1, 0]}
  B: {shape: point, mass: 0, x: [0, 1]}
joints:
  a: {slider: [A, h]}
  b: {slider: [B, v]}
  ab: {link: [A, B], length: "sqrt(2)"}
at: [0, 1]
"""], ids=["collar-alone", "two-collars-linked"])
def test_a_motion_that_moves_no_mass_is_refused(text):
    rec = solve_text(text, "massless.yaml")[0]
    err = rec.get("error") or ""
    assert "has no mass but can move freely" in err, err
