"""Scene equilibria and small oscillations (`linearize: true`, docs/types/scene.md "Equilibria and
small oscillations") against an independent route: each scene's Lagrangian written by hand in its
textbook coordinates (angles, stretches), linearized by sympy (the Hessians of T and V at the rest
point) and its ω² the roots of det(K − ω² M) = 0 found by sympy — never by dyncli — or the notes'
closed forms (ω² = (g/l)(2 ± √2), k/m, 3g/2L, 2k/3m).  ω² do not depend on the coordinates chosen,
so dyncli's (body positions in the null space of the joints) and the references' (angles) compare
directly; mode shapes compare after the linear map between the two sets of coordinates.

Tolerance: 1e-9 relative to the largest |ω²| — the engine's ω² are the eigenvalues of matrices
assembled from analytic second derivatives at an equilibrium found by Newton to ~1e-13 of the
scene's size; rounding with the modest condition numbers here (< 1e3) leaves ~1e-13, so 1e-9 is
a wide margin that still catches any wrong term (a missing constraint-curvature term is O(1)).
The analytic Hessians are also checked against central differences of the analytic Jacobians
(step 1e-6, agreement 1e-7: the differences' own truncation error O(h²) ~ 1e-12 and rounding
ε/h ~ 1e-10, times the entries' scale).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import error_of, solve_one_text, solve_text
from tests.topics.scene.common import DOUBLE_PENDULUM

TOL = 1e-9
G = 9.81


def solved(text: str) -> dict:
    return solve_one_text(text)["results"]


def sympy_omega2(T, V, coords, rates, at):
    """ω² (ascending floats) and the mode shapes (columns, first component 1) of the Lagrangian
    T − V linearized at ``at`` (a dict coordinate -> value)."""
    import sympy as sp

    sub = {**at, **{r: 0 for r in rates}}
    M = sp.hessian(T, rates).subs(sub)
    K = sp.hessian(V, coords).subs(sub)
    w = sp.symbols("w")
    roots = sp.Poly(sp.expand((K - w * M).det()), w).nroots(n=30)
    out = sorted(float(sp.re(r)) for r in roots)
    shapes = []
    for r in out:
        A = (K - sp.Float(r, 30) * M).evalf(30)
        # the null vector of the (nearly singular) 2x2 or 1x1 pencil: from its first row
        if A.shape[0] == 1:
            shapes.append([1.0])
        else:
            shapes.append([1.0, float(-A[0, 0] / A[0, 1]) if abs(A[0, 1]) > 1e-20 else 0.0])
    return out, shapes


def close(a, b, scale):
    assert abs(a - b) <= TOL * scale, (a, b)


DOUBLE = """
type: scene
title: double pendulum
params: {m1: %s, m2: %s, L1: %s, L2: %s, p1: "10*deg", p2: "-5*deg"}
""" + DOUBLE_PENDULUM + """at: [0, 0.5]
linearize: true
"""


def test_double_pendulum_equal_closed_form():
    r = solved(DOUBLE % (1, 1, 1, 1))
    eq = r["equilibria"]
    assert [e["stability"] for e in eq] == ["stable", "unstable", "unstable", "unstable"]
    w2 = eq[0]["omega2"]
    for got, want in zip(w2, (G * (2 - math.sqrt(2)), G * (2 + math.sqrt(2)))):
        close(got, want, G * 4)
    assert eq[0]["frequencies"] == pytest.approx([math.sqrt(x) for x in w2], rel=1e-15)
    assert eq[0]["frequencies_hz"] == pytest.approx([math.sqrt(x) / (2 * math.pi) for x in w2], rel=1e-15)
    # in (xA, xB) = (l φ1, l (φ1 + φ2)): the angles' modes (1, ±√2) become (1, 1 ± √2)
    assert eq[0]["coordinates"] == ["x.A.0", "x.B.0"]
    assert eq[0]["modes"][0] == pytest.approx([1, 1 + math.sqrt(2)], rel=TOL)
    assert eq[0]["modes"][1] == pytest.approx([1, 1 - math.sqrt(2)], rel=TOL)
    # the both-up rest: ω² = −(g/l)(2 ± √2)
    assert eq[3]["omega2"] == pytest.approx([-G * (2 + math.sqrt(2)), -G * (2 - math.sqrt(2))], rel=TOL)
    assert eq[3]["frequencies"] is None and eq[3]["response"] is None


def test_double_pendulum_unequal_against_sympy():
    import sympy as sp

    m1, m2, L1, L2 = 1, 2, 1, sp.Rational(7, 10)
    r = solved(DOUBLE % (1, 2, 1, 0.7))
    p1, p2, w1, w2 = sp.symbols("p1 p2 w1 w2")
    xA = sp.Matrix([L1 * sp.sin(p1), -L1 * sp.cos(p1)])
    xB = xA + sp.Matrix([L2 * sp.sin(p2), -L2 * sp.cos(p2)])
    vA, vB = xA.jacobian([p1, p2]) * sp.Matrix([w1, w2]), xB.jacobian([p1, p2]) * sp.Matrix([w1, w2])
    T = (m1 * vA.dot(vA) + m2 * vB.dot(vB)) / 2
    V = sp.Rational(981, 100) * (m1 * xA[1] + m2 * xB[1])
    want, shapes = sympy_omega2(T, V, [p1, p2], [w1, w2], {p1: 0, p2: 0})
    e = r["equilibria"][0]
    for got, w in zip(e["omega2"], want):
        close(got, w, max(abs(x) for x in want))
    # (xA, xB) = (L1 φ1, L1 φ1 + L2 φ2) to first order
    for mode, (a, b) in zip(e["modes"], shapes):
        u = np.array([float(L1) * a, float(L1) * a + float(L2) * b])
        assert mode == pytest.approx(list(u / u[0]), rel=1e-8)


def test_two_masses_three_springs_against_sympy():
    import sympy as sp

    from tests.conftest import PROBLEMS, solve_path

    rec = solve_path(PROBLEMS / "scenes" / "two-mass-three-springs.yaml")[0]
    e = rec["results"]["equilibria"]
    assert len(e) == 1 and e[0]["stable"]
    u1, u2, v1, v2 = sp.symbols("u1 u2 v1 v2")
    k = 100
    T = (2 * v1**2 + v2**2) / 2
    V = k * (u1**2 + (u2 - u1) ** 2 + u2**2) / 2
    want, shapes = sympy_omega2(T, V, [u1, u2], [v1, v2], {u1: 0, u2: 0})
    for got, w in zip(e[0]["omega2"], want):
        close(got, w, want[-1])
    for mode, s in zip(e[0]["modes"], shapes):
        assert mode == pytest.approx(s, rel=TOL)
    assert np.allclose(e[0]["M"], [[2, 0], [0, 1]], rtol=0, atol=1e-12)
    assert np.allclose(e[0]["K"], [[200, -100], [-100, 200]], rtol=1e-12, atol=1e-10)


ELASTIC = """
type: scene
title: pendulum on a spring
params: {m: 0.5, k: 40, L0: 0.8}
bodies:
  bob: {shape: point, mass: m, x: [0.1, -0.9]}
