"""Steady precession of a symmetric top (notes §38) — numeric core.

Pure Python (math only): no numpy, no scipy.

With ψ̇ = Ω, θ̇ = 0, φ̇ = p constant, (38.18) reduces to (38.22):

    [a Ω² − b Ω + c] sin θ = 0,   a = (I11 − I33) cos θ,  b = I33 p,  c = m g L.

* The roots are computed without cancellation (erratum to 38.23):
  q = (b + sign(b)·√disc)/2, Ω_fast = q/a, Ω_slow = c/q.
* |a| ≤ 1e-14·max(I11, I33) is the linear case: one root Ω = c/b.
* The discriminant is formed with scaling so that huge spins do not overflow.
* sin θ = 0 (the top is vertical) satisfies (38.22) for every Ω: the trivial
  solution; the roots of the bracket are still reported (they are the limits
  of the non-trivial precession as θ → 0 or π) together with a warning.
"""

from __future__ import annotations

import math

from dyncli.errors import InputError
from dyncli.exact import cmp_sqrt, fr
from dyncli.result import Result, SolveOptions
from dyncli.topics.precession import stability
from dyncli.topics.precession.equations import LINEAR_TOL, coefficients, is_linear, p_min, reaction, roots, sqrt_disc  # noqa: F401
from dyncli.topics.precession.table38 import table_38_1

VERTICAL_TOL = 1e-15
DOUBLE_ROOT_REL = 2.0 ** -49   # |p| within 16 round-offs of p_min: the double root (dyncli.exact)


def _finite_vec(v):
    return v if all(math.isfinite(x) for x in v) else None


def solve(pb, options: SolveOptions | None = None) -> Result:
    m, L, I11, I33, theta, g = pb.m, pb.L, pb.I11, pb.I33, pb.theta, pb.g
    res = Result({}, method="closed-form")
    a, _, c = coefficients(m, L, I11, I33, theta, 0.0, g)
    _finite_coefficients(pb, a, c)
    linear = is_linear(a, I11, I33)
    vertical = abs(math.sin(theta)) <= VERTICAL_TOL
    pm = 0.0 if linear else p_min(a, c, I33)
    if vertical:
        res.warn("sin θ = 0: the top stands vertical, and (38.22) holds for every Ω (a trivial steady "
                 "precession); the values reported are the roots of the bracket in (38.22), the limit of the "
                 "non-trivial precession as θ → 0 or π")
    if pb.p is not None:
        _solve_p(pb, res, a, c, linear, pm)
    else:
        _solve_Omega(pb, res, a, c, linear, pm)
    return res


def _finite_coefficients(pb, a, c) -> None:
    """(38.22)'s coefficients must be doubles: m g L or I33 p beyond 1.8e308 is refused."""
    if not math.isfinite(c):
        raise InputError(f"m g L = {pb.m:.3g}·{pb.g:.3g}·{pb.L:.3g} is beyond the range of a double (1.8e308): "
                         "give m, L and g in units that keep their product finite", path="m")
    if not math.isfinite(a):
        raise InputError("(I11 − I33) cos θ is beyond the range of a double (1.8e308): give I11 and I33 in "
                         "smaller units", path="I11")
    for name in ("p", "Omega"):
        v = getattr(pb, name, None)
        if v is not None and not math.isfinite(pb.I33 * v):
            raise InputError(f"I33·{name} is beyond the range of a double (1.8e308): give I33 and {name} in units "
                             "that keep their product finite", path=name)


