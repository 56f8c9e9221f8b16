"""Kinematics of a point (notes §4, §5, §7, §8, §12) — numeric core.

The coordinates are expressions in t; their exact first and second
derivatives come from forward-mode automatic differentiation
(:mod:`dyncli.expr.jet`, no sympy on this path).  Every
coordinate system is treated as a rotating basis with the general operator
(11.4): the basis (e_R, e_θ, e_φ) of §12, (e_r, e_θ, e_3) of §7-§8, or the
fixed e_i, with

    x = x'_i e'_i,   v = δx/δt + ω×x,   a = δv/δt + ω×v,

which reproduces (7.14), (7.16c), the summary of §8 and the table of §12.
Tangential-normal quantities follow §5: e_t = v/|v|, a_t = a·e_t,
a_n = |v×a|/|v| = ṡ²/ρ, e_n = ((v×a)×v)/(|v×a||v|).  The distance (4.5) is
∫|v| dt by adaptive Gauss–Kronrod quadrature (G7/K15, vectorised).
"""

from __future__ import annotations

import numpy as np

from dyncli.result import Result, Series, SolveOptions
from dyncli.topics.kinematics import frame
from dyncli.topics.kinematics.equations import frame_rows
from dyncli.topics.kinematics.motion import BASIS_LABELS, EQUATIONS, ROW_LABELS, STRAIGHT_TOL, motion, per_time


def _times(ts) -> str:
    shown = ", ".join(f"{t:g}" for t in ts[:6])
    return shown + (f", … ({len(ts)} times)" if len(ts) > 6 else "")


def solve(p, options: SolveOptions | None = None) -> Result:
    options = options or SolveOptions()
    if p.instant is not None:
        from dyncli.topics.kinematics import instant

        ins, c = p.instant, p.coordinates
        if c == "path":
            state = instant.Instant(c, v=ins.v, v_dot=ins.v_dot or 0.0, rho=ins.rho, m=p.m)
        else:
            state = instant.Instant(c, tuple(ins.jets(c).items()), m=p.m)
        return instant.solve(state, options)
    coords = p.coordinates
    times = [float(t) for t in p.at]
    t = np.asarray(times, dtype=float)
    res = Result({}, method="closed-form", equations=list(EQUATIONS[coords]))
    rows = motion(coords, p.position, t)
    out, rest, straight, undefined = per_time(rows, times)
    res.results.update(out)
    res.equations += ["5.3", "5.5", "5.14b"]
    if undefined:
        res.warn(f"the position or its derivatives are not finite at t = {_times(undefined)} "
                 "(e.g. sqrt or log at 0, or a division by zero): those entries are null")
    if rest:
        res.warn(f"the point is at rest at t = {_times(rest)}: the tangent e_t is undefined, so "
                 "e_t, e_n, a_t, a_n and rho are null there")
    if straight:
        res.warn(f"zero curvature at t = {_times(straight)} (straight path or inflection point, "
                 f"|v×a| <= {STRAIGHT_TOL:g}·|v||a|): rho and e_n are null and a_n = 0 there")
    if p.m is not None:
        m = p.m
        res.results["F"] = [None if a is None else [m * c for c in a] for a in out["a"]]
        res.results["F_basis"] = [None if a is None else [m * c for c in a] for a in out["a_basis"]]
        res.equations.append("16.1")
    if p.distance is not None:
        t1, t2 = p.distance
        D, err, ok = distance(coords, p.position, t1, t2, p.accuracy.rtol, p.accuracy.atol,
                              p.accuracy.max_steps)
        res.results["distance"] = D
        res.method = "quadrature"
        res.error_estimate = err / abs(D) if D else err      # relative to the distance (docs/accuracy.md)
        res.equations.append("4.5")
        if not ok:
            res.warn(f"distance: the adaptive quadrature did not reach the requested tolerance "
                     f"(estimated error {err:.3g}); the path may have many kinks or a singularity")
    names = [["x", "v", "a", "speed"], ["v_basis", "a_basis"], ["a_t", "a_n", "rho"], ["e_t", "e_n"]]
    titles = ["Cartesian components", f"components on ({', '.join(BASIS_LABELS[coords])})", "tangential and normal (§5)", "tangent and principal normal (Cartesian)"]
    if p.m is not None:
        names.append(["F", "F_basis"])
        titles.append("force F = m a (Cartesian / own basis)")
    if times:
        res.series = [Series("t", times, n, title) for n, title in zip(names, titles)]
    if coords != "cartesian" and times:
        res.views = _views(coords, p, times, rows, options, res)
    return res


