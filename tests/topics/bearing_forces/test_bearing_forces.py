"""bearing-forces (notes §36, Fig. 36.4, Table 36.1, 36.15, 36.22; issue 21
item 8): the gallery's hand-derived values, the notes' closed forms (with the
erratum of 36.15b), and an independent sympy route: positions in the fixed
frame differentiated symbolically, G and H_O differentiated again, and the
results turned back onto the rotating basis."""

from __future__ import annotations

import math

import pytest

from tests.conftest import PROBLEMS, error_of, run_cli, solve_one_text, solve_path


def test_gallery_bearing_forces():
    free, driven, rotor = (rec["results"] for rec in solve_path(PROBLEMS / "rigid-bodies/bearing-forces.yaml"))
    m, L, a0, ad = 1.0, 0.5, math.pi / 3, -math.pi / 12
    al = [a0 + ad * t for t in (0, 1, 2)]
    # (36.22) and (36.15a) with α̈ = 0; (36.20) M_O = 0
    assert free["omega"] == pytest.approx([2 * (math.sin(a0) / math.sin(a)) ** 2 for a in al], rel=1e-14)
    assert free["omega"][2] == pytest.approx(6.0, rel=1e-14)
    assert [F[1] for F in free["F"]] == pytest.approx([-2 * m * L * ad**2 * math.cos(a) for a in al], rel=1e-14)
    assert all(F[0] == 0.0 and F[2] == 0.0 for F in free["F"])
    assert free["M_O"] == [[0.0, 0.0, 0.0]] * 3 and free["motor_torque"] == [0.0] * 3
    assert [H[1] for H in free["H_O"]] == pytest.approx([0.75] * 3, rel=1e-14)          # (36.21)
    # the corrected (36.15b): M_O = 2 m L² d/dt(ω sin²α) = 2 m L² ω sin 2α α̇ at constant ω
    assert driven["motor_torque"] == pytest.approx([2 * m * L * L * 2 * math.sin(2 * a) * ad for a in al], rel=1e-14)
    assert driven["motor_torque"][1] == pytest.approx(-math.pi / 12, rel=1e-14)
    assert driven["M1"] == driven["M_O"]                                                  # (36.18)
    (F,), (M,), (M1,) = rotor["F"], rotor["M_O"], rotor["M1"]
    s, c = math.sin(math.pi / 3), math.cos(math.pi / 3)
    assert F == pytest.approx([-0.1 * 1e4 * 0.05 * s, 0, 0], rel=1e-14, abs=1e-12)
    assert M == pytest.approx([0, 0, 0.1 * 0.0025 * 1e4 * s * c], rel=1e-14, abs=1e-12)
    assert M1 == pytest.approx([0, 0, 0.1 * 0.0025 * 1e4 * s * c + 0.2 * 0.1 * 1e4 * 0.05 * s], rel=1e-14, abs=1e-12)


def _sympy_loads(masses, omega_expr, times, omega0=None):
    """F and M_O on e'ᵢ by differentiating in the fixed frame (sympy)."""
    import sympy as sp

    t = sp.Symbol("t", real=True)
    th = sp.Function("theta")(t)                   # shaft angle about e2
    R = sp.Matrix([[sp.cos(th), 0, sp.sin(th)], [0, 1, 0], [-sp.sin(th), 0, sp.cos(th)]])
    Xs = []
    for m, L, a in masses:
        a = sp.sympify(a, locals={"t": t})
        Xs.append((m, R * sp.Matrix([L * sp.sin(a), L * sp.cos(a), 0])))
    if omega0 is not None:                         # (36.21) written out independently
        I = sum(m * L**2 * sp.sin(sp.sympify(a, locals={"t": t})) ** 2 for m, L, a in masses)
        w = omega0 * I.subs(t, 0) / I
    else:
        w = sp.sympify(omega_expr, locals={"t": t})
    G = sum((m * X.diff(t) for m, X in Xs), sp.zeros(3, 1))
    H = sum((X.cross(m * X.diff(t)) for m, X in Xs), sp.zeros(3, 1))
    out = []
    for Q in (G.diff(t), H.diff(t)):
        Q = R.T * Q
        Q = Q.subs(sp.Derivative(th, (t, 2)), sp.diff(w, t)).subs(sp.Derivative(th, t), w).subs(th, 0)
        out.append([[float(Q[i].subs(t, tt)) for i in range(3)] for tt in times])
    return out


