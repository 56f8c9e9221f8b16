"""The exact Kepler route of ``particle`` (inverse-square central force alone) and the ODE route
on eccentric orbits (issues #27 item 3, #28).

References: mpmath at 30 digits (tests/topics/particle/kepler_ref.py: the eccentricity vector,
the perifocal frame, Kepler's equation by findroot; it never imports dyncli) from the same double
initial state.  Tolerances: the exact route's own error_estimate (the rounding of the time carried
through the orbit's fastest rate, 8 ε (1 + t v_p/r_p)), itself asserted small; the ODE route's
default estimate must bound its true error (and the error be <= 100 x rtol unless a warning says
the request was not met)."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from tests.conftest import error_of, run_cli, solve_one_text
from tests.topics.particle import kepler_ref as ref

MU = 3.986004418e14           # g R0² with R0 = 6371 km
G = MU / 6371000.0 ** 2
RP = 7.0e6
QUANTITIES = ("x", "v", "a", "T", "V", "E", "H_O")


def text(x0, v0, at, extra="", m=1000.0):
    return (f"type: particle\nm: {m!r}\ng: {G!r}\nx0: {[float(c) for c in x0]}\nv0: {[float(c) for c in v0]}\n"
            f"forces: [{{kind: inverse-square, R0: 6371000}}]\nat: {[float(t) for t in at]}\n{extra}")


def perigee_state(e, incline=0.0):
    """A state at perigee (r = RP) of eccentricity e, its plane turned about e1 by ``incline``, and
    the position rotated in the plane so that no component is trivially zero."""
    vp = math.sqrt(MU * (1 + e) / RP)
    c, s = math.cos(0.6), math.sin(0.6)
    r = np.array([RP * c, RP * s, 0.0])
    v = np.array([-vp * s, vp * c, 0.0])
    ci, si = math.cos(incline), math.sin(incline)
    rot = np.array([[1, 0, 0], [0, ci, -si], [0, si, ci]])
    return rot @ r, rot @ v


def reference(x0, v0, times, m=1000.0):
    """The reported quantities at the times from the mpmath state."""
    out = {q: [] for q in QUANTITIES}
    for t in times:
        x, v = (np.array(u) for u in ref.state(MU, x0, v0, t))
        R = np.linalg.norm(x)
        out["x"].append(x)
        out["v"].append(v)
        out["a"].append(-MU * x / R ** 3)
        out["T"].append(0.5 * m * v @ v)
        out["V"].append(-m * MU / R)
        out["E"].append(0.5 * m * v @ v - m * MU / R)
        out["H_O"].append(m * np.cross(x, v))
    return out


def relative_error(results, expected) -> float:
    """The largest error of every quantity, each relative to its scale (largest magnitude)."""
    worst = 0.0
    for q in QUANTITIES:
        got, exp = np.array(results[q], float), np.array(expected[q], float)
        worst = max(worst, float(np.max(np.abs(got - exp))) / float(np.max(np.abs(exp))))
    return worst


# -- Kepler's equation itself ----------------------------------------------------------------------

@pytest.mark.parametrize("e", [0.0, 0.5, 0.9, 0.99, 0.999999])
def test_kepler_equation_against_mpmath(e):
    from dyncli.topics.particle.kepler import kepler_E

    M = np.array([0.0, 1e-9, 1e-4, 0.3, 1.0, 2.5, 3.1, -2.0, 40.0])
    E = kepler_E(M, e)
    with mp.workdps(30):
        for Mi, Ei in zip(M, E):
            Er = mp.findroot(lambda x: x - e * mp.sin(x) - mp.mpf(float(Mi)), mp.mpf(float(Ei)))
            assert abs(Ei - float(Er)) <= 8e-16 * max(1.0, abs(float(Er))) + 4e-16 / (1 - e), (e, Mi)


@pytest.mark.parametrize("e", [1.000001, 1.5, 4.0])
def test_hyperbolic_kepler_equation_against_mpmath(e):
    from dyncli.topics.particle.kepler import kepler_H

    M = np.array([0.0, 1e-6, 0.5, 3.0, 50.0, -7.0, 1e4])
    H = kepler_H(M, e)
    with mp.workdps(30):
        for Mi, Hi in zip(M, H):
            Hr = mp.findroot(lambda x: e * mp.sinh(x) - x - mp.mpf(float(Mi)), mp.mpf(float(Hi)))
            assert abs(Hi - float(Hr)) <= 1e-15 * max(1.0, abs(float(Hr))) + 1e-15 / (e - 1) ** 0.5, (e, Mi)


def test_barker_equation():
    from dyncli.topics.particle.kepler import barker_D

    for B in (0.0, 1e-8, 0.7, -3.0, 1e6):
        D = float(barker_D(B))
        assert D + D ** 3 / 3 == pytest.approx(B, rel=1e-14, abs=1e-22)


# -- the exact route against mpmath ----------------------------------------------------------------

@pytest.mark.parametrize("e", [0.0, 0.5, 0.9, 0.99])
def test_exact_route_against_mpmath(e):
    x0, v0 = perigee_state(e)
    el = ref.elements(MU, x0, v0)
    T = float(el["period"])
    times = [0.0, 0.013 * T, 0.25 * T, 0.5 * T, 0.77 * T, T, 2.999 * T]
    rec = solve_one_text(text(x0, v0, times))
    assert rec["method"] == "exact"
    err = relative_error(rec["results"], reference(x0, v0, times))
    assert err <= rec["error_estimate"] <= 1e-10, (e, err, rec["error_estimate"])
    orb = rec["results"]["orbit"]
    for k in ("e", "a", "r_p", "r_a", "period", "v_p", "v_a"):
        assert orb[k] == pytest.approx(float(el[k]), rel=1e-13, abs=1e-15), k
    assert orb["v_circular"] == pytest.approx(math.sqrt(MU / RP), rel=1e-15)
    assert orb["v_escape"] == pytest.approx(math.sqrt(2 * MU / RP), rel=1e-15)
    assert not rec["warnings"]


@pytest.mark.parametrize("e", [1.0, 1.2, 3.0])
def test_open_orbits_against_mpmath(e):
    x0, v0 = perigee_state(e)
    x0 = x0 * 1.0000000000000002 if e == 1.0 else x0      # rounding: still a parabola
    times = [0.0, 300.0, 2000.0, 20000.0]
    rec = solve_one_text(text(x0, v0, times))
    orb = rec["results"]["orbit"]
    assert orb["r_a"] is None and orb["period"] is None and orb["v_a"] is None
    if e == 1.0:
        assert orb["a"] is None and orb["e"] == 1.0
        # a parabola's reference: r = p(1 + D²)/2 with D from Barker's equation, in mpmath
        with mp.workdps(30):
            p = mp.mpf(float(np.linalg.norm(np.cross(x0, v0)))) ** 2 / MU
            for t, x in zip(times, rec["results"]["x"]):
                B = 2 * mp.sqrt(MU / p ** 3) * t
                D = mp.findroot(lambda d: d + d ** 3 / 3 - B, 1)
                assert float(np.linalg.norm(x)) == pytest.approx(float(p * (1 + D ** 2) / 2), rel=1e-13)
    else:
        assert orb["a"] < 0
        err = relative_error(rec["results"], reference(x0, v0, times))
        assert err <= rec["error_estimate"] <= 1e-12


def test_inclined_orbit_3d_against_mpmath():
    x0, v0 = perigee_state(0.7, incline=math.radians(51.6))
    x0 = x0 + np.array([0.0, 0.0, 1.0e5])            # not at perigee
    el = ref.elements(MU, x0, v0)
    T = float(el["period"])
    times = [0.0, 0.1 * T, 0.6 * T, 1.7 * T]
    rec = solve_one_text(text(x0, v0, times))
    err = relative_error(rec["results"], reference(x0, v0, times))
    assert err <= rec["error_estimate"] <= 1e-11
    h = np.cross(x0, v0)
    for x in rec["results"]["x"]:                      # in the plane through O normal to H_O
        assert abs(np.dot(x, h)) <= 1e-14 * np.linalg.norm(x) * np.linalg.norm(h)


def test_state_function_gives_the_reported_results():
    from dyncli.loader import split_problems, validate
    from dyncli.run import solve_one

    x0, v0 = perigee_state(0.6)
    for method in ("auto", "DOP853"):
        (lp,), _ = split_problems("o.yaml", text(x0, v0, [0, 1000.0, 4321.0], f"accuracy: {{method: {method}}}\n").encode(), None)
        validate(lp)
        res = solve_one(lp).result
        st = res.extra["state"](4321.0)
        assert st["x"] == pytest.approx(res.results["x"][2], rel=1e-12)
        assert st["E"] == pytest.approx(res.results["E"][2], rel=1e-12)


# -- the exact and the ODE route ------------------------------------------------------------------

@pytest.mark.parametrize("e", [0.3, 0.9])
def test_exact_and_forced_ode_agree_within_the_estimate(e):
    x0, v0 = perigee_state(e, incline=0.4)
    T = float(ref.elements(MU, x0, v0)["period"])
    times = [0.0, 0.3 * T, T, 2.2 * T]
    exact = solve_one_text(text(x0, v0, times))
    ode = solve_one_text(text(x0, v0, times, "accuracy: {rtol: 1.0e-9, method: ode}\n"))
    assert ode["method"] == "ode:DOP853" and exact["method"] == "exact"
    assert relative_error(ode["results"], exact["results"]) <= ode["error_estimate"] <= 100 * 1e-9
    assert ode["results"]["orbit"] == exact["results"]["orbit"]


ECC = [(e, rtol) for e in (0.5, 0.9, 0.97) for rtol in (1e-6, 1e-9)]


@pytest.mark.parametrize("e,rtol", ECC)
def test_eccentric_orbit_default_estimate_bounds_the_error(e, rtol):
    # mu = 1, r_p = 1, 5 revolutions, the perigee passages among the times (issue #28)
    T = 2 * math.pi * (1 / (1 - e)) ** 1.5
    times = sorted({5 * T * k / 40 for k in range(41)} | {k * T + 1e-3 for k in range(5)})
    x0, v0 = [1.0, 0.0, 0.0], [0.0, math.sqrt(1 + e), 0.0]
    rec = solve_one_text(f"type: particle\nm: 1\ng: 1\nx0: {x0}\nv0: {v0}\nforces: [{{kind: inverse-square, R0: 1}}]\n"
                         f"at: {times}\naccuracy: {{rtol: {rtol!r}, atol: 1.0e-30, method: DOP853}}\n")
    expected = {q: [] for q in QUANTITIES}
    for t in times:
        x, v = (np.array(u) for u in ref.state(1.0, x0, v0, t))
        R = np.linalg.norm(x)
        for q, val in zip(QUANTITIES, (x, v, -x / R ** 3, v @ v / 2, -1 / R, v @ v / 2 - 1 / R, np.cross(x, v))):
            expected[q].append(val)
    err = relative_error(rec["results"], expected)
    est = rec["error_estimate"]
    assert err <= est, (e, rtol, err, est)
    promise_missed = [w for w in rec["warnings"] if "requested accuracy is not met" in w]
    assert (est > 100 * rtol) == bool(promise_missed)
    if not promise_missed:
        assert err <= 100 * rtol


# -- refusals and warnings -------------------------------------------------------------------------

def test_exact_with_another_force_is_refused():
    msg = error_of("type: particle\nm: 1\nx0: [7e6, 0, 0]\nv0: [0, 7000, 0]\nt_end: 10\n"
                   "forces: [{kind: inverse-square, R0: 6371000}, {kind: drag, c: 1}]\naccuracy: {method: exact}\n")
    assert "accuracy.method" in msg and "inverse-square central force alone" in msg


def test_an_added_force_keeps_the_ode():
    rec = solve_one_text("type: particle\nm: 1\nx0: [7e6, 0, 0]\nv0: [0, 7000, 0]\nt_end: 10\n"
                         "forces: [{kind: inverse-square, R0: 6371000}, {kind: gravity}]\n")
    assert rec["method"] == "ode:DOP853" and "orbit" not in rec["results"]


def test_radial_orbit_goes_to_the_ode_and_exact_refuses_it():
    base = "type: particle\nm: 1\nx0: [7e6, 0, 0]\nv0: [100, 0, 0]\nt_end: 10\nforces: [{kind: inverse-square, R0: 6371000}]\n"
    rec = solve_one_text(base)
    assert rec["method"] == "ode:DOP853"
    assert any("radial" in w for w in rec["warnings"])
    assert "radial" in error_of(base + "accuracy: {method: exact}\n")


def test_radial_fall_into_the_centre_is_refused_with_its_time():
    # dropped from rest at r0: the free-fall time (pi/2) sqrt(r0³/(2 mu)), in mpmath
    with mp.workdps(30):
        t_c = mp.pi / 2 * mp.sqrt(mp.mpf(7e6) ** 3 / (2 * mp.mpf(9.81) * mp.mpf(6371000) ** 2))
    rc, _, msg = run_cli("solve", "-", input="type: particle\nm: 1\nx0: [7e6, 0, 0]\nt_end: 5000\n"
                                             "forces: [{kind: inverse-square, R0: 6371000}]\n")
    assert rc == 1 and "t_end" in msg and f"t = {float(t_c):.6g} s" in msg and "falls into the centre" in msg
    rec = solve_one_text("type: particle\nm: 1\nx0: [7e6, 0, 0]\nt_end: 100\nforces: [{kind: inverse-square, R0: 6371000}]\n")
    assert any(f"reaches the centre at t = {float(t_c):.6g} s" in w for w in rec["warnings"])


@pytest.mark.parametrize("rdot", [3000.0, -3000.0, -20000.0])
def test_radial_fall_time_against_mpmath(rdot):
    from dyncli.topics.particle.kepler import radial_fall_time

    mu, R = 3.986e14, 7.0e6
    with mp.workdps(30):
        # t = ∫ dr / |ṙ(r)| along the way out (to the apex, if bound) and in, ṙ² = 2(ε + mu/r)
        eps = mp.mpf(rdot) ** 2 / 2 - mp.mpf(mu) / R
        def fall(r):    # the time from r to the centre: ∫ dr/|ṙ|, ṙ² = 2(eps + mu/r)
            if eps >= 0:
                return mp.quad(lambda x: mp.sqrt(x / (2 * (eps * x + mu))), [0, r])
            apex = -mp.mpf(mu) / eps      # r = apex sin²φ takes the apex's 1/sqrt away
            return mp.quad(lambda f: 2 * apex * mp.sqrt(apex / (2 * mu)) * mp.sin(f) ** 2,
                           [0, mp.asin(mp.sqrt(r / apex))])

        if eps < 0 and rdot > 0:            # up to the apex, then all the way down
            t = 2 * fall(-mp.mpf(mu) / eps) - fall(R)
        else:
            t = fall(R)
    assert radial_fall_time(mu, R, rdot) == pytest.approx(float(t), rel=1e-12)


def test_collision_with_the_body_is_said_with_its_time():
    # released at apogee r = 7e6 m with too little speed: r_p < R0 = 6371 km
    v = 5000.0
    rec = solve_one_text(text([7.0e6, 0, 0], [0, v, 0], [0, 2000.0]))
    (w,) = [w for w in rec["warnings"] if "inside R0" in w]
    # reference: r(E) = a(1 − e cos E) = R0 on the way down from apogee (E = π), mpmath
    with mp.workdps(30):
        r0, mu = mp.mpf(7e6), mp.mpf(MU)
        a = 1 / (2 / r0 - mp.mpf(v) ** 2 / mu)
        e = r0 / a - 1
        E = 2 * mp.pi - mp.acos((1 - mp.mpf(6371000) / a) / e)
        t = (E - e * mp.sin(E) - mp.pi) * mp.sqrt(a ** 3 / mu)
    assert f"t = {float(t):.6g} s" in w


def test_the_state_at_t0_is_the_input_exactly():
    x0, v0 = perigee_state(0.3, incline=0.2)
    x0 = x0 + np.array([123.4, 0, 0])
    rec = solve_one_text(text(x0, v0, [0, 10.0]))
    assert rec["results"]["x"][0] == [float(c) for c in x0]
    assert rec["results"]["v"][0] == [float(c) for c in v0]
