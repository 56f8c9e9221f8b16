"""The first impact of a point that turns with its body, decided from the exact form of its gap.

Over a phase of constant accelerations in which a rigid body turns at a constant rate (free
flight under gravity), a body point's height over a line is c0 + c1 τ + c2 τ² + P cos φ + Q sin φ,
φ = θ0 + ω τ (crossing.Sinusoid); its critical points come from the closed-form zeros of its
second derivative, its first impact from the monotone pieces (crossing.sinusoid_crossing).

References, never the code under test: the forms' roots and critical points by mpmath at 30
digits (a fine scan refined by findroot); the scenes' first impact as the root of the end's
height written by hand, y(t) = y0 − g t²/2 + (L/2) sin(ω t) (mpmath), and the search the route
used before (routes._turning_gaps disabled: the generic sign analysis of crossing.first_crossing).
"""

from __future__ import annotations

import math
import random

import mpmath as mp
import pytest

from tests.conftest import solve_one_text

G = 9.81
EPS = 2.0 ** -52


def _mp_form(t0, c0, c1, c2, P, Q, th0, w):
    def f(t):
        tau = t - t0
        ph = th0 + w * tau
        return c0 + c1 * tau + c2 * tau ** 2 + P * mp.cos(ph) + Q * mp.sin(ph)
    return f


def _mp_roots(f, a, b, n=4000):
    """The sign changes of f over [a, b] on a fine scan, each refined by findroot (30 digits)."""
    with mp.workdps(30):
        xs = [mp.mpf(a) + (mp.mpf(b) - mp.mpf(a)) * k / n for k in range(n + 1)]
        ys = [f(x) for x in xs]
        return [float(mp.findroot(f, (x0, x1), solver="anderson"))
                for x0, x1, y0, y1 in zip(xs, xs[1:], ys, ys[1:]) if y0 * y1 < 0]


FORMS = [
    (0.0, 1.0, 0.3, -4.905, 0.5, 0.0, 0.0, 7.0),
    (0.2, -0.1, 2.0, -1.0, 0.3, -0.2, 1.0, -11.0),
    (1.0, 0.05, -0.2, 0.5, 0.0, 0.4, -2.5, 25.0),
    (0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.3, 3.0),         # a pure sinusoid (no quadratic)
    (0.0, 0.2, -1.0, 0.0, 0.1, 0.0, 0.0, 0.0),        # not turning: a line
]


@pytest.mark.parametrize("form", FORMS)
def test_sinusoid_roots_and_critical_points_against_mpmath(form):
    from dyncli.topics.scene.crossing import Sinusoid

    f = Sinusoid(*form)
    a, b = form[0], form[0] + 2.0
    ref = _mp_form(*[mp.mpf(x) for x in form])
    for level in (0.0, 0.1, -0.3):
        got = f.roots(level, a, b)
        want = _mp_roots(lambda t: ref(t) - level, a, b)
        assert len(got) == len(want), (level, got, want)
        for x, y in zip(got, want):
            assert abs(x - y) <= 1e-13 * max(1.0, abs(y))
    # the monotone pieces: f' of one sign inside each (mpmath's f' at their midpoints and quarters)
    cuts = f.monotone(a, b)
    with mp.workdps(30):
        for u, w in zip(cuts[:-1], cuts[1:]):
            signs = {mp.sign(mp.diff(ref, mp.mpf(u) + (mp.mpf(w) - mp.mpf(u)) * k / 8)) for k in range(1, 8)}
            assert len(signs - {0}) <= 1, (u, w)
        crit = _mp_roots(lambda t: mp.diff(ref, t), a, b)
    for c in crit:                                   # every critical point is a cut
        assert min(abs(c - x) for x in cuts) <= 1e-12 * max(1.0, abs(c))


def test_random_forms_every_root_found():
    """Random forms (seeded): the roots of f in [a, b] are mpmath's, one for one."""
    from dyncli.topics.scene.crossing import Sinusoid

    rnd = random.Random(25)
    for _ in range(12):
        form = (rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-3, 3), rnd.uniform(-5, 5),
                rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-4, 4), rnd.uniform(-20, 20))
        f = Sinusoid(*form)
        a, b = form[0], form[0] + 1.5
        got = f.roots(0.0, a, b)
        want = _mp_roots(_mp_form(*[mp.mpf(x) for x in form]), a, b)
        assert len(got) == len(want), (form, got, want)
        assert all(abs(x - y) <= 1e-13 * max(1.0, abs(y)) for x, y in zip(got, want))


