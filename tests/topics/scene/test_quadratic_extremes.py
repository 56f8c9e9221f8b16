"""The extremes of a closed-form motion of constant accelerations, decided from its formula
(dyncli.topics.scene.queries.quadratic_extremes): a coordinate q0 + v0 τ + a τ²/2 turns at
τ = −v0/a, a rate never.  References by hand (the apex of a parabola) and mpmath at 30 digits
(``mp.findroot`` on the hand-written flight of a bouncing ball); an exact route: 1e-12 relative.
"""

from __future__ import annotations

from types import SimpleNamespace

import mpmath as mp
import numpy as np

from dyncli.topics.scene.queries import quadratic_extremes
from tests.conftest import PROBLEMS, solve_path

mp.mp.dps = 30
G = 9.81
EXACT = 1e-12


def _piece(t_a, t_b, q0, v0, a, quad=True):
    q0, v0, a = (np.array(x, dtype=float) for x in (q0, v0, a))
    return SimpleNamespace(t_a=t_a, t_b=t_b, quad=(t_a, q0, v0, a) if quad else None)


COORDS = {"x.b.0": ("q", 0), "x.b.1": ("q", 1), "v.b.1": ("v", 1)}


def test_apex_of_each_parabola_and_none_outside_its_piece():
    # piece 1: thrown up at 4 m/s: apex at 4/g; piece 2 (from t = 1): falling, apex before it (not kept)
    traj = SimpleNamespace(pieces=[_piece(0.0, 1.0, [0, 0], [1, 4], [0, -G]),
                                   _piece(1.0, 2.0, [1, 0], [1, -3], [0, -G])])
    known = quadratic_extremes(traj, COORDS, 0.0, 2.0)
    assert known is not None
    (t,) = known("x.b.1")
    assert abs(t - 4 / G) <= EXACT * 1
    assert known("x.b.0") == []          # no acceleration along x: monotone
    assert known("v.b.1") == []          # a rate linear in t: no interior extreme
    assert known("E") is None            # not a coordinate: resolved by the general search


def test_another_piece_or_an_uncovered_span_defers_to_the_general_search():
    traj = SimpleNamespace(pieces=[_piece(0.0, 1.0, [0, 0], [1, 4], [0, -G]),
                                   _piece(1.0, 2.0, [1, 0], [1, -3], [0, -G], quad=False)])
    assert quadratic_extremes(traj, COORDS, 0.0, 2.0) is None
    traj = SimpleNamespace(pieces=[_piece(0.0, 1.0, [0, 0], [1, 4], [0, -G])])
    assert quadratic_extremes(traj, COORDS, 0.0, 2.0) is None


def test_bouncing_ball_third_crossing_of_half_height():
    # h = 1, e = 0.8: down through 0.5 (1st), the first bounce rises to 0.64 > 0.5: up (2nd),
    # down (3rd) — the crossing pair inside one flight, found through the flight's apex
    rec = solve_path(PROBLEMS / "scenes" / "bouncing-ball.yaml")[0]
    f = rec["results"]["find"][0]
    h, e = mp.mpf(1), mp.mpf("0.8")
    t1 = mp.sqrt(2 * h / G)
    v = e * G * t1
    tau = mp.findroot(lambda s: v * s - G * s**2 / 2 - mp.mpf("0.5"), v / G + 0.1)
    want = t1 + tau
    assert abs(float(want) - (float(t1) + float((v + mp.sqrt(v**2 - G)) / G))) < 1e-15   # by hand too
    assert f["reached"] and abs(f["t"] - float(want)) <= EXACT * float(want)
    assert not any("could not be followed" in w for w in rec.get("warnings", []))
