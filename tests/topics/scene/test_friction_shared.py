"""Rough contacts of one body on one line held together (docs/types/scene.md, "Points of one body
held on one line"): their sticking rows are one row, so only the sum of their friction is
determined.  dyncli holds the group with one row, tests it as a whole (|ΣF| ≤ Σ μ_s N), shows
each F in proportion to μ_s N, and lists `sticks` / `slips` on each contact.

References, independent of dyncli's code: the crate's statics and its sliding motion solved by
sympy in exact rationals from the body's own balance laws (16.7 for the centre, 32.15 moments
about it) with the forces at the corners as unknowns — not through dyncli's rows; the box sliding
to rest on a level floor by hand (a = −μ_k g, t = V/(μ_k g), d = V²/(2 μ_k g)).

Tolerances: exact routes (statics, the closed form of a constant-acceleration phase) 1e-12 of
the quantity's scale; the ODE route (a load growing in time) ODE_GLOBAL × rtol.
"""

from __future__ import annotations

import pytest
import sympy as sp

from tests.conftest import solve_one_text
from tests.tolerances import ODE_GLOBAL
from tests.topics.scene.common import gallery

G = sp.Rational(981, 100)
EXACT = 1e-12

CRATE = """
type: scene
params: {{m: {m}, w: {w}, h: {h}}}
surfaces:
  floor: {{through: [-5, 0], direction: [1, 0]}}
bodies:
  crate:
    shape: box
    mass: m
    size: [w, h]
    x: [0, "h/2"]
    points: {{BL: ["-w/2", "-h/2"], BR: ["w/2", "-h/2"], TL: ["-w/2", "h/2"]}}
joints:
  left: {{contact: [crate.BL, floor], mu_s: {mus_l}, mu_k: 0.4}}
  right: {{contact: [crate.BR, floor], mu_s: {mus_r}, mu_k: 0.4}}
forces:
  - {{force: crate.TL, F: ["{P}", 0]}}
{when}
"""


def _held_reference(m, w, h, P, mus_l, mus_r):
    """(N_L, N_R, F_L, F_R) of the crate at rest: its centre's balance (16.7), its moments about
    the centre (32.15: corner forces at (∓w/2, −h/2), the push at (−w/2, h/2)); ΣF fixed, the
    split in proportion to μ_s N."""
    NL, NR, S = sp.symbols("N_L N_R S")
    sol = sp.solve([sp.Eq(S + P, 0), sp.Eq(NL + NR - m * G, 0),
                    sp.Eq(-w / 2 * NL + w / 2 * NR + h / 2 * S - h / 2 * P, 0)],
                   [NL, NR, S], dict=True)[0]
    nl, nr, s = sol[NL], sol[NR], sol[S]
    lim = mus_l * nl + mus_r * nr
    return nl, nr, s * mus_l * nl / lim, s * mus_r * nr / lim


@pytest.mark.parametrize("P,mus", [(40, ("1/2", "1/2")), (25, ("3/10", "7/10")), (0, ("1/2", "1/2"))])
def test_a_crate_held_on_two_rough_corners_shares_its_friction_in_proportion_to_mu_s_n(P, mus):
    m, w, h = 20, sp.Rational(3, 5), 1
    mus_l, mus_r = (sp.Rational(x) for x in mus)
    rec = solve_one_text(CRATE.format(m=m, w=w, h=h, P=P, mus_l=float(mus_l), mus_r=float(mus_r), when="at: [0]"))
    r = rec["results"]
    nl, nr, fl, fr = _held_reference(m, w, h, P, mus_l, mus_r)
    scale = float(m * G)
    for got, want, what in ((r["reaction"]["left"]["N"][0], nl, "N_L"), (r["reaction"]["right"]["N"][0], nr, "N_R"),
                            (r["reaction"]["left"]["F"][0], fl, "F_L"), (r["reaction"]["right"]["F"][0], fr, "F_R")):
        assert abs(got - float(want)) <= EXACT * scale, (what, got, float(want))
    assert r["route"] == "statics" and r["dof"] == 1
    assert any("statically indeterminate" in w and "left, right" in w for w in rec["warnings"])
    assert abs(r["a"]["crate"][0][0]) <= EXACT


