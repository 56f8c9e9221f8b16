"""Steady precession at p = p_min is decided exactly (issue 16): a p given as
the expression of p_min (38.24) has the double root Ω = √(mgL/a), not
`exists: false` (docs/types/precession.md "Method").  References: 50-digit
mpmath from the given doubles."""

from __future__ import annotations

from decimal import Decimal

import mpmath as mp
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.conftest import solve_one_text

dec = st.builds(lambda n, e: Decimal(n).scaleb(e), st.integers(1, 999), st.integers(-3, 0))
PMIN = "2*sqrt(m*g*L*(I11-I33)*cos(th))/I33"


def _doc(m, L, I33, ratio, th, p):
    return (f"type: precession\nparams: {{m: {m}, L: {L}, I33: {I33}, I11: {I33}*{ratio}, th: {th}}}\n"
            f"m: m\nL: L\nI11: I11\nI33: I33\ntheta: th\np: \"{p}\"\n")


def _omega_double(rec_params):
    m, L, I11, I33, th = (mp.mpf(float(x)) for x in rec_params)
    return mp.sqrt(m * mp.mpf("9.81") * L / ((I11 - I33) * mp.cos(th)))


@settings(max_examples=40, deadline=None)
@given(m=dec, L=dec, I33=dec, ratio=st.sampled_from(["1.5", "2", "3.7", "1.01"]),
       th=st.sampled_from(["0.3", "1", "1.2", "pi/4"]))
def test_p_equal_to_p_min_is_the_double_root(m, L, I33, ratio, th):
    rec = solve_one_text(_doc(m, L, I33, ratio, th, PMIN))
    r = rec["results"]
    assert r["exists"] is True
    with mp.workdps(50):
        thv = mp.pi / 4 if th == "pi/4" else mp.mpf(float(Decimal(th)))
        I33f = float(I33)
        I11f = I33f * float(Decimal(ratio))
        a = (mp.mpf(I11f) - mp.mpf(I33f)) * mp.cos(thv)
        om = mp.sqrt(mp.mpf(float(m)) * mp.mpf("9.81") * mp.mpf(float(L)) / a)
        for k in ("Omega_slow", "Omega_fast"):
            assert abs(r[k] / om - 1) <= 1e-14, (k, r[k], om)


def test_p_just_off_p_min():
    base = _doc("0.5", "0.04", "4e-4", "3", "1", PMIN)
    below = solve_one_text(base.replace(PMIN, f"({PMIN})*(1 - 1e-13)"))["results"]
    above = solve_one_text(base.replace(PMIN, f"({PMIN})*(1 + 1e-13)"))["results"]
    assert below["exists"] is False and below["Omega_slow"] is None
    assert above["exists"] is True
    # two roots split by √(2e-13) relative
    split = above["Omega_fast"] / above["Omega_slow"] - 1
    assert 0.5 * 2 * (2e-13) ** 0.5 < split < 2 * 2 * (2e-13) ** 0.5


def test_gyroscope_equilibria_given_as_expressions():
    """(37.12): θ̈ = 0 at cos θ = 0 and at sin θ = I1 p/((I2 − I1) q); starting
    there at rest, θ_min = θ_max = θ₀ (was a swing π/2 → 5π/2)."""
    import math

    cases = [("0.01", "0.006", "100", "1", "pi/2"), ("0.01", "0.006", "100", "-1", "-pi/2"),
             ("0.01", "0.02", "1", "1", "asin(I1*p/((I2 - I1)*q))"),
             ("0.01", "0.03", "3", "7", "asin(I1*p/((I2 - I1)*q))")]
    for I1, I2, p, q, th in cases:
        text = (f"type: gyroscope\nparams: {{I1: {I1}, I2: {I2}, p: {p}, q: {q}}}\n"
                f"I1: I1\nI2: I2\np: p\nq: q\ntheta0: \"{th}\"\nat: [0, 1]\n")
        r = solve_one_text(text)["results"]
        assert r["theta_min"] == r["theta_max"] == r["theta"][0], (th, r["theta_min"], r["theta_max"])
    # off the equilibrium by 1e-9 rad: a real (small) swing
    r = solve_one_text("type: gyroscope\nI1: 0.01\nI2: 0.006\np: 100\nq: 1\ntheta0: pi/2 - 1e-9\nat: [0]\n")["results"]
    assert r["theta_max"] - r["theta_min"] > 1e-9 and math.isfinite(r["theta_max"])
