"""kinematics (§4, §5, §7, §8, §12): references computed independently —
closed forms re-derived here, sympy.physics.vector for the spherical frame,
and a second route (the Cartesian position differentiated directly)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, HealthCheck, given, settings
from hypothesis import strategies as st

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

KIN = PROBLEMS / "kinematics"


def close(a, b, tol=1e-12):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert np.allclose(a, b, rtol=tol, atol=tol), (a, b)


# ---------------------------------------------------------------------------
# the helix (example file): analytic curvature


def test_helix_example_analytic():
    (rec,) = solve_path(KIN / "helix-cylindrical.yaml")
    r = rec["results"]
    a, c, w = 2.0, 0.5, 3.0
    speed = w * math.hypot(a, c)
    rho = (a * a + c * c) / a                  # helix: κ = a/(a² + c²)
    for i, t in enumerate([0.0, 1.0]):
        th = w * t
        close(r["x"][i], [a * math.cos(th), a * math.sin(th), c * th])
        close(r["v"][i], [-a * w * math.sin(th), a * w * math.cos(th), c * w])
        close(r["a"][i], [-a * w * w * math.cos(th), -a * w * w * math.sin(th), 0])
        close(r["v_basis"][i], [0, a * w, c * w])
        close(r["a_basis"][i], [-a * w * w, 0, 0])
        close(r["speed"][i], speed)
        close(r["rho"][i], rho)
        close(r["a_t"][i], 0.0)
        close(r["a_n"][i], speed ** 2 / rho)
        close(r["e_n"][i], [-math.cos(th), -math.sin(th), 0])   # toward the axis
        close(r["e_t"][i], np.array(r["v"][i]) / speed)
        close(r["F"][i], 2.0 * np.array(r["a"][i]))
        close(r["F_basis"][i], [-2.0 * a * w * w, 0, 0])
    close(r["distance"], 2.0 * speed, 1e-10)
    assert rec["method"] == "quadrature"
    assert rec["error_estimate"] is not None and rec["error_estimate"] < 1e-8
    assert "4.5" in rec["equations"]


# ---------------------------------------------------------------------------
# spherical coordinates: sympy.physics.vector as the reference


def _spherical_reference(R_fn, th_fn, ph_fn, times):
    import sympy as sp
    from sympy.physics.vector import ReferenceFrame, dynamicsymbols

    t = dynamicsymbols._t
    R, th, ph = R_fn(t, sp), th_fn(t, sp), ph_fn(t, sp)
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [th, N.z])           # A.x = e_r, A.y = e_θ
    B = A.orientnew("B", "Axis", [-ph, A.y])          # B.x = e_R, B.y = e_θ, B.z = e_φ (elevation φ)
    x = R * B.x
    v = x.dt(N)
    a = v.dt(N)
    w = B.ang_vel_in(N)
    out = []
    for tv in times:
        sub = {t: tv}

        def comps(vec, frame):
            return [float(vec.dot(u).subs(sub).evalf()) for u in (frame.x, frame.y, frame.z)]

        out.append({
            "x": comps(x, N), "v": comps(v, N), "a": comps(a, N),
            "v_basis": comps(v, B), "a_basis": comps(a, B), "omega": comps(w, B),
        })
    return out


def test_spherical_example_vs_sympy_physics_vector():
    (rec,) = solve_path(KIN / "spherical-motion.yaml")
    r = rec["results"]
    ref = _spherical_reference(lambda t, m: 2 + m.Rational(1, 2) * m.sin(t), lambda t, m: 2 * t,
                               lambda t, m: m.Rational(3, 10) * t, [0, 1])
    for i in range(2):
        for k in ("x", "v", "a", "v_basis", "a_basis"):
            close(r[k][i], ref[i][k])
    # the values quoted in the file's comment, from the §12 table at t = 0
    close(r["v_basis"][0], [0.5, 4, 0.6])
    close(r["a_basis"][0], [-8.18, 2, 0.3])


def test_spherical_table_rows_match_section_12():
    """The frame table of the example at t = 1 against the §12 formulas."""
    from dyncli.loader import split_problems, validate
    from dyncli.registry import solver
    from dyncli.result import SolveOptions

    text = (KIN / "spherical-motion.yaml").read_text()
    (lp,), _ = split_problems("s.yaml", text.encode(), KIN)
    validate(lp)
    res = solver("kinematics")(lp.model, SolveOptions())
    tab = res.views[1]
    assert tab.basis == ("e_R", "e_θ", "e_φ")
    rows = dict(tab.rows)
    t = 1.0
    R, Rd, Rdd = 2 + 0.5 * math.sin(t), 0.5 * math.cos(t), -0.5 * math.sin(t)
    th, thd, thdd = 2 * t, 2.0, 0.0
    ph, phd, phdd = 0.3 * t, 0.3, 0.0
    c, s = math.cos(ph), math.sin(ph)
    close(rows["ω"], [thd * s, -phd, thd * c])
    close(rows["x"], [R, 0, 0])
    close(rows["δx/δt"], [Rd, 0, 0])
    close(rows["ω×x"], [0, R * thd * c, R * phd])
    close(rows["v"], [Rd, R * thd * c, R * phd])
    close(rows["δv/δt"], [Rdd, Rd * thd * c + R * thdd * c - R * thd * phd * s, Rd * phd + R * phdd])
    close(rows["ω×v"], [-R * phd ** 2 - R * thd ** 2 * c * c, -R * phd * thd * s + Rd * thd * c,
                        R * thd ** 2 * c * s + Rd * phd])
    close(rows["a"], [Rdd - R * phd ** 2 - R * thd ** 2 * c * c,
                      R * thdd * c + 2 * Rd * thd * c - 2 * R * thd * phd * s,
                      R * phdd + R * thd ** 2 * s * c + 2 * Rd * phd])


def test_spherical_symbolic_table_formulas():
    from dyncli.loader import split_problems, validate
    from dyncli.registry import solver
    from dyncli.result import SolveOptions

    text = (KIN / "spherical-motion.yaml").read_text()
    (lp,), _ = split_problems("s.yaml", text.encode(), KIN)
    validate(lp)
    res = solver("kinematics")(lp.model, SolveOptions(symbolic=True))
    tab = res.views[0]
    rows = dict(tab.rows)
    assert rows["ω"] == ["2*sin(0.3*t)", "-0.3", "2*cos(0.3*t)"]
    assert rows["x"] == ["0.5*sin(t) + 2", "0", "0"]
    assert all(isinstance(c, str) for _, cs in tab.rows for c in cs)


# ---------------------------------------------------------------------------
# polar coordinates (7.14, 7.16c) and a second route (Cartesian directly)


def test_polar_components():
    rec = solve_one_text("""
