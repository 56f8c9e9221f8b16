"""``find`` and ``distance`` in ``particle``: a projectile on the ODE route and an elliptic orbit on
the exact Kepler route and the ODE, against closed forms and mpmath.

Projectile: apex at t = v_z/g, height v_z²/2g, landing at 2v_z/g, arc length ∫|v| dt by
mpmath.quad.  Orbit (mu = g R0² = 1, starting at perigee r_p = 1 with v = 1.2): e = 0.44,
a = 1/(2/r_p − v²), period P = 2π a^1.5; the apogee at P/2, perigee again at P, x = 0 where
cos E = e (Kepler's equation M = E − e sin E), and the path over one period the ellipse's
perimeter 4 a E(e²) (mpmath.ellipe).  Tolerances: the ODE at accuracy.rtol = 1e-10, held to
``tolerances.ode(rtol)``; the exact route's elements and Kepler solve to 1e-12 relative, its
distance by 10-point Gauss–Legendre on pieces of equal eccentric anomaly to 1e-10.  T's extremes
are roots of its rate m v·a; V's (no rate reported) come from Brent's minimiser: the time to
~√eps of the piece, the value to the route's accuracy.
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.tolerances import ode

from .refs import entry, solve

MPMATH_DPS = 30
RTOL = 1e-10
TOL = ode(RTOL)
G = mp.mpf("9.81")

PROJECTILE = """
type: particle
m: 1
x0: [0, 0, 0]
v0: [10, 0, 10]
forces: [{kind: gravity}]
t_end: 3
accuracy: {rtol: 1e-10}
find:
  - {max: x.2}
  - {when: {x.2: 0}, direction: down}
  - {when: {x.2: 0}}
  - {min: v.2, within: [0.5, 1.5]}
  - {when: {x.0: 15}}
  - {max: x.2, within: [4, 5]}
  - {when: {x.2: 100}}
  - {max: distance}
"""


def test_projectile_apex_landing_arc_length():
    r, warns = solve(PROJECTILE)
    vz, vx = mp.mpf(10), mp.mpf(10)
    apex, land = vz / G, 2 * vz / G
    arc = lambda t: mp.quad(lambda s: mp.sqrt(vx**2 + (vz - G * s) ** 2), [0, min(t, apex), t])   # noqa: E731
    e = entry(r, 0)
    assert e["t"] == pytest.approx(float(apex), rel=TOL)
    assert e["x"][2] == pytest.approx(float(vz**2 / (2 * G)), rel=TOL)
    assert e["at_end"] is False
    assert e["distance"] == pytest.approx(float(arc(apex)), rel=TOL)
    for k in (1, 2):                                 # x.2 = 0 held at the start: the landing
        e = entry(r, k)
        assert e["t"] == pytest.approx(float(land), rel=TOL)
        assert e["distance"] == pytest.approx(float(arc(land)), rel=TOL)
    e = entry(r, 3)
    assert (e["t"], e["at_end"]) == (1.5, True)
    assert entry(r, 4)["t"] == pytest.approx(1.5, rel=TOL)
    e = entry(r, 5)                                  # a window beyond t_end = 3: the motion extended to 5
    assert (e["t"], e["at_end"]) == (4.0, True)
    assert e["x"][2] == pytest.approx(float(40 - G * 8), rel=TOL)
    assert r["find"][6]["reached"] is False and r["find"][6]["x"] is None
    assert any("find.6" in w and "not reached" in w for w in warns)
    e = entry(r, 7)
    assert (e["t"], e["at_end"]) == (5.0, True)
    assert e["distance"] == pytest.approx(float(arc(5)), rel=TOL)


ORBIT = """
type: particle
m: 1
x0: [1, 0, 0]
v0: [0, 1.2, 0]
forces: [{{kind: inverse-square, center: [0, 0, 0], R0: 1, g: 1}}]
t_end: 20
accuracy: {{method: {method}, rtol: 1e-10}}
find:
  - {{min: T}}
  - {{max: T, within: [1, 20]}}
  - {{when: {{x.1: 0}}}}
  - {{when: {{x.1: 0}}, direction: up}}
  - {{when: {{x.0: 0}}}}
  - {{max: V}}
  - {{when: {{x.0: 0}}, occurrence: 3}}
