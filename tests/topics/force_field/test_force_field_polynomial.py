"""force-field's exact polynomial route (no sympy) against the sympy route as the oracle:
random integer/rational-coefficient fields, conservative ones built from random
potentials and arbitrary (mostly non-conservative) ones, solved both ways; every result
must agree — the formula strings character for character, the verdicts and warnings
exactly, the numbers to rounding.  Also: which expressions are polynomials (the rest
keeps the sympy route), and sympy's printing corner cases."""

from __future__ import annotations

import contextlib
import math
import os
from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dyncli.expr import parse
from dyncli.topics.force_field import polynomial as P
from dyncli.expr import derivative
from dyncli.topics.force_field import polynomial_field
from tests.conftest import solve_one_text

VARS = ("x1", "x2", "x3")
X = [sp.Symbol(n, real=True) for n in VARS]


@contextlib.contextmanager
def sympy_route():
    """Force the sympy route (the oracle): the field's and the path's derivatives."""
    polynomial_field.ENABLED = derivative.ENABLED = False
    try:
        yield
    finally:
        polynomial_field.ENABLED = derivative.ENABLED = True


def _yaml(F, points, path=None):
    text = f"type: force-field\nF: [{', '.join(repr(f) for f in F)}]\npoints: {points!r}\n"
    return text + (f"path: {path}\n" if path else "")


def _both(text):
    new = solve_one_text(text)
    with sympy_route():
        old = solve_one_text(text)
    return new, old


def _close(a, b, what):
    """Numbers to rounding: the sympy route evaluates in floating point, the polynomial route
    exactly then rounds once, so they differ by a few ulp of the terms' magnitudes."""
    if a is None or b is None:
        assert a is b, what
    elif isinstance(a, list):
        assert len(a) == len(b), what
        for u, v in zip(a, b):
            _close(u, v, what)
    else:
        assert math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-9), (what, a, b)


def _assert_same(new, old):
    assert new["method"] == old["method"]
    assert new["equations"] == old["equations"]
    assert new["warnings"] == old["warnings"]
    R, S = new["results"], old["results"]
    assert R.keys() == S.keys()
    for k in R:
        if k in ("work", "work_check") and S[k] is not None:     # quadratures of integrands equal to rounding: within their error estimates
            assert abs(R[k] - S[k]) <= 4 * (R["work_error"] + S["work_error"]) + 1e-12 * (1 + abs(R[k])), (k, R, S)
        elif k == "work_error" and S[k] is not None:
            assert math.isfinite(R[k]) and math.isfinite(S[k])
        elif isinstance(S[k], (float, list)) and k != "curl_formula":
            _close(R[k], S[k], k)
        else:
            assert R[k] == S[k], (k, R[k], S[k])


# -- random polynomial texts ---------------------------------------------------------------

_leaf = st.one_of(st.sampled_from(VARS), st.integers(-9, 9).map(str))


def _grow(children):
    return st.one_of(
        st.tuples(children, st.sampled_from(["+", "-", "*"]), children).map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
        st.tuples(children, st.integers(0, 3)).map(lambda t: f"({t[0]})**{t[1]}"),
        st.tuples(children, st.integers(1, 6)).map(lambda t: f"{t[0]}/{t[1]}"),
        children.map(lambda c: f"-{c}"),
    )


_monomial = st.tuples(st.integers(-12, 12), st.integers(1, 12), st.lists(st.integers(0, 4), min_size=3, max_size=3)).map(
    lambda t: "*".join([f"({t[0]}/{t[1]})"] + [f"{v}**{e}" for v, e in zip(VARS, t[2])]))