def test_the_crossing_answers_only_what_it_can_tell():
    """sinusoid_crossing on forms given exactly (g the same form): a clear miss is None, a clear
    crossing is the gap's own root (mpmath), a dip below the line beside its extent is no event,
    a graze of the band or a start below it is UNDECIDED."""
    import numpy as np

    from dyncli.topics.scene import crossing

    tol, e = 1e-12, 1e-15

    def on_arrays(G, S=None, length=None):
        def g(ts):
            out = []
            for t in np.atleast_1d(ts):
                gap = G(float(t))
                m = None if S is None else min(S(float(t)), length - S(float(t)))
                out.append(gap if m is None or m >= 0 else abs(gap) - m)
            return np.array(out)
        return g

    Sin = crossing.Sinusoid
    # a spinning end falling onto an endless line: the first root of 1 − 4.905 t² + 0.5 sin(7 t)
    G = Sin(0.0, 1.0, 0.0, -4.905, 0.0, 0.5, 0.0, 7.0)
    got = crossing.sinusoid_crossing(G, None, None, on_arrays(G), 0.0, 2.0, tol, e)
    want = _mp_roots(_mp_form(0, 1, 0, mp.mpf("-4.905"), 0, mp.mpf("0.5"), 0, 7), 0, 2)[0]
    assert abs(got - want) <= 4 * EPS * want
    # rising all along: no event
    G = Sin(0.0, 0.1, 3.0, 0.0, 0.0, 0.05, 0.0, 7.0)
    assert crossing.sinusoid_crossing(G, None, None, on_arrays(G), 0.0, 2.0, tol, e) is None
    # the end passes below the line beside a short ledge (x = 0.5 cos 3t leaves [0.2, 1.2] before
    # the end gets there): no event while it stays beside
    G = Sin(0.0, 1.0, 0.0, -4.905, 0.0, 0.5, 0.0, 3.0)
    S = Sin(0.0, -0.2, 0.0, 0.0, 0.5, 0.0, 0.0, 3.0)
    assert crossing.sinusoid_crossing(G, S, 1.0, on_arrays(G, S, 1.0), 0.0, 1.0, tol, e) is None
    # ... but with a ledge under the whole swing, the same fall strikes it
    S2 = Sin(0.0, 2.0, 0.0, 0.0, 0.5, 0.0, 0.0, 3.0)
    got = crossing.sinusoid_crossing(G, S2, 4.0, on_arrays(G, S2, 4.0), 0.0, 1.0, tol, e)
    want = _mp_roots(_mp_form(0, 1, 0, mp.mpf("-4.905"), 0, mp.mpf("0.5"), 0, 3), 0, 1)[0]
    assert abs(got - want) <= 4 * EPS * want
    # a graze of −tol (a parabola's vertex at −tol, within the error): too close to call
    for d in (0.0, 2e-16, -2e-16):
        G = Sin(0.0, 1.0 - tol + d, -2.0, 1.0, 0.0, 0.0, 0.0, 0.0)
        assert crossing.sinusoid_crossing(G, None, None, on_arrays(G), 0.0, 3.0, tol, e) == crossing.UNDECIDED
    # a start below the band
    G = Sin(0.0, -2 * tol, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert crossing.sinusoid_crossing(G, None, None, on_arrays(G), 0.0, 3.0, tol, e) == crossing.UNDECIDED
    # turns beyond the doubles' resolution of an angle, or without end: not listed (searched instead)
    assert Sin(0.0, 1.0, 0.0, -4.905, 0.5, 0.0, 0.0, 1e200).monotone(0.0, 1e-190) is None
    assert Sin(0.0, 1.0, 0.0, -4.905, 0.5, 0.0, 0.0, float("inf")).monotone(0.0, 1.0) is None
    assert Sin(0.0, 1.0, 0.0, -4.905, 0.5, 0.0, 0.0, 1e4).monotone(0.0, 10.0) is None     # > 4096 half-turns
    # a watched quantity that is not the form: refused, never trusted
    G = Sin(0.0, 1.0, 0.0, -4.905, 0.0, 0.5, 0.0, 7.0)
    assert crossing.sinusoid_crossing(G, None, None, lambda ts: on_arrays(G)(ts) + 1e-9, 0.0, 2.0, tol, e) \
        == crossing.UNDECIDED


SPIN = """
type: scene
params: {{m: 1, L: 1, w: {w}}}
surfaces:
  ledge: {{through: [0.2, 0], direction: [1, 0], length: 1}}
bodies:
  rod: {{shape: rod, mass: m, length: L, x: [0, 1], angle: 0, omega: w}}
joints:
  strike: {{stop: [rod.end2, ledge], e: 0.5}}
at: [0, 0.25]
t_end: {t_end}
"""


def _end_height(w):
    """y of end2 by hand: the centre falls from 1, the rod turns at w: 1 − g t²/2 + (L/2) sin w t."""
    return lambda t: 1 - mp.mpf("9.81") / 2 * t ** 2 + mp.sin(mp.mpf(w) * t) / 2


def test_a_spinning_rod_strikes_the_ledge_at_the_hand_root(monkeypatch):
    rec = solve_one_text(SPIN.format(w=1, t_end=0.6))
    ev = rec["results"]["events"]
    assert ev and ev[0]["joint"] == "strike"
    with mp.workdps(30):
        want = float(mp.findroot(_end_height(1), (mp.mpf("0.45"), mp.mpf("0.55")), solver="anderson"))
        assert 0.2 <= 0.5 * math.cos(want) <= 1.2          # over the ledge
    assert abs(ev[0]["t"] - want) <= 4 * EPS * want
    # the search the route used before agrees to Brent's tolerance
    from dyncli.topics.scene import routes

    monkeypatch.setattr(routes, "_turning_gaps", lambda s, p, at, state: {})
    old = solve_one_text(SPIN.format(w=1, t_end=0.6))["results"]["events"]
    assert abs(old[0]["t"] - ev[0]["t"]) <= 8 * EPS * want


def test_a_spinning_rod_end_passing_beside_the_ledge_strikes_nothing(monkeypatch):
    """At w = 3 the end reaches the ledge's level at t ≈ 0.55 s where x = 0.5 cos 3t < 0.2 (beside
    the ledge, mpmath): no event by t = 1 s, as the search the route used before finds."""
    with mp.workdps(30):
        t = mp.findroot(_end_height(3), (mp.mpf("0.5"), mp.mpf("0.6")), solver="anderson")
        assert 0.5 * mp.cos(3 * t) < 0.2
    rec = solve_one_text(SPIN.format(w=3, t_end=1))
    assert rec["results"]["events"] == []
    from dyncli.topics.scene import routes

    monkeypatch.setattr(routes, "_turning_gaps", lambda s, p, at, state: {})
    assert solve_one_text(SPIN.format(w=3, t_end=1))["results"]["events"] == []


RANDOM_ROD = """
type: scene
surfaces:
  ledge: {{through: [{x0!r}, {y0!r}], direction: [1, {slope!r}], length: {L!r}}}
bodies:
  rod: {{shape: rod, mass: 1, length: 1, x: [0, 1], angle: {th!r}, v: [{vx!r}, {vy!r}], omega: {w!r}}}
joints:
  strike: {{stop: [rod.end2, ledge], e: {e!r}}}
at: [0, 0.5]
t_end: 1.2
"""


def test_random_spinning_rods_strike_where_the_search_finds(monkeypatch):
    """Random rods thrown spinning at a random ledge (seeded): the events are the generic
    search's (routes._turning_gaps disabled), the same joints in the same order, the first at the
    same time to Brent's tolerance; later ones (a rod chattering on the ledge amplifies rounding
    from bounce to bounce) to 1e-9 of the time."""
    from tests.conftest import solve_text

    from dyncli.topics.scene import routes

    rnd = random.Random(2025)
    own = routes._turning_gaps
    for _ in range(8):
        P = dict(x0=rnd.uniform(-1, 0.5), y0=rnd.uniform(-1.5, 0.3), slope=rnd.uniform(-0.3, 0.3),
                 L=rnd.uniform(0.2, 2), th=rnd.uniform(-3, 3), vx=rnd.uniform(-2, 2), vy=rnd.uniform(-2, 3),
                 w=rnd.choice([0.0, rnd.uniform(-15, 15)]), e=rnd.choice([0.0, 0.5, 1.0]))
        text = RANDOM_ROD.format(**P)
        monkeypatch.setattr(routes, "_turning_gaps", own)
        new = solve_text(text)[0]
        monkeypatch.setattr(routes, "_turning_gaps", lambda s, p, at, state: {})
        old = solve_text(text)[0]
        assert (new.get("error") is None) == (old.get("error") is None), (P, new.get("error"), old.get("error"))
        if new.get("error"):
            continue
        a, b = new["results"]["events"], old["results"]["events"]
        assert [(e["joint"], e["what"]) for e in a] == [(e["joint"], e["what"]) for e in b], P
        for k, (x, y) in enumerate(zip(a, b)):
            assert abs(x["t"] - y["t"]) <= (8 * EPS if k == 0 else 1e-9) * max(1.0, y["t"]), (P, k)
