"""The gallery (problems/): every problem file solves, says where it comes
from, and is verified by a test.

The values themselves are checked by the topic tests (tests/<topic>/) and by
tests/docs/test_gallery_values.py against independently derived references;
here: every file solves without an error, begins with a comment naming the
section of the notes, and is named by at least one test module.
"""

from __future__ import annotations

import pytest

from tests.conftest import ROOT, solve_path
from tests.docs.util import problem_files

FILES = problem_files()


@pytest.mark.parametrize("path", FILES)
def test_gallery_file_solves(path):
    recs = solve_path(ROOT / path)
    assert recs
    for rec in recs:
        assert rec.get("error") is None, f"{path} #{rec.get('index')}: {rec.get('error')}"
        assert rec["results"] is not None


@pytest.mark.parametrize("path", FILES)
def test_gallery_file_names_its_section(path):
    lines = (ROOT / path).read_text(encoding="utf-8").splitlines()
    header = []
    for ln in lines:
        if not ln.startswith("#"):
            break
        header.append(ln)
    assert header, f"{path}: no header comment"
    assert "§" in "\n".join(header), f"{path}: the header comment does not name the section of the notes (§N)"


def _test_sources() -> str:
    me = ROOT / "tests" / "docs" / "test_gallery.py"
    return "\n".join(p.read_text(encoding="utf-8") for p in (ROOT / "tests").rglob("*.py") if p != me)


def test_every_gallery_file_is_checked_by_a_test():
    src = _test_sources()
    missing = []
    for path in FILES:
        name = path.rsplit("/", 1)[-1]
        if name not in src and name.removesuffix(".yaml") not in src:
            missing.append(path)
    assert not missing, "gallery files that no test names: " + ", ".join(missing)