forces:
  - {spring: [[0, 0], bob], k: k, L: L0}
at: [0, 0.2]
linearize: true
"""


def test_pendulum_on_a_spring():
    """A bob on a spring from a fixed point (no joints: two degrees of freedom): at rest the spring
    hangs stretched by mg/k; ω² = k/m (stretch) and g/(L0 + mg/k) (swing)."""
    import sympy as sp

    r = solved(ELASTIC)
    m, k, L0 = 0.5, 40, 0.8
    ls = L0 + m * G / k
    e = r["equilibria"]
    assert e[0]["x"]["bob"] == pytest.approx([0, -ls, 0], abs=1e-12)
    assert e[0]["omega2"] == pytest.approx(sorted([k / m, G / ls]), rel=TOL)
    # sympy on the polar Lagrangian, the second route
    rr, th, rd, thd = sp.symbols("r th rd thd")
    T = sp.Rational(1, 2) * (rd**2 + rr**2 * thd**2) / 2
    V = 20 * (rr - sp.Rational(4, 5)) ** 2 - sp.Rational(981, 200) * rr * sp.cos(th)
    want, _ = sympy_omega2(T, V, [rr, th], [rd, thd], {rr: sp.Rational(4, 5) + sp.Rational(981, 100) / 80, th: 0})
    assert e[0]["omega2"] == pytest.approx(want, rel=TOL)
    # the upright rest (the spring compressed, holding the bob up) is unstable
    assert any(not x["stable"] and x["x"]["bob"][1] > 0 for x in e)


CART = """
type: scene
title: pendulum under a spring-held cart
params: {M: 2, m: 0.5, l: 0.6, k: 40, p0: "10*deg"}
surfaces:
  track: {through: [0, 1], direction: [1, 0]}
