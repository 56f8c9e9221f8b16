"""Surfaces carried by a body (``surfaces.NAME.body``): a block on a wedge free to slide, a block
on a block pulled across the floor, a bead on a bar driven round in the vertical plane, a mass
held by a spring on a cart — against references derived here by hand (16.7 for each body with
the contact forces equal and opposite, solved as a small linear system in mpmath) and, where the
motion is not one of constant accelerations, the closed-form solution of the bead's equation in
the bar's turning frame (mpmath at 30 digits).  Exact routes: 1e-12 of each quantity's scale;
the ODE route at its default rtol: ODE_GLOBAL × 1e-10.
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL
from tests.topics.scene.common import gallery
from tests.topics.scene.test_refusals import refusal
from tests.topics.scene.test_start import near

G = 9.81
EXACT = 1e-12
ODE_TOL = ODE_GLOBAL * 1e-10


WEDGE = """
type: scene
params: {{M: 4, m: 1, beta: "30*deg"}}
surfaces:
  floor: {{through: [0, 0], direction: [1, 0]}}
  slope: {{body: wedge, through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}}
bodies:
  wedge: {{shape: box, mass: M, size: [2, 1], x: [1, 0.5], angle: 0}}
  block: {{shape: point, mass: m, x: ["cos(beta)", "sin(beta)"]}}
joints:
  on_floor: {{slider: [wedge, floor]}}
  on_slope: {{contact: [block, slope]{friction}}}
at: [0, 0.5]
"""


def wedge_reference(mu):
    """(A, s̈, N) of the block sliding down the wedge's slope with kinetic friction μ (up the
    slope, on the block), the wedge (M) free on a smooth floor: the block's acceleration is
    A e1 − s̈ (cos β, sin β); 16.7 for the block along e1, e2 and for the wedge along e1."""
    M, m, b = 4, 1, mp.pi / 6
    c, s = mp.cos(b), mp.sin(b)
    A = mp.matrix([[m, -m * c, s - mu * c], [0, -m * s, -(c + mu * s)], [M, 0, -(s - mu * c)]])
    return mp.lu_solve(A, mp.matrix([0, -m * G, 0]))


@pytest.mark.parametrize("mu", [0, mp.mpf("0.3")])
def test_a_block_slides_down_a_wedge_free_on_a_smooth_floor(mu):
    rec = solve_one_text(WEDGE.format(friction=f", mu: {mu}" if mu else ""))
    r = rec["results"]
    A, sdd, N = wedge_reference(mu)
    b = mp.pi / 6
    if mu == 0:     # the textbook's forms
        assert abs(A - mp.sin(b) * mp.cos(b) * G / (4 + mp.sin(b) ** 2)) < 1e-14
        assert abs(N - 4 * G * mp.cos(b) / (4 + mp.sin(b) ** 2)) < 1e-14
    assert r["route"] == "closed-form" and r["dof"] == 2 and r["events"] == []
    near(r["a"]["wedge"][0][0], A, G, "A")
    near(r["a"]["block"][0][0], A - sdd * mp.cos(b), G, "block a1")
    near(r["a"]["block"][1][1], -sdd * mp.sin(b), G, "block a2")
    near(r["reaction"]["on_slope"]["N"][0], N, G, "N")
    near(r["reaction"]["on_slope"]["F"][0], mu * N, G, "F")
    near(r["reaction"]["on_floor"]["N"][0], 5 * G - sdd * mp.sin(b), 5 * G, "floor N")   # 29.5 for the two
    near(r["x"]["wedge"][1][0], 1 + A / 8, 1, "wedge x at 0.5 s")
    assert "G.0" in [i["name"] for i in r["integrals"]]     # the friction is internal to the pair (36.10)


def test_block_on_wedge_gallery():
    # the gallery's file is WEDGE (smooth) with the slope's length and a find: the same hand
    # solution; halfway down (x2 = 0.25 m) at √(0.5/(s̈ sin β))
    r = gallery("block-on-wedge.yaml")["results"]
    A, sdd, N = wedge_reference(0)
    b = mp.pi / 6
    assert r["route"] == "closed-form"
    near(r["a"]["wedge"][0][0], A, G, "A")
    near(r["reaction"]["on_slope"]["N"][0], N, G, "N")
    near(r["x"]["block"][2][1], mp.sin(b) - sdd * mp.sin(b) / 8, 1, "block x2 at 0.5 s")
    near(r["find"][0]["t"], mp.sqrt(mp.mpf("0.5") / (sdd * mp.sin(b))), 1, "halfway down")
    near(4 * r["v"]["wedge"][2][0] + r["v"]["block"][2][0], 0, 4 * A, "G.0 (36.10)")


def test_a_block_on_a_rough_wedge_that_can_hold_it_stays():
    # μ_s = 0.7 > tan 30°: held, so nothing moves (no horizontal load on the pair): N = m g cos β,
    # F = m g sin β up the slope
    r = solve_one_text(WEDGE.format(friction=", mu: 0.7"))["results"]
    b = mp.pi / 6
    for body in ("wedge", "block"):
        near(r["v"][body][1][0], 0, 1, f"v {body}")
    near(r["reaction"]["on_slope"]["N"][0], G * mp.cos(b), G, "N")
    near(r["reaction"]["on_slope"]["F"][0], G * mp.sin(b), G, "F")


def test_a_block_on_a_block_slips_and_leaves_the_deck_at_its_end():
    # the lower block (M = 3 kg) pulled by 20 N on a smooth floor; the upper (1 kg) on its deck
    # (μ_s = 0.3, μ_k = 0.2): held together they would need m F/(m + M) = 5 N > μ_s m g, so it
    # slips: a_upper = μ_k g, a_lower = (F − μ_k m g)/M; starting 0.5 m ahead of the lower's
    # centre, it reaches the deck's back end (1 m behind) where 1.5 = (a_lower − a_upper) t²/2
    rec = solve_one_text("""
