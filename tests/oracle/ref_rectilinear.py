"""Oracle cases: rectilinear motion, cases 1–4 and the general ODE route, at the extremes:
times and lengths of 1e-8, a velocity that only grazes zero (a tangency: a bifurcation of the
roots of v(t)), the approach to a terminal velocity to 1 − 1e-9, a pendulum-like a(s) released
2e-9 below its separatrix, a critically damped motion at ω = 1e8 rad/s."""

from __future__ import annotations

import mpmath as mp

from tests.oracle.common import EPS, absolute, bisect, case, closed, estimated, ode, same, x


def _case1():
    a, v1, s1 = x(1e8), x(-1), x(1e-8)
    s = lambda t: s1 + v1 * t + a * t ** 2 / 2          # noqa: E731
    t3 = (-v1 + mp.sqrt(v1 ** 2 + 2 * a * (x(2e-8) - s1))) / a
    return [case("tiny times, huge a", "rectilinear", {
        "a": 1e8, "s1": 1e-8, "v1": -1, "find": [{"t": 1e-8}, {"v": 0}, {"s": 2e-8}]},
        [closed("find.0.s", s(x(1e-8)), scale=s1, cond=4, reason="s1 + v1 t + a t²/2 from terms of 1e-8"),
         closed("find.1.t", -v1 / a), closed("find.1.s", s(-v1 / a), scale=s1, cond=4),
         closed("find.2.t", t3, cond=4)],
        "a = 1e8 m/s², v1 = −1 m/s: it turns at t = 1e-8 s, 5e-9 m from the origin")]


def _case2():
    v1 = x(-1 + 1e-10)
    ts = mp.asin(-v1)                                   # v = v1 + sin t first reaches 0
    ss = v1 * ts + 1 - mp.cos(ts)
    # the root's condition: an error δv in v(t) moves t by δv / a(t*) (a = cos t* ≈ 1.4e-5)
    tol_t = 16 * EPS / mp.cos(ts)
    graze = case("v grazes zero", "rectilinear", {"a": "cos(t)", "v1": -1 + 1e-10, "t_max": 3, "find": [{"v": 0}]},
                 [absolute("find.0.t", ts, tol_t, "16 eps of v's scale over a(t*) = 1.4e-5 (the root's condition)"),
                  estimated("find.0.s", ss, abs(ss), floor=tol_t, reason="s at that time")],
                 "a = cos t from v1 = −1 + 1e-10: v rises to 1e-10 at t = π/2 and first reaches 0 1.4e-5 s before",
                 same_=[same("find.0.reached", True)])
    miss = case("v stays below zero", "rectilinear", {"a": "cos(t)", "v1": -1 - 1e-10, "t_max": 3, "find": [{"v": 0}]},
                [], "a = cos t from v1 = −1 − 1e-10: v peaks at −1e-10, never 0", same_=[same("find.0.reached", False)])
    # a(t) = (t − 1)² − 1e-6 dips below 0 for 2e-3 s: v has a maximum and a minimum 2e-3 apart, and
    # a target between them is crossed three times; the first crossing is the answer
    d = x(1e-6)
    v = lambda t: (t - 1) ** 3 / 3 + mp.mpf(1) / 3 - d * t         # noqa: E731
    lo, hi = 1 - mp.sqrt(d), 1 + mp.sqrt(d)
    V = x(float((v(lo) + v(hi)) / 2))
    tf = bisect(lambda t: v(t) - V, 0, lo)
    tol = 16 * EPS * abs(V) / ((tf - 1) ** 2 - d)
    dip = case("a target inside a narrow dip of v", "rectilinear", {
        "a": "(t-1)**2 - 1e-6", "v1": 0, "t_max": 10, "find": [{"v": float(V)}]},
        [estimated("find.0.t", tf, tf, floor=tol, reason="plus 16 eps of v over a(t*) = 2e-6 (the root's condition)")],
        "v rises to a maximum at 1 − 1e-3 s, falls 1.3e-9 until 1 + 1e-3 s and rises again: the target between "
        "the two is first reached before the dip", same_=[same("find.0.reached", True)])
    # a narrow pulse a = exp(−((t − 5.123)/1e-3)²) on [0, 10]: v jumps by 1e-3 √π within 4e-3 s
    c, w = x(5.123), x(1e-3)
    a = lambda t: mp.exp(-((t - c) / w) ** 2)                        # noqa: E731
    pts = [0, c - 8 * w, c, c + 8 * w, 10]
    v10, s10 = mp.quad(a, pts), mp.quad(lambda t: (10 - t) * a(t), pts)
    pulse = case("a narrow pulse of a, t query", "rectilinear", {
        "a": "exp(-((t-5.123)/1e-3)**2)", "v1": 0, "find": [{"t": 10}]},
        [estimated("find.0.v", v10, v10), estimated("find.0.s", s10, s10)],
        "a pulse 1e-3 s wide in 10 s: v(10) = 1e-3 √π, s(10) = v(10)(10 − 5.123) (one quadrature over [0, 10] saw "
        "none of it: v(10) was 1e-293)")
    vq = float(v10 / 2)
    tq = c                                                              # by symmetry v = v(∞)/2 at the pulse's centre
    pulse_v = case("a narrow pulse of a, v query", "rectilinear", {
        "a": "exp(-((t-5.123)/1e-3)**2)", "v1": 0, "t_max": 10, "find": [{"v": vq}]},
        [estimated("find.0.t", tq, tq, floor=16 * EPS * abs(vq) / a(tq) + 8 * EPS * tq)],
        "the same pulse: v reaches half its jump at the pulse's centre, t = 5.123 s",
        same_=[same("find.0.reached", True)])
    return [graze, miss, dip, pulse, pulse_v]


