"""Property tests (hypothesis) at the extremes: free flight, Coulomb
oscillators from one half-swing to many, gradient fields and linear fields."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from dyncli import expr
from tests.conftest import solve_one_text
from tests.topics.particle.test_examples import _coulomb_oscillator

SETTINGS = dict(deadline=None, suppress_health_check=[HealthCheck.too_slow])
num = st.floats(min_value=-50, max_value=50, allow_nan=False)


@settings(max_examples=40, **SETTINGS)
@given(v=st.tuples(num, num, num), m=st.floats(min_value=1e-3, max_value=1e3),
       g=st.floats(min_value=0.0, max_value=30.0), t=st.floats(min_value=1e-3, max_value=20.0))
def test_projectile_closed_form(v, m, g, t):
    rec = solve_one_text(f"""
type: particle
m: {m!r}
g: {g!r}
v0: [{v[0]!r}, {v[1]!r}, {v[2]!r}]
forces: [{{kind: gravity}}]
at: [{t!r}]
""")
    R = rec["results"]
    want = [v[0] * t, v[1] * t, v[2] * t - 0.5 * g * t * t]
    scale = 1 + max(abs(c) for c in want)
    np.testing.assert_allclose(R["x"][0], want, rtol=0, atol=1e-9 * scale)
    E1 = 0.5 * m * sum(c * c for c in v)
    assert R["energy_residual"] <= 10 * 1e-10 * max(E1, abs(R["V"][0]), R["T"][0], 1e-300) + 1e-300 or \
        R["energy_residual"] <= 1e-12 * m * scale * scale


@settings(max_examples=30, **SETTINGS)
@given(e0=st.one_of(st.floats(min_value=-1.0, max_value=-1e-3), st.floats(min_value=1e-3, max_value=1.0)),
       ratio=st.floats(min_value=0.005, max_value=3.0),   # mu N / (k |e0|): many swings ... stuck at once
       k=st.floats(min_value=1.0, max_value=1e3), m=st.floats(min_value=0.1, max_value=10.0))
def test_coulomb_oscillator(e0, ratio, k, m):
    muN = ratio * k * abs(e0)
    L = 2.0
    w = math.sqrt(k / m)
    n_swings = max(1, math.ceil(abs(e0) / (2 * muN / k)))
    t_end = (n_swings + 1) * math.pi / w
    _, t_rest, e_rest = _coulomb_oscillator(m, k, L, e0, muN, [])
    # keep away from razor-thin stick/slip decisions (|e_n| = mu N/k to 1e-6)
    d = muN / k
    e = e0
    amp = math.inf          # the smallest swing amplitude |e| - d: v crosses 0 with slope w² amp
    while True:
        assume(abs(abs(e) - d) > 1e-6 * d)
        if abs(e) <= d:
            break
        amp = min(amp, abs(e) - d)
        e = 2 * math.copysign(d, e) - e
    rec = solve_one_text(f"""
type: particle
m: {m!r}
x0: [{L + e0!r}, 0, 0]
forces:
  - {{kind: spring, k: {k!r}, L: {L}}}
  - {{kind: friction, mu: 1, N: {muN!r}}}
at: [{t_end!r}]
accuracy: {{max_cpu: 60}}
""")    # (up to ~100 stops take ~1-2 s of CPU: the answer is under test, not the default budget)
    R = rec["results"]
    # the stop is where v·d = 0: located to the velocity's error (atol = 1e-12 m/s absolute, plus
    # rtol of its scale) over the slope w² amp of v there — a tiny last swing is ill-conditioned
    # (ratio 0.999: amp = 1.5e-6 m, t off by atol/(w² amp) = 7e-7 s, found at the lowest versions)
    t_tol = 1e-7 * t_rest + 1e-9 + 10 * 1e-12 / (w * w * amp)
    assert abs(R["t_rest"] - t_rest) <= t_tol
    assert R["x"][0][0] == pytest.approx(L + e_rest, abs=1e-7 * (1 + abs(e0)))
    assert R["v"][0] == [0, 0, 0]
    # static condition where it sticks; all initial energy minus the rest is dissipated
    assert k * abs(R["x"][0][0] - L) <= muN * (1 + 1e-6)
    assert R["W_nc"][0] == pytest.approx(0.5 * k * (e_rest ** 2 - e0 ** 2), rel=1e-6, abs=1e-9 * k)


@settings(max_examples=25, **SETTINGS)
@given(c=st.lists(st.integers(min_value=-5, max_value=5), min_size=6, max_size=6),
       p=st.tuples(*[st.floats(min_value=-3, max_value=3)] * 3))
def test_gradient_fields_are_conservative(c, p):
    # V = c0 x1² + c1 x1 x2 + c2 x3³ + c3 sin(x2) + c4 x1 x3 + c5 exp(x3) ; F = -grad V
    F = [f"-({2 * c[0]}*x1 + {c[1]}*x2 + {c[4]}*x3)",
         f"-({c[1]}*x1 + {c[3]}*cos(x2))",
         f"-({3 * c[2]}*x3**2 + {c[4]}*x1 + {c[5]}*exp(x3))"]

    def V(x1, x2, x3):
        return c[0] * x1 ** 2 + c[1] * x1 * x2 + c[2] * x3 ** 3 + c[3] * math.sin(x2) + c[4] * x1 * x3 + c[5] * math.exp(x3)

    rec = solve_one_text(f"""
type: force-field
F: {F}
points: [[{p[0]!r}, {p[1]!r}, {p[2]!r}]]
path: {{x1: "{p[0]!r}*t", x2: "{p[1]!r}*t**2", x3: "{p[2]!r}*sin(pi*t/2)", t_span: [0, 1]}}
""")
    R = rec["results"]
    assert R["conservative"] is True
    np.testing.assert_allclose(R["curl"][0], [0, 0, 0], atol=1e-12)
    Vp = expr.parse(R["potential"], ("x1", "x2", "x3"))
    got = float(Vp.evaluate(x1=p[0], x2=p[1], x3=p[2]))
    assert got == pytest.approx(V(*p) - V(0, 0, 0), rel=1e-9, abs=1e-9)
    # path from 0 to p: work = V(0) - V(p) (19.8)
    assert R["work"] == pytest.approx(V(0, 0, 0) - V(*p), rel=1e-9, abs=1e-9)
    assert abs(R["work_check"]) <= 1e-9 * (1 + abs(R["work"]))


@settings(max_examples=25, **SETTINGS)
@given(A=st.lists(st.integers(min_value=-4, max_value=4), min_size=9, max_size=9),
       sym=st.booleans())
def test_linear_fields(A, sym):
    a = np.array(A, float).reshape(3, 3)
    if sym:
        a = a + a.T
    F = [" + ".join(f"({int(a[i, j])})*x{j + 1}" for j in range(3)) for i in range(3)]
    rec = solve_one_text(f"""
type: force-field
F: {F}
points: [[1, 2, 3]]
""")
    R = rec["results"]
    # curl of F = A x is the axial vector of A - A^T
    curl = [a[2, 1] - a[1, 2], a[0, 2] - a[2, 0], a[1, 0] - a[0, 1]]
    np.testing.assert_allclose(R["curl"][0], curl, atol=1e-12)
    assert R["conservative"] is (not any(curl))
    if R["conservative"]:
        Vp = expr.parse(R["potential"], ("x1", "x2", "x3"))
        x = np.array([0.7, -1.1, 0.4])
        assert float(Vp.evaluate(x1=x[0], x2=x[1], x3=x[2])) == pytest.approx(-0.5 * x @ a @ x, abs=1e-9)
    else:
        assert R["potential"] is None
