"""constrained-particle (notes §16 problem II, §18): the gallery files
bead-on-a-hoop.yaml and rotating-slot.yaml against closed forms and mpmath,
the energy route against the ODE route, the extremes and invalid input."""

from __future__ import annotations

import functools
import math

import mpmath as mp
import numpy as np
import pytest

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path, solve_text

G = 9.81
# ODE route at the default rtol 1e-10 over a few periods: ~1e-9 relative
ODE_REL = 1e-8


def close(a, b, rel=ODE_REL, abs_=1e-9):
    np.testing.assert_allclose(np.asarray(a, float), np.asarray(b, float), rtol=rel, atol=abs_)


@functools.lru_cache(maxsize=None)
def gallery(name):
    recs = solve_path(PROBLEMS / "particle" / name)
    for r in recs:
        assert r.get("error") is None, r.get("error")
    return recs


HOOP = """
type: constrained-particle
m: 0.1
curve: {{x1: "0.5*sin(q)", x2: 0, x3: "-0.5*cos(q)"}}
q_range: [-pi, pi]
{extra}
"""


# --- bead-on-a-hoop.yaml --------------------------------------------------------

def test_fixed_hoop_period_by_elliptic_integral():
    rec = gallery("bead-on-a-hoop.yaml")[0]
    r = rec["results"]
    assert rec["method"] == "quadrature"
    with mp.workdps(30):
        P = 4 * mp.sqrt(mp.mpf("0.5") / mp.mpf("9.81")) * mp.ellipk(mp.sin(mp.mpf(1) / 2) ** 2)
    # Gauss-Jacobi of an analytic integrand: a few ulp of the period
    assert r["period"] == pytest.approx(float(P), rel=1e-13)
    close(r["q_turn"], [-1, 1], rel=0, abs_=1e-13)
    close(r["N"][0], [0, 0.1 * G * math.cos(1), 0], rel=1e-14, abs_=1e-15)
    assert r["energy_residual"] < 1e-13 and rec["error_estimate"] < 1e-12
    # a fixed curve does no work on the bead
    assert r["W_N"] == [0, 0, 0, 0]
    eq = r["equilibria"]
    assert [e["stable"] for e in eq] == [False, True]
    close(eq[1]["omega_small"], math.sqrt(G / 0.5), rel=1e-8)


def test_fixed_hoop_quadrature_against_mpmath_pendulum():
    """q̈ = −(g/R) sin q integrated by mpmath's Taylor method (a second method)."""
    r = gallery("bead-on-a-hoop.yaml")[0]["results"]
    with mp.workdps(20):
        sol = mp.odefun(lambda t, y: [y[1], -mp.mpf("19.62") * mp.sin(y[0])], 0, [mp.mpf(1), mp.mpf(0)])
        ref = [sol(t) for t in (0.5, 1, 2)]
    for i, (q, qd) in enumerate(ref, start=1):
        close(r["q"][i], float(q), rel=1e-12, abs_=1e-12)
        close(r["q_dot"][i], float(qd), rel=1e-12, abs_=1e-12)


def test_rotating_hoop_equilibria_and_stability():
    recs = gallery("bead-on-a-hoop.yaml")
    eq = recs[1]["results"]["equilibria"]
    qs = math.acos(G / (0.5 * 36))
    close([e["q"] for e in eq], [-math.pi, -qs, 0, qs], rel=1e-13, abs_=1e-13)
    assert [e["stable"] for e in eq] == [False, True, False, True]
    # the Richardson difference of G: ~1e-9 relative
    close(eq[3]["omega_small"], 6 * math.sin(qs), rel=1e-8)
    close(eq[3]["x"], [0.5 * math.sin(qs), 0, -0.5 * math.cos(qs)], rel=1e-13)
    eq = recs[2]["results"]["equilibria"]
    assert [(e["q"], e["stable"]) for e in eq] == [(-math.pi, False), (0.0, True)]
    close(eq[1]["omega_small"], math.sqrt(G / 0.5 - 16), rel=1e-8)