type: kinematics
coordinates: polar
position: {r: 1 + t**2, theta: t**2}
at: [0.5, 1.5]
""")
    r = rec["results"]
    for i, t in enumerate([0.5, 1.5]):
        rr, rd, rdd = 1 + t * t, 2 * t, 2.0
        th, thd, thdd = t * t, 2 * t, 2.0
        close(r["v_basis"][i], [rd, rr * thd, 0])
        close(r["a_basis"][i], [rdd - rr * thd ** 2, rr * thdd + 2 * rd * thd, 0])
        close(r["x"][i], [rr * math.cos(th), rr * math.sin(th), 0])


coef = st.floats(-2, 2, allow_nan=False, allow_infinity=False)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(a0=st.floats(0.5, 3), a1=coef, w=coef, b=coef, c=coef, t=st.floats(0, 3))
@example(a0=1.0, a1=1.0, w=5e-323, b=0.0, c=0.0, t=0.0)      # a_n = 1e-322: rho beyond a double
@example(a0=1.0, a1=0.0, w=5e-324, b=0.0, c=1.25, t=0.0)     # speed 5e-324: a_n was 2.0, not 2.5
def test_cylindrical_equals_cartesian_route(a0, a1, w, b, c, t):
    """Same motion given in cylindrical and in Cartesian coordinates: the
    frame formulas of §7-§8 and direct differentiation of x agree, and the
    §5 decomposition a = a_t e_t + a_n e_n holds."""
    r = f"({a0!r} + {a1!r}*sin(t))"
    th = f"({w!r}*t + {b!r}*t**2)"
    x3 = f"({c!r}*t**2)"
    cyl = solve_one_text(f"type: kinematics\ncoordinates: cylindrical\nposition: {{r: '{r}', theta: '{th}', x3: '{x3}'}}\nat: [{t!r}]\n")
    car = solve_one_text(f"type: kinematics\nposition: {{x1: '{r}*cos{th}', x2: '{r}*sin{th}', x3: '{x3}'}}\nat: [{t!r}]\n")
    R1, R2 = cyl["results"], car["results"]
    scale = 1 + max(abs(x) for k in ("x", "v", "a") for x in R2[k][0])
    for k in ("x", "v", "a"):
        assert np.allclose(R1[k][0], R2[k][0], rtol=1e-12, atol=1e-12 * scale)
    assert math.isclose(R1["speed"][0], R2["speed"][0], rel_tol=1e-12, abs_tol=1e-12 * scale)
    # invariants of §5
    v, a = np.array(R1["v"][0]), np.array(R1["a"][0])
    if R1["e_t"][0] is not None:
        et = np.array(R1["e_t"][0])
        assert math.isclose(np.linalg.norm(et), 1.0, rel_tol=1e-12)
        recon = R1["a_t"][0] * et
        if R1["e_n"][0] is not None:
            en = np.array(R1["e_n"][0])
            assert abs(et @ en) < 1e-10
            recon = recon + R1["a_n"][0] * en
            # ρ = v²/a_n underflows to 0 for a speed ~1e-252, and is beyond a double (null) for
            # a_n ~1e-322 (e_t, e_n still defined)
            if R1["rho"][0] is not None and R1["rho"][0] > 0:
                assert math.isclose(R1["a_n"][0], R1["speed"][0] * (R1["speed"][0] / R1["rho"][0]), rel_tol=1e-10)
        assert np.allclose(recon, a, atol=1e-9 * (1 + np.linalg.norm(a)))
        vs = v / np.max(np.abs(v))    # scaled first: |v|² of a speed ~1e-252 underflows
        assert R1["a_t"][0] == pytest.approx(vs @ a / np.linalg.norm(vs), rel=1e-9, abs=1e-9 * scale)


# ---------------------------------------------------------------------------
# straight paths, rest, undefined derivatives


def test_straight_line_has_null_rho():
    rec = solve_one_text("""