bodies:
  cart: {shape: box, mass: M, size: [0.4, 0.2], x: [0, 1], angle: 0, points: {hook: [0, -0.1]}}
  bob: {shape: point, mass: m, x: ["l*sin(p0)", "0.9 - l*cos(p0)"]}
joints:
  rail: {slider: [cart, track]}
  hanger: {link: [cart.hook, bob], length: l}
forces:
  - {spring: [cart, [-1, 1]], k: k, L: 0.8}
%s
at: [0, 0.5]
linearize: true
"""


def test_cart_pendulum_against_sympy_and_damped():
    import sympy as sp

    x, p, xd, pd = sp.symbols("x p xd pd")
    Mc, m, l, k = 2, sp.Rational(1, 2), sp.Rational(3, 5), 40
    T = Mc * xd**2 / 2 + m * ((xd + l * sp.cos(p) * pd) ** 2 + (l * sp.sin(p) * pd) ** 2) / 2
    V = k * (x + 1 - sp.Rational(4, 5)) ** 2 / 2 - m * sp.Rational(981, 100) * l * sp.cos(p)
    want, _ = sympy_omega2(T, V, [x, p], [xd, pd], {x: -sp.Rational(1, 5), p: 0})
    e = solved(CART % "")["equilibria"][0]
    assert e["stable"]
    assert e["omega2"] == pytest.approx(want, rel=TOL)
    # with a damper on the cart: the complex modes' eigenvalues solve det(K + λ C + λ² M) = 0
    d = solved(CART % "  - {damper: [cart, [-1, 1]], c: 3}")["equilibria"][0]
    lam = sp.symbols("lam")
    Ms = sp.hessian(T, [xd, pd]).subs({p: 0, pd: 0})
    Ks = sp.hessian(V, [x, p]).subs({x: -sp.Rational(1, 5), p: 0})
    Cs = sp.Matrix([[3, 0], [0, 0]])
    roots = sp.Poly(sp.expand((Ks + lam * Cs + lam**2 * Ms).det()), lam).nroots(n=30)
    upper = sorted((complex(r) for r in roots if sp.im(r) >= 0), key=lambda z: (abs(z), z.real))
    got = [complex(*z) for z in d["damped"]["eigenvalues"]]
    assert got == pytest.approx(upper, rel=1e-9)
    assert d["damped"]["damping_ratios"] == pytest.approx([-z.real / abs(z) for z in upper], rel=1e-9)


def _rod(extra: str, angle: str = "1.5") -> str:
    return f"""
type: scene
title: rod pinned at its end
params: {{m: 2, L: 1.2}}
bodies:
  bar: {{shape: rod, mass: m, length: L, angle: {angle}}}
joints:
  pivot: {{pin: [bar.end1, [0, 0]]}}
{extra}
at: [0, 0.1]
linearize: true
"""


def test_inverted_pendulum_unstable_and_hanging_stable():
    e = solved(_rod(""))["equilibria"]
    w = 3 * G / (2 * 1.2)             # m g (L/2) / (m L²/3)
    assert [x["stability"] for x in e] == ["stable", "unstable"]
    assert e[0]["omega2"] == pytest.approx([w], rel=TOL)
    assert e[1]["omega2"] == pytest.approx([-w], rel=TOL)
    assert e[1]["angle"]["bar"] == pytest.approx(math.pi / 2, abs=1e-12)
    assert e[1]["reaction"]["pivot"]["R"] == pytest.approx([0, 2 * G, 0], abs=1e-9)    # holds the bar's weight up


@pytest.mark.parametrize("k", [5.0, 20.0])
def test_inverted_pendulum_held_by_a_spring(k):
    """A horizontal spring at the tip, unstretched upright: ω² = (k L² − m g L/2)/(m L²/3) —
    stable only for k > m g/(2L) = 8.175 N/m."""
    spring = "forces:\n  - {spring: [bar.end2, [-3, 1.2]], k: %s, L: 3}" % k
    e = solved(_rod(spring, "pi/2 + 0.05"))["equilibria"]
    up = [x for x in e if abs(x["angle"]["bar"] - math.pi / 2) < 1e-9][0]
    m, L = 2, 1.2
    want = (k * L**2 - m * G * L / 2) / (m * L**2 / 3)
    assert up["omega2"] == pytest.approx([want], rel=TOL)
    assert up["stable"] == (want > 0)


DISK = """
type: scene
title: disk rolling on an incline held by a spring
params: {m: 2, R: 0.2, k: 250, L0: 0.5, beta: "30*deg", s0: 2}
surfaces:
  slope: {through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}
