"""rotating-frame (§10, §11): references from sympy.physics.vector and from
direct differentiation of the rotated position; snapshots of the δ/δt table."""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.conftest import PROBLEMS, error_of, run_cli, solve_one_text, solve_path

KIN = PROBLEMS / "kinematics"
SNAP = Path(__file__).parent / "snapshots"


def close(a, b, tol=1e-12):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert np.allclose(a, b, rtol=tol, atol=tol), (a, b)


# ---------------------------------------------------------------------------
# Fig. 9.1: the rotating slot, checked in the fixed frame


def test_rotating_slot_vs_fixed_frame():
    """x_A = x_B + s(t) e'_1 written in the fixed basis, differentiated
    directly, then projected on e'_i (no general operator involved)."""
    import sympy as sp

    t = sp.Symbol("t", real=True)
    R, w0, s0, c = sp.Rational(1, 2), 2, sp.Rational(1, 10), sp.Rational(1, 20)
    th = -w0 * t                                   # e'_1 turns clockwise
    e1p = sp.Matrix([sp.cos(th), sp.sin(th), 0])
    e2p = sp.Matrix([-sp.sin(th), sp.cos(th), 0])
    e3p = sp.Matrix([0, 0, 1])
    s = s0 + c * sp.sin(3 * t)
    xB = sp.Matrix([R * w0 * t, R, 0])             # rolling: center at height R
    xA = xB + s * e1p
    p = xA - xB
    refs = {"vA": xA.diff(t), "aA": xA.diff(t, 2), "p_dot": p.diff(t), "p_ddot": p.diff(t, 2), "p": p}
    (rec,) = solve_path(KIN / "rotating-slot.yaml")
    r = rec["results"]
    for i, tv in enumerate([0, 0.5]):
        for name, vec in refs.items():
            comps = [float(vec.dot(e).subs(t, tv)) for e in (e1p, e2p, e3p)]
            close(r[name][i], comps)
    # the numbers quoted in the example's comment
    close(r["vA"][0], [1.15, -0.2, 0])
    close(r["aA"][0], [-0.4, -0.6, 0])
    close(r["coriolis"][0], [0, -0.6, 0])
    close(r["centripetal"][0], [-0.4, 0, 0])
    assert rec["warnings"] == []


# ---------------------------------------------------------------------------
# a general 3-1-3 rotation: ω from sympy.physics.vector, p̈ by differentiating
# the rotated position twice


def _general_case():
    import sympy as sp
    from sympy.physics.vector import ReferenceFrame, dynamicsymbols

    t = dynamicsymbols._t
    psi, th, phi = sp.Rational(3, 10) * t, sp.Rational(1, 2) + sp.sin(t) / 5, t ** 2 / 2
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Body", [psi, th, phi], "313")
    w = B.ang_vel_in(N)
    wB = [sp.simplify(w.dot(u)) for u in (B.x, B.y, B.z)]
    pB = [1 + t, sp.sin(2 * t), t ** 2 / 4]
    p = pB[0] * B.x + pB[1] * B.y + pB[2] * B.z
    pN = sp.Matrix([p.dot(u) for u in (N.x, N.y, N.z)])      # fixed components
    C = sp.Matrix([[u.dot(n) for n in (N.x, N.y, N.z)] for u in (B.x, B.y, B.z)])  # rows: e'_i in N
    vel = C * pN.diff(t)
    acc = C * pN.diff(t, 2)
    pdot_pv = p.dt(N)                                          # sympy.physics.vector's operator
    return t, wB, pB, vel, acc, pdot_pv, B


