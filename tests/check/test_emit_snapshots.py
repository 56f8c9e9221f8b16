"""Every ``dyncli check`` format, fed by the same fixtures in both modes
(self-study answer files and graded work), against reviewed snapshots.

The fixtures (tests/check/emitdata/) hold every status of each mode: a
correct answer, slips with and without partial credit, a carried answer,
a missing, an unreadable and an unknown answer, a wrong dimension, a
problem that cannot be read and an invalid file.  Each snapshot
(tests/check/snapshots/MODE-FORMAT[-reveal].txt) holds the exit code,
stdout, stderr and, for ``github``, the step summary: what a user sees.

After a deliberate change of an output, rewrite the snapshots with
``DYNCLI_UPDATE_SNAPSHOTS=1 pytest tests/check/test_emit_snapshots.py``
and review the diff before committing it.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
DATA = HERE / "emitdata"
SNAPSHOTS = HERE / "snapshots"

STUDY = ["study.yaml", "broken.yaml"]
SUBMISSIONS = ["ann.yaml", "ben.yaml", "cy.yaml"]
MODES = {
    "study": ("table", "json", "junit", "github", "gradescope"),
    "key": ("table", "json", "junit", "github", "gradescope", "csv"),
}
CASES = [(mode, fmt, reveal) for mode, fmts in MODES.items() for fmt in fmts for reveal in (False, True)]


def _run(mode: str, fmt: str, reveal: bool, capsys, monkeypatch, tmp_path) -> str:
    monkeypatch.chdir(DATA)
    monkeypatch.setenv("COLUMNS", "200")
    summary = tmp_path / "summary.md"
    monkeypatch.setenv("GITHUB_STEP_SUMMARY", str(summary))
    capsys.readouterr()
    if mode == "study":
        from dyncli.check.command import run_check

        argv = STUDY
        code = run_check(list(STUDY), fmt, reveal)
    else:
        from dyncli.check.keycommand import run_key_check

        argv = ["--key", "key.yaml"] + SUBMISSIONS
        code = run_key_check("key.yaml", list(SUBMISSIONS), fmt, reveal)
    out, err = capsys.readouterr()
    cmd = " ".join(["dyncli check"] + argv + ["--format", fmt] + (["--reveal"] if reveal else []))
    text = f"$ {cmd}\nexit code: {code}\n--- stdout\n{out}--- stderr\n{err}"
    if summary.exists():
        text += f"--- $GITHUB_STEP_SUMMARY\n{summary.read_text(encoding='utf-8')}"
    return text


@pytest.mark.parametrize("mode,fmt,reveal", CASES, ids=[f"{m}-{f}{'-reveal' if r else ''}" for m, f, r in CASES])
def test_format_matches_snapshot(mode, fmt, reveal, capsys, monkeypatch, tmp_path):
    got = _run(mode, fmt, reveal, capsys, monkeypatch, tmp_path)
    path = SNAPSHOTS / f"{mode}-{fmt}{'-reveal' if reveal else ''}.txt"
    if os.environ.get("DYNCLI_UPDATE_SNAPSHOTS"):
        SNAPSHOTS.mkdir(exist_ok=True)
        path.write_text(got, encoding="utf-8")
    assert path.exists(), f"no snapshot {path.name}: run with DYNCLI_UPDATE_SNAPSHOTS=1 and review it"
    assert got == path.read_text(encoding="utf-8"), f"{path.name} differs (DYNCLI_UPDATE_SNAPSHOTS=1 rewrites it)"


def test_every_format_has_a_snapshot_in_both_modes():
    """The same formats in both modes (csv, the gradebook, is graded work only)."""
    from dyncli.cli import CheckFormat

    formats = {f.value for f in CheckFormat}
    assert set(MODES["key"]) == formats
    assert set(MODES["study"]) == formats - {"csv"}


def test_both_modes_grade_alike(monkeypatch):
    """One grader: the same answers to the same problems get the same status,
    points, diagnosis and feedback as graded work and as self-study."""
    from dyncli.check.keycommand import grade_all, load_key
    from dyncli.check.selfstudy import SelfStudy

    monkeypatch.chdir(DATA)
    key, files = load_key("same-key.yaml", None)
    graded = grade_all(key, files, ["same-sub.yaml"]).submissions[0].questions
    study = SelfStudy().check_paths(["same-study.yaml"]).submissions[0].questions
    by_path = {(q.title, q.answer): q for q in study}
    assert len(graded) == len(study) == 4
    for g in graded:
        s = by_path[(g.title, g.answer)]
        assert (s.status, s.score, s.points, s.diagnosis, s.message, s.rel_error) == \
            (g.status, g.score, g.points, g.diagnosis, g.message, g.rel_error), g.id
    assert [q.status for q in graded] == ["wrong", "correct", "wrong", "invalid"]
    assert [q.diagnosis for q in graded][:3] == ["sign", None, "power_of_ten"]


def test_github_lists_the_annotations_beyond_ten_alike_in_both_modes(monkeypatch, tmp_path):
    """GitHub shows 10 error annotations per step: the rest go to one notice,
    one line each, in both modes."""
    from dyncli.check.emit import github
    from dyncli.check.keycommand import grade_all, load_key
    from dyncli.check.selfstudy import SelfStudy

    monkeypatch.chdir(DATA)
    key, files = load_key("same-key.yaml", None)
    subs = []
    for i in range(4):                      # 3 annotations each: 12
        p = tmp_path / f"s{i}.yaml"
        p.write_text((DATA / "same-sub.yaml").read_text(encoding="utf-8"), encoding="utf-8")
        subs.append(str(p))
    graded = github.render(grade_all(key, files, subs)).splitlines()
    study = github.render(SelfStudy().check_paths(["same-study.yaml"] * 4)).splitlines()
    for lines in (graded, study):
        assert sum(line.startswith("::error ") for line in lines) == 10
        more = [line for line in lines if line.startswith("::notice title=dyncli check%3A 2 more::")]
        assert len(more) == 1 and more[0].count("%0A") == 2 and "(GitHub shows at most 10" in more[0], more
