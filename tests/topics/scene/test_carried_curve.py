"""A curve carried by a body: a small block P (mass m) in a circular groove of radius R cut in a
block W (mass M) free to slide on a smooth floor — the textbook's "particle slides down the
quarter-circle of a movable block" — and a bead in a curved groove of a free turntable.

Independent references (never the engine's own): with ψ the angle of P on the groove from its
bottom, horizontal momentum and energy give ψ̇² = 2 g cos ψ / (R (1 − μ' cos² ψ)), μ' = m/(M + m),
for a release from the rim (ψ0 = −π/2), so the time to the bottom is mpmath's quadrature of dψ/ψ̇
and there v_W = −μ' R ψ̇, N = m g (3 + 2m/M) (W does not accelerate there: a vertical N).
Rough, the free-body diagrams of P and W (N along the inward normal, friction −μ N along P's
slip over W, W's floor force vertical) are three linear equations in (ẍ_W, ψ̈, N), integrated by
mpmath's Taylor-series ODE solver.  On the turntable (g = 0) the angular momentum about the pin
and the kinetic energy are conserved (the rows' Coriolis and centripetal terms, carried_curve.py).
A bowl on a free cart oscillates at ω² = (g/R)(M + m)/M (linearize, the rows' Hessian) with a
free translation ω = 0.

Rolling on a carried curve: a cylinder (m, radius r, Ī = m r²/2) inside a pipe of radius R cut in
a block (M) free to slide, its centre at ρ = R − r from the pipe's axis at the angle ψ from the
bottom: with the momentum M ẋ + m (ẋ + ρ ψ̇ cos ψ) = 0, its spin ω_D = −ρ ψ̇/r (no slip on the
pipe, which does not turn) and the energy,
½ m ρ² ψ̇² (3/2 − μ' cos² ψ) = m g ρ (cos ψ − cos ψ0); the time to the bottom is its quadrature.
On a free turntable whose rim it rolls inside (g = 0): angular momentum about the pin and
energy conserved; the small oscillations of the cylinder in the sliding pipe,
ω² = g / (ρ (3/2 − μ')), from linearize."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import solve_text

G, m, M, R = 9.81, 1.0, 4.0, 0.5


def groove(mu: str = "", psi0: str = "-pi/2", extra: str = "", q_range: str = "[-1.5707963267948966, 0]",
           at: str = "[0, 0.2, 0.4]", find: str = "") -> str:
    return f"""type: scene
params: {{m: {m}, M: {M}, R: {R}, psi0: "{psi0}"}}
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
  groove: {{body: W, curve: {{x1: "R*sin(q)", x2: "R - R*cos(q)"}}, q_range: {q_range}}}
bodies:
  W: {{shape: box, mass: M, size: [0.6, 0.6], x: [0.2, 0.3]}}
  P: {{shape: point, mass: m, x: ["R*sin(psi0)", "R - R*cos(psi0)"]}}
joints:
  base: {{slider: [W, floor]}}
  on: {{contact: [P, groove]{mu}}}
