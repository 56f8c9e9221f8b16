"""Solve cache: one solve per distinct problem, however many answer files."""

from __future__ import annotations

from dyncli.check.paths import available_paths, lookup
from dyncli.check.selfstudy import SelfStudy
from tests.check.helpers import FIX, grade


def test_many_files_one_solve_per_problem():
    c = SelfStudy()
    for i in range(40):
        grade("problem: brake.yaml\nanswers: {find.0.s: 32}\n", name=f"s{i}.yaml", checker=c)
        grade(f"problem: set.yaml\nindex: {i % 2}\nanswers: {{case: 1}}\n", name=f"t{i}.yaml", checker=c)
    assert c.solves == 3   # brake, set #0, set #1


def test_same_problem_by_other_path_or_inline_shares_the_solve(tmp_path):
    c = SelfStudy()
    grade("problem: brake.yaml\nanswers: {find.0.s: 32}\n", checker=c)
    grade("problem: ./../fixtures/brake.yaml\nanswers: {find.0.s: 32}\n", checker=c)
    assert c.solves == 1
    inline = "problem: {type: rectilinear, a: 2, find: [{t: 1}]}\nanswers: {find.0.s: 1}\n"
    for i in range(5):
        assert grade(inline, name=f"i{i}.yaml", checker=c).exit_code == 0
    assert c.solves == 2


def test_params_overrides_are_distinct_problems():
    c = SelfStudy()
    for v0, s in [(20, 15), (30, 25), (20, 15), (40, 35)]:
        r = grade(f"problem: params.yaml\nparams: {{v0: {v0}}}\nanswers: {{find.0.s: {s}}}\n", checker=c)
        assert r.exit_code == 0
    assert c.solves == 3


def test_lookup_and_paths():
    res = {"case": 1, "find": [{"t": 2.0, "s": 32.0}], "vA": [1.0, 2.0, 3.0], "pts": {"A": [0.0, 1.0, 0.0]}}
    assert lookup(res, "find.0.s") == (True, 32.0, "")
    assert lookup(res, "vA.2")[1] == 3.0
    assert lookup(res, "pts.A.1")[1] == 1.0
    assert lookup(res, "find.1.s")[0] is False
    paths = available_paths(res)
    assert {"case", "find", "find.0", "find.0.t", "vA.0", "pts.A", "pts.A.2"} <= set(paths)


def test_fixture_dir_exists():
    assert (FIX / "brake.yaml").exists()
