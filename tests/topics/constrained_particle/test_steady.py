"""Steady motions solved for what holds them (constrained-particle ``steady``): the conical
pendulum, the banked curve with friction, the bead's relative equilibrium on a turning hoop and on
a general curve.  References: the force balance m a = F + N + f at rest relative to the turning
curve, solved by sympy (tests only), and the textbook closed forms derived by hand."""

from __future__ import annotations

import math

import pytest
import sympy as sp

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

G = 9.81
REL = 1e-12          # closed forms evaluated in double precision: a few ulps


def _problem(curve, steady, forces="[{kind: gravity}]", extra="", m=0.5, params="{}"):
    return (f"type: constrained-particle\nm: {m}\nparams: {params}\ncurve: {curve}\n"
            f"rotation: {{axis: [0, 0, 1]}}\nforces: {forces}\nsteady: {steady}\n{extra}")


def _balance_rate2(x1, x3, q):
    """ω² from the balance along the tangent of a curve (x1(q), 0, x3(q)) turning about e3, gravity
    −m g e3: m a = F + N with a = −ω² x1 e1 at rest relative to the curve; sympy."""
    w2, m, g = sp.symbols("w2 m g", positive=True)
    t = sp.Matrix([sp.diff(x1, q), 0, sp.diff(x3, q)])
    a = sp.Matrix([-w2 * x1, 0, 0])
    F = sp.Matrix([0, 0, -m * g])
    (sol,) = sp.solve(sp.Eq((m * a - F).dot(t), 0), w2)
    return sp.simplify(sol.subs(g, G))


@pytest.mark.parametrize("deg", [5, 30, 45, 60, 80, 89])
def test_conical_pendulum_rate_and_tension(deg):
    L, m = 0.8, 0.5
    rec = solve_one_text(_problem('{x1: "0.8*sin(q)", x2: 0, x3: "-0.8*cos(q)"}', f'[{{q: "{deg}*deg"}}]', m=m))
    (e,) = rec["results"]["steady"]
    q = sp.Symbol("q")
    w2 = _balance_rate2(L * sp.sin(q), -L * sp.cos(q), q)
    th = math.radians(deg)
    assert e["omega"] == pytest.approx(math.sqrt(float(w2.subs(q, th))), rel=REL)
    assert e["omega"] == pytest.approx(math.sqrt(G / (L * math.cos(th))), rel=REL)   # by hand
    assert e["v"] == pytest.approx(e["omega"] * L * math.sin(th), rel=REL)
    assert e["period"] == pytest.approx(2 * math.pi * math.sqrt(L * math.cos(th) / G), rel=REL)
    assert e["N"][1] == pytest.approx(m * G / math.cos(th), rel=1e-11)       # the string's tension
    assert e["N"][0] == 0 and abs(e["N"][2]) < 1e-12
    assert e["omega_min"] == e["omega_max"] == e["omega"]
    # stable, small oscillations about the cone at ω sin θ (linearised by hand)
    assert e["stable"] is True
    assert e["omega_small"] == pytest.approx(e["omega"] * math.sin(th), rel=1e-6)


def test_turning_hoop_rate_is_the_equilibrium_of_the_motion_solve():
    """Posed with a motion at ω = 6: the steady rate at the reported equilibrium q* is 6 again."""
    text = ('type: constrained-particle\nm: 0.1\ncurve: {x1: "0.5*sin(q)", x2: 0, x3: "-0.5*cos(q)"}\n'
            "q_range: [-pi, pi]\nrotation: {axis: [0, 0, 1], omega: 6}\nq0: 0.3\nforces: [{kind: gravity}]\n"
            f"at: [0, 0.5]\nsteady: [{{q: {math.acos(G / (0.5 * 36))!r}}}]\n")
    rec = solve_one_text(text)
    (e,) = rec["results"]["steady"]
    assert e["omega"] == pytest.approx(6, rel=REL)
    assert e["omega_small"] == pytest.approx(rec["results"]["equilibria"][3]["omega_small"], rel=1e-6)
    assert rec["results"]["x"]                     # the motion is solved too


def _banked_limits(beta, mu, r):
    """v_min², v_max² of a car on a banked curve from the two force balances (radial, vertical) with
    friction at its limit down or up the slope: sympy; None when there is no solution."""
    v2, N = sp.symbols("v2 N", real=True)
    beta, mu = sp.Float(beta, 40), sp.Float(mu, 40)    # 40 digits: a linear system, solved at once
    out = []
    for s in (+1, -1):          # friction up the slope (v_min), down the slope (v_max)
        eqs = [sp.Eq(-N * sp.sin(beta) + s * mu * N * sp.cos(beta), -v2 / r),   # m = 1: radial, towards the axis
               sp.Eq(N * sp.cos(beta) + s * mu * N * sp.sin(beta) - G, 0)]
        sol = sp.solve(eqs, [v2, N], dict=True)
        out.append(float(sol[0][v2]) if sol and sol[0][N] > 0 else None)
    return out