@pytest.mark.parametrize("case", [
    dict(masses=[(1.0, 0.5, "-(1 - 0.3*sin(t))"), (1.0, 0.5, "1 - 0.3*sin(t)")], omega="2 + t"),
    dict(masses=[(0.7, 0.4, "0.5 + 0.2*t**2"), (1.3, 0.9, "-1.1 + cos(2*t)"), (0.2, 0.3, "2")], omega="3*exp(-t/4)"),
    dict(masses=[(1.0, 0.6, "pi/3 - 0.2*t"), (2.0, 0.3, "-(pi/4 + 0.1*t)")], omega=None, omega0=1.5),
])
def test_against_sympy_fixed_frame(case):
    times = [0.0, 0.7, 1.9]
    ms = "".join(f"  - {{m: {m}, L: {L}, alpha: \"{a}\"}}\n" for m, L, a in case["masses"])
    rate = f"omega: \"{case['omega']}\"\n" if case["omega"] else f"omega0: {case['omega0']}\n"
    r = solve_one_text(f"type: bearing-forces\nmasses:\n{ms}{rate}at: {times}\n")["results"]
    F, M = _sympy_loads(case["masses"], case["omega"], times, case.get("omega0"))
    for k in range(len(times)):
        # closed forms with O(1) terms: a few ulp of the largest term
        scale = 1 + max(abs(x) for x in F[k] + M[k])
        assert r["F"][k] == pytest.approx(F[k], abs=1e-13 * scale)
        assert r["M_O"][k] == pytest.approx(M[k], abs=1e-13 * scale)


def test_extremes():
    # at rest with fixed arms: no load
    r = solve_one_text("type: bearing-forces\nmasses: [{m: 1, L: 1, alpha: 0.5}]\nomega: 0\nat: [0, 1]\n")["results"]
    assert r["F"] == [[0.0, 0.0, 0.0]] * 2 and r["M_O"] == [[0.0, 0.0, 0.0]] * 2 and r["T"] == [0.0, 0.0]
    # a mass on the axis (α = 0) spinning: no load at all; zero-length arm likewise
    r = solve_one_text("type: bearing-forces\nmasses: [{m: 1, L: 1, alpha: 0}, {m: 2, L: 0, alpha: 1}]\n"
                       "omega: 50\nat: [0]\n")["results"]
    assert r["F"] == [[0.0, 0.0, 0.0]] and r["M_O"] == [[0.0, 0.0, 0.0]] and r["I_axis"] == [0.0]
    # free shaft with zero angular momentum: it does not turn
    r = solve_one_text("type: bearing-forces\nmasses: [{m: 1, L: 1, alpha: \"t\"}]\nomega0: 0\nat: [0, 1]\n")["results"]
    assert r["omega"] == [0.0, 0.0]
    # free shaft whose masses reach the axis at a requested time: exit 1, one message
    rc, _, err = run_cli("solve", "-", input="type: bearing-forces\nmasses: [{m: 1, L: 1, alpha: \"1 - t\"}]\n"
                                              "omega0: 1\nat: [0, 1]\n")
    assert rc == 1 and "t = 1" in err and "Traceback" not in err
    # an angle not differentiable at a requested time
    rc, _, err = run_cli("solve", "-", input="type: bearing-forces\nmasses: [{m: 1, L: 1, alpha: \"sqrt(t)\"}]\n"
                                              "omega: 1\nat: [0]\n")
    assert rc == 1 and "not finite" in err