at: {at}
accuracy: {{rtol: 1e-11}}
{find}{extra}"""


def solve(text: str) -> dict:
    rec = solve_text(text, "groove.yaml")[0]
    assert rec.get("error") is None, rec.get("error")
    return rec


def test_smooth_release_from_the_rim_reaches_the_bottom():
    mu1 = m / (M + m)
    with mp.workdps(30):
        t_bottom = mp.quad(lambda p: 1 / mp.sqrt(2 * G * mp.cos(p) / (R * (1 - mu1 * mp.cos(p) ** 2))),
                           [-mp.pi / 2, 0])
    rec = solve(groove(at="[0, 0.3]", extra="t_end: 2\n"))
    r = rec["results"]
    assert r["route"] == "ode"
    ev = next(e for e in r["events"] if e["joint"] == "on")
    assert ev["what"] == "leaves"
    assert ev["t"] == pytest.approx(float(t_bottom), rel=1e-9)
    rel_speed = math.sqrt(2 * G * R / (1 - mu1))          # R ψ̇ at the bottom
    st = ev["state"]
    assert st["v"]["W"][0] == pytest.approx(-mu1 * rel_speed, rel=1e-9)
    assert st["v"]["P"][0] == pytest.approx((1 - mu1) * rel_speed, rel=1e-9)
    # the horizontal momentum stays 0 at every reported time (no horizontal external force)
    for vw, vp in zip(r["v"]["W"], r["v"]["P"]):
        assert M * vw[0] + m * vp[0] == pytest.approx(0.0, abs=1e-10)


def test_smooth_normal_force_at_the_bottom():
    """On a groove that runs on past the bottom, the time P's height is least (v.P.1 = 0 going
    up): N = m g (3 + 2m/M)."""
    rec = solve(groove(q_range="[-1.5707963267948966, 1.5707963267948966]", at="[0]",
                       find='find: [{when: {v.P.1: 0}, direction: up}]\n', extra="t_end: 1\n"))
    hit = rec["results"]["find"][0]
    assert hit["reached"]
    assert hit["reaction"]["on"]["N"] == pytest.approx(m * G * (3 + 2 * m / M), rel=1e-8)
    assert hit["x"]["P"][1] == pytest.approx(0.0, abs=1e-9)


def _rough_reference(mu: float, psi0: float, times: list[float]):
    """(x_W − x_W0, ψ, N) at the times from the free-body diagrams, by mpmath's odefun (at 25
    digits, in a context: the other modules' mpmath precision left as it was)."""
    def accel(psi, dpsi):
        c, s = mp.cos(psi), mp.sin(psi)
        A = mp.matrix([[m, m * R * c, s + mu * c],
                       [0, m * R * s, -(c - mu * s)],
                       [M, 0, -(s + mu * c)]])
        b = mp.matrix([m * R * dpsi ** 2 * s, -m * R * dpsi ** 2 * c - m * G, 0])
        return mp.lu_solve(A, b)

    with mp.workdps(25):
        f = mp.odefun(lambda t, y: [y[1], accel(y[2], y[3])[0], y[3], accel(y[2], y[3])[1]], 0, [0, 0, psi0, 0])
        out = []
        for t in times:
            y = f(t)
            out.append((float(y[0]), float(y[2]), float(accel(y[2], y[3])[2])))
    return out


def test_rough_groove_against_the_free_body_diagrams():
    mu, psi0, times = 0.2, -1.2, [0.1, 0.25]
    ref = _rough_reference(mu, psi0, times)
    rec = solve(groove(mu=f", mu: {mu}", psi0=str(psi0), at=str([0] + times)))
    r = rec["results"]
    for i, (dxw, psi, N) in enumerate(ref, start=1):
        xw = r["x"]["W"][i][0] - 0.2
        assert xw == pytest.approx(dxw, rel=1e-8)
        assert math.asin((r["x"]["P"][i][0] - xw) / R) == pytest.approx(psi, rel=1e-8)
        assert r["reaction"]["on"]["N"][i] == pytest.approx(N, rel=1e-8)
        assert r["reaction"]["on"]["F"][i] == pytest.approx(-mu * N, rel=1e-8)
    for vw, vp in zip(r["v"]["W"], r["v"]["P"]):       # friction is internal: momentum holds
        assert M * vw[0] + m * vp[0] == pytest.approx(0.0, abs=1e-10)


def test_rough_groove_holds_the_block_where_friction_suffices():
    """tan 0.3 < μ_s = 0.5: P sticks on the groove, nothing moves; N = m g cos ψ, |F| = m g sin ψ."""
    rec = solve(groove(mu=", mu: 0.5", psi0="-0.3", at="[0, 1]"))
    r = rec["results"]
    for i in (0, 1):
        assert r["x"]["W"][i][0] == pytest.approx(0.2, abs=1e-12)
        assert r["reaction"]["on"]["N"][i] == pytest.approx(m * G * math.cos(0.3), rel=1e-12)
        assert abs(r["reaction"]["on"]["F"][i]) == pytest.approx(m * G * math.sin(0.3), rel=1e-12)
    assert not r["events"]


TURNTABLE = """type: scene
g: 0
params: {m: 0.5, I: 0.2}
surfaces:
  groove: {body: D, curve: {x1: "0.3 + 0.2*cos(q)", x2: "0.5*sin(q)"}}
bodies:
  D: {shape: disk, mass: 2, radius: 1, I: I, x: [0, 0], angle: 0, omega: 1.5}
  P: {shape: point, mass: m, x: [0.5, 0], v: [0, 1]}
joints:
  pin: {pin: [D, ground]}
  on: {contact: [P, groove]}
at: [0, 0.5, 1, 1.5]
accuracy: {rtol: 1e-11}
"""


