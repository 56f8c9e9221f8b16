"""A point body threaded on a curve (`slider: [P, CURVE]`): a collar on a curved rod, held both
ways (N signed, never released).  By hand: a collar (m = 2 kg) on a smooth circular rod of radius
R = 0.5 m in the vertical plane, a spring (k = 80 N/m, free length 0.3 m) to (0, −0.2), started
at the top at 0.5 m/s — at the bottom ½ m v² = ½ m v0² + m g 2R + ½ k (0.4² − 0²) (34.20) and
the rod pushes up with m g + m v²/R (the spring slack there); at the top, N = m g + k 0.4 − m v0²/R.
Rough (μ = 0.3, no spring), released at ψ0 = 1.2 rad from the bottom of a rod of radius 0.5: the
tangential and radial equations m R ψ̈ = −m g sin ψ + μ N sgn, N = m R ψ̇² + m g cos ψ, integrated
by mpmath's Taylor-series solver up to before the first turn.  On a free turntable (g = 0) a
collar threaded on a curved rod keeps the angular momentum about the pin and the energy."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import solve_text

G = 9.81

COLLAR = """type: scene
params: {m: 2, R: 0.5, k: 80, L0: 0.3}
surfaces:
  rod: {curve: {x1: "R*sin(q)", x2: "R*cos(q)"}}
bodies:
  C: {shape: point, mass: m, x: [0, 0.5], v: [0.5, 0]}
joints:
  ring: {slider: [C, rod]}
forces:
  - {spring: [C, [0, -0.2]], k: k, L: L0}
t_end: 2
at: [0, 0.3]
find: [{when: {x.C.1: -0.5}}]
accuracy: {rtol: 1e-11}
"""


def solve(text: str) -> dict:
    rec = solve_text(text, "collar.yaml")[0]
    assert rec.get("error") is None, rec.get("error")
    return rec


def test_collar_on_a_circular_rod_with_a_spring():
    r = solve(COLLAR)["results"]
    m, R, k = 2.0, 0.5, 80.0
    vb2 = 0.5 ** 2 + 2 * G * 2 * R + k * 0.4 ** 2 / m
    # the rod's normal n = e3 × t̂ points up at the top (t̂ = e1) and down at the bottom (t̂ = −e1)
    assert r["reaction"]["ring"]["N"][0] == pytest.approx(m * G + k * 0.4 - m * 0.25 / R, rel=1e-12)
    bottom = r["find"][0]
    assert math.hypot(*bottom["v"]["C"][:2]) == pytest.approx(math.sqrt(vb2), rel=1e-9)
    assert bottom["reaction"]["ring"]["N"] == pytest.approx(-(m * G + m * vb2 / R), rel=1e-8)
    assert not r["events"]                              # held both ways: nothing to release


def test_rough_collar_against_its_equations():
    mu, R, psi0, times = 0.3, 0.5, 1.2, [0.1, 0.2]

    def rates(t, y):                                    # sliding down (ψ̇ ≤ 0) until the first turn
        psi, w = y
        N = R * w * w + G * mp.cos(psi)                     # per unit mass, inward
        return [w, (-G * mp.sin(psi) + mu * abs(N)) / R]

    with mp.workdps(25):                                # (the others' mpmath precision left as it was)
        f = mp.odefun(rates, 0, [mp.mpf(psi0), mp.mpf(0)])
        ref = [float(f(t)[0]) for t in times]
    text = f"""type: scene
surfaces:
  rod: {{curve: {{x1: "{R}*sin(q)", x2: "-{R}*cos(q)"}}}}
bodies:
  C: {{shape: point, mass: 1, x: ["{R}*sin({psi0})", "-{R}*cos({psi0})"]}}
joints:
  ring: {{slider: [C, rod], mu: {mu}}}
at: {[0] + times}
accuracy: {{rtol: 1e-11}}
"""
    r = solve(text)["results"]
    for i, psi in enumerate(ref, start=1):
        x = r["x"]["C"][i]
        assert math.atan2(x[0], -x[1]) == pytest.approx(psi, rel=1e-8)


def test_collar_on_a_curved_rod_of_a_free_turntable():
    text = """type: scene
g: 0
surfaces:
  rod: {body: T, curve: {x1: "0.2 + 0.3*q", x2: "0.5*q*q"}, q_range: [-1, 1]}
bodies:
  T: {shape: disk, mass: 2, radius: 1, I: 0.3, x: [0, 0], angle: 0, omega: 2}
  C: {shape: point, mass: 0.5, x: [0.2, 0], v: [0, 0.4]}
joints:
  pin: {pin: [T, ground]}
  ring: {slider: [C, rod]}
t_end: 0.6
at: [0, 0.2, 0.4, 0.6]
accuracy: {rtol: 1e-11}
"""
    r = solve(text)["results"]
    L, T = [], []
    for i in range(len(r["t"])):
        w = r["omega"]["T"][i][2]
        x, v = r["x"]["C"][i], r["v"]["C"][i]
        L.append(0.3 * w + 0.5 * (x[0] * v[1] - x[1] * v[0]))
        T.append(0.15 * w * w + 0.25 * (v[0] ** 2 + v[1] ** 2))
    assert L == pytest.approx([L[0]] * len(L), rel=1e-9)
    assert T == pytest.approx([T[0]] * len(T), rel=1e-9)


def test_a_rigid_body_on_a_curved_slider_is_refused():
    rec = solve_text("""type: scene
surfaces:
  rod: {curve: {x1: "q", x2: "q*q"}}
bodies:
  B: {shape: box, mass: 1, size: [0.2, 0.1], x: [0, 0]}
joints:
  s: {slider: [B, rod]}
at: [0, 1]
""", "bad.yaml")[0]
    err = rec.get("error") or ""
    assert "joints.s.slider.0" in err and "for a point body" in err, err


def test_collar_on_circular_rod_gallery():
    """The gallery's file is COLLAR; the time to the bottom is mpmath's quadrature of R dq / v(q)
    with v(q) from the energy balance at each q."""
    from tests.topics.scene.common import gallery

    def d(q):
        return mp.sqrt((0.5 * mp.sin(q)) ** 2 + (0.5 * mp.cos(q) + 0.2) ** 2) - 0.3

    def v(q):
        return mp.sqrt(0.25 + 2 * G * 0.5 * (1 - mp.cos(q)) + 40 * (d(0) ** 2 - d(q) ** 2))

    with mp.workdps(30):
        t_bottom = float(mp.quad(lambda q: 0.5 / v(q), [0, mp.pi / 2, mp.pi]))
    r = gallery("collar-on-circular-rod.yaml")["results"]
    assert r["find"][0]["t"] == pytest.approx(t_bottom, rel=1e-8)
    assert r["find"][0]["reaction"]["ring"]["N"] == pytest.approx(-124.70, rel=1e-8)
