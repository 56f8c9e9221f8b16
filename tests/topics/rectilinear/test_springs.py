"""One-sided and two-sided springs along the line of a rectilinear motion (``springs``, ``m``):
the block dropped onto a spring posed without min(s, 0), the elastic cord, and the two-sided spring.
References: the energy equation solved by hand (the maximum compression and the lowest point), the
period of the bouncing block pieced together by hand (free flight + half-swing), and the same
problem written with the acceleration by hand."""

from __future__ import annotations

import math

import pytest

from tests.conftest import error_of, solve_one_text

G = 9.81


def _find(text):
    return solve_one_text(text)["results"]


def test_block_dropped_onto_a_spring_max_compression_and_period():
    m, k, L, h = 2.0, 2000.0, 0.5, 1.0
    res = _find(f"type: rectilinear\na: -{G}\ns1: {L + h}\nm: {m}\n"
                f"springs: [{{k: {k}, anchor: 0, L: {L}, one_sided: compression}}]\n"
                "find: [{v: 0}, {min: s}]\nt_max: 2\n")
    # by hand: m g (h + δ) = ½ k δ²
    d = (m * G + math.sqrt((m * G) ** 2 + 2 * k * m * G * h)) / k
    turn, low = res["find"]
    assert res["case"] == 4
    assert turn["reached"] and turn["s"] == pytest.approx(L - d, rel=1e-12)
    assert low["s"] == pytest.approx(L - d, rel=1e-12) and low["t"] == pytest.approx(turn["t"], rel=1e-12)
    # the period: free flight down and up, 2 sqrt(2h/g), plus the contact, (π + 2 asin(x_st/A))/ω
    w, x_st, v0 = math.sqrt(k / m), m * G / k, math.sqrt(2 * G * h)
    A = math.sqrt(x_st ** 2 + (v0 / w) ** 2)
    period = 2 * math.sqrt(2 * h / G) + (math.pi + 2 * math.asin(x_st / A)) / w
    assert res["period"] == pytest.approx(period, rel=1e-10)
    assert turn["t"] == pytest.approx(period / 2, rel=1e-10)


def test_the_same_as_the_acceleration_written_by_hand():
    spring = _find("type: rectilinear\na: -9.81\ns1: 1.5\nm: 2\n"
                   "springs: [{k: 2000, L: 0.5, one_sided: compression}]\nfind: [{t: 0.3}, {t: 0.61}]\n")
    hand = _find('type: rectilinear\na: "-9.81 - 1000*min(s - 0.5, 0)"\ns1: 1.5\nfind: [{t: 0.3}, {t: 0.61}]\n')
    for a, b in zip(spring["find"], hand["find"]):
        assert a["s"] == pytest.approx(b["s"], rel=1e-11, abs=1e-12)
        assert a["v"] == pytest.approx(b["v"], rel=1e-11, abs=1e-12)


def test_elastic_cord_only_pulls():
    """A jumper (70 kg) on a cord (L = 10 m, k = 700 N/m) fixed at s = 0, released there from rest:
    free fall for 10 m, then the cord; lowest point from m g (L + δ) = ½ k δ² (by hand)."""
    m, k, L = 70.0, 700.0, 10.0
    text = f"type: rectilinear\na: -{G}\nm: {m}\nsprings: [{{k: {k}, L: {L}, one_sided: tension}}]\n"
    d = (m * G + math.sqrt((m * G) ** 2 + 2 * k * m * G * L)) / k
    (low,) = _find(text + "find: [{v: 0}]\nt_max: 5\n")["find"]
    (early,) = _find(text + "find: [{t: 1}]\n")["find"]
    assert low["s"] == pytest.approx(-(L + d), rel=1e-12)
    assert early["s"] == pytest.approx(-G / 2, rel=1e-12)          # the slack cord does nothing


def test_two_sided_spring_is_simple_harmonic():
    res = _find("type: rectilinear\na: 0\ns1: 0.2\nm: 0.5\nsprings: [{k: 8, anchor: 0.1}]\nfind: [{t: 0.7}]\n")
    w = math.sqrt(8 / 0.5)
    (e,) = res["find"]
    assert e["s"] == pytest.approx(0.1 + 0.1 * math.cos(w * 0.7), rel=1e-12)
    assert e["v"] == pytest.approx(-0.1 * w * math.sin(w * 0.7), rel=1e-11)


def test_with_damping_the_general_route_crosses_the_contact():
    """a uses v too: the ODE route; the block stays on the spring in the end, at rest at the static
    compression x_st = m g / k below L (by hand)."""
    res = _find('type: rectilinear\na: "-9.81 - 4*v"\ns1: 1\nm: 2\n'
                "springs: [{k: 2000, L: 0.5, one_sided: compression}]\nfind: [{t: 20}]\n")
    assert res["case"] == "general"
    assert res["find"][0]["s"] == pytest.approx(0.5 - 2 * G / 2000, rel=1e-8)


@pytest.mark.parametrize("extra, where, message", [
    ("springs: [{k: 10, L: 1}]", "m", "springs need the body's mass"),
    ("m: 1\nsprings: [{k: 10, one_sided: compression}]", "springs.0", "needs a free length L > 0"),
    ("m: 1\nsprings: [{k: -10}]", "springs.0.k", "> 0"),
    ("m: 1\nsprings: [{k: 10, side: up}]", "springs.0.side", "unknown field"),
])
def test_invalid_springs(extra, where, message):
    msg = error_of(f"type: rectilinear\na: 0\nfind: [{{t: 1}}]\n{extra}\n")
    assert f": {where}" in msg and message in msg, msg
