"""The example files in problems/impact/, each checked against references
computed independently: exact rational arithmetic (fractions.Fraction) from
the notes' formulas, or mpmath at 50 digits (tests/topics/impact/reference.py)."""

from __future__ import annotations

import math
from fractions import Fraction as Fr

import pytest
from mpmath import mp, mpf

from tests.conftest import PROBLEMS, solve_path
MPMATH_DPS = 50
from tests.topics.impact import reference as ref
from tests.topics.impact.util import assert_close

D = PROBLEMS / "impact"


def one(name):
    recs = solve_path(D / name)
    assert len(recs) == 1
    rec = recs[0]
    assert rec.get("error") is None, rec
    return rec


def test_plastic_23_13():
    # (23.13a,b), (23.17), (23.18) with mA = 2, mB = 3, v0 = 5
    rec = one("plastic-23-13.yaml")
    r = rec["results"]
    mA, mB, v0 = Fr(2), Fr(3), Fr(5)
    v = mA / (mA + mB) * v0
    F = mA * mB / (mA + mB) * v0
    assert r["impact"] is True
    assert_close(r["vA2"], [v, 0, 0], abs_=1e-15)
    assert_close(r["vB2"], [v, 0, 0], abs_=1e-15)
    assert_close(r["impulse"], [-F, 0, 0], abs_=1e-15)            # F̂_A = -F̂ e1 (23.10)
    assert_close(r["T1"], mA * v0 ** 2 / 2)
    assert_close(r["T2"], mA / (mA + mB) * mA * v0 ** 2 / 2)      # (23.17)
    assert_close(r["energy_loss"], mB / (mA + mB) * mA * v0 ** 2 / 2)   # (23.18)
    assert_close(r["G1"], [mA * v0, 0, 0])
    assert_close(r["G2"], [mA * v0, 0, 0])                       # (23.15)
    assert r["separation_speed"] == 0
    assert "23.13" in rec["equations"]
    assert rec["warnings"] == []


def test_oblique_smooth():
    rec = one("oblique-smooth.yaml")
    r = rec["results"]
    mA, mB, e = Fr(1), Fr(2), Fr(4, 5)
    n = [Fr(3, 5), Fr(4, 5), Fr(0)]
    vA1, vB1 = [Fr(4), Fr(0), Fr(0)], [Fr(0)] * 3
    a = sum((x - y) * c for x, y, c in zip(vA1, vB1, n))
    ms = mA * mB / (mA + mB)
    F = [-ms * (1 + e) * a * c for c in n]                        # (28.13)
    vA2 = [x + f / mA for x, f in zip(vA1, F)]                    # (28.5)
    vB2 = [x - f / mB for x, f in zip(vB1, F)]
    assert_close(r["impulse"], F, rel=4e-16, abs_=1e-16)
    assert_close(r["vA2"], vA2, rel=4e-16, abs_=1e-16)
    assert_close(r["vB2"], vB2, rel=4e-16, abs_=1e-16)
    assert_close(r["m_star"], ms)
    assert_close(r["approach_speed"], a)
    assert_close(r["separation_speed"], e * a)                    # (28.7)
    assert_close(r["energy_loss"], (1 - e * e) * ms * a * a / 2, rel=1e-15)   # (28.16)
    T2 = (mA * sum(x * x for x in vA2) + mB * sum(x * x for x in vB2)) / 2
    assert_close(r["T2"], T2)
    assert_close(r["G2"], [mA * x + mB * y for x, y in zip(vA1, vB1)], abs_=1e-15)


@pytest.mark.parametrize("name, phi, admissible", [("rough-admissible.yaml", 0.2, True),
                                                   ("rough-inadmissible.yaml", 1.0, False)])
def test_rough(name, phi, admissible):
    rec = one(name)
    r = rec["results"]
    R = ref.impact(1.0, 2.0, [3.0, 1.0, 0.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], eta=0.5, phi=phi)
    for k in ("vA2", "vB2", "impulse"):
        assert_close(r[k], R[k], rel=1e-15, abs_=2e-15, what=k)
    for k in ("energy_loss", "separation_speed", "theta", "phi1", "phi2", "T1", "T2"):
        assert_close(r[k], R[k], rel=1e-15, abs_=2e-15, what=k)
    # the closed forms the example's comment quotes
    assert_close(r["theta"], math.atan(1 / 3))
    assert_close(r["phi1"], -math.atan(0.5))
    assert_close(r["phi2"], math.pi / 4)
    assert r["admissible"] is admissible
    for k in ("P1", "P2", "P3", "P4"):
        assert r[k] == R[k], k
    assert all(r[k] for k in ("P1", "P2", "P3", "P4")) is admissible
    if not admissible:
        assert r["P3"] is False and r["separation_speed"] < 0
        assert any("admissible" in w for w in rec["warnings"])


