"""The distance quadrature (and the force-field work along a path, the same Gauss–Kronrod runner)
honours the solve's CPU budget (accuracy.max_cpu, default 2 s): a pathological path is refused
with exit 1 naming accuracy.max_cpu, not after the panel budget's minutes.  Not timed: a tiny
max_cpu makes the refusal certain whatever the machine."""

from __future__ import annotations

from tests.conftest import solve_one_text, solve_text

#: a speed with a kink every ~3 ms over 100 s: far more panels than any budget
KINKED = "type: kinematics\nposition: {x1: 'abs(sin(1000*t))', x2: 't'}\ndistance: [0, 100]\n"


def test_kinked_distance_is_refused_by_the_cpu_budget():
    rec = solve_text(KINKED + "accuracy: {max_cpu: 0.001}\n")[0]
    assert rec["exit_code"] == 1
    assert "accuracy.max_cpu" in rec["error"] and "distance" in rec["error"]


def test_distance_within_the_budget_is_answered():
    rec = solve_one_text("type: kinematics\nposition: {x1: 'cos(t)', x2: 'sin(t)'}\ndistance: [0, 6]\n"
                         "accuracy: {max_cpu: 5}\n")
    assert abs(rec["results"]["distance"] - 6.0) < 1e-9


def test_kinked_work_along_a_path_is_refused_by_the_cpu_budget():
    rec = solve_text("type: force-field\nF: [x2, x1, 0]\npoints: [[1, 1, 0]]\n"
                     "path: {x1: 'sqrt(abs(sin(300*t)))', x2: 't', x3: 0, t_span: [0, 100]}\n"
                     "accuracy: {max_cpu: 0.001}\n")[0]
    assert rec["exit_code"] == 1
    assert "accuracy.max_cpu" in rec["error"] and "path" in rec["error"]
