"""Force excitation F = F0 sin(ωt) on the mass (issue 21 item 10): the gallery
file problems/vibration/force-excitation.yaml, an independent 50-digit
reference (mpmath, fitted constants of the general solution), resonance,
ζ across 1, the numerical route, the sweep, and invalid input."""

from __future__ import annotations

import math

import mpmath as mp
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.conftest import PROBLEMS, error_of, run_cli, solve_one_text, solve_path


def ref_force(times, *, m, k, zeta, F0, Om, x0=0.0, v0=0.0, L=0.0):
    """x(t) of m ẍ + c ẋ + k(x − L) = F0 sin(Ωt), from scratch: particular
    solution Im(F0/(k − mΩ² + icΩ) e^{iΩt}) (or the secular one), homogeneous
    c1 e^{s1 t} + c2 e^{s2 t} ((c1 + c2 t) e^{−ωt} at ζ = 1) fitted to x0, v0."""
    with mp.workdps(50):
        m, k, z, F0, Om = (mp.mpf(v) for v in (m, k, zeta, F0, Om))
        wn = mp.sqrt(k / m)
        c = 2 * m * z * wn
        den = k - m * Om**2 + 1j * c * Om
        if den == 0:
            a = -F0 / (2 * m * wn)

            def wp(t):
                return a * t * mp.cos(wn * t), a * (mp.cos(wn * t) - wn * t * mp.sin(wn * t))
        else:
            Z = F0 / den

            def wp(t):
                e = mp.expj(Om * t)
                return mp.im(Z * e), mp.im(1j * Om * Z * e)
        p0, pd0 = wp(mp.mpf(0))
        h0, hd0 = mp.mpf(x0) - L - p0, mp.mpf(v0) - pd0
        out = []
        for t in times:
            t = mp.mpf(t)
            if z == 1:
                hw = (h0 + (hd0 + wn * h0) * t) * mp.exp(-wn * t)
            else:
                q = wn * mp.sqrt(mp.mpc(z**2 - 1))
                s1, s2 = -z * wn + q, -z * wn - q
                c1 = (hd0 - s2 * h0) / (s1 - s2)
                hw = mp.re(c1 * mp.exp(s1 * t) + (h0 - c1) * mp.exp(s2 * t))
            out.append(hw + wp(t)[0] + L)
        return out


def _close(got, ref, rel):
    scale = max(abs(float(r)) for r in ref) or 1.0
    for g, r in zip(got, ref):
        assert abs(g - float(r)) <= rel * scale, (g, float(r))


def test_gallery_force_excitation():
    damped, resonant = solve_path(PROBLEMS / "vibration/force-excitation.yaml")
    r = damped["results"]
    # header: |D| = 0.4625 exactly, X = 1/37, φ = −atan2(0.15, 0.4375)
    assert r["r"] == 0.75
    assert r["magnification"] == pytest.approx(1 / 0.4625, rel=4e-16)
    assert r["X"] == pytest.approx(1 / 37, rel=4e-16)
    assert r["phi"] == pytest.approx(-math.atan2(0.15, 0.4375), rel=4e-16)
    assert r["transmissibility"] == pytest.approx(math.sqrt(1.0225) / 0.4625, rel=4e-16)
    assert r["F_T"] == pytest.approx(10 * math.sqrt(1.0225) / 0.4625, rel=4e-16)
    assert "A" not in r
    # the response: a closed form, a few ulp times the modest condition (ω t ≤ 60)
    _close(r["x"], ref_force(damped_times := [0, 0.5, 1, 3], m=2, k=800, zeta=0.1, F0=10, Om=15), 1e-13)
    assert r["x"][1:] == pytest.approx([0.0215438130126782, 0.0217153319064105, 0.0171282515883277], rel=1e-12)
    assert len(damped_times) == len(r["x"])
    s = resonant["results"]
    assert s["X"] is None and s["magnification"] is None and s["F_T"] is None
    assert any("undamped resonance" in w for w in resonant["warnings"])
    assert s["x"][2] == pytest.approx(0.02 * (math.sin(50) - 50 * math.cos(50)), rel=1e-13)


def _problem(zeta, Om, times, F0=3.0, x0=0.01, v0=-0.2, m=1.5, k=60.0, extra=""):
    return (f"type: vibration\nm: {m!r}\nk: {k!r}\nzeta: {zeta!r}\nx0: {x0!r}\nv0: {v0!r}\n"
            f"force: {{amplitude: {F0!r}, omega: {Om!r}}}\nat: {list(times)!r}\n{extra}")


@pytest.mark.parametrize("zeta", [0.0, 0.3, 1 - 1e-12, 1.0, 1 + 1e-12, 2.5, 40.0])
@pytest.mark.parametrize("ratio", [0.0, 0.5, 1.0, 1 + 1e-9, 3.0])
def test_against_reference_across_zeta_and_resonance(zeta, ratio):
    wn = math.sqrt(60.0 / 1.5)
    Om = ratio * wn
    times = [0, 0.05, 0.7, 2.0, 9.0]
    r = solve_one_text(_problem(zeta, Om, times))["results"]
    ref = ref_force(times, m=1.5, k=60.0, zeta=zeta, F0=3.0, Om=Om, x0=0.01, v0=-0.2)
    # closed form: ω t ≤ 60 and the divided differences are cancellation-free: 1e-12 of the scale
    _close(r["x"], ref, 1e-12)