type: scene
params: {m: 1, M: 3, F: 20}
surfaces:
  floor: {through: [-10, 0], direction: [1, 0]}
  deck: {body: lower, through: [-1, 0.5], direction: [1, 0], length: 2}
bodies:
  lower: {shape: box, mass: M, size: [2, 0.5], x: [0, 0.25], angle: 0}
  upper: {shape: point, mass: m, x: [0.5, 0.5]}
joints:
  slide: {slider: [lower, floor]}
  rest: {contact: [upper, deck], mu_s: 0.3, mu_k: 0.2}
forces:
  - {force: lower, F: [F, 0]}
at: [0, 0.5]
t_end: 1
""")
    r = rec["results"]
    au, al = mp.mpf("0.2") * G, (20 - mp.mpf("0.2") * G) / 3
    assert r["route"] == "closed-form"
    near(r["a"]["upper"][0][0], au, G, "a upper")
    near(r["a"]["lower"][0][0], al, G, "a lower")
    near(r["reaction"]["rest"]["F"][0], mp.mpf("0.2") * G, G, "F forward on the upper")
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("rest", "leaves")]
    near(r["events"][0]["t"], mp.sqrt(3 / (al - au)), 1, "leaves at")


def test_a_bead_on_a_bar_driven_round_leaves_where_the_bar_stops_pushing():
    # the bar turns at ω = 1 rad/s about its centre in the vertical plane; the bead (0.1 kg) on
    # its upper line starts at s0 = 0.5 m carried with it (its velocity left out: the one the
    # contact imposes, ω s0 up).  In the bar's frame (16.7 with r = s d̂, θ = ω t):
    #   s̈ − ω² s = −g sin ωt,  N = m (g cos ωt + 2 ω ṡ)  (the Coriolis term on the bar),
    # so s = s0 cosh ωt − (g/2ω²)(sinh ωt − sin ωt); it leaves where N = 0 (mpmath findroot)
    rec = solve_one_text("""
type: scene
bodies:
  bar: {shape: rod, mass: 2, length: 2, x: [0, 0], angle: 0}
  bead: {shape: point, mass: 0.1, x: [0.5, 0]}
surfaces:
  top: {body: bar, through: [0, 0], direction: [1, 0]}
joints:
  axle: {pin: [bar, ground]}
  turn: {drive: bar.angle, value: "1.0*t"}
  on: {contact: [bead, top]}
