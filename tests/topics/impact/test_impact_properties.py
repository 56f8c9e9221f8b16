"""Property tests (hypothesis) over random masses, velocities, normals and
0 <= e, eta <= 1: momentum conserved, energy never created, separation after
impact, the e-relation (28.7), eta along f (28.28), admissibility (28.53)
agrees with P1-P4 (28.22), and agreement with the 50-digit reference."""

from __future__ import annotations

import math

from hypothesis import assume, given, settings, strategies as st

MPMATH_DPS = 50
from tests.topics.impact import reference as ref
from tests.topics.impact.util import EPS, assert_close, run_impact, vnorm

# components below 1e-12 are snapped to 0: such values make the approach speed a
# rounding-level number that a finite-precision reference cannot decide (grazing
# incidence has its own tests in test_impact_extremes.py)
coord = st.floats(-10, 10, allow_nan=False, allow_infinity=False).map(lambda x: 0.0 if abs(x) < 1e-12 else x)
vec = st.tuples(coord, coord, coord)
mass = st.floats(-8, 8).map(lambda x: 10.0 ** x)   # mass ratios up to 1e16
unit01 = st.floats(0, 1)
SETTINGS = settings(max_examples=200, deadline=None)


def _normal(v):
    assume(vnorm(v) > 1e-3)
    return list(v)


def _dot(a, b):
    return math.fsum(x * y for x, y in zip(a, b))


@SETTINGS
@given(mA=mass, mB=mass, vA1=vec, vB1=vec, n=vec, e=unit01)
def test_smooth(mA, mB, vA1, vB1, n, e):
    n = _normal(n)
    r, warns = run_impact(mA=mA, mB=mB, vA1=list(vA1), vB1=list(vB1), n=n, e=e)
    vs = max(vnorm(vA1), vnorm(vB1), 1e-300)
    gs = mA * vnorm(vA1) + mB * vnorm(vB1)
    # momentum (28.6)
    assert_close(r["G2"], r["G1"], rel=0, abs_=16 * EPS * gs + 1e-300, what="G")
    # energy never created (28.19); the reduced-mass loss agrees with T1 - T2
    assert r["energy_loss"] >= 0
    assert r["T1"] - r["T2"] >= -16 * EPS * r["T1"]
    assert abs((r["T1"] - r["T2"]) - r["energy_loss"]) <= 32 * EPS * r["T1"] + 1e-300
    if r["impact"]:
        # separation (P3) and the e-relation (28.7)
        assert r["separation_speed"] >= 0
        assert abs(r["separation_speed"] - e * r["approach_speed"]) <= 8 * EPS * vs
        # recompute the e-relation from the velocities themselves
        nu = [c / vnorm(n) for c in n]
        sep = _dot([b - a for a, b in zip(r["vA2"], r["vB2"])], nu)
        assert abs(sep - e * r["approach_speed"]) <= 32 * EPS * vs
        # the impulse is normal (28.11) and equals mA (vA2 - vA1) (28.4a)
        R = ref.impact(mA, mB, vA1, vB1, n, e=e)
        for k in ("vA2", "vB2"):
            assert_close(r[k], R[k], rel=0, abs_=16 * EPS * vs, what=k)
        assert_close(r["impulse"], R["impulse"], rel=4e-15, abs_=1e-300, what="impulse")
        assert_close(r["energy_loss"], R["energy_loss"], rel=4e-15, abs_=1e-300, what="loss")
    else:
        assert r["vA2"] == list(vA1) and r["vB2"] == list(vB1)
        assert any("do not approach" in w for w in warns)


