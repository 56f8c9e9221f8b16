"""A body held at rest by friction and struck (docs/types/scene.md, "Impacts"): a rough contact
made before the impact keeps its tangential row only while its friction impulse is within μ_s
times its normal impulse (Coulomb's law for impulses).  A block on a rough floor struck sideways
gets no normal impulse from the floor, so no friction impulse: it moves off (it was held fixed,
as if the floor were glue, before); struck downwards at an angle it stays when the floor's
friction impulse can hold it, else it slides through the impact at μ_k times the floor's normal
impulse.  Also: a point that comes over a stop's surface past its end, on the side away from
its normal, passes behind it (no impact, a warning naming the normal).

References, independent of dyncli's code:

* the pendulum striking a block: the bob's speed at the bottom from the energy integral
  (34.20, √(2 g L (1 − cos θ0))), Newton's restitution and momentum for two particles (28.7,
  28.4): V = m (1 + e) u/(m + M); the block then slides to rest under μ g (16.7): after V/(μ g)
  more seconds, V²/(2 μ g) further on;
* a ball striking the inclined face of a block: the impulse–momentum equations of both bodies and
  the floor (33.2 for particles) with Newton's law along the face's normal, solved by sympy in
  exact arithmetic (held: the floor's friction impulse unknown, the block's speed 0; sliding: the
  friction impulse −μ_k Λ_n, the block's speed unknown), with the static test |F| ≤ μ_s Λ_n
  deciding which.

Tolerances: the closed-form route (g = 0: free flight and one impulse solve) 1e-12 relative; the
ODE route at rtol 1e-10, ODE_GLOBAL × rtol of the quantity's scale.
"""

from __future__ import annotations

import math

import pytest
import sympy as sp

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL

EXACT = 1e-12

PENDULUM = """
type: scene
title: a pendulum bob strikes a block resting on a rough floor
params: {{m: 1, M: 2, L: 1, e: 0.7, mu: {mu}}}
surfaces:
  floor: {{through: [-5, 0], direction: [1, 0]}}
  face: {{body: block, through: [0, 0], direction: [0, 1], length: 0.2}}
bodies:
  bob: {{shape: point, mass: m, x: ["-L*sin(pi/3)", "1.1 - L*cos(pi/3)"]}}
  block: {{shape: point, mass: M, x: [0.2, 0]}}
joints:
  string: {{cord: [[0, 1.1], bob], length: L}}
  hit: {{stop: [bob, face], e: e}}
  foot: {{contact: [block, floor], mu: mu}}
t_end: 2
at: [0, 2]
accuracy: {{rtol: 1.0e-10}}
find: [{{event: impact, after: true}}, {{event: sticks}}]
"""


@pytest.mark.parametrize("mu", [0.3, 0.6])
def test_a_block_on_a_rough_floor_struck_sideways_moves_off_and_slides_to_rest(mu):
    g, m, M, L, e = 9.81, 1.0, 2.0, 1.0, 0.7
    u = math.sqrt(2 * g * L * (1 - math.cos(math.pi / 3)))       # the bob at the bottom (34.20)
    V = m * (1 + e) * u / (m + M)                                 # the block just after (28.4, 28.7)
    rec = solve_one_text(PENDULUM.format(mu=mu))
    r = rec["results"]
    (im,) = r["impacts"]
    tol = ODE_GLOBAL * 1e-10
    assert abs(im["v_n_before"] + u) <= tol * u
    assert abs(im["impulse"] - M * V) <= tol * M * V, "the block takes the whole impulse: none from the floor"
    hit, stop = r["find"]
    assert hit["reached"] and stop["reached"]
    assert abs(hit["v"]["block"][0] - V) <= tol * u, "just after: the block's speed (28.4, 28.7)"
    assert abs(hit["v"]["bob"][0] - (m - e * M) * u / (m + M)) <= tol * u
    lost = (1 - e * e) * 0.5 * (m * M / (m + M)) * u * u         # (28.16)
    assert abs(im["energy_loss"] - lost) <= tol * lost
    assert abs(hit["W_nc"] + lost) <= tol * lost, "the state just after counts the impact's loss in W_nc"
    assert abs(hit["energy_residual"]) <= tol * lost
    t_stop = hit["t"] + V / (mu * g)
    assert abs(stop["t"] - t_stop) <= tol * t_stop
    x_stop = 0.2 + V * V / (2 * mu * g)
    x_block = r["x"]["block"][1][0]
    assert abs(x_block - x_stop) <= tol * x_stop, (x_block, x_stop)
    assert not rec["warnings"], rec["warnings"]