"""


class Orbit:
    def __init__(self):
        v, r = mp.mpf("1.2"), mp.mpf(1)
        self.a = 1 / (2 / r - v**2)
        self.e = r * v**2 - 1                         # starts at perigee: r_p = a (1 − e) = 1
        self.n = self.a ** mp.mpf(-1.5)
        self.P = 2 * mp.pi / self.n
        self.perimeter = 4 * self.a * mp.ellipe(self.e**2)

    def t_of_E(self, E):
        return (E - self.e * mp.sin(E)) / self.n


@pytest.mark.parametrize("method,tol", [("exact", 1e-12), ("ode", TOL)])
def test_orbit_apsides_crossings_perimeter(method, tol):
    r, _ = solve(ORBIT.format(method=method))
    o = Orbit()
    e = entry(r, 0)                                  # slowest: the apogee, half a period
    assert e["t"] == pytest.approx(float(o.P / 2), rel=tol)
    assert e["at_end"] is False
    assert (e["x"][0] ** 2 + e["x"][1] ** 2) ** 0.5 == pytest.approx(float(o.a * (1 + o.e)), rel=tol)
    assert e["distance"] == pytest.approx(float(o.perimeter / 2), rel=max(tol, 1e-10))
    e = entry(r, 1)                                  # fastest after t = 1: the perigee, one period
    assert e["t"] == pytest.approx(float(o.P), rel=tol)
    assert e["distance"] == pytest.approx(float(o.perimeter), rel=max(tol, 1e-10))
    assert entry(r, 2)["t"] == pytest.approx(float(o.P / 2), rel=tol)     # x.1 = 0 held at the start
    assert entry(r, 3)["t"] == pytest.approx(float(o.P), rel=tol)
    t_x0 = o.t_of_E(mp.acos(o.e))                    # x = a (cos E − e) = 0
    assert entry(r, 4)["t"] == pytest.approx(float(t_x0), rel=tol)
    e = entry(r, 5)                                  # V has no reported rate: Brent's minimiser, t to ~√eps
    assert e["t"] == pytest.approx(float(o.P / 2), rel=1e-7)
    assert e["V"] == pytest.approx(float(-1 / (o.a * (1 + o.e))), rel=tol)
    assert entry(r, 6)["t"] == pytest.approx(float(o.P + t_x0), rel=tol)


@pytest.mark.parametrize("rtol", [1e-8, 1e-10])
def test_a_backward_dip_inside_one_step_is_not_stepped_over(rtol):
    # F = sin(2π t) on m = 1 from v0 = −ε (ε = 1e-5): v = −ε + (1 − cos 2πt)/(2π) is negative only for
    # |t − 1| < 1.8e-3 s, so x.0 steps back by ~2e-8 m inside one ODE step (~0.05 s), the rate positive at
    # both of its ends. The level X halfway through that dip is crossed up, down (t ≈ 1) and up again.
    # Before, the step ends' samples and rates saw one crossing only ("not reached" for the others, exit 0);
    # now the extremes of the step's polynomial are breaks. Reference: the closed form in mpmath (30 digits).
    with mp.workdps(30):
        eps, w = mp.mpf("1e-5"), 2 * mp.pi
        x = lambda t: -eps * t + (t - mp.sin(w * t) / w) / w          # noqa: E731
        v = lambda t: -eps + (1 - mp.cos(w * t)) / w                  # noqa: E731
        r1, r2 = mp.findroot(v, 0.999), mp.findroot(v, 1.001)
        X = (x(r1) + x(r2)) / 2
        ups = [mp.findroot(lambda t: x(t) - X, (mp.mpf("0.9"), r1), solver="anderson"),
               mp.findroot(lambda t: x(t) - X, (r2, mp.mpf("1.1")), solver="anderson")]
        down = mp.findroot(lambda t: x(t) - X, (r1, r2), solver="anderson")
        want = [(float(t), float(abs(v(t)))) for t in (ups[0], down, ups[1])]
    R, _ = solve(f"""
type: particle
m: 1
x0: [0, 0, 0]
v0: [-1.0e-5, 0, 0]
forces:
  - {{kind: custom, F: ["sin(2*pi*t)", "0", "0"]}}
t_end: 1.5
find:
  - {{when: {{x.0: {float(X)!r}}}}}
  - {{when: {{x.0: {float(X)!r}}}, direction: down}}
  - {{when: {{x.0: {float(X)!r}}}, occurrence: 3}}
accuracy: {{rtol: {rtol!r}}}
""")
    for k, (t, speed) in enumerate(want):
        # a crossing's time is off by the error of x (the route's, relative to x ~ 0.16 m) over |v| there
        assert abs(entry(R, k)["t"] - t) * speed <= ode(rtol) * 0.16 + 1e-15, k


@pytest.mark.parametrize("method", ["DOP853", "RK45"])
def test_least_kinetic_energy_of_a_block_that_sticks_is_at_the_stop(method):
    # a block (m = 2 kg, v0 = 10 m/s) slides with Coulomb friction μN = 9.81 N and sticks at
    # t_s = v0 m/(μN) = 20/9.81 s. T is 0 from t_s on; the stop itself carries the rounding of the
    # phase before it (T ~ 3e-30 J). Before, DOP853 reported min T at the end (t = 5 s, at_end true).
    t_s = float(mp.mpf(20) / G)
    R, _ = solve(f"""
type: particle
m: 2
v0: [10, 0, 0]
forces: [{{kind: friction, mu: 0.5, N: 19.62}}]
t_end: 5
accuracy: {{method: {method}, rtol: 1e-10}}
find: [{{min: T}}, {{min: T, within: [1, 4]}}, {{max: x.0}}, {{when: {{T: 0}}}}]
""")
    for k in range(4):
        e = entry(R, k)
        assert e["t"] == pytest.approx(t_s, rel=TOL), k
        assert e["at_end"] in (False, None), k
        assert e["x"][0] == pytest.approx(float(mp.mpf(100) / G), rel=TOL), k


def test_a_time_before_the_start_says_so():
    # before: "not reached between t = 0 and t = 2 s; raise t_end to search further"
    R, warns = solve("""
type: particle
m: 1
v0: [1, 0, 0]
forces: [{kind: gravity}]
t_end: 2
find: [{t: -1}]
""")
    assert R["find"][0]["reached"] is False
    assert any("find.0: t = -1 s is before the start of the motion (t = 0 s)" in w for w in warns), warns
