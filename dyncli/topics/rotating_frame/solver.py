"""Rotating frames (notes §10, §11) — numeric core.

p = p'_i e'_i with ė'_i = ω × e'_i.  The exact derivatives of the
components (forward-mode AD, :mod:`dyncli.expr.jet`, in plain floats at each time) give

    δp/δt = ṗ'_i e'_i (11.5),     ṗ = δp/δt + ω×p (11.4),
    ω̇ = δω/δt (11.10),
    p̈ = δ²p/δt² + ω̇×p + 2ω×δp/δt + ω×(ω×p) (11.11),

and, with the motion of B, v_A = v_B + ṗ, a_A = a_B + p̈ (9.1).  When only
``vB`` is given, a_B follows from it by the general operator,
a_B = δv_B/δt + ω×v_B.
"""

from __future__ import annotations

import math

from dyncli.result import Result, Series, SolveOptions
from dyncli.topics.kinematics import frame
from dyncli.expr.jet import vec_jet_at
from dyncli.topics.rotating_frame import equations as eq
from dyncli.topics.rotating_frame import fixed


#: the rows of the δ/δt table, in the notes' order (label, result name)
TABLE_ROWS = [
    ("ω", "omega"), ("p", "p"), ("δp/δt", "dp_dt"), ("ω×p", "omega_x_p"), ("ṗ", "p_dot"),
    ("δ²p/δt²", "d2p_dt2"), ("ω̇×p", "omega_dot_x_p"), ("2ω×δp/δt", "coriolis"),
    ("ω×(ω×p)", "centripetal"), ("p̈", "p_ddot"),
]
EXTRA_ROWS = [("ω̇ = δω/δt", "omega_dot"), ("v_B", "vB"), ("v_A", "vA"), ("a_B", "aB"), ("a_A", "aA")]
BASIS = ("e'₁", "e'₂", "e'₃")


def terms(w, dw, p, dp, d2p, vB=None, dvB=None, aB=None) -> dict:
    """Every named term from the components (floats or sympy objects), through
    :mod:`dyncli.topics.rotating_frame.equations`."""
    out = {"omega": w, "p": p, "dp_dt": dp, "omega_x_p": frame.cross(w, p), "p_dot": eq.total_rate(dp, w, p),
           "omega_dot": dw, "d2p_dt2": d2p, "omega_dot_x_p": frame.cross(dw, p), "coriolis": eq.coriolis(w, dp),
           "centripetal": eq.centripetal(w, p), "p_ddot": eq.total_acceleration(d2p, dw, w, p, dp)}
    if vB is not None:
        out["vB"] = vB
        out["vA"] = eq.point_velocity(vB, out["p_dot"])
        if aB is None:
            aB = eq.total_rate(dvB, w, vB)               # (11.4) applied to v_B
    if aB is not None:
        out["aB"] = aB
        out["aA"] = eq.point_acceleration(aB, out["p_ddot"])
    return out


def _terms_at(p, t: float) -> dict:
    """Every named term at the time t, in plain floats (exact derivatives of the components)."""
    W, P = vec_jet_at(p.omega, t), vec_jet_at(p.p, t)
    VB = vec_jet_at(p.vB, t) if p.vB is not None else None
    AB = vec_jet_at(p.aB, t) if p.aB is not None else None
    return terms(W[0], W[1], P[0], P[1], P[2], VB[0] if VB else None, VB[1] if VB else None,
                 AB[0] if AB else None)