INCLINE = """
type: scene
params: {{m: 1, M: 2, u: 3, th: {th}, mu: {mu}, e: 0.5}}
g: 0
surfaces:
  floor: {{through: [-5, 0], direction: [1, 0]}}
  face: {{body: block, through: [0, 0], direction: ["cos(th)", "sin(th)"], length: 1}}
bodies:
  ball: {{shape: point, mass: m, x: [-1, 0.2], v: [u, 0]}}
  block: {{shape: point, mass: M, x: [0.5, 0]}}
joints:
  hit: {{stop: [ball, face], e: e}}
  foot: {{contact: [block, floor], mu: mu}}
at: [0, 1]
"""


def _incline_reference(th, mu, m=1, M=2, u=3, e=sp.Rational(1, 2)):
    """(ball's velocity after, block's speed after, the face's impulse) by sympy: both bodies'
    momentum (33.2), the floor's normal impulse keeping the block on it, Newton's law along the
    face's normal n = (−sin th, cos th); held when the friction impulse needed is within μ Λ_n."""
    s, c = sp.sin(th), sp.cos(th)
    P, Lam, F, V, u1, u2 = sp.symbols("P Lambda F V u1 u2")
    common = [sp.Eq(m * (u1 - u), -P * s), sp.Eq(m * u2, P * c),        # the ball: impulse P n
              sp.Eq(0, -P * c + Lam),                                   # the block stays on the floor
              sp.Eq((u1 - V) * (-s) + u2 * c, -e * (-u * s))]           # Newton's law (28.7)
    held = sp.solve(common + [sp.Eq(M * V, P * s + F), sp.Eq(V, 0)], [P, Lam, F, V, u1, u2], dict=True)[0]
    if abs(held[F]) <= mu * held[Lam]:
        sol = held
    else:
        sol = sp.solve(common + [sp.Eq(M * V, P * s - mu * Lam)], [P, Lam, V, u1, u2], dict=True)[0]
    return [float(sol[u1]), float(sol[u2])], float(sol[V]), float(sol[P])


@pytest.mark.parametrize("mu", ["3/10", "2", "1", "17/10"])
def test_a_block_struck_down_at_an_angle_is_held_by_friction_or_slides_at_mu_k(mu):
    th = sp.pi / 3                      # tan 60° = 1.732: held from μ_s ≥ √3
    mu_s = sp.Rational(mu)
    ball, V, P = _incline_reference(th, mu_s)
    rec = solve_one_text(INCLINE.format(th=repr(float(th)), mu=float(mu_s)))
    r = rec["results"]
    (im,) = r["impacts"]
    assert abs(im["impulse"] - P) <= EXACT * P
    got_ball = r["v"]["ball"][1][:2]
    assert all(abs(a - b) <= EXACT * 3 for a, b in zip(got_ball, ball)), (got_ball, ball)
    assert abs(r["v"]["block"][1][0] - V) <= EXACT * 3, (r["v"]["block"][1], V)
    assert (V == 0) == (mu_s >= sp.sqrt(3))


BOUNCE_BESIDE = """
type: scene
params: {m: 1, M: 2}
surfaces:
  floor: {through: [-5, 0], direction: [1, 0]}
bodies:
  ball: {shape: point, mass: m, x: [-1, 1]}
  block: {shape: point, mass: M, x: [1, 0]}
joints:
  bounce: {stop: [ball, floor], e: 0.8}
  foot: {contact: [block, floor], mu: 0.3}
at: [0, 1]
"""


def test_an_impact_that_does_not_load_a_resting_block_leaves_it_held():
    """A ball bouncing beside a block at rest on a rough floor: the block's joint takes no impulse;
    rounding never makes it slip (no event of the foot, the block where it was)."""
    rec = solve_one_text(BOUNCE_BESIDE)
    r = rec["results"]
    assert [ev["joint"] for ev in r["events"]] == ["bounce"]
    assert r["x"]["block"][1][:2] == [1.0, 0.0]
    assert r["v"]["block"][1][:2] == [0.0, 0.0]


