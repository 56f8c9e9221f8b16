"""Rotating unbalance `unbalance: {m0, e, omega}` (issue 27): F = m0 e ω² sin(ωt) on the mass.
References: the hand derivation X = m0 e r²/(m √((1 − r²)² + (2ζr)²)) (mpmath), the total
response from scratch (tests/topics/vibration/test_force.ref_force, 50 digits, with
F0 = m0 e ω²), and the same problem written as a `force` (a second input route)."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path
from tests.topics.vibration.test_force import _close, ref_force


def test_gallery_rotating_unbalance_by_hand():
    above, resonant = solve_path(PROBLEMS / "vibration/rotating-unbalance.yaml")
    r = above["results"]
    m, m0, e, w, zeta = 40.0, 0.5, 0.02, 100.0, 0.1
    rr = w / 50.0
    D = math.hypot(1 - rr * rr, 2 * zeta * rr)
    assert r["r"] == 2.0 and r["F0"] == pytest.approx(m0 * e * w * w, rel=4e-16)
    assert r["X"] == pytest.approx(m0 * e * rr * rr / (m * D), rel=4e-16)
    assert r["phi"] == pytest.approx(-math.atan2(2 * zeta * rr, 1 - rr * rr), rel=4e-16)
    assert r["F_T"] == pytest.approx(m0 * e * w * w * math.hypot(1, 2 * zeta * rr) / D, rel=4e-16)
    s = resonant["results"]
    assert s["r"] == 1.0 and s["X"] == pytest.approx(m0 * e / (2 * zeta * m), rel=4e-16)   # r = 1
    assert s["phi"] == pytest.approx(-math.pi / 2, rel=4e-16)
    times = [0, 0.05, 0.2, 1]
    _close(s["x"], ref_force(times, m=m, k=1e5, zeta=zeta, F0=m0 * e * 50.0 ** 2, Om=50.0), 1e-13)


def _problem(zeta, w, times, m=1.5, k=60.0, m0=0.1, e=0.05, x0=0.01, v0=-0.2, extra=""):
    return (f"type: vibration\nm: {m!r}\nk: {k!r}\nzeta: {zeta!r}\nx0: {x0!r}\nv0: {v0!r}\n"
            f"unbalance: {{m0: {m0!r}, e: {e!r}, omega: {w!r}}}\nat: {list(times)!r}\n{extra}")


@pytest.mark.parametrize("zeta", [0.0, 0.05, 1.0, 3.0])
@pytest.mark.parametrize("ratio", [0.0, 0.4, 1.0, 2.5, 20.0])
def test_steady_amplitude_and_response_against_mpmath(zeta, ratio):
    wn = math.sqrt(60.0 / 1.5)
    w = ratio * wn
    times = [0, 0.1, 0.9, 4.0]
    rec = solve_one_text(_problem(zeta, w, times))
    r = rec["results"]
    with mp.workdps(30):
        rr, z = mp.mpf(r["r"]), mp.mpf(zeta)
        den = mp.sqrt((1 - rr**2) ** 2 + (2 * z * rr) ** 2)
        X = mp.mpf("0.1") * mp.mpf("0.05") * rr**2 / (mp.mpf("1.5") * den) if den else None
    if X is None:
        assert r["X"] is None and any("undamped resonance" in x for x in rec["warnings"])
    else:
        assert r["X"] == pytest.approx(float(X), rel=1e-13, abs=1e-300)
    # the total response: ωt ≤ 260 here, cancellation-free closed form
    ref = ref_force(times, m=1.5, k=60.0, zeta=zeta, F0=0.1 * 0.05 * w * w, Om=w, x0=0.01, v0=-0.2)
    _close(r["x"], ref, 1e-12)


def test_same_as_the_force_it_makes():
    w = 9.0
    u = solve_one_text(_problem(0.2, w, [0.3, 2.0], extra="sweep: {ratio: [0.5, 2], points: 4}\n"))["results"]
    f = solve_one_text(_problem(0.2, w, [0.3, 2.0], extra="sweep: {ratio: [0.5, 2], points: 4}\n")
                       .replace("unbalance: {m0: 0.1, e: 0.05, omega: 9.0}",
                                f"force: {{amplitude: {0.1 * 0.05 * w * w!r}, omega: 9.0}}"))["results"]
    assert set(u) == set(f) | {"F0"}
    for k in f:
        assert u[k] == f[k], k


def test_ode_route_agrees():
    rec = solve_one_text(_problem(0.2, 5.0, [0, 1, 4],
                                  extra="accuracy: {method: DOP853, rtol: 1e-10, atol: 1e-12}\n"))
    ref = ref_force([0, 1, 4], m=1.5, k=60.0, zeta=0.2, F0=0.1 * 0.05 * 25.0, Om=5.0, x0=0.01, v0=-0.2)
    _close(rec["results"]["x"], ref, 1e-7)      # DOP853 at rtol 1e-10: a global error well under 1e3·rtol


HEAD = "type: vibration\nm: 1\nk: 1\n"


@pytest.mark.parametrize("text,expected", [
    (HEAD + "base: {amplitude: 0.1, omega: 1}\nunbalance: {m0: 0.1, e: 0.1, omega: 1}\n",
     "unbalance: give one excitation: unbalance (a rotating unbalance) or base, not both"),
    (HEAD + "force: {amplitude: 1, omega: 1}\nunbalance: {m0: 0.1, e: 0.1, omega: 1}\n",
     "unbalance: give one excitation: unbalance (a rotating unbalance) or force, not both"),
    (HEAD + "unbalance: {m0: 2, e: 0.1, omega: 1}\n", "unbalance.m0: m0 = 2 kg exceeds m = 1 kg"),
    (HEAD + "unbalance: {m0: 0.1, e: -0.1, omega: 1}\n", "unbalance.e: must be > 0"),
    (HEAD + "unbalance: {m0: 0.1, e: 0.1, omega: -1}\n", "unbalance.omega: must be >= 0"),
    (HEAD + "unbalance: {m0: 0.1, e: 0.1}\n", "unbalance.omega: required field is missing"),
    (HEAD + "unbalance: {m0: 0.1, e: 0.1, omega: 1e300}\n", "unbalance.omega: ω/ωₙ must be <= 1e+100"),
    (HEAD + "unbalance: {m0: 0.1, e: 1e300, omega: 1e90}\n", "unbalance: m0·e·ω²/m overflows"),
    (HEAD + "unbalance: {m0: 0.1, e: 0.1, omega: 1, phase: 0}\n", "unbalance.phase: unknown field"),
])
def test_invalid_unbalance(text, expected):
    msg = error_of(text)
    assert expected in msg, msg
    assert "Traceback" not in msg and "\n" not in msg.strip()


@pytest.mark.parametrize("excitation", ["unbalance: {m0: 0.1, e: 0.05, omega: 9.0}",
                                        "force: {amplitude: 0.405, omega: 9.0}"])
def test_plot_draws_the_forced_response(tmp_path, excitation):
    """The x(t) panel is the forced total response (it was the free vibration for `force`), and a
    sweep with a force is drawn (it failed on the missing base)."""
    import numpy as np

    from tests.plots.util import Fig, line, panels, render_both, solved_text

    text = _problem(0.1, 9.0, [0.5, 1.5], extra="sweep: {ratio: [0, 3], points: 7}\n")
    text = text.replace("unbalance: {m0: 0.1, e: 0.05, omega: 9.0}", excitation)
    pans = panels(solved_text(text))
    assert len(pans) == 2
    render_both(tmp_path, pans)
    ref = ref_force([0.5, 1.5], m=1.5, k=60.0, zeta=0.1, F0=0.405, Om=9.0, x0=0.01, v0=-0.2)
    with Fig(pans[:1]) as f:
        (ax,) = f.axes
        assert "excited" in ax.get_title() or "unbalance" in ax.get_title()
        t, x = (np.asarray(a, float) for a in (line(ax, "x(t)").get_xdata(), line(ax, "x(t)").get_ydata()))
        for tt, want in zip([0.5, 1.5], ref):
            assert float(np.interp(tt, t, x)) == pytest.approx(float(want), abs=2e-3 * max(abs(float(r)) for r in ref))


def test_find_and_distance_follow_the_unbalance():
    """find and distance (§11) answer on the unbalance-excited motion: the same answers as the
    force m0 e ω² it makes, and x at the answered time is the mpmath response there."""
    extra = "find: [{max: x, within: [0, 3]}, {when: {v: 0}, occurrence: 2}]\n"
    u = solve_one_text(_problem(0.05, 6.0, [1.0, 2.0], extra=extra))["results"]
    f = solve_one_text(_problem(0.05, 6.0, [1.0, 2.0], extra=extra).replace(
        "unbalance: {m0: 0.1, e: 0.05, omega: 6.0}", f"force: {{amplitude: {0.1 * 0.05 * 36.0!r}, omega: 6.0}}"))["results"]
    assert u["find"] == f["find"] and u["distance"] == f["distance"]
    t_max = u["find"][0]["t"]
    (ref,) = ref_force([t_max], m=1.5, k=60.0, zeta=0.05, F0=0.1 * 0.05 * 36.0, Om=6.0, x0=0.01, v0=-0.2)
    assert u["find"][0]["x"] == pytest.approx(float(ref), abs=1e-12)