bodies:
  disk: {shape: disk, mass: m, radius: R, angle: 0}
joints:
  roll: {rolls: [disk, slope], at: s0, mu_s: 0.5}
forces:
  - spring: [disk, ["(s0 + L0)*cos(beta) - R*sin(beta)", "(s0 + L0)*sin(beta) + R*cos(beta)"]]
    k: k
    L: L0
at: [0, 0.25]
linearize: true
"""


def test_rolling_disk_bowl_like():
    """The disk rolls about the rest where the spring holds it: ω² = k/(m + Ī/R²) = 2k/(3m), and
    the linear response is the closed form itself (the motion is exactly linear)."""
    r = solved(DISK)
    e = r["equilibria"]
    assert len(e) == 1 and e[0]["stable"]
    assert e[0]["omega2"] == pytest.approx([2 * 250 / 6], rel=TOL)
    angle = e[0]["response"]["s"][1][0]
    assert angle == pytest.approx(r["angle"]["disk"][1], rel=1e-9)


def test_neutral_continuum_is_one_equilibrium():
    """A free cart (no spring) under a pendulum rests anywhere along the track: one neutral
    equilibrium (ω² = 0 and the pendulum's ω² = g (M + m)/(M l)), not a row per position; its
    zero mode is the free translation of the whole scene, so the frequencies hold, ω = 0 first."""
    e = solved((CART % "").replace("  - {spring: [cart, [-1, 1]], k: k, L: 0.8}\n", "")
               .replace("forces:\n", ""))["equilibria"]
    low = [x for x in e if x["x"]["bob"][1] < 1]
    assert len(low) == 1 and low[0]["stability"] == "neutral"
    assert low[0]["omega2"] == pytest.approx([0.0, G * 2.5 / (2 * 0.6)], rel=TOL, abs=1e-9)
    assert low[0]["frequencies"] == pytest.approx([0.0, (G * 2.5 / (2 * 0.6)) ** 0.5], rel=TOL, abs=1e-9)


WHEEL = """
type: scene
title: pendulum from the axle of a wheel rolling on a floor
params: {M: 2, m: 0.5, R: 0.3, l: 0.6}
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  wheel: {shape: %s, mass: M, radius: R, x: [0, R], angle: 0}
  bob: {shape: point, mass: m, x: [0.1, "R - sqrt(l**2 - 0.01)"]}
joints:
  roll: {rolls: [wheel, floor]}
  hanger: {link: [%s, bob], length: l}
at: [0, 0.5]
linearize: true
"""


@pytest.mark.parametrize("shape, turning", [("disk", 0.5), ("ring", 1.0)])
def test_wheel_rolling_free_is_one_neutral_equilibrium(shape, turning):
    """A pendulum hung from the axle of a wheel rolling on a floor rests anywhere along it: one
    hanging and one inverted equilibrium (not one per wheel turn), the hanging one neutral with
    its frequencies: ω = 0 for the rolling, and the pendulum's from the Lagrangian of x (the
    axle) and φ (the pendulum), T = ½ (M + Ī/R²) ẋ² + ½ m ((ẋ + l φ̇ cos φ)² + (l φ̇ sin φ)²),
    V = −m g l cos φ, linearized by sympy at φ = 0 (by hand: ω² = (g/l)(M′ + m)/M′)."""
    import sympy as sp

    x, phi, xd, phid = sp.symbols("x phi xd phid")
    M, m, R, l = 2, sp.Rational(1, 2), sp.Rational(3, 10), sp.Rational(3, 5)
    Mp = M + sp.nsimplify(turning) * M
    T = Mp * xd ** 2 / 2 + m * ((xd + l * phid * sp.cos(phi)) ** 2 + (l * phid * sp.sin(phi)) ** 2) / 2
    V = -m * sp.nsimplify(G) * l * sp.cos(phi)
    ref, _ = sympy_omega2(T, V, [x, phi], [xd, phid], {x: 0, phi: 0})
    e = solved(WHEEL % (shape, "wheel"))["equilibria"]
    assert [x["stability"] for x in e] == ["neutral", "unstable"]
    hanging = e[0]
    assert hanging["x"]["bob"][1] == pytest.approx(0.3 - 0.6, abs=1e-9)
    assert hanging["omega2"] == pytest.approx(ref, rel=TOL, abs=1e-9)
    assert hanging["frequencies"] == pytest.approx([0.0, ref[1] ** 0.5], rel=TOL, abs=1e-9)
    assert ref[1] == pytest.approx(G / 0.6 * (float(Mp) + 0.5) / float(Mp), rel=1e-12)
    # the zero mode rolls: the axle moves by R per radian the wheel turns back
    i = e[0]["coordinates"].index("angle.wheel")
    zero = e[0]["modes"][0]
    assert zero[1 - i] / zero[i] == pytest.approx(-0.3, rel=1e-9)


def test_wheel_pendulum_response_about_its_free_rest():
    """The linear response about the rolling wheel's neutral rest (its frequencies given): from
    rest at 10°, Mp x + m x_b is constant (the floor's friction is −Ī ẍ/R², so
    d/dt (M ẋ + m ẋ_b) = −Ī ẍ/R²) and u = x_b − x = u0 cos ωt (the relative swing), in closed
    form: x = m (u0 − u)/(Mp + m), x_b = x + u, the wheel's angle −x/R.  Pushed at V (the wheel
    rolling, the bob moving with it), the free mode adds V t to every position and −V t/R to
    the angle."""
    Mp, m, R, l, V = 3.0, 0.5, 0.3, 0.6, 0.4
    w = (G / l * (Mp + m) / Mp) ** 0.5
    u0 = l * math.sin(math.radians(10))
    base = (WHEEL % ("disk", "wheel")).replace('[0.1, "R - sqrt(l**2 - 0.01)"]', '["l*sin(10*deg)", "R - l*cos(10*deg)"]')
    for push in (0.0, V):
        text = base.replace("angle: 0}", f"angle: 0, v: [{push}, 0], omega: {-push / R}}}")
        text = text.replace("x: [\"l*sin", f"v: [{push}, 0], x: [\"l*sin")
        e = solved(text)["equilibria"][0]
        r = e["response"]
        iw, ib = e["coordinates"].index("angle.wheel"), e["coordinates"].index("x.bob.0")
        for k, t in enumerate((0, 0.5)):
            u = u0 * math.cos(w * t)
            x = m * (u0 - u) / (Mp + m) + push * t
            assert r["s"][k][iw] == pytest.approx(-x / R, rel=1e-9, abs=1e-12)
            assert r["s"][k][ib] == pytest.approx(x + u, rel=1e-9, abs=1e-12)


def test_wheel_pendulum_gallery():
    """problems/scenes/pendulum-on-rolling-wheel.yaml: the rolling and the swing (the closed
    form of its header, ω² = (g/l)(M′ + m)/M′), the motion near its linear response at 10°."""
    from tests.topics.scene.common import gallery

    r = gallery("pendulum-on-rolling-wheel.yaml")["results"]
    e = r["equilibria"]
    assert [x["stability"] for x in e] == ["neutral", "unstable"]
    assert e[0]["omega2"] == pytest.approx([0.0, G / 0.6 * 3.5 / 3], rel=TOL, abs=1e-9)
    iw = e[0]["coordinates"].index("angle.wheel")
    for k in (1, 2):
        assert abs(r["angle"]["wheel"][k] - e[0]["response"]["s"][k][iw]) < 0.02 * abs(r["angle"]["wheel"][k])


def _system(text):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver
    from tests.conftest import ROOT

    problems, _ = split_problems("t.yaml", text.encode(), ROOT)
    validate(problems[0])
    scene = prepare.setup(solver._plan(problems[0].model))
    return scene.system, scene.q0


@pytest.mark.parametrize("g", ["", "g: 0\n"])
def test_rolling_is_free_only_when_nothing_reads_the_wheels_angle(g):
    """The rolling translation of the wheel and its pendulum is a free motion with the pendulum
    on the axle (the axle moves e1, the wheel turns −1/R) and none with it on the rim (the turn
    moves its pin), nor with a spring from the axle to the ground (it ties the scene) — with
    gravity or without."""
    s, q = _system(g + WHEEL % ("disk", "wheel"))
    (T,) = s.rolling_translations(q)
    b = s.names
    assert T[b.index("x.wheel.0")] == T[b.index("x.bob.0")] == 1.0 and T[b.index("angle.wheel")] == pytest.approx(-1 / 0.3)
    rim = (WHEEL % ("disk", "wheel.rim")).replace("angle: 0}", "angle: 0, points: {rim: [0.3, 0]}}")
    s, q = _system(g + rim.replace('[0.1, "R - sqrt(l**2 - 0.01)"]', '[0.3, "R - l"]'))
    assert s.rolling_translations(q) == []
    sprung = (WHEEL % ("disk", "wheel")) + "forces:\n  - {spring: [wheel, [-1, 0.3]], k: 10, L: 1}\n"
    s, q = _system(g + sprung)
    assert s.rolling_translations(q) == []


def test_hessians_against_differences():
    """The analytic second derivatives against central differences of the analytic Jacobians."""
    from dyncli.topics.scene import curvature, prepare, solver
    from dyncli.loader import split_problems, validate
    from tests.conftest import ROOT

    text = CART % "  - {damper: [bob, [1, 0]], c: 1}"
    problems, _ = split_problems("t.yaml", text.encode(), ROOT)
    validate(problems[0])
    scene = prepare.setup(solver._plan(problems[0].model))
    s = scene.system
    rng = np.random.default_rng(1)
    q = scene.q0 + 0.1 * rng.standard_normal(s.n)
    lam = rng.standard_normal(s.m)
    h = 1e-6
    H = curvature.rows_hessian(s, q, lam)
    HV = curvature.potential_hessian(s, q)
    for j in range(s.n):
        dq = np.zeros(s.n)
        dq[j] = h
        col = (s.jac(q + dq).T @ lam - s.jac(q - dq).T @ lam) / (2 * h)
        assert H[:, j] == pytest.approx(col, abs=1e-7 * max(1.0, float(np.max(np.abs(H)))))
        f = lambda x: s.applied(x, np.zeros(s.n), 0.0)[0]      # noqa: E731
        assert HV[:, j] == pytest.approx(-(f(q + dq) - f(q - dq)) / (2 * h), abs=1e-7 * max(1.0, float(np.max(np.abs(HV)))))


def test_refusals():
    """Each refusal names `linearize` and says why: no freedom, a drive, friction at rest."""
    no_dof = """