def test_wall():
    rec = one("wall.yaml")
    r = rec["results"]
    mA, e = Fr(1, 2), Fr(3, 5)
    vA1 = [Fr(3), Fr(-4), Fr(0)]
    n = [0, -1, 0]
    a = sum(x * c for x, c in zip(vA1, n))                        # B at rest
    vA2 = [vA1[0], -e * vA1[1], 0]                                # (28.10) with mB -> inf, (28.12)
    assert r["m_star"] == 0.5
    assert_close(r["vA2"], vA2, abs_=1e-16)
    assert r["vB2"] == [0.0, 0.0, 0.0]
    assert_close(r["impulse"], [mA * (v2 - v1) for v1, v2 in zip(vA1, vA2)], abs_=1e-16)
    assert_close(r["energy_loss"], (1 - e * e) * mA * a * a / 2)
    for k in ("T1", "T2", "G1", "G2"):
        assert r[k] is None
    assert any("infinite" in w for w in rec["warnings"])


def test_four_particles():
    rec = one("four-particles.yaml")
    r = rec["results"]
    ps = [(1, (1, 0, 0), (0, 1, 0)), (2, (0, 1, 0), (1, 0, 0)), (3, (0, 0, 1), (0, 0, 2)), (4, (1, 1, 1), (-1, 0, 0))]
    ps = [(Fr(m), [Fr(c) for c in x], [Fr(c) for c in v]) for m, x, v in ps]
    O = [Fr(1), Fr(0), Fr(0)]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    M = sum(m for m, _, _ in ps)
    xb = [sum(m * x[i] for m, x, _ in ps) / M for i in range(3)]
    vb = [sum(m * v[i] for m, _, v in ps) / M for i in range(3)]
    H_O = [sum(cross([x[j] - O[j] for j in range(3)], [m * c for c in v])[i] for m, x, v in ps) for i in range(3)]
    H_c = [sum(cross([x[j] - xb[j] for j in range(3)], [m * (v[j] - vb[j]) for j in range(3)])[i] for m, x, v in ps) for i in range(3)]
    T = sum(m * sum(c * c for c in v) for m, _, v in ps) / 2
    Tc = M * sum(c * c for c in vb) / 2
    assert_close(r["mass"], M)
    assert_close(r["com"], xb)
    assert_close(r["v_com"], vb)
    assert_close(r["G"], [M * c for c in vb])
    assert_close(r["H_O"], H_O, abs_=1e-15)
    assert_close(r["H_com"], H_c, rel=4e-15)
    # (25.7) with B at the center of mass
    via = cross([xb[j] - O[j] for j in range(3)], [M * c for c in vb])
    assert_close(r["H_O"], [via[i] + H_c[i] for i in range(3)], abs_=1e-15)
    assert_close(r["T"], T)
    assert_close(r["T_com"], Tc)
    assert_close(r["T_rel"], T - Tc, rel=4e-15)                 # (27.8)


def test_struck_bar():
    rec = one("struck-bar.yaml")
    r = rec["results"]
    mp.dps = 50
    m, k2, R, h = mpf(3), mpf(0.12), mpf(6), mpf(0.6)   # k² from the float sqrt(0.12)
    k = mpf(math.sqrt(0.12))
    k2 = k * k
    I = m * k2
    assert_close(r["v2"], [R / m, 0, 0])                                  # (33.5)
    assert_close(r["omega2"], [0, 0, h * R / I])                          # (33.8)
    assert_close(r["percussion"], [0, k2 / h, 0])                         # (33.10)
    assert_close(r["omega2"], [0, 0, 10], rel=1e-14)
    assert_close(r["percussion"], [0, 0.2, 0], rel=1e-14)
    # the percussion point has zero velocity: v̄ + ω × p = 0 (33.9)
    w, p2 = r["omega2"][2], r["percussion"][1]
    assert abs(r["v2"][0] - w * p2) < 1e-14
