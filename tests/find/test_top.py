"""``find`` in ``top`` and ``gyroscope`` against the energy integrals in mpmath.

Top (notes §38): with u = cos θ, u̇² = f(u) = (α − βu)(1 − u²) − (b − au)², a = I33 ω3/I11,
b = H_e3/I11, α = 2(E − ½I33ω3²)/I11, β = 2mgL/I11; θ_min, θ_max from the roots of the cubic
f (mpmath.polyroots), the time between them ∫ du/√f (mpmath.quad), the precession rate
ψ̇ = (b − au)/(1 − u²).  Gyroscope (§37): θ̇² = [(I1 − I2) q² sin θ + 2 I1 p q] sin θ / I2, the
time from θ = 0 to θ by ∫ dθ/θ̇.  Both routes are exact (the integrals' own quadratures): times
to 1e-9 relative, angles to 1e-12.
"""

from __future__ import annotations

import mpmath as mp
import pytest

from .refs import entry, solve

MPMATH_DPS = 30
T_REL, A_REL = 1e-9, 1e-12

TOP = """
type: top
m: 0.5
L: 0.05
I11: 2.0e-3
I33: 1.0e-3
theta: 0.5
phi_dot: 100
t_end: 0.2
find:
  - {max: theta}
  - {min: theta, within: [0.01, 0.2]}
  - {when: {theta: 0.52}}
  - {when: {theta_dot: 0}}
  - {max: psi_dot}
  - {when: {theta: 0.52}, direction: up, occurrence: 2}
"""


def test_top_nutation():
    r, _ = solve(TOP)
    m, L, I1, I3, th0, w3, g = (mp.mpf(x) for x in ("0.5", "0.05", "2e-3", "1e-3", "0.5", "100", "9.81"))
    u0 = mp.cos(th0)
    a, b = I3 * w3 / I1, I3 * w3 * u0 / I1
    beta = 2 * m * g * L / I1
    alpha = beta * u0                                # E − ½I33ω3² = mgL cos θ0 (released with θ̇ = ψ̇ = 0)
    # f(u) = (α − βu)(1 − u²) − (b − au)² = βu³ − (α + a²)u² + (2ab − β)u + α − b²
    roots = mp.polyroots([beta, -(alpha + a**2), 2 * a * b - beta, alpha - b**2], maxsteps=200, extraprec=60)
    real = sorted(x.real for x in roots if abs(x.imag) < 1e-20)
    u1 = max(x for x in real if -1 < x < u0 - mp.mpf("1e-20"))
    u3 = max(real)                                   # the root beyond u = 1
    assert u3 > 1 and abs(beta * u0**3 - (alpha + a**2) * u0**2 + (2 * a * b - beta) * u0 + alpha - b**2) < 1e-25
    f = lambda u: beta * (u - u1) * (u0 - u) * (u3 - u)      # noqa: E731  (factored: positive between the roots)
    half = mp.quad(lambda u: 1 / mp.sqrt(f(u)), [u1, u0])
    assert float(mp.acos(u1)) == pytest.approx(r["theta_max"], rel=A_REL)
    for k in (0, 3):
        assert entry(r, k)["t"] == pytest.approx(float(half), rel=T_REL), k
    assert entry(r, 4)["t"] == pytest.approx(float(half), rel=1e-7)     # ψ̇ has no reported rate: Brent's minimiser
    assert entry(r, 0)["theta"] == pytest.approx(float(mp.acos(u1)), rel=A_REL)
    assert entry(r, 4)["psi_dot"] == pytest.approx(float((b - a * u1) / (1 - u1**2)), rel=1e-9)
    e = entry(r, 1)                                  # back at θ0 after a whole nutation
    assert e["t"] == pytest.approx(float(2 * half), rel=T_REL)
    assert e["at_end"] is False
    u52 = mp.cos(mp.mpf("0.52"))
    t52 = mp.quad(lambda u: 1 / mp.sqrt(f(u)), [u52, u0])
    assert entry(r, 2)["t"] == pytest.approx(float(t52), rel=T_REL)
    assert entry(r, 5)["t"] == pytest.approx(float(2 * half + t52), rel=T_REL)


GYRO = """
type: gyroscope
I1: 0.01
I2: 0.006
p: 100
q: 1
t_end: 0.5
find:
  - {max: theta}
  - {when: {theta: "pi/2"}}
  - {when: {theta_dot: 0}}
  - {min: theta, within: [0.1, 0.7]}
  - {max: theta_dot}
"""


def test_gyroscope_zero_to_pi():
    r, _ = solve(GYRO)
    I1, I2, p, q = mp.mpf("0.01"), mp.mpf("0.006"), mp.mpf(100), mp.mpf(1)
    rate = lambda th: mp.sqrt(((I1 - I2) * q**2 * mp.sin(th) + 2 * I1 * p * q) * mp.sin(th) / I2)   # noqa: E731
    t_of = lambda th: mp.quad(lambda x: 1 / rate(x), [0, th])        # noqa: E731
    T = t_of(mp.pi)
    for k in (0, 2):                                 # θ̇ = 0 held at the start: reached again at θ = π
        assert entry(r, k)["t"] == pytest.approx(float(T), rel=T_REL)
        assert entry(r, k)["theta"] == pytest.approx(float(mp.pi), rel=A_REL)
    assert entry(r, 1)["t"] == pytest.approx(float(t_of(mp.pi / 2)), rel=T_REL)
    e = entry(r, 3)                                  # back at θ = 0 after 2T (the motion extended to 0.7)
    assert e["t"] == pytest.approx(float(2 * T), rel=T_REL)
    th = mp.findroot(lambda x: mp.diff(lambda y: rate(y) ** 2, x), 1.6)   # the largest θ̇²
    e = entry(r, 4)
    assert e["theta_dot"] == pytest.approx(float(rate(th)), rel=1e-9)
    assert e["t"] == pytest.approx(float(t_of(th)), rel=1e-7)