def test_bead_in_the_groove_of_a_free_turntable_keeps_its_momentum_and_energy():
    rec = solve(TURNTABLE)
    r = rec["results"]
    I, mb = 0.2, 0.5
    Ls, Ts = [], []
    for i in range(len(r["t"])):
        w = r["omega"]["D"][i][2]
        x, v = r["x"]["P"][i], r["v"]["P"][i]
        Ls.append(I * w + mb * (x[0] * v[1] - x[1] * v[0]))
        Ts.append(0.5 * I * w * w + 0.5 * mb * (v[0] ** 2 + v[1] ** 2))
    assert Ls == pytest.approx([Ls[0]] * len(Ls), rel=1e-9)
    assert Ts == pytest.approx([Ts[0]] * len(Ts), rel=1e-9)
    assert Ls[0] == pytest.approx(0.2 * 1.5 + 0.5 * 0.5 * 1.0)
    # still in the groove, pressing on its wall, at every reported time (no event before 1.5 s)
    assert all(N > 0 for N in r["reaction"]["on"]["N"][1:])
    assert not r["events"]


def test_bowl_on_a_free_cart_small_oscillations():
    text = """type: scene
params: {m: 1, M: 3, R: 0.4}
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
  bowl: {body: C, curve: {x1: "R*sin(q)", x2: "0.5 + R - R*cos(q)"}, q_range: [-1.4, 1.4]}
bodies:
  C: {shape: box, mass: M, size: [1, 0.5], x: [0, 0.25]}
  P: {shape: point, mass: m, x: ["R*sin(0.2)", "0.5 + R - R*cos(0.2)"]}
joints:
  base: {slider: [C, floor]}
  on: {contact: [P, bowl]}
at: [0]
linearize: true
"""
    rec = solve(text)
    eq = rec["results"]["equilibria"]
    assert len(eq) == 1
    assert eq[0]["frequencies"] == pytest.approx([0.0, math.sqrt(9.81 / 0.4 * 4 / 3)], rel=1e-10, abs=1e-12)


def test_fixed_bowl_with_ends_small_oscillations():
    """A bowl with q_range: the search of equilibria walks past its rim (the circle's other half,
    beyond the ends) without failing (it used to stop the solve: "no nearest point")."""
    text = """type: scene
surfaces:
  bowl: {curve: {x1: "0.4*sin(q)", x2: "0.9 - 0.4*cos(q)"}, q_range: [-1.4, 1.4]}
bodies:
  P: {shape: point, mass: 1, x: ["0.4*sin(0.2)", "0.9 - 0.4*cos(0.2)"]}
joints:
  on: {contact: [P, bowl]}
at: [0]
linearize: true
"""
    eq = solve(text)["results"]["equilibria"]
    assert [e["frequencies"] for e in eq] == [pytest.approx([math.sqrt(9.81 / 0.4)], rel=1e-12)]


@pytest.mark.parametrize("joint, where, words", [
    ("{stop: [D, groove], e: 0.5}", "joints.on.stop.1", "a disk's stop runs along a straight surface"),
    ("{contact: [W, groove]}", "joints.on.contact.0", "cannot touch its own surface"),
])
def test_refusals(joint, where, words):
    text = f"""type: scene
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
  groove: {{body: W, curve: {{x1: "0.5*sin(q)", x2: "0.5 - 0.5*cos(q)"}}, q_range: [-1.5, 0]}}
bodies:
  W: {{shape: box, mass: 4, size: [0.6, 0.6], x: [0.2, 0.3]}}
  D: {{shape: disk, mass: 1, radius: 0.05, x: [-0.4, 0.4]}}
joints:
  base: {{slider: [W, floor]}}
  on: {joint}
at: [0, 1]
"""
    rec = solve_text(text, "bad.yaml")[0]
    err = rec.get("error") or ""
    assert words in err and where in err, err