type: kinematics
position: {x1: t**3, x2: 2*t**3, x3: 3*t**3}
at: [0, 1]
""")
    r = rec["results"]
    assert r["speed"][0] == 0.0 and r["e_t"][0] is None and r["rho"][0] is None
    assert r["rho"][1] is None and r["e_n"][1] is None and r["a_n"][1] == 0.0
    close(r["e_t"][1], np.array([1, 2, 3]) / math.sqrt(14))
    close(r["a_t"][1], 6 * math.sqrt(14))
    assert any("at rest" in w for w in rec["warnings"])
    assert any("zero curvature" in w for w in rec["warnings"])


def test_straight_line_in_polar_is_detected_despite_cancellation():
    # r = 1/cos θ is the line x1 = 1: a_r and a_θ are large and cancel
    rec = solve_one_text("""
type: kinematics
coordinates: polar
position: {r: 1/cos(t), theta: t}
at: [0.3, 1.2]
""")
    r = rec["results"]
    assert r["rho"] == [None, None]
    for i, t in enumerate([0.3, 1.2]):
        assert abs(r["v"][i][0]) < 1e-12 and abs(r["a"][i][0]) < 1e-11
        close(r["v"][i][1], 1 / math.cos(t) ** 2)


def test_undefined_derivative_is_null_with_warning():
    rec = solve_one_text("""
type: kinematics
position: {x1: sqrt(t)}
at: [0, 1]
""")
    r = rec["results"]
    assert r["x"][0] == [0.0, 0.0, 0.0]
    assert r["v"][0] is None and r["a"][0] is None and r["speed"][0] is None
    close(r["v"][1], [0.5, 0, 0])
    assert any("not finite" in w for w in rec["warnings"])


# ---------------------------------------------------------------------------
# distance (4.5)


def test_distance_with_turning_points():
    # x = sin t over [0, 2π] goes 1 out, 2 back, 1 out: D = 4 (|v| has kinks)
    rec = solve_one_text("""
