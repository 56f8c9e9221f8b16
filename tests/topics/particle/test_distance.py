"""``distance`` (∫|v| dt) of the ODE route against independent references.

The route integrates |v| by Gauss–Legendre on every step's interpolant, with the stops where
|v| nearly vanishes located inside the steps; these tests hold it to ``tolerances.ode(rtol)``
relative to the distance, whatever way it is computed:

* a projectile with linear drag (m v' = −c v + m g): v(t) = v∞ + (v0 − v∞) e^(−kt), k = c/m,
  v∞ = g/k downwards; the distance is that closed-form speed integrated by mpmath at 30 digits
  (split at the apex, where |v| is least);
* a spring oscillator from rest at x = A (x = A cos ωt): it passes through v = 0 at every half
  period, where |v| has a kink; the distance is 2A per half period, exactly
  (n half periods done: 2A n + A (1 − cos(ωt − nπ)));
* the same oscillator with a small transverse velocity u (|v|² = A²ω² sin²ωt + u² cos²ωt): |v|
  nearly vanishes without a kink; mpmath at 30 digits, split at each least speed.
"""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import solve_one_text
from tests.tolerances import ode

mp.mp.dps = 30

RTOLS = (1e-6, 1e-8, 1e-10)


def _distance(text: str) -> list[float]:
    rec = solve_one_text(text)
    return rec["results"]["distance"]


def _drag_arc(t):
    m, c, g = mp.mpf("0.5"), mp.mpf("0.1"), mp.mpf("9.81")
    k = c / m
    vinf = -g / k
    vx = lambda s: 20 * mp.exp(-k * s)                               # noqa: E731
    vz = lambda s: vinf + (20 - vinf) * mp.exp(-k * s)               # noqa: E731
    apex = mp.log((20 - vinf) / -vinf) / k
    pts = [0, apex, t] if t > apex else [0, t]
    return mp.quad(lambda s: mp.sqrt(vx(s) ** 2 + vz(s) ** 2), pts)


@pytest.mark.parametrize("rtol", RTOLS)
@pytest.mark.parametrize("method", ["auto", "RK45"])
def test_linear_drag_projectile_distance(rtol, method):
    times = [0.3, 1.0, 1.7, 2.0, 3.0, 4.5]
    got = _distance("type: particle\nm: 0.5\nv0: [20, 0, 20]\n"
                    "forces: [{kind: gravity}, {kind: drag, c: 0.1, power: 1}]\n"
                    f"t_end: 4.5\nat: {times}\naccuracy: {{rtol: {rtol}, method: {method}}}\n")
    for t, d in zip(times, got):
        assert d == pytest.approx(float(_drag_arc(mp.mpf(t))), rel=ode(rtol)), t


@pytest.mark.parametrize("rtol", RTOLS)
@pytest.mark.parametrize("vx", [4.0, 5.5, 6.0, 8.0])
def test_light_drag_long_steps_near_the_apex(rtol, vx):
    """Light drag (c/m = 0.001 /s): the motion is nearly a parabola, so DOP853 takes steps of a
    second or more, and at the apex the speed dips to vx — not below a quarter of its largest
    (no stop split) for vx ≥ 5.5, yet |v| = √(vx² + vz²) bends over ~vx/g s, far inside the
    step: each step's rule is checked for resolution (its Legendre tail) and halved until it
    is.  A single 10-point rule per step was off by 1.5e-5 at vx = 5.5, rtol 1e-8 (the route's
    estimate said 7e-8)."""
    times = [1.0, 2.5, 4.0]
    got = _distance(f"type: particle\nm: 1\nv0: [{vx}, 0, 20]\n"
                    "forces: [{kind: gravity}, {kind: drag, c: 0.001, power: 1}]\n"
                    f"t_end: 4\nat: {times}\naccuracy: {{rtol: {rtol}}}\n")
    k, g = mp.mpf("0.001"), mp.mpf("9.81")
    vinf = -g / k
    vxs = lambda s: vx * mp.exp(-k * s)                               # noqa: E731
    vz = lambda s: vinf + (20 - vinf) * mp.exp(-k * s)                 # noqa: E731
    apex = mp.log((20 - vinf) / -vinf) / k
    for t, d in zip(times, got):
        pts = [0, apex, t] if t > apex else [0, t]
        ref = mp.quad(lambda s: mp.sqrt(vxs(s) ** 2 + vz(s) ** 2), pts)
        assert d == pytest.approx(float(ref), rel=ode(rtol)), t