def test_block_in_groove_gallery():
    """The gallery's file (a groove running up both sides): at the bottom the speeds and N of the
    module docstring's momentum and energy, W moved −m R/(M + m); back at the rim's height at
    twice the time to the bottom (mpmath's quadrature)."""
    from tests.topics.scene.common import gallery

    mu1 = m / (M + m)
    with mp.workdps(30):
        t_bottom = float(mp.quad(lambda p: 1 / mp.sqrt(2 * G * mp.cos(p) / (R * (1 - mu1 * mp.cos(p) ** 2))),
                                 [-mp.pi / 2, 0]))
    bottom, top = gallery("block-in-groove.yaml")["results"]["find"]
    u = math.sqrt(2 * G * R / (1 - mu1))
    assert bottom["t"] == pytest.approx(t_bottom, rel=1e-8)
    assert bottom["v"]["W"][0] == pytest.approx(-mu1 * u, rel=1e-8)
    assert bottom["v"]["P"][0] == pytest.approx((1 - mu1) * u, rel=1e-8)
    assert bottom["reaction"]["in_groove"]["N"] == pytest.approx(m * G * (3 + 2 * m / M), rel=1e-8)
    assert bottom["x"]["W"][0] == pytest.approx(0.2 - m * R / (M + m), rel=1e-9)
    assert top["t"] == pytest.approx(2 * t_bottom, rel=1e-8)
    assert top["x"]["P"][1] == pytest.approx(R, rel=1e-9)


def pipe(extra: str = "", at: str = "[0, 0.2, 0.4]", psi0: str = "-60*deg") -> str:
    return f"""type: scene
params: {{m: 1, M: 3, R: 0.5, r: 0.1, th0: "{psi0}"}}
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
  inside: {{body: C, curve: {{x1: "R*sin(q)", x2: "0.6 - R*cos(q)"}}, q_range: [-1.5, 1.5]}}
bodies:
  C: {{shape: box, mass: M, size: [1.2, 0.2], x: [0, 0.1]}}
  D: {{shape: disk, mass: m, radius: r, x: ["(R - r)*sin(th0)", "0.6 - (R - r)*cos(th0)"]}}
joints:
  base: {{slider: [C, floor]}}
  roll: {{rolls: [D, inside], mu_s: 1}}
at: {at}
accuracy: {{rtol: 1e-11}}
{extra}"""


RHO, MU_PIPE = 0.4, 1 / 4


def test_cylinder_rolling_in_a_sliding_pipe_on_the_energy_integral():
    psi0 = -math.pi / 3
    r = solve(pipe(extra='find: [{when: {v.D.1: 0}, direction: up}]\nt_end: 2\n'))["results"]
    assert r["route"] == "ode"
    for i in range(len(r["t"])):
        xc, vc = r["x"]["C"][i][0], r["v"]["C"][i][0]
        xd, vd = r["x"]["D"][i], r["v"]["D"][i]
        psi = math.asin((xd[0] - xc) / RHO)
        rel = (vd[0] - vc, vd[1])
        dpsi = math.copysign(math.hypot(*rel) / RHO, rel[0] * math.cos(psi) + rel[1] * math.sin(psi))
        assert 3 * vc + vd[0] == pytest.approx(0.0, abs=1e-10)
        assert r["omega"]["D"][i][2] == pytest.approx(-RHO * dpsi / 0.1, rel=1e-9, abs=1e-12)
        assert (dpsi * dpsi * (1.5 - MU_PIPE * math.cos(psi) ** 2)
                == pytest.approx(2 * G / RHO * (math.cos(psi) - math.cos(psi0)), rel=1e-9, abs=1e-12))
    with mp.workdps(30):
        t_bottom = mp.quad(lambda p: mp.sqrt(RHO * (1.5 - MU_PIPE * mp.cos(p) ** 2)
                                             / (2 * G * (mp.cos(p) - mp.cos(psi0)))), [psi0, 0])
    assert r["find"][0]["t"] == pytest.approx(float(t_bottom), rel=1e-8)


def test_cylinder_in_a_sliding_pipe_small_oscillations():
    r = solve(pipe(extra="linearize: true\n", at="[0]", psi0="-10*deg"))["results"]
    (eq,) = r["equilibria"]
    assert eq["frequencies"] == pytest.approx([0.0, math.sqrt(G / (RHO * (1.5 - MU_PIPE)))], rel=1e-10, abs=1e-12)