BF = "type: bearing-forces\n"


@pytest.mark.parametrize("text,expected", [
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5}]\nat: [0]\n", "omega: give exactly one of omega"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5}]\nomega: 1\nomega0: 1\nat: [0]\n", "both were given"),
    (BF + "masses: []\nomega: 1\nat: [0]\n", "masses: at least one mass"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5}]\nomega: 1\nat: []\n", "at: give at least one time"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5}]\nomega: 1\n", "at: required field is missing"),
    (BF + "masses: [{m: -1, L: 1, alpha: 0.5}]\nomega: 1\nat: [0]\n", "masses.0.m: must be > 0"),
    (BF + "masses: [{m: 1, L: -1, alpha: 0.5}]\nomega: 1\nat: [0]\n", "masses.0.L: must be >= 0"),
    (BF + "masses: [{m: 1, L: 1, alpha: \"x + t\"}]\nomega: 1\nat: [0]\n", "masses.0.alpha: unknown name 'x'"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5}]\nomega: \"t^2\"\nat: [0]\n", "use ** for powers"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0}]\nomega0: 3\nat: [0]\n", "omega0: every mass starts on the axis"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0, gamma: 1}]\nomega: 1\nat: [0]\n", "masses.0.gamma: unknown field"),
])
def test_invalid(text, expected):
    msg = error_of(text)
    assert expected in msg, msg
    assert "Traceback" not in msg


def test_table_puts_each_time_on_its_own_row():
    # the vectors over time were stacked in the results table with no time beside them
    rc, out, err = run_cli("solve", str(PROBLEMS / "rigid-bodies/bearing-forces.yaml"))
    assert rc == 0, err
    rows = [line.split() for line in out.splitlines() if "[0, -0.0342695, 0]" in line]
    assert rows and all(r[0] == "0" for r in rows)           # F at t = 0 (the gallery's check value)
    assert "F = Ġ [N]" in out and "M₁ = M_O − x₁×F₁ [N·m]" in out


# ---------------------------------------------------------------------------
# two bearings (issue 27): masses at axial positions y and azimuths β


def test_gallery_two_bearing_rotor_by_hand():
    (rec,) = solve_path(PROBLEMS / "rigid-bodies" / "two-bearing-rotor.yaml")
    r = rec["results"]
    w, rad = 100.0, 0.05
    f1, f2 = 0.1 * w * w * rad, 0.2 * w * w * rad          # m ω² r toward the axis: 50 N, 100 N
    F = -f1 + f2                                            # along e'1
    M3 = -(0.25 * -f1 + 0.75 * f2)                          # y e'2 × F1 e'1 = −y F1 e'3
    FB = -M3 / 1.0                                          # bearing B at 1 m: −1·F_B1 = M3
    assert r["F"][0] == pytest.approx([F, 0, 0], abs=1e-12)
    assert r["M_O"][0] == pytest.approx([0, 0, M3], abs=1e-12)
    assert r["F_A"][0] == pytest.approx([F - FB, 0, 0], abs=1e-12)
    assert r["F_B"][0] == pytest.approx([FB, 0, 0], abs=1e-12)
    assert "F1" not in r and "M1" not in r


