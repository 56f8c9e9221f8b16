"""Force fields (notes §19) — numeric core (no pydantic); this module is the adapter:
the symbolic curl and potential are in :mod:`dyncli.topics.force_field.symbolic_field`,
the checks at random points in :mod:`dyncli.topics.force_field.checks`.

* a polynomial field (integer or rational coefficients) takes the exact route of
  :mod:`dyncli.topics.force_field.polynomial_field` (no sympy: exact curl, verdict and
  potential, formulas printed as sympy prints them); every other field the sympy route:
* curl F (19.9) from exact derivatives: the field's expressions are turned
  into sympy objects node by node (``dyncli.symbolic``), differentiated, and
  converted back to dyncli expressions for evaluation at the points;
* the conservative verdict: every curl component simplified to 0 (symbolic
  proof) — if sympy cannot decide, a numeric check at random points (said so
  in ``conservative_method`` and a warning); a curl that is non-zero at some
  point proves the field non-conservative;
* the potential V with F = -grad V (19.7) and V(0) = 0, integrated
  symbolically one coordinate at a time and verified by differentiation, then
  checked for being single-valued (its differences must equal the work along
  random straight segments by Gauss-Legendre quadrature — a field such as -x2/(x1²+x2²) e1 + x1/(x1²+x2²) e2
  has zero curl but no potential around the x3 axis);
* the work along a path x(t) (19.4): adaptive quadrature (:mod:`dyncli.quadrature`) of
  F(x(t)) . x'(t) with x'(t) exact (the rules of calculus on the expression IR,
  :mod:`dyncli.expr.derivative`), cross-checked against V1 - V2 (19.8).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, cast

from dyncli import symbolic
from dyncli.errors import InputError
from dyncli.result import Result, SolveOptions
from dyncli.topics.force_field.checks import N_RANDOM, box_of, numeric_verdict, random_points, real_somewhere, single_valued
from dyncli.topics.force_field.path import path_work
from dyncli.topics.force_field.setup import Path, Setup
from dyncli.topics.force_field.symbolic_field import (SYMBOLIC_SECONDS, Field, display_formula, conservative_verdict, numeric_potential,
                                                      potential, report_verdict)

if TYPE_CHECKING:
    from dyncli.topics.force_field.polynomial_field import PolynomialField


def _field(F) -> Field:
    """The field with its exact derivatives, within SYMBOLIC_SECONDS of CPU."""
    from dyncli import cputime

    symbolic.warm()                  # the limit measures sympy's work, not its first import
    try:
        with cputime.limit(SYMBOLIC_SECONDS):
            return Field(F)
    except (cputime.CpuTimeout, RecursionError):
        raise InputError(f"F is too large for its exact derivatives (the curl): sympy needs more than "
                         f"{SYMBOLIC_SECONDS:g} s of CPU; write F with fewer factors or terms", "F") from None


def _symbolic_part(fld: Field, box: float, res: Result):
    """(conservative, how, curl formulas, V, Vnum): the exact verdict and
    potential within SYMBOLIC_SECONDS of CPU; beyond it the verdict is the
    numeric check at random points and the formulas are null (with a warning)."""
    from dyncli import cputime

    warned = len(res.warnings)
    try:
        with cputime.limit(SYMBOLIC_SECONDS):
            cons, how, curl_simpl = conservative_verdict(fld, box, res)
            curl_formula = [display_formula(c, fld.decimals) for c in curl_simpl]
            V = Vnum = None
            if cons:
                V = potential(fld, res)
                if V is not None:
                    Vnum = numeric_potential(V)
                    cons, how, V, Vnum = _single_valued(fld, V, Vnum, box, res, how)
            return cons, how, curl_formula, V, Vnum
    except (cputime.CpuTimeout, RecursionError):
        del res.warnings[warned:]
        res.warn(f"F is too large to simplify its curl or integrate a potential within {SYMBOLIC_SECONDS:g} s "
                 "of CPU: the verdict is the numeric check at random points; curl_formula and potential are null")
        cons, how = numeric_verdict(fld, box, res)
        return cons, how, None, None, None


def _single_valued(fld, V, Vnum, box, res, how):
    ok, why = single_valued(fld, Vnum, box)
    if not ok:
        res.warn("the curl vanishes wherever F is defined, but F is singular on a set that "
                 f"closed paths can loop around, so no single-valued potential exists: {why}")
        return False, "curl = 0 where F is defined, but the work is path dependent", None, None
    if why:
        res.warn(f"single-valuedness of V not checked: {why}")
    return True, how, V, Vnum


def plain(p) -> Setup:
    """The validated model as plain inputs (expressions and SI floats)."""
    path = None
    if p.path is not None:
        t1, t2 = (float(v) for v in p.path.t_span)
        path = Path(p.path.x1, p.path.x2, p.path.x3, t1, t2)
    a = p.accuracy
    return Setup(tuple(p.F), tuple((float(pt[0]), float(pt[1]), float(pt[2])) for pt in p.points), path,
                 getattr(p, "coordinates", "cartesian"), float(a.rtol), float(a.atol), a.max_steps)


def solve(p, options: SolveOptions | None = None) -> Result:
    return solve_setup(plain(p), options)


def solve_setup(p: Setup, options: SolveOptions | None = None) -> Result:
    """curl, verdict, potential and work of the field ``p`` (plain inputs: :func:`plain`)."""
    if p.coordinates != "cartesian":     # Tables 19.1-19.2: coordinates.py
        from .coordinates import solve as solve_curvilinear

        return solve_curvilinear(p, options)
    from . import polynomial_field

    poly = polynomial_field.of(p.F)       # a polynomial field: exact without sympy
    fld = poly if poly is not None else _field(p.F)
    box = box_of(v for pt in p.points for v in pt)   # the region of the random checks
    if poly is None:
        pts = random_points(N_RANDOM, box)
        real_somewhere(fld.exprs, [dict(x1=pts[0], x2=pts[1], x3=pts[2])]
                       + [dict(x1=float(a), x2=float(b), x3=float(c)) for a, b, c in p.points])
    res = Result({}, method="closed-form", equations=["19.9"])

    # curl at the points
    curls: list[list[float] | None] = []       # plain floats: a conservative polynomial field without a path imports no numpy
    for i, pt in enumerate(p.points):
        x = [float(v) for v in pt]
        c = [float(v) + 0.0 for v in fld.curl_at(x)]
        if all(map(math.isfinite, c)) and all(math.isfinite(float(v)) for v in fld.F_at(x)):
            curls.append(c)
        else:
            curls.append(None)
            res.warn(f"curl at points[{i}] is undefined (F is singular there)")
    res.results["curl"] = curls

    part = polynomial_field.exact_part(poly, box) if poly is not None else _symbolic_part(cast(Field, fld), box, res)   # (fld is _field's)
    cons, how, res.results["curl_formula"], V, Vnum = part
    report_verdict(res, cons, how, V, fld.decimals)

    _work(res, p, fld, cons, Vnum)
    return res


def _work(res: Result, p: Setup, fld: Field | PolynomialField, cons: bool, Vnum) -> None:
    """The work along the path (19.4) and its check against V1 − V2 (19.8)."""
    if p.path is None:
        res.results["work"] = None
        res.warn("no path given: work is null")
    else:
        U, err, xa, xb = path_work(fld, p.path, p.rtol, p.atol, res, p.max_steps)
        res.equations.append("19.4")
        res.results["work"] = U
        res.results["work_error"] = err
        res.results["x_start"] = [float(v) + 0.0 for v in xa]
        res.results["x_end"] = [float(v) + 0.0 for v in xb]
        if Vnum is not None:
            Va, Vb = Vnum(*xa), Vnum(*xb)
            if math.isfinite(Va) and math.isfinite(Vb):
                res.results["work_from_potential"] = Va - Vb
                res.results["work_check"] = U - (Va - Vb)
            else:
                res.results["work_from_potential"] = None
                res.results["work_check"] = None
                res.warn("V is undefined at an end of the path: work_check is null")
        else:
            res.results["work_from_potential"] = None
            res.results["work_check"] = None
            if cons:
                res.warn("no potential to cross-check the work: work_check is null")
