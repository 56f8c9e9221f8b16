"""Force fields in the notes' curvilinear coordinates (notes §19, Tables 19.1-19.2).

With ``coordinates: polar | cylindrical | spherical`` the field F is given by
its components on that system's basis as expressions in its coordinates:

* cylindrical (Table 19.1): (r, θ, x3), F = F_r e_r + F_θ e_θ + F_3 e3;
  polar is the same in the plane (F may not depend on x3);
* spherical (Table 19.2): (R, θ, φ) with φ the ELEVATION from the e1-e2
  plane (the notes' convention), F = F_R e_R + F_θ e_θ + F_φ e_φ.

Both are orthogonal systems with scale factors h = (1, r, 1) and
(1, R cos φ, R); with them

    ∇V = Σ (1/h_i) ∂V/∂q_i e_i,
    (∇×F)_1 = [∂(h3 F3)/∂q2 − ∂(h2 F2)/∂q3] / (h2 h3)   (and cyclically),

which are the formulas of the tables.  The curl is exact (sympy) and shown
on the system's basis; the potential solves ∂V/∂q_i = −h_i F_i one
coordinate at a time and is checked by differentiation; it must also be
single-valued, V(θ + 2π) = V(θ) — a field such as F_θ = 1/r has zero curl
but V = −θ, so it is not conservative (the work once around the axis is 2π).
A path is given in the same coordinates (``{r, theta, x3}`` or
``{R, theta, phi}`` as expressions in t); its work is ∫ Σ F_i h_i q̇_i dt
(19.4) by adaptive quadrature, cross-checked against V1 − V2 (19.8).
"""

from __future__ import annotations

import math
from typing import Any

from dyncli import symbolic
from dyncli.errors import InputError
from dyncli.result import Result, SolveOptions
from dyncli.topics.force_field.checks import box_of, real_somewhere
from dyncli.topics.force_field.setup import Path, Setup

SYSTEMS = {
    "polar": (("r", "theta"), ("e_r", "e_θ", "e₃"), "Table 19.1"),
    "cylindrical": (("r", "theta", "x3"), ("e_r", "e_θ", "e₃"), "Table 19.1"),
    "spherical": (("R", "theta", "phi"), ("e_R", "e_θ", "e_φ"), "Table 19.2"),
}
N_RANDOM = 48


def variables(coords: str) -> tuple[str, ...]:
    return SYSTEMS[coords][0]


def prepare(data: Any, info) -> Any:
    """Before validation: parse F in the coordinates' variables, and rename a
    path's coordinate keys to the x1, x2, x3 slots of the path model."""
    if not isinstance(data, dict) or data.get("coordinates", "cartesian") == "cartesian":
        return data
    choices = ("cartesian",) + tuple(SYSTEMS)
    if not isinstance(data["coordinates"], str):
        raise InputError(f"coordinates must be one of: {', '.join(choices)}", "coordinates")
    if data["coordinates"] not in SYSTEMS:
        from dyncli.expr import did_you_mean

        raise InputError(f"unknown coordinates {data['coordinates']!r}{did_you_mean(str(data['coordinates']), choices)}; "
                         f"choose one of: {', '.join(choices)}", "coordinates")
    from pydantic_core import PydanticCustomError

    from dyncli.fields import parse_expr_value

    coords = data["coordinates"]
    names = variables(coords)
    out = dict(data)
    F = data.get("F")
    if isinstance(F, (list, tuple)) and len(F) == 3:
        parsed = []
        for i, comp in enumerate(F):
            try:
                parsed.append(parse_expr_value(comp, names, info, "force"))
            except PydanticCustomError as exc:
                raise InputError(f"component {i + 1}: {exc.message()} (with coordinates: {coords} the variables "
                                 f"are {', '.join(names)})", "F") from None
        out["F"] = parsed
    path = data.get("path")
    if isinstance(path, dict):
        keys = names if len(names) == 3 else names + ("x3",)
        wrong = [k for k in ("x1", "x2", "x3") if k in path and k not in keys]
        if wrong:
            raise InputError(f"with coordinates: {coords} the path is given by {', '.join(keys)} "
                             f"(expressions in t), not {wrong[0]}", f"path.{wrong[0]}")
        renamed = {k: v for k, v in path.items() if k not in keys}
        for slot, k in zip(("x1", "x2", "x3"), keys):
            if k in path:
                renamed[slot] = path[k]
        if len(names) == 2:
            renamed.setdefault("x3", 0)
        out["path"] = renamed
    return out