_expanded = st.lists(_monomial, min_size=1, max_size=6).map(" + ".join)     # sums of rational monomials
poly_text = st.one_of(st.recursive(_leaf, _grow, max_leaves=7), _expanded)
points = st.lists(st.lists(st.integers(-4, 4).map(lambda k: k / 2), min_size=3, max_size=3), min_size=1, max_size=2)
# 40 examples each (~2 s); DYNCLI_FF_EXAMPLES=3000 for a deep run (as in development: ~6 min)
N_EXAMPLES = int(os.environ.get("DYNCLI_FF_EXAMPLES", "40"))
FAST = settings(max_examples=N_EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _sym(text):
    return parse(text, VARS).to_sympy({n: x for n, x in zip(VARS, X)})


@FAST
@given(V=poly_text, pts=points)
def test_conservative_fields_from_random_potentials_agree_with_sympy(V, pts):
    Vs = _sym(V)
    F = [sp.sstr(-sp.diff(Vs, x)) for x in X]             # F = -grad V (19.7), unexpanded forms
    new, old = _both(_yaml(F, pts))
    _assert_same(new, old)
    R = new["results"]
    assert R["conservative"] is True and R["conservative_method"] == "symbolic"
    assert R["potential"] == sp.sstr(sp.expand(Vs - Vs.subs({x: 0 for x in X})))      # V(0) = 0


@FAST
@given(F=st.lists(poly_text, min_size=3, max_size=3), pts=points)
def test_random_fields_agree_with_sympy(F, pts):
    new, old = _both(_yaml(F, pts))
    _assert_same(new, old)
    curl = [sp.expand(_sym(F[2]).diff(X[1]) - _sym(F[1]).diff(X[2])),
            sp.expand(_sym(F[0]).diff(X[2]) - _sym(F[2]).diff(X[0])),
            sp.expand(_sym(F[1]).diff(X[0]) - _sym(F[0]).diff(X[1]))]
    assert new["results"]["curl_formula"] == [sp.sstr(c) for c in curl]
    assert new["results"]["conservative"] is all(c == 0 for c in curl)


@settings(max_examples=max(8, N_EXAMPLES // 20), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(V=poly_text, path=st.lists(poly_text.map(lambda s: s.replace("x1", "t").replace("x2", "(1-t)")
                                                  .replace("x3", "(t/2)")), min_size=3, max_size=3))
def test_work_along_polynomial_paths_agrees_with_sympy(V, path):
    F = [sp.sstr(-sp.diff(_sym(V), x)) for x in X]
    p = "{" + ", ".join(f"x{i + 1}: {s!r}" for i, s in enumerate(path)) + ", t_span: [0, 1]}"
    new, old = _both(_yaml(F, [[1, 2, 3]], p))
    _assert_same(new, old)
    R = new["results"]         # U = V1 - V2 (19.8) within the quadrature's error estimate
    assert abs(R["work_check"]) <= 4 * R["work_error"] + 1e-12 * (1 + abs(R["work"]))


# -- the printer's corner cases and the shapes that keep the sympy route ---------------------

@pytest.mark.parametrize("text", [
    "1 - x1", "2/3 - x1**2/3", "-x1 + 1/2", "1 - 2*x1*x2", "-1 - x1", "x1 - 1", "3 - x1 - x2", "1 + x1",
    "-x1**2*x2 - x1*x3**3", "-x1/7 + 2*x2**3*x3/5 - 1/9", "-5", "7/3", "0", "x3", "-x2**3", "x1*x2*x3",
    "(x1 - x2)**3", "(x1/2 + x3/3 - 1)**4", "-(x2 + 1)*(x3 - 2)/6",
])
def test_printing_matches_sympy(text):
    assert P.sstr(P.from_ir(parse(text, VARS).ir, VARS), VARS) == sp.sstr(sp.expand(_sym(text)))


@pytest.mark.parametrize("text", [
    "0.5*x1", "pi*x1", "1e15*x1", "sin(x1)", "x1/x2", "x1/(2 - 2)", "x1**-1", "x1**0.5", "x1**(1/2)",
    "sqrt(4)*x1", "x1**41", "(x1 + x2 + x3 + 1)**40", "2**-50000*x1", "abs(x1)", "t*x1",
])
def test_non_polynomials_keep_the_sympy_route(text):
    with pytest.raises(P.NotPolynomial):
        P.from_ir(parse(text, VARS + ("t",)).ir, VARS)


def test_constant_arithmetic_is_exact():
    # sympy's exact arithmetic on integers (2**-2 = 1/4, (1/3)**2 = 1/9) is reproduced
    assert P.from_ir(parse("2**-2*x1 + (1/3)**2", VARS).ir, VARS) == {(1, 0, 0): 0.25, (0, 0, 0): Fraction(1, 9)}


def test_integer_params_are_polynomial():
    rec = solve_one_text("type: force-field\nparams: {k: 3}\nF: ['-k*x1', '-k*x2', '0']\n")
    assert rec["results"]["potential"] == "3*x1**2/2 + 3*x2**2/2"


def test_curl_at_a_huge_point_is_exact_or_null():
    # x1**2 x2: exact curl −x1² rounded once; at 1e200 F overflows a float, so curl is null (as on sympy's route)
    rec = solve_one_text(_yaml(["x1**2*x2", "0", "0"], [[3.0, 1.0, 0.0], [1e200, 1.0, 0.0]]))
    assert rec["results"]["curl"] == [[0.0, 0.0, -9.0], None]
    assert "curl at points[1] is undefined (F is singular there)" in rec["warnings"]
