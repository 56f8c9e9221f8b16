"""``find`` in ``rectilinear``: the block dropped onto a spring, and the queries of cases 1–4 and
the general case against closed forms (mpmath).

Routes: case 1 is a closed form (times to 1e-12 relative: a root of it to full precision);
cases 2–4 are quadratures and the general case an ODE, each run at accuracy.rtol = 1e-10 and
held to ``tolerances.ode(rtol)`` = 100 rtol.  An extreme of a result with no reported rate
(``a``) is located by Brent's minimiser: its time to √eps of the piece, its value to rounding.
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import error_of
from tests.tolerances import ode

from .refs import Vib, crossings, entry, length, solve

MPMATH_DPS = 30
RTOL = 1e-10
TOL = ode(RTOL)
EXACT = 1e-12

M, K, H, G = 2, 800, mp.mpf("0.5"), mp.mpf("9.81")

BLOCK = """
type: rectilinear
title: a block dropped from h onto a spring (s down from the release; contact at s = h)
params: {m: 2, k: 800, h: 0.5}
a: "g - k/m*max(s - h, 0)"
accuracy: {rtol: 1e-10}
find:
  - {v: 0}
  - {max: s}
  - {when: {s: h}, direction: down}
  - {when: {v: 0}, occurrence: 2}
  - {min: v}
  - {max: a}
  - {min: a}
  - {s: 0.6}
  - {when: {distance: 1.0}}
  - {t: 1}
"""


class Block:
    """Free fall through h, then x = compression = d + A sin(ωτ − φ) on the spring (d = mg/k)."""

    def __init__(self):
        self.tc, self.vc = mp.sqrt(2 * H / G), mp.sqrt(2 * G * H)
        self.w, self.d = mp.sqrt(mp.mpf(K) / M), M * G / K
        self.A = mp.sqrt(self.d**2 + (self.vc / self.w) ** 2)
        self.phi = mp.atan2(self.d, self.vc / self.w)
        self.delta = (M * G + mp.sqrt((M * G) ** 2 + 2 * K * M * G * H)) / K    # the notes' energy balance

    def tau(self, angle):                            # the time on the spring where ωτ − φ = angle
        return (angle + self.phi) / self.w


def test_block_on_spring_max_compression():
    r, warns = solve(BLOCK)
    b = Block()
    assert b.d + b.A == pytest.approx(b.delta, rel=1e-25)
    t_bottom = b.tc + b.tau(mp.pi / 2)
    for k in (0, 1):                                 # {v: 0} from rest: the turning point, not the release
        e = entry(r, k)
        assert e["t"] == pytest.approx(float(t_bottom), rel=TOL)
        assert e["s"] - 0.5 == pytest.approx(float(b.delta), rel=TOL)
        assert e["distance"] == pytest.approx(float(H + b.delta), rel=TOL)
    assert entry(r, 1)["at_end"] is False
    e = entry(r, 2)                                  # leaves the spring
    assert e["t"] == pytest.approx(float(b.tc + b.tau(mp.pi + b.phi)), rel=TOL)
    assert e["v"] == pytest.approx(float(-b.vc), rel=TOL)
    assert e["distance"] == pytest.approx(float(H + 2 * b.delta), rel=TOL)
    e = entry(r, 3)                                  # back at the release point: one period
    assert e["t"] == pytest.approx(float(2 * t_bottom), rel=TOL)
    assert e["s"] == pytest.approx(0, abs=TOL)
    e = entry(r, 4)                                  # fastest on the way up: at the static deflection
    assert e["t"] == pytest.approx(float(b.tc + b.tau(mp.pi)), rel=TOL)
    assert e["v"] == pytest.approx(float(-b.A * b.w), rel=TOL)
    e = entry(r, 5)                                  # a = g all through the fall: the first of equal maxima
    assert (e["t"], e["at_end"], e["a"]) == (0.0, True, 9.81)
    e = entry(r, 6)                                  # no rate of a: Brent's minimiser
    assert e["t"] == pytest.approx(float(t_bottom), rel=1e-7)
    assert e["a"] == pytest.approx(float(G - K / M * b.delta), rel=TOL)
    tau = mp.findroot(lambda x: b.d + b.A * mp.sin(b.w * x - b.phi) - mp.mpf("0.1"), (0, b.tau(mp.pi / 2)),
                      solver="anderson")
    assert entry(r, 7)["t"] == pytest.approx(float(b.tc + tau), rel=TOL)
    up = mp.findroot(lambda x: b.vc * x - G * x**2 / 2 - (1 - H - 2 * b.delta), (0, b.vc / G), solver="anderson")
    e = entry(r, 8)                                  # distance 1: in free flight above the spring
    assert e["t"] == pytest.approx(float(b.tc + b.tau(mp.pi + b.phi) + up), rel=TOL)
    assert e["distance"] == pytest.approx(1.0, rel=TOL)
    e = entry(r, 9)                                  # second drop: h + 2δ + h + (fall to s(1))
    assert e["distance"] == pytest.approx(float(2 * (H + b.delta) + e["s"]), rel=TOL)
    assert warns == []


def test_case1_projectile():
    r, warns = solve("""