class CurvilinearField:
    def __init__(self, F, coords: str):
        import sympy as sp

        self.coords = coords
        self.names, self.basis, self.table = SYSTEMS[coords]
        pos = {"r", "R"}
        self.Q = [sp.Symbol(n, positive=True) if n in pos else symbolic.symbol(n) for n in self._all_names()]
        rep = {symbolic.symbol(n): q for n, q in zip(self._all_names(), self.Q)}
        from .symbolic_field import exact_rationals, finite_real

        raw = [symbolic.sym(e).xreplace(rep) for e in F]
        finite_real(raw)
        self.decimals = any(r.atoms(sp.Float) for r in raw)
        self.S = [exact_rationals(r) for r in raw]
        q1, q2, q3 = self.Q
        self.h = [sp.Integer(1), q1 * sp.cos(q3), q1] if self.coords == "spherical" else [sp.Integer(1), q1, sp.Integer(1)]
        self.exprs = [symbolic.expr_from_sympy(s, self._all_names()) for s in self.S]
        self.curl_parts = self._curl_parts()
        self.curl_sym = [a - b for a, b in self.curl_parts]

    def _all_names(self):
        return self.names if len(self.names) == 3 else self.names + ("x3",)

    def _curl_parts(self):
        """(A_i, B_i) with (∇×F)_i = A_i − B_i (Tables 19.1-19.2)."""
        import sympy as sp

        Q, S, h = self.Q, self.S, self.h
        out = []
        for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
            den = h[j] * h[k]
            out.append((sp.diff(h[k] * S[k], Q[j]) / den, sp.diff(h[j] * S[j], Q[k]) / den))
        return out

    def cartesian(self, q):
        """Cartesian position of the point with coordinates q (3 floats)."""
        a, b, c = (float(v) for v in q)
        if self.coords == "spherical":
            return [a * math.cos(c) * math.cos(b), a * math.cos(c) * math.sin(b), a * math.sin(c)]
        return [a * math.cos(b), a * math.sin(b), c]

    def num(self, obj):
        return symbolic.expr_from_sympy(obj, self._all_names())

    def env(self, q):
        return dict(zip(self._all_names(), q))

    def random_points(self, box):
        import numpy as np

        rng = np.random.default_rng(19)
        a = rng.uniform(0.1, box, N_RANDOM)
        b = rng.uniform(-math.pi, math.pi, N_RANDOM)
        c = rng.uniform(-1.4, 1.4, N_RANDOM) if self.coords == "spherical" else rng.uniform(-box, box, N_RANDOM)
        return [a, b, c]


def verdict(fld: CurvilinearField, box: float, res: Result):
    import numpy as np

    from .symbolic_field import simplify_formula

    simplified = [simplify_formula(c) for c in fld.curl_sym]
    if all(c == 0 for c in simplified):
        return True, "symbolic", simplified
    pts = fld.random_points(box)
    env = fld.env(pts)
    worst, where = 0.0, [0.0, 0.0, 0.0]          # (where: read once worst > 0)
    checked = 0
    for A, B in fld.curl_parts:
        a, b = fld.num(A).evaluate(**env), fld.num(B).evaluate(**env)
        ok = np.isfinite(a) & np.isfinite(b)
        checked = max(checked, int(np.sum(ok)))
        rel = np.where(ok, np.abs(a - b) / (1e-300 + np.abs(a) + np.abs(b) + 1e-12), 0.0)
        k = int(np.argmax(rel))
        if rel[k] > worst:
            worst, where = float(rel[k]), [float(pts[0][k]), float(pts[1][k]), float(pts[2][k])]
    if worst > 1e-9:
        return False, (f"counterexample: curl != 0 at ({', '.join(fld._all_names())}) = "
                       f"({where[0]:.4g}, {where[1]:.4g}, {where[2]:.4g})"), simplified
    res.warn(f"sympy could not simplify the curl to 0; it vanishes (to rounding) at {checked} random points, "
             "so F is taken as conservative (numeric check)")
    return True, f"numeric (curl = 0 at {checked} random points)", simplified


def potential(fld: CurvilinearField, res: Result):
    """V with ∂V/∂q_i = −h_i F_i (sympy) or None; also whether V is single-valued in θ."""
    import sympy as sp

    from .symbolic_field import generic_branch, simplify_formula

    Q, G = fld.Q, [h * s for h, s in zip(fld.h, fld.S)]
    try:
        V = -generic_branch(sp.integrate(G[0], Q[0]))
        for i in (1, 2):
            r = simplify_formula(-G[i] - sp.diff(V, Q[i]))
            V = V + generic_branch(sp.integrate(r, Q[i]))
        if V.has(sp.Integral):
            raise ValueError("unevaluated integral")
    except Exception:  # noqa: BLE001 - sympy could not integrate
        res.warn("the field is conservative but sympy found no closed-form potential; potential is null")
        return None, True
    if any(simplify_formula(g + sp.diff(V, q)) != 0 for g, q in zip(G, Q)):
        res.warn("sympy's antiderivative could not be verified as a potential: potential is null")
        return None, True
    from .symbolic_field import pin_at_origin

    V = pin_at_origin(V, Q, res)
    jump = simplify_formula(V.subs(Q[1], Q[1] + 2 * sp.pi) - V)
    return V, jump == 0


