"""Routes and special results: the DOP853 route, no scipy on the closed form,
A/φ where the amplitude–phase form does not exist, undamped sweeps."""

from __future__ import annotations

import math
import subprocess
import sys

import pytest

from tests.conftest import ROOT, solve_one_text
from tests.topics.vibration import notes_formulas as nf
from tests.topics.vibration.reference import max_rel_err, reference

BASE = """type: vibration
m: 1
k: 4
zeta: 0.1
x0: 0.1
v0: 0.3
base: {amplitude: 0.02, omega: 1.5}
at: [0, 0.5, 1, 2, 4, 8]
"""


def test_closed_form_does_not_import_scipy():
    code = (
        "import sys; from tests.conftest import solve_one_text\n"
        f"rec = solve_one_text({BASE + 'sweep: {ratio: [0, 3], points: 7}'!r})\n"
        "assert rec['method'] == 'closed-form'\n"
        "bad = [m for m in sys.modules if m == 'scipy' or m.startswith('scipy.')]\n"
        "assert not bad, bad\n"
    )
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr


@pytest.mark.parametrize("method", ["DOP853", "ode"])
def test_dop853_route(method):
    rec = solve_one_text(BASE + f"accuracy: {{method: {method}, rtol: 1.0e-10, atol: 1.0e-12}}\n")
    assert rec["method"] == "ode:DOP853"
    assert rec["error_estimate"] is not None and 0 <= rec["error_estimate"] < 1e-8
    rx, rv, _ = reference([0, 0.5, 1, 2, 4, 8], m=1, k=4, zeta=0.1, x0=0.1, v0=0.3, s0=0.02, Omega=1.5)
    assert max_rel_err(rec["results"]["x"], rx) < 1e-7
    closed = solve_one_text(BASE)
    # the largest difference of x and of v, each relative to its largest magnitude over the run
    err = 0.0
    for q in ("x", "v"):
        a, b = rec["results"][q], closed["results"][q]
        scale = max(max(abs(c) for c in a), max(abs(c) for c in b))
        err = max(err, max(abs(u - w) for u, w in zip(a, b)) / scale)
    assert err == pytest.approx(rec["error_estimate"], rel=1e-12, abs=1e-300)


def test_dop853_refuses_stiff_problem():
    from tests.conftest import solve_text

    recs = solve_text("type: vibration\nm: 1\nk: 1\nzeta: 1e8\nx0: 1\nat: [0, 10]\naccuracy: {method: DOP853}\n")
    assert recs[0]["exit_code"] == 1
    assert "method: auto" in recs[0]["error"]


def test_overdamped_negative_branch_has_no_nonnegative_amplitude():
    # v0 + ζωw0 < -ω*|w0|: sinh form would need A < 0
    rec = solve_one_text("type: vibration\nm: 1\nk: 1\nzeta: 1.25\nx0: 0.1\nv0: -2\n")
    R = rec["results"]
    assert R["A"] is None and R["phi"] is None
    # w = −A' e^(−ζωt) sinh(ω*t + φ'), A' = √((b/ω*)² − w0²) = √(6.25 − 0.01), tanh φ' = w0 ω*/b
    a = math.sqrt(2.5 ** 2 - 0.1 ** 2)
    ph = math.atanh(0.1 / -2.5)
    assert any(f"−{a:.6g} e^(−ζωₙt) sinh(ω*t − {abs(ph):.6g})" in w for w in rec["warnings"]), rec["warnings"]


def test_overdamped_amplitude_phase_from_notes():
    rec = solve_one_text("type: vibration\nm: 2\nk: 8\nzeta: 3\nx0: -0.2\nv0: 5\n")
    A, phi = nf.free_A_phi(-0.2, 5.0, 2.0, 3.0)
    assert rec["results"]["A"] == pytest.approx(float(A), rel=1e-14)
    assert rec["results"]["phi"] == pytest.approx(float(phi), rel=1e-14)


def test_at_rest_phase_null():
    rec = solve_one_text("type: vibration\nm: 1\nk: 1\nzeta: 0.3\n")
    assert rec["results"]["A"] == 0.0 and rec["results"]["phi"] is None
    assert rec["warnings"]


def test_free_phase_on_negative_axis_is_plus_pi():
    # w0 = 0, v0 < 0: sin φ = 0, cos φ = -1 -> φ = π (not -π)
    rec = solve_one_text("type: vibration\nm: 1\nk: 1\nx0: 0\nv0: -1\n")
    assert rec["results"]["phi"] == math.pi
    assert rec["results"]["A"] == 1.0


def test_undamped_sweep_through_resonance():
    rec = solve_one_text("type: vibration\nm: 1\nk: 1\nsweep: {ratio: [0, 2], points: 5}\n")
    R = rec["results"]
    assert R["sweep_r"] == [0.0, 0.5, 1.0, 1.5, 2.0]
    assert R["sweep_G"][2] is None and R["sweep_g"][2] is None
    assert R["sweep_G"][1] == pytest.approx(1 / 3, rel=1e-15)
    assert R["sweep_Phi"][3] == math.pi and R["sweep_Phi"][1] == 0.0
    assert R["peak_G"] is None and R["peak_g"] is None
    assert any("r = 1" in w for w in rec["warnings"])


def test_heavily_damped_sweep_has_no_G_peak():
    rec = solve_one_text("type: vibration\nm: 1\nk: 1\nzeta: 0.8\nsweep: {ratio: [0.1, 10], points: 20, spacing: log}\n")
    R = rec["results"]
    assert R["peak_G"] is None and R["peak_G_r"] is None
    assert R["peak_g"] is not None
    assert R["sweep_r"][0] == 0.1 and R["sweep_r"][-1] == 10.0
    assert R["sweep_r"][10] == pytest.approx(0.1 * 100 ** (10 / 19), rel=1e-14)
    rg, gm = nf.peak(nf.g_of(0.8), 0.1, 1.0)
    assert R["peak_g_r"] == pytest.approx(float(rg), rel=1e-13)
    assert R["peak_g"] == pytest.approx(float(gm), rel=1e-14)


def test_c_gives_zeta_and_symbols_units_render(cli):
    rec = solve_one_text("type: vibration\nm: 2\nk: 50\nc: 4\n")
    assert rec["results"]["zeta"] == pytest.approx(4 / (2 * math.sqrt(100)), rel=1e-15)
    rc, out, err = cli("solve", "problems/vibration/base-excitation.yaml")
    assert rc == 0, err
    for s in ("ωₙ", "ζ", "ω*", "Φ", "rad/s", "N·s/m"):
        assert s in out


def test_dop853_route_keeps_request_order_with_duplicates():
    text = "type: vibration\nm: 1\nk: 1\nzeta: 0.1\nx0: 1\nat: [1, 0, 1, 0.5]\n"
    ode = solve_one_text(text + "accuracy: {method: DOP853}\n")["results"]["x"]
    exact = solve_one_text(text)["results"]["x"]
    assert ode[0] == ode[2] and ode[1] == 1.0
    assert ode == pytest.approx(exact, rel=1e-8)


def test_unrepresentable_time_is_a_numerical_error():
    from tests.conftest import solve_text

    rec = solve_text("type: vibration\nm: 1\nk: 10000\nx0: 1\nat: [1e307]\n")[0]
    assert rec["exit_code"] == 1 and "not representable" in rec["error"]
