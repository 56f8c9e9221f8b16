"""Simultaneous impacts: several points striking at one instant, solved together
(docs/types/scene.md: impacts).

References by hand from the impulse–momentum balance of the rod (33.2, 33.7) with Newton's law
at each striking end (28.7): unknown impulses P_j ≥ 0 with v̄⁺ = −v + ΣP/m, Ī ω⁺ = Σ d_j P_j,
v̄⁺ + d_j ω⁺ = e v where P_j > 0, and a point whose impulse would pull struck with none (it
leaves: the complementarity of the impulse LCP).  Exact routes: tolerance 1e-12 of the scale.
"""

from __future__ import annotations

import mpmath as mp

from tests.conftest import solve_one_text
from tests.topics.scene.common import gallery

G = 9.81
EXACT = 1e-12


def near(got, want, scale, what, tol=EXACT):
    assert got is not None, f"{what}: null"
    assert abs(float(got) - float(want)) <= tol * abs(float(scale)), f"{what}: {got!r} vs {float(want)!r}"


ROD = """
type: scene
params: {{m: 2, L: 1, e: 0.5}}
surfaces:
  left: {{through: [{a}, 0], direction: [1, 0], length: 0.2}}
  right: {{through: [{b}, 0], direction: [1, 0], length: 0.2}}
bodies:
  rod: {{shape: rod, mass: m, length: L, x: [0, 0.5], angle: 0, points: {{p: [{d}, 0]}}}}
joints:
  a: {{stop: [rod.end1, left], e: e}}
  b: {{stop: [rod.p, right], e: e}}
at: [0, 0.4]
"""


def _rod(a, b, d):
    rec = solve_one_text(ROD.format(a=a, b=b, d=d))
    assert rec.get("error") is None, rec.get("error")
    return rec["results"]