@SETTINGS
@given(mA=mass, mB=mass, vA1=vec, vB1=vec, n=vec, eta=unit01, phi=st.floats(-math.pi / 2, math.pi / 2))
def test_general(mA, mB, vA1, vB1, n, eta, phi):
    n = _normal(n)
    nu = [c / vnorm(n) for c in n]
    dv1 = [a - b for a, b in zip(vA1, vB1)]
    a = _dot(dv1, nu)
    tang = vnorm([d - a * c for d, c in zip(dv1, nu)])
    assume(tang > 1e-6 * vnorm(dv1))          # t defined by Δv1 (the parallel case is tested elsewhere)
    r, warns = run_impact(mA=mA, mB=mB, vA1=list(vA1), vB1=list(vB1), n=n, eta=eta, phi=phi)
    vs = max(vnorm(vA1), vnorm(vB1))
    gs = mA * vnorm(vA1) + mB * vnorm(vB1)
    assert_close(r["G2"], r["G1"], rel=0, abs_=16 * EPS * gs, what="G")
    assert r["energy_loss"] >= 0 and r["P4"]
    assert r["T1"] - r["T2"] >= -16 * EPS * r["T1"]
    if not r["impact"]:
        assert r["admissible"] is None
        return
    R = ref.impact(mA, mB, vA1, vB1, n, eta=eta, phi=phi)
    for k in ("vA2", "vB2"):
        assert_close(r[k], R[k], rel=0, abs_=32 * EPS * vs, what=k)
    assert_close(r["impulse"], R["impulse"], rel=0, abs_=32 * EPS * float(R["m_star"]) * vnorm(dv1), what="impulse")
    for k in ("theta", "phi1", "phi2"):
        # (28.50) evaluated as printed (arccos) at 50 digits
        assert abs(r[k] - float(R[k])) <= 1e-13, k
    # eta is the ratio of separation to approach along f (28.28)
    f = [-(math.cos(phi) * x + math.sin(phi) * y) for x, y in zip(nu, r["t"])]
    dv2 = [p - q for p, q in zip(r["vA2"], r["vB2"])]
    s1 = -_dot(f, dv1)
    if abs(s1) > 1e-6 * vnorm(dv1):
        assert abs(_dot(f, dv2) - eta * s1) <= 64 * EPS * vs
    # admissibility (28.53) agrees with the four restrictions (28.22) away from the boundaries
    margin = 1e-9
    if min(abs(phi - r["phi1"]), abs(phi - r["phi2"])) > margin:
        allP = r["P1"] and r["P2"] and r["P3"] and r["P4"]
        assert allP == r["admissible"], (r["phi1"], phi, r["phi2"], [r[k] for k in ("P1", "P2", "P3", "P4")])
        assert r["admissible"] == (phi >= float(R["phi1"]) and phi <= float(R["phi2"]))
        for k in ("P1", "P2", "P3"):
            # P2 is the sign of -F.n = |F| cos(phi): at |phi| = pi/2 it is a
            # round-off-sized number whose sign is not defined in floats
            if k == "P2" and abs(abs(phi) - math.pi / 2) <= margin:
                continue
            assert r[k] == R[k], k
        if r["admissible"]:
            assert r["separation_speed"] >= 0
    # theta itself is always admissible (28.52)
    assert r["phi1"] <= r["theta"] <= r["phi2"]


@settings(max_examples=60, deadline=None)
@given(theta=st.floats(0, math.pi / 2 - 1e-9), eta=unit01)
def test_bounds_match_28_50(theta, eta):
    """The cancellation-free bounds agree with (28.50) as printed, and make
    F(theta, phi) of (28.42f) vanish."""
    from mpmath import mpf, mp

    from dyncli.topics.impact.solver import admissible_bounds

    p1, p2 = admissible_bounds(theta, eta)
    r1, r2 = ref.bounds_28_50(theta, eta)
    assert abs(p1 - float(r1)) <= 4 * EPS
    assert abs(p2 - float(r2)) <= 4 * EPS
    T, H = mpf(theta), mpf(eta)
    for ph in (r1, r2):
        F = (1 + H) * mp.cos(ph - T) * mp.cos(ph) - mp.cos(T)             # (28.42f)
        assert abs(F) < mpf(10) ** -40
