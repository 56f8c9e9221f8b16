"""The distance quadrature (and the force-field work along a path, the same Gauss–Kronrod runner)
honours the solve's CPU budget (accuracy.max_cpu, default 2 s): a pathological path is refused
with exit 1 naming accuracy.max_cpu, not after the panel budget's minutes.  Not timed: a tiny
max_cpu makes the refusal certain whatever the machine."""

from __future__ import annotations

import pytest

from tests.conftest import ROOT, solve_one_text, solve_text

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


@pytest.mark.parametrize("type_, text", [
    ("kinematics", "type: kinematics\ncoordinates: spherical\nposition: {R: '2 + 0.5*sin(t)', theta: '0.3*t', "
                   "phi: '0.1*t'}\nat: [1]\n"),
    ("rotating-frame", "type: rotating-frame\nomega: [0, 0, '2*t']\np: ['t**2', 0, 0]\nat: [1]\n"),
])
def test_symbolic_table_beyond_its_cpu_limit_is_left_out_with_a_warning(monkeypatch, type_, text):
    """--symbolic's sympy work is bounded (dyncli.cputime.limit): beyond it the formula table is left
    out with one warning, the numeric results stay (forced here by a limit that has already expired)."""
    import contextlib

    from dyncli import cputime
    from dyncli.loader import split_problems, validate
    from dyncli.registry import solver
    from dyncli.result import SolveOptions

    @contextlib.contextmanager
    def expired(seconds):
        raise cputime.CpuTimeout(f"more than {seconds:g} s of CPU")
        yield

    monkeypatch.setattr(cputime, "limit", expired)
    (lp,), _ = split_problems("s.yaml", text.encode(), ROOT)
    validate(lp)
    plain = solver(type_)(lp.model, SolveOptions())
    res = solver(type_)(lp.model, SolveOptions(symbolic=True))
    assert [w for w in res.warnings if "--symbolic" in w and "CPU" in w]
    assert len(res.views) == len(plain.views)          # the numeric tables only
    assert res.results == plain.results
