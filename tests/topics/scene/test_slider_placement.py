"""A body on a straight smooth ``slider`` whose position is left out is placed with its centre on
the slider's line (before: left at the sketch's default, the origin, it ran along the parallel
line through the origin — an offset slider-crank with its guide 3 cm below the crank's pivot was
solved as an in-line one, with no warning).  A body whose position is given runs along the line
through its centre parallel to the surface (a wedge on a floor: its centre above it), as before.

The reference is the offset slider-crank's vector loop, by hand: the wrist B at the guide's
height e, l sin φ = e − r sin θ, x_B = r cos θ + l cos φ; ẋ_B by differentiating."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_text

CRANK = """
type: scene
params: {r: 0.08, l: 0.3, e: -0.03, w: 20}
surfaces:
  guide_line: {through: [0, "e"], direction: [1, 0]}
bodies:
  crank: {shape: rod, mass: 0.4, length: r, angle: 0, x: ["r/2", 0]}
  conrod: {shape: rod, mass: 1.2, length: l, angle: ANGLE}
  slider: {shape: box, mass: 1.5, size: [0.06, 0.04], angle: 0}
joints:
  main: {pin: [crank.end1, [0, 0]]}
  crankpin: {pin: [conrod.end1, crank.end2]}
  wrist: {pin: [conrod.end2, slider]}
  guide: {slider: [slider, guide_line]}
  motor: {drive: crank.angle, value: "w*t"}
at: [0]
t_end: 0.1
find:
  - {when: {angle.crank: "45*deg"}}
"""


def test_a_slider_whose_position_is_left_out_runs_on_its_line():
    r, l, e, w = 0.08, 0.3, -0.03, 20.0
    th = math.pi / 4
    phi = math.asin((e - r * math.sin(th)) / l)
    rec = solve_text(CRANK.replace("ANGLE", f"{math.asin(e / l)!r}"))[0]     # the crank at 0 at t = 0
    assert not rec.get("error"), rec.get("error")
    got = rec["results"]["find"][0]
    x_b = r * math.cos(th) + l * math.cos(phi)
    phid = -r * math.cos(th) * w / (l * math.cos(phi))
    v_b = -r * math.sin(th) * w - l * math.sin(phi) * phid
    assert got["t"] == pytest.approx(th / w, rel=1e-12)
    assert got["x"]["slider"][:2] == pytest.approx([x_b, e], rel=1e-9, abs=1e-12)
    assert got["angle"]["conrod"] == pytest.approx(phi, rel=1e-9)
    assert got["v"]["slider"][0] == pytest.approx(v_b, rel=1e-9)


def test_a_slider_whose_position_is_given_keeps_its_height():
    """A box drawn with its centre 0.05 m above a smooth floor line (its half height) slides along
    at that height: the given centre fixes the parallel line."""
    rec = solve_text("""
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  b: {shape: box, mass: 1, size: [0.2, 0.1], x: [0, 0.05], angle: 0, v: [1, 0]}
joints:
  s: {slider: [b, floor]}
at: [0, 1]
""")[0]
    r = rec["results"]
    assert r["x"]["b"][1][:2] == pytest.approx([1.0, 0.05], rel=1e-12)
    assert r["reaction"]["s"]["N"][1] == pytest.approx(9.81, rel=1e-12)


PINNED = """
type: scene
bodies:
  bar: {shape: rod, mass: 2, length: 1, angle: 0, x: [X, 0]}
joints:
  pivot: {pin: [bar.end1, [0, 0]]}
at: [0, 0.2]
"""


def test_positions_rounded_in_the_last_digits_are_moved_onto_the_joints():
    """A bar whose centre is typed 0.500000004 (a hand solution's 9 digits: the pin 4e-9 m open):
    moved onto the pin with a warning naming the gap, and solved; 1e-4 m open is a mistake, not a
    rounding: refused with the gap as before."""
    rec = solve_text(PINNED.replace("X", "0.500000004"))[0]
    assert not rec.get("error"), rec.get("error")
    (w,) = [w for w in rec["warnings"] if "moved onto them" in w]
    assert "4e-09 m open" in w
    assert rec["results"]["x"]["bar"][0][0] == pytest.approx(0.5, abs=1e-15)
    rec = solve_text(PINNED.replace("X", "0.5001"))[0]
    assert "violate the pin joint 'pivot': a gap of 0.0001 m" in str(rec.get("error")), rec.get("error")