def _osc_arc(A, w, t):
    n = math.floor(w * t / math.pi)
    return 2 * A * n + A * (1 - math.cos(w * t - n * math.pi))


@pytest.mark.parametrize("rtol", RTOLS)
def test_spring_oscillator_through_rest_many_times(rtol):
    A, k, m = 0.3, 40.0, 0.9
    w = math.sqrt(k / m)
    times = [0.05 * j + 0.013 for j in range(0, 400, 7)]            # ~ 42 half periods
    got = _distance(f"type: particle\nm: {m}\nx0: [{A}, 0, 0]\nforces: [{{kind: spring, k: {k}}}]\n"
                    f"t_end: {times[-1]}\nat: {times}\naccuracy: {{rtol: {rtol}}}\n")
    for t, d in zip(times, got):
        assert d == pytest.approx(_osc_arc(A, w, t), rel=ode(rtol), abs=ode(rtol) * A), t


@pytest.mark.parametrize("rtol", RTOLS)
def test_oscillator_with_small_transverse_speed(rtol):
    A, k, m, u = 0.3, 40.0, 0.9, 1e-4
    times = [0.37, 1.0, 2.2, 3.9]
    got = _distance(f"type: particle\nm: {m}\nx0: [{A}, 0, 0]\nv0: [0, {u}, 0]\nforces: [{{kind: spring, k: {k}}}]\n"
                    f"t_end: 3.9\nat: {times}\naccuracy: {{rtol: {rtol}}}\n")
    W, AA, U = mp.sqrt(mp.mpf(k) / mp.mpf(m)), mp.mpf(A), mp.mpf(u)
    for t, d in zip(times, got):
        T = mp.mpf(t)
        pts = [0] + [j * mp.pi / W for j in range(1, int(T * W / mp.pi) + 1)] + [T]
        ref = mp.quad(lambda s: mp.sqrt((AA * W * mp.sin(W * s)) ** 2 + (U * mp.cos(W * s)) ** 2), pts)
        assert d == pytest.approx(float(ref), rel=ode(rtol)), t


def test_distance_same_with_and_without_find():
    """The run with ``find`` (every step's interpolant kept) reports the same distance."""
    base = ("type: particle\nm: 0.5\nv0: [20, 0, 20]\nforces: [{kind: gravity}, {kind: drag, c: 0.1, power: 1}]\n"
            "t_end: 3\nat: [1, 2, 3]\naccuracy: {rtol: 1e-8}\n")
    plain = _distance(base)
    with_find = _distance(base + "find: [{max: x.2}]\n")
    assert with_find == pytest.approx(plain, rel=1e-14)


def test_exact_orbit_distance_after_many_turns():
    """The exact Kepler route's distance over a million turns of an ellipse (μ = 1, a = 1, e = 0.5,
    from perigee): the speed repeats every period T = 2π, so d(kT + τ) = k · 4aE(e) + the arc from
    perigee to the eccentric anomaly E(τ), a ∫₀^E √(1 − e² cos²u) du (mpmath, 30 digits).  The
    answer takes the same time at any t (it once spent 24 s on 200,000 pieces of many turns each,
    which a Gauss–Legendre rule cannot follow); the tolerance is the rounding of kT (ε k) carried
    by the speed, and the route's own error estimate."""
    e, k = 0.5, 10 ** 6
    T = 2 * math.pi
    tau = math.pi / 2 - e                        # E(τ) = π/2 from perigee: τ = (E − e sin E)/n
    t = k * T + tau
    rec = solve_one_text(f"type: particle\nm: 1\ng: 1\nx0: [0.5, 0, 0]\nv0: [0, {math.sqrt(3.0)!r}, 0]\n"
                         f"forces: [{{kind: inverse-square, R0: 1}}]\nat: [0, {tau!r}, {t!r}]\n")
    d = rec["results"]["distance"]
    C = 4 * mp.ellipe(mp.mpf(e) ** 2)
    arc = mp.quad(lambda u: mp.sqrt(1 - mp.mpf(e) ** 2 * mp.cos(u) ** 2), [0, mp.pi / 2])
    want = k * C + arc
    assert rec["method"] == "exact"
    assert abs(d[1] - float(arc)) <= 1e-12 * float(arc)
    assert abs(d[2] - float(want)) <= max(64 * 2.2e-16 * k * float(C), rec["error_estimate"] * float(want))


