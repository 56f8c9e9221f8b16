"""The particle's integration budget (accuracy.max_steps) and fail-fast checks:
a run that needs too many steps is refused early with exit 1 and the message
of dyncli/ode.py; a non-finite force is exit 1 at once; an overflowing field
strength is exit 2."""

from __future__ import annotations

from tests.conftest import solve_text

LONG_DRAG = ("type: particle\nm: 0.5\nx0: [2.0, 0, -1.0]\nv0: [20, 0, 20]\n"
             "forces: [{kind: gravity}, {kind: drag, c: 0.005, power: 2}]\nt_end: 3.0e+8\nat: [0, 1, 2, 3]\n")


def _one(text):
    (rec,) = solve_text(text)
    return rec


def test_max_steps_is_honoured_with_the_budget_message():
    rec = _one("type: particle\nm: 1\nv0: [1, 0, 0]\nforces: [{kind: spring, k: 100}]\nt_end: 100\n"
               "accuracy: {max_steps: 200}\n")
    assert rec["exit_code"] == 1
    assert "more than the budget of 200" in rec["error"]
    assert "shorten the time span, loosen accuracy.rtol, or raise accuracy.max_steps" in rec["error"]
    # the same problem within a larger budget is solved
    rec = _one("type: particle\nm: 1\nv0: [1, 0, 0]\nforces: [{kind: spring, k: 100}]\nt_end: 100\n"
               "accuracy: {max_steps: 20000}\n")
    assert rec.get("error") is None and rec["method"] == "ode:DOP853"


def test_budget_counts_the_steps_of_every_friction_phase():
    # a lightly damped block on a rough floor: hundreds of phases, each a few steps
    text = ("type: particle\nm: 1\nv0: [1, 0, 0.2]\nforces: [{kind: spring, k: 1}, {kind: friction, mu: 0.0001, N: 1}]\n"
            "t_end: 3000\n")
    rec = _one(text + "accuracy: {max_steps: 1000}\n")
    assert rec["exit_code"] == 1 and "more than the budget of 1000" in rec["error"]


def test_stiff_run_with_dop853_suggests_lsoda():
    rec = _one(LONG_DRAG + "accuracy: {method: DOP853}\n")
    assert rec["exit_code"] == 1
    assert "stiff" in rec["error"] and "accuracy.method: LSODA" in rec["error"]


def test_stiff_run_with_auto_switches_to_lsoda():
    rec = _one(LONG_DRAG)
    assert rec.get("error") is None, rec.get("error")
    assert rec["method"] == "ode:LSODA"
    assert any("integrated with LSODA" in w for w in rec["warnings"])
    # the early motion agrees with a DOP853 run over the first 3 s
    ref = _one(LONG_DRAG.replace("t_end: 3.0e+8", "t_end: 3"))
    for x, xr in zip(rec["results"]["x"], ref["results"]["x"]):
        assert max(abs(a - b) for a, b in zip(x, xr)) < 1e-6


def test_fast_gyration_is_refused_with_its_time_scale():
    rec = _one("type: particle\nm: 1\nv0: [1, 0, 0.2]\nforces:\n- kind: custom\n  F: [1e150*v2, -1e150*v1, '0']\n"
               "at: [0, 1, 2]\n")
    assert rec["exit_code"] == 1
    assert "more than the budget" in rec["error"] and "time scale of about 1e-150 s" in rec["error"]


def test_non_finite_custom_force_names_time_and_position():
    # sqrt of a negative number once x1 > 1.5 (at t ~ 0.5): NaN
    rec = _one("type: particle\nm: 1\nx0: [1, 2, 3]\nv0: [1, 0, 0.2]\nforces:\n- kind: custom\n"
               "  F: [0, 'sqrt(1.5 - x1)', '0']\nat: [0, 1]\n")
    assert rec["exit_code"] == 1
    assert "not finite" in rec["error"] and "t = 0.5" in rec["error"] and "x = [1.5" in rec["error"]
    rec = _one("type: particle\nm: 1\nv0: [1, 0, 0.2]\nforces:\n- kind: custom\n  F: [v2, t/0, '0']\nat: [0, 1, 2]\n")
    assert rec["exit_code"] == 1 and "not finite (inf or NaN) at t = 0 s, x = [0, 0, 0] m" in rec["error"]


def test_overflowing_inverse_square_strength_is_invalid_input():
    rec = _one("type: particle\nm: 1000\nx0: [7000000, 0, 0]\nv0: [0, 14000.0, 3000]\n"
               "forces: [{kind: inverse-square, center: [0, 0, 0], R0: 6.371e+156}]\nt_end: 1000\n")
    assert rec["exit_code"] == 2
    assert "forces.0.R0" in rec["error"] and "overflows" in rec["error"]
