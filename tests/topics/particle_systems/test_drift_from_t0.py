"""Issue #29, wrong results at exit 0: the balance checks of ``particles``
count from the initial state at t = 0 whatever times ``at`` reports (with
``at: [1, 2]`` T(0) was taken at t = 1: energy_residual 0.0475 J)."""

from __future__ import annotations

import pytest

import dyncli

MOLECULE = {"type": "particles",
            "particles": [{"m": 1, "x": [0, 0, 0], "v": [0, 1, 0]}, {"m": 1, "x": [1.5, 0, 0], "v": [0, 1, 0]}],
            "pairs": [{"between": [0, 1], "kind": "spring", "k": 4, "L": 1}]}
# independent: T0 = ½ Σ m v0² = 1 J and the spring's V(0) = ½ k (1.5 − 1)² = 0.5 J, so T + V = 1.5 J at all times
T0, E = 1.0, 1.5


@pytest.mark.parametrize("at", [[1, 2], [2], [0, 1, 2], [0.5, 3]])
def test_residuals_count_from_t0_whatever_at_reports(at):
    s = dyncli.solve(dict(MOLECULE, at=at))[0]
    T, V, W = s["T_motion"], s["V_internal_motion"], s["W_internal"]
    rtol = s._problem.model.accuracy.rtol
    for t, v, w in zip(T, V, W):
        assert t + v == pytest.approx(E, rel=100 * rtol)          # energy conservation (27.10)
        assert t - T0 == pytest.approx(w, abs=100 * rtol * E)     # W is the work since t = 0
    assert s["energy_residual"] <= 100 * rtol * E
    assert s["G_drift"] <= 1e-12                                  # G = [0, 2, 0] at t = 0 and ever after


def test_residuals_agree_with_and_without_t0_reported():
    a = dyncli.solve(dict(MOLECULE, at=[1, 2]))[0]
    b = dyncli.solve(dict(MOLECULE, at=[0, 1, 2]))[0]
    assert a["energy_residual"] == pytest.approx(b["energy_residual"], abs=1e-9)
