"""dyncli.expr.period: the period of an expression in q read from its IR, against sympy's
``periodicity`` (the oracle: sympy in the tests only) and f(q + T) = f(q) at many points; and the
constrained-particle curve given without q_range that the period makes closed (the energy route)."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from dyncli.expr import parse
from dyncli.expr.period import common_period
from tests.conftest import solve_one_text

Q = sp.Symbol("q", real=True)


@pytest.mark.parametrize("texts", [
    ["0.5*sin(q)", "-0.5*cos(q)"], ["cos(2*q)", "sin(3*q)"], ["sin(q/4)"], ["exp(cos(q))*sin(2*q)"],
    ["tan(q)"], ["sin(2*q + 1)/3", "cos(q/2)**2"], ["sqrt(2 + sin(q))", "atan2(sin(q), 2 + cos(q))"],
])
def test_a_period_of_trig_curves(texts):
    exprs = [parse(t, ("q",)) for t in texts]
    T = common_period(exprs, "q")
    assert T is not None
    qs = np.linspace(-7.0, 7.0, 101)
    for e in exprs:
        assert np.allclose(e.evaluate(q=qs + T), e.evaluate(q=qs), rtol=1e-12, atol=1e-12)
    # sympy's least period of each divides it (a whole number of them)
    for e in exprs:
        least = sp.periodicity(e.to_sympy({"q": Q}), Q)
        if least is not None:
            ratio = T / float(least)
            assert abs(ratio - round(ratio)) < 1e-9 and round(ratio) >= 1, (e.text, T, least)


@pytest.mark.parametrize("texts", [["q*sin(q)"], ["q"], ["sin(q)", "q**2"], ["sin(q**2)"], ["0"],
                                   ["sin(1.1*q)", "sin(q)"], ["exp(q)*cos(q)"]])
def test_no_period(texts):
    assert common_period([parse(t, ("q",)) for t in texts], "q") is None


HOOP = """
type: constrained-particle
m: 0.1
curve: {x1: "0.5*sin(q)", x2: 0, x3: "-0.5*cos(q)"}
q0: 1
forces: [{kind: gravity}]
at: [0, 0.5]
"""


def test_a_bead_on_a_hoop_without_q_range_takes_the_energy_route():
    # the hoop's coordinates repeat every 2π: a closed curve, so the energy integral gives the
    # motion by quadrature with its period 4 √(R/g) K(sin²(q0/2)) (mpmath), as with q_range given
    rec = solve_one_text(HOOP)
    assert rec["method"] == "quadrature"
    R, g = mp.mpf("0.5"), mp.mpf("9.81")
    T = 4 * mp.sqrt(R / g) * mp.ellipk(mp.sin(mp.mpf(1) / 2) ** 2)
    assert abs(rec["results"]["period"] - float(T)) <= 1e-10 * float(T)
    assert [round(e["q"], 12) for e in rec["results"]["equilibria"]] == [round(-math.pi, 12), 0.0]
    with_range = solve_one_text(HOOP + "q_range: [-pi, pi]\n")
    assert rec["results"]["q"] == with_range["results"]["q"]


def test_an_open_curve_keeps_the_ode():
    rec = solve_one_text(HOOP.replace('x1: "0.5*sin(q)"', 'x1: "0.5*sin(q) + 0.1*q"'))
    assert rec["method"].startswith("ode")
