"""A Kepler orbit read at long times: the mean anomaly n·t carries n's rounding (and mu's) once per
revolution, which error_estimate counts (kepler_estimate); past 1e-6 of the motion a warning says
so — the gallery's orbits over a revolution or a few are not warned."""

from __future__ import annotations

from tests.conftest import ROOT, solve_one_text


def _text(at: str) -> str:
    lines = (ROOT / "problems/particle/satellite-inverse-square.yaml").read_text().splitlines()
    return "\n".join([ln for ln in lines if not ln.startswith(("at:", "t_end:"))] + [f"at: [{at}]", ""])


def _lost(rec):
    return [w for w in rec.get("warnings", []) if "phase" in w and "smaller t" in w]


def test_a_revolution_is_not_warned():
    rec = solve_one_text(_text("0, period/2, period, 10*period"))
    assert rec["method"] == "exact" and _lost(rec) == []


def test_ten_billion_revolutions_are_warned():
    rec = solve_one_text(_text("0, 1e6, 1e10, 1e14"))
    warned = _lost(rec)
    assert len(warned) == 1 and warned[0].startswith("the state at t = 1e+14 s has a phase error up to")
    assert rec["error_estimate"] > 1e-6
