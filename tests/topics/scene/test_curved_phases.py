"""Rolling on a curve phase by phase: slip, stick, slip again, flight and landing
(docs/types/scene.md: curved surfaces).

The reference is a second formulation written here: the disk in a circular bowl in its own
angle φ from the bottom (L = ρ − r, u = L φ̇ + r ω the contact point's slip),
    m L φ̈ = −m g sin φ + F,  Ī ω̇ = r F,  N = m g cos φ + m L φ̇²,
F = −μ N sign u while it slips, integrated by mpmath's Taylor ODE solver at 30 digits with the
slip's zeros found by findroot and the static test (rolling needs F = m g sin φ / 3) decided
there; the rolling phase by its energy integral (¾ m L² φ̇² − m g L cos φ constant) and the root
of the slip condition.  dyncli takes the ODE route: tolerance ODE_GLOBAL × rtol (docs/accuracy.md).
"""

from __future__ import annotations

import math

import mpmath as mp

from tests.tolerances import ODE_GLOBAL
from tests.topics.scene.common import gallery

ODE_TOL = ODE_GLOBAL * 1e-10


def near(got, want, scale, what, tol=ODE_TOL):
    assert got is not None, f"{what}: null"
    assert abs(float(got) - float(want)) <= tol * abs(float(scale)), f"{what}: {got!r} vs {float(want)!r}"


def _bowl_reference():
    """[(t, φ, φ̇, holds)] at each zero of the slip, until the static test holds."""
    with mp.workdps(30):
        g, m, r, mu = mp.mpf("9.81"), 1, mp.mpf("0.1"), mp.mpf("0.1")
        I, L = m * r**2 / 2, 1 - r

        def N(ph, w):
            return m * g * mp.cos(ph) + m * L * w**2

        def rhs(s):
            def f(t, y):
                F = -mu * N(y[0], y[1]) * s
                return [y[1], (-m * g * mp.sin(y[0]) + F) / (m * L), r * F / I]
            return f

        t, y = mp.mpf(0), [mp.pi / 3, mp.mpf(0), mp.mpf(0)]
        s, out = -1, []                 # rolling would need F = m g sin φ/3 > 0: it slips against it
        for _ in range(4):
            sol = mp.odefun(rhs(s), t, y)

            def u(tt):
                st = sol(tt)
                return L * st[1] + r * st[2]

            a, h = t + mp.mpf("0.01"), mp.mpf("0.01")
            while mp.sign(u(a + h)) == mp.sign(u(a)):
                a += h
            tc = mp.findroot(u, (a, a + h), solver="anderson")
            y, t = sol(tc), tc
            F_roll = m * g * mp.sin(y[0]) / 3
            holds = abs(F_roll) <= mu * N(y[0], y[1])
            out.append((tc, y[0], y[1], holds))
            if holds:
                break
            s = -mp.sign(F_roll)
        # rolling on: where m g |sin φ|/3 reaches μ N, and the time by the energy quadrature
        p0, w0 = y[0], y[1]
        C = mp.mpf(3) / 4 * L**2 * w0**2 - g * L * mp.cos(p0)

        def w2(p):
            return (C + g * L * mp.cos(p)) / (mp.mpf(3) / 4 * L**2)

        ps = mp.findroot(lambda p: g * abs(mp.sin(p)) / 3 - mu * (g * mp.cos(p) + L * w2(p)), p0 - mp.mpf("0.1"))
        ts = t + mp.quad(lambda p: 1 / mp.sqrt(w2(p)), [ps, p0])
        return out, (ts, ps, L)


def test_disk_slips_sticks_and_slips_again_in_a_bowl():
    r = gallery("disk-slips-in-bowl.yaml")["results"]
    zeros, (ts, ps, L) = _bowl_reference()
    assert [z[3] for z in zeros] == [False, False, True]
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("r", "sticks"), ("r", "slips")]
    assert [ph["route"] for ph in r["phases"]] == ["ode"] * 5
    for k, (tc, ph, _w, _h) in enumerate(zeros):
        near(r["phases"][k]["t_end"], tc, tc, f"phases.{k}.t_end")
    tc, ph, w, _ = zeros[-1]
    st = r["events"][0]["state"]
    near(st["x"]["disk"][0], L * mp.sin(ph), L, "x at sticks")
    near(st["v"]["disk"][0], L * w * mp.cos(ph), L * abs(w), "v at sticks")
    near(st["omega"]["disk"][2], -L * w / mp.mpf("0.1"), L * abs(w) / 0.1, "rolling at sticks: omega")
    near(r["events"][1]["t"], ts, ts, "slips t")
    near(r["events"][1]["state"]["x"]["disk"][0], L * mp.sin(ps), L, "x at slips")
    # slipping at the start: N = m g cos 60°, F = μ N up the bowl
    near(r["reaction"]["r"]["N"][0], 9.81 / 2, 9.81, "N.0", 1e-12)
    near(r["reaction"]["r"]["F"][0], 0.981 / 2, 9.81, "F.0", 1e-12)
    # the energy balance holds across the phases (the friction's work in W_nc)
    E0 = abs(r["E"][0])
    for k, res in enumerate(r["energy_residual"]):
        near(res, 0, E0, f"energy_residual.{k}")