at: [0, 0.2]
t_end: 2
""")
    r = rec["results"]
    assert rec["warnings"] == []
    m, s0 = mp.mpf("0.1"), mp.mpf("0.5")
    with mp.workdps(30):
        def s(t):
            return s0 * mp.cosh(t) - G / 2 * (mp.sinh(t) - mp.sin(t))

        def N(t):
            return m * (G * mp.cos(t) + 2 * mp.diff(s, t))

        t_off = mp.findroot(N, mp.mpf("0.8"))
    near(r["v"]["bead"][0][1], s0, 1, "carried up at t = 0")
    t = mp.mpf("0.2")
    near(r["reaction"]["on"]["N"][1], N(t), m * G, "N at 0.2 s", ODE_TOL)
    near(r["x"]["bead"][1][0], s(t) * mp.cos(t), 1, "x1 at 0.2 s", ODE_TOL)
    near(r["x"]["bead"][1][1], s(t) * mp.sin(t), 1, "x2 at 0.2 s", ODE_TOL)
    assert [(e["joint"], e["what"]) for e in r["events"]] == [("on", "separates")]
    near(r["events"][0]["t"], t_off, 1, "leaves at", ODE_TOL)


COLLAR = """
type: scene
bodies:
  bar: {{shape: rod, mass: 2, length: 4, x: [0, 0], angle: 0}}
  collar: {{shape: {shape}, mass: 0.1, x: [0.5, 0]{extra}}}
surfaces:
  along: {{body: bar, through: [0, 0], direction: [1, 0]}}
joints:
  axle: {{pin: [bar, ground]}}
  turn: {{drive: bar.angle, value: "1.0*t"}}
  guide: {{slider: [collar, along]}}
at: [0, 0.2, 1.5]
"""


@pytest.mark.parametrize("shape, extra", [("point", ""), ("box", ", size: [0.1, 0.1], angle: 0")])
def test_a_collar_on_a_bar_driven_round_in_the_vertical_plane(shape, extra):
    # the bead's equation with a two-sided guide: s = s0 cosh t − (g/2)(sinh t − sin t),
    # N = m (g cos t + 2 ṡ) now of either sign (here negative by t = 1.5 s); a box collar turns
    # with the bar (the guide keeps its angle to the bar: angle = t), the bar's drive couple at
    # t = 0 is N s0 (the collar pressing on the bar at s0, at rest along it)
    rec = solve_one_text(COLLAR.format(shape=shape, extra=extra))
    r = rec["results"]
    m, s0 = mp.mpf("0.1"), mp.mpf("0.5")
    with mp.workdps(30):
        def s(t):
            return s0 * mp.cosh(t) - G / 2 * (mp.sinh(t) - mp.sin(t))

        def N(t):
            return m * (G * mp.cos(t) + 2 * mp.diff(s, t))

    assert rec["warnings"] == [] and r["events"] == []
    for k, t in enumerate((0, mp.mpf("0.2"), mp.mpf("1.5"))):
        near(r["reaction"]["guide"]["N"][k], N(t), m * G, f"N.{k}", ODE_TOL * 10)
        near(r["x"]["collar"][k][0], s(t) * mp.cos(t), 4, f"x1.{k}", ODE_TOL * 10)
        near(r["x"]["collar"][k][1], s(t) * mp.sin(t), 4, f"x2.{k}", ODE_TOL * 10)
    near(r["drive"]["turn"][0], N(0) * s0, m * G, "drive couple")
    if shape == "box":
        near(r["angle"]["collar"][2], mp.mpf("1.5"), 1, "the collar turns with the bar", ODE_TOL * 10)
        assert "M" in r["reaction"]["guide"]


PLANK = """
type: scene
params: {{M: 2, m: 3, R: 0.2, F: 12}}
surfaces:
  floor: {{through: [-10, 0], direction: [1, 0]}}
  deck: {{body: plank, through: [-2, 0.1], direction: [1, 0], length: 4}}
bodies:
  plank: {{shape: box, mass: M, size: [4, 0.1], x: [0, 0.05], angle: 0}}
  drum: {{shape: disk, mass: m, radius: R, x: [0, 0.3], angle: 0}}
joints:
  slide: {{slider: [plank, floor]}}
  roll: {{rolls: [drum, deck], mu_s: {mu}}}
forces:
  - {{force: plank, F: [F, 0]}}
