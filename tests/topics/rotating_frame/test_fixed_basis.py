"""rotating-frame on the fixed basis (`fixed`, `basis0`; issue 27): every vector also as NAME_fixed.
References: the hand derivation of the gallery file (a turntable); sympy: the fixed components
p_e(t) = Q(t) p'(t) written out and differentiated (never the general operator under test);
mpmath's Taylor integrator at 25 digits for an ω whose direction turns on e'_i; and the two
routes of the type against each other (Rodrigues for a constant ω' vs the ODE of 10.4)."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path


def close(a, b, tol):
    assert len(a) == len(b) and all(abs(x - y) <= tol for x, y in zip(a, b)), (a, b)


def test_gallery_turntable_by_hand():
    (rec,) = solve_path(PROBLEMS / "kinematics" / "turntable-fixed-basis.yaml")
    r = rec["results"]
    W, u, t = 2.0, 0.5, 1.0
    c, s = math.cos(W * t), math.sin(W * t)
    e1, e2 = (c, s, 0.0), (-s, c, 0.0)
    comb = lambda a, b: [a * x + b * y for x, y in zip(e1, e2)]      # noqa: E731
    close(r["p_fixed"][1], comb(u * t, 0.0), 1e-15)
    close(r["p_dot_fixed"][1], comb(u, u * W * t), 1e-15)
    close(r["p_ddot_fixed"][1], comb(-u * W * W * t, 2 * u * W), 1e-14)
    close(r["basis_fixed"][1][0], list(e1), 1e-15)
    assert r["p_fixed"][0] == r["p"][0]                      # e'_i = e_i at t = 0
    assert rec["method"] == "closed-form" and "10.4" in rec["equations"]


def _sympy_fixed(omega_dir, rate, Q0, p_exprs, times):
    """ω' = rate·n constant: Q(t) = Q0 exp(rate t [n]×) from sympy's matrix exponential, the fixed
    components Q p' and their first and second time derivatives (sympy)."""
    import sympy as sp

    t = sp.symbols("t")
    n = sp.Matrix(omega_dir) / sp.sqrt(sum(x ** 2 for x in omega_dir))
    K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    Q = sp.Matrix(Q0) * (K * rate * t).exp()
    pe = Q * sp.Matrix([sp.sympify(e, locals={"t": t}) for e in p_exprs])
    out = []
    for tt in times:
        out.append([[float(sp.re(sp.N(c.subs(t, tt), 20))) for c in m] for m in (pe, pe.diff(t), pe.diff(t, 2))])
    return out


def test_three_d_constant_omega_with_basis0_against_sympy():
    Q0 = [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]        # columns e'_i: e2, e3, e1
    p = ["0.3 + 0.2*t", "sin(t)", "0.1*t**2"]
    times = [0.0, 0.4, 1.7]
    rec = solve_one_text("type: rotating-frame\nomega: [1, -2, 0.5]\np: ['0.3 + 0.2*t', 'sin(t)', '0.1*t**2']\n"
                         "vB: [0, 0, 0]\naB: [0, 0, 0]\nbasis0: {matrix: [[0, 0, 1], [1, 0, 0], [0, 1, 0]]}\n"
                         f"at: {times}\n")
    r = rec["results"]
    ref = _sympy_fixed([1, -2, 0.5], math.sqrt(1 + 4 + 0.25), Q0, p, times)
    for k, (pe, pd, pdd) in enumerate(ref):
        close(r["p_fixed"][k], pe, 1e-13)
        close(r["p_dot_fixed"][k], pd, 1e-13)
        close(r["p_ddot_fixed"][k], pdd, 1e-12)
        close(r["vA_fixed"][k], pd, 1e-13)
    assert rec["method"] == "closed-form"


def test_the_two_routes_agree():
    text = ("type: rotating-frame\nomega: [0.3, -1.1, 2]\np: [1, 't', 0]\nbasis0: {euler313: [0.2, 0.7, -0.4]}\n"
            "at: [0.5, 3, 8]\n")
    a = solve_one_text(text)
    b = solve_one_text(text + "accuracy: {method: ode, estimate: true}\n")
    assert a["method"] == "closed-form" and b["method"] == "ode:DOP853"
    for k in range(3):
        for row_a, row_b in zip(a["results"]["basis_fixed"][k], b["results"]["basis_fixed"][k]):
            close(row_a, row_b, 1e-8)          # rtol 1e-10 over |ω| t ≤ 20 rad
    assert b["error_estimate"] < 1e-8


def test_turning_omega_against_mpmath():
    """ω' = [sin t, 0.5, 1]: the direction turns on e'_i, so only (10.4) integrated gives Q;
    mpmath's Taylor-series ODE solver at 25 digits is the reference."""
    times = [0.8, 2.5]
    rec = solve_one_text("type: rotating-frame\nomega: ['sin(t)', 0.5, 1]\np: [1, 0, 0]\nfixed: true\n"
                         f"at: {times}\n")
    assert rec["method"] == "ode:DOP853" and rec["error_estimate"] is not None
    with mp.workdps(25):
        def rhs(t, y):
            w = (mp.sin(t), mp.mpf("0.5"), mp.mpf(1))
            W = ((0, -w[2], w[1]), (w[2], 0, -w[0]), (-w[1], w[0], 0))
            return [sum(y[3 * i + k] * W[k][j] for k in range(3)) for i in range(3) for j in range(3)]

        sol = mp.odefun(rhs, 0, [1, 0, 0, 0, 1, 0, 0, 0, 1])
        for k, tt in enumerate(times):
            Q = sol(tt)
            rows = [[float(Q[3 * i + j]) for i in range(3)] for j in range(3)]     # e'_j = column j
            for got, want in zip(rec["results"]["basis_fixed"][k], rows):
                close(got, want, 1e-8)                                          # rtol 1e-10, a few steps
            close(rec["results"]["p_fixed"][k], rows[0], 1e-8)                  # p = e'_1


def test_without_fixed_nothing_changes():
    r = solve_one_text("type: rotating-frame\nomega: [0, 0, 1]\np: [1, 0, 0]\nat: [1]\n")["results"]
    assert not any(k.endswith("_fixed") for k in r)


@pytest.mark.parametrize("text,field,fix", [
    ("basis0: {axis: [0, 0, 1]}\n", "basis0", "needs an 'angle'"),
    ("basis0: {matrix: [[1, 0, 0], [0, 1, 0], [0, 0, 2]]}\n", "basis0", "not orthonormal"),
    ("basis0: {axis: [0, 0, 1], angle: 1, euler313: [0, 0, 0]}\n", "basis0", "exactly one of"),
    ("fixed: 2\n", "fixed", ""),
    ("accuracy: {method: DOP853}\n", "accuracy.method", "choose one of: auto, ode"),
])
def test_invalid_fixed_basis(text, field, fix):
    msg = error_of("type: rotating-frame\nomega: [0, 0, 1]\np: [1, 0, 0]\nat: [1]\n" + text)
    assert f" {field}" in msg and fix in msg, msg


def test_exact_route_imports_no_numpy():
    """A constant ω' turns the basis in plain floats: the type stays without numpy and scipy."""
    import subprocess
    import sys

    from tests.conftest import ROOT

    code = ("import sys; from dyncli.loader import load_paths; from dyncli.run import solve_one; "
            "ps, _ = load_paths(['problems/kinematics/turntable-fixed-basis.yaml']); "
            "[solve_one(lp) for lp in ps]; print('numpy' in sys.modules, 'scipy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         env={"PYTHONPATH": str(ROOT), "PATH": ""})
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["False", "False"]
