"""Query semantics and edge cases of every route, against references derived here."""

from __future__ import annotations

import math
import subprocess
import sys

import mpmath as mp
import pytest

from tests.conftest import ROOT, solve_one_text

MPMATH_DPS = 30
mp.mp.dps = 30
RTOL = 1e-10


def close(x, ref, scale=1.0, rtol=RTOL):
    assert x is not None
    assert abs(x - float(ref)) <= rtol * max(abs(float(ref)), scale), (x, float(ref))


def problem(a, find, **kw):
    lines = ["type: rectilinear", f'a: "{a}"'] + [f"{k}: {v}" for k, v in kw.items()]
    lines.append("find:")
    lines += [f"  - {{{k}: {v}}}" for q in find for k, v in q.items()]
    return solve_one_text("\n".join(lines) + "\n")


def entries(rec):
    return rec["results"]["find"]


def is_unreached(e):
    return {k: x for k, x in e.items() if k != "at_end"} == {"t": None, "s": None, "v": None, "a": None,
                                                             "reached": False, "distance": None}


# -- case 1 ---------------------------------------------------------------------


def test_case1_semantics():
    rec = problem("-4", [{"s": -10}, {"v": 30}, {"s": 20}, {"s": 0}, {"v": 20}, {"t": -3}, {"v": -60}],
                  v1=20, t_max=11)
    f = entries(rec)
    close(f[0]["t"], (20 + math.sqrt(400 + 80)) / 4)     # passes s = 0 downwards later
    assert is_unreached(f[1])                             # v moves away from 30
    close(f[2]["t"], (20 - math.sqrt(400 - 160)) / 4)    # first of two crossings
    close(f[3]["t"], 10.0)                                # s1 again on the way back (not t1: §11)
    assert is_unreached(f[4])                             # v1 held at the start is never reached again
    close(f[5]["s"], 20 * -3 - 2 * 9); close(f[5]["v"], 32)
    assert is_unreached(f[6])                             # t = 20 > t_max
    assert any("find[6]" in w and "t_max" in w for w in rec["warnings"])


def test_case1_turning_point_up_to_rounding():
    # s_turn = v1^2 / (2|a|) = 0.45, with rounding in 0.3**2 and 0.2*0.45
    f = entries(problem("-0.1", [{"s": 0.45}], v1=0.3))
    close(f[0]["t"], 3.0); close(f[0]["v"], 0.0, scale=0.3)
    f = entries(problem("-0.1", [{"s": 0.4500001}], v1=0.3))
    assert is_unreached(f[0])