at: [0, 1]
"""


def test_a_plank_pulled_from_under_a_rolling_drum():
    # the drum (a uniform disk, m = 3 kg, R = 0.2 m) rolls on the plank (M = 2 kg, smooth floor,
    # pulled by F = 12 N): drum m a_c = f, (m R²/2) α = f R, no slip on the plank a_p = a_c + R α
    # (15.8 relative to the deck), plank M a_p = F − f: a_p = 3F/(3M + m), a_c = a_p/3, f = m a_c;
    # rolling needs f = 4 N ≤ μ_s N = 14.715 N: it rolls
    r = solve_one_text(PLANK.format(mu=0.5))["results"]
    a_p = mp.mpf(36) / 9
    assert r["route"] == "closed-form" and r["events"] == []
    near(r["a"]["plank"][0][0], a_p, 4, "a plank")
    near(r["a"]["drum"][0][0], a_p / 3, 4, "a drum")
    near(r["alpha"]["drum"][0][2], (a_p - a_p / 3) / mp.mpf("0.2"), 20, "alpha (the drum turns back over the deck)")
    near(r["reaction"]["roll"]["F"][0], 3 * a_p / 3, 4, "friction on the drum")
    near(r["reaction"]["roll"]["slip_margin"][0], mp.mpf("0.5") * 3 * G - 4, 3 * G, "slip margin")


def test_drum_on_plank_gallery():
    # the gallery's file is PLANK with μ_s = 0.5: the same hand solution, and the positions at
    # 1 s from rest (a t²/2)
    r = gallery("drum-on-plank.yaml")["results"]
    a_p = mp.mpf(36) / 9
    near(r["a"]["plank"][0][0], a_p, 4, "a plank")
    near(r["x"]["plank"][1][0], a_p / 2, 4, "x plank")
    near(r["x"]["drum"][1][0], a_p / 6, 4, "x drum")
    near(r["reaction"]["roll"]["F"][0], a_p, 4, "f")


def test_a_plank_pulled_harder_than_friction_can_roll_the_drum_slides_under_it():
    # μ_s = μ_k = 0.1: rolling would need f = 4 N > μ N = 2.943 N, so the deck slips under the
    # drum from t = 0: f = μ m g forward on the drum, a_c = μ g, α = 2 μ g / R, a_p = (F − μ m g)/M
    r = solve_one_text(PLANK.format(mu=0.1))["results"]
    f = mp.mpf("0.1") * 3 * G
    near(r["reaction"]["roll"]["F"][0], f, 4, "kinetic friction")
    near(r["a"]["drum"][0][0], mp.mpf("0.1") * G, 4, "a drum")
    near(r["alpha"]["drum"][0][2], 2 * mp.mpf("0.1") * G / mp.mpf("0.2"), 20, "alpha")
    near(r["a"]["plank"][0][0], (12 - f) / 2, 4, "a plank")


def test_a_mass_on_a_spring_on_a_free_cart_oscillates_at_the_reduced_mass_frequency():
    # B (1 kg) on the cart's smooth deck, tied to the cart (3 kg, free on a smooth floor) by a
    # spring k = 12 N/m: ω² = k (1/m + 1/M) = 16 besides the free translation (ω² = 0), whose
    # mode moves both together; the other keeps the centre of mass: M x_cart + m x_B = 0
    rec = solve_one_text("""
type: scene
surfaces:
  floor: {through: [-10, 0], direction: [1, 0]}
  deck: {body: cart, through: [-1, 0.5], direction: [1, 0]}
bodies:
  cart: {shape: box, mass: 3, size: [2, 0.5], x: [0, 0.25], angle: 0, points: {wall: [-0.5, 0.25]}}
  B: {shape: point, mass: 1, x: [0.3, 0.5]}
joints:
  roll: {slider: [cart, floor]}
  on: {contact: [B, deck]}
forces:
  - {spring: [B, cart.wall], k: 12, L: 0.5}
