"""Every file of ``problems/`` gives the results recorded in ``tests/data/baseline-results.json``
(recorded from ``main`` before the refactors of issue #19) within the route's tolerance: a closed
form to 1e-13 of each quantity's scale, a numerical route to 100 × (rtol·scale + atol). See
``tests/tools/baseline.py`` for the rule and for how to re-record after an intended change."""

from __future__ import annotations

import pytest

from tests.tools import baseline

BASE = baseline.load()


def test_every_problem_file_is_recorded():
    files = {p.relative_to(baseline.ROOT).as_posix() for p in baseline.problem_files()}
    missing = sorted(files - BASE.keys())
    assert not missing, (f"no baseline for {missing}; record only those with "
                         "`python -m tests.tools.baseline add TYPE` (a new type's examples) or `add FILE`")


@pytest.mark.parametrize("name", sorted(BASE))
def test_results_match_baseline(name):
    path = baseline.ROOT / name
    if not path.exists():
        pytest.skip(f"{name} no longer in problems/")
    old, new = BASE[name], baseline.record_file(path)
    assert len(new) == len(old), f"{name}: {len(new)} problems, baseline has {len(old)}"
    diffs = [d for o, n in zip(old, new) for d in baseline.compare(o, n)]
    assert not diffs, ("\n".join(diffs[:20]) + "\n(an intended change of results: re-record with "
                       "`python -m tests.tools.baseline record` and say why in the commit)")


def test_add_type_records_only_that_types_files(tmp_path, monkeypatch):
    """``add TYPE`` solves and records the type's example files and leaves every other entry as it
    was (the tool never re-records what it holds)."""
    files = baseline.type_files("pendulum")
    assert files and files[0] == "problems/particle/pendulum.yaml"
    before = {k: v for k, v in BASE.items() if k not in files}
    path = tmp_path / "baseline.json"
    path.write_text(__import__("json").dumps(before))
    monkeypatch.setattr(baseline, "BASELINE", path)
    assert baseline.add(baseline.expand(["pendulum"])) == files
    after = baseline.load()
    assert {k: v for k, v in after.items() if k not in files} == before
    with pytest.raises(SystemExit, match="already recorded"):
        baseline.add(baseline.expand(["pendulum"]))
