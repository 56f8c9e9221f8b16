"""Every example in problems/particle/ against reference values computed
independently: mpmath Taylor integration, closed forms re-derived here."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dyncli import expr
from tests.conftest import PROBLEMS, solve_path

DIR = PROBLEMS / "particle"


def rec_of(name, index=0):
    recs = solve_path(DIR / name)
    for r in recs:
        assert r.get("error") is None, r.get("error")
    return recs[index] if index is not None else recs


def close(a, b, rtol=1e-8, atol=1e-9):
    np.testing.assert_allclose(np.asarray(a, float), np.asarray(b, float), rtol=rtol, atol=atol)


def test_projectile_quadratic_drag_against_mpmath():
    import mpmath as mp

    m, c, g = 0.5, 0.005, 9.81
    with mp.workdps(20):
        def f(t, y):
            x1, x3, v1, v3 = y
            s = mp.sqrt(v1 * v1 + v3 * v3)
            return [v1, v3, -c * s * v1 / m, -g - c * s * v3 / m]

        sol = mp.odefun(f, 0, [0, 0, 20, 20])
        ref = {t: [float(v) for v in sol(t)] for t in (1, 2, 3)}
    r = rec_of("projectile-quadratic-drag.yaml")
    R = r["results"]
    assert r["method"] == "ode:DOP853"
    for i, t in enumerate([0, 1, 2, 3]):
        if t == 0:
            continue
        x1, x3, v1, v3 = ref[t]
        close(R["x"][i], [x1, 0, x3], rtol=1e-8, atol=1e-8)
        close(R["v"][i], [v1, 0, v3], rtol=1e-8, atol=1e-8)
        # a = F/m
        s = math.hypot(v1, v3)
        close(R["a"][i], [-c * s * v1 / m, 0, -g - c * s * v3 / m], rtol=1e-7, atol=1e-7)
        # energies: T, V = m g x3, E = T + V, W_nc = E - E1 (drag dissipates)
        T = 0.5 * m * (v1 * v1 + v3 * v3)
        assert R["T"][i] == pytest.approx(T, rel=1e-8)
        assert R["V"][i] == pytest.approx(m * g * x3, rel=1e-8)
        assert R["W_nc"][i] == pytest.approx(T + m * g * x3 - 0.5 * m * 800, rel=1e-7)
        assert R["W_nc"][i] < 0
    assert R["energy_residual"] < 1e-6
    assert 0 <= r["error_estimate"] < 1e-5


def _coulomb_oscillator(m, k, L, e0, muN, times):
    """Closed form of a block on a spring with Coulomb friction released from
    rest with extension e0: harmonic half-swings of period pi/omega about the
    shifted equilibrium s_n = sign(e_n) mu N / k."""
    w = math.sqrt(k / m)
    d = muN / k
    swings = []          # (t_start, e_start, shift)
    t, e = 0.0, e0
    while abs(e) > d:
        s = math.copysign(d, e)
        swings.append((t, e, s))
        t += math.pi / w
        e = 2 * s - e
    t_rest, e_rest = t, e
    out = []
    for tt in times:
        if tt >= t_rest:
            out.append((L + e_rest, 0.0))
            continue
        n = int((tt) // (math.pi / w))
        n = min(n, len(swings) - 1)
        t0, e0_, s = swings[n]
        tau = tt - t0
        out.append((L + s + (e0_ - s) * math.cos(w * tau), -(e0_ - s) * w * math.sin(w * tau)))
    return out, t_rest, e_rest


def test_spring_with_friction_comes_to_rest_closed_form():
    m, k, L, muN = 1.0, 100.0, 0.5, 0.3 * 9.81
    times = [0, 0.5, 1, 2, 2.5, 3]
    ref, t_rest, e_rest = _coulomb_oscillator(m, k, L, 0.4, muN, times)
    assert t_rest == pytest.approx(7 * math.pi / 10)
    r = rec_of("spring-friction-rest.yaml")
    R = r["results"]
    assert R["t_rest"] == pytest.approx(t_rest, rel=1e-9)
    for i, (x1, v1) in enumerate(ref):
        close(R["x"][i], [x1, 0, 0], rtol=1e-8, atol=1e-8)
        close(R["v"][i], [v1, 0, 0], rtol=1e-7, atol=1e-7)
        E = 0.5 * m * v1 ** 2 + 0.5 * k * (x1 - L) ** 2
        assert R["E"][i] == pytest.approx(E, rel=1e-7, abs=1e-9)
        assert R["W_nc"][i] == pytest.approx(E - 8.0, rel=1e-7, abs=1e-9)
    assert R["x"][-1][0] == pytest.approx(L + e_rest, abs=1e-9)
    assert R["a"][-1] == [0, 0, 0]
    assert any("sticks" in w for w in r["warnings"])


def test_satellite_conserves_H_O_and_returns_after_one_period():
    mu = 9.81 * 6371000.0 ** 2
    m = 1000.0
    x0, v0 = np.array([7e6, 0, 0]), np.array([0, 7000.0, 3000.0])
    H = m * np.cross(x0, v0)
    a = 1 / (2 / 7e6 - v0 @ v0 / mu)
    r = rec_of("satellite-inverse-square.yaml")
    R = r["results"]
    for x, h in zip(R["x"], R["H_O"]):
        close(h, H, rtol=1e-9, atol=1e-9 * np.linalg.norm(H))
        # orbit plane through O perpendicular to H_O (21.9)
        assert abs(np.dot(x, H)) <= 1e-9 * np.linalg.norm(x) * np.linalg.norm(H)
    close(R["x"][-1], x0, rtol=0, atol=1e-8 * 7e6)
    close(R["v"][-1], v0, rtol=0, atol=1e-8 * 7616)
    # half a period later the satellite is at apoapsis 2a - r0 (on the -e1 side)
    assert np.linalg.norm(R["x"][2]) == pytest.approx(2 * a - 7e6, rel=1e-9)
    E1 = 0.5 * m * v0 @ v0 - m * mu / 7e6
    close(R["E"], [E1] * 5, rtol=1e-9)
    assert R["W_nc"] == [0, 0, 0, 0, 0]
    assert R["energy_residual"] <= 10 * 1e-10 * abs(E1)


def test_charged_particle_helix():
    r = rec_of("charged-particle.yaml")
    R = r["results"]
    for i, t in enumerate([0, math.pi / 2, math.pi, 2 * math.pi]):
        close(R["x"][i], [math.sin(t), math.cos(t) - 1, 0.2 * t], rtol=0, atol=1e-8)
        close(R["v"][i], [math.cos(t), -math.sin(t), 0.2], rtol=0, atol=1e-8)
        assert R["T"][i] == pytest.approx(0.5 * 1.04, rel=1e-9)
        assert abs(R["W_nc"][i]) < 1e-12      # the magnetic force does no work
        assert R["V"][i] == 0


def _check_potential(text, F, at_zero=True):
    """-grad V = F at a few points, by central differences of the parsed V."""
    V = expr.parse(text, ("x1", "x2", "x3"))
    rng = np.random.default_rng(3)
    for p in rng.uniform(-2, 2, size=(5, 3)):
        h = 1e-5
        grad = []
        for i in range(3):
            e = np.zeros(3)
            e[i] = h
            grad.append((float(V(x1=p[0] + e[0], x2=p[1] + e[1], x3=p[2] + e[2]))
                         - float(V(x1=p[0] - e[0], x2=p[1] - e[1], x3=p[2] - e[2]))) / (2 * h))
        close(-np.array(grad), F(*p), rtol=1e-6, atol=1e-6)
    if at_zero:
        assert float(V.evaluate(x1=0.0, x2=0.0, x3=0.0)) == pytest.approx(0, abs=1e-14)


def test_fields_and_paths_path_independence():
    recs = rec_of("fields-and-paths.yaml", None)
    c1, c2, n1, n2 = (r["results"] for r in recs)
    # conservative: V = -x1² x2 - x1 x3³, work from 0 to (1,1,1) = 2 on both paths
    for R in (c1, c2):
        assert R["conservative"] is True
        assert R["conservative_method"] == "symbolic"
        assert R["work"] == pytest.approx(2.0, abs=1e-12)
        assert R["work_from_potential"] == pytest.approx(2.0, abs=1e-12)
        assert abs(R["work_check"]) < 1e-12
        _check_potential(R["potential"], lambda x1, x2, x3: [2 * x1 * x2 + x3 ** 3, x1 ** 2, 3 * x1 * x3 ** 2])
    assert c1["curl"] == [[0, 0, 0]]
    # non-conservative: curl (0, 0, 2); work pi on the half circle, 0 on the line
    assert n1["conservative"] is False and n2["conservative"] is False
    assert n1["potential"] is None and n1["work_check"] is None
    close(n1["curl"][0], [0, 0, 2])
    assert n1["work"] == pytest.approx(math.pi, abs=1e-12)
    assert n2["work"] == pytest.approx(0.0, abs=1e-14)
    assert recs[0]["method"] == "quadrature" and recs[0]["error_estimate"] < 1e-10


def test_vortex_field_is_not_conservative():
    r = rec_of("vortex-field.yaml")
    R = r["results"]
    close(R["curl"][0], [0, 0, 0], atol=1e-15)
    assert R["conservative"] is False
    assert R["potential"] is None
    assert R["work"] == pytest.approx(2 * math.pi, abs=1e-11)
    assert any("single-valued" in w for w in r["warnings"])


def test_transfer_orbit_exact_against_closed_forms():
    # Hohmann transfer r1 -> r2 (closed forms of the conic re-derived here, in mpmath)
    import mpmath as mp

    r = rec_of("transfer-orbit.yaml")
    assert r["method"] == "exact"
    R, orb = r["results"], r["results"]["orbit"]
    with mp.workdps(30):
        mu, r1, r2 = mp.mpf(9.81) * 6371000 ** 2, mp.mpf(6678000), mp.mpf(42164000)
        a = (r1 + r2) / 2
        vp = mp.sqrt(2 * mu * r2 / (r1 * (r1 + r2)))
        ref = {"e": (r2 - r1) / (r2 + r1), "a": a, "r_p": r1, "r_a": r2, "v_p": vp, "v_a": vp * r1 / r2,
               "period": 2 * mp.pi * mp.sqrt(a ** 3 / mu), "v_circular": mp.sqrt(mu / r1),
               "v_escape": mp.sqrt(2 * mu / r1)}
    for k, v in ref.items():
        assert orb[k] == pytest.approx(float(v), rel=1e-13), k
    # at half the period: apogee, on the −e1 side, moving along −e2 at v_a
    close(R["x"][1], [-float(r2), 0, 0], rtol=1e-13, atol=1e-6)
    close(R["v"][1], [0, -float(ref["v_a"]), 0], rtol=1e-13, atol=1e-9)
    close(R["x"][2], R["x"][0], rtol=1e-13, atol=1e-5)
