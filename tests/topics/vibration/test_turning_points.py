"""The turning points of a forced vibration decided exactly (issue #28), against mpmath.

The reference is the closed form written by hand here (free part plus the steady state, or the
secular term), evaluated with mpmath at 40 digits (so the near-resonance cancellation of the two
parts costs nothing), its rate's sign changes bracketed on a grid of 2e-3 s evaluated in
mpmath and refined by mpmath's root finder: no dyncli code.  The code's roots are Newton
steps to 4 ulp on a rate computed to its rounding, so a turning time is within a few ulp of
the rounding of v over its slope: 1e-12 of the window is ample and far below a missed pair.
"""

import functools
import math

import mpmath as mp
import pytest

from dyncli.topics.vibration import turns
from tests.conftest import solve_one_text

mp.mp.dps = 40


@functools.lru_cache(maxsize=None)
def _reference(wn, z, w0, wd0, F, Om, t_end, d=1, step=2e-3):
    """The roots of x^(d) (x = w here: a force on the mass) in (0, t_end), by mpmath."""
    wn, z, w0, wd0, F, Om = (mp.mpf(repr(float(v))) for v in (wn, z, w0, wd0, F, Om))
    P = F / (wn ** 2 - Om ** 2 + 2j * z * wn * Om)
    a0, b0 = w0 - P.imag, wd0 - (1j * Om * P).imag        # the free part's initial conditions
    ws = wn * mp.sqrt(1 - z * z)
    A, B = a0, (b0 + z * wn * a0) / ws

    lam = mp.mpc(-z * wn, ws)                        # the free part Re(C e^{λt}), C = A − iB
    C = A - 1j * B

    def f(t):                                         # x^(d) = Re(C λ^d e^{λt}) + Im(P (iΩ)^d e^{iΩt})
        return (C * lam ** d * mp.exp(lam * t)).real + (P * (1j * Om) ** d * mp.exp(1j * Om * t)).imag

    n = int(t_end / step)
    ts = [mp.mpf(t_end) * k / n for k in range(n + 1)]
    vs = [f(t) for t in ts]
    out = []
    for a, b, fa, fb in zip(ts, ts[1:], vs, vs[1:]):
        if fa * fb < 0:
            out.append(float(mp.findroot(f, (a, b), solver="anderson")))
    return out


CASES = {
    # a beat (ωₙ = 1, Ω = 1.1) whose amplitudes make a pair of turning points 9e-3 s apart
    # (an eighth of a period is 0.71 s: a grid of breaks holds both in one piece)
    "beat, near-double turning point": (1.0, 0.0, 5.761887207031251, -1.1 / (1 - 1.21), 1.0, 1.1, 70.0),
    "beat, pair 0.2 s apart": (1.0, 0.0, 5.74, -1.1 / (1 - 1.21), 1.0, 1.1, 70.0),
    "undamped, r = 1 + 1e-9": (1.0, 0.0, 0.3, 0.0, 1.0, 1.0 + 1e-9, 40.0),
    "undamped, r = 1 - 1e-9": (1.0, 0.0, 0.3, -0.2, 1.0, 1.0 - 1e-9, 40.0),
    "damped, r = 1 + 1e-9": (2.0, 0.01, 0.0, 0.0, 3.0, 2.0 * (1.0 + 1e-9), 30.0),
}


@pytest.mark.parametrize("case", sorted(CASES))
@pytest.mark.parametrize("on_arrays", [False, True])
def test_turning_points_match_mpmath(case, on_arrays):
    wn, z, w0, wd0, F, Om, t_end = CASES[case]
    mo = turns.Motion(wn, z, w0, wd0, F, Om)
    h = 2 * math.pi / max(wn, Om) / 8
    n = math.ceil(t_end / h)
    got, touches, capped = turns.roots(mo, [t_end * k / n for k in range(n + 1)], 1, on_arrays)
    want = _reference(wn, z, w0, wd0, F, Om, t_end)
    assert not capped and not touches
    assert len(got) == len(want), (got, want)
    assert max(abs(g - w) for g, w in zip(got, want)) <= 1e-12 * t_end