def test_general_rotation_vs_sympy_physics_vector():
    import sympy as sp

    t, wB, pB, vel, acc, pdot_pv, B = _general_case()
    omega = "[" + ", ".join(f"'{sp.sstr(c)}'" for c in wB) + "]"
    pstr = "[" + ", ".join(f"'{sp.sstr(c)}'" for c in pB) + "]"
    times = [0.0, 0.7, 1.9]
    rec = solve_one_text(f"type: rotating-frame\nomega: {omega}\np: {pstr}\nat: {times}\n")
    r = rec["results"]
    for i, tv in enumerate(times):
        close(r["omega"][i], [float(c.subs(t, tv)) for c in wB])
        close(r["p_dot"][i], [float(c.subs(t, tv)) for c in vel])
        close(r["p_dot"][i], [float(pdot_pv.dot(u).subs(t, tv)) for u in (B.x, B.y, B.z)])
        close(r["p_ddot"][i], [float(c.subs(t, tv)) for c in acc], 1e-11)
        # the pieces add up as (11.11) says
        parts = sum(np.array(r[k][i]) for k in ("d2p_dt2", "omega_dot_x_p", "coriolis", "centripetal"))
        close(parts, r["p_ddot"][i])


# ---------------------------------------------------------------------------
# identities (hypothesis)

small = st.floats(-3, 3, allow_nan=False, allow_infinity=False)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(w=st.lists(small, min_size=3, max_size=3), p0=st.lists(small, min_size=3, max_size=3),
       p1=st.lists(small, min_size=3, max_size=3), k=small, t=st.floats(0, 2))
def test_identities(w, p0, p1, k, t):
    """ω = w + k t e'_3 (so ω̇ = k e'_3), p = p0 + p1 t:
    δ²p/δt² = 0, ω̇×p, d(p·p)/dt = 2 p·δp/δt, ω·(ω×p) = 0, and the named
    terms against their definitions."""
    om = [repr(w[0]), repr(w[1]), f"{w[2]!r} + {k!r}*t"]
    pp = [f"{a!r} + {b!r}*t" for a, b in zip(p0, p1)]
    rec = solve_one_text(f"type: rotating-frame\nomega: {om}\np: {pp}\nat: [{t!r}]\n")
    r = {k_: np.array(v[0]) for k_, v in rec["results"].items()}
    W = np.array([w[0], w[1], w[2] + k * t])
    P = np.array(p0) + np.array(p1) * t
    dP = np.array(p1)
    tol = 1e-12 * (1 + np.abs(W).max()) ** 2 * (1 + np.abs(P).max() + np.abs(dP).max())
    assert np.allclose(r["omega"], W, atol=tol) and np.allclose(r["p"], P, atol=tol)
    assert np.allclose(r["dp_dt"], dP, atol=tol)
    assert np.allclose(r["d2p_dt2"], 0, atol=tol)
    assert np.allclose(r["omega_dot"], [0, 0, k], atol=tol)
    assert np.allclose(r["omega_x_p"], np.cross(W, P), atol=tol)
    assert np.allclose(r["omega_dot_x_p"], np.cross([0, 0, k], P), atol=tol)
    assert np.allclose(r["coriolis"], 2 * np.cross(W, dP), atol=tol)
    assert np.allclose(r["centripetal"], np.cross(W, np.cross(W, P)), atol=tol)
    assert abs(P @ r["p_dot"] - P @ dP) <= tol * 10
    assert abs(W @ r["omega_x_p"]) <= tol * 10


def test_vB_only_derives_aB():
    rec = solve_one_text("""
type: rotating-frame
omega: [0, 0, 2]
p: [1, 0, 0]
vB: [3, 0, 0]
at: [0]
""")
    r = rec["results"]
    close(r["vA"][0], [3, 2, 0])
    # a_B = δv_B/δt + ω×v_B = [0, 6, 0]; p̈ = ω×(ω×p) = [-4, 0, 0]
    close(r["aA"][0], [-4, 6, 0])
    assert any("aB not given" in w for w in rec["warnings"])


def test_aB_only_and_no_times():
    rec = solve_one_text("type: rotating-frame\nomega: [0, 0, 1]\np: [1, 0, 0]\naB: [0, -9.81, 0]\nat: [1]\n")
    assert "vA" not in rec["results"]
    close(rec["results"]["aA"][0], [-1, -9.81, 0])
    rec = solve_one_text("type: rotating-frame\nomega: [0, 0, 1]\np: [1, 0, 0]\n")
    assert rec["results"]["p"] == []