linearize: true
at: [0]
""")
    (eq,) = rec["results"]["equilibria"]
    assert eq["coordinates"] == ["x.cart.0", "x.B.0"] and eq["stability"] == "neutral"
    near(eq["omega2"][0], 0, 16, "translation", 1e-9)
    near(eq["omega2"][1], 16, 16, "omega2", 1e-9)
    assert eq["frequencies"][0] == 0.0                     # the free translation: a rigid-body mode
    near(eq["frequencies"][1], 4, 4, "omega", 1e-9)
    near(eq["modes"][1][1], -3, 3, "mode", 1e-9)


def test_a_ball_dropped_on_a_moving_cart_rebounds_and_is_dragged_along_by_friction():
    # a stop on the cart's deck (e = 0.5, μ = 0.2): the ball (1 kg, 1 m above the deck, 1 m/s)
    # meets the deck (the cart at 2 m/s, 3 kg, on a smooth floor that holds it upright) after
    # √(2/g), at v = √(2 g); rebound e v (28.7), normal impulse m (1 + e) v.  Its slip over the
    # deck, −1 m/s, needs a friction impulse F (1/m + 1/M) = 1 to stop: F = 0.75 N·s < μ P, so it
    # ends sticking (Routh's method, 33.2): both at 1.75 m/s along e1 after
    rec = solve_one_text("""
type: scene
surfaces:
  floor: {through: [-10, 0], direction: [1, 0]}
  deck: {body: cart, through: [-1, 0.5], direction: [1, 0]}
bodies:
  cart: {shape: box, mass: 3, size: [2, 0.5], x: [0, 0.25], angle: 0, v: [2, 0]}
  B: {shape: point, mass: 1, x: [0.3, 1.5], v: [1, 0]}
joints:
  roll: {slider: [cart, floor]}
  on: {stop: [B, deck], e: 0.5, mu: 0.2}
at: [0, 0.5]
""")
    r = rec["results"]
    v = mp.sqrt(2 * G)
    (imp,) = r["impacts"]
    near(imp["t"], mp.sqrt(2 / mp.mpf(G)), 1, "t")
    near(imp["v_n_before"], -v, v, "v_n before")
    near(imp["v_n_after"], v / 2, v, "v_n after")
    near(imp["impulse"], mp.mpf("1.5") * v, v, "P")
    near(imp["impulse_F"], mp.mpf("0.75"), v, "F")
    near(imp["slip_before"], -1, 1, "slip before")
    near(imp["slip_after"], 0, 1, "slip after")
    near(r["v"]["B"][1][0], mp.mpf("1.75"), 2, "ball after")
    near(r["v"]["cart"][1][0], mp.mpf("1.75"), 2, "cart after")


CARRIED = """
type: scene
surfaces:
  deck: {{body: cart, through: [-1, 0.5], direction: [1, 0]{extra}}}
bodies:
  cart: {{shape: box, mass: 3, size: [2, 0.5], x: [0, 0.25], angle: 0}}
  B: {{shape: disk, mass: 1, radius: 0.1, x: [0.3, 0.6], angle: 0}}
joints:
  j: {joint}
at: [0]
"""


@pytest.mark.parametrize("joint, field, needles", [
    ("{contact: [cart.center, deck]}", "joints.j.contact.0", ("cannot touch its own surface",)),
    ("{slider: [cart, deck]}", "joints.j.slider.0", ("cannot slide on its own surface",)),
])
def test_a_body_on_its_own_carried_surface_is_refused(joint, field, needles):
    refusal(CARRIED.format(extra="", joint=joint), field, *needles)


def test_the_body_that_carries_a_surface_is_given_its_place():
    # the line is drawn in ground coordinates at t = 0 with its body where the file puts it: a
    # carrier left to the joints would move the line away from where it was drawn
    refusal(WEDGE.format(friction="").replace("size: [2, 1], x: [1, 0.5], angle: 0", "size: [2, 1]"),
            "bodies.wedge", "give the position x of 'wedge'", "carries the surface 'slope'")


def test_a_carried_surface_names_a_body_that_exists():
    # (a carried curve is no longer refused: tests/topics/scene/test_carried_curve.py)
    refusal(CARRIED.format(extra="", joint="{contact: [B, deck]}").replace("body: cart", "body: crat"),
            "surfaces.deck.body", "unknown body 'crat'", "did you mean 'cart'")


def test_an_incline_on_a_cart_driven_at_constant_speed_is_an_incline_galileo():
    # the cart's x prescribed as 3 t (no acceleration): in its frame the block slides down the rough
    # slope as on a fixed incline, s̈ = g (sin β − μ cos β) (16.7), N = m g cos β; on the ground it
    # has the cart's 3 m/s besides (given only the cart's motion: the block's velocity left out is
    # the one the contact imposes, the cart's)
    rec = solve_one_text("""
