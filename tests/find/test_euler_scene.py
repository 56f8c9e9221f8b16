"""``find`` in ``euler`` (torque-free, Jacobi elliptic route) against Euler's equations integrated
by mpmath's Taylor ODE solver, and in ``scene`` (a compound pendulum on the ODE) against the
elliptic closed form.

Euler: I = [1, 2, 3], ω0 = [1, 0, 2] (H² > 2T I2: ω3 keeps its sign); ω̇1 = −ω2ω3,
ω̇2 = ω3ω1, ω̇3 = −ω1ω2/3; the zeros of ω1, ω2 by mpmath.findroot on mpmath.odefun's solution at
25 digits.  The route is exact (Jacobi elliptic functions in doubles): crossings to 1e-10
relative; extremes of ω (no rate reported) by Brent's minimiser, their times to 1e-7.

Scene: a bar (m, L) pinned at an end, released at rest 30° below the horizontal; φ = θ + π/2 from
the downward vertical: sin(φ/2) = k sn(K − ω t | k²), k = sin(φ0/2), ω² = 3g/2L; the bottom at
T/4, the far turning point at T/2; the bar's centre travels (L/2) Σ|Δφ|.  ODE at accuracy.rtol =
1e-10: ``tolerances.ode(rtol)``.
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.tolerances import ode

from .refs import entry, solve

MPMATH_DPS = 25
TOL = ode(1e-10)

EULER = """
type: euler
I: [1, 2, 3]
omega0: [1, 0, 2]
t_end: 4
find:
  - {when: {omega.0: 0}}
  - {max: omega.1}
  - {when: {omega.1: 0}}
  - {when: {omega.1: 0}, direction: up}
  - {min: omega.2}
  - {t: 3}
"""


def test_euler_torque_free():
    r, _ = solve(EULER)
    sol = mp.odefun(lambda t, w: [-w[1] * w[2], w[2] * w[0], -w[0] * w[1] / 3], 0, [1, 0, 2])
    w = lambda k: (lambda t: sol(t)[k])               # noqa: E731
    z0 = mp.findroot(w(0), 0.8)
    z1 = mp.findroot(w(1), 2 * z0)                   # ω2 back to 0 at twice the zero of ω1 (symmetry)
    assert abs(z1 - 2 * z0) < mp.mpf("1e-15")
    for k, t in ((0, z0), (2, z1)):
        assert entry(r, k)["t"] == pytest.approx(float(t), rel=1e-10), k
    for k in (1, 4):                                 # euler reports no rate of ω: Brent's minimiser, t to ~√eps
        assert entry(r, k)["t"] == pytest.approx(float(z0), rel=1e-7), k
    assert entry(r, 1)["omega"][1] == pytest.approx(float(w(1)(z0)), rel=1e-12)
    assert entry(r, 4)["omega"][2] == pytest.approx(float(w(2)(z0)), rel=1e-12)
    assert entry(r, 3)["t"] == pytest.approx(float(mp.findroot(w(1), 4 * z0)), rel=1e-10)
    assert entry(r, 5)["omega"] == pytest.approx([float(x) for x in sol(3)], rel=1e-12, abs=1e-12)


PENDULUM = """
type: scene
params: {m: 2, L: 1.2, th0: "-30*deg"}
bodies:
  bar: {shape: rod, mass: m, length: L, angle: th0, x: ["L/2*cos(th0)", "L/2*sin(th0)"]}
joints:
  pivot: {pin: [bar.end1, [0, 0]]}
t_end: 1.6
accuracy: {rtol: 1e-10}
find:
  - {when: {angle.bar: "-pi/2"}}
  - {min: angle.bar}
  - {when: {angle.bar: "-pi/2"}, direction: up}
  - {min: omega.bar.2}
  - {when: {angle.bar: "-100*deg"}}
  - {t: 1.6}
  - {max: reaction.pivot.R.1}
  - {max: angle.bar, within: [1, 2.5]}
"""


def test_scene_compound_pendulum():
    r, _ = solve(PENDULUM)
    g, L, M = mp.mpf("9.81"), mp.mpf("1.2"), 2
    phi0 = mp.pi / 3
    k2, w = mp.sin(phi0 / 2) ** 2, mp.sqrt(3 * g / (2 * L))
    K = mp.ellipk(k2)
    T = 4 * K / w
    phi = lambda t: 2 * mp.asin(mp.sqrt(k2) * mp.ellipfun("sn", K - w * t, m=k2))     # noqa: E731

    def t_at(ph):                                    # first time at φ (|φ| < φ0), on the first swing
        return (K - mp.ellipf(mp.asin(mp.sin(ph / 2) / mp.sqrt(k2)), k2)) / w
    for k, t in ((0, T / 4), (1, T / 2), (2, 3 * T / 4), (3, T / 4), (4, t_at(-mp.pi / 18)), (7, T)):
        assert entry(r, k)["t"] == pytest.approx(float(t), rel=TOL), k
    assert entry(r, 1)["angle"]["bar"] == pytest.approx(float(-5 * mp.pi / 6), rel=TOL)
    assert entry(r, 3)["omega"]["bar"][2] == pytest.approx(float(-mp.sqrt(3 * g * (1 - mp.cos(phi0)) / L)), rel=TOL)
    e = entry(r, 5)
    assert e["angle"]["bar"] == pytest.approx(float(phi(mp.mpf("1.6")) - mp.pi / 2), rel=TOL)
    arc = L / 2 * (2 * phi0 + abs(phi(mp.mpf("1.6")) + phi0))
    assert e["distance"]["bar"] == pytest.approx(float(arc), rel=TOL)
    e = entry(r, 6)                                  # the pin's largest push: at the bottom, m g (5 − 3 cos φ0)/2
    assert e["t"] == pytest.approx(float(T / 4), rel=1e-7)                  # (no rate: Brent's minimiser)
    assert e["reaction"]["pivot"]["R"][1] == pytest.approx(float(M * g * (5 - 3 * mp.cos(phi0)) / 2), rel=TOL)
    assert entry(r, 7)["at_end"] is False


def test_a_window_late_in_a_long_euler_run_is_searched_in_that_window():
    """A torque-free body (I = 1, 2, 3, ω0 = [1, 0, 1]: ω = (cn, −sn, dn)(t, k² = 1/3) by hand)
    followed to 1e4 s turns ~1,600 times, more than a search resolves over the whole run; a `min`
    asked within [9990, 10000] spans 4 turns and is searched there alone (before: "not
    searched", though the refusal says to narrow the window with within).  dn's least value
    √(1 − k²) = √(2/3) at t = (2j + 1) K(1/3), the first such time in the window (mpmath); a
    `max` without a window is still not searched, and said so."""
    import math

    r, warnings = solve("""
type: euler
I: [1, 2, 3]
omega0: [1, 0, 1]
t_end: 10000
find:
  - {min: omega.2, within: [9990, 10000]}
  - {max: omega.2}
""")
    with mp.workdps(30):
        K = mp.ellipk(mp.mpf(1) / 3)
        j = math.ceil((9990 / float(K) - 1) / 2)
        t = float((2 * j + 1) * K)
    e = entry(r, 0)
    assert e["t"] == pytest.approx(t, rel=1e-13)
    assert e["omega"][2] == pytest.approx(math.sqrt(2 / 3), rel=1e-13)
    assert r["find"][1]["reached"] is False
    assert any(w.startswith("find.1: not searched") for w in warnings)