def test_nonfinite_is_null():
    rec = solve_one_text("type: rotating-frame\nomega: [0, 0, 1]\np: ['sqrt(t)', 0, 0]\nat: [0, 1]\n")
    r = rec["results"]
    assert r["p"][0] == [0.0, 0.0, 0.0] and r["dp_dt"][0] is None and r["p_ddot"][0] is None
    close(r["dp_dt"][1], [0.5, 0, 0])
    assert any("not finite" in w for w in rec["warnings"])


# ---------------------------------------------------------------------------
# invalid input


def test_invalid_inputs():
    msg = error_of("type: rotating-frame\nomega: [0, 1]\np: [1, 0, 0]\n")
    assert msg.startswith("bad.yaml:2:") and "omega" in msg and "3" in msg
    msg = error_of("type: rotating-frame\nomega: [0, 0, 1]\np: [1, 'x', 0]\n")
    assert "bad.yaml:3:" in msg and "component 2" in msg and "unknown name 'x'" in msg
    msg = error_of("type: rotating-frame\nomega: [0, 0, 1]\n")
    assert "p" in msg and "required" in msg
    msg = error_of("type: rotating-frame\nomega: [0, 0, 1]\np: [1, 0, 0]\nvb: [1, 0, 0]\n")
    assert "unknown field 'vb'" in msg and "vB" in msg


# ---------------------------------------------------------------------------
# snapshots of the table layout (numeric and --symbolic)


def _tables(out: str, start: str) -> str:
    lines = out.splitlines()
    i = next(k for k, line in enumerate(lines) if start in line)
    keep = [line.rstrip() for line in lines[i:] if not line.startswith("warning:") and not line.startswith(
        "problems/")]
    return "\n".join(keep).rstrip() + "\n"


@pytest.mark.parametrize("name,args,start", [
    ("rotating-slot", ["problems/kinematics/rotating-slot.yaml"], "δ/δt table"),
    ("rotating-slot-symbolic", ["problems/kinematics/rotating-slot.yaml", "--symbolic"], "δ/δt table"),
    ("spherical-symbolic", ["problems/kinematics/spherical-motion.yaml", "--symbolic"], "spherical basis"),
])
def test_table_snapshot(name, args, start):
    rc, out, err = run_cli("solve", *args)
    assert rc == 0, err
    got = _tables(out, start)
    path = SNAP / f"{name}.txt"
    if os.environ.get("UPDATE_SNAPSHOTS"):
        SNAP.mkdir(exist_ok=True)
        path.write_text(got)
    assert path.exists(), (f"snapshot {path.relative_to(SNAP.parents[3])} is missing; review the table below and "
                           f"create it with: UPDATE_SNAPSHOTS=1 python -m pytest -n 0 tests/topics/rotating_frame/test_rotating_frame.py -k snapshot\n{got}")
    assert got == path.read_text(), f"table layout changed; rerun with UPDATE_SNAPSHOTS=1 if intended\n{got}"


@pytest.mark.parametrize("path,kind", [(KIN / "rotating-slot.yaml", "rotating-frame"),
                                       (KIN / "spherical-motion.yaml", "kinematics")])
def test_symbolic_entries_evaluate_to_numeric_table(path, kind):
    """Each formula of the --symbolic table, read back by dyncli's own
    expression parser, gives the numeric table's entry at every time."""
    from dyncli import expr
    from dyncli.expr import resolve_params
    from dyncli.loader import split_problems, validate
    from dyncli.registry import solver
    from dyncli.result import SolveOptions

    (lp,), _ = split_problems("x.yaml", path.read_bytes(), KIN)
    validate(lp)
    res = solver(kind)(lp.model, SolveOptions(symbolic=True))
    sym, numeric = res.views[0], res.views[1:]
    params = resolve_params(lp.model.params)
    times = lp.model.at
    for tab, tv in zip(numeric, times):
        assert tab.title.endswith(f"t = {tv:g}")
        for (lab_s, f_s), (lab_n, v_n) in zip(sym.rows, tab.rows):
            assert lab_s == lab_n
            got = [expr.parse(f, ("t",), params).evaluate(t=np.array(tv)) for f in f_s]
            close(got, v_n, 1e-12)
