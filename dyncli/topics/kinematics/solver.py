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

from dyncli.errors import InputError
from dyncli.exact import INPUT_ROUNDING
from dyncli.result import Result, Series, SolveOptions
from dyncli.topics.kinematics import equations as eq
from dyncli.topics.kinematics import frame
from dyncli.topics.kinematics.equations import frame_rows, to_cartesian  # noqa: F401
from dyncli.expr.jet import jet

#: a path is taken as straight at an instant (rho = null, e_n = null,
#: a_n = 0) when |v×a| <= STRAIGHT_TOL·|v||a|, i.e. when the angle between v
#: and a is below 1e-12 rad: a_n is then below 1e-12·|a|, under the rounding
#: noise of the components (each carries ~1e-16 relative error of its
#: largest term).
STRAIGHT_TOL = 1e-12

BASIS_LABELS = {
    "cartesian": ("e₁", "e₂", "e₃"),
    "polar": ("e_r", "e_θ", "e₃"),
    "cylindrical": ("e_r", "e_θ", "e₃"),
    "spherical": ("e_R", "e_θ", "e_φ"),
}

EQUATIONS = {
    "cartesian": ["4.2", "4.3"],
    "polar": ["7.3", "7.14", "7.16c"],
    "cylindrical": ["8.1", "8.2", "7.14", "7.16c"],
    "spherical": ["12.1", "12.2", "12.8", "11.4"],
}


def motion(coords: str, position: dict, t: np.ndarray) -> dict:
    """Numeric rows of the frame table and the Cartesian x, v, a at times t
    (non-finite entries where a derivative does not exist)."""
    with np.errstate(all="ignore"):
        return _motion(coords, position, t)


def _motion(coords: str, position: dict, t: np.ndarray) -> dict:
    from dyncli.topics.kinematics.model import COORDINATES

    J = {}
    for name in COORDINATES[coords]:
        e = position.get(name)
        J[name] = jet(e, t) if e is not None else (np.zeros_like(t), np.zeros_like(t), np.zeros_like(t))
    return motion_of_jets(coords, J, t.shape)


def motion_of_jets(coords: str, J: dict, shape) -> dict:
    """The rows of :func:`motion` from each coordinate's (q, q̇, q̈), arrays of the given shape
    (from expressions in t, or the numbers of one instant)."""
    rows = frame_rows(coords, J, np)
    rows = {k: tuple(np.broadcast_to(np.asarray(c, dtype=float), shape) for c in v) if k != "basis" else
            tuple(tuple(np.broadcast_to(np.asarray(c, dtype=float), shape) for c in b) for b in v)
            for k, v in rows.items()}
    w, x, dx, dv = rows["omega"], rows["x"], rows["dx"], rows["dv"]
    wx = frame.cross(w, x)
    v = frame.add(dx, wx)                     # (11.4)
    wv = frame.cross(w, v)
    a = frame.add(dv, wv)                     # (11.4) applied to v
    rows.update({"wx": wx, "v": v, "wv": wv, "a": a})
    B = rows["basis"]
    rows["x_cart"] = to_cartesian(x, B)
    rows["v_cart"] = to_cartesian(v, B)
    rows["a_cart"] = to_cartesian(a, B)
    return rows


def _times(ts) -> str:
    shown = ", ".join(f"{t:g}" for t in ts[:6])
    return shown + (f", … ({len(ts)} times)" if len(ts) > 6 else "")


def solve(p, options: SolveOptions | None = None) -> Result:
    options = options or SolveOptions()
    if p.instant is not None:
        from dyncli.topics.kinematics import instant

        return instant.solve(p, options)
    coords = p.coordinates
    times = [float(t) for t in p.at]
    t = np.asarray(times, dtype=float)
    res = Result({}, method="closed-form", equations=list(EQUATIONS[coords]))
    rows = motion(coords, p.position, t)
    out, rest, straight, undefined = _per_time(rows, times)
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
        res.views = _views(coords, p, times, rows, options)
    return res


def _stack(comps, n):
    return np.stack([np.broadcast_to(np.asarray(c, dtype=float), (n,)) for c in comps], axis=1) + 0.0


def _rows_list(arr, ok):
    vals = arr.tolist()
    for i in np.flatnonzero(~ok):
        vals[i] = None
    return vals