type: rectilinear
a: -9.81
v1: 10
find:
  - {when: {s: 0}}
  - {max: s}
  - {v: 10}
  - {when: {v: -10}}
  - {min: s, within: [0, 3]}
  - {s: 0}
  - {when: {s: 2}, direction: down}
  - {when: {s: 2}, occurrence: 2}
""")
    v, g = mp.mpf(10), G
    land, apex = 2 * v / g, v / g
    for k in (0, 3, 5):                              # s = 0 and v = 10 held at the start: the landing
        assert entry(r, k)["t"] == pytest.approx(float(land), rel=EXACT)
        assert entry(r, k)["distance"] == pytest.approx(float(v**2 / g), rel=EXACT)
    e = entry(r, 1)
    assert (e["t"], e["s"], e["at_end"]) == (pytest.approx(float(apex), rel=EXACT),
                                             pytest.approx(float(v**2 / (2 * g)), rel=EXACT), False)
    assert r["find"][2]["reached"] is False and r["find"][2]["s"] is None
    assert any(w.startswith("find[2]") and "not reached" in w for w in warns)
    e = entry(r, 4)
    assert (e["t"], e["at_end"]) == (3.0, True)
    assert e["distance"] == pytest.approx(float(v**2 / (2 * g) + g * (3 - apex) ** 2 / 2), rel=EXACT)
    down = (v + mp.sqrt(v**2 - 4 * g)) / g          # s = 2 on the way down: the larger root of v t − g t²/2 = 2
    assert entry(r, 6)["t"] == pytest.approx(float(down), rel=EXACT)
    assert entry(r, 7)["t"] == pytest.approx(float(down), rel=EXACT)


def test_case2_time_dependent():
    r, _ = solve("""
type: rectilinear
a: "cos(t)"
accuracy: {rtol: 1e-10}
find:
  - {v: 0}
  - {max: s}
  - {min: v}
  - {when: {s: 1}, occurrence: 2}
  - {when: {s: 1}, occurrence: 3}
  - {t: 7}
  - {max: s, within: [8, 10]}
  - {when: {s: 1}, occurrence: 4}
""")                                                 # v = sin t, s = 1 − cos t
    pi = mp.pi
    for k, t in ((0, pi), (1, pi), (2, 3 * pi / 2), (3, 3 * pi / 2)):
        assert entry(r, k)["t"] == pytest.approx(float(t), rel=TOL)
    assert entry(r, 1)["s"] == pytest.approx(2, rel=TOL)
    assert entry(r, 2)["v"] == pytest.approx(-1, rel=TOL)
    assert entry(r, 4)["t"] == pytest.approx(float(5 * pi / 2), rel=TOL)     # the window [8, 10] extends the motion
    assert r["find"][7]["reached"] is False          # 7π/2 lies beyond the window's end
    assert entry(r, 5)["distance"] == pytest.approx(float(4 + 1 - mp.cos(7)), rel=TOL)
    e = entry(r, 6)                                  # a window past t = 7: the motion is extended to 10
    assert (e["t"], e["at_end"]) == (pytest.approx(float(3 * pi), rel=TOL), False)


def test_case3_linear_drag_throw():
    r, _ = solve("""
type: rectilinear
a: "-0.5*v - 9.81"
v1: 20
accuracy: {rtol: 1e-10}
find:
  - {max: s}
  - {when: {s: 0}}
  - {v: 0}
  - {t: 5}
""")
    c, v1 = mp.mpf("0.5"), mp.mpf(20)
    s = lambda t: (v1 + G / c) * (1 - mp.exp(-c * t)) / c - G * t / c      # noqa: E731
    apex = mp.log((G + c * v1) / G) / c
    land = mp.findroot(s, (apex, 10), solver="anderson")
    for k, t in ((0, apex), (2, apex)):
        assert entry(r, k)["t"] == pytest.approx(float(t), rel=TOL)
        assert entry(r, k)["s"] == pytest.approx(float(s(apex)), rel=TOL)
    assert entry(r, 1)["t"] == pytest.approx(float(land), rel=TOL)
    assert entry(r, 1)["distance"] == pytest.approx(float(2 * s(apex)), rel=TOL)
    assert entry(r, 3)["distance"] == pytest.approx(float(2 * s(apex) - s(5)), rel=TOL)


def test_general_damped_oscillator():
    r, _ = solve("""
