"""kinematics at one instant (`instant`): the textbook's numbers give the same results as a
motion given by functions of t.  References: the components derived by hand (7.14), (7.16c),
(5.14b); sympy.physics.vector for spherical coordinates; and a second route, the position route
on quadratics in t that have the given (q, q̇, q̈) at t = 0."""

from __future__ import annotations

import math

import pytest

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path
from tests.topics.kinematics.test_kinematics import _spherical_reference, close

HAND = 1e-13      # a handful of roundings of numbers of order 1


def _yaml(coords, instant, extra=""):
    body = ", ".join(f"{k}: {v!r}" for k, v in instant.items())
    return f"type: kinematics\ncoordinates: {coords}\ninstant: {{{body}}}\n{extra}"


def _as_functions(coords, instant):
    """The same state as a position in t: q + q̇ t + q̈ t²/2 for each coordinate."""
    from dyncli.topics.kinematics.model import COORDINATES

    pos = {}
    for n in COORDINATES[coords]:
        q, qd, qdd = (instant.get(n + s, 0.0) for s in ("", "_dot", "_ddot"))
        pos[n] = f"({q!r}) + ({qd!r})*t + ({qdd!r})*t**2/2"
    body = ", ".join(f"{k}: '{v}'" for k, v in pos.items())
    return f"type: kinematics\ncoordinates: {coords}\nposition: {{{body}}}\nat: [0]\nm: 3\n"


def test_gallery_collar_by_hand():
    recs = solve_path(PROBLEMS / "kinematics" / "instant-data.yaml")
    r = recs[0]["results"]
    rr, rd, rdd, th, thd, thdd = 0.5, 0.8, -0.2, math.pi / 6, 2.0, 1.5
    vb = [rd, rr * thd, 0.0]                                   # (7.14)
    ab = [rdd - rr * thd ** 2, rr * thdd + 2 * rd * thd, 0.0]  # (7.16c)
    close(r["v_basis"], vb, HAND)
    close(r["a_basis"], ab, HAND)
    c, s = math.cos(th), math.sin(th)
    close(r["x"], [rr * c, rr * s, 0.0], HAND)
    close(r["a"], [ab[0] * c - ab[1] * s, ab[0] * s + ab[1] * c, 0.0], HAND)
    speed = math.hypot(vb[0], vb[1])
    close(r["speed"], speed, HAND)
    close(r["a_t"], (vb[0] * ab[0] + vb[1] * ab[1]) / speed, HAND)
    an = abs(vb[0] * ab[1] - vb[1] * ab[0]) / speed
    close(r["a_n"], an, HAND)
    close(r["rho"], speed ** 2 / an, HAND)
    close(r["F_basis"], [0.4 * x for x in ab], HAND)
    assert not isinstance(r["speed"], list)                   # single values, not lists


def test_gallery_car_on_a_curve_by_hand():
    r = solve_path(PROBLEMS / "kinematics" / "instant-data.yaml")[1]["results"]
    assert r["a_t"] == -3.0 and r["a_n"] == 20.0 ** 2 / 50.0 and r["rho"] == 50.0 and r["speed"] == 20.0
    assert r["a_basis"] == [-3.0, 8.0, 0.0] and r["F_basis"] == [-3600.0, 9600.0, 0.0]
    assert "x" not in r and "e_t" not in r          # a path gives no Cartesian frame


STATES = [
    ("polar", {"r": 2.0, "r_dot": -1.5, "r_ddot": 0.25, "theta": 1.1, "theta_dot": 0.7, "theta_ddot": -2.0}),
    ("cylindrical", {"r": 1.2, "r_dot": 0.3, "theta": -0.4, "theta_dot": 5.0, "theta_ddot": 0.5,
                     "x3": 0.7, "x3_dot": -2.0, "x3_ddot": 9.0}),
    ("spherical", {"R": 3.0, "R_dot": 0.5, "R_ddot": -1.0, "theta": 0.3, "theta_dot": 1.2,
                   "theta_ddot": 0.1, "phi": 0.6, "phi_dot": -0.8, "phi_ddot": 0.4}),
]