@pytest.mark.parametrize("deg, mu", [(20, 0.3), (10, 0.05), (35, 0.6), (15, 0.0)])
def test_banked_curve_speed_range(deg, mu):
    r = 50.0
    forces = f"[{{kind: gravity}}, {{kind: friction, mu: {mu}}}]" if mu else "[{kind: gravity}]"
    rec = solve_one_text(_problem('{x1: "r + q*cos(b)", x2: 0, x3: "q*sin(b)"}', "[{q: 0}]", forces=forces, m=1200,
                                  params=f'{{r: {r}, b: "{deg}*deg"}}'))
    (e,) = rec["results"]["steady"]
    b = math.radians(deg)
    lo2, hi2 = _banked_limits(math.radians(deg), mu, r)
    assert e["v_min"] == pytest.approx(math.sqrt(max(lo2, 0.0)), rel=1e-12, abs=1e-12)
    assert e["v_max"] == pytest.approx(math.sqrt(hi2), rel=1e-12)
    assert e["v"] == pytest.approx(math.sqrt(r * G * math.tan(b)), rel=REL)    # no friction needed
    # by hand: v² = r g (sin β ∓ μ cos β)/(cos β ± μ sin β)
    assert e["v_max"] ** 2 == pytest.approx(r * G * (math.sin(b) + mu * math.cos(b)) / (math.cos(b) - mu * math.sin(b)),
                                            rel=1e-12)
    assert e["omega_max"] == pytest.approx(e["v_max"] / r, rel=REL)
    assert not rec["warnings"]


@pytest.mark.parametrize("deg, mu", [(70, 0.5), (45, 1.0), (60, 2.0)])
def test_banked_curve_without_an_upper_limit(deg, mu):
    """μ ≥ cot β: friction holds the car at every speed above v_min; v_max null and said so."""
    rec = solve_one_text(_problem('{x1: "r + q*cos(b)", x2: 0, x3: "q*sin(b)"}', "[{q: 0}]",
                                  forces=f"[{{kind: gravity}}, {{kind: friction, mu: {mu}}}]", m=1000,
                                  params=f'{{r: 40, b: "{deg}*deg"}}'))
    (e,) = rec["results"]["steady"]
    b = math.radians(deg)
    assert e["v_max"] is None and e["omega_max"] is None
    lo2 = 40 * G * (math.sin(b) - mu * math.cos(b)) / (math.cos(b) + mu * math.sin(b))
    assert e["v_min"] == pytest.approx(math.sqrt(max(lo2, 0.0)), rel=1e-12, abs=1e-9)
    (w,) = rec["warnings"]
    assert w.startswith("steady.0:") and "no upper limit" in w and "μ ≥ cot β" in w


def test_parabolic_wire_holds_at_every_height_at_one_rate():
    """x3 = a x1²: ω² = 2 g a wherever the bead is (by hand: tan of the slope 2 a x1 = ω² x1 / g)."""
    rec = solve_one_text(_problem('{x1: q, x2: 0, x3: "1.5*q**2"}', "[{q: 0.1}, {q: 0.7}, {q: -2}]"))
    for e in rec["results"]["steady"]:
        assert e["omega"] == pytest.approx(math.sqrt(2 * G * 1.5), rel=REL)
        assert e["stable"] is None          # neutral: G ≡ 0 along the wire at that rate


def test_general_curve_from_the_effective_potential():
    """x3 = cosh(q) − 1, x1 = q: ω² from dV_eff/dq = 0 with V_eff = m g x3 − ½ m ω² x1² (sympy);
    stability from the sign of d²V_eff/dq² there."""
    q, w2 = sp.symbols("q w2", real=True)
    Veff = G * (sp.cosh(q) - 1) - w2 * q ** 2 / 2          # per unit mass
    sol = sp.solve(sp.diff(Veff, q), w2)[0]
    rec = solve_one_text(_problem('{x1: q, x2: 0, x3: "cosh(q) - 1"}', "[{q: 0.4}, {q: 1.3}]"))
    for e in rec["results"]["steady"]:
        u = float(sol.subs(q, e["q"]))
        assert e["omega"] == pytest.approx(math.sqrt(u), rel=REL)
        k = float(sp.diff(Veff, q, 2).subs({w2: u, q: e["q"]}))        # > 0: stable
        assert e["stable"] is (k > 0)
        if k > 0:                            # m |y'|² δq̈ = −V_eff'' δq on this curve (|y'|² = cosh² q)
            assert e["omega_small"] == pytest.approx(math.sqrt(k) / math.cosh(e["q"]), rel=1e-6)