type: rectilinear
a: "-4*s - 0.4*v"
s1: 0.5
accuracy: {rtol: 1e-10}
find:
  - {v: 0}
  - {when: {s: 0}, occurrence: 2}
  - {min: s}
  - {max: v, within: [1, 3]}
  - {t: 6}
""")
    ref = Vib(1, 4, 0.1, "0.5", 0)                   # s'' + 0.4 s' + 4 s = 0
    turns = crossings(ref.v, "1e-9", 7)
    assert entry(r, 0)["t"] == pytest.approx(float(turns[0]), rel=TOL)
    assert entry(r, 1)["t"] == pytest.approx(float(crossings(ref.y, 0, 7)[1]), rel=TOL)
    assert entry(r, 2)["t"] == pytest.approx(float(turns[0]), rel=TOL)
    assert entry(r, 2)["s"] == pytest.approx(float(ref.y(turns[0])), rel=TOL)
    tv, = crossings(lambda t: mp.diff(ref.y, t, 2), 1, 3)
    assert entry(r, 3)["t"] == pytest.approx(float(tv), rel=TOL)
    assert entry(r, 4)["distance"] == pytest.approx(float(length(ref.y, turns, 0, 6)), rel=TOL)



def test_general_distance_backward_in_time_with_a_search():
    """A search of ``find`` and an answer before t1 in the general case: the motion before t1 is
    integrated backward (it was the first forward step's interpolant extrapolated: the distance
    to t = −3 read 0.395 where the body travels 2.766, with exit 0)."""
    r, _ = solve("""
type: rectilinear
a: "-4*s - 0.4*v"
s1: 0.5
accuracy: {rtol: 1e-10}
find:
  - {when: {s: 0}}
  - {t: -3}