def test_rod_flat_on_two_ledges_gallery():
    r = gallery("rod-on-two-ledges.yaml")["results"]
    m, e = 2, mp.mpf("0.5")
    t1, v = mp.sqrt(1 / mp.mpf(G)), mp.sqrt(mp.mpf(G))
    ev = [(x["t"], x["joint"], x["what"]) for x in r["events"]]
    assert ev[:2] == [(ev[0][0], "a", "impact"), (ev[0][0], "b", "impact")]
    near(ev[0][0], t1, t1, "t1")
    for k in (0, 1):
        im = r["impacts"][k]
        near(im["impulse"], m * (1 + e) * v / 2, m * v, f"impacts.{k}.impulse")
        near(im["v_n_after"], e * v, v, f"impacts.{k}.v_n_after")
    near(r["impacts"][0]["energy_loss"], (1 - e**2) * m * v**2 / 2, m * v**2, "energy loss")
    assert r["impacts"][1]["energy_loss"] == 0
    # it bounces flat: no turn at all, every later pair simultaneous too
    assert all(w == 0 for w in r["angle"]["rod"]) and all(o[2] == 0 for o in r["omega"]["rod"])
    imp = [(x["t"], x["joint"]) for x in r["events"] if x["what"] == "impact"]
    assert [j for _, j in imp] == ["a", "b"] * (len(imp) // 2)
    assert all(imp[2 * k][0] == imp[2 * k + 1][0] for k in range(len(imp) // 2))
    # both rest at the sum of the geometric series, each carrying m g / 2
    rests = [(x["t"], x["joint"]) for x in r["events"] if x["what"] == "rests"]
    assert [j for _, j in rests] == ["a", "b"]
    near(rests[0][0], t1 * (1 + e) / (1 - e), t1, "t_rest")
    near(r["reaction"]["a"]["N"][3], m * G / 2, m * G, "N.a at rest", 1e-9)
    near(r["reaction"]["b"]["N"][3], m * G / 2, m * G, "N.b at rest", 1e-9)
    assert all(im["energy_loss"] >= 0 for im in r["impacts"])


def test_two_ledges_unequal_arms():
    # end1 (d = −0.5) and the point p at d = +0.25: ω⁺ = 0 needs 0.5 P1 = 0.25 P2, so
    # P1 = m (1 + e) v / 3, P2 = 2 m (1 + e) v / 3, and both ends leave at e v
    r = _rod(-0.6, 0.15, 0.25)
    m, e, v = 2, mp.mpf("0.5"), mp.sqrt(mp.mpf(G))
    assert [(im["joint"]) for im in r["impacts"]] == ["a", "b"]
    near(r["impacts"][0]["impulse"], m * (1 + e) * v / 3, m * v, "P1")
    near(r["impacts"][1]["impulse"], 2 * m * (1 + e) * v / 3, m * v, "P2")
    near(r["impacts"][0]["energy_loss"], (1 - e**2) * m * v**2 / 2, m * v**2, "loss")
    t1 = mp.sqrt(1 / mp.mpf(G))
    near(r["v"]["rod"][1][1], e * v - G * (mp.mpf("0.4") - t1), v, "v after")
    near(r["omega"]["rod"][1][2], 0, 1, "omega after")


def test_a_striking_point_whose_impulse_would_pull_leaves():
    # end1 (d = −0.5) and p at d = −0.3, both on one side of the centre: held together, end1's
    # impulse would pull (−0.5 P1 − 0.3 P2 = 0 gives P1 = −0.6 P2), so only p strikes:
    # P = (1 + e) m v / (1 + m d²/Ī) = (1 + e) m v / 2.08, and end1 leaves its ledge upwards
    r = _rod(-0.6, -0.4, -0.3)
    m, e, v = 2, mp.mpf("0.5"), mp.sqrt(mp.mpf(G))
    assert [im["joint"] for im in r["impacts"]] == ["b"]
    P = (1 + e) * m * v / mp.mpf("2.08")
    near(r["impacts"][0]["impulse"], P, m * v, "P")
    w = -mp.mpf("0.3") * P / (m / mp.mpf(12))
    near(r["impacts"][0]["energy_loss"], m * v**2 / 2 - (m * (P / m - v) ** 2 + m / mp.mpf(12) * w**2) / 2,
         m * v**2, "loss")
    assert r["impacts"][0]["energy_loss"] > 0
    t1 = mp.sqrt(1 / mp.mpf(G))
    near(r["omega"]["rod"][1][2], w, abs(w), "omega after")
    near(r["v"]["rod"][1][1], -v + P / m - G * (mp.mpf("0.4") - t1), v, "v after")


ROUGH_LEDGES = """
type: scene
params: {{m: 2, L: 1, h: 0.5, e: 0.5, u: 0.5, mu: {mu}}}
surfaces:
  left: {{through: [-1.5, 0], direction: [1, 0], length: 1.2}}
  right: {{through: [0.3, 0], direction: [1, 0], length: 1.2}}
bodies:
  rod: {{shape: rod, mass: m, length: L, x: [0, h], angle: 0, v: [u, 0]}}
joints:
  a: {{stop: [rod.end1, left], e: e, mu: mu}}
  b: {{stop: [rod.end2, right], e: e, mu: mu}}
at: [0, 0.4]
t_end: 0.4
"""


def test_rod_flat_and_sliding_on_two_rough_ledges():
    """A rod (m = 2) falls flat from h = 0.5 with a sideways speed u = 0.5 onto two rough ledges,
    both ends at once.  By hand (33.2, 28.7, Coulomb's law for impulses): each normal impulse
    P = m (1 + e) v / 2, v = √(2 g h); holding the slip needs the total friction impulse −m u,
    within μ (2P) for μ = 0.3: the rod stops sliding, the loss ½ m u² + ½ m v² (1 − e²); the two
    ends' shares are not determined (one line of one rigid body: only the sum is), split by the
    least norm (−m u / 2 each) and said in `course`.  With μ = 0.05 holding needs more than μ (2P):
    both slide, −μ P each, u⁺ = u − 2 μ P / m.  (The rows of the two held points are dependent:
    before, the impact was refused, exit 1.)"""
    m, e, u = mp.mpf(2), mp.mpf("0.5"), mp.mpf("0.5")
    v = mp.sqrt(2 * mp.mpf(G) * mp.mpf("0.5"))
    P = m * (1 + e) * v / 2
    r = solve_one_text(ROUGH_LEDGES.format(mu=0.3))["results"]
    a, b = r["impacts"][:2]
    for hit in (a, b):
        near(hit["impulse"], P, P, "P")
        near(hit["impulse_F"], -m * u / 2, P, "F")
        assert "least norm" in hit["course"]
    near(a["energy_loss"] + b["energy_loss"], m * u ** 2 / 2 + m * v ** 2 * (1 - e ** 2) / 2, m * v ** 2, "loss")
    near(r["v"]["rod"][1][0], 0, v, "u after")
    r = solve_one_text(ROUGH_LEDGES.format(mu=0.05))["results"]
    for hit in r["impacts"][:2]:
        near(hit["impulse_F"], -mp.mpf("0.05") * P, P, "F sliding")
        assert "least norm" not in hit["course"]
    near(r["v"]["rod"][1][0], u - 2 * mp.mpf("0.05") * P / m, v, "u after sliding")
