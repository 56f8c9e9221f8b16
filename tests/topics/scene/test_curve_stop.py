"""A point's `stop` on a curve (a ball dropped into a bowl), fixed or carried by a body: open at
t = 0, made where the point strikes — by hand: the bowl is the circle of radius 0.5 about
(0, 0.5); a ball dropped from (0.2, 0.6) meets it at y* = 0.5 − √(0.25 − 0.04) after
√(2 (0.6 − y*)/g), its velocity split along the inward normal n = (−0.4, 0.916515…) (reversed
and scaled by e) and the tangent (kept: smooth).  With e = 0 it stays on and slides: it turns at
y* + v_t²/(2g) (energy, 34.20).  On a cart free to slide, the impulse is internal: the
horizontal momentum holds through the impact, and the normal speed relative to the cart turns
by −e (28.7)."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_text

G = 9.81
Y_HIT = 0.5 - math.sqrt(0.25 - 0.04)
T_HIT = math.sqrt(2 * (0.6 - Y_HIT) / G)
N_HAT = (-0.4, 2 * math.sqrt(0.25 - 0.04))          # (centre − point)/R at x = 0.2


def bowl(e: float, extra: str = "", carried: bool = False) -> str:
    cart = "  C: {shape: box, mass: 3, size: [1.2, 0.5], x: [0, -0.25]}\n" if carried else ""
    on = ", body: C" if carried else ""
    floor = "  floor: {through: [0, -0.5], direction: [1, 0]}\n" if carried else ""
    base = "  base: {slider: [C, floor]}\n" if carried else ""
    return f"""type: scene
surfaces:
{floor}  bowl: {{curve: {{x1: "0.5*sin(q)", x2: "0.5 - 0.5*cos(q)"}}, q_range: [-1.5, 1.5]{on}}}
bodies:
{cart}  P: {{shape: point, mass: 1, x: [0.2, 0.6]}}
joints:
{base}  on: {{stop: [P, bowl], e: {e}}}
t_end: 1.5
at: [0, 0.2]
accuracy: {{rtol: 1e-11}}
{extra}"""


def solve(text: str) -> dict:
    rec = solve_text(text, "bowl.yaml")[0]
    assert rec.get("error") is None, rec.get("error")
    return rec


def test_ball_dropped_into_a_bowl_strikes_it_where_and_when_by_hand():
    r = solve(bowl(0.5))["results"]
    im = r["impacts"][0]
    v = G * T_HIT                                   # falling straight down: (0, −v)
    vn, vt = -v * N_HAT[1], -v * -N_HAT[0]          # along n, and along t = (n2, −n1)
    assert im["t"] == pytest.approx(T_HIT, rel=1e-10)
    assert im["v_n_before"] == pytest.approx(vn, rel=1e-10)
    assert im["v_n_after"] == pytest.approx(-0.5 * vn, rel=1e-10)
    assert im["slip_before"] == pytest.approx(im["slip_after"], rel=1e-12)
    assert abs(im["slip_after"]) == pytest.approx(abs(vt), rel=1e-10)
    assert im["energy_loss"] == pytest.approx(0.5 * (1 - 0.25) * vn * vn, rel=1e-10)
    assert r["x"]["P"][1][:2] == pytest.approx([0.2, 0.6 - 0.5 * G * 0.04], rel=1e-12)   # still falling at 0.2 s


def test_plastic_impact_then_slides_to_the_height_energy_allows():
    r = solve(bowl(0.0, extra="find: [{when: {v.P.0: 0}}]\n"))["results"]
    assert [e["what"] for e in r["events"]][:1] == ["impact"]
    v_t = G * T_HIT * 0.4
    turn = r["find"][0]
    assert turn["reached"]
    assert turn["x"]["P"][1] == pytest.approx(Y_HIT + v_t * v_t / (2 * G), rel=1e-8)


def test_ball_into_a_bowl_on_a_free_cart():
    r = solve(bowl(0.5, carried=True))["results"]
    im = r["impacts"][0]
    assert im["t"] == pytest.approx(T_HIT, rel=1e-10)         # the cart is at rest until then
    assert im["v_n_after"] == pytest.approx(-0.5 * im["v_n_before"], rel=1e-10)
    for vc, vp in zip(r["v"]["C"], r["v"]["P"]):
        assert 3 * vc[0] + vp[0] == pytest.approx(0.0, abs=1e-10)
    assert r["v"]["C"][1][0] == 0.0                            # (at 0.2 s, before the impact, the cart rests)


def test_rough_strike_stops_the_slip_when_friction_suffices():
    """μ P_n = 0.3 × 1.5 m v_n exceeds the m |v_t| the slip needs: the tangential impulse takes it
    all (Routh: slides, then sticks)."""
    r = solve(bowl(0.5).replace("e: 0.5}", "e: 0.5, mu: 0.3}"))["results"]
    im = r["impacts"][0]
    v = G * T_HIT
    assert im["impulse"] == pytest.approx(1.5 * v * N_HAT[1], rel=1e-10)
    assert abs(im["impulse_F"]) == pytest.approx(v * 0.4, rel=1e-10)
    assert im["slip_after"] == pytest.approx(0.0, abs=1e-12)


def test_a_points_stop_on_a_corner_is_still_refused():
    """A corner is not a curve a point strikes (its rim strikes it: a round body's stop)."""
    rec = solve_text("""type: scene
surfaces:
  edge: {corner: [0, 0]}
bodies:
  P: {shape: point, mass: 1, x: [0, 1]}
joints:
  s: {stop: [P, edge], e: 0.5}
at: [0, 1]
""", "bad.yaml")[0]
    err = rec.get("error") or ""
    assert "joints.s.stop.1" in err and "is a corner" in err, err