def _per_time(rows, times):
    """Every per-time result, vectorised over the times.

    §5 quantities are computed from the components on the orthonormal own
    basis (rows of Q, Cartesian components), where the algebra is exact for
    the book's examples; e_t and e_n are then returned in Cartesian
    components."""
    n = len(times)
    if n == 0:
        keys = ("x", "v", "a", "v_basis", "a_basis", "speed", "a_t", "a_n", "rho", "e_t", "e_n")
        return {k: [] for k in keys}, [], [], []
    X, V, A = (_stack(rows[k], n) for k in ("x_cart", "v_cart", "a_cart"))
    VB, AB = _stack(rows["v"], n), _stack(rows["a"], n)
    Q = np.stack([_stack(b, n) for b in rows["basis"]], axis=1)      # Q[i, j, :] = e'_j
    fin = lambda M: np.all(np.isfinite(M.reshape(n, -1)), axis=1)    # noqa: E731
    okx, okv, oka = fin(X), fin(V) & fin(VB), fin(A) & fin(AB)
    okq = fin(Q)
    with np.errstate(all="ignore"):
        speed, et, at, c, amag = eq.tangential_normal(VB, AB)
        an = eq.normal_acceleration(c)
        rho = eq.radius_of_curvature(speed, an)
        en = eq.principal_normal(c, an, et)
        et_c = np.einsum("ij,ijk->ik", et, Q) + 0.0
        en_c = np.einsum("ij,ijk->ik", en, Q) + 0.0
    okva = okv & oka & okq
    # at rest: |v| = 0 to within what the rounding of the given t (4 round-offs, dyncli.exact)
    # can change, |a|·δt — so t = pi on x = cos t is a rest point, not a noise direction
    rest_band = INPUT_ROUNDING * np.abs(np.asarray(times, dtype=float)) * amag
    moving = okva & (speed > 0) & ~(speed <= rest_band)
    is_straight = moving & (an <= STRAIGHT_TOL * amag)          # |v×a| <= tol |v||a|
    curved = moving & ~is_straight
    out = {
        "x": _rows_list(X, okx), "v": _rows_list(V, okv), "a": _rows_list(A, oka),
        "v_basis": _rows_list(VB, okv), "a_basis": _rows_list(AB, oka),
        "speed": [float(s_) if ok else None for s_, ok in zip(speed, okv)],
        "a_t": [float(x) if ok else None for x, ok in zip(at, moving)],
        "a_n": [float(x) if c_ else (0.0 if s_ else None) for x, c_, s_ in zip(an, curved, is_straight)],
        "rho": [float(x) if c_ and np.isfinite(x) else None for x, c_ in zip(rho, curved)],
        "e_t": _rows_list(et_c, moving),
        "e_n": _rows_list(en_c, curved & fin(en_c)),
    }
    undefined = [t for t, ok in zip(times, okx & okva) if not ok]
    rest = [t for t, ok, m_ in zip(times, okva, moving) if ok and not m_]
    straight = [t for t, s_ in zip(times, is_straight) if s_]
    return out, rest, straight, undefined


# ---------------------------------------------------------------------------
# distance traveled (4.5): the quadrature runner's adaptive Gauss–Kronrod (dyncli/quadrature.py)


def distance(coords: str, position: dict, t1: float, t2: float, rtol: float, atol: float, max_steps=None):
    """D = ∫|v| dt (4.5): (D, error estimate, converged)."""
    from dyncli.quadrature import gauss_kronrod

    def speed(tt):
        r = motion(coords, position, tt)
        v = r["v"]   # components on an orthonormal basis: same length
        return np.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2)

    return gauss_kronrod(speed, t1, t2, rtol, atol, max_steps=max_steps, what="the speed", path="distance")


# ---------------------------------------------------------------------------
# frame tables (§12 layout): numeric per time, symbolic with --symbolic

ROW_LABELS = [("ω", "omega"), ("x", "x"), ("δx/δt", "dx"), ("ω×x", "wx"), ("v", "v"),
              ("δv/δt", "dv"), ("ω×v", "wv"), ("a", "a")]


def _views(coords, p, times, rows, options):
    basis = BASIS_LABELS[coords]
    title = f"{coords} basis"
    views = []
    if options.symbolic:
        views.append(symbolic_view(coords, p, title, basis))
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
