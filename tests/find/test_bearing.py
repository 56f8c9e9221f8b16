"""``find`` in ``bearing-forces``: arms closed by a motor on a free shaft (Fig. 36.4), against the
closed forms of (36.22) and (36.15a).

α = π/3 − (π/12) t, ω = ω0 (sin α0 / sin α)² (36.22): ω = 3 at α = π/4 (t = 1), 6 at α = π/6
(t = 2); ω and |F| grow to the end of the window (at_end).  The route is a closed form: times
to 1e-12 relative.  (A `when` search whose samples were all fetched already once asked for no
times at all — an internal error, exit 3.)
"""

from __future__ import annotations

import mpmath as mp
import pytest

from .refs import entry, solve

MPMATH_DPS = 30

ARMS = """
type: bearing-forces
params: {m: 1, L: 0.5}
masses:
  - {m: m, L: L, alpha: "-(pi/3 - pi/12*t)"}
  - {m: m, L: L, alpha: "pi/3 - pi/12*t"}
omega0: 2
at: [0, 1]
t_end: 3
find:
  - {when: {omega: 6}}
  - {when: {omega: 3}}
  - {max: omega}
  - {min: F.1}
  - {when: {omega: 100}}
"""


def test_arms_closed_on_a_free_shaft():
    r, warns = solve(ARMS)
    alpha = lambda t: mp.pi / 3 - mp.pi / 12 * t                      # noqa: E731
    omega = lambda t: 2 * (mp.sin(mp.pi / 3) / mp.sin(alpha(t))) ** 2  # noqa: E731
    for k, t in ((0, 2), (1, 1)):
        e = entry(r, k)
        assert e["t"] == pytest.approx(t, rel=1e-12)
        assert e["omega"] == pytest.approx(float(omega(t)), rel=1e-12)
    for k in (2, 3):
        e = entry(r, k)
        assert (e["t"], e["at_end"]) == (3.0, True)
    assert entry(r, 2)["omega"] == pytest.approx(float(omega(3)), rel=1e-12)
    F = -2 * 1 * mp.mpf("0.5") * (mp.pi / 12) ** 2 * mp.cos(alpha(3))  # (36.15a) with α̈ = 0
    assert entry(r, 3)["F"][1] == pytest.approx(float(F), rel=1e-12)
    assert r["find"][4]["reached"] is False and r["find"][4]["omega"] is None
    assert any("find.4" in w for w in warns)


def test_a_spin_that_stops_at_a_kink_reaches_zero():
    # ω = |t − 1| (a motor that brakes to rest and reverses): ω = 0 at t = 1 exactly, where ω has
    # a kink; the exact route's cut there lies ~1e-13 s off it. Before: {when: {omega: 0}} "not
    # reached" while {min: omega} answered ~0 at t = 1.
    r, _ = solve("""
type: bearing-forces
masses: [{m: 2, L: 0.5, alpha: pi/2}]
omega: "abs(t-1)"
at: [0.5]
t_end: 3
find: [{when: {omega: 0}}, {min: omega}, {when: {omega: 0.25}, occurrence: 2}]
""")
    for k, t in ((0, 1.0), (1, 1.0), (2, 1.25)):
        assert entry(r, k)["t"] == pytest.approx(t, abs=1e-14), k