type: kinematics
position: {x1: sin(t)}
distance: [0, 2*pi]
""")
    assert rec["results"]["distance"] == pytest.approx(4.0, rel=1e-9)
    assert rec["error_estimate"] < 1e-7


def test_distance_circle_nonuniform():
    rec = solve_one_text("""
type: kinematics
coordinates: polar
position: {r: 3, theta: t**2}
distance: [1, 2]
""")
    assert rec["results"]["distance"] == pytest.approx(3 * (4 - 1), rel=1e-12)


def test_distance_empty_interval_and_no_times():
    rec = solve_one_text("type: kinematics\nposition: {x1: t}\ndistance: [1, 1]\n")
    assert rec["results"]["distance"] == 0.0
    assert rec["results"]["x"] == []


# ---------------------------------------------------------------------------
# AD jets against sympy derivatives


@pytest.mark.parametrize("text", [
    "0.3*sin(2*t) + t**2", "exp(-t)*cos(3*t)", "sqrt(1 + t**2)", "atan2(sin(t), 2 + cos(t))", "t**t",
    "2**t", "log(2 + t)", "log10(3 + t**3)", "abs(t - 0.5)*t", "tan(t/3)", "asin(t/3)", "acos(t/4)",
    "atan(t)", "sinh(t)", "cosh(t)*tanh(t)", "min(t, 1 - t) + max(t**2, 0.5)", "(1 + t)**(-1.5)",
    "1/(2 + t)**3", "(t + 2)**0.5*t**3", "-t/(1 + t)", "sign(t - 0.3)*t", "t**0", "t**1", "(t - 0.5)**3",
])
def test_jet_matches_symbolic_derivatives(text):
    from dyncli import expr, symbolic
    from dyncli.expr.jet import jet

    e = expr.parse(text, ("t",))
    t = np.linspace(0.05, 0.95, 9)
    f = jet(e, t)
    close(f[0], e.evaluate(t=t), 1e-14)
    for n in (1, 2):
        close(f[n], symbolic.diff(e, "t", n).evaluate(t=t), 1e-12)


JET_TEXTS = [
    "0.3*sin(2*t) + t**2", "exp(-t)*cos(3*t)", "sqrt(1 + t**2)", "atan2(sin(t), 2 + cos(t))", "t**t",
    "2**t", "log(2 + t)", "log10(3 + t**3)", "abs(t - 0.5)*t", "tan(t/3)", "asin(t/3)", "acos(t/4)",
    "atan(t)", "sinh(t)", "cosh(t)*tanh(t)", "min(t, 1 - t) + max(t**2, 0.5)", "(1 + t)**(-1.5)",
    "1/(2 + t)**3", "(t + 2)**0.5*t**3", "-t/(1 + t)", "sign(t - 0.3)*t", "t**0", "t**1", "(t - 0.5)**3",
    # out of range: poles, domain errors, overflow (numpy's inf and nan, never an exception)
    "sqrt(t)", "log(t)", "1/t", "asin(t)", "acos(t)", "exp(1000*t)", "sinh(1000*t)", "cosh(-1000*t)", "t**(1/3)",
    "(-1 - t)**0.5", "t**(-2)", "(t - 1)**(-3)", "sin(1e300*t*1e10)", "t**t", "log10(t)", "atan2(t, 0)",
    "atan2(0*t, t)", "abs(t)", "sign(t)", "2**(1100*t)", "(-2)**(1100*t)",
]


@pytest.mark.parametrize("text", JET_TEXTS)
def test_jet_at_one_time_equals_the_arrays(text):
    """The plain-float jet (one time, no numpy: the closed forms' route) gives the array jet's
    values, and is non-finite exactly where they are (the solvers report those entries null):
    which of inf and nan numpy returns out of range changed between numpy 1 and 2 (e.g.
    (-inf)**0.5 is inf under numpy 1.26, as C's pow, and nan under numpy 2)."""
    from dyncli import expr
    from dyncli.expr.jet import jet, jet_at

    e = expr.parse(text, ("t",))
    ts = [0.0, -0.0, 0.5, 1.0, -1.0, 3.0, -1e-300, 1e300, math.inf]
    arr = jet(e, np.array(ts))
    for i, t in enumerate(ts):
        one = jet_at(e, t)
        for n in range(3):
            a, b = float(arr[n][i]), one[n]
            both_undefined = not math.isfinite(a) and not math.isfinite(b)
            assert both_undefined or a == b or abs(a - b) <= 4e-16 * abs(a), (text, t, n, a, b)


def test_numeric_path_does_not_import_sympy():
    from tests.conftest import run_cli

    code = ("import sys; from tests.conftest import solve_path, PROBLEMS; "
            "solve_path(PROBLEMS / 'kinematics' / 'helix-cylindrical.yaml'); "
            "solve_path(PROBLEMS / 'kinematics' / 'rotating-slot.yaml'); "
            "print('sympy' in sys.modules, 'scipy' in sys.modules)")
    import subprocess
    import sys

    from tests.conftest import ROOT

    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         env={"PYTHONPATH": str(ROOT), "PATH": ""})
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["False", "False"]


# ---------------------------------------------------------------------------
# invalid input


def test_unknown_coordinate_hint():
    msg = error_of("type: kinematics\ncoordinates: spherical\nposition: {r: 1, theta: t, phi: 0}\n")
    assert msg.startswith("bad.yaml:3:")
    assert "position.r" in msg and "did you mean 'R'" in msg


def test_coordinate_of_another_system():
    msg = error_of("type: kinematics\nposition: {r: 1, theta: t}\n")
    assert "position.r" in msg and "set coordinates: polar" in msg


def test_missing_coordinate():
    msg = error_of("type: kinematics\ncoordinates: polar\nposition: {r: 1}\n")
    assert "bad.yaml:3:" in msg and "missing: theta" in msg


def test_expression_with_other_variable():
    msg = error_of("type: kinematics\nposition: {x1: 'x*t'}\n")
    assert "bad.yaml:2:" in msg and "position.x1" in msg and "unknown name 'x'" in msg


def test_power_caret():
    msg = error_of("type: kinematics\nposition: {x1: 't^2'}\n")
    assert "use ** for powers" in msg


def test_bad_distance():
    assert "t1 <= t2" in error_of("type: kinematics\nposition: {x1: t}\ndistance: [2, 1]\n")
    assert "[t1, t2]" in error_of("type: kinematics\nposition: {x1: t}\ndistance: [0, 1, 2]\n")


def test_bad_mass_and_system():
    assert "must be > 0" in error_of("type: kinematics\nposition: {x1: t}\nm: -1\n")
    msg = error_of("type: kinematics\ncoordinates: sphere\nposition: {x1: t}\n")
    assert "coordinates" in msg and "spherical" in msg


def test_distance_through_singularity_is_invalid():
    msg = error_of("type: kinematics\nposition: {x1: 'sqrt(t)'}\ndistance: [-1, 1]\n")
    assert "distance" in msg and "not finite" in msg


def test_tangential_components_on_a_circle():
    """Circle of radius 3 with θ = t²: ṡ = 6t, a_t = s̈ = 6, a_n = ṡ²/ρ = 12t², ρ = 3 (5.14b)."""
    rec = solve_one_text("type: kinematics\ncoordinates: polar\nposition: {r: 3, theta: t**2}\nat: [0.5, 2]\nm: 2\n")
    r = rec["results"]
    for i, t in enumerate([0.5, 2.0]):
        close(r["speed"][i], 6 * t)
        close(r["a_t"][i], 6.0)
        close(r["a_n"][i], 12 * t * t)
        close(r["rho"][i], 3.0)
        close(r["F_basis"][i], [2 * -12 * t * t, 2 * 6.0, 0])
        th = t * t
        close(r["e_t"][i], [-math.sin(th), math.cos(th), 0])
        close(r["e_n"][i], [-math.cos(th), -math.sin(th), 0])


def test_signed_zero_parameters_are_not_confused():
    """k: 0.0 and k: -0.0 compile to different derivative jets (atan2(k, -1) is π and −π), in
    whichever order they are solved in one process (the jets are cached by expression)."""
    text = "type: kinematics\nparams: {{k: {k}}}\nposition: {{x1: 'atan2(k, -1)*t', x2: 't', x3: 0}}\nat: [1]\n"
    for order in (("0.0", "-0.0"), ("-0.0", "0.0")):
        got = [solve_one_text(text.format(k=k))["results"]["x"][0][0] for k in order]
        assert got == [math.copysign(math.pi, float(k)) for k in order], (order, got)