def test_cylinder_rolling_inside_a_free_turntable_keeps_momentum_and_energy():
    text = """type: scene
g: 0
surfaces:
  rim: {body: T, curve: {x1: "0.5*sin(q)", x2: "-0.5*cos(q)"}}
bodies:
  T: {shape: ring, mass: 2, radius: 0.5, x: [0, 0], angle: 0, omega: 0.5}
  D: {shape: disk, mass: 1, radius: 0.1, x: [0, -0.4], v: [1.2, 0]}
joints:
  pin: {pin: [T, ground]}
  roll: {rolls: [D, rim]}
at: [0, 0.5, 1, 2]
accuracy: {rtol: 1e-11}
"""
    r = solve(text)["results"]
    IT, ID = 2 * 0.25, 0.5 * 0.01
    L, T = [], []
    for i in range(len(r["t"])):
        wt, wd = r["omega"]["T"][i][2], r["omega"]["D"][i][2]
        x, v = r["x"]["D"][i], r["v"]["D"][i]
        L.append(IT * wt + ID * wd + (x[0] * v[1] - x[1] * v[0]))
        T.append(0.5 * IT * wt * wt + 0.5 * ID * wd * wd + 0.5 * (v[0] ** 2 + v[1] ** 2))
    assert L == pytest.approx([L[0]] * len(L), rel=1e-9)
    assert T == pytest.approx([T[0]] * len(T), rel=1e-9)
    assert not r["events"]


def test_the_groove_is_drawn_with_its_block():
    """The mechanism plot places a carried curve with its body at each requested time: the
    groove's lowest point is at (x_W(t) − 0.2, 0) (drawn at t = 0 with W at x1 = 0.2)."""
    from dyncli import registry
    from dyncli.loader import split_problems, validate
    from dyncli.result import SolveOptions
    from dyncli.topics.scene.plots import _mechanism
    from tests.conftest import PROBLEMS

    path = PROBLEMS / "scenes" / "block-in-groove.yaml"
    (lp,), _ = split_problems(path.name, path.read_bytes(), path.parent)
    validate(lp)
    res = registry.solver(lp.type)(lp.model, SolveOptions())
    grooves = [ln for ln in _mechanism(res, res.extra["scene_draw"]).lines if ln.style == ":" and
               (ln.label or "").startswith("t = ")]
    assert len(grooves) == len(res.results["t"])
    for ln, xw in zip(grooves, res.results["x"]["W"]):
        k = min(range(len(ln.y)), key=lambda i: ln.y[i])
        assert ln.y[k] == pytest.approx(0.0, abs=1e-4)                 # (the polyline's nearest vertex)
        assert ln.x[k] == pytest.approx(xw[0] - 0.2, abs=1e-2)


@pytest.mark.parametrize("M_big", [1e-3, 1e6])
def test_groove_at_extreme_mass_ratios(M_big):
    """A carrier a thousand times lighter than the block (it shoots sideways at ~m/M times the
    block's speed) or a million times heavier (it barely moves: the fixed bowl): the module
    docstring's quadrature, speeds and N = m g (3 + 2m/M) at the bottom, to the ODE's tolerance."""
    from tests.conftest import PROBLEMS
    from tests.tolerances import ODE_GLOBAL

    text = (PROBLEMS / "scenes" / "block-in-groove.yaml").read_text().replace(
        "params: {m: 1, M: 4, R: 0.5}", f"params: {{m: 1, M: {M_big}, R: 0.5}}") + "accuracy: {rtol: 1e-11}\n"
    bottom = solve(text)["results"]["find"][0]
    mu1 = m / (M_big + m)
    with mp.workdps(30):
        t_bottom = float(mp.quad(lambda p: 1 / mp.sqrt(2 * G * mp.cos(p) / (R * (1 - mu1 * mp.cos(p) ** 2))),
                                 [-mp.pi / 2, 0]))
    u = math.sqrt(2 * G * R / (1 - mu1))
    tol = ODE_GLOBAL * 1e-11
    assert bottom["t"] == pytest.approx(t_bottom, rel=tol)
    assert bottom["v"]["W"][0] == pytest.approx(-mu1 * u, rel=tol)
    assert bottom["v"]["P"][0] == pytest.approx((1 - mu1) * u, rel=tol)
    assert bottom["reaction"]["in_groove"]["N"] == pytest.approx(m * G * (3 + 2 * m / M_big), rel=tol)


