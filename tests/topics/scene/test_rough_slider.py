"""A rough slider (docs/types/scene.md, the joints' table): a point body threaded on a rough rod,
held both ways (N signed), kinetic friction μ_k |N| against its slip, held while |F| ≤ μ_s |N|.
Where N changes sign while it slides, the friction keeps opposing the slip with the new |N|
(a kink of the motion, no event).

References, independent of dyncli's code: mpmath's Taylor ODE solver at 30 digits on the collar's
own equation m ẍ = F_x(x) − μ_k |N(x)| sign ẋ with N(x) = m g − F_y(x) (the rod horizontal),
integrated piecewise: the instant where N(x(t)) = 0 is mpmath's findroot on the first piece's
solution and the second piece starts there — not through dyncli's rows; the static case by hand.

Tolerances: the ODE route at rtol 1e-11, ODE_GLOBAL × rtol of the quantity's scale; the statics
route 1e-12.
"""

from __future__ import annotations

import math

import mpmath as mp

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL
from tests.topics.scene.test_refusals import refusal

COLLAR = """
type: scene
title: a collar on a rough rod; the spring's pull turns the rod's normal force round
params: {{m: 2, k: {k}}}
surfaces:
  rod: {{through: [-5, 0], direction: [1, 0]}}
bodies:
  collar: {{shape: point, mass: m, x: [0, 0]}}
joints:
  guide: {{slider: [collar, rod], mu: 0.3}}
forces:
  - {{spring: [collar, [{ax}, 0.5]], k: k, L: 0.3}}
t_end: 0.4
at: [0, 0.1, 0.2, 0.3, 0.4]
accuracy: {{rtol: 1.0e-11}}
find: [{{when: {{reaction.guide.N: 0}}}}]
"""


def _collar_reference(times):
    """(t where N = 0, [(x, ẋ) at each time]) by mpmath: the collar sliding to +x the whole time."""
    mp.mp.dps = 30
    m, k, L, mu, g = mp.mpf(2), mp.mpf(60), mp.mpf("0.3"), mp.mpf("0.3"), mp.mpf("9.81")

    def pull(x):
        dx, dy = 1 - x, mp.mpf("0.5")
        ell = mp.sqrt(dx * dx + dy * dy)
        return k * (ell - L) * dx / ell, k * (ell - L) * dy / ell

    def N(x):                                   # the rod's force on the collar along +e2
        return m * g - pull(x)[1]

    def rhs(sign_n):
        return lambda t, y: [y[1], (pull(y[0])[0] - mu * sign_n * N(y[0])) / m]

    first = mp.odefun(rhs(-1), 0, [mp.mpf(0), mp.mpf(0)])       # N < 0 at the start
    t0 = mp.findroot(lambda t: N(first(t)[0]), 0.15)
    second = mp.odefun(rhs(1), t0, first(t0))
    return t0, [first(mp.mpf(t)) if t < t0 else second(mp.mpf(t)) for t in times]


def test_a_collar_sliding_on_a_rough_rod_through_the_reversal_of_its_normal_force():
    rec = solve_one_text(COLLAR.format(k=60, ax=1))
    r = rec["results"]
    t0, ref = _collar_reference(r["t"])
    tol = ODE_GLOBAL * 1e-11
    assert abs(r["find"][0]["t"] - float(t0)) <= tol * float(t0)
    for i, (x, xd) in enumerate(ref):
        assert abs(r["x"]["collar"][i][0] - float(x)) <= tol * 1.3, (r["t"][i], r["x"]["collar"][i][0], float(x))
        assert abs(r["v"]["collar"][i][0] - float(xd)) <= tol * 4.3
    N, F = r["reaction"]["guide"]["N"], r["reaction"]["guide"]["F"]
    assert N[0] < 0 < N[-1], "pulled off the rod at first, pressed on it later"
    for n, f in zip(N[1:], F[1:]):                  # sliding to +x: F = −μ_k |N| throughout
        assert abs(f + 0.3 * abs(n)) <= 1e-12 * 20
    assert r["events"] == [] and not rec["warnings"]


def test_a_collar_held_by_friction_while_the_rod_pulls_it_down():
    # the spring pulls up harder than the weight (N < 0: the rod holds the collar down) and along
    # the rod less than μ_s |N|: it stays; F = −F_x, N = m g − F_y (16.7)
    text = """
type: scene
params: {m: 2}
surfaces:
  rod: {through: [-5, 0], direction: [1, 0]}
bodies:
  collar: {shape: point, mass: m, x: [0, 0]}
joints:
  guide: {slider: [collar, rod], mu_s: 0.8, mu_k: 0.6}
forces:
  - {force: collar, F: [20, 50]}
at: [0, 1]
"""
    r = solve_one_text(text)["results"]
    assert r["route"] == "statics" and r["events"] == []
    assert abs(r["reaction"]["guide"]["N"][1] - (2 * 9.81 - 50)) <= 1e-12 * 50
    assert abs(r["reaction"]["guide"]["F"][1] + 20) <= 1e-12 * 50
    assert r["x"]["collar"][1][:2] == [0.0, 0.0]