def _case3():
    g, k = x(9.81), x(0.1)
    vt = mp.sqrt(g / k)
    vq = x(float(vt * (1 - mp.mpf("1e-9"))))
    tq = vt / g * mp.atanh(vq / vt)
    s = lambda t: vt ** 2 / g * mp.log(mp.cosh(g * t / vt))      # noqa: E731
    v = lambda t: vt * mp.tanh(g * t / vt)                        # noqa: E731
    T = x(50)
    tsc, ssc = T, s(T)
    return [case("terminal velocity to 1e-9", "rectilinear", {
        "a": "9.81 - 0.1*v*abs(v)", "v1": 0, "t_max": 100, "find": [{"v": float(vq)}, {"t": 50}]},
        [estimated("find.0.t", tq, tsc, floor=8 * EPS * tsc / (1 - vq / vt),
                   reason="plus rounding of the target v over 1 − v/v_t = 1e-9"),
         estimated("find.0.s", s(tq), ssc, floor=8 * EPS * ssc / (1 - vq / vt)),
         estimated("find.1.s", s(T), ssc), estimated("find.1.v", v(T), vt)],
        "quadratic drag from rest: v reaches v_t (1 − 1e-9) at t = 11 s; v and s at 50 s"), _terminal_pair()]


def _terminal_pair():
    # a = (v − v*)(v − v* − 1e-6), v* = 3 + 1e-6: two roots 1e-6 apart; from rest v → v* as 1/t
    r1, r2 = x(3) + x(1e-6), x(3) + 2 * x(1e-6)
    d = r2 - r1
    # t(v) = ∫ dv/((v − r1)(v − r2)) = ln(|v − r2| r1 / (|v − r1| r2)) / d from v = 0
    tv = lambda v: mp.log((r2 - v) * r1 / ((r1 - v) * r2)) / d      # noqa: E731
    T = x(100)
    vT = bisect(lambda v: tv(v) - T, 0, r1 - mp.mpf("1e-30"))
    return case("two terminal velocities 1e-6 apart", "rectilinear", {
        "a": "(v - 3 - 1e-6)*(v - 3 - 2e-6)", "v1": 0, "find": [{"t": 100}, {"v": 3.5}]},
        [estimated("find.0.v", vT, r1)],
        "from rest v approaches v* = 3 + 1e-6 (the next root 1e-6 beyond): v = 3.5 is never reached "
        "(it was, at t = −1e7 s)", same_=[same("find.1.reached", False)])


def _case4():
    v1 = x(2 * (1 - 1e-9))
    k = v1 / 2
    m = k ** 2
    K = mp.ellipk(m)
    s = lambda t: 2 * mp.asin(k * mp.ellipfun("sn", t, m=m))      # noqa: E731
    T = x(5)
    return [case("a(s) released 1e-9 below its separatrix", "rectilinear", {
        "a": "-sin(s)", "v1": float(v1), "find": [{"v": 0}, {"t": 5}]},
        [estimated("find.0.t", K, K, reason="near the separatrix the rounding of v1² moves t by dK/dv1² ε v1² "
                                            "~ 3e-8: the estimate must say so"),
         estimated("find.0.s", 2 * mp.asin(k), mp.pi), estimated("find.1.s", s(T), mp.pi)],
        "a = −sin s from s = 0 at v1 = 2(1 − 1e-9): the turning point 1.3e-4 rad below π after K(m) = 11.4 s")]


def _general():
    wn, s1 = x(1e8), x(1e-8)
    s = lambda t: s1 * (1 + wn * t) * mp.exp(-wn * t)      # noqa: E731
    v = lambda t: -s1 * wn ** 2 * t * mp.exp(-wn * t)      # noqa: E731
    rtol = 1e-10
    vs = s1 * wn / mp.e
    return [case("critically damped at 1e8 rad/s", "rectilinear", {
        "a": "-1e16*s - 2e8*v", "s1": 1e-8, "v1": 0, "accuracy": {"rtol": rtol, "atol": 1e-30},
        "find": [{"t": 1e-8}, {"t": 5e-8}]},
        [ode("find.0.s", s(x(1e-8)), rtol, s1), ode("find.1.s", s(x(5e-8)), rtol, s1),
         ode("find.0.v", v(x(1e-8)), rtol, vs), ode("find.1.v", v(x(5e-8)), rtol, vs)],
        "s'' = −1e16 s − 2e8 s' (ζ = 1, ω = 1e8 rad/s) from 1e-8 m: times 1e-8 s")]


def cases():
    return _case1() + _case2() + _case3() + _case4() + _general()