BEHIND = """
type: scene
title: the bob comes over the face from behind (the face drawn the wrong way round)
params: {m: 1, M: 2, L: 1}
surfaces:
  floor: {through: [-5, 0], direction: [1, 0]}
  face: {body: block, through: [0, 0.2], direction: [0, -1], length: 0.2}
bodies:
  bob: {shape: point, mass: m, x: ["-L*sin(pi/3)", "1.1 - L*cos(pi/3)"]}
  block: {shape: point, mass: M, x: [0.2, 0]}
joints:
  string: {cord: [[0, 1.1], bob], length: L}
  hit: {stop: [bob, face], e: 0.7}
  foot: {contact: [block, floor], mu: 0.3}
t_end: 0.45
at: [0, 0.45]
"""


def test_a_point_coming_over_a_stop_past_its_end_on_the_far_side_passes_behind_with_a_warning():
    rec = solve_one_text(BEHIND)
    r = rec["results"]
    assert r["impacts"] == [] and r["events"] == []
    (w,) = [w for w in rec["warnings"] if w.startswith("hit:")]
    assert "far side" in w and "n = [1, 0]" in w and "reverse the surface's direction" in w
    assert r["v"]["block"][1][:2] == [0.0, 0.0]


def test_the_gallery_pendulum_strikes_a_block_on_a_rough_floor():
    """problems/scenes/pendulum-strikes-block.yaml: the numbers of its header, from the closed
    forms above (mpmath's K(1/4) for the swing's quarter period)."""
    import mpmath as mp

    from tests.topics.scene.common import gallery

    rec = gallery("pendulum-strikes-block.yaml")
    r = rec["results"]
    g, u = 9.81, math.sqrt(9.81)
    V = 1.7 * u / 3
    t1 = float(mp.ellipk(mp.mpf(1) / 4) * mp.sqrt(1 / mp.mpf(g)))
    tol = ODE_GLOBAL * 1e-10
    assert abs(r["impacts"][0]["t"] - t1) <= tol * t1
    assert abs(r["find"][0]["v"]["block"][0] - V) <= tol * V
    assert abs(r["find"][1]["t"] - (t1 + V / (0.3 * g))) <= tol * 2
    assert abs(r["x"]["block"][1][0] - (0.2 + 2.89 / 5.4)) <= tol


DISK = """
type: scene
title: a ball strikes a disk at rest on a rough floor level with its centre
params: {m: 1, M: 2, R: 0.1}
surfaces:
  floor: {through: [-5, 0], direction: [1, 0]}
  face: {body: wheel, through: [-0.1, 0.05], direction: [0, 1], length: 0.1}
bodies:
  ball: {shape: point, mass: m, x: [-0.2, 0.10545], v: [3, 0]}
  wheel: {shape: disk, mass: M, radius: R, x: [0, 0.1], angle: 0}
joints:
  hit: {stop: [ball, face], e: 1}
  roll: {rolls: [wheel, floor], mu_s: 0.3, mu_k: 0.2}
t_end: 1
at: [0, 1]
find: [{event: impact, after: true}, {event: sticks}]
accuracy: {max_cpu: 10}     # (0.4 s of CPU alone; the distance stops refining at half the budget, which a loaded machine can reach)
"""


def test_a_disk_at_rest_struck_level_with_its_centre_skids_then_rolls():
    """The blow passes through the centre and the floor gives no normal impulse, so no friction
    impulse: the disk leaves with V = 2 m u/(m + M) (e = 1) and no spin (it was held rolling
    before), skids with μ_k g against its slip and rolls from V/(3 μ_k g) later at 2V/3 (a
    uniform disk: v − μ_k g t = 2 μ_k g t).  The face it carries turns with it afterwards and
    sweeps over the ball moving away: no impact and no warning."""
    g, m, M, u, mu_k = 9.81, 1.0, 2.0, 3.0, 0.2
    V = 2 * m * u / (m + M)
    rec = solve_one_text(DISK)
    r = rec["results"]
    after, rolls = r["find"]
    assert abs(after["v"]["wheel"][0] - V) <= EXACT * V and abs(after["omega"]["wheel"][2]) <= EXACT * V / 0.1
    assert abs(rolls["t"] - (after["t"] + V / (3 * mu_k * g))) <= EXACT
    assert abs(r["v"]["wheel"][1][0] - 2 * V / 3) <= EXACT * V
    assert [(ev["joint"], ev["what"]) for ev in r["events"]] == [("hit", "impact"), ("roll", "sticks")]
    assert rec["warnings"] == []