def solve(p, options: SolveOptions | None = None) -> Result:
    options = options or SolveOptions()
    times = [float(t) for t in p.at]
    at = [_terms_at(p, t) for t in times]
    res = Result({}, method="closed-form", equations=["11.4", "11.5", "11.10", "11.11"])
    bad: set[float] = set()
    given = {"omega_dot"} | ({"vB", "vA"} if p.vB is not None else set()) | (
        {"aB", "aA"} if p.vB is not None or p.aB is not None else set())     # the keys terms() returns
    names = [n for _, n in TABLE_ROWS] + [n for _, n in EXTRA_ROWS if n in given]
    per_time: dict[str, list] = {}
    for name in names:
        vals: list[list[float] | None] = []
        for ti, T in zip(times, at):
            v = [float(c) + 0.0 for c in T[name]]
            finite = all(math.isfinite(c) for c in v)
            if not finite:
                bad.add(ti)
            vals.append(v if finite else None)
        per_time[name] = vals
    for name in ["omega", "p", "dp_dt", "omega_x_p", "p_dot", "omega_dot", "d2p_dt2", "omega_dot_x_p",
                 "coriolis", "centripetal", "p_ddot", "vA", "aA"]:
        if name in per_time:
            res.results[name] = per_time[name]
    if p.vB is not None or p.aB is not None:
        res.equations += ["9.1"]
    wanted = p.fixed or p.basis0 is not None
    if wanted:                           # e'_i turned by (10.4) from basis0: every vector on e_i too
        a = p.accuracy
        fixed.report(fixed.Turning(tuple(p.omega), _basis0(p.basis0), a.method, a.rtol, a.atol, a.max_steps,
                                   a.estimate), res, times)
    if p.vB is not None and p.aB is None:
        res.warn("aB not given: a_B is taken as the derivative of the given v_B, δv_B/δt + ω×v_B (11.4)")
    if bad:
        res.warn("the components or their derivatives are not finite at t = "
                 + ", ".join(f"{x:g}" for x in sorted(bad)) + ": those entries are null")
    if times:
        res.series = [
            Series("t", times, ["omega", "p", "dp_dt"], "ω, p and δp/δt (11.5), components on e'_i"),
            Series("t", times, ["omega_x_p", "p_dot"], "ṗ = δp/δt + ω×p (11.4), components on e'_i"),
            Series("t", times, ["omega_dot", "d2p_dt2", "omega_dot_x_p"], "ω̇ = δω/δt (11.10), δ²p/δt², ω̇×p"),
            Series("t", times, ["coriolis", "centripetal", "p_ddot"], "p̈ (11.11), components on e'_i"),
        ]
        ab: list[str] = [n for n in ("vA", "aA") if n in res.results]
        if ab:
            res.series.append(Series("t", times, ab, "point A (9.1), components on e'_i"))
        if wanted:                       # each table again with the vectors on e_i
            res.series += [Series("t", times, [n + "_fixed" for n in s.names],
                                  (s.title or "").replace("components on e'_i", "") + " — on the fixed basis e_i")
                           for s in list(res.series)]
            res.series.append(Series("t", times, ["basis_fixed"], "e'_1, e'_2, e'_3 on the fixed basis e_i (10.4)"))
    rows = [(lab, per_time[n]) for lab, n in TABLE_ROWS] + [(lab, per_time[n]) for lab, n in EXTRA_ROWS if n in per_time]
    if options.symbolic:
        view = frame.symbolic_within(lambda: symbolic_table(p), res, "the components")
        res.views += [view] if view is not None else []
    if times:
        res.views += frame.numeric_tables("δ/δt table", times, rows, BASIS)
    return res


def _basis0(b):
    """Q0 of a ``basis0`` orientation (None: the identity), rows of floats: the columns are e'_i at
    t = 0 in fixed components."""
    from dyncli.topics.inertia import mat3, rotations

    Q = mat3.eye() if b is None else rotations.from_fields(b.axis, b.angle, b.euler313, b.matrix)
    return tuple(tuple(float(x) for x in row) for row in Q)


def symbolic_table(p):
    """The δ/δt table with formulas in t (sympy, imported only here)."""
    import sympy as sp

    from dyncli import symbolic

    ts = symbolic.symbol("t")

    def comps(exprs):
        return tuple(frame.exact_sym(e) for e in exprs)

    def d(v, n=1):
        return tuple(sp.diff(c, ts, n) for c in v)

    w, pp = comps(p.omega), comps(p.p)
    vB = comps(p.vB) if p.vB is not None else None
    aB = comps(p.aB) if p.aB is not None else None
    T = terms(w, d(w), pp, d(pp), d(pp, 2), vB, d(vB) if vB is not None else None, aB)
    rows = [(lab, T[n]) for lab, n in TABLE_ROWS] + [(lab, T[n]) for lab, n in EXTRA_ROWS if n in T]
    used = set()
    for group in (p.omega, p.p, p.vB or (), p.aB or ()):
        for e in group:
            used |= set(e.params_used)
    note = "formulas in t" + (f"; params: {', '.join(f'{n} = {p.params[n]}' for n in sorted(used))}" if used else "")
    return frame.symbolic_table("δ/δt table, formulas", rows, BASIS, note)
