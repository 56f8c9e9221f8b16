"""`find: [{event: WHAT, joint: NAME, occurrence: n}]` on a scene: the n-th event of a one-sided
joint with the whole state then.  References in closed form (mpmath), never from dyncli:

* a sphere thrown along a rough lane without spin slides with friction μ_k m g against its
  motion until v = Rω: v = v0 − μ_k g t, Rω = (5/2) μ_k g t, so it rolls from t = 2 v0/(7 μ_k g)
  at v = 5 v0/7 (the event `sticks`);
* a ball dropped from h onto a floor with restitution e strikes at t1 = √(2h/g), and next at
  t1 + 2 e √(2 g h)/g (the events `impact`, occurrence 1 and 2).
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import error_of
from tests.tolerances import ode

from .refs import entry, solve

G = mp.mpf("9.81")
TOL = ode(1e-10)

LANE = """
type: scene
surfaces:
  lane: {through: [0, 0], direction: [1, 0]}
bodies:
  ball: {shape: disk, mass: 7, radius: 0.11, I: 0.03388, x: [0, 0.11], v: [8, 0], omega: 0}
joints:
  roll: {rolls: [ball, lane], mu_s: 0.25, mu_k: 0.2}
at: [0, 3]
find:
  - {event: sticks}
  - {event: sticks, joint: roll}
  - {event: slips}
"""


def test_when_a_thrown_sphere_starts_to_roll():
    r, warnings = solve(LANE)
    t_roll = 2 * 8 / (7 * mp.mpf("0.2") * G)
    for k in (0, 1):
        e = entry(r, k)
        assert e["t"] == pytest.approx(float(t_roll), rel=1e-12)
        assert e["v"]["ball"][0] == pytest.approx(float(5 * mp.mpf(8) / 7), rel=1e-12)
        # the state of the phase that ends there: still sliding, F = −μ_k m g
        assert e["reaction"]["roll"]["F"] == pytest.approx(float(-mp.mpf("0.2") * 7 * G), rel=1e-12)
    assert r["find"][2]["reached"] is False and r["find"][2]["t"] is None
    assert any(w.startswith("find.2: not reached") for w in warnings), warnings


DROP = """
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  ball: {shape: point, mass: 1, x: [0, 2]}
joints:
  bounce: {stop: [ball, floor], e: 0.5}
t_end: 2
find:
  - {event: impact}
  - {event: impact, occurrence: 2}
"""


def test_the_second_bounce_of_a_dropped_ball():
    r, _ = solve(DROP)
    t1 = mp.sqrt(2 * 2 / G)
    t2 = t1 + 2 * mp.mpf("0.5") * mp.sqrt(2 * G * 2) / G
    e1, e2 = entry(r, 0), entry(r, 1)
    assert e1["t"] == pytest.approx(float(t1), rel=TOL)
    assert e2["t"] == pytest.approx(float(t2), rel=TOL)
    assert e2["x"]["ball"][1] == pytest.approx(0.0, abs=1e-9)


@pytest.mark.parametrize("query,field,words", [
    ("{event: rolls}", "find.0.event", ["no event 'rolls'", "did you mean 'sticks'", "separates, slack"]),
    ("{event: stiks}", "find.0.event", ["did you mean 'sticks'"]),
    ("{event: sticks, joint: rol}", "find.0.joint", ["no joint 'rol'", "did you mean 'roll'"]),
    ("{event: sticks, direction: up}", "find.0.direction", ["goes with when only"]),
    ("{event: sticks, within: [0, 1]}", "find.0.within", ["goes with max and min only"]),
    ("{max: x.ball.0, joint: roll}", "find.0.joint", ["goes with event only"]),
    ("{event: sticks, occurrence: 0}", "find.0.occurrence", ["counts from 1"]),
    ("{event: 3}", "find.0.event", ["event names what happens"]),
    ("{event: sticks, joint: on}", "find.0.joint", ["the boolean True", 'quote the name, joint: "on"']),
    ("{event: sticks, when: {x.ball.0: 1}}", "find.0.event", ["one thing"]),
])
def test_invalid_event_queries(query, field, words):
    text = LANE.split("find:")[0] + f"find:\n  - {query}\n"
    msg = error_of(text)
    assert f" {field}:" in msg, msg
    for w in words:
        assert w in msg, (w, msg)


def test_an_event_query_on_a_type_without_events_says_what_to_ask():
    msg = error_of("type: vibration\nm: 2\nk: 200\nzeta: 0.1\nt_end: 1\nfind:\n  - {event: impact}\n")
    assert " find.0.event:" in msg and "for scenes" in msg and "when: {RESULT: VALUE}" in msg, msg


def test_a_joint_named_on_is_found_though_yaml_reads_the_bare_name_as_true():
    # `joint: on` is the boolean true to YAML 1.1; the query takes the joint named on, off, yes or
    # no that it stands for when the scene has exactly one
    r, _ = solve(LANE.replace("  roll: {rolls:", "  on: {rolls:").split("find:")[0]
                 + "find:\n  - {event: sticks, joint: on}\n")
    assert entry(r, 0)["t"] == pytest.approx(float(2 * 8 / (7 * mp.mpf("0.2") * G)), rel=1e-12)