type: scene
title: held
bodies:
  A: {shape: point, mass: 1, x: [0, -1]}
joints:
  pin: {pin: [A, [0, -1]]}
at: [0, 1]
linearize: true
"""
    msg = error_of(no_dof)
    assert "linearize" in msg and "degree of freedom" in msg
    driven = (CART % "").replace("  hanger:", "  push: {drive: cart.x1, value: \"0.1*t\"}\n  hanger:")
    msg = error_of(driven)
    assert "linearize" in msg and "drive" in msg
    rough = """
type: scene
title: rough block
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  A: {shape: point, mass: 1, x: [0, 0]}
joints:
  c: {contact: [A, floor], mu: 0.3}
forces:
  - {spring: [A, [-1, 0]], k: 10, L: 1}
at: [0, 1]
linearize: true
"""
    msg = error_of(rough)
    assert "friction" in msg and "linearize" in msg


def test_gallery_double_pendulum_modes_side_by_side():
    """problems/scenes/double-pendulum-modes.yaml: the same ω² at both amplitudes; the sum of the
    modes in closed form (computed here with mpmath from the hand-derived modes (1, 1 ± √2)) equals
    `response.s`; the motion stays within (3° in rad)³ of it at 3°, and is 4 % off at 30°."""
    from mpmath import mp, mpf

    from tests.conftest import PROBLEMS, solve_path

    recs = solve_path(PROBLEMS / "scenes" / "double-pendulum-modes.yaml")
    with mp.workdps(30):
        s2, g = mp.sqrt(2), mpf("9.81")
        w = (mp.sqrt(g * (2 - s2)), mp.sqrt(g * (2 + s2)))
        for rec, deg in zip(recs, (3, 30)):
            r = rec["results"]
            e = r["equilibria"][0]
            assert e["omega2"] == pytest.approx([float(x * x) for x in w], rel=TOL)
            p1 = mpf(deg) * mp.pi / 180
            xA = mp.sin(p1)
            xB = xA + mp.sin(s2 * p1)
            a2 = (xA * (1 + s2) - xB) / (2 * s2)
            a1 = xA - a2
            for k, t in enumerate(r["t"]):
                c1, c2 = a1 * mp.cos(w[0] * t), a2 * mp.cos(w[1] * t)
                want = [float(c1 + c2), float(c1 * (1 + s2) + c2 * (1 - s2))]
                assert e["response"]["s"][k] == pytest.approx(want, rel=1e-12, abs=1e-14)
                off = abs(r["x"]["A"][k][0] - want[0]) / float(xA)
                assert off <= (float(p1) ** 2 if deg == 3 else 1.0)
            assert abs(r["x"]["A"][1][0] - e["response"]["s"][1][0]) > 0.02 * float(xA) or deg == 3


def test_no_rest_through_a_surface_and_none_at_all():
    """The falling rod on its smooth floor rests only upright (unstable; free to slide: ω² = 0
    too) — hanging below the floor from its end would need the body through the surface, left
    out with a warning; the Atwood machine with unequal masses has no rest: an empty list."""
    from tests.conftest import PROBLEMS

    text = (PROBLEMS / "scenes" / "falling-rod.yaml").read_text() + "linearize: true\n"
    rec = solve_one_text(text)
    e = rec["results"]["equilibria"]
    assert len(e) == 1 and e[0]["angle"]["rod"] == pytest.approx(math.pi / 2, abs=1e-12)
    assert e[0]["stability"] == "unstable" and e[0]["omega2"][1] == pytest.approx(0.0, abs=1e-9)
    assert any("through the surface 'floor'" in w for w in rec["warnings"])
    text = (PROBLEMS / "scenes" / "atwood-massive-pulley.yaml").read_text() + "linearize: true\n"
    rec = solve_one_text(text)
    assert rec["results"]["equilibria"] == []
    assert any("no rest configuration" in w for w in rec["warnings"])


@pytest.mark.parametrize("c", [2.0, 20.0, 30.0])
def test_damped_response_against_the_vibration_closed_form(c):
    """A block on a smooth floor between a spring and a damper to the wall (m = 1 kg, k = 100 N/m),
    released 0.1 m from rest: x(t) = e^{−ζωt}(x0 cos ω_d t + (ζω x0/ω_d) sin ω_d t) for ζ = 0.1, and
    x0 (1 + ωt) e^{−ωt} at critical damping (ζ = 1: a defective pair, the exponential route)."""
    text = f"""