def test_distance_at_many_times_against_the_closed_form_speed(monkeypatch):
    """3,000 requested times (their partial steps' nodes a chunk at a time: CHUNK made small so that
    many chunks are taken) against mpmath's integral of the closed-form speed at a sample of them."""
    from dyncli import motion_find

    rtol = 1e-10
    times = [4.5 * j / 2999 for j in range(3000)]
    doc = ("type: particle\nm: 0.5\nv0: [20, 0, 20]\nforces: [{kind: gravity}, {kind: drag, c: 0.1, power: 1}]\n"
           f"t_end: 4.5\nat: {times}\naccuracy: {{rtol: {rtol}}}\n")
    whole = _distance(doc)
    monkeypatch.setattr(motion_find, "CHUNK", 640)          # 64 pieces a chunk: 47 chunks
    got = _distance(doc)
    assert got == whole                                     # the same doubles, chunk by chunk
    assert got[0] == 0.0 and all(b >= a for a, b in zip(got, got[1:]))
    for j in list(range(0, 3000, 157)) + [2999]:
        assert got[j] == pytest.approx(float(_drag_arc(mp.mpf(times[j]))), rel=ode(rtol)), times[j]


@pytest.mark.parametrize("body", [
    "m: 0.5\nv0: [20, 0, 20]\nforces: [{kind: gravity}, {kind: drag, c: 0.1, power: 1}]\nt_end: 4.5\n",
    "m: 1.0\nx0: [2.5, 0, 0]\nforces: [{kind: spring, k: 104.0, L: 2}, {kind: friction, mu: 1, N: 0.26}]\nt_end: 5\n",
])
def test_distance_the_same_whichever_way_its_nodes_are_evaluated(monkeypatch, body):
    """The partial steps' nodes of a few times evaluated in one call with the steps' own, or apart,
    give the same doubles: every operation is node by node, each set of pieces summed on its own."""
    from dyncli import motion_find

    times = [0.0, 0.013, 0.4, 1.0, 1.0000001, 2.2, 3.9, 4.5] + [0.01 * j + 0.005 for j in range(100)]
    doc = f"type: particle\n{body}at: {sorted(times)}\n"
    together = _distance(doc)
    monkeypatch.setattr(motion_find, "EARLY", 0)
    assert _distance(doc) == together


def test_a_speed_no_halving_resolves_is_said_within_the_cpu_budget():
    """A transfer orbit of eccentricity 1 − 1.3e-15 (r1 = 6.7e22 m, r2 = 4.2e7 m: the pericentre
    passes in ~1e-22 of the period): its speed cannot be resolved in time; the odometer stops
    refining at half the solve's CPU budget and warns (it ran 20 s, fuzz seed 3100155), the
    distance over the period still 4aE(e) to 1e-4 (mpmath)."""
    text = ("type: particle\nparams: {mu: 9.81*6371000**2, r1: 6.678e+22, r2: 42164000, "
            "vp: sqrt(2*mu*r2/(r1*(r1 + r2))), period: 2*pi*sqrt(((r1 + r2)/2)**3/mu)}\n"
            "m: 1.0e+19\nx0: [r1, 0, 1.0e-16]\nv0: [0, vp, 0]\n"
            "forces: [{kind: inverse-square, center: [1.0e+16, 1.0e+16, 0], R0: 6371000}]\n"
            "at: [0, period/2, period]\n")
    rec = solve_one_text(text)
    assert any(w.startswith("distance:") for w in rec["warnings"])
    r1, r2 = 6.678e22, 42164000.0
    a, e = (r1 + r2) / 2, (r1 - r2) / (r1 + r2)
    assert rec["results"]["distance"][2] == pytest.approx(float(4 * a * mp.ellipe(e * e)), rel=1e-4)