def test_resonance_is_the_limit_of_near_resonance():
    wn = math.sqrt(60.0 / 1.5)
    at = _problem(0.0, wn, [5.0])
    near = _problem(0.0, wn * (1 + 1e-10), [5.0])
    a, b = solve_one_text(at)["results"]["x"][0], solve_one_text(near)["results"]["x"][0]
    assert a == pytest.approx(b, rel=1e-8)   # the secular term is continuous in ω (change ~ ω t δ)


@settings(max_examples=25, deadline=None)
@given(zeta=st.floats(0, 5), ratio=st.floats(0, 4), F0=st.floats(-100, 100))
def test_steady_amplitude_property(zeta, ratio, F0):
    """X k/|F0| = 1/|D| and F_T = |F0|·|1 + 2iζr|/|D| (mpmath), X ≥ 0, φ in (−π, π]."""
    wn = math.sqrt(60.0 / 1.5)
    r = solve_one_text(_problem(zeta, ratio * wn, [], F0=F0))["results"]
    if zeta == 0 and r["r"] == 1.0:
        assert r["X"] is None
        return
    with mp.workdps(30):
        rr = mp.mpf(r["r"])
        D = (1 - rr**2) + 2j * mp.mpf(zeta) * rr
        assert r["magnification"] == pytest.approx(float(1 / abs(D)), rel=1e-13)
        assert r["X"] == pytest.approx(float(abs(mp.mpf(F0)) / 60 / abs(D)), rel=1e-13, abs=1e-300)
        assert r["transmissibility"] == pytest.approx(float(abs(1 + 2j * mp.mpf(zeta) * rr) / abs(D)), rel=1e-13)
        # x_p = X sin(ωt + φ) is F0 Im(e^{iωt}/D)/k: the phase of F0/D
        want = mp.arg(mp.mpf(F0) / D) if F0 != 0 else None
    assert -math.pi <= r["phi"] <= math.pi   # −π only as the rounding of a value just above it
    if want is not None and r["X"] > 0:
        assert math.cos(r["phi"] - float(want)) == pytest.approx(1.0, abs=1e-12)


def test_ode_route_agrees():
    rec = solve_one_text(_problem(0.2, 5.0, [0, 1, 4], extra="accuracy: {method: DOP853, rtol: 1e-10, atol: 1e-12}\n"))
    ref = ref_force([0, 1, 4], m=1.5, k=60.0, zeta=0.2, F0=3.0, Om=5.0, x0=0.01, v0=-0.2)
    _close(rec["results"]["x"], ref, 1e-7)   # DOP853 at rtol 1e-10: a global error well under 1e3·rtol
    assert rec["error_estimate"] < 1e-7


def test_sweep_magnification():
    r = solve_one_text(_problem(0.0, 1.0, [], extra="sweep: {ratio: [0, 2], points: 5}\n"))["results"]
    M = r["sweep_magnification"]
    assert M[2] is None
    assert [M[0], M[1], M[3], M[4]] == pytest.approx([1.0, 1 / 0.75, 1 / 1.25, 1 / 3.0], rel=4e-16)


HEAD = "type: vibration\nm: 1\nk: 1\n"


@pytest.mark.parametrize("text,expected", [
    (HEAD + "base: {amplitude: 0.1, omega: 1}\nforce: {amplitude: 1, omega: 1}\n",
     "force: give either base (base motion) or force (force on the mass), not both"),
    (HEAD + "force: {amplitude: 1, omega: -1}\n", "force.omega: must be >= 0"),
    (HEAD + "force: {amplitude: 1}\n", "force.omega: required field is missing"),
    (HEAD + "force: {amplitude: .nan, omega: 1}\n", "force.amplitude: not a number (NaN)"),
    (HEAD + "force: {amplitude: 1, omega: 1e300}\n", "force.omega: ω/ωₙ must be <= 1e+100"),
    ("type: vibration\nm: 1e-300\nk: 1e-300\nforce: {amplitude: 1e300, omega: 1}\n", "force.amplitude: F0/m overflows"),
    (HEAD + "force: {amplitude: 1, omega: 1, phase: 0}\n", "force.phase: unknown field"),
    (HEAD + "force: {amplitude: \"F**\", omega: 1}\n", "force.amplitude"),
])
def test_invalid_force(text, expected):
    msg = error_of(text)
    assert expected in msg, msg
    assert "Traceback" not in msg and "\n" not in msg.strip()


def test_force_with_base_exit_2_on_the_command_line():
    rc, _, err = run_cli("solve", "-", input=HEAD + "base: {amplitude: 0.1, omega: 1}\nforce: {amplitude: 1, omega: 1}\n")
    assert rc == 2 and "not both" in err and "Traceback" not in err


@pytest.mark.parametrize("ratio,zeta", [(1e-60, 0.3), (1e-60, 1e59), (1e-45, 2.0), (1e90, 0.5), (1e90, 1e95)])
def test_magnification_at_extreme_ratios(ratio, zeta):
    wn = math.sqrt(60.0 / 1.5)
    r = solve_one_text(_problem(zeta, ratio * wn, []))["results"]
    with mp.workdps(40):
        rr, z = mp.mpf(r["r"]), mp.mpf(zeta)
        want = 1 / abs((1 - rr**2) + 2j * z * rr)
    assert r["magnification"] == pytest.approx(float(want), rel=1e-14)
