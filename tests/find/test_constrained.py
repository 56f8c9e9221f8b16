"""``find`` in ``constrained-particle``: a bead on a fixed vertical hoop released from rest at q0,
on the energy quadrature and on the ODE, against the elliptic closed form (mpmath).

q from the lowest point, R the hoop's radius, ω = √(g/R), k = sin(q0/2), m = k²:
sin(q/2) = k sn(K(m) − ωt | m), so q passes 0 at T/4 = K/ω, turns at −q0 at T/2 and is back at
q0 at T; a level q is passed at t = (K − F(asin(sin(q/2)/k) | m))/ω.  The normal force is largest
at the bottom, N = m g (3 − 2 cos q0), and smallest at the turning points, m g cos q0 (at the
release and at T/2: equal minima, the first reported).  The arc length is R Σ|Δq|.  Both routes
run at accuracy.rtol = 1e-10 and are held to ``tolerances.ode(rtol)``.
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.tolerances import ode

from .refs import entry, solve

MPMATH_DPS = 30
TOL = ode(1e-10)
R, Q0, G, MASS = mp.mpf("0.5"), mp.mpf(1), mp.mpf("9.81"), mp.mpf("0.1")

BEAD = """
type: constrained-particle
params: {{R: 0.5}}
m: 0.1
curve: {{x1: "R*sin(q)", x2: 0, x3: "-R*cos(q)"}}
q_range: [-pi, pi]
q0: 1
forces: [{{kind: gravity}}]
t_end: 2
accuracy: {{method: {method}, rtol: 1e-10}}
find:
  - {{min: q}}
  - {{max: q, within: [0.1, 2]}}
  - {{when: {{q: 0}}}}
  - {{when: {{q: 0}}, direction: up}}
  - {{max: N.1}}
  - {{min: N.1}}
  - {{when: {{q_dot: 0}}}}
  - {{when: {{distance: 1.5}}}}
  - {{when: {{q: 0.5}}, occurrence: 3}}
  - {{t: 2}}
"""


def t_at(q):
    """The first time the bead released at q0 passes the level q (|q| < q0), by the closed form."""
    m = mp.sin(Q0 / 2) ** 2
    u = mp.ellipf(mp.asin(mp.sin(mp.mpf(q) / 2) / mp.sqrt(m)), m)
    return (mp.ellipk(m) - u) / mp.sqrt(G / R)


def q_at(t):
    m = mp.sin(Q0 / 2) ** 2
    return 2 * mp.asin(mp.sqrt(m) * mp.ellipfun("sn", mp.ellipk(m) - mp.sqrt(G / R) * t, m=m))


@pytest.mark.parametrize("method", ["quadrature", "ode"])
def test_bead_on_a_hoop(method):
    r, _ = solve(BEAD.format(method=method))
    T = 4 * mp.ellipk(mp.sin(Q0 / 2) ** 2) / mp.sqrt(G / R)
    if method == "quadrature":
        assert r["period"] == pytest.approx(float(T), rel=TOL)
    for k, t, q in ((0, T / 2, -1), (1, T, 1), (2, T / 4, 0), (3, 3 * T / 4, 0), (6, T / 2, -1), (7, 3 * T / 4, 0)):
        e = entry(r, k)
        assert e["t"] == pytest.approx(float(t), rel=TOL), k
        assert e["q"] == pytest.approx(q, abs=TOL), k
    assert entry(r, 0)["at_end"] is False and entry(r, 1)["at_end"] is False
    e = entry(r, 4)                                  # the bottom
    assert e["t"] == pytest.approx(float(T / 4), rel=TOL)
    assert e["N"][1] == pytest.approx(float(MASS * G * (3 - 2 * mp.cos(Q0))), rel=TOL)
    e = entry(r, 5)                                  # equal minima at the release and at T/2: the first
    assert (e["t"], e["at_end"]) == (0.0, True)
    assert e["N"][1] == pytest.approx(float(MASS * G * mp.cos(Q0)), rel=TOL)
    assert entry(r, 7)["distance"] == pytest.approx(1.5, rel=TOL)
    # q = 0.5 is passed going down at t_at(0.5), up at T − t_at(0.5), down again at T + t_at(0.5)
    assert entry(r, 8)["t"] == pytest.approx(float(T + t_at("0.5")), rel=TOL)
    e = entry(r, 9)
    assert e["q"] == pytest.approx(float(q_at(2)), abs=TOL)
    assert e["distance"] == pytest.approx(float(R * (4 * Q0 + Q0 - q_at(2))), rel=TOL)


def test_least_kinetic_energy_of_a_bead_that_sticks_is_at_the_stop():
    # a bead on a straight horizontal wire (m = 2 kg, q̇0 = 10 m/s) with friction μ = 0.5 stops at
    # t_s = q̇0/(μg) and sticks. Before, min T was reported 1e-6 s late (the first step of the stuck
    # phase: the stop carries the rounding of the sliding phase, T ~ 1e-30 J).
    t_s = float(10 / (mp.mpf("0.5") * G))
    r, _ = solve("""
type: constrained-particle
m: 2
curve: {x1: q, x2: 0, x3: 0}
q_dot0: 10
forces: [{kind: gravity}, {kind: friction, mu: 0.5}]
t_end: 5
accuracy: {rtol: 1e-10}
find: [{min: T}, {min: q_dot}, {max: q}]
""")
    for k in range(3):
        e = entry(r, k)
        assert e["t"] == pytest.approx(t_s, rel=TOL), k
        assert e["at_end"] is False, k
        assert e["q"] == pytest.approx(float(100 / (2 * mp.mpf("0.5") * G)), rel=TOL), k