def test_rotating_hoop_motion_against_mpmath():
    """Relative to the hoop: q̈ = sin q (ω² cos q − g/R); the hoop's normal
    force does work T − T1 − (V − V1) (no other force does)."""
    rec = gallery("bead-on-a-hoop.yaml")[1]
    r = rec["results"]
    with mp.workdps(20):
        w2, gR = mp.mpf(36), mp.mpf("19.62")
        sol = mp.odefun(lambda t, y: [y[1], mp.sin(y[0]) * (w2 * mp.cos(y[0]) - gR)], 0, [mp.mpf("0.3"), mp.mpf(0)])
        ref = [sol(t) for t in (0.5, 1)]
    for i, (q, qd) in enumerate(ref, start=1):
        close(r["q"][i], float(q), rel=ODE_REL, abs_=ODE_REL)
        close(r["q_dot"][i], float(qd), rel=ODE_REL, abs_=ODE_REL)
    for i in range(3):
        close(r["W_N"][i], r["E"][i] - r["E"][0], rel=1e-9, abs_=1e-10)
    # constant ω, gravity along the axis: the Jacobi integral holds, and the energy route is exact
    assert rec["method"] == "quadrature"


def test_rotating_hoop_period_from_the_jacobi_integral():
    """The relative motion's energy ½ m R² q̇² − ½ m ω² R² sin² q − m g R cos q is constant (the
    Jacobi integral): q oscillates between q0 = 0.3 and the other root q1 of q̇² = 0, and the period
    is 2 ∫ dq/q̇ over [q0, q1] (mpmath's tanh-sinh, which takes the turning points' inverse square
    roots).  The hoop's normal force does work W_N = ω ΔH_axis = ΔE (only gravity, conservative,
    acts besides it)."""
    rec = gallery("bead-on-a-hoop.yaml")[1]
    r = rec["results"]
    with mp.workdps(30):
        w2, gR, q0 = mp.mpf(36), mp.mpf("19.62"), mp.mpf("0.3")
        qd2 = lambda q: w2 * (mp.sin(q) ** 2 - mp.sin(q0) ** 2) + 2 * gR * (mp.cos(q) - mp.cos(q0))  # noqa: E731
        q1 = mp.findroot(qd2, 1.4)
        period = 2 * mp.quad(lambda q: 1 / mp.sqrt(qd2(q)), [q0, q1])
    close(r["q_turn"], [0.3, float(q1)], rel=1e-12)
    close(r["period"], float(period), rel=1e-11)
    assert r["energy_residual"] <= 1e-12 * abs(r["E"][0]) + 1e-15


def test_a_turning_curve_with_a_find_of_a_turning_component_takes_the_ode():
    """x.0 of the fixed frame turns with the hoop (a function of t as well as of q): not searched
    along the energy route's legs, so `auto` takes the ODE; q is searched on the energy route."""
    base = HOOP.format(extra="q0: 0.3\nrotation: {omega: 6}\nforces: [{kind: gravity}]\nt_end: 1\nfind: [{max: %s}]")
    assert solve_one_text(base % "x.0")["method"] == "ode:DOP853"
    assert solve_one_text(base % "q")["method"] == "quadrature"


# --- rotating-slot.yaml ------------------------------------------------------------

def test_smooth_rotating_slot_closed_forms():
    r = gallery("rotating-slot.yaml")[0]["results"]
    m, w, r0 = 0.2, 3.0, 0.1
    for i, t in enumerate([0, 0.5, 0.9]):
        rr, rd = r0 * math.cosh(w * t), r0 * w * math.sinh(w * t)
        close(r["q"][i], rr)
        close(r["q_dot"][i], rd)
        close(r["x"][i], [rr * math.cos(w * t), rr * math.sin(w * t), 0])
        close(r["N"][i], [0, m * G, -2 * m * w * rd])
        close(r["W_N"][i], m * w * w * r0 * r0 * math.sinh(w * t) ** 2)
        assert r["kappa"][i] == 0
    assert [(e["q"], e["stable"]) for e in r["equilibria"]] == [(0.0, False)]


def test_rough_rotating_slot_against_mpmath():
    r = gallery("rotating-slot.yaml")[1]["results"]
    m, w, mu = 0.2, 3, 0.2
    with mp.workdps(20):
        def f(t, y):
            N = m * mp.sqrt(mp.mpf("9.81") ** 2 + (2 * w * y[1]) ** 2)
            return [y[1], w * w * y[0] - mu * N / m]

        sol = mp.odefun(f, 0, [mp.mpf("0.5"), mp.mpf(0)])
        ref = [sol(t) for t in (0.2, 0.4)]
    for i, (q, qd) in enumerate(ref, start=1):
        close(r["q"][i], float(q))
        close(r["q_dot"][i], float(qd))
        close(r["friction"][i], -mu * m * math.sqrt(G ** 2 + (2 * w * float(qd)) ** 2))
    assert r["t_rest"] is None
    assert r["energy_residual"] < 1e-9


