"""Exact inputs at the boundaries of rectilinear motion (issue 16): a v1
given as the terminal velocity is the equilibrium, a target given as the
turning point is reached with v = 0 (docs/types/rectilinear.md).

References: the closed form of case 3 with a = −g + k v² in 50-digit mpmath
(u = −v: u = u* tanh(k u* t + α) below u*, u* coth(k u* t + α) above).
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import solve_one_text

G, K = "9.81", "0.002"


def _s_ref(v1: float, t: float):
    with mp.workdps(50):
        g, k, u1 = mp.mpf(G), mp.mpf(K), -mp.mpf(v1)
        us = mp.sqrt(g / k)
        if u1 == us:
            return -us * t
        if u1 < us:
            al = mp.atanh(u1 / us)
            return -(mp.log(mp.cosh(k * us * t + al)) - mp.log(mp.cosh(al))) / k
        al = mp.acoth(u1 / us)
        return -(mp.log(mp.sinh(k * us * t + al)) - mp.log(mp.sinh(al))) / k


@pytest.mark.parametrize("v1", ["-sqrt(9.81/0.002)", "-sqrt(9.81)/sqrt(0.002)", "-70.03570517957252"])
def test_terminal_velocity_given_is_equilibrium(v1):
    """a(v1) = ±1.8e-15 (rounding): the body moves uniformly (was exit 3)."""
    rec = solve_one_text(f'type: rectilinear\na: "-{G} + {K}*v**2"\nv1: "{v1}"\nfind: [{{t: 2}}, {{s: -100}}]\n')
    f = rec["results"]["find"]
    v = f[0]["v"]
    assert f[0]["reached"] and f[0]["s"] == 2 * v
    assert f[1]["reached"] and f[1]["t"] == pytest.approx(-100 / v, rel=2.3e-16)
    assert float(abs(f[0]["s"] - _s_ref(v, 2.0))) <= 1e-13 * 140


@pytest.mark.parametrize("v1", [-70.03570517957256, -70.03570517957248, -70.0357051795724])
def test_just_off_terminal_velocity_is_not_a_pole(v1):
    """v1 a few ulps beyond the rule: v tends to v* (a zero of a), not to a
    singularity (these were 'a is singular at v = -70.04')."""
    rec = solve_one_text(f'type: rectilinear\na: "-{G} + {K}*v**2"\nv1: {v1!r}\nfind: [{{t: 2}}]\n')
    q = rec["results"]["find"][0]
    assert q["reached"] and not rec["warnings"]
    assert float(abs(q["s"] - _s_ref(v1, 2.0))) <= 1e-12 * 140


def test_case1_turning_point_given_as_expression():
    """s = v1²/(2|a|) written as an expression is the turning point: reached, v = 0."""
    rec = solve_one_text('type: rectilinear\na: -9.81\nv1: 10\nfind: [{s: "100/19.62"}, {s: "50/9.81"}]\n')
    for q in rec["results"]["find"]:
        assert q["reached"] and q["v"] == 0.0
        assert q["t"] == pytest.approx(10 / 9.81, rel=4.5e-16)


def test_an_oscillation_below_the_rounding_of_s_is_a_numerical_error():
    """k = 1e-298, m = 4, v1 = 1e-300 from s1 = 0: the amplitude v1/ω = 2e-151 is below the
    rounding the position scan resolves, so both legs last 0 s in doubles and the period is 0;
    a time query then took fmod(t, 0) (exit 3, fuzz seed 3391620).  Refused, exit 1, saying why."""
    from tests.conftest import solve_text

    rec = solve_text("type: rectilinear\na: -k/m*s\nparams: {k: 1.0000000000000001e-298, m: 4}\n"
                     "s1: 0.0\nv1: 1.0e-300\nfind: [{t: 1.0e-16}, {t: 50}]\n", "tiny.yaml")[0]
    assert rec["exit_code"] == 1, rec["error"]
    assert "period" in rec["error"] and "rescale" in rec["error"]