def _solve_p(pb, res, a, c, linear, pm):
    m, L, I11, I33, theta, g, p = pb.m, pb.L, pb.I11, pb.I33, pb.theta, pb.g, pb.p
    b = I33 * p
    res.equations = ["38.20", "38.22", "38.23", "38.24", "38.27a", "38.27b"]
    r = res.results
    slow = fast = None
    exists = True
    if linear:
        res.warn("(I11 − I33) cos θ = 0: (38.22) is linear in Ω and has one root; Omega_fast, "
                 "Omega_fast_approx and R_fast are null")
        if b != 0:
            slow = c / b
        elif c == 0:
            res.warn("p = 0 and m g L = 0: (38.22) holds for every Ω; Omega_slow is null")
        else:
            exists = False
            res.warn("p = 0 with (I11 − I33) cos θ = 0 and m g L != 0: no steady precession exists")
    else:
        rr = roots(a, b, c)
        if a * c > 0 and cmp_sqrt(abs(b), 4 * fr(a) * fr(c), DOUBLE_ROOT_REL) == 0:
            q = 0.5 * b                        # |p| = p_min to within rounding: the double root (38.24)
            rr = (c / q, q / a)
        if rr is None:
            exists = False
            res.warn(f"no steady precession: |p| = {abs(p):.6g} rad/s is below p_min = {pm:.6g} rad/s (38.24); "
                     "the roots and reactions are null")
        else:
            slow, fast = rr
    r["exists"] = exists
    r["Omega_slow"] = slow
    r["Omega_fast"] = fast
    r["p_min"] = pm
    # (38.27): large-spin approximations
    if b != 0:
        r["Omega_slow_approx"] = c / b
    else:
        r["Omega_slow_approx"] = None
        res.warn("p = 0: the approximations (38.27) are not defined")
    r["Omega_fast_approx"] = None if (linear or b == 0) else b / a
    stability.add(res, I11, I33, theta, p, slow, fast, abs(math.sin(theta)) <= VERTICAL_TOL)
    r["R_slow"] = None if slow is None else _finite_vec(reaction(m, L, g, theta, slow))
    r["R_fast"] = None if fast is None else _finite_vec(reaction(m, L, g, theta, fast))
    for k in ("Omega_fast", "R_fast"):
        if fast is not None and r[k] is None:
            res.warn(f"{k} overflows (the fast root is {fast:.3g} rad/s); reported as null")
    for name, Om in (("slow", slow), ("fast", fast)):
        if Om is not None and math.isfinite(Om * Om):
            res.views.append(table_38_1(f"Table 38.1 — steady precession, {name} root Ω = {Om:.6g} rad/s",
                                        m, L, I11, I33, g, theta, Om, 0.0, p, 0.0, 0.0, 0.0))


def _solve_Omega(pb, res, a, c, linear, pm):
    m, L, I11, I33, theta, g, Om = pb.m, pb.L, pb.I11, pb.I33, pb.theta, pb.g, pb.Omega
    res.equations = ["38.20", "38.22", "38.24"]
    r = res.results
    r["exists"] = True
    for k in ("Omega_slow", "Omega_fast"):
        r[k] = None
    r["p_min"] = pm
    r["Omega_slow_approx"] = None
    r["Omega_fast_approx"] = None
    r["R_slow"] = None
    r["R_fast"] = None
    stability.add(res, I11, I33, theta, 0.0, None, None, False)
    res.warn("Omega is given: the root fields (Omega_slow, Omega_fast, their approximations and reactions) are null")
    if Om == 0.0:
        r["p"] = None
        if c == 0:
            res.warn("Omega = 0 and m g L = 0: every spin p is a steady motion; p is null")
            r["R"] = reaction(m, L, g, theta, 0.0)
        else:
            r["exists"] = False
            r["R"] = None
            res.warn("Omega = 0: a top with m g L != 0 cannot stand still inclined; no p gives steady precession")
        return
    aw = 0.0 if linear else a
    p = (aw * Om + c / Om) / I33
    r["p"] = p if math.isfinite(p) else None
    r["stable"], r["nutation_freq"] = (None, None) if r["p"] is None else stability.nutation(
        I11, I33, theta, p, Om, abs(math.sin(theta)) <= VERTICAL_TOL)
    r["R"] = _finite_vec(reaction(m, L, g, theta, Om))
    if r["p"] is None or r["R"] is None:
        res.warn("p or R overflows for this Omega; reported as null")
    if r["p"] is not None:
        res.views.append(table_38_1(f"Table 38.1 — steady precession Ω = {Om:.6g} rad/s, p = {p:.6g} rad/s",
                                    m, L, I11, I33, g, theta, Om, 0.0, p, 0.0, 0.0, 0.0))