type: scene
params: {beta: "30*deg"}
surfaces:
  slope: {body: cart, through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}
bodies:
  cart: {shape: box, mass: 10, size: [2, 1], x: [1, 0.5], angle: 0}
  block: {shape: point, mass: 2, x: ["cos(beta)", "sin(beta)"], v: [3, 0]}
joints:
  go: {drive: cart.x1, value: "1 + 3*t"}
  lift: {drive: cart.x2, value: 0.5}
  turn: {drive: cart.angle, value: 0}
  on: {contact: [block, slope], mu: 0.2}
at: [0, 0.5]
""")
    r = rec["results"]
    b = mp.pi / 6
    a = G * (mp.sin(b) - mp.mpf("0.2") * mp.cos(b))
    assert rec["warnings"] == []
    tol = EXACT if r["route"] == "closed-form" else ODE_TOL      # (a drive in time: the ODE route)
    near(r["reaction"]["on"]["N"][1], 2 * G * mp.cos(b), 2 * G, "N", 10 * tol)
    near(r["reaction"]["on"]["F"][1], mp.mpf("0.2") * 2 * G * mp.cos(b), 2 * G, "F up the slope", 10 * tol)
    near(r["x"]["block"][1][0] - r["x"]["cart"][1][0], mp.cos(b) - 1 - a / 8 * mp.cos(b), 1, "relative x1", tol)
    near(r["x"]["block"][1][1], mp.sin(b) - a / 8 * mp.sin(b), 1, "x2", tol)
    near(r["v"]["block"][1][0], 3 - a / 2 * mp.cos(b), 3, "v1", tol)


SPUN_ON_DECK = """
type: scene
surfaces:
  floor: {through: [-10, 0], direction: [1, 0]}
  deck: {body: plank, through: [-5, 0.1], direction: [1, 0], length: 10}
bodies:
  plank: {shape: box, mass: 2, size: [10, 0.1], x: [0, 0.05], angle: 0, v: [0, 0]}
  drum: {shape: disk, mass: 3, radius: 0.2, x: [0, 0.3], angle: 0, v: [0, 0], omega: -20}
joints:
  slide: {slider: [plank, floor]}
  HOLD
  roll: {rolls: [drum, deck], mu_s: 0.2, mu_k: 0.2}
at: [0, 0.2]
t_end: 1
find: [{event: sticks}]
"""


@pytest.mark.parametrize("held", [True, False])
def test_a_disk_spun_on_a_carried_deck_starts_slipping(held):
    """A disk (3 kg, R = 0.2) set down spinning at ω = −20 rad/s on a plank (2 kg) that a slider
    keeps level (its ω left out: the slider fixes it), μ = 0.2.  By hand, friction μ m g = 5.886 N
    drives the disk forward (a = μ g), turns it back (α = F R/Ī = 19.62 rad/s²) and, on a plank
    free on a smooth floor, pushes the plank back (−F/2); it sticks where the slip over the deck
    v_d − v_p + R ω = 0: at 4/5.886 s on a plank held still by a drive (as on the floor), at
    4/8.829 s on the free plank.  Before, the plank's ω left out made the rolling row place the
    rates: the disk was set rolling at t = 0, with no friction and no sticking."""
    rec = solve_one_text(SPUN_ON_DECK.replace("HOLD", "hold: {drive: plank.x1, value: 0}" if held else ""))
    r = rec["results"]
    assert not any("projected" in w for w in rec["warnings"]), rec["warnings"]
    t_stick = 4 / 5.886 if held else 4 / 8.829
    assert r["find"][0]["t"] == pytest.approx(t_stick, rel=1e-10)
    assert r["reaction"]["roll"]["F"][0] == pytest.approx(5.886, rel=1e-12)
    assert r["v"]["drum"][1][0] == pytest.approx(1.962 * 0.2, rel=1e-10)
    assert r["omega"]["drum"][1][2] == pytest.approx(-20 + 19.62 * 0.2, rel=1e-10)