def test_case1_does_not_import_scipy_or_numpy():
    code = ("import sys; from tests.conftest import solve_path; "
            "solve_path('problems/rectilinear/case1-constant-acceleration.yaml'); "
            "print('scipy' in sys.modules, 'numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         env={"PYTHONPATH": str(ROOT), "PATH": ""})
    assert out.stdout.split() == ["False", "False"], out.stderr


# -- routes agree ---------------------------------------------------------------


@pytest.mark.parametrize("a,kw,find", [
    ("3*sin(2*t)", dict(v1=-1, s1=0.5), [{"t": 2}, {"t": -1.5}, {"v": 0.5}, {"s": 1}]),
    ("-9.81 - 0.01*v*abs(v)", dict(v1=20), [{"t": 1}, {"t": -1}, {"v": 0}, {"s": -10}]),
    ("-4*s - 0.5*s**3", dict(v1=1, s1=0.5), [{"t": 1}, {"t": -2.5}, {"v": 0}, {"s": -0.6}]),
])
def test_quadrature_and_ode_routes_agree(a, kw, find):
    q = problem(a, find, **kw)
    o = problem(a, find, accuracy="{method: ode}", **kw)
    assert q["method"].startswith("quadrature") and o["method"] == "ode:DOP853"
    for x, y in zip(entries(q), entries(o)):
        for k in "tsv":
            close(x[k], y[k], scale=1.0, rtol=1e-9)


def test_quadrature_for_case1_uses_the_case2_route():
    rec = problem("-4", [{"t": 2}, {"s": 50}], v1=20, accuracy="{method: quadrature}")
    assert rec["method"] == "quadrature+root"
    f = entries(rec)
    close(f[0]["s"], 32); close(f[1]["t"], 5, scale=5)


def test_estimate_reports_a_second_solve():
    rec = problem("-0.5*v", [{"t": 2}], v1=10, accuracy="{estimate: true}")
    assert 0 <= rec["error_estimate"] < 1e-10


# -- case 2 -------------------------------------------------------------------------


def test_case2_grazing_turning_point():
    # a = -2 (written with t): s rises to its maximum 4 at t = 2 and comes back
    f = entries(problem("-2 + 0*t", [{"s": 4}, {"v": -4}, {"s": 4.0000001}], v1=4))
    assert f[0]["t"] == pytest.approx(2, rel=1e-12) and f[0]["s"] == pytest.approx(4, rel=1e-12)
    close(f[1]["t"], 4)
    assert is_unreached(f[2])


# -- case 3 -------------------------------------------------------------------------


def test_case3_coulomb_friction_stops_in_finite_time():
    f = entries(problem("-2*sign(v)", [{"t": 1}, {"t": 5}, {"v": 0}, {"s": 4}, {"s": 5}, {"t": -1}], v1=4))
    close(f[0]["s"], 3); close(f[0]["v"], 2)
    close(f[1]["s"], 4); close(f[1]["v"], 0, scale=1)     # at rest after t = 2
    close(f[2]["t"], 2); close(f[3]["t"], 2)
    assert is_unreached(f[4])
    close(f[5]["s"], -5); close(f[5]["v"], 6)


def test_case3_finite_time_blow_up():
    # a = v^2, v1 = 1: v = 1/(1 - t), s = -ln(1 - t)
    rec = problem("v**2", [{"t": 0.5}, {"t": 2}, {"t": -1}, {"v": 1e6}], v1=1)
    f = entries(rec)
    close(f[0]["v"], 2); close(f[0]["s"], math.log(2))
    assert is_unreached(f[1]) and any("blow-up" in w for w in rec["warnings"])
    close(f[2]["v"], 0.5); close(f[2]["s"], -math.log(2))
    close(f[3]["t"], 1 - 1e-6); close(f[3]["s"], math.log(1e6))


@pytest.mark.parametrize("T", [5, 20, 40, 200, 1e5])
def test_case3_t_queries_near_terminal_velocity(T):
    # a = 5 - v from rest: v = 5 (1 - e^-t), s = 5 t - 5 (1 - e^-t)
    f = entries(problem("5 - v", [{"t": T}]))
    T = mp.mpf(T)
    close(f[0]["v"], 5 * (1 - mp.exp(-T)))
    close(f[0]["s"], 5 * T - 5 * (1 - mp.exp(-T)))


def test_case3_v_query_close_to_terminal_velocity():
    f = entries(problem("5 - v", [{"v": 4.999999}, {"v": 5}, {"v": 5.1}]))
    close(f[0]["t"], mp.log(5 / mp.mpf("0.000001")))
    assert is_unreached(f[1]) and is_unreached(f[2])


# -- case 4 -------------------------------------------------------------------------


@pytest.mark.parametrize("rtol", [1e-12, 2.3e-14])
def test_case4_tight_rtol_is_answered(rtol):
    # the quadratures' rtol (rtol/100) is floored where their error estimate can certify it:
    # below 1.1e-14 they never converged and the work budget refused the problem (exit 1)
    rec = problem("-4*s", [{"t": 1}, {"s": -0.3}], s1=0.5, v1=1, accuracy=f"{{rtol: {rtol}, estimate: true}}")
    f = entries(rec)
    s_ = lambda t: (mp.cos(2 * t) + mp.sin(2 * t)) / 2     # noqa: E731
    close(f[0]["s"], s_(1), scale=0.5, rtol=1e-13)
    close(f[1]["t"], mp.findroot(lambda t: s_(t) + mp.mpf("0.3"), 1.2), rtol=1e-13)
    assert rec["error_estimate"] < 1e-12 and not rec["warnings"]


def test_case4_start_at_rest_is_symmetric_in_time():
    f = entries(problem("-9*s", [{"t": 0.4}, {"t": -0.4}, {"v": 0}, {"s": -0.2}], s1=0.2))
    close(f[0]["s"], 0.2 * math.cos(1.2)); close(f[1]["s"], 0.2 * math.cos(1.2))
    close(f[0]["v"], -0.6 * math.sin(1.2)); close(f[1]["v"], 0.6 * math.sin(1.2))
    close(f[0]["distance"], 0.2 - 0.2 * math.cos(1.2))
    assert not f[2]["reached"]                            # searched to the largest t asked, 0.4 < π/3 (§11)
    close(f[3]["t"], math.pi / 3)                         # the type's own {s} looks to t_max
    f = entries(problem("-9*s", [{"v": 0}], s1=0.2))
    close(f[0]["t"], math.pi / 3)                         # from rest: the next turning point (§11)
    close(f[0]["distance"], 0.4)


def test_case4_equilibrium():
    rec = problem("-s", [{"t": 3}, {"s": 1}, {"v": 0}])
    f = entries(rec)
    assert f[0]["s"] == 0 and f[0]["v"] == 0
    assert is_unreached(f[2])                             # at rest for ever: v = 0 is never reached again
    assert is_unreached(f[1]) and any("equilibrium" in w for w in rec["warnings"])


def test_case4_pendulum_separatrix_is_approached_never_reached():
    # s'' = -sin s with v1 = 2: s = 4 atan(e^t) - pi, v = 2 sech t
    rec = problem("-sin(s)", [{"t": 3}, {"t": -3}, {"t": 50}, {"s": 3}, {"s": 3.2}, {"v": 0}], v1=2)
    f = entries(rec)
    for k, T in ((0, 3), (1, -3)):
        close(f[k]["s"], 4 * mp.atan(mp.exp(T)) - mp.pi, scale=1)
        close(f[k]["v"], 2 / mp.cosh(T), scale=1)
    close(f[2]["s"], mp.pi)
    close(f[3]["t"], mp.log(mp.tan((3 + mp.pi) / 4)), scale=1)
    assert is_unreached(f[4]) and is_unreached(f[5])


def test_case4_escape_and_fall_into_a_singularity():
    # a = -1/s^2 (mu = 1) from s1 = 1 with v1 = 2 > sqrt(2): v^2 = 2 + 2/s, escapes
    rec = problem("-1/s**2", [{"s": 10}, {"v": 1.5}, {"v": 1.4}, {"t": -0.3}, {"t": -0.5}], s1=1, v1=2)
    f = entries(rec)
    t10 = mp.quad(lambda s: 1 / mp.sqrt(2 + 2 / s), [1, 10])
    close(f[0]["t"], t10)
    s15 = 2 / (mp.mpf("2.25") - 2)
    close(f[1]["t"], mp.quad(lambda s: 1 / mp.sqrt(2 + 2 / s), [1, s15]))
    assert is_unreached(f[2])
    s_back = mp.findroot(lambda x: mp.quad(lambda s: 1 / mp.sqrt(2 + 2 / s), [x, 1]) - mp.mpf("0.3"), 0.3)
    close(f[3]["s"], s_back)
    assert is_unreached(f[4]) and any("singular" in w for w in rec["warnings"])
    # from rest: s = x, t = sqrt(1/2) (sqrt(x (1 - x)) + acos(sqrt(x))); falls in at pi / (2 sqrt 2)
    rec = problem("-1/s**2", [{"t": 1}, {"s": 0.5}, {"t": 1.2}], s1=1)
    f = entries(rec)
    T = lambda x: mp.sqrt(mp.mpf(1) / 2) * (mp.sqrt(x * (1 - x)) + mp.acos(mp.sqrt(x)))
    close(f[0]["s"], mp.findroot(lambda x: T(x) - 1, 0.35))
    close(f[1]["t"], T(mp.mpf("0.5")))
    assert is_unreached(f[2])
    assert any(f"{float(mp.pi / (2 * mp.sqrt(2))):.9g}"[:9] in w for w in rec["warnings"])


def test_case4_long_times_stay_on_the_orbit():
    # 1000 periods of a stiff-ish spring: phase must survive the reduction mod the period
    f = entries(problem("-100*s", [{"t": 628.3}], s1=0.1, v1=1))
    close(f[0]["s"], 0.1 * mp.cos(6283) + 0.1 * mp.sin(6283), rtol=1e-9)


EXP_GROWTH = """\
type: rectilinear
params: {k: -100.0, m: 4}
a: -k/m*s
s1: 1.0000000000000001e-151
v1: 1.0e-08
find: [{t: 1}, {t: -0.7}, {t: 50}, {v: 0}, {s: 0.2}, {s: -2.23606797749979e-301}, {v: -0.0}, {s: 0.3}, {t: 51}, {t: -51}]
"""


def test_case4_exponential_growth_across_scales():
    # a = 25 s from s1 = 1e-151, v1 = 1e-8 (fuzz seed 1096): s = s1 cosh 5t + (v1/5) sinh 5t crosses the scales
    # 1e-151 ... 1e100; no finite-time escape — |s| = 1e100 only at t ≈ 50.196 (both ways)
    rec = solve_one_text(EXP_GROWTH)
    f = entries(rec)
    with mp.workdps(50):
        s1, v1 = mp.mpf(1.0000000000000001e-151), mp.mpf("1e-8")
        S = lambda t: s1 * mp.cosh(5 * t) + v1 / 5 * mp.sinh(5 * t)
        V = lambda t: 5 * s1 * mp.sinh(5 * t) + v1 * mp.cosh(5 * t)
        # s = R sinh(5t + φ), R = sqrt((v1/5)^2 - s1^2), tanh φ = 5 s1 / v1
        R, ph = mp.sqrt((v1 / 5) ** 2 - s1 ** 2), mp.atanh(5 * s1 / v1)
        t_of = lambda x: (mp.asinh(x / R) - ph) / 5
        for k, T in ((0, 1), (1, mp.mpf(-0.7)), (2, 50)):
            assert f[k]["t"] == T
            close(f[k]["s"], S(mp.mpf(T)), scale=0, rtol=1e-9)
            close(f[k]["v"], V(mp.mpf(T)), scale=0, rtol=1e-9)
        close(f[4]["t"], t_of(mp.mpf("0.2")))
        close(f[7]["t"], t_of(mp.mpf("0.3")))
        t_cap = t_of(mp.mpf(10) ** 100)
    # v never vanishes (|v1| > 5 |s1|); s < s1 was passed before t1 only
    assert is_unreached(f[3]) and is_unreached(f[5]) and is_unreached(f[6])
    assert is_unreached(f[8]) and is_unreached(f[9])
    w8 = next(w for w in rec["warnings"] if w.startswith("find[8]"))
    w9 = next(w for w in rec["warnings"] if w.startswith("find[9]"))
    assert f"t ≈ {float(t_cap):.10g}"[:13] in w8 and f"t ≈ {float(-t_cap):.10g}"[:14] in w9, (w8, w9)
    assert all("finite time" not in w for w in rec["warnings"])
    assert "grows without bound" in w8 and "quadrature" not in " ".join(rec["warnings"])


def test_case4_finite_time_escape_of_a_cubic_force():
    # a = s^3 from rest at s1 = 1: v^2 = (s^4 - 1)/2, t(∞) = ∫_1^∞ ds / |v| converges (v^2 overflows the
    # doubles near s ~ 1e77: that is a cap like |s| = 1e100, not a singularity of a)
    rec = problem("s**3", [{"t": 5}, {"s": 10}], s1=1)
    f = entries(rec)
    T = mp.quad(lambda u: 2 / mp.sqrt((4 + 6 * u**2 + 4 * u**4 + u**6) / 2), [0, 1, mp.inf])    # s = 1 + u^2
    assert is_unreached(f[0])
    w = rec["warnings"][-1]
    assert "escape to infinity in finite time" in w and f"t ≈ {float(T):.10g}"[:12] in w and "singular" not in w, w
    close(f[1]["t"], mp.quad(lambda u: 2 / mp.sqrt((4 + 6 * u**2 + 4 * u**4 + u**6) / 2), [0, 1, 3]))
    # from rest far out: s1 = -4e49 (scaled: s = s1 x, t = x-integral / |s1|)
    f = entries(problem("s**3", [{"s": -1e50}, {"t": 1e-100}], s1=-4e49))
    close(f[0]["t"], mp.quad(lambda u: 2 / mp.sqrt((4 + 6 * u**2 + 4 * u**4 + u**6) / 2), [0, mp.sqrt(1.5)])
          / mp.mpf("4e49"), scale=0)
    close(f[0]["v"], -mp.sqrt((mp.mpf("1e50") ** 4 - mp.mpf("4e49") ** 4) / 2), scale=0)
    close(f[1]["s"], mp.mpf("-4e49") - mp.mpf("6.4e148") * mp.mpf("1e-200") / 2, scale=0)
    close(f[1]["v"], -mp.mpf("6.4e148") * mp.mpf("1e-100"), scale=0)


# -- general ------------------------------------------------------------------------


def test_general_grazing_turning_point_and_extremum_of_v():
    # a = -4 s written with t: amplitude sqrt(0.5) — the target IS the turning point
    # s = sin(2t + pi/4)/sqrt(2), v = sqrt(2) cos(2t + pi/4): v = -sqrt(2) is the extremum of v
    f = entries(problem("-4*s + 0*t", [{"s": 0.7071067811865476}, {"v": -1.4142135623730951}], s1=0.5, v1=1))
    close(f[0]["t"], mp.pi / 8, rtol=1e-9)
    close(f[1]["t"], 3 * mp.pi / 8, rtol=1e-9)


def test_general_blow_up_is_reported():
    rec = problem("v**2 + 0*t", [{"t": 0.5}, {"t": 2}, {"t": -1}], v1=1)
    f = entries(rec)
    close(f[0]["v"], 2, rtol=1e-9); close(f[2]["v"], 0.5, rtol=1e-9)
    assert is_unreached(f[1])
    assert any("find[1]" in w and "blows up" in w for w in rec["warnings"])


def test_general_blow_up_backwards_is_reported_where():
    # v' = v², v(0) = -1: v = -1/(1 + t) blows up at t = -1 going backwards
    rec = problem("v**2 + 0*t", [{"t": -0.5}, {"t": -2}], v1=-1)
    f = entries(rec)
    close(f[0]["v"], -2, rtol=1e-9)
    assert is_unreached(f[1])
    w = [w for w in rec["warnings"] if "find[1]" in w]
    assert w and "stopped at t = -" in w[0] and "blows up" in w[0]


def _general_error(text):
    from tests.conftest import solve_text

    (rec,) = solve_text(text)
    return rec


def test_general_budget_refuses_far_queries():
    # damped oscillator, growing backwards: t = -1e8 needs ~1e9 steps — refused (exit 1), not a hang
    rec = _general_error("type: rectilinear\na: -4*s - 0.4*v + sin(t)\ns1: 0.25\nv1: 1\n"
                         "find: [{t: 3}, {t: -1.0e+8}]\n")
    assert rec["exit_code"] == 1
    assert "t = -1e+08 s needs about" in rec["error"] and "budget of 10000" in rec["error"]   # general.DEFAULT_MAX_STEPS
    assert "accuracy.max_steps" in rec["error"]


def test_general_budget_honours_max_steps():
    text = "type: rectilinear\na: -4*s + 0*t\ns1: 1\nfind: [{t: 100}]\n"
    assert _general_error(text).get("error") is None
    rec = _general_error(text + "accuracy: {max_steps: 300}\n")
    assert rec["exit_code"] == 1 and "budget of 300" in rec["error"]


def _relative_error(pairs_by_quantity) -> float:
    """The largest error of each quantity relative to its scale (its largest exact magnitude
    over the answers): the terms of error_estimate."""
    worst = 0.0
    for pairs in pairs_by_quantity:
        scale = max(abs(ref) for _, ref in pairs)
        worst = max(worst, max(abs(x - ref) for x, ref in pairs) / scale)
    return float(worst)


@pytest.mark.parametrize("rtol", [1e-6, 1e-8, 1e-10])
@pytest.mark.parametrize("estimate", [False, True])
def test_general_error_estimate_is_honest(rtol, estimate):
    # a = -4 s (written with t, so the general ODE route): s = 0.3 cos 2t + 0.5 sin 2t exactly
    def s_(t):
        return mp.mpf("0.3") * mp.cos(2 * t) + mp.mpf("0.5") * mp.sin(2 * t)

    def v_(t):
        return -mp.mpf("0.6") * mp.sin(2 * t) + mp.cos(2 * t)

    t_v0 = mp.atan(mp.mpf(5) / 3) / 2                       # first v = 0
    t_s = mp.findroot(lambda t: s_(t) + mp.mpf("0.4"), 1.2)  # first s = -0.4
    assert 0 < t_v0 < t_s < mp.pi / 2 + t_v0
    rec = problem("-4*s + 0*t", [{"t": 1}, {"t": 20}, {"t": -3}, {"v": 0}, {"s": -0.4}], s1=0.3, v1=1,
                  accuracy=f"{{rtol: {rtol}, atol: {rtol * 1e-2}, estimate: {str(estimate).lower()}}}")
    assert rec["results"]["case"] == "general" and rec["method"].startswith("ode:")
    f = entries(rec)
    times = [mp.mpf(t) for t in (1, 20, -3)] + [t_v0, t_s]
    # t relative to the time elapsed since t1 = 0, s, v, a to their largest magnitudes
    err = _relative_error([[(e["t"], t) for e, t in zip(f, times)], [(e["s"], s_(t)) for e, t in zip(f, times)],
                           [(e["v"], v_(t)) for e, t in zip(f, times)], [(e["a"], -4 * s_(t)) for e, t in zip(f, times)]])
    assert err > 1e-14
    ratio = rec["error_estimate"] / err
    # the check solve measures the error (its own is 1/100 of it); the nominal estimate (no second
    # solve: rtol x the accepted steps, the local error bounds added up) bounds it: DOP853's global
    # error grows with the span (here 2.4-3 x rtol after the ~6 undamped periods to t = 20), the
    # bound with the steps (20-50 x the error here)
    assert (0.5 <= ratio <= 2) if estimate else (rec["error_estimate"] >= rtol and 1 <= ratio <= 1000), \
        (rec["error_estimate"], err)


def test_general_error_estimate_falls_back_to_a_looser_solve_over_budget():
    # the solve at rtol 1e-10 (~580 steps) fits max_steps: 800, the check solve at rtol/100 (~1020) does not
    rec = problem("-4*s + 0*t", [{"t": 100}], s1=1, accuracy="{max_steps: 800, estimate: true}")
    assert entries(rec)[0]["reached"] and rec["error_estimate"] > 0
    assert any("10·rtol" in w and "accuracy.max_steps" in w for w in rec["warnings"])
    rec = problem("-4*s + 0*t", [{"t": 100}], s1=1, accuracy="{max_steps: 800}")
    assert rec["error_estimate"] >= 1e-10 and not rec["warnings"]     # no check solve: the nominal bound


# -- case 2: singular and unresolvable a(t), work budget ---------------------------

_TAN_NEST = "sin(cos(tan(exp(log(sqrt(abs(t)))))))"   # = sin(cos(tan(sqrt t))): poles of tan at t = (pi/2 + k pi)^2


def test_case2_unresolvable_oscillation_warns_with_an_honest_error_estimate():
    # near t = (pi/2)^2 the integrand oscillates without bound (bounded, so the integral exists):
    # answered, with a warning that names the place and an error estimate far above rtol
    rec = problem(_TAN_NEST, [{"t": 2}, {"v": 0}, {"s": 50}])
    e = entries(rec)
    assert e[0]["reached"] and e[2]["reached"]
    # t = 2 lies before the first pole: full accuracy
    ref = mp.quad(lambda x: mp.sin(mp.cos(mp.tan(mp.sqrt(x)))), [0, 2])
    close(e[0]["v"], ref)
    assert not e[1]["reached"]          # v1 = 0 held at the start: searched to the largest t asked, 2 (§11)
    assert abs(e[2]["s"] - 50) < 1e-9
    # the place named: within the panels next to the pole of tan at t = (π/2)² = 2.4674
    near = [float(w.split("near t = ")[1].split(")")[0]) for w in rec["warnings"]
            if "did not reach the requested tolerance" in w and "near t = " in w]
    assert near and abs(near[0] - (math.pi / 2) ** 2) < 2e-3
    assert rec["error_estimate"] > 1e-6


def test_case2_pole_with_sign_change_is_not_a_principal_value():
    # 1/(t - 1) and tan t change sign through their poles; symmetric quadrature nodes would
    # cancel them to a finite principal value: the integral does not exist, the motion ends there
    rec = problem("1/(t-1)", [{"t": 2}, {"t": 0.5}, {"v": 3}])
    e = entries(rec)
    assert is_unreached(e[0]) and is_unreached(e[2])
    close(e[1]["v"], math.log(0.5))
    assert any("find[0]" in w and "t = 1" in w for w in rec["warnings"])
    rec = problem("tan(t)", [{"t": 2}, {"v": 3}, {"s": 50}])
    e = entries(rec)
    assert is_unreached(e[0]) and is_unreached(e[2])
    close(e[1]["t"], math.atan(math.sqrt(math.exp(6) - 1)))      # v = -ln cos t = 3
    assert any("find[0]" in w and "not integrable near t = 1.570796327" in w for w in rec["warnings"])


def test_case2_even_pole_ends_the_motion():
    rec = problem("1/(t-1)**2", [{"t": 2}, {"v": 3}, {"s": 50}])
    e = entries(rec)
    assert is_unreached(e[0]) and is_unreached(e[2])
    close(e[1]["t"], 0.75)                                     # v = t/(1 - t) = 3
    assert any("find[2]" in w and "t = 1" in w for w in rec["warnings"])


def test_case2_integrable_singularity_is_answered():
    rec = problem("1/sqrt(abs(t-1))", [{"t": 2.3}, {"v": 3}])
    e = entries(rec)
    assert e[0]["reached"] and abs(e[0]["v"] - 2 - 2 * math.sqrt(1.3)) < 1e-5
    assert abs(e[1]["t"] - 1.25) < 1e-5
    # relative to the scale of v over the answers (|v| = 4.28 at t = 2.3)
    assert rec["error_estimate"] >= abs(e[0]["v"] - 2 - 2 * math.sqrt(1.3)) / e[0]["v"]


def test_case2_budget_refuses_unresolvable_sign_changes():
    from tests.conftest import solve_text

    (rec,) = solve_text("type: rectilinear\na: cos(1e300 * t)\ns1: 2.5\nv1: -1\nfind: [{s: 0}]\n")
    assert rec["exit_code"] == 1
    assert "budget of 50000" in rec["error"] and "accuracy.max_steps" in rec["error"]
    (rec,) = solve_text("type: rectilinear\na: 3*sin(2*t)\nfind: [{s: 1e9}]\naccuracy: {max_steps: 300}\n")
    assert rec["exit_code"] == 1 and "budget of 300" in rec["error"]


def test_case2_long_scan_with_a_huge_s1():
    # 3 sin 2t over t_max = 1000 s with an unreachable s target: ~640 zeros of v, found together
    rec = problem("3*sin(2*t)", [{"v": 0.5}, {"s": 1}], s1="5.0e+149", v1="-1.0e-08")
    e = entries(rec)
    close(e[0]["t"], math.acos((-1e-8 + 1.5 - 0.5) / 1.5) / 2)
    assert is_unreached(e[1])


def test_case3_quadratic_drag_with_negligible_k():
    # v* = -3e76: v = v* - D0 e^-u cancelled catastrophically near v1 (t = 1 gave s = 0, v = 0)
    rec = problem("-9.81 - k*v*abs(v)", [{"t": 1}, {"v": 0}, {"s": -10}, {"t": -1}], params="{k: 1.0e-152}", v1=20)
    e = entries(rec)
    close(e[0]["s"], 20 - 4.905)
    close(e[0]["v"], 20 - 9.81)
    close(e[1]["t"], 20 / 9.81)
    close(e[2]["t"], (20 + math.sqrt(400 + 2 * 9.81 * 10)) / 9.81)
    close(e[3]["s"], -20 - 4.905)


def test_case3_v1_beyond_the_blow_up_threshold():
    rec = problem("-9.81 - k*v*abs(v)", [{"t": 1}, {"v": 0}], params="{k: 0.0}", v1="2.0e+301")
    assert all(is_unreached(x) for x in entries(rec))


def test_case1_subnormal_acceleration():
    # a/2 underflows to 0 for a = 5e-324: the position root must not divide by it
    rec = problem("5.0e-324", [{"s": 0.2}], s1=0.1, v1=1)
    close(entries(rec)[0]["t"], 0.1)


# -- the general route: an asymptote is not reached -----------------------------------------------

def test_a_critically_damped_return_never_reaches_rest_on_the_ode_route():
    # s̈ = −2ṡ − s from s = 1, v = −1: s = e^−t, v = −e^−t exactly (the critical root −1 twice, the
    # initial state on its pure exponential).  Neither s nor v ever reaches 0; the integration's
    # rounding crosses 0 tens of time constants later (at ~1e-28), which once read as "reached".
    rec = problem("-2*v - s", [{"s": 0}, {"v": 0}], s1=1, v1=-1, t_max=50)
    for e in entries(rec)[:2]:
        assert is_unreached(e), e
    said = [w for w in rec["warnings"] if "only creeps toward it" in w]
    assert len(said) == 2 and "asymptote" in said[0], rec["warnings"]


def test_an_underdamped_return_crosses_rest_on_the_ode_route():
    # the same equation's neighbour s̈ = −0.2ṡ − s from s = 1 at rest crosses 0 first at the root of
    # e^(−0.1 t) (cos ωd t + (0.1/ωd) sin ωd t), ωd = √0.99, and turns (v = 0) at t = π/ωd
    rec = problem("-0.2*v - s", [{"s": 0}, {"v": 0}], s1=1, v1=0, t_max=50)
    wd = mp.sqrt(mp.mpf("0.99"))
    t0 = mp.findroot(lambda t: mp.cos(wd * t) + mp.mpf("0.1") / wd * mp.sin(wd * t), 1.6)
    e0, e1 = entries(rec)[:2]
    close(e0["t"], t0, 1, rtol=1e-8)
    close(e1["t"], mp.pi / wd, 1, rtol=1e-8)
    assert not any("creeps" in w for w in rec["warnings"]), rec["warnings"]


def test_a_graze_at_the_top_is_reached_on_the_ode_route():
    # thrown up at 10 m/s under gravity, forced onto the ODE route: the top v0²/(2g) is met at an
    # extreme (a touch within the tolerance), at t = v0/g — not a creep
    rec = problem("-9.81", [{"s": "100/19.62"}], s1=0, v1=10, accuracy="{method: ode}")
    e = entries(rec)[0]
    assert e["reached"] is True, (e, rec["warnings"])
    close(e["t"], mp.mpf(10) / mp.mpf("9.81"), 1, rtol=1e-6)