class _ScaledField:
    """F_at(q) = (h_i F_i)(q), so that the Cartesian path_work's F·x' becomes
    Σ F_i h_i q̇_i along a path given by its coordinates q(t)."""

    def __init__(self, fld: CurvilinearField):
        self.fld = fld
        self.G = [fld.num(h * s) for h, s in zip(fld.h, fld.S)]

    def F_at(self, q):
        import numpy as np

        env = self.fld.env(q)
        return np.array([float(g.evaluate(**env)) for g in self.G])


def path_work(fld: CurvilinearField, path: Path, rtol, atol, res, max_steps=None):
    """∫ Σ F_i h_i q̇_i dt along q(t) (19.4): (U, error, q_start, q_end)."""
    from .path import path_work as cartesian_path_work

    return cartesian_path_work(_ScaledField(fld), path, rtol, atol, res, max_steps)


def _curl_at_points(fld, points, formulas, res):
    import numpy as np

    exprs = [fld.num(c) for c in formulas]
    out = []
    for i, pt in enumerate(points):
        env = fld.env([float(v) for v in pt])
        c = np.array([float(e.evaluate(**env)) for e in exprs])
        F = np.array([float(e.evaluate(**env)) for e in fld.exprs])
        if np.all(np.isfinite(c)) and np.all(np.isfinite(F)):
            out.append([float(v) + 0.0 for v in c])
        else:
            out.append(None)
            res.warn(f"curl at points[{i}] is undefined (F or the basis is singular there, e.g. on the axis)")
    return out


def solve(p: Setup, options: SolveOptions | None = None) -> Result:
    from dyncli import cputime

    from dyncli import symbolic

    from .symbolic_field import SYMBOLIC_SECONDS

    symbolic.warm()                  # the limit measures sympy's work, not its first import
    try:
        with cputime.limit(2 * SYMBOLIC_SECONDS):   # sympy's work, as for Cartesian F
            fld, res, V, cons = _symbolic(p)
    except (cputime.CpuTimeout, RecursionError):
        raise InputError(f"F is too large for its exact curl and potential in {p.coordinates} coordinates: sympy "
                         f"needs more than {2 * SYMBOLIC_SECONDS:g} s of CPU; write F with fewer factors or terms",
                         "F") from None
    _work(fld, p, V, cons, res)
    return res


def _symbolic(p: Setup):
    from .symbolic_field import display_formula

    fld = CurvilinearField(p.F, p.coordinates)
    res = Result({}, method="closed-form", equations=["19.9", fld.table])
    res.results["basis"] = ", ".join(fld.basis)
    box = box_of(pt[0] for pt in p.points)
    names = fld._all_names()
    real_somewhere(fld.exprs, [dict(zip(names, fld.random_points(box)))] + [fld.env(pt) for pt in p.points])
    cons, how, simplified = verdict(fld, box, res)
    res.results["curl"] = _curl_at_points(fld, p.points, simplified, res)
    res.results["curl_formula"] = [display_formula(c, fld.decimals) for c in simplified]
    V = None
    curl_zero = cons
    if cons:
        V, single = potential(fld, res)
        if V is not None and not single:
            cons, how = False, "curl = 0 where F is defined, but the potential is not single-valued in θ"
            res.warn(f"the curl vanishes, but V = {display_formula(V, fld.decimals)} changes by going once around the axis "
                     "(θ → θ + 2π): no single-valued potential exists, the field is not conservative (19.6)")
            V = None
    from .symbolic_field import report_verdict

    report_verdict(res, cons, how, V, fld.decimals, curl_zero)
    return fld, res, V, cons


def _work(fld, p: Setup, V, cons, res) -> None:
    r = res.results
    if p.path is None:
        r["work"] = None
        res.warn("no path given: work is null")
        return
    U, err, qa, qb = path_work(fld, p.path, p.rtol, p.atol, res, p.max_steps)
    res.equations.append("19.4")
    r.update(work=U, work_error=err, x_start=[v + 0.0 for v in fld.cartesian(qa)],
             x_end=[v + 0.0 for v in fld.cartesian(qb)], work_from_potential=None, work_check=None)
    if V is not None:
        Vn = fld.num(V)
        Va, Vb = float(Vn.evaluate(**fld.env(qa))), float(Vn.evaluate(**fld.env(qb)))
        if math.isfinite(Va) and math.isfinite(Vb):
            r["work_from_potential"], r["work_check"] = Va - Vb, U - (Va - Vb)
        else:
            res.warn("V is undefined at an end of the path: work_check is null")
    elif cons:
        res.warn("no potential to cross-check the work: work_check is null")
