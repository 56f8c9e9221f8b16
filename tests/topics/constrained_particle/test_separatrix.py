"""Issue #28: the energy route decides its turning points exactly (critical points of V first,
then the barrier's top decides; never by sampling).  A bead released from rest on a fixed hoop
at 1e-1 … 1e-14 rad below the top: every case right against mpmath (30 digits, the pendulum's
closed form q = 2 asin(k sn(K − ω0 t | k²)), k = sin(q0/2), period 4K/ω0, with q0 the very
double given) or refused with a message (1e-13 and closer: the timing is not determined in
double precision; 1e-12 is answered with its estimate ~1e-3 and a warning).  Within 2 ulp of the
top the start is the equilibrium itself (at rest)."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import solve_one_text, solve_text

R, G = 0.5, 9.81
W0 = math.sqrt(G / R)
TIMES = [0.0, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0]


def hoop(q0, qd0=0.0, times=TIMES):
    return (f"type: constrained-particle\nparams: {{R: 0.5}}\nm: 0.1\ncurve: {{x1: 'R*sin(q)', x2: 0, "
            f"x3: '-R*cos(q)'}}\nq_range: [-pi, pi]\nq0: {q0!r}\nq_dot0: {qd0!r}\nforces: [{{kind: gravity}}]\n"
            f"at: {times}\n")


def reference(q0, t):
    """(q(t), period) of the pendulum from rest at q0, in mpmath at 30 digits."""
    with mp.workdps(30):
        k = mp.sin(mp.mpf(q0) / 2)
        K, w = mp.ellipk(k * k), mp.sqrt(mp.mpf(G) / mp.mpf(R))
        q = 2 * mp.asin(k * mp.ellipfun("sn", K - w * t, m=k * k))
        return float(q), float(4 * K / w)


@pytest.mark.parametrize("eps", [1e-1, 1e-2, 1.5e-3, 1e-3, 1e-4, 1e-5, 1e-6, 1e-8, 1e-10, 1e-12])
def test_released_near_the_top_is_an_oscillation(eps):
    q0 = math.pi - eps
    rec = solve_one_text(hoop(q0))
    assert rec["method"] == "quadrature"
    r, est = rec["results"], rec["error_estimate"]
    P = reference(q0, 0.0)[1]
    # the barrier is not passed; the turning point to a few ulp (Brent to 4 ε, the seam at ±fl(π))
    assert r["q_turn"] == pytest.approx([-q0, q0], abs=4 * math.ulp(math.pi))
    assert r["q"][0] == q0 and r["q_dot"][0] == 0.0                 # the input itself at t = 0
    # the period to the conditioning of a start eps below the top: ~ulp(q0)/eps (q0's own last digit)
    assert abs(r["period"] - P) <= max(1e-13, 1e-15 / eps) * P
    # positions: within the estimate, relative to |x| + |v| t (the estimate's scale)
    vmax = 2 * W0 * R
    for t, q, x in zip(TIMES, r["q"], r["x"]):
        qr = reference(q0, t)[0]
        err = math.hypot(x[0] - R * math.sin(qr), x[2] + R * math.cos(qr))
        assert err <= est * (R + vmax * max(TIMES)), (t, q, qr, err, est)
    assert bool(rec.get("warnings")) == (est > 1e-10)                # the default rtol not met: said


@pytest.mark.parametrize("eps", [1e-13, 1e-14])
def test_released_closer_to_the_top_is_refused_with_what_to_change(eps):
    msg = solve_text(hoop(math.pi - eps))[0]["error"]
    assert "barrier's top" in msg and "start further from the separatrix" in msg


def test_passing_just_over_the_top_is_a_revolution():
    # from the bottom with 1 + 1e-8 times the speed that just reaches the top: a revolution, period
    # 2 ∫ dq/q̇ over [0, π] = 4 K(1/k²)/(ω0 k) with k² = E/(2 m g R) > 1 (mpmath, 30 digits)
    f = 1 + 1e-8
    qd0 = 2 * W0 * f
    rec = solve_one_text(hoop(0.0, qd0, [0.0, 1.0]))
    with mp.workdps(30):
        k2 = (mp.mpf(qd0) / (2 * mp.sqrt(mp.mpf(G) / mp.mpf(R)))) ** 2
        P = float(2 * mp.ellipk(1 / k2) / (mp.sqrt(mp.mpf(G) / mp.mpf(R)) * mp.sqrt(k2)))
    r = rec["results"]
    assert rec["method"] == "quadrature" and r["q_turn"] == []
    # K at the top is 2e-8 of the kinetic energy, formed with rounding ~1e-14: ~1e-6 of the time there
    assert r["period"] == pytest.approx(P, rel=1e-6)
    assert r["q"][0] == 0.0 and r["q_dot"][0] == qd0


def test_released_from_rest_reports_the_input_at_t0():
    rec = solve_one_text(hoop(1.0, 0.0, [0.0, 0.5]))
    assert rec["results"]["q"][0] == 1.0 and rec["results"]["q_dot"][0] == 0.0


def test_the_turning_points_time_is_half_the_period_to_rounding():
    """A bead on a hoop (R = 0.5 m) spun at 6 rad/s about its vertical diameter, released at rest
    relative at q0 = 0.3 (below the off-axis equilibrium cos q* = g/(R ω²)): per unit m R²,
    q̇² = K(q) = ω² (sin²q − sin²q0) + 2 (g/R)(cos q − cos q0); it rises to q1 (K's other root,
    mpmath's findroot) at t = ∫_{q0}^{q1} dq/√K (mpmath's tanh-sinh at 30 digits).  `max: q` is at
    that time to the route's own estimate (before: 4.8e-9 relative off where the estimate said
    8.9e-14 — the rate's root read from √K's rounding near the turning point)."""
    rec = solve_one_text("""
type: constrained-particle
params: {R: 0.5}
m: 0.1
curve: {x1: "R*sin(q)", x2: 0, x3: "-R*cos(q)"}
q_range: [-pi, pi]
rotation: {axis: [0, 0, 1], omega: 6}
q0: 0.3
forces:
  - {kind: gravity}
t_end: 5
find:
  - {max: q}
""")
    with mp.workdps(30):
        w2, gR, q0 = mp.mpf(36), mp.mpf("9.81") / mp.mpf("0.5"), mp.mpf("0.3")

        def K(q):
            return w2 * (mp.sin(q) ** 2 - mp.sin(q0) ** 2) + 2 * gR * (mp.cos(q) - mp.cos(q0))

        q1 = mp.findroot(K, 1.7)
        t1 = mp.quad(lambda q: 1 / mp.sqrt(K(q)), [q0, q1])
    f = rec["results"]["find"][0]
    assert float(q1) > 1.0
    assert f["t"] == pytest.approx(float(t1), rel=max(10 * rec["error_estimate"], 1e-13))
    assert f["q"] == pytest.approx(float(q1), rel=1e-12)