# --- the two routes agree ------------------------------------------------------------

def test_quadrature_and_ode_routes_agree_with_a_spring():
    text = HOOP.format(extra="q0: 2.5\nq_dot0: -1\nforces: [{kind: gravity}, {kind: spring, anchor: [0, 0, 0.5], k: 3, L: 0.2}]\n"
                             "at: [0, 0.3, 1.1, 2.7]")
    a = solve_one_text(text)
    b = solve_one_text(text + "accuracy: {method: ode}\n")
    assert a["method"] == "quadrature" and b["method"] == "ode:DOP853"
    close(a["results"]["q"], b["results"]["q"], rel=1e-8, abs_=1e-8)
    close(a["results"]["N"], b["results"]["N"], rel=1e-8, abs_=1e-8)


def test_revolving_bead_goes_round_the_hoop():
    """Enough energy to pass the top: q grows without bound; the time of one
    revolution is ∫ dq/q̇ over the loop (mpmath quad)."""
    rec = solve_one_text(HOOP.format(extra="q0: 0\nq_dot0: 10\nforces: [{kind: gravity}]\nat: [0, 1, 3]"))
    r = rec["results"]
    with mp.workdps(20):
        def qd(q):   # ½ R² q̇² − g R cos q = ½ R² q̇0² − g R, R = ½
            return mp.sqrt(mp.mpf(100) + 2 * mp.mpf("19.62") * (mp.cos(q) - 1))
        P = mp.quad(lambda q: 1 / qd(q), [-mp.pi, 0, mp.pi])
    assert r["period"] == pytest.approx(float(P), rel=1e-12)
    assert r["q"][2] > 2 * math.pi                   # more than one loop
    b = solve_one_text(HOOP.format(extra="q0: 0\nq_dot0: 10\nforces: [{kind: gravity}]\nat: [0, 1, 3]\n"
                                         "accuracy: {method: ode}"))
    close(r["q"], b["results"]["q"], rel=1e-8)


# --- extremes ------------------------------------------------------------------------

def test_at_rest_in_equilibrium_stays():
    r = solve_one_text(HOOP.format(extra="forces: [{kind: gravity}]\nat: [0, 5]"))["results"]
    assert r["q"] == [0.0, 0.0] and r["q_dot"] == [0.0, 0.0]
    close(r["N"][1], [0, 0.1 * G, 0], rel=1e-15)


def test_zero_rate_rotation_is_the_fixed_curve():
    a = solve_one_text(HOOP.format(extra="q0: 1\nforces: [{kind: gravity}]\nat: [0, 0.7]"))
    b = solve_one_text(HOOP.format(extra="q0: 1\nrotation: {omega: 0}\nforces: [{kind: gravity}]\nat: [0, 0.7]"))
    assert b["method"] == "quadrature"
    close(a["results"]["q"], b["results"]["q"], rel=1e-13)
    assert b["results"]["W_N"][1] == pytest.approx(0, abs=1e-12)


def test_critical_rate_is_decided_by_the_sign_of_G():
    """ω² = g/R exactly: G′(0) = 0 at the bottom, so the linearisation cannot tell, but G ≈ −m g q³/2
    is restoring on both sides: stable (issue #28: decided by G's sign), with no linear frequency."""
    r = solve_one_text(HOOP.format(extra="rotation: {omega: \"sqrt(19.62)\"}\nforces: [{kind: gravity}]\nat: [0, 0.1]"))
    bottom = [e for e in r["results"]["equilibria"] if e["q"] == 0][0]
    assert bottom["stable"] is True and bottom["omega_small"] == 0


def test_free_straight_wire_and_its_end():
    text = "type: constrained-particle\nm: 1\ncurve: {x1: q, x2: \"2*q\", x3: 0}\nq_range: [0, 3]\nq_dot0: 1\nat: [0, 2]\n"
    rec = solve_one_text(text)
    assert rec["method"] == "quadrature"
    close(rec["results"]["q"], [0, 2], rel=1e-13)
    close(rec["results"]["s"], [0, 2 * math.sqrt(5)], rel=1e-13)
    assert not any("straight" in w for w in rec["warnings"])   # nothing a student could act on
    out = solve_text(text.replace("at: [0, 2]", "at: [0, 4]"))[0]
    assert "reaches the end of the wire (q = 3) at t = 3 s" in out["error"]


