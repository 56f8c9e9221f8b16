"""Force fields (notes §19): the symbolic part (sympy, imported inside each function).

* curl F (19.9) from exact derivatives: the field's expressions are turned
  into sympy objects node by node (``dyncli.symbolic``), differentiated, and
  converted back to dyncli expressions for evaluation at the points;
* the conservative verdict (and its report, :func:`report_verdict`, for Cartesian and curvilinear
  fields alike, within :data:`SYMBOLIC_SECONDS` of CPU): every curl component simplified to 0 (symbolic
  proof) — if sympy cannot decide, the numeric check at random points
  (:mod:`dyncli.topics.force_field.checks`);
* the potential V with F = -grad V (19.7) and V(0) = 0, integrated
  symbolically one coordinate at a time and verified by differentiation;
* the display of formulas (decimals where the user wrote decimals).

The exact forms (:func:`exact_rationals`, :func:`simplify_formula`, :func:`generic_branch`) and
:func:`display_formula` serve the curvilinear fields (:mod:`dyncli.topics.force_field.coordinates`) too.
"""

from __future__ import annotations

import math
from typing import Any

from dyncli import symbolic
from dyncli.result import Result
from dyncli.topics.force_field.checks import N_RANDOM, numeric_verdict, random_points

VARS = ("x1", "x2", "x3")
MAX_OPS = 400          # above this size, skip sympy's simplify (numeric check instead)
SYMBOLIC_SECONDS = 1.0  # CPU for the exact derivatives, and again for the verdict and potential (dyncli.cputime)


def exact_rationals(obj):
    """Floats (from decimal literals) -> exact rationals, so that sympy's
    integration and simplification work exactly (Cartesian and curvilinear fields alike)."""
    import sympy as sp

    return obj.xreplace({f: sp.Rational(repr(float(f))) for f in obj.atoms(sp.Float)})


def _decimalize(obj):
    """For display when the user wrote decimals: coefficients that are
    rationals with a power-of-ten denominator become floats (exponents stay
    exact, so sqrt(...) prints as sqrt)."""
    import sympy as sp

    exponents = {pw.exp for pw in obj.atoms(sp.Pow)}
    rep = {}
    for q in obj.atoms(sp.Rational):
        if q.is_Integer or q in exponents or -q in exponents:
            continue
        d = int(q.q)
        for b in (2, 5):
            while d % b == 0:
                d //= b
        if d == 1:
            rep[q] = sp.Float(float(q), 15)
    return obj.xreplace(rep) if rep else obj


def display_formula(obj, decimals: bool) -> str:
    """A formula of the results (curl, potential) as one-line text: its shortest readable form
    (simplified or expanded; a polynomial expanded), with decimals where the user wrote decimals."""
    import sympy as sp

    forms = [obj]
    try:
        forms.append(sp.expand(obj))
    except Exception:  # noqa: BLE001 - cosmetic
        pass
    if len(forms) == 2 and forms[1].is_polynomial(*[symbolic.symbol(n) for n in VARS]):
        best = forms[1]
    else:
        best = min(forms, key=lambda f: (sp.count_ops(f), len(sp.sstr(f))))
    return symbolic.pretty(_decimalize(best) if decimals else best)


def simplify_formula(obj):
    """The canonical form of a sympy expression, best effort: cancel over a common denominator,
    then sympy's simplify unless the result is a polynomial or above MAX_OPS; the expression
    unchanged when sympy fails.  A result of 0 is the symbolic proof that a curl (or the
    residual of a potential) vanishes."""
    import sympy as sp

    if obj == 0:
        return obj
    try:
        out = sp.cancel(sp.together(obj))
        # a polynomial is already canonical after cancel (and shown expanded): no simplify, whose
        # first call alone imports sympy.physics.units (~0.15 s) and takes ~0.1 s more
        if out != 0 and sp.count_ops(out) <= MAX_OPS and not out.is_polynomial():
            out = sp.simplify(out)
        return out
    except Exception:  # noqa: BLE001 - simplification is best effort
        return obj


def generic_branch(obj):
    """An antiderivative's generic case: each Piecewise replaced by its first branch (integration of
    e.g. x2*cos(x1*x2) in x1 gives sin(x1*x2) 'for x2 != 0'); the potential found with it
    is verified by differentiation afterwards."""
    import sympy as sp

    return obj.replace(lambda e: isinstance(e, sp.Piecewise), lambda e: e.args[0].expr)


def finite_real(raw) -> None:
    """Refuse a component whose exact form holds a constant beyond a double
    (``.inf``, ``x1*1e308*2``) or the imaginary unit (``sqrt(-R)`` with R > 0)."""
    import sympy as sp

    from dyncli.errors import InputError

    for i, r in enumerate(raw):
        if r.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or any(not math.isfinite(float(f)) for f in r.atoms(sp.Float)):
            raise InputError(f"component {i + 1} holds a constant beyond the range of a double (1.8e308); "
                             "give F in units that keep its constants finite", f"F.{i}")
        if r.has(sp.I):
            raise InputError(f"component {i + 1} is imaginary ({sp.sstr(r)[:80]}): F must be a real field", f"F.{i}")