""")
    ref = Vib(1, 4, 0.1, "0.5", 0)                   # s'' + 0.4 s' + 4 s = 0, backward too
    assert entry(r, 0)["t"] == pytest.approx(float(crossings(ref.y, 0, 2)[0]), rel=TOL)
    e = entry(r, 1)
    assert e["s"] == pytest.approx(float(ref.y(-3)), rel=TOL)
    assert e["distance"] == pytest.approx(float(length(ref.y, crossings(ref.v, -3, "-1e-9"), -3, 0)), rel=TOL)

def test_invalid_generic_query_names_the_users_index():
    msg = error_of("type: rectilinear\na: -1\nfind:\n  - {t: 1}\n  - {v: -1}\n  - {when: {xx: 1}}\n")
    assert " find.2.when:" in msg and "'xx'" in msg, msg
    msg = error_of("type: rectilinear\na: -1\nfind:\n  - {t: 1}\n  - {max: s, within: [3, 1]}\n")
    assert " find.1.within:" in msg and "reversed" in msg, msg


def test_gallery_block_on_spring_with_the_default_t_max():
    """The gallery's block asks only `when`-type queries and no time: the search runs to
    t1 + t_max = 1000 s (about 1230 periods) and must stop at each answer."""
    from tests.conftest import PROBLEMS, solve_path

    rec, = solve_path(PROBLEMS / "rectilinear" / "block-on-spring.yaml")
    assert rec.get("error") is None, rec.get("error")
    b = Block()
    f = rec["results"]["find"]
    assert f[0]["t"] == pytest.approx(float(b.tc + b.tau(mp.pi / 2)), rel=1e-6)      # default rtol 1e-6
    assert f[0]["s"] - 0.5 == pytest.approx(float(b.delta), rel=1e-6)
    assert f[1]["t"] == pytest.approx(float(b.tc + b.tau(mp.pi + b.phi)), rel=1e-6)
    assert f[1]["distance"] == pytest.approx(float(H + 2 * b.delta), rel=1e-6)
    assert f[2]["t"] == pytest.approx(float(2 * (b.tc + b.tau(mp.pi / 2))), rel=1e-6)


class Excursions:
    """s = c t + B sin ωt (B = −A/ω) solves a = −ω²(s − c t) from s1 = 0, v1 = c − A: with A just
    above c, v = c − A cos ωt is negative only in narrow windows of half-width h = acos(c/A)/ω
    around t_k = 2πk/ω, where s makes a narrow excursion back (issue 28)."""

    c, w, A = mp.mpf(1), mp.mpf(40), mp.mpf("1.002")

    def __init__(self):
        self.B, self.h = -self.A / self.w, mp.acos(self.c / self.A) / self.w

    def s(self, t):
        return self.c * t + self.B * mp.sin(self.w * t)

    def v(self, t):
        return self.c - self.A * mp.cos(self.w * t)

    def window(self, k):
        tk = 2 * mp.pi * k / self.w
        return tk - self.h, tk + self.h                  # the local maximum and minimum of s

    def distance(self, a, b):
        """∫|v| dt over [a, b]: Σ|Δs| between the zeros of v (the ends of the windows)."""
        ks = range(int(mp.floor(a * self.w / (2 * mp.pi))) - 1, int(mp.ceil(b * self.w / (2 * mp.pi))) + 2)
        knots = [a] + sorted(z for k in ks for z in self.window(k) if a < z < b) + [b]
        return sum(abs(self.s(y) - self.s(x)) for x, y in zip(knots, knots[1:]))


@pytest.mark.parametrize("backward", [True, False])
def test_general_narrow_excursions_are_never_missed(backward):
    """A crossing between two samples cannot be missed (issue 28): the general route's searches
    and its own {s: S} queries run on its steps, cut at the exact extremes of s and v inside
    each step's interpolant.
    Every excursion here (v < 0 for 3.2e-3 s, s back by 7e-6 m) is narrower than 1/256 (and
    1/1024) of the 10 s searched, and each level is crossed down and up again inside it: with a
    query before t1 the searches ran on a uniform grid of 256 pieces and answered all four
    down-crossings "not reached"; without one the turning points were roots of v between step
    ends only, so every distance was off by 1e-5 to 6e-5 relative and the time of a distance
    1.2e-4 s late; and an {s: S} crossed up and down inside one step was answered at a later
    window (22 of 177 levels, 5e-3 s late).  References: the closed form (mpmath, 30 digits)."""
    mp.mp.dps = MPMATH_DPS
    x = Excursions()
    levels = []
    for k in (3, 11, 19, 27):                       # a level just below the k-th local maximum of s
        tM, tm = x.window(k)
        X = x.s(tM) - (x.s(tM) - x.s(tm)) / 10
        levels.append((X, mp.findroot(lambda t: x.s(t) - X, (tM, tm), solver="anderson")))
    firsts = []
    for k, frac in ((4, 10), (23, 2)):              # {s: S}: first crossed on the way up to a maximum
        tM, tm = x.window(k)
        S = x.s(tM) - (x.s(tM) - x.s(tm)) / frac
        firsts.append((S, mp.findroot(lambda t: x.s(t) - S, (tM - x.h, tM), solver="anderson")))
    t5 = mp.mpf(5)
    D5 = x.distance(0, t5)
    queries = "".join(f"  - {{when: {{s: {mp.nstr(X, 20)}}}, direction: down}}\n" for X, _ in levels)
    queries += ("  - {when: {v: 0}, direction: down, occurrence: 20}\n"
                f"  - {{when: {{distance: {mp.nstr(D5, 20)}}}}}\n")
    queries += "".join(f"  - {{s: {mp.nstr(S, 20)}}}\n" for S, _ in firsts) + "  - {t: 10}\n"
    queries += "  - {t: -0.5}\n" if backward else ""
    r, warns = solve(f"""
type: rectilinear
params: {{w: 40, c: 1}}
a: "-w**2*(s - c*t)"
v1: -0.002
t_max: 10
accuracy: {{rtol: {RTOL}}}
find:
{queries}""")
    assert not warns, warns
    for k, (X, down) in enumerate(levels):
        e = entry(r, k)
        # the first down-crossing (inside its window), its time to the error of s over |v| there
        assert abs(e["t"] - float(down)) <= TOL * float(abs(X)) / float(abs(x.v(down))), (k, e["t"], down)
        assert e["distance"] == pytest.approx(float(x.distance(0, down)), rel=TOL)
    e = entry(r, 4)
    t20 = 2 * mp.pi * 20 / x.w - x.h
    assert e["t"] == pytest.approx(float(t20), rel=TOL)
    assert e["distance"] == pytest.approx(float(x.distance(0, t20)), rel=TOL)
    assert entry(r, 5)["t"] == pytest.approx(5.0, rel=TOL)          # the distance travelled by t = 5
    for k, (S, up) in enumerate(firsts):
        e = entry(r, 6 + k)
        assert abs(e["t"] - float(up)) <= TOL * float(abs(S)) / float(abs(x.v(up))), (k, e["t"], up)
        assert e["distance"] == pytest.approx(float(x.distance(0, up)), rel=TOL)
    assert entry(r, 8)["distance"] == pytest.approx(float(x.distance(0, 10)), rel=TOL)
    if backward:
        e = entry(r, 9)
        assert e["s"] == pytest.approx(float(x.s(mp.mpf("-0.5"))), rel=TOL)
        assert e["distance"] == pytest.approx(float(x.distance(mp.mpf("-0.5"), 0)), rel=TOL)