def test_extrema_of_the_rate_match_mpmath():
    """d = 2: the turning points of v (the roots of the acceleration), the beat's near-double."""
    wn, z, w0, wd0, F, Om, t_end = CASES["beat, near-double turning point"]
    mo = turns.Motion(wn, z, w0, wd0, F, Om)
    got, _, _ = turns.roots(mo, [t_end * k / 400 for k in range(401)], 2, True)
    want = _reference(wn, z, w0, wd0, F, Om, t_end, d=2)
    assert len(got) == len(want)
    assert max(abs(g - w) for g, w in zip(got, want)) <= 1e-12 * t_end


def test_tangency_is_reported_not_missed():
    """v = cos t − cos(2t)·... a level inflection: x = sin t − t (v = cos t − 1 ≤ 0, double roots
    at 2πk) has no turning point; the double roots are touches, not sign changes."""
    # w'' + w = 0 with a base-free force F sin(Ωt), Ω = 1: here built as the undamped resonance
    # x = (sin t − t cos t)/2 has v = t sin t / 2: simple roots at kπ; the level tangent at 0 only
    mo = turns.Motion(1.0, 0.0, 0.0, 0.0, 1.0, 1.0)
    got, _, _ = turns.roots(mo, [0.25 * k for k in range(81)], 1, False)
    assert [round(t / math.pi, 12) for t in got if t > 0] == [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]


@pytest.mark.parametrize("d", [1, 2])
@pytest.mark.parametrize("arrays", [False, True])
def test_a_mass_at_rest_with_nothing_forcing_it_has_no_turning_point(d, arrays):
    # a force of frequency 0 is F sin(0) = 0: w ≡ 0, so x⁽ᵈ⁾ ≡ 0 — no isolated root, and the
    # search ends at once (before, every cell was undecided and halved until the cell budget:
    # a hang found by tests/fuzz at force.omega = 0)
    mo = turns.Motion(20.0, 0.1, 0.0, 0.0, 5.0, 0.0)
    assert turns.roots(mo, [0.0, 0.5, 1.0, 3.0], d, arrays) == ([], [], False)


@pytest.mark.parametrize("window", [(9999.0, 10000.0), (1999.0, 2000.0)])
def test_a_window_late_in_a_long_forced_motion_is_searched_exactly(window):
    """Undamped forcing at resonance (m = 2, k = 200, F0 = 4 at ω = ωₙ = 10, from rest at L):
    x − L = 0.01 sin 10t − 0.1 t cos 10t, whose largest values in a window are at 10t = nπ, n odd
    (ẋ = t sin 10t), x = L + 0.1 t.  The motion to 1e4 s spans far more than the capped grid's
    20,000 eighths of a period; a max asked within a window of a few periods has its window's
    turning points found exactly (before: read on the coarse grid, 999.861 at the window's end
    where the max is 1000.4375 at 9999.3753); a `when` with no window keeps the capped grid and
    is named in the warning."""
    import math

    a, b = window
    rec = solve_one_text(f"""
type: vibration
m: 2
k: 200
L: 0.5
x0: 0.5
v0: 0
force: {{amplitude: 4, omega: 10}}
at: [1, {b}]
t_end: {b}
find:
  - {{max: x, within: [{a}, {b}]}}
  - {{when: {{x: 0.6}}}}
""")
    n = math.floor(10 * b / math.pi)
    n -= (n + 1) % 2                         # the last odd n with nπ/10 ≤ b
    t = n * math.pi / 10
    f = rec["results"]["find"][0]
    assert f["t"] == pytest.approx(t, rel=1e-13)
    assert f["x"] == pytest.approx(0.5 + 0.1 * t, rel=1e-9)
    assert any("find.1: no `within` window" in w for w in rec["warnings"])
