"""Force fields (notes §19): the exact route for a polynomial field on the Cartesian basis,
without sympy (:mod:`dyncli.topics.force_field.polynomial` holds the algebra).

* curl F (19.9) from exact derivatives of the polynomials; its values at the points are
  computed exactly and rounded once;
* the verdict is exact: F is conservative iff the three curl polynomials are identically
  zero.  A polynomial field is defined everywhere (a simply connected region), so a zero
  curl gives a single-valued potential: no numeric check.  For a non-zero curl the
  counterexample is the first random test point where the curl is non-zero, chosen as the
  sympy route chooses it (:func:`dyncli.topics.force_field.checks.numeric_verdict`);
* the potential with F = −∇V and V(0) = 0 (19.7): V(x) = −∫₀¹ F(s x)·x ds, monomial by
  monomial (a monomial of degree d in F_i gives −c x^m x_i / (d + 1));
* the formulas print exactly as sympy prints the same polynomials (``conservative_method``
  stays ``symbolic``: the verdict is a symbolic proof, as on sympy's route).

Anything that is not such a polynomial keeps the sympy route (:func:`of` returns None).
"""

from __future__ import annotations

from dyncli.topics.force_field import polynomial as P

VARS = ("x1", "x2", "x3")
ENABLED = True          # tests set this False to force the sympy route (the oracle)


class PolynomialField:
    """A polynomial field F with its curl and first derivatives, all exact."""

    decimals = False

    def __init__(self, exprs, polys):
        self.exprs = tuple(exprs)
        self.F = polys
        D = [[P.diff(polys[i], j) for j in range(3)] for i in range(3)]      # D[i][j] = ∂F_i/∂x_j
        self.grad = [d for row in D for d in row]
        self.curl = [P.add(D[2][1], D[1][2], -1), P.add(D[0][2], D[2][0], -1), P.add(D[1][0], D[0][1], -1)]

    def F_at(self, x):
        return [P.value(p, x) for p in self.F]

    def curl_at(self, x):
        return [P.value(p, x) for p in self.curl]

    def potential(self) -> P.Poly:
        """V(x) = −∫₀¹ F(s x)·x ds (F = −∇V, V(0) = 0) for a curl-free F."""
        V: P.Poly = {}
        for i, Fi in enumerate(self.F):
            for m, c in Fi.items():
                mm = list(m)
                mm[i] += 1
                V = P.add(V, {tuple(mm): -c / (sum(m) + 1)})
        return V


def of(F) -> PolynomialField | None:
    """The polynomial field of the three expressions F, or None (the sympy route)."""
    if not ENABLED:
        return None
    try:
        return PolynomialField(F, [P.from_ir(e.ir, VARS) for e in F])
    except P.NotPolynomial:
        return None


def _counterexample(fld: PolynomialField, box: float) -> str:
    """The first random test point where the curl is non-zero: by the numeric criterion of
    checks.numeric_verdict (so the point is the one the sympy route names), else exactly."""
    import numpy as np

    from dyncli.topics.force_field.checks import CURL_RTOL, N_RANDOM, random_points

    pts = random_points(N_RANDOM, box)
    curl = np.array([P.values(c, pts) for c in fld.curl])
    scale = np.zeros(pts.shape[1])
    for d in fld.grad:
        val = np.abs(P.values(d, pts))
        scale = np.maximum(scale, np.where(np.isfinite(val), val, 0.0))
    ok = np.all(np.isfinite(curl), axis=0)
    big = np.any(np.abs(curl) > CURL_RTOL * scale, axis=0) & ok
    if np.any(big):
        k = int(np.argmax(big))
    else:       # rounding or overflow hides it: the exact curl at the test points
        k = next((j for j in range(pts.shape[1]) if any(P.exact_value(c, pts[:, j]) for c in fld.curl)), 0)
    p = [float(v) for v in pts[:, k]]
    return f"counterexample: curl != 0 at x = [{p[0]:.4g}, {p[1]:.4g}, {p[2]:.4g}]"


def exact_part(fld: PolynomialField, box: float):
    """(conservative, how, curl formulas, V formula, V as a function of a point): the
    polynomial counterpart of the solver's _symbolic_part."""
    curl_formula = [P.sstr(c, VARS) for c in fld.curl]
    if any(fld.curl):
        return False, _counterexample(fld, box), curl_formula, None, None
    V = fld.potential()

    def Vnum(x1, x2, x3):
        return P.value(V, (x1, x2, x3))

    return True, "symbolic", curl_formula, P.sstr(V, VARS), Vnum