def test_rough_hoop_sticks_when_friction_holds():
    """At rest at q0 on a fixed rough hoop: tangential m g sin q0 against
    μ N = μ m g cos q0 — sticks when μ ≥ tan q0."""
    r = solve_one_text(HOOP.format(extra="q0: 0.3\nforces: [{kind: gravity}, {kind: friction, mu: 0.31}]\nat: [0, 1]"))["results"]
    assert r["t_rest"] == 0 and r["q"] == [0.3, 0.3]
    close(r["friction"][1], 0.1 * G * math.sin(0.3), rel=1e-12)
    r = solve_one_text(HOOP.format(extra="q0: 0.3\nforces: [{kind: gravity}, {kind: friction, mu: 0.1}]\nat: [0, 10]"))["results"]
    assert r["q"][1] != 0.3 and r["W_nc"][1] < 0 and r["t_rest"] is not None


def test_prescribed_rate_has_no_relative_equilibria():
    rec = solve_one_text(HOOP.format(extra="q0: 0.2\nrotation: {omega: \"2*t\"}\nforces: [{kind: gravity}]\nat: [0, 1]"))
    assert rec["results"]["equilibria"] is None
    assert any("depends on t" in w for w in rec["warnings"])


# --- invalid input -------------------------------------------------------------------

BASE = "type: constrained-particle\nm: 1\ncurve: {x1: q, x2: 0, x3: 0}\nt_end: 1\n"


@pytest.mark.parametrize("extra, where, message", [
    ("forces: [{kind: friction, mu: 0.2, N: 3}]", "forces.0", "the normal force N is computed"),
    ("forces: [{kind: frictoin, mu: 0.2}]", "forces.0", "did you mean 'friction'"),
    ("q_range: [1, -1]", "q_range", "q_min < q_max"),
    ("q_range: [1, 2]", "q0", "outside q_range"),
    ("rotation: {omega: x1}", "rotation.omega", "unknown name 'x1'"),
    ("rotation: {axis: [0, 0, 0], omega: 1}", "rotation.axis", ""),
    ("accuracy: {method: quadrature}\nrotation: {omega: \"1 + t\"}", "accuracy.method", "fixed curve"),
    ("m2: 1", "m2", "unknown field"),
])
def test_invalid_constrained_particle(extra, where, message):
    msg = error_of(BASE + extra + "\n")
    assert msg.startswith("bad.yaml:"), msg
    assert where in msg and message in msg, msg


def test_invalid_curve():
    msg = error_of("type: constrained-particle\nm: 1\ncurve: {x1: t, x2: 0, x3: 0}\nt_end: 1\n")
    assert "curve.x1" in msg and "unknown name 't'" in msg, msg
    msg = error_of("type: constrained-particle\nm: 1\ncurve: {x1: \"q**2\", x2: 0, x3: 0}\nt_end: 1\n")
    assert "curve" in msg and "tangent dy/dq vanishes at q0 = 0" in msg, msg


# --- acceptance findings --------------------------------------------------------

def test_released_at_the_end_of_the_wire_leaves_it_at_once():
    # at rest at q = 1, the lower end of q_range, gravity pulls towards q = 0 (off the wire):
    # was a ZeroDivisionError (exit 3) in the energy route's period
    out = solve_text(HOOP.format(extra="q0: 1\nforces: [{kind: gravity}]\nat: [0, 0.5]").replace("[-pi, pi]", "[1, 2]"))[0]
    assert "reaches the end of the wire (q = 1) at t = 0 s" in out["error"]
    assert "internal error" not in out["error"]


def test_q_range_longer_than_the_energy_cells_resolve():
    # a hoop on q_range [-1e4, 1e4] (about 1600 turns): the energy route's 1024 cells cannot
    # resolve the force along it, so auto takes the ODE; the equilibria are too many to list
    rec = solve_one_text(HOOP.format(extra="q0: 1\nforces: [{kind: gravity}]\nat: [0, 0.2]").replace(
        "[-pi, pi]", "[-1e4, 1e4]"))
    assert rec["method"].startswith("ode")
    assert rec["results"]["equilibria"] is None
    assert any("more than 100 relative equilibria" in w for w in rec["warnings"])
    # the pendulum from rest at q = 1: q(0.2) as on the short q_range (quadrature)
    ref = solve_one_text(HOOP.format(extra="q0: 1\nforces: [{kind: gravity}]\nat: [0, 0.2]"))
    close(rec["results"]["q"], ref["results"]["q"])