def test_disk_leaves_a_loop_flies_and_lands():
    # a disk rolling into a loop (radius 1 m) too slowly to go round: it slips near the top,
    # separates where N = 0, flies (a parabola: the closed-form route) and lands on the loop
    # (e = 0); the flight between the two events is checked against the parabola of its
    # centre, and the landing's gap is 0
    from tests.conftest import solve_one_text

    rec = solve_one_text("""
type: scene
surfaces:
  loop: {curve: {x1: "sin(q)", x2: "1 - cos(q)"}}
bodies:
  disk: {shape: disk, mass: 1, radius: 0.1, angle: 0, v: [4.5, 0], omega: -45}
joints:
  c: {rolls: [disk, loop], at: 0, mu_s: 0.5}
at: [0, 2]
""")
    assert rec.get("error") is None, rec.get("error")
    r = rec["results"]
    assert [e["what"] for e in r["events"]] == ["slips", "separates", "impact"]
    sep, land = r["events"][1], r["events"][2]
    x0, v0 = sep["state"]["x"]["disk"], sep["state"]["v"]["disk"]
    tau = land["t"] - sep["t"]
    x1 = [x0[0] + v0[0] * tau, x0[1] + v0[1] * tau - 9.81 * tau**2 / 2]
    assert math.isclose(land["state"]["x"]["disk"][0], x1[0], abs_tol=1e-9)
    assert math.isclose(land["state"]["x"]["disk"][1], x1[1], abs_tol=1e-9)
    # landed: the centre at 0.9 m from the loop's centre (0, 1), inside
    assert math.isclose(math.hypot(x1[0], x1[1] - 1), 0.9, abs_tol=1e-9)
    # the spin is constant in flight
    assert math.isclose(land["state"]["omega"]["disk"][2], sep["state"]["omega"]["disk"][2], rel_tol=1e-12)
    # at separation N = 0: the centre's normal acceleration is gravity's alone
    n = [-x0[0] / 0.9, -(x0[1] - 1) / 0.9]
    vv = v0[0] ** 2 + v0[1] ** 2
    assert math.isclose(vv / 0.9, -9.81 * n[1], rel_tol=1e-7)      # the ODE route's speed, 100 × rtol, squared


def _rough_bowl_reference(mu, phi0, g=mp.mpf("9.81"), rho=1):
    """[(t, φ, holds)] at each stop of a block sliding in a rough circular bowl: W = φ̇² solves
    dW/dφ + 2 μ s W = −2 (g/ρ)(sin φ + μ s cos φ) in closed form (W(φ) = C e^{−2μsφ} + A sin φ
    + B cos φ), its zero the stop, the time ∫ dφ/√W (mpmath, 30 digits)."""
    out = []
    with mp.workdps(30):
        phi, t, c = phi0, mp.mpf(0), g / rho
        for _ in range(8):
            s = -mp.sign(phi)
            A, B = mp.lu_solve(mp.matrix([[1, 2 * mu * s], [2 * mu * s, -1]]), mp.matrix([-2 * c * mu * s, -2 * c]))
            C = -(A * mp.sin(phi) + B * mp.cos(phi)) * mp.exp(2 * mu * s * phi)

            def w(p, A=A, B=B, C=C, s=s):
                return C * mp.exp(-2 * mu * s * p) + A * mp.sin(p) + B * mp.cos(p)

            p1 = mp.findroot(w, -phi / 2)
            t += mp.quad(lambda p: 1 / mp.sqrt(abs(w(p))), sorted([p1, phi]))    # W ≥ 0 there; abs: its rounding at the ends
            holds = abs(mp.tan(p1)) <= mu
            out.append((t, p1, holds))
            phi = p1
            if holds:
                return out
    raise AssertionError("no stop")


def test_block_slides_in_a_rough_bowl_until_it_sticks():
    r = gallery("block-in-rough-bowl.yaml")["results"]
    stops = _rough_bowl_reference(mp.mpf("0.2"), mp.pi / 3)
    assert [h for _, _, h in stops] == [False, True]
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("c", "sticks")]
    assert [ph["route"] for ph in r["phases"]] == ["ode", "ode", "statics"]
    near(r["phases"][0]["t_end"], stops[0][0], stops[0][0], "slides back t")
    t2, p2, _ = stops[1]
    near(r["events"][0]["t"], t2, t2, "sticks t")
    near(r["events"][0]["state"]["x"]["block"][0], mp.sin(p2), 1, "x at rest")
    # at rest: the static friction that holds it, and the energy friction took
    near(r["reaction"]["c"]["N"][3], 9.81 * mp.cos(p2), 9.81, "N at rest")
    near(r["reaction"]["c"]["F"][3], 9.81 * mp.sin(p2), 9.81, "F at rest")
    near(r["W_nc"][3], -9.81 * (mp.cos(p2) - mp.cos(mp.pi / 3)), 9.81, "W_nc")


def test_rough_contact_on_a_curve_that_holds_at_rest():
    # released 10° up a bowl with μ = 0.3 (tan 10° < 0.3): it stays (statics), F = m g sin 10°
    from tests.conftest import solve_one_text

    rec = solve_one_text("""
type: scene
surfaces:
  bowl: {curve: {x1: "sin(q)", x2: "-cos(q)"}}
bodies:
  block: {shape: point, mass: 2}
joints:
  c: {contact: [block, bowl], at: "10*deg", mu: 0.3}
at: [0, 1]
""")
    assert rec.get("error") is None, rec.get("error")
    r = rec["results"]
    assert r["route"] == "statics" and r["events"] == []
    b = mp.radians(10)
    near(r["reaction"]["c"]["F"][1], 2 * 9.81 * mp.sin(b), 20, "F", 1e-12)
    near(r["reaction"]["c"]["N"][1], 2 * 9.81 * mp.cos(b), 20, "N", 1e-12)