def test_cylinder_in_sliding_pipe_gallery():
    """The gallery's file: at release the free-body diagrams (by hand, with the rolling tying the
    spin to ψ̈) give N = 10 m g/23, F = −4√3 m g/23; at the bottom the speeds of the module
    docstring's momentum and energy and N = m g + m (ρψ̇)²/ρ; the time there is the quadrature.
    With μ_s = 0.5 (below |F|/N = 2√3/5) it slips first and `sticks` later, losing energy."""
    from tests.conftest import PROBLEMS
    from tests.topics.scene.common import gallery

    psi0 = -math.pi / 3
    r = gallery("cylinder-in-sliding-pipe.yaml")["results"]
    assert r["reaction"]["roll"]["N"][0] == pytest.approx(10 * G / 23, rel=1e-12)
    assert r["reaction"]["roll"]["F"][0] == pytest.approx(-4 * math.sqrt(3) * G / 23, rel=1e-12)
    u = math.sqrt(2 * G * RHO * (1 - math.cos(psi0)) / (1.5 - MU_PIPE))
    with mp.workdps(30):
        t_bottom = float(mp.quad(lambda p: mp.sqrt(RHO * (1.5 - MU_PIPE * mp.cos(p) ** 2)
                                                   / (2 * G * (mp.cos(p) - mp.cos(psi0)))), [psi0, 0]))
    bottom = r["find"][0]
    assert bottom["t"] == pytest.approx(t_bottom, rel=1e-8)
    assert bottom["v"]["C"][0] == pytest.approx(-MU_PIPE * u, rel=1e-8)
    assert bottom["v"]["D"][0] == pytest.approx((1 - MU_PIPE) * u, rel=1e-8)
    assert bottom["omega"]["D"][2] == pytest.approx(-u / 0.1, rel=1e-8)
    assert bottom["reaction"]["roll"]["N"] == pytest.approx(G + u * u / RHO, rel=1e-8)
    text = (PROBLEMS / "scenes" / "cylinder-in-sliding-pipe.yaml").read_text().replace("mu_s: 1}", "mu_s: 0.5}")
    slipping = solve(text)["results"]
    assert slipping["events"][0]["what"] == "sticks"
    assert slipping["E"][1] < slipping["E"][0] - 1e-3


LOOPING = """type: scene
params: {{m: 1, M: 3, R: 0.5, r: 0.1}}
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
  pipe: {{{body}curve: {{x1: "R*sin(q)", x2: "0.6 - R*cos(q)"}}}}
bodies:
  C: {{shape: box, mass: M, size: [1.2, 1.4], x: [0, 0.7]}}
  D: {{shape: disk, mass: m, radius: r, x: [0, 0.2], v: [3.2, 0], omega: -32}}
joints:
  slide: {{slider: [C, floor]}}
  roll: {{rolls: [D, pipe], mu_s: 1, e: 0.3}}
t_end: 1.5
at: {at}
"""


@pytest.mark.parametrize("body", ["body: C, ", ""], ids=["carried", "fixed"])
def test_a_cylinder_that_bounces_to_rest_in_a_pipe_never_gains_energy(body):
    """Sent round the pipe too slowly, the cylinder leaves its wall near the top, falls, strikes
    it (e = 0.3, rough), bounces to rest against it and rolls on.  Friction and impacts only take
    energy: T + V never rises and W_nc never grows.  (After the bounces accumulated, a slip at the
    rounding of its terms, 4e-16 m/s, was taken for a slip: the cylinder slid on with friction
    pushing along its slip and gained 0.63 J in 0.04 s.)"""
    at = [round(0.05 * k, 2) for k in range(31)]
    r = solve(LOOPING.format(body=body, at=at))["results"]
    E, W = r["E"], r["W_nc"]
    scale = max(abs(x) for x in E)
    assert all(b <= a + 1e-9 * scale for a, b in zip(E, E[1:])), E
    assert all(b <= a + 1e-9 * scale for a, b in zip(W, W[1:])), W
    assert any(ev["what"] == "rests" for ev in r["events"])
