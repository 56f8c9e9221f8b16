"""Issue #28 for case 2 (a = a(t)): the extrema of v (the sign changes of a) and the quadrature
panels are decided by the signs of a at its critical points (case2_signs), never by a grid of
samples.  References by hand or mpmath at 30 digits, never from the code under test."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import solve_one_text

mp.mp.dps = 30


def solve(a: str, find: list[str], **kw) -> dict:
    lines = ["type: rectilinear", f'a: "{a}"'] + [f"{k}: {v}" for k, v in kw.items()] + ["find:"]
    return solve_one_text("\n".join(lines + [f"  - {q}" for q in find]) + "\n")


def test_a_thousand_sign_changes_of_a():
    # a = cos(100 t) + 1e-4 changes sign ~1000 times in 32 s; v = sin(100 t)/100 + 1e-4 t first
    # reaches 0.0131 just before its peak at t_494 = (π/2 + 988π)/100 = 31.05 s
    V = mp.mpf(0.0131)
    v = lambda t: mp.sin(100 * t) / 100 + mp.mpf("1e-4") * t          # noqa: E731
    peak = (mp.pi / 2 + 2 * mp.pi * 494) / 100
    assert v(peak - 2 * mp.pi / 100) < V < v(peak)                     # the peak before stays below
    t_ref = mp.findroot(lambda t: v(t) - V, (peak - mp.mpf("0.005"), peak), solver="anderson")
    rec = solve("cos(100*t) + 1e-4", ["{v: 0.0131}"], v1=0, t_max=32)
    f = rec["results"]["find"][0]
    assert f["reached"]
    # the root's condition: v's error (≤ estimate × scale) over |a(t*)|
    a_star = abs(mp.cos(100 * t_ref) + mp.mpf("1e-4"))
    assert abs(f["t"] - t_ref) <= 1e-9 * float(0.0131 / a_star) + 1e-12 * 31


def test_a_double_root_of_a_is_an_inflection_of_v_not_an_extremum():
    # a = −(t − 1)² touches 0 at t = 1: v = −((t − 1)³ + 1)/3 falls through −1/3 there and on
    rec = solve("-(t-1)**2", ["{v: -0.3343333333333333}", "{v: -0.3333333333333333}", "{s: -0.5}"], v1=0, t_max=10)
    f = rec["results"]["find"]
    assert all(e["reached"] for e in f)
    v = lambda t: -((t - 1) ** 3 + 1) / 3                              # noqa: E731
    s = lambda t: -((t - 1) ** 4 / 4 + t - mp.mpf(1) / 4) / 3            # noqa: E731
    t0 = 1 + mp.cbrt(3 * (mp.mpf(-0.3343333333333333) * -1) - 1)
    assert abs(f[0]["t"] - t0) <= 1e-9 and abs(v(t0) - mp.mpf(-0.3343333333333333)) < 1e-25
    # at the touch itself the root is ill-conditioned: δt ~ (3 δv)^(1/3) with δv ~ 1e-16
    assert abs(f[1]["t"] - 1) <= 1e-4
    t2 = mp.findroot(lambda t: s(t) + mp.mpf("0.5"), 1.5)
    assert abs(f[2]["t"] - t2) <= 1e-9


def test_two_roots_of_a_1e_10_apart_are_both_seen():
    # a = (t − 1)² − 1e-20: v has a maximum at 1 − 1e-10 and a minimum at 1 + 1e-10, 1.3e-30 apart;
    # the s-turning point at v = 0 (t = 3 (1/3 · 1e-20)…) — the scan must not fail on the pair
    rec = solve("(t-1)**2 - 1e-20", ["{v: 0.5}", "{t: 2}"], v1=0, t_max=10)
    f = rec["results"]["find"]
    t_ref = 1 + mp.cbrt(mp.mpf(0.5) * 3 - 1 + 3 * mp.mpf("1e-20"))   # ≈ (t−1)³/3 + 1/3 − 1e-20 t = 0.5
    t_ref = mp.findroot(lambda t: (t - 1) ** 3 / 3 + mp.mpf(1) / 3 - mp.mpf("1e-20") * t - mp.mpf(0.5), t_ref)
    assert f[0]["reached"] and abs(f[0]["t"] - t_ref) <= 1e-9
    assert f[1]["v"] == pytest.approx(2 / 3, rel=1e-12)


@pytest.mark.parametrize("c, w, t_max", [(5.123, 1e-5, 10), (0.5123, 1e-5, 10), (987.654321, 1e-3, 1000), (3.3, 1e-3, 1000)])
def test_a_pulse_1e_6_of_the_span_wide_is_found_wherever_it_lies(c, w, t_max):
    # a = exp(−((t − c)/w)²), w = 1e-6 of the span: no grid sees it, the enclosures of a locate it;
    # v jumps by w √π, half of it at the centre (by symmetry); s = jump · (t − c) after it
    jump = w * math.sqrt(math.pi)
    rec = solve(f"exp(-((t-{c!r})/{w!r})**2)", [f"{{v: {jump / 2!r}}}", f"{{t: {t_max}}}", f"{{s: {jump!r}}}"],
                v1=0, t_max=t_max)
    f = rec["results"]["find"]
    assert f[0]["reached"] and abs(f[0]["t"] - c) <= 1e-9 * max(c, 1)
    ref_v = mp.quad(lambda t: mp.exp(-((t - mp.mpf(c)) / mp.mpf(w)) ** 2), [c - 30 * w, c, c + 30 * w])
    assert abs(f[1]["v"] - ref_v) <= rec["error_estimate"] * float(ref_v)
    # s(t) = jump (t − c) once the pulse is past: s = jump a second after it
    assert f[2]["reached"] and abs(f[2]["t"] - (c + 1)) <= 1e-6 * max(c, 1)


def test_a_negative_a_with_a_hidden_positive_pulse():
    # a = −1e-3 + exp(−((t − 0.5123)/1e-5)²): v falls to −5.1e-4, jumps by 1.77e-5 and falls on
    rec = solve("-1e-3 + exp(-((t-0.5123)/1e-5)**2)", ["{t: 10}", "{v: 1.0e-6}"], v1=0, t_max=10)
    f = rec["results"]["find"]
    ref = -1e-2 + mp.sqrt(mp.pi) * mp.mpf("1e-5")
    assert abs(f[0]["v"] - ref) <= max(rec["error_estimate"], 1e-10) * 1e-2
    assert not f[1]["reached"]


def test_find_on_a_case4_motion_solved_once():
    # issue 29: find's searches evaluate the case-4 motion solved once (solved.Solved), each try
    # was a new solve (34 s of CPU for this problem, refused at the default budget); s = 0.1 cos 5t
    # + 0.2 sin 5t: the first maximum at atan(2)/5, s = 0.15 first at (asin(0.15/√0.05) − atan(1/2))/5
    rec = solve("-25*s", ["{max: s}", "{when: {s: 0.15}}", "{min: v}", "{t: 3}"], s1=0.1, v1=1)
    f = rec["results"]["find"]
    amp = math.sqrt(0.05)
    assert abs(f[0]["t"] - math.atan(2) / 5) <= 1e-7 and abs(f[0]["s"] - amp) <= 1e-9
    assert abs(f[1]["t"] - (math.asin(0.15 / amp) - math.atan(0.5)) / 5) <= 1e-9
    assert abs(f[2]["v"] + 5 * amp) <= 1e-8
    assert abs(f[3]["s"] - (0.1 * math.cos(15) + 0.2 * math.sin(15))) <= 1e-9