def test_bottom_of_the_hoop_is_held_at_every_rate():
    rec = solve_one_text(_problem('{x1: "sin(q)", x2: 0, x3: "-cos(q)"}', "[{q: 0}]"))
    (e,) = rec["results"]["steady"]
    assert e["omega"] is None and e["omega_min"] == 0 and e["omega_max"] is None
    assert any("every rate" in w for w in rec["warnings"])


HOOP = '{x1: "sin(q)", x2: 0, x3: "-cos(q)"}'


def test_degrees_slip_on_a_hoop_is_said():
    """q: 30 meant as 30°: solved in radians (cos 30 > 0), with a warning naming the field and 30*deg;
    none for 30*deg, nor on a curve that does not repeat (q is then no angle)."""
    (w,) = solve_one_text(_problem(HOOP, "[{q: 30}]"))["warnings"]
    assert w.startswith("steady.0:") and "30*deg" in w
    assert not solve_one_text(_problem(HOOP, '[{q: "30*deg"}]'))["warnings"]
    assert not solve_one_text(_problem('{x1: q, x2: 0, x3: "0.1*q**2"}', "[{q: 30}]"))["warnings"]


@pytest.mark.parametrize("text, index, message", [
    (_problem(HOOP, "[{q: 2}]"), 0, "ω² = -"),
    (_problem(HOOP, "[{q: 0.3}, {q: 2}]"), 1, "points away from the axis"),
    (_problem(HOOP, '[{q: "pi/2"}]'), 0, "normal to the direction from the axis"),
    (_problem(HOOP, "[{q: 2}]", forces="[{kind: gravity}, {kind: friction, mu: 0.1}]"), 0,
     "friction μ = 0.1 cannot hold it"),
])
def test_no_steady_motion_is_an_answer(text, index, message):
    """No steady motion at q is the physics' answer (exit 0): the entry says exists: false, its rates
    are null, and a warning names the query and says why."""
    rec = solve_one_text(text)
    e = rec["results"]["steady"][index]
    assert e["exists"] is False and e["omega"] is None and e["v"] is None
    assert any(w.startswith(f"steady.{index}:") and message in w for w in rec["warnings"]), rec["warnings"]
    assert all(x["exists"] for i, x in enumerate(rec["results"]["steady"]) if i != index)


@pytest.mark.parametrize("text, where, message", [
    (_problem(HOOP, "[{q: 1}]", forces="[{kind: gravity}, {kind: damper, c: 1}]"), "forces.1", "position only"),
    (_problem(HOOP, "[{q: 4}]", extra="q_range: [-pi, pi]\n"), "steady.0.q", "outside q_range"),
    (_problem(HOOP, "[{q: 1}]").replace("rotation: {axis: [0, 0, 1]}\n", ""), "steady", "rotation: {axis"),
    (_problem(HOOP, "[{q: 1}]", extra="at: [0, 1]\n"), "rotation.omega", "steady queries alone"),
    (_problem(HOOP, "[{Q: 1}]"), "steady.0.Q", "unknown field"),
])
def test_invalid_steady_requests(text, where, message):
    msg = error_of(text)
    assert f": {where}: " in msg and message in msg, msg


def test_gallery_steady_motions_against_the_closed_forms():
    recs = solve_path(PROBLEMS / "particle" / "steady-motions.yaml")
    cone, bank, steep, parabola, elastic = (r["results"]["steady"] for r in recs)
    R = 0.6 + 0.3 * G / (50 * math.cos(math.radians(30)))
    assert elastic[0]["omega"] == pytest.approx(math.sqrt(50 * (R - 0.6) / (0.3 * R)), rel=1e-12)
    th = math.radians(30)
    assert cone[0]["omega"] == pytest.approx(math.sqrt(G / (1.2 * math.cos(th))), rel=REL)
    assert cone[0]["N"][1] == pytest.approx(0.4 * G / math.cos(th), rel=1e-11)
    b, mu, r = math.radians(15), 0.25, 60
    assert bank[0]["v_min"] ** 2 == pytest.approx(r * G * (math.sin(b) - mu * math.cos(b)) / (math.cos(b) + mu * math.sin(b)), rel=1e-12)
    assert bank[0]["v_max"] ** 2 == pytest.approx(r * G * (math.sin(b) + mu * math.cos(b)) / (math.cos(b) - mu * math.sin(b)), rel=1e-12)
    assert steep[0]["v_max"] is None and 0.4 >= 1 / math.tan(math.radians(75))
    assert [e["omega"] for e in parabola] == pytest.approx([math.sqrt(4 * G)] * 2, rel=REL)
    assert [len(r["warnings"]) for r in recs] == [0, 0, 1, 0, 0]
