"""A scene whose every phase has constant accelerations (the closed-form route's quadratics) has
its distance in closed form, piece by piece (dyncli.motion_find.uniform_path_length): checked
against mpmath's quadrature of |v| with the velocities written by hand — a ball thrown over a
floor (a parabola's arc), a block sent up a smooth incline that turns and slides back (the kink
at the turn), an Atwood machine, and a ball bouncing to rest then rolling on (a sum of parabola
arcs to the accumulation time of its bounces, then a straight line)."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import PROBLEMS, solve_text

G = 9.81


def arc(vx: float, vy: float, ay: float, tau: float) -> mp.mpf:
    """∫₀^τ |(vx, vy + ay s)| ds by mpmath, split where vy + ay s = 0."""
    with mp.workdps(30):
        f = lambda s: mp.sqrt(mp.mpf(vx) ** 2 + (mp.mpf(vy) + mp.mpf(ay) * s) ** 2)  # noqa: E731
        pts = [0, tau]
        if ay and 0 < -vy / ay < tau:
            pts = [0, -mp.mpf(vy) / ay, tau]
        return mp.quad(f, pts)


def solve(text: str) -> dict:
    rec = solve_text(text, "distance.yaml")[0]
    assert rec.get("error") is None, rec.get("error")
    return rec


def test_thrown_ball_parabola_arc():
    times = [0.2, 0.7, 1.1]
    rec = solve(f"""type: scene
bodies:
  ball: {{shape: point, mass: 0.2, x: [0, 0], v: [3, 6]}}
at: {times}
""")
    assert rec["results"]["route"] == "closed-form"
    for t, d in zip(times, rec["results"]["distance"]["ball"]):
        assert d == pytest.approx(float(arc(3, 6, -G, t)), rel=1e-14), t
    assert not rec["warnings"]


def test_block_up_a_smooth_incline_and_back():
    """Sent up at 4 m/s on a smooth 30° slope: it turns at v0/(g sin β) and slides back; the
    distance is v0 t − g sin β t²/2 before the turn, the turn's v0²/(2 g sin β) plus the fall's
    g sin β (t − t*)²/2 after it."""
    beta, v0 = math.radians(30), 4.0
    a = G * math.sin(beta)
    t_turn = v0 / a
    times = [0.3, t_turn, 1.2, 2.0]
    rec = solve(f"""type: scene
params: {{beta: "30*deg"}}
surfaces:
  slope: {{through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}}
bodies:
  B: {{shape: point, mass: 1, x: [0, 0], v: ["4*cos(beta)", "4*sin(beta)"]}}
joints:
  on: {{contact: [B, slope]}}
t_end: 2
at: {times}
""")
    for t, d in zip(times, rec["results"]["distance"]["B"]):
        ref = v0 * t - a * t * t / 2 if t <= t_turn else v0 * v0 / (2 * a) + a * (t - t_turn) ** 2 / 2
        assert d == pytest.approx(ref, rel=1e-13), t


def test_atwood_machine():
    text = (PROBLEMS / "scenes" / "atwood-massive-pulley.yaml").read_text()
    rec = solve(text)
    import yaml

    data = yaml.safe_load(text)
    P = data["params"]
    acc = (P["m1"] - P["m2"]) * G / (P["m1"] + P["m2"] + 0.5 * P["M"])
    for body in ("A", "B"):
        for t, d in zip(data["at"], rec["results"]["distance"][body]):
            assert d == pytest.approx(0.5 * abs(acc) * t * t, rel=1e-13, abs=1e-15), (body, t)
    assert rec["results"]["distance"]["pulley"] == [0.0] * len(data["at"])


def test_ball_bouncing_to_rest_then_moving_on():
    """h = 1, e = 0.8, horizontal speed 0.3 on a smooth floor: the flights are parabola arcs, the
    k-th after the first fall lasting 2 e^k √(2 g h)/g; the bounces accumulate at
    t∞ = t1 (1 + 2e/(1 − e)), after which the ball slides at 0.3 m/s."""
    h, e, u = 1.0, 0.8, 0.3
    text = (PROBLEMS / "scenes" / "bouncing-ball.yaml").read_text()
    times = [0.3, 1.0, 2.0, 5.0]
    lines = [ln for ln in text.splitlines() if not ln.startswith(("at:", "find:"))]
    rec = solve("\n".join(lines) + f"\nat: {times}\n")
    t1 = math.sqrt(2 * h / G)
    w1 = G * t1
    flights = [(0.0, 0.0, t1)] + [(e ** k * w1, -G, 2 * e ** k * w1 / G) for k in range(1, 400)]
    t_inf = t1 * (1 + 2 * e / (1 - e))

    def distance(t: float) -> float:
        total, start = mp.mpf(0), 0.0
        for vy, _ay, dur in flights:
            if t <= start + dur:
                return float(total + arc(u, vy if start else 0.0, -G, t - start))
            total += arc(u, vy if start else 0.0, -G, dur)
            start += dur
        return float(total + u * (t - t_inf))

    for t, d in zip(times, rec["results"]["distance"]["ball"]):
        assert d == pytest.approx(distance(t), rel=1e-11), t