type: scene
title: block spring damper
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
bodies:
  A: {{shape: point, mass: 1, x: [1.1, 0]}}
joints:
  s: {{slider: [A, floor]}}
forces:
  - {{spring: [[0, 0], A], k: 100, L: 1}}
  - {{damper: [[0, 0], A], c: {c}}}
at: [0, 0.1, 0.3, 0.7]
linearize: true
"""
    r = solved(text)
    e = r["equilibria"][0]
    w, z, x0 = 10.0, c / 20.0, 0.1
    for k, t in enumerate(r["t"]):
        if z < 1:
            wd = w * math.sqrt(1 - z * z)
            want = math.exp(-z * w * t) * (x0 * math.cos(wd * t) + z * w * x0 / wd * math.sin(wd * t))
        elif z == 1:
            want = x0 * (1 + w * t) * math.exp(-w * t)
        else:                           # overdamped: x0 (s2 e^{s1 t} − s1 e^{s2 t})/(s2 − s1)
            s1, s2 = -w * (z - math.sqrt(z * z - 1)), -w * (z + math.sqrt(z * z - 1))
            want = x0 * (s2 * math.exp(s1 * t) - s1 * math.exp(s2 * t)) / (s2 - s1)
        assert e["response"]["s"][k][0] - 1.0 == pytest.approx(want, rel=1e-9, abs=1e-14)
    lam = e["damped"]["eigenvalues"][0]
    if z <= 1:
        assert lam[0] == pytest.approx(-z * w, rel=1e-6)
    if z < 1:
        assert e["damped"]["damping_ratios"][0] == pytest.approx(z, rel=1e-12)
        assert e["damped"]["frequencies"][0] == pytest.approx(w * math.sqrt(1 - z * z), rel=1e-12)
    if z > 1:                           # both real roots carry the mode's ζ = c/(2√(km)), not 1
        assert [x[0] for x in e["damped"]["eigenvalues"]] == pytest.approx(
            [-w * (z - math.sqrt(z * z - 1)), -w * (z + math.sqrt(z * z - 1))], rel=1e-12)
        assert e["damped"]["damping_ratios"] == pytest.approx([z, z], rel=1e-12)
        assert e["damped"]["frequencies"] == [0.0, 0.0]


SNAP = """
type: scene
title: snap-through bead
params: {k: 100, a: 0.03, h: 1, L0: 1.002}
surfaces:
  track: {through: [0, 0], direction: [1, 0]}
