"""Exact inputs keep exact answers (issue 16): the regime of a vibration is
decided exactly, with each given number allowed 4 round-offs (2⁻⁵¹ relative;
docs/expressions.md "Exact inputs and boundaries").

Expected classes come from 50-digit mpmath (the relative distance of c from
2√(km) of the given doubles), the critical response from (17.23) in mpmath.
"""

from __future__ import annotations

import math
from decimal import Decimal

import mpmath as mp
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncli import registry
from dyncli.result import SolveOptions
from tests.conftest import solve_one_text

RULE = 2.0 ** -51
U = 2.0 ** -53
Vibration = registry.model_class("vibration")
solve = registry.solver("vibration")


def _solve(**data):
    model = Vibration.model_validate({"type": "vibration", **data}, context={"params": {}})
    return solve(model, SolveOptions()).results


def _expected(k, m, c):
    """Class of the given doubles under the rule, or None within 0.1 u of its edge."""
    with mp.workdps(50):
        d = mp.mpf(c) / (2 * mp.sqrt(mp.mpf(k) * mp.mpf(m))) - 1
        if abs(abs(d) - RULE) < 0.1 * U:
            return None
        return "critical" if abs(d) <= RULE else "underdamped" if d < 0 else "overdamped"


def _assert_critical(r):
    assert r["regime"] == "critical", r["regime"]
    assert r["zeta"] == 1.0 and r["omega_d"] == 0.0
    assert r.get("A") is None and r.get("phi") is None


# decimals with few digits: 1 to 3 significant digits, exponents -2..2
decimal = st.builds(lambda n, e: Decimal(n).scaleb(e), st.integers(1, 999), st.integers(-4, 2))


def test_issue_regression_m2_k50_c20():
    r = _solve(m=2, k=50, c=20, x0=0.1, at=[0.0, 0.5, 2.0])
    _assert_critical(r)
    # (17.23): w = (w0 + (v0 + ωₙ w0) t) e^{-ωₙ t}, ωₙ = 5
    with mp.workdps(30):
        for t, x in zip([0.0, 0.5, 2.0], r["x"]):
            ref = (mp.mpf("0.1") * (1 + 5 * mp.mpf(t))) * mp.exp(-5 * mp.mpf(t))
            assert abs(x - ref) <= 4 * U * 0.1, (t, x, ref)


def test_integer_grid_all_critical():
    """The issue's grid: every integer k, m in 1..39 with c = 2√(km) computed
    as a double (four common spellings of it)."""
    for k in range(1, 40):
        for m in range(1, 40):
            for c in (2 * math.sqrt(k * m), math.sqrt(4 * k * m), 2 * math.sqrt(k) * math.sqrt(m),
                      2 * m * math.sqrt(k / m)):
                r = _solve(m=m, k=k, c=c)
                assert r["regime"] == "critical" and r["omega_d"] == 0.0 and r["A"] is None, (k, m, c)


@settings(max_examples=60, deadline=None)
@given(a=decimal, b=decimal)
def test_decimal_perfect_squares_given_as_numbers(a, b):
    """k = a·b², m = a (short decimals), c = 2ab: critical in exact decimals;
    the doubles differ from them by ≤ 2 round-offs."""
    k, m, c = a * b * b, a, 2 * a * b
    r = solve_one_text(f"type: vibration\nm: {m}\nk: {k}\nc: {c}\nx0: 0.01\n")["results"]
    _assert_critical(r)


@settings(max_examples=60, deadline=None)
@given(k=decimal, m=decimal, form=st.sampled_from(["2*sqrt(k*m)", "sqrt(4*k*m)", "2*sqrt(k)*sqrt(m)",
                                                   "2*m*sqrt(k/m)", "2*(k*m)**0.5"]))
