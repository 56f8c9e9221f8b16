"""Property tests at the extremes for the additions of issue 21 (items 1-4):
per-force power and work of particle, the relative equilibria of
constrained-particle, curvilinear force fields."""

from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.conftest import solve_one_text

FAST = settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
pos = st.floats(0.05, 50.0)


@FAST
@given(m=pos, k=pos, c=st.floats(0.0, 5.0), L=st.floats(0.0, 2.0), vz=st.floats(-20, 20))
def test_powers_add_up_to_T_dot_and_works_to_delta_T(m, k, c, L, vz):
    r = solve_one_text(f"""
type: particle
m: {m}
x0: [1, 0.5, 0]
v0: [0, 1, {vz}]
forces: [{{kind: gravity}}, {{kind: spring, k: {k}, L: {L}}}, {{kind: damper, c: {c}}}]
at: [0, 0.3, 0.7]
accuracy: {{rtol: 1e-9}}
""")["results"]
    for P, a, v in zip(r["power"], r["a"], r["v"]):
        Tdot = m * sum(ai * vi for ai, vi in zip(a, v))
        assert abs(sum(P.values()) - Tdot) <= 1e-11 * (1 + sum(abs(p) for p in P.values()))
    scale = max(abs(w) for W in r["work"] for w in W.values()) + max(r["T"]) + 1
    assert r["work_residual"] <= 1e-6 * scale            # rtol 1e-9: a few 1e-9 of the energy scale


@FAST
@given(R=st.floats(0.01, 10.0), w=st.floats(0.0, 60.0))
def test_hoop_equilibria_follow_cos_q_star(R, w):
    g = 9.81
    crit = g / R
    if abs(w * w - crit) < 1e-3 * crit:                   # the exact critical rate is tested on its own
        return
    r = solve_one_text(f"""
type: constrained-particle
m: 1
curve: {{x1: "{R}*sin(q)", x2: 0, x3: "-{R}*cos(q)"}}
q_range: [-pi, pi]
rotation: {{omega: {w}}}
forces: [{{kind: gravity}}]
q0: 0
t_end: 0.01
""")["results"]
    eq = r["equilibria"]
    if w * w > crit:
        qs = math.acos(crit / (w * w))
        assert [round(e["q"], 9) for e in eq] == [round(v, 9) for v in (-math.pi, -qs, 0.0, qs)]
        assert [e["stable"] for e in eq] == [False, True, False, True]
        assert abs(eq[3]["omega_small"] - w * math.sin(qs)) <= 1e-6 * w
    else:
        assert [(round(e["q"], 12), e["stable"]) for e in eq] == [(round(-math.pi, 12), False), (0.0, True)]
        assert abs(eq[1]["omega_small"] - math.sqrt(crit - w * w)) <= 1e-6 * math.sqrt(crit)


@settings(max_examples=5, deadline=None)
@given(a=st.integers(-5, 5), b=st.integers(-5, 5), r=st.floats(0.2, 5.0), th=st.floats(-3.0, 3.0))
def test_gradient_fields_in_cylindrical_coordinates_are_conservative(a, b, r, th):
    """F = −∇V for V = a r² + b r x3 cos θ (Table 19.1's ∇V): curl 0, potential V."""
    F = [f"-(2*{a}*r + {b}*x3*cos(theta))", f"{b}*x3*sin(theta)", f"-{b}*r*cos(theta)"]
    rec = solve_one_text("type: force-field\ncoordinates: cylindrical\nF: [" + ", ".join(f'"{c}"' for c in F)
                         + f"]\npoints: [[{r}, {th}, 0.5]]\n")
    res = rec["results"]
    assert res["conservative"] is True and res["conservative_method"] == "symbolic"
    assert res["curl"][0] == [0.0, 0.0, 0.0]
