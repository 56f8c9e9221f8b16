"""The documentation site builds cleanly and covers every type and gallery file.

* ``mkdocs build --strict`` (warnings are errors) succeeds;
* every registered type has a page ``docs/types/TYPE.md`` with the generated
  field table and a checked command example, and the page is in the nav;
* every file in ``problems/`` is listed in ``docs/gallery.md`` (and every
  path listed there exists);
* a YAML block marked ``<!-- same-as: PATH -->`` (used in the README, which
  the site's include hook does not process) holds the same data as PATH.
"""

from __future__ import annotations

import importlib.util
import os
import re
import subprocess
import sys

import pytest
import yaml

from dyncli import registry
from tests.conftest import ROOT
from tests.docs.util import DOCS, gallery_files, gallery_text, load_docs_module

HAVE_MKDOCS = importlib.util.find_spec("mkdocs") is not None


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    if not HAVE_MKDOCS:
        pytest.skip("mkdocs is not installed (pip install '.[test]' installs mkdocs and mkdocs-material)")
    out = tmp_path_factory.mktemp("site")
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1", NO_COLOR="1")
    p = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-f", str(ROOT / "mkdocs.yml"), "-d", str(out)],
                       cwd=ROOT, env=env, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, f"mkdocs build --strict failed:\n{p.stdout}\n{p.stderr}"
    warnings = [ln for ln in p.stderr.splitlines() if ln.startswith("WARNING")]
    assert not warnings, "\n".join(warnings)
    return out


def test_site_builds_strict(site):
    assert (site / "index.html").exists()
    for page in ("getting-started", "cli", "gallery", "check", "accuracy", "changelog", "types"):
        assert (site / page / "index.html").exists(), page


def _nav_links(site) -> set[str]:
    html = (site / "index.html").read_text(encoding="utf-8")
    return set(re.findall(r'href="([^"#]+)"', html))


@pytest.mark.parametrize("name", list(registry.TYPES))
def test_type_page_in_nav(name, site):
    page = DOCS / "types" / f"{name}.md"
    if not page.exists() and not registry.available(name):
        pytest.skip(f"type {name} is not implemented yet (no model/solver), so it has no page yet")
    assert page.exists(), f"docs/types/{name}.md missing"
    assert (site / "types" / name / "index.html").exists()
    assert f"types/{name}/" in _nav_links(site), f"types/{name} is not in the nav"


@pytest.mark.parametrize("name", list(registry.TYPES))
def test_type_page_has_generated_fields_and_example(name):
    page = DOCS / "types" / f"{name}.md"
    if not page.exists() and not registry.available(name):
        pytest.skip(f"type {name} is not implemented yet (no model/solver), so it has no page yet")
    text = page.read_text(encoding="utf-8")
    assert f"<!-- fields: {name} -->" in text, f"{page.name}: no generated field table (<!-- fields: {name} -->)"
    assert re.search(r"^```console\n\$ dyncli ", text, re.M), f"{page.name}: no checked command example (```console block)"


def test_fields_tables_render_for_every_available_type():
    hooks = load_docs_module("hooks")
    for name in registry.TYPES:
        if registry.available(name):
            table = hooks.fields_table(name)
            assert table.startswith("| field | unit | default | description |")
            assert "`type`" not in table


def test_types_nav_groups_every_page_by_chapter():
    hooks = load_docs_module("hooks")
    nav = hooks.types_nav()
    listed = {v for sec in nav[1:] for entries in sec.values() for e in entries for v in e.values()}
    pages = {f"types/{p.stem}.md" for p in (DOCS / "types").glob("*.md") if p.stem != "index"}
    assert pages - listed == set(), "type pages that are not registered types"
    assert listed <= pages


def test_every_gallery_file_is_listed():
    text = gallery_text()
    missing = [f for f in gallery_files() if f"`{f}`" not in text]
    assert not missing, "files in problems/ not listed in docs/gallery.md: " + ", ".join(missing)


def test_gallery_lists_only_existing_files():
    listed = re.findall(r"`(problems/[^`]+)`", gallery_text())
    assert listed
    stale = [f for f in listed if not (ROOT / f).is_file()]
    assert not stale, "docs/gallery.md lists missing files: " + ", ".join(stale)


def test_includes_point_at_existing_files():
    for md in [ROOT / "README.md", *DOCS.rglob("*.md")]:
        for path in re.findall(r"<!--\s*include:\s*(\S+)\s*-->", md.read_text(encoding="utf-8")):
            assert (ROOT / path).is_file(), f"{md.relative_to(ROOT)}: include of missing {path}"


def test_same_as_blocks_match_their_files():
    n = 0
    for md in [ROOT / "README.md", *DOCS.rglob("*.md")]:
        text = md.read_text(encoding="utf-8")
        for path, body in re.findall(r"<!--\s*same-as:\s*(\S+)\s*-->\s*\n```ya?ml\n(.*?)^```", text, re.S | re.M):
            n += 1
            assert yaml.safe_load(body) == yaml.safe_load((ROOT / path).read_text(encoding="utf-8")), \
                f"{md.relative_to(ROOT)}: the YAML shown differs from {path}"
    assert n >= 1  # the README's sample problem


def test_no_file_sends_the_reader_outside_the_repository():
    """The contract and the conventions live in docs/ (docs/conventions.md, the type pages,
    docs/reference/): no tracked file cites the specification files outside the repository."""
    import re
    import subprocess

    from tests.conftest import ROOT

    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True).stdout.split()
    pattern = re.compile(r"book-conventions|problem-files\.md|shared/spec|shared/seed|contract §")
    this = "tests/docs/test_docs.py"
    bad = []
    for f in files:
        if f == this or not f.endswith((".py", ".md", ".yaml", ".yml", ".toml", ".txt", ".sh", ".cfg")):
            continue
        text = (ROOT / f).read_text(encoding="utf-8", errors="replace")
        bad += [f"{f}:{i}" for i, line in enumerate(text.splitlines(), 1) if pattern.search(line)]
    assert not bad, "files citing a document outside the repository: " + ", ".join(bad[:20])


def test_readme_says_how_to_put_dyncli_on_path():
    """After the Quick start `dyncli` lives in .venv/bin: the README says in one
    line how to type it plainly, and the console script it names exists."""
    import tomllib

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    line = next((ln for ln in readme.splitlines() if "PATH" in ln), "")
    assert "activate" in line and "pipx install ." in line, line
    scripts = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["scripts"]
    assert "dyncli" in scripts
    module, func = scripts["dyncli"].split(":")
    assert callable(getattr(importlib.import_module(module), func))
    assert re.search(r"\.venv/bin/dyncli solve", readme)   # the Quick start runs it from the venv


def test_plots_page_lists_exactly_the_types_that_draw_plots():
    """docs/plots.md's "Plots per type" table has one row per type declared with ``plots``
    (dyncli/declare.py), and none for a type without."""
    text = (DOCS / "plots.md").read_text(encoding="utf-8")
    table = text.split("## Plots per type", 1)[1].split("\n\n", 2)[1]
    listed = re.findall(r"^\| `([\w-]+)` \|", table, re.M)
    assert sorted(listed) == sorted(registry.having("plots"))
