"""particle ``steady``: the rate of a circular motion about an axis at x0 that the forces alone hold
(F = −m ω² ρ).  References by hand: the circular orbit ω² = g R0²/r³ (19.18, 21), the puck on a spring
ω² = k (r − L)/(m r), the elastic conical pendulum (the spring's stretch from the vertical balance)."""

from __future__ import annotations

import math

import pytest

from tests.conftest import error_of, solve_one_text

G = 9.81


def _steady(text):
    return solve_one_text(text)["results"]["steady"]


def test_circular_orbit_rate_and_speed():
    R0, r = 6.371e6, 7.0e6
    (e,) = _steady(f"type: particle\nm: 1000\nx0: [{r}, 0, 0]\nforces: [{{kind: inverse-square, R0: {R0}}}]\n"
                   "steady: [{axis: [0, 0, 1]}]\n")
    assert e["omega"] == pytest.approx(math.sqrt(G * R0 ** 2 / r ** 3), rel=1e-14)
    assert e["v"] == pytest.approx(math.sqrt(G * R0 ** 2 / r), rel=1e-14)
    assert e["period"] == pytest.approx(2 * math.pi * math.sqrt(r ** 3 / (G * R0 ** 2)), rel=1e-14)


def test_same_as_the_orbit_circular_speed():
    rec = solve_one_text("type: particle\nm: 1\nx0: [7e6, 0, 0]\nv0: [0, 7000, 0]\n"
                         "forces: [{kind: inverse-square, R0: 6.371e6}]\nt_end: 10\nsteady: [{}]\n")
    assert rec["results"]["steady"][0]["v"] == pytest.approx(rec["results"]["orbit"]["v_circular"], rel=1e-13)


def test_puck_on_a_spring_about_a_tilted_axis():
    """The axis along e1 + e2 (the spring's anchor on it): ρ = the distance of x0 from that line."""
    (e,) = _steady("type: particle\nm: 0.5\nx0: [0, 0, 0.4]\nforces: [{kind: spring, k: 20, L: 0.3}]\n"
                   'steady: [{axis: ["sqrt(0.5)", "sqrt(0.5)", 0]}]\n')
    assert e["rho"] == pytest.approx(0.4, rel=1e-15)
    assert e["omega"] == pytest.approx(math.sqrt(20 * 0.1 / (0.5 * 0.4)), rel=1e-13)


@pytest.mark.parametrize("deg", [20, 45, 70])
def test_elastic_conical_pendulum(deg):
    m, k, L = 0.3, 50.0, 0.6
    th = math.radians(deg)
    R = L + m * G / (k * math.cos(th))            # the vertical balance k (R − L) cos θ = m g
    x0 = [R * math.sin(th), 0, -R * math.cos(th)]
    (e,) = _steady(f"type: particle\nm: {m}\nx0: [{x0[0]!r}, 0, {x0[2]!r}]\n"
                   f"forces: [{{kind: gravity}}, {{kind: spring, k: {k}, L: {L}}}]\nsteady: [{{}}]\n")
    assert e["omega"] == pytest.approx(math.sqrt(k * (R - L) / (m * R)), rel=1e-12)
    assert e["omega"] == pytest.approx(math.sqrt(G / (R * math.cos(th))), rel=1e-12)   # as the string's


def test_with_a_motion_both_are_reported():
    rec = solve_one_text("type: particle\nm: 0.5\nx0: [0.4, 0, 0]\nv0: [0, 1.2649110640673518, 0]\n"
                         "forces: [{kind: spring, k: 20, L: 0.3}]\nat: [0, 1]\nsteady: [{}]\n")
    x1 = rec["results"]["x"][1]
    assert math.hypot(x1[0], x1[1]) == pytest.approx(0.4, rel=1e-8)    # started at v = ω ρ: stays on the circle


BASE = "type: particle\nm: 0.5\nx0: [0.4, 0, 0]\n"


@pytest.mark.parametrize("extra, message", [
    ("forces: [{kind: gravity}]\nsteady: [{}]", "along the axis"),
    ("forces: [{kind: uniform, F: [0, 1, 0]}]\nsteady: [{}]", "along e_θ"),
    ("forces: [{kind: uniform, F: [1, 0, 0]}]\nsteady: [{}]", "points away from the axis"),
])
def test_no_circular_motion_is_an_answer(extra, message):
    """Forces that cannot hold a circular motion at x0 are the physics' answer (exit 0): exists:
    false, the rates null, a warning naming the query and the unbalanced part."""
    rec = solve_one_text(BASE + extra + "\n")
    (e,) = rec["results"]["steady"]
    assert e["exists"] is False and e["omega"] is None and e["period"] is None
    assert any(w.startswith("steady.0:") and message in w for w in rec["warnings"]), rec["warnings"]


@pytest.mark.parametrize("extra, where, message", [
    ("forces: [{kind: spring, k: 1}]\nsteady: [{axis: [1, 0, 0]}]", "steady.0", "on the axis"),
    ("forces: [{kind: spring, k: 1}, {kind: damper, c: 1}]\nsteady: [{}]", "forces.1", "position only"),
    ("forces: [{kind: spring, k: 1}]\nsteady: [{axs: [0, 0, 1]}]", "steady.0.axs", "unknown field"),
])
def test_invalid_steady(extra, where, message):
    msg = error_of(BASE + extra + "\n")
    assert f": {where}: " in msg and message in msg, msg


def test_angular_speed_that_leaves_the_doubles_is_a_numerical_error():
    """m = 3e299 kg at ρ = 1e16 m on a spring: ω² = −F·ρ̂/(m ρ) underflows to 0, so the period
    2π/ω would divide by zero (fuzz seed 3071278: exit 3); refused naming the query (exit 1)."""
    from tests.conftest import solve_text

    rec = solve_text("type: particle\nm: 3.0e+299\nx0: [0.5, 1.0e+16, -0.9]\n"
                     "forces: [{kind: gravity}, {kind: spring, k: 50, L: 0.6}]\n"
                     "steady: [{axis: [0, 0, 1]}]\n", "big.yaml")[0]
    assert rec["exit_code"] == 1, rec["error"]
    assert "steady.0" in rec["error"] and "rescale" in rec["error"]