def _sympy_two_bearings(masses, omega_expr, times, yA, yB):
    """F, M_O on e'ᵢ by differentiating the masses' positions in the fixed frame (sympy), then the
    bearing forces from the 5×5 linear system F_A + F_B = F, (x_A × F_A + x_B × F_B)·e'₁,₃ = M_O·e'₁,₃,
    F_B·e'₂ = 0 (numpy), a formulation of its own."""
    import numpy as np
    import sympy as sp

    t = sp.Symbol("t", real=True)
    th = sp.Function("theta")(t)
    R = sp.Matrix([[sp.cos(th), 0, sp.sin(th)], [0, 1, 0], [-sp.sin(th), 0, sp.cos(th)]])
    Xs = []
    for m, L, a, y, b in masses:
        a = sp.sympify(a, locals={"t": t})
        u = sp.Matrix([sp.cos(b), 0, sp.sin(b)])
        Xs.append((m, R * (y * sp.Matrix([0, 1, 0]) + L * (sp.sin(a) * u + sp.cos(a) * sp.Matrix([0, 1, 0])))))
    w = sp.sympify(omega_expr, locals={"t": t})
    G = sum((m * X.diff(t) for m, X in Xs), sp.zeros(3, 1))
    H = sum((X.cross(m * X.diff(t)) for m, X in Xs), sp.zeros(3, 1))
    out = []
    for tt in times:
        F, M = ([float(q) for q in (R.T * Q.diff(t)).subs(sp.Derivative(th, (t, 2)), sp.diff(w, t))
                 .subs(sp.Derivative(th, t), w).subs(th, 0).subs(t, tt)] for Q in (G, H))
        # unknowns FA1, FA2, FA3, FB1, FB3; y e2 × F = (y F3, 0, −y F1)
        A = np.array([[1, 0, 0, 1, 0], [0, 1, 0, 0, 0], [0, 0, 1, 0, 1],
                      [0, 0, yA, 0, yB], [-yA, 0, 0, -yB, 0]], float)
        x = np.linalg.solve(A, [F[0], F[1], F[2], M[0], M[2]])
        out.append((F, M, [x[0], x[1], x[2]], [x[3], 0.0, x[4]]))
    return out


@pytest.mark.parametrize("case", [
    dict(masses=[(0.3, 0.2, "pi/2", 0.1, 0.0), (0.5, 0.1, "pi/2", 0.6, 2.0)], omega="50", A=-0.2, B=0.9),
    dict(masses=[(1.0, 0.4, "0.6 + 0.3*sin(t)", 0.3, 0.7), (0.4, 0.3, "-1.2 + 0.2*t", -0.5, 4.0)],
         omega="3 + t", A=0.5, B=-0.4),
])
def test_two_bearings_against_sympy_and_a_linear_solve(case):
    times = [0.0, 1.3]
    ms = "".join(f"  - {{m: {m}, L: {L}, alpha: \"{a}\", y: {y}, beta: {b}}}\n" for m, L, a, y, b in case["masses"])
    r = solve_one_text(f"type: bearing-forces\nmasses:\n{ms}omega: \"{case['omega']}\"\n"
                       f"bearings: {{A: {case['A']}, B: {case['B']}}}\nat: {times}\n")["results"]
    for k, (F, M, FA, FB) in enumerate(_sympy_two_bearings(case["masses"], case["omega"], times, case["A"], case["B"])):
        scale = 1 + max(abs(x) for x in F + M + FA + FB)
        assert r["F"][k] == pytest.approx(F, abs=1e-12 * scale)
        assert r["M_O"][k] == pytest.approx(M, abs=1e-12 * scale)
        assert r["F_A"][k] == pytest.approx(FA, abs=1e-12 * scale)
        assert r["F_B"][k] == pytest.approx(FB, abs=1e-12 * scale)


@pytest.mark.parametrize("text,expected", [
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5}]\nomega: 1\nbearings: {A: 0.5, B: 0.5}\nat: [0]\n",
     "bearings.B: bearings A and B are both at 0.5 m"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5}]\nomega: 1\nh: 0.2\nbearings: {A: 0, B: 1}\nat: [0]\n",
     "h: give either h (one bearing at −h e'2) or bearings"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5}]\nomega: 1\nbearings: {A: 0}\nat: [0]\n",
     "bearings.B: required field is missing"),
    (BF + "masses: [{m: 1, L: 1, alpha: 0.5, y: [1]}]\nomega: 1\nat: [0]\n", "masses.0.y: expected a number"),
])
def test_invalid_two_bearings(text, expected):
    msg = error_of(text)
    assert expected in msg, msg