def test_a_growing_push_slides_the_crate_when_it_reaches_mu_s_m_g_on_both_corners():
    """P = c t on a low crate: the group slips when ΣF = P reaches μ_s m g (the sum of the
    limits, however N is shared); each contact on its own (|F| ≤ μ_s N with equal shares) would
    have let go earlier at the lighter corner."""
    m, w, h, c = 10, sp.Rational(3, 5), sp.Rational(1, 5), 20
    text = CRATE.format(m=m, w=w, h=h, P=f"{c}*t", mus_l=0.5, mus_r=0.5,
                        when="t_end: 3\nat: [0, 3]\nfind: [{event: slips}]\naccuracy: {rtol: 1.0e-10}")
    r = solve_one_text(text)["results"]
    t1 = sp.Rational(1, 2) * m * G / c
    tol = ODE_GLOBAL * 1e-10
    assert [(ev["joint"], ev["what"]) for ev in r["events"]] == [("left", "slips"), ("right", "slips")]
    assert abs(r["events"][0]["t"] - float(t1)) <= tol * float(t1)
    # sliding (16.7, 32.15): m a = c t − μ_k (N_L + N_R), N_L + N_R = m g, no turning
    t = sp.symbols("t")
    a = sp.Rational(c, m) * t - sp.Rational(2, 5) * G
    v3 = sp.integrate(a, (t, t1, 3))
    x3 = sp.integrate(sp.integrate(a, (t, t1, t)), (t, t1, 3))
    assert abs(r["v"]["crate"][1][0] - float(v3)) <= tol * float(v3)
    assert abs(r["x"]["crate"][1][0] - float(x3)) <= tol * float(v3)
    NL, NR = sp.symbols("N_L N_R")
    muk, P = sp.Rational(2, 5), 3 * c
    sol = sp.solve([NL + NR - m * G, -w / 2 * NL + w / 2 * NR + h / 2 * (-muk * (NL + NR)) - h / 2 * P], [NL, NR])
    assert abs(r["reaction"]["left"]["N"][1] - float(sol[NL])) <= tol * float(m * G)
    assert abs(r["reaction"]["right"]["F"][1] + float(muk * sol[NR])) <= tol * float(m * G)


BOX = """
type: scene
params: {m: 2}
surfaces:
  floor: {through: [-5, 0], direction: [1, 0]}
bodies:
  box: {shape: box, mass: m, size: [0.4, 0.2], x: [0, 0.1], v: [2, 0], points: {bl: [-0.2, -0.1], br: [0.2, -0.1]}}
joints:
  f1: {contact: [box.bl, floor], mu: 0.3}
  f2: {contact: [box.br, floor], mu: 0.3}
t_end: 2
at: [0, 2]
"""


def test_a_box_sliding_on_two_rough_feet_comes_to_rest_with_no_friction_left():
    # before: one foot stuck and the other kept sliding, its kinetic friction −μ N on a box at
    # rest (the forces on the box did not add up to its acceleration, 0)
    rec = solve_one_text(BOX)
    r = rec["results"]
    t_stop, d = 2 / (0.3 * 9.81), 4 / (2 * 0.3 * 9.81)
    assert [(ev["joint"], ev["what"]) for ev in r["events"]] == [("f1", "sticks"), ("f2", "sticks")]
    assert all(abs(ev["t"] - t_stop) <= EXACT * t_stop for ev in r["events"])
    assert abs(r["x"]["box"][1][0] - d) <= EXACT * d
    for j in ("f1", "f2"):
        assert abs(r["reaction"][j]["F"][1]) <= EXACT * 9.81 * 2
        assert abs(r["reaction"][j]["N"][1] - 9.81) <= EXACT * 9.81 * 2
    assert any("statically indeterminate" in w for w in rec["warnings"])


def test_the_gallery_crate_pushed_harder():
    """problems/scenes/crate-pushed-harder.yaml: its header's numbers, by the references above."""
    r = gallery("crate-pushed-harder.yaml")["results"]
    nl, nr, fl, fr = _held_reference(10, sp.Rational(3, 5), sp.Rational(1, 5), 40, sp.Rational(1, 2),
                                     sp.Rational(1, 2))
    assert abs(r["find"][0]["t"] - 2.4525) <= ODE_GLOBAL * 1e-10 * 2.4525
    assert abs(r["reaction"]["left"]["F"][1] - float(fl)) <= EXACT * 98.1
    assert abs(r["reaction"]["right"]["N"][1] - float(nr)) <= EXACT * 98.1