def test_a_rough_slider_of_a_rigid_body_is_refused():
    refusal("""
type: scene
surfaces:
  rod: {through: [-5, 0], direction: [1, 0]}
bodies:
  collar: {shape: box, mass: 1, size: [0.2, 0.1], x: [0, 0]}
joints:
  guide: {slider: [collar, rod], mu: 0.3}
at: [0]
""", "joints.guide.slider.0", "a rough slider is for a point body", "write a contact with mu at each point")


SPUN = """
type: scene
title: a collar on a rough rod whose motor brakes
g: 0
params: {m: 0.5, mu: 0.3, w0: 4, b: 8, r0: 0.5, L: 2}
surfaces:
  rod_line: {through: [0, 0], direction: [1, 0], body: rod, length: L}
bodies:
  rod: {shape: rod, mass: 3, length: L, x: ["L/2", 0], angle: 0}
  collar: {shape: point, mass: m, x: [r0, 0]}
joints:
  pivot: {pin: [rod.end1, ground]}
  spin: {drive: rod.angle, value: "w0*t - b*t*t/2"}
  sleeve: {slider: [collar, rod_line], mu: mu}
at: [0, 0.05, 0.1, 0.2, 0.3]
t_end: 0.3
accuracy: {rtol: 1.0e-11}
find: [{when: {reaction.sleeve.N: 0}}, {when: {reaction.sleeve.N: 0}, occurrence: 2}]
"""


def _spun_reference(T):
    """The collar on the braked rod in polar coordinates along it (ω = w0 − b t, ω̇ = −b, g = 0):
    r̈ = ω² r − μ |N|/m (sliding outward), N/m = 2 ω ṙ + r ω̇ across the rod; mpmath piece by
    piece between the reversals of N (findroot on each piece's solution).  (reversals, r at t)."""
    mp.mp.dps = 30
    mu, w0, b, r0 = mp.mpf("0.3"), mp.mpf(4), mp.mpf(8), mp.mpf("0.5")

    def Nm(t, r, rd):
        return 2 * (w0 - b * t) * rd - b * r

    def rhs(sgn):
        return lambda t, y: [y[1], (w0 - b * t) ** 2 * y[0] - mu * sgn * Nm(t, y[0], y[1])]

    t0, y0, sgn, pieces, flips = mp.mpf(0), [r0, mp.mpf(0)], -1, [], []
    while True:
        f = mp.odefun(rhs(sgn), t0, y0)
        pieces.append((t0, f))
        prev, nxt = t0, None
        for k in range(1, 400):
            t = t0 + mp.mpf(k) / 200
            if t > T:
                break
            if sgn * Nm(t, *f(t)) < 0:
                nxt = mp.findroot(lambda s: Nm(s, *f(s)), (prev, t), solver="anderson")
                break
            prev = t
        if nxt is None:
            return flips, lambda t: [g for s, g in pieces if s <= t][-1](mp.mpf(t))[0]
        flips.append(nxt)
        t0, y0, sgn = nxt, f(nxt), -sgn


def test_a_collar_on_a_rough_rod_a_motor_brakes_is_held_both_ways():
    """The braking rod first pulls the collar back (N = −m b r0 < 0: a one-sided contact would let
    it fly off), then its Coriolis push 2 m ω ṙ wins (N > 0), then the braking wins again: two
    reversals of N, the friction μ_k |N| against the outward slip throughout."""
    r = solve_one_text(SPUN)["results"]
    flips, radius = _spun_reference(mp.mpf("0.3"))
    tol = ODE_GLOBAL * 1e-11
    assert len(flips) == 2
    for want, f in zip(flips, r["find"]):
        assert abs(f["t"] - float(want)) <= tol * float(want), (f["t"], float(want))
    for t, x in zip(r["t"], r["x"]["collar"]):
        assert abs(math.hypot(x[0], x[1]) - float(radius(t))) <= tol * 0.8, t
    assert abs(r["reaction"]["sleeve"]["N"][0] + 2.0) <= 1e-12 * 2
    for n, f in zip(r["reaction"]["sleeve"]["N"], r["reaction"]["sleeve"]["F"]):
        assert abs(f + 0.3 * abs(n)) <= 1e-12 * 2


def test_the_gallery_collar_on_a_rough_rod():
    """problems/scenes/collar-rough-rod.yaml is the first test's collar: its header's numbers."""
    from tests.topics.scene.common import gallery

    r = gallery("collar-rough-rod.yaml")["results"]
    t0, ((x1, _),) = _collar_reference([0.4])
    tol = ODE_GLOBAL * 1e-11
    assert abs(r["find"][0]["t"] - float(t0)) <= tol * float(t0)
    assert abs(r["x"]["collar"][1][0] - float(x1)) <= tol * 1.3
    assert abs(r["reaction"]["guide"]["N"][0] + 2.3301552810007564) <= 1e-12 * 20