def test_expression_critical_damping(k, m, form):
    text = f"type: vibration\nparams: {{k: {k}, m: {m}}}\nm: m\nk: k\nc: {form}\nx0: 0.01\nv0: -1\nat: [0, 1]\n"
    rec = solve_one_text(text)
    r = rec["results"]
    _assert_critical(r)
    assert "17.23" in rec["equations"]
    # the response is (17.23) with ωₙ = √(k/m) of the given doubles
    with mp.workdps(40):
        wn = mp.sqrt(mp.mpf(float(k)) / mp.mpf(float(m)))
        w0, v0 = mp.mpf(0.01), mp.mpf(-1)
        ref = (w0 + (v0 + wn * w0)) * mp.exp(-wn)
        scale = max(abs(w0), abs(v0) / wn)
        assert abs(r["x"][1] - ref) <= 1e-14 * scale


def test_zeta_one_and_its_neighbours():
    _assert_critical(_solve(m=1, k=1, zeta=1, x0=1))
    _assert_critical(_solve(m=3, k=7, zeta=math.nextafter(1.0, 0.0)))     # within the rule
    assert _solve(m=1, k=1, zeta=1 - 1e-15)["regime"] == "underdamped"
    assert _solve(m=1, k=1, zeta=1 + 1e-15)["regime"] == "overdamped"


@settings(max_examples=80, deadline=None)
@given(k=decimal, m=decimal, rel=st.sampled_from([-8, -5, -3, -1, 0, 1, 3, 5, 8, -1e3, 1e3]))
def test_near_critical_classified_by_the_rule(k, m, rel):
    """c = 2√(km)(1 + rel·u), rounded: within 4 u → critical, beyond → by side."""
    kf, mf = float(k), float(m)
    with mp.workdps(50):
        c = float(2 * mp.sqrt(mp.mpf(kf) * mp.mpf(mf)) * (1 + rel * mp.mpf(U)))
    want = _expected(kf, mf, c)
    if want is None:
        return
    r = _solve(m=mf, k=kf, c=c)
    assert r["regime"] == want, (kf, mf, c, rel)
    if want == "underdamped":
        assert r["zeta"] < 1.0 and r["omega_d"] > 0
    elif want == "overdamped":
        assert r["zeta"] > 1.0 and r["omega_d"] > 0
    else:
        _assert_critical(r)


def test_undamped_resonance_given_as_expression():
    """ω = √k/√m (1 ulp from the solver's √(k/m)) is exact resonance: G, g null."""
    for k, m in ((3, 7), (2, 3), (10, 0.3)):
        text = (f"type: vibration\nparams: {{k: {k}, m: {m}}}\nm: m\nk: k\n"
                "base: {amplitude: 0.01, omega: sqrt(k)/sqrt(m)}\n")
        r = solve_one_text(text)["results"]
        assert r["r"] == 1.0 and r["G"] is None and r["g"] is None


@pytest.mark.parametrize("zeta", ["1/sqrt(2)", "sqrt(2)/2", "sqrt(0.5)"])
def test_peak_boundary_zeta_one_over_root_two(zeta):
    """ζ = 1/√2 is the edge where G loses its peak (either neighbouring double)."""
    r = solve_one_text(f"type: vibration\nm: 1\nk: 1\nzeta: {zeta}\nsweep: {{ratio: [0, 3]}}\n")["results"]
    assert r["peak_G"] is None and r["peak_G_r"] is None
    assert r["peak_g"] is not None


def test_peak_boundary_from_c():
    # c² = 2km exactly: ζ = 1/√2
    r = _solve(m=1, k=2, c=2, sweep={"ratio": [0, 3]})
    assert r["peak_G"] is None
    # just inside: a real, far-out peak r = 1/√(1 − 2ζ²)
    z = 0.7
    r = _solve(m=1, k=1, zeta=z, sweep={"ratio": [0, 3]})
    assert r["peak_G_r"] == pytest.approx(1 / math.sqrt(1 - 2 * z * z), rel=4 * U)


def test_force_excitation_at_exact_resonance_uses_the_same_rule():
    """ω written as sqrt(k)/sqrt(m) (1 ulp from √(k/m)) is exact resonance for a force too."""
    from tests.conftest import solve_one_text

    R = solve_one_text("""
type: vibration
params: {k: 50, m: 2}
m: m
k: k
force: {amplitude: 1, omega: "sqrt(k)/sqrt(m)"}
at: [1]
""")["results"]
    assert R["r"] == 1.0 and R["X"] is None and R["magnification"] is None