bodies:
  bead: {shape: point, mass: 1, x: [1.2, 0]}
joints:
  rail: {slider: [bead, track]}
forces:
  - {spring: [bead, [a, h]], k: k, L: L0}
at: [0]
linearize: true
"""


def test_three_equilibria_within_one_step_of_the_path():
    """A bead on a smooth horizontal rail, a spring (k, natural length L0) to the anchor (a, h) with
    L0 just over h: V = k (√((x − a)² + h²) − L0)²/2 has the snap-through's three rests x = a
    (unstable, ω² = k (1 − L0/h)/m) and x = a ± √(L0² − h²) (stable, ω² = k (L0² − h²)/(m L0²)), all
    three within 0.13 of each other.  The path from x = 1.2 steps by 0.12 (a tenth of the scene's
    size): its step from 0.12 to 0 holds the unstable rest and a well, where the force along it
    changes sign twice — the signs at the steps' ends alone found only the two wells.  The
    references: the closed forms, and sympy's roots of V'."""
    import sympy as sp

    k, a, h, L0 = 100, 0.03, 1, 1.002
    e = sorted(solved(SNAP)["equilibria"], key=lambda r: r["x"]["bead"][0])
    w = math.sqrt(L0**2 - h**2)
    assert [r["x"]["bead"][0] for r in e] == pytest.approx([a - w, a, a + w], abs=1e-12)
    assert [r["stability"] for r in e] == ["stable", "unstable", "stable"]
    assert [r["omega2"][0] for r in e] == pytest.approx(
        [k * w**2 / L0**2, k * (1 - L0 / h), k * w**2 / L0**2], rel=1e-9)
    x = sp.symbols("x", real=True)
    ka, aa, ha, La = 100, sp.Rational(3, 100), 1, sp.Rational(1002, 1000)
    V = ka * (sp.sqrt((x - aa) ** 2 + ha**2) - La) ** 2 / 2
    want = sorted(float(r) for r in sp.solve(sp.diff(V, x), x))
    assert [r["x"]["bead"][0] for r in e] == pytest.approx(want, abs=1e-12)


def test_linearize_over_its_cpu_budget_on_a_closed_curve_names_the_curve():
    """A disk rolling in a full circular track (no q_range) released at 60°: the search for the
    rest configurations follows the feet of trial states over several laps of the curve and used
    the CPU budget; the message says so (linearize, the curve without q_range, the budget) and
    not "check the scales of the inputs", which are ordinary."""
    from tests.topics.scene.test_curved import CAN_IN_TRACK

    rec = solve_text(CAN_IN_TRACK + "at: [0, 0.3]\nlinearize: true\naccuracy: {max_cpu: 0.2}\n")[0]
    err = str(rec.get("error") or "")
    assert "linearize" in err and "q_range (track)" in err and "accuracy.max_cpu" in err, err
    assert "scales" not in err, err