class Field:
    def __init__(self, F):
        import sympy as sp

        self.exprs = tuple(F)
        self.X = [symbolic.symbol(n) for n in VARS]
        raw = [symbolic.sym(e) for e in F]
        finite_real(raw)
        self.decimals = any(r.atoms(sp.Float) for r in raw)
        self.S = [exact_rationals(r) for r in raw]
        X, S = self.X, self.S
        D = [[sp.diff(S[i], X[j]) for j in range(3)] for i in range(3)]    # D[i][j] = ∂F_i/∂x_j
        self.curl_sym = [D[2][1] - D[1][2], D[0][2] - D[2][0], D[1][0] - D[0][1]]
        self.curl_expr = [symbolic.expr_from_sympy(c, VARS) for c in self.curl_sym]
        self.grad_expr = [symbolic.expr_from_sympy(d, VARS) for row in D for d in row]

    def F_at(self, x):
        import numpy as np

        env = {"x1": x[0], "x2": x[1], "x3": x[2]}
        return np.stack([e.evaluate(**env) for e in self.exprs])

    def curl_at(self, x):
        import numpy as np

        env = {"x1": x[0], "x2": x[1], "x3": x[2]}
        return np.stack([e.evaluate(**env) for e in self.curl_expr])


def conservative_verdict(fld: Field, box: float, res: Result) -> tuple[bool, str, Any]:
    """(conservative?, how it was decided, curl formulas)."""
    simplified = [simplify_formula(c) for c in fld.curl_sym]
    if all(c == 0 for c in simplified):
        return True, "symbolic", simplified
    cons, how = numeric_verdict(fld, box, res)
    return cons, how, simplified


def potential(fld: Field, res: Result):
    """V with F = -grad V, V(0) = 0 (sympy object) or None (with a warning)."""
    import sympy as sp

    X, S = fld.X, fld.S
    try:
        V = -generic_branch(sp.integrate(S[0], X[0]))
        for i in (1, 2):
            r = simplify_formula(-S[i] - sp.diff(V, X[i]))
            for j in range(i):
                if X[j] in r.free_symbols:
                    # mathematically independent of x_j (curl = 0): evaluate at a
                    # regular value of x_j
                    for val in (0, 1, sp.Rational(1, 3)):
                        rr = r.subs(X[j], val)
                        if rr.is_finite is not False and not rr.has(sp.zoo, sp.nan):
                            r = rr
                            break
            V = V + generic_branch(sp.integrate(r, X[i]))
        if V.has(sp.Integral):
            raise ValueError("unevaluated integral")
    except Exception:  # noqa: BLE001 - sympy could not integrate
        res.warn("the field is conservative but sympy found no closed-form potential; potential is null")
        return None
    V = pin_at_origin(V, X, res, "F (or V)")
    # verify F = -grad V
    for i in range(3):
        if simplify_formula(S[i] + sp.diff(V, X[i])) != 0:
            if not _numeric_gradient_ok(fld, V, i):
                res.warn("sympy's antiderivative is not a potential everywhere (piecewise or singular), "
                         "so no closed-form potential is given: potential is null")
                return None
    return V


def _numeric_gradient_ok(fld: Field, V, i: int) -> bool:
    import numpy as np
    import sympy as sp

    d = symbolic.expr_from_sympy(sp.diff(V, fld.X[i]), VARS)
    pts = random_points(N_RANDOM, 2.0, seed=7)
    a = d.evaluate(x1=pts[0], x2=pts[1], x3=pts[2]) + fld.exprs[i].evaluate(x1=pts[0], x2=pts[1], x3=pts[2])
    ok = np.isfinite(a)
    return bool(np.any(ok)) and bool(np.all(np.abs(a[ok]) < 1e-8 * (1 + np.abs(d.evaluate(x1=pts[0], x2=pts[1], x3=pts[2])[ok]))))


def numeric_potential(V):
    """A float-valued function of a point for the sympy potential V: dyncli's
    own evaluator when V converts back to an expression, else sympy's evalf
    of V with the coordinates substituted (e.g. for erf)."""
    import sympy as sp

    try:
        e = symbolic.expr_from_sympy(V, VARS)

        def f(x1, x2, x3):
            return float(e.evaluate(x1=float(x1), x2=float(x2), x3=float(x3)))

        return f
    except ValueError:
        X = [symbolic.symbol(n) for n in VARS]

        def g(x1, x2, x3):
            val = V.subs({X[0]: sp.Float(float(x1)), X[1]: sp.Float(float(x2)), X[2]: sp.Float(float(x3))}).evalf()
            try:
                out = complex(val)
            except TypeError:
                return float("nan")
            return out.real if abs(out.imag) <= 1e-12 * (1 + abs(out.real)) else float("nan")

        return g


def pin_at_origin(V, symbols, res, what: str = "V"):
    """V − V(0), simplified, so that V(0) = 0; V unchanged (with a warning) where V is singular
    at the origin of the coordinates ``symbols``."""
    import sympy as sp

    V0 = V.subs({q: 0 for q in symbols})
    if V0.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or V0.is_finite is False:
        res.warn(f"{what} is singular at the origin, so V(0) = 0 cannot be imposed; "
                 "the additive constant of V is the one of the antiderivative")
    else:
        V = V - V0
    return simplify_formula(V)


def report_verdict(res: Result, cons: bool, how: str, V, decimals: bool, curl_zero: bool | None = None) -> None:
    """``conservative``, ``conservative_method`` and ``potential`` (V a sympy object, or already its
    formula text); (19.7), (19.8) when the curl
    vanishes (``curl_zero``, default ``cons``: a zero curl with a multi-valued V is not conservative)."""
    if cons if curl_zero is None else curl_zero:
        res.equations += ["19.7", "19.8"]
    else:
        res.warn("F is not conservative (its curl is not zero), so it has no potential: potential is null")
    res.results["conservative"] = bool(cons)
    res.results["conservative_method"] = how
    res.results["potential"] = V if V is None or isinstance(V, str) else display_formula(V, decimals)
