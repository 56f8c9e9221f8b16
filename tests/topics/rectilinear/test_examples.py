"""Every example in problems/rectilinear checked against independent references:
closed forms re-derived here (evaluated with mpmath at 30 digits) or mpmath's
Taylor-series ODE solver / findroot — never the solver's own output."""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import PROBLEMS, solve_path

MPMATH_DPS = 30
mp.mp.dps = 30
RTOL = 1e-10          # the default accuracy.rtol every answer must meet
DIR = PROBLEMS / "rectilinear"


def close(x, ref, scale=1.0, rtol=RTOL):
    ref = float(ref)
    assert x is not None
    assert abs(x - ref) <= rtol * max(abs(ref), scale), (x, ref, abs(x - ref))


def check(entry, t=None, s=None, v=None, scale=1.0, rtol=RTOL):
    assert entry["reached"] is True, entry
    for key, ref in (("t", t), ("s", s), ("v", v)):
        if ref is not None:
            close(entry[key], ref, scale, rtol)


def unreached(entry):
    assert {k: x for k, x in entry.items() if k != "at_end"} == {"t": None, "s": None, "v": None, "a": None,
                                                                 "reached": False, "distance": None}


def solve(name):
    recs = solve_path(DIR / name)
    assert len(recs) == 1
    rec = recs[0]
    assert rec.get("error") is None
    return rec


def test_case1_braking_car():
    rec = solve("case1-constant-acceleration.yaml")
    assert rec["results"]["case"] == 1 and rec["method"] == "closed-form"
    f = rec["results"]["find"]
    a, v1 = -4.0, 20.0
    check(f[0], t=2, s=v1 * 2 + a / 2 * 4, v=v1 + 2 * a)
    check(f[1], t=-v1 / a, s=-v1 ** 2 / (2 * a), v=0)     # stop: v = 0
    check(f[2], t=5, s=50, v=0)                          # s = 50 is the turning point itself
    assert rec["warnings"] == []


def test_case2_oscillating_push():
    rec = solve("case2-time-dependent.yaml")
    assert rec["results"]["case"] == 2 and rec["method"] == "quadrature+root"
    assert rec["equations"] == ["6.6a", "6.6b"]
    f = rec["results"]["find"]
    # a = 3 sin 2t, v1 = -1, s1 = 1/2: integrate by hand
    v = lambda t: mp.mpf(1) / 2 - mp.mpf(3) / 2 * mp.cos(2 * t)
    s = lambda t: mp.mpf(1) / 2 + t / 2 - mp.mpf(3) / 4 * mp.sin(2 * t)
    check(f[0], t=2, s=s(2), v=v(2))
    check(f[1], t=-1.5, s=s(mp.mpf(-1.5)), v=v(mp.mpf(-1.5)))
    check(f[2], t=mp.pi / 4, s=s(mp.pi / 4), v=0.5)
    check(f[3], t=mp.pi / 2, s=s(mp.pi / 2), v=2)      # grazing: the maximum of v
    t_s1 = mp.findroot(lambda t: s(t) - 1, 1.4)
    check(f[4], t=t_s1, s=1, v=v(t_s1))
    unreached(f[5])
    assert any("find[5]" in w and "[-1, 2]" in w for w in rec["warnings"])
    assert rec["error_estimate"] is not None and rec["error_estimate"] < 1e-10


def test_case3_linear_drag():
    rec = solve("case3-linear-drag.yaml")
    assert rec["results"]["case"] == 3
    f = rec["results"]["find"]
    c, v1 = mp.mpf("0.5"), 10
    v = lambda t: v1 * mp.exp(-c * t)
    s = lambda t: v1 / c * (1 - mp.exp(-c * t))
    check(f[0], t=2, s=s(2), v=v(2), scale=10)
    check(f[1], t=-1, s=s(-1), v=v(-1), scale=10)
    check(f[2], t=2 * mp.log(10), s=18, v=1, scale=10)
    check(f[3], t=2 * mp.log(20), s=19, v=0.5, scale=10)
    unreached(f[4])
    unreached(f[5])
    assert any("find[4]" in w and "approaches s = 20" in w for w in rec["warnings"])
    assert any("find[5]" in w and "terminal velocity v* = 0" in w for w in rec["warnings"])


def _drag_reference():
    g, k, v1 = mp.mpf("9.81"), mp.mpf("0.01"), mp.mpf(20)
    vt = mp.sqrt(g / k)
    th = mp.atan(v1 / vt)
    t_top = vt / g * th
    h = mp.log(1 + v1 ** 2 / vt ** 2) / (2 * k)

    def state(t):
        t = mp.mpf(t)
        if t <= t_top:        # rising: a = -g - k v^2  (also backwards in time)
            return vt ** 2 / g * mp.log(mp.cos(th - g * t / vt) / mp.cos(th)), vt * mp.tan(th - g * t / vt)
        x = g * (t - t_top) / vt   # falling: a = -g + k v^2
        return h - vt ** 2 / g * mp.log(mp.cosh(x)), -vt * mp.tanh(x)

    return vt, t_top, h, state