@pytest.mark.parametrize("coords,state", STATES, ids=[s[0] for s in STATES])
def test_instant_equals_the_position_route(coords, state):
    r = solve_one_text(_yaml(coords, state, "m: 3\n"))["results"]
    ref = solve_one_text(_as_functions(coords, state))["results"]
    assert set(r) == set(ref) - {"distance"}
    for k in r:
        close(r[k], ref[k][0], 1e-13)


def test_spherical_instant_vs_sympy_physics_vector():
    _, st = STATES[2]

    def q(n):
        return lambda t, sp: st[n] + st[n + "_dot"] * t + st[n + "_ddot"] * t ** 2 / 2

    ref = _spherical_reference(q("R"), q("theta"), q("phi"), [0.0])[0]
    r = solve_one_text(_yaml("spherical", st))["results"]
    for k in ("x", "v", "a", "v_basis", "a_basis"):
        close(r[k], ref[k], 1e-13)


def test_path_equals_a_circle_in_polar_coordinates():
    """A circle of radius ρ travelled with s = v t + v̇ t²/2 is r = ρ, θ = s/ρ."""
    v, vd, rho = 7.0, -2.5, 4.0
    r = solve_one_text(_yaml("path", {"v": v, "v_dot": vd, "rho": rho}))["results"]
    ref = solve_one_text(_yaml("polar", {"r": rho, "theta": 0.0, "theta_dot": v / rho,
                                         "theta_ddot": vd / rho}))["results"]
    for k in ("speed", "a_t", "a_n", "rho"):
        close(r[k], ref[k], 1e-13)
    # (e_r, e_θ) of the circle are (−e_n, e_t): the components agree after that relabelling
    close(r["a_basis"][:2], [ref["a_basis"][1], -ref["a_basis"][0]], 1e-13)


def test_straight_path_and_rest():
    rec = solve_one_text(_yaml("path", {"v": 3.0, "v_dot": 1.0}))
    assert rec["results"]["rho"] is None and rec["results"]["a_n"] == 0.0
    assert any("straight path" in w for w in rec["warnings"])
    rec = solve_one_text(_yaml("polar", {"r": 1.0, "theta": 0.0, "r_ddot": 2.0}))
    assert rec["results"]["a_t"] is None and any("at rest at the instant" in w for w in rec["warnings"])


@pytest.mark.parametrize("text,field,fix", [
    ("coordinates: polar\ninstant: {r: 1, theta_dot: 2}\n", "instant", "missing: theta"),
    ("coordinates: polar\ninstant: {r: 1, theta: 0, R_dot: 2}\n", "instant.R_dot", "set coordinates: spherical"),
    ("instant: {r: 1, theta: 0}\n", "coordinates", "set coordinates"),
    ("coordinates: path\nposition: {x1: t}\n", "position", "give instant"),
    ("coordinates: path\ninstant: {v: -1}\n", "instant.v", "must be >= 0"),
    ("coordinates: path\ninstant: {v: 1, rho: 0}\n", "instant.rho", "must be > 0"),
    ("coordinates: path\ninstant: {v: 1}\nat: [1]\n", "at", "remove at"),
    ("coordinates: path\ninstant: {v: 1}\ndistance: [0, 1]\n", "distance", "give position"),
    ("coordinates: polar\nposition: {r: 1, theta: t}\ninstant: {r: 1, theta: 0}\n", "instant", "not both"),
    ("coordinates: polar\n", "position", "or instant"),
    ("coordinates: path\ninstant: {v: 1, rhoo: 2}\n", "instant.rhoo", "did you mean 'rho'"),
])
def test_invalid_instant_names_the_field_and_the_fix(text, field, fix):
    msg = error_of("type: kinematics\n" + text)
    assert f" {field}:" in msg and fix in msg, msg


def test_symbolic_says_it_has_nothing_to_show():
    from dyncli.loader import split_problems, validate
    from dyncli.result import SolveOptions
    from dyncli.run import solve_one
    from tests.conftest import ROOT

    (lp,), _ = split_problems("x.yaml", _yaml("path", {"v": 2.0, "rho": 4.0}).encode(), ROOT)
    validate(lp)
    o = solve_one(lp, SolveOptions(symbolic=True))
    assert any("--symbolic: no formulas at one instant" in w for w in o.result.warnings)