# ---------------------------------------------------------------------------
# distance traveled (4.5): the quadrature runner's adaptive Gauss–Kronrod (dyncli/quadrature.py)


#: the speed is evaluated in chunks of this many times, the solve's CPU looked at before each
#: (one pass of the quadrature may hold ~10⁵ times, a second of CPU for a long expression)
CHUNK = 15 * 512


def distance(coords: str, position: dict, t1: float, t2: float, rtol: float, atol: float, max_steps=None):
    """D = ∫|v| dt (4.5): (D, error estimate, converged).  The work is bounded twice: by the
    quadrature's panels (``max_steps``) and by the solve's CPU budget (:mod:`dyncli.cputime`,
    ``accuracy.max_cpu``, default 2 s), refused with a NumericalError naming what to change."""
    from dyncli.quadrature import gauss_kronrod

    def speed(tt):
        parts = []
        for k in range(0, max(len(tt), 1), CHUNK):
            _within_cpu(t1, t2)
            r = motion(coords, position, tt[k:k + CHUNK])
            v = r["v"]   # components on an orthonormal basis: same length
            parts.append(np.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2))
        return parts[0] if len(parts) == 1 else np.concatenate(parts)

    return gauss_kronrod(speed, t1, t2, rtol, atol, max_steps=max_steps, what="the speed", path="distance")


def _within_cpu(t1: float, t2: float) -> None:
    """NumericalError once the solve has used more than its CPU budget (the quadrature's work is
    adaptive, so it is not projected to its end as an ODE's is)."""
    from dyncli import cputime
    from dyncli.errors import NumericalError

    if (limit := cputime.over()) is not None:
        raise NumericalError(
            f"distance: the quadrature of the speed over [{t1:g}, {t2:g}] s took more than the CPU budget of "
            f"{limit:g} s (accuracy.max_cpu) before reaching accuracy.rtol (a path with many kinks or a singular "
            "slope): shorten the interval of distance, loosen accuracy.rtol, or raise accuracy.max_cpu")


# ---------------------------------------------------------------------------
# frame tables (§12 layout): numeric per time, symbolic with --symbolic

def _views(coords, p, times, rows, options, res):
    basis = BASIS_LABELS[coords]
    title = f"{coords} basis"
    views = []
    if options.symbolic:
        view = frame.symbolic_within(lambda: symbolic_view(coords, p, title, basis), res, "the position")
        views += [view] if view is not None else []
    views += frame.numeric_tables(title, times, [(lab, rows[key]) for lab, key in ROW_LABELS], basis)
    return views


def symbolic_view(coords, p, title, basis):
    import sympy as sp

    from dyncli import symbolic
    from dyncli.topics.kinematics.model import COORDINATES

    tsym = symbolic.symbol("t")
    J = {}
    for name in COORDINATES[coords]:
        e = p.position.get(name)
        q = frame.exact_sym(e) if e is not None else sp.Integer(0)
        J[name] = (q, sp.diff(q, tsym), sp.diff(q, tsym, 2))
    r = frame_rows(coords, J, sp)
    w, x, dx, dv = r["omega"], r["x"], r["dx"], r["dv"]
    wx = frame.cross(w, x)
    v = frame.add(dx, wx)
    wv = frame.cross(w, v)
    a = frame.add(dv, wv)
    vals = {"omega": w, "x": x, "dx": dx, "wx": wx, "v": v, "dv": dv, "wv": wv, "a": a}
    params = sorted({n for e in p.position.values() for n in e.params_used})
    note = "formulas in t" + (f"; params: {', '.join(f'{n} = {p.params[n]}' for n in params)}" if params else "")
    return frame.symbolic_table(title + ", formulas", [(lab, vals[key]) for lab, key in ROW_LABELS], basis, note)