def test_case3_quadratic_drag_throw():
    rec = solve("case3-quadratic-drag-throw.yaml")
    assert rec["results"]["case"] == 3
    f = rec["results"]["find"]
    vt, t_top, h, state = _drag_reference()
    s1, v_1 = state(1)
    check(f[0], t=1, s=s1, v=v_1, scale=20)
    check(f[1], t=t_top, s=h, v=0, scale=20)
    t_low = mp.findroot(lambda t: state(t)[0] + 10, 4.3)
    check(f[2], t=t_low, s=-10, v=state(t_low)[1], scale=20)
    s100, v100 = state(100)
    check(f[3], t=100, s=s100, v=v100, scale=20)
    assert f[3]["v"] >= float(-vt) * (1 + 1e-15)  # never beyond the terminal speed (to rounding)
    t313 = t_top + vt / mp.mpf("9.81") * mp.atanh(mp.mpf("31.3") / vt)
    check(f[4], t=t313, s=state(t313)[0], v=-31.3, scale=20)
    unreached(f[5])
    assert any("find[5]" in w and "terminal velocity" in w for w in rec["warnings"])
    sm1, vm1 = state(-1)
    check(f[6], t=-1, s=sm1, v=vm1, scale=20)


def test_case4_spring():
    rec = solve("case4-spring.yaml")
    assert rec["results"]["case"] == 4
    assert rec["equations"] == ["6.14", "6.15", "6.12"]
    f = rec["results"]["find"]
    w, s1, v1 = mp.mpf(5), mp.mpf("0.1"), mp.mpf(1)
    s = lambda t: s1 * mp.cos(w * t) + v1 / w * mp.sin(w * t)
    v = lambda t: -s1 * w * mp.sin(w * t) + v1 * mp.cos(w * t)
    A = mp.sqrt(s1 ** 2 + (v1 / w) ** 2)
    phi = mp.atan2(s1, v1 / w)                   # s = A sin(w t + phi)
    for k, t in ((0, 1), (1, mp.mpf("-0.7")), (2, 50)):
        check(f[k], t=t, s=s(t), v=v(t), scale=1)
    check(f[3], t=(mp.pi / 2 - phi) / w, s=A, v=0)
    check(f[4], t=(mp.asin(mp.mpf("0.2") / A) - phi) / w, s=0.2)
    check(f[5], t=(3 * mp.pi / 2 - phi) / w, s=-A, v=0)     # grazing the lower turning point
    check(f[6], t=(mp.pi - 2 * phi) / w, s=0.1, v=-1)
    unreached(f[7])
    assert any("find[7]" in w_ and "turning point s = 0.2236067977" in w_ for w_ in rec["warnings"])
    assert rec["results"]["period"] == pytest.approx(float(2 * mp.pi / w), rel=1e-12)


def test_general_forced_damped():
    rec = solve("general-forced-damped.yaml")
    assert rec["results"]["case"] == "general"
    assert rec["method"] == "ode:DOP853"
    f = rec["results"]["find"]
    F = lambda t, y: [y[1], -4 * y[0] - mp.mpf("0.4") * y[1] + mp.sin(t)]
    sol = mp.odefun(F, 0, [mp.mpf("0.5"), mp.mpf(1)])
    check(f[0], t=3, s=sol(3)[0], v=sol(3)[1])
    # backward: integrate the time-reversed system u(tau) = y(-tau)
    G = lambda tau, y: [-y[1], -(-4 * y[0] - mp.mpf("0.4") * y[1] + mp.sin(-tau))]
    back = mp.odefun(G, 0, [mp.mpf("0.5"), mp.mpf(1)])
    check(f[1], t=-1, s=back(1)[0], v=back(1)[1])
    t0 = mp.findroot(lambda t: sol(t)[1], 0.39)
    check(f[2], t=t0, s=sol(t0)[0], v=0)
    t5 = mp.findroot(lambda t: sol(t)[0] + mp.mpf("0.5"), 4.6)
    check(f[3], t=t5, s=-0.5, v=sol(t5)[1])
    unreached(f[4])
    assert any("find[4]" in w and "t_max" in w for w in rec["warnings"])
    assert 0 < rec["error_estimate"] <= 1e-10 * 10_000      # the nominal bound: rtol x the steps (at most the budget)
