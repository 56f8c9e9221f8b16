"""The particle's error_estimate is honest and relative (the runner's policy, docs/accuracy.md).

* ``accuracy.estimate: true``: a check solve at rtol/100 (ode.check_solve); the estimate is the
  largest difference of every reported quantity (x, v, a, T, V, E, W_nc, H_O), each relative to
  its own scale over the run, so estimate / true relative error stays near 1 (the check run's
  own error is 1/100 of the reported run's: 0.99-1.01 in exact arithmetic; 0.5-2 is asserted).
* default (``estimate: false``): no second solve; the nominal estimate max(rtol, relative
  energy residual) — except under an inverse-square force (an orbit, whose phase error the
  nominal estimate misses): there every run is checked and the estimate is 2 x the difference
  (runner.solve_to_promise; the eccentric orbits are in test_kepler.py).

True errors from closed forms (harmonic oscillator, circular Kepler orbit), never from the code."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dyncli import ode
from tests.conftest import solve_one_text

TIMES = [0, 1, 2.5, 5, 10]
QUANTITIES = ("x", "v", "a", "T", "V", "E", "W_nc", "H_O")

# harmonic oscillator: m = 2, k = 8 (w = 2), x0 = [1, 0, 0.5], v0 = [0, 3, 0]
SHO = ("type: particle\nm: 2\nx0: [1, 0, 0.5]\nv0: [0, 3, 0]\nforces: [{kind: spring, k: 8}]\n"
       f"at: {TIMES}\n")


def _sho(t):
    m, k = 2.0, 8.0
    c, s = math.cos(2 * t), math.sin(2 * t)
    x = np.array([c, 1.5 * s, 0.5 * c])
    v = np.array([-2 * s, 3 * c, -s])
    return {"x": x, "v": v, "a": -4 * x, "T": 0.5 * m * v @ v, "V": 0.5 * k * x @ x,
            "E": 0.5 * m * 9 + 0.5 * k * 1.25, "W_nc": 0.0, "H_O": m * np.cross(x, v)}


# circular orbit of radius R about the centre of an inverse-square field: mu = g R0²
M, R, MU = 1000.0, 7.0e6, 9.81 * 6371000.0 ** 2
VC = math.sqrt(MU / R)
KEPLER = (f"type: particle\nm: {M!r}\nx0: [{R!r}, 0, 0]\nv0: [0, {VC!r}, 0]\n"
          f"forces: [{{kind: inverse-square, R0: 6371000}}]\nat: {[t * 1200 for t in TIMES]}\n")


def _kepler(t):
    n = VC / R
    c, s = math.cos(n * t), math.sin(n * t)
    x, v = R * np.array([c, s, 0.0]), VC * np.array([-s, c, 0.0])
    T, V = 0.5 * M * VC ** 2, -M * MU / R
    return {"x": x, "v": v, "a": -MU / R ** 3 * x, "T": T, "V": V, "E": T + V, "W_nc": 0.0,
            "H_O": np.array([0.0, 0.0, M * R * VC])}


def true_relative_error(rec, exact, times) -> float:
    """The largest error of every reported quantity, each relative to its exact scale over the run."""
    worst = 0.0
    for q in QUANTITIES:
        got = np.array(rec["results"][q], float)
        ref = np.array([np.broadcast_to(exact(t)[q], np.shape(got[0])) for t in times], float)
        scale = float(np.max(np.abs(ref)))
        if scale > 0:
            worst = max(worst, float(np.max(np.abs(got - ref))) / scale)
    return worst


CASES = [("harmonic-oscillator", SHO, _sho, TIMES, 1e-3, ""),
         ("kepler-circular", KEPLER, _kepler, [t * 1200 for t in TIMES], 1e4, ", method: DOP853")]


@pytest.mark.parametrize("rtol", [1e-6, 1e-8, 1e-10])
@pytest.mark.parametrize("name,text,exact,times,atol_factor,method", CASES)
def test_measured_estimate_over_true_relative_error_is_near_one(name, text, exact, times, atol_factor, method, rtol):
    rec = solve_one_text(text + f"accuracy: {{rtol: {rtol!r}, atol: {rtol * atol_factor!r}, estimate: true{method}}}\n")
    assert rec.get("error") is None, rec.get("error")
    true = true_relative_error(rec, exact, times)
    est = rec["error_estimate"]
    assert est is not None
    # an orbit reports 2 x the difference (1.0-1.01 x the error in exact arithmetic)
    lo, hi = (1.0, 4.0) if method else (0.5, 2.0)
    assert lo <= est / true <= hi, (name, rtol, est, true)


@pytest.mark.parametrize("rtol", [1e-6, 1e-8, 1e-10])
def test_an_orbit_by_default_is_checked_and_its_estimate_bounds(rtol):
    rec = solve_one_text(KEPLER + f"accuracy: {{rtol: {rtol!r}, atol: {rtol * 1e4!r}, method: DOP853}}\n")
    true = true_relative_error(rec, _kepler, [t * 1200 for t in TIMES])
    assert true <= rec["error_estimate"] <= 4 * true
    assert true <= 100 * rtol


@pytest.mark.parametrize("name,text,exact,times,atol_factor,method", CASES[:1])
def test_default_is_nominal_without_a_second_solve(name, text, exact, times, atol_factor, method, monkeypatch):
    from dyncli.topics.particle import solver

    calls = []
    real = solver.integrate
    monkeypatch.setattr(solver, "integrate", lambda *a, **k: calls.append(1) or real(*a, **k))
    rec = solve_one_text(text + f"accuracy: {{rtol: 1.0e-8, atol: {1e-8 * atol_factor!r}}}\n")
    assert len(calls) == 1                      # no check solve
    r = rec["results"]
    E1 = exact(0)["E"]
    drift = r["energy_residual"] / max(abs(E1), max(abs(v) for q in ("T", "V", "W_nc") for v in r[q]))
    # the nominal bound: rtol x the accepted steps, or the energy's relative drift when larger
    assert rec["error_estimate"] >= max(1e-8, drift)
    assert rec["error_estimate"] >= true_relative_error(rec, exact, times)


def test_estimate_true_and_default_answers_agree():
    a = solve_one_text(SHO + "accuracy: {rtol: 1.0e-8}\n")
    b = solve_one_text(SHO + "accuracy: {rtol: 1.0e-8, estimate: true}\n")
    assert a["results"] == b["results"]        # the check solve changes only error_estimate
    assert a["error_estimate"] >= 1e-8 and 0 < b["error_estimate"] < 1e-6


def test_check_solve_over_the_budget_falls_back_to_a_looser_run():
    # the main run fits in max_steps, the 100x tighter one does not: the runner's one fallback,
    # a check run at 10 x rtol, whose difference bounds the reported run's error from above
    text = SHO.replace("at: [0, 1, 2.5, 5, 10]", "t_end: 60") + "accuracy: {rtol: 1.0e-10, max_steps: 520, estimate: true}\n"
    rec = solve_one_text(text)
    assert rec.get("error") is None, rec.get("error")
    assert any(ode.fallback_warning(ode.CHECK_DIV) == w for w in rec["warnings"])
    true = true_relative_error(rec, _sho, [0.0, 60.0])
    assert rec["error_estimate"] >= true
    assert rec["results"]["x"][-1][0] == pytest.approx(math.cos(120), abs=1e-6)
