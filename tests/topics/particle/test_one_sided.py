"""One-sided springs (`one_sided: compression | tension`) in particle and constrained-particle,
against the energy balance by hand: a mass m dropped from a height h above the free end of a
spring that only pushes stops at the compression δ with m g (h + δ) = ½ k δ², δ = (m g +
√((m g)² + 2 k m g h))/k; on an elastic cord that only pulls (a bungee of free length L from
the anchor) the lowest point is L + δ with m g (L + δ) = ½ k δ² after a fall from rest at the
anchor (started 0.1 m below it with the speed of that fall)."""

import math

import pytest

from tests.conftest import solve_one_text, solve_text

M, G, K, L = 2.0, 9.81, 2000.0, 0.5


def _delta(h):
    return (M * G + math.sqrt((M * G) ** 2 + 2 * K * M * G * h)) / K


BLOCK = f"""type: particle
m: {M}
x0: [0, 0, 1.5]
forces:
  - {{kind: gravity}}
  - {{kind: spring, anchor: [0, 0, 0], k: {K}, L: {L}, one_sided: compression}}
t_end: 2
accuracy: {{method: DOP853, rtol: 1.0e-10}}
find: [{{min: x.2, within: [0, 1]}}, {{min: x.2, within: [1, 2]}}, {{when: {{x.2: {L}}}, direction: up}}]
"""


def test_block_dropped_onto_a_spring_stops_at_the_energy_balance_and_bounces_each_time():
    rec = solve_one_text(BLOCK)
    assert rec.get("error") is None, rec.get("error")
    low = L - _delta(1.0)
    for e in rec["results"]["find"][:2]:            # both impacts: the energy is kept (no step over the contact)
        assert e["x"][2] == pytest.approx(low, abs=1e-8)
    # leaves the spring moving up at the speed it arrived with, √(2 g h)
    e = rec["results"]["find"][2]
    assert e["v"][2] == pytest.approx(math.sqrt(2 * G * 1.0), rel=1e-8)


def test_elastic_cord_only_pulls():
    text = f"""type: particle
m: {M}
x0: [0, 0, -0.1]
v0: [0, 0, {-math.sqrt(2 * G * 0.1)!r}]
forces:
  - {{kind: gravity}}
  - {{kind: spring, anchor: [0, 0, 0], k: {K}, L: {L}, one_sided: tension}}
t_end: 1
accuracy: {{method: DOP853, rtol: 1.0e-10}}
find: [{{min: x.2}}]
"""
    rec = solve_one_text(text)
    d = (M * G + math.sqrt((M * G) ** 2 + 2 * K * M * G * L)) / K
    assert rec["results"]["find"][0]["x"][2] == pytest.approx(-(L + d), abs=1e-8)


@pytest.mark.parametrize("method", ["auto", "DOP853"])
def test_bead_on_a_vertical_wire_onto_a_spring(method):
    text = f"""type: constrained-particle
m: {M}
curve: {{x1: 0, x2: 0, x3: "q"}}
q_range: [-1, 3]
q0: 1.5
forces:
  - {{kind: gravity}}
  - {{kind: spring, anchor: [0, 0, 0], k: {K}, L: {L}, one_sided: compression}}
t_end: 2
accuracy: {{method: {method}, rtol: 1.0e-10}}
find: [{{min: q}}]
"""
    rec = solve_one_text(text)
    assert rec.get("error") is None, rec.get("error")
    assert rec["results"]["find"][0]["q"] == pytest.approx(L - _delta(1.0), abs=1e-8)


def test_compression_needs_a_free_length():
    rec = solve_text("type: particle\nm: 1\nforces: [{kind: spring, k: 10, one_sided: compression}]\nt_end: 1\n")[0]
    assert rec["exit_code"] == 2 and "L > 0" in rec["error"] and "forces.0" in rec["error"]
