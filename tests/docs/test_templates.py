"""`dyncli new TYPE` templates: each solves (exit 0) and is the gallery's
example of its type — the file named on its "# Gallery: PATH" line, with the
same results."""

from __future__ import annotations

import re

import pytest

from dyncli import registry
from dyncli.schema import template
from tests.conftest import ROOT, run_cli, solve_one_text, solve_path

TEMPLATES = ROOT / "dyncli" / "templates"


def _template_or_skip(name):
    if not (TEMPLATES / f"{name}.yaml").exists():
        if not registry.available(name):
            pytest.skip(f"type {name} is not implemented yet")
        pytest.fail(f"dyncli/templates/{name}.yaml missing")
    return template(name)


@pytest.mark.parametrize("name", list(registry.TYPES))
def test_template_solves(name):
    text = _template_or_skip(name)
    rec = solve_one_text(text)
    assert rec["type"] == name
    assert text.startswith(f"# dyncli problem: {name} "), "the template's first line names the type"


@pytest.mark.parametrize("name", list(registry.TYPES))
def test_template_is_the_gallery_example(name):
    text = _template_or_skip(name)
    m = re.search(r"^# Gallery: (problems/\S+\.yaml)", text, re.M)
    assert m, f"template {name}: no '# Gallery: problems/...yaml' line"
    gallery = solve_path(ROOT / m.group(1))
    ours = solve_one_text(text)
    same = [g for g in gallery if g["type"] == name and g["results"] == ours["results"]]
    assert same, f"template {name} does not give the results of {m.group(1)}"


def test_new_then_solve_on_the_command_line():
    rc, out, err = run_cli("new", "impact")
    assert rc == 0, err
    rc, out2, err = run_cli("solve", "--format", "json", "-", input=out)
    assert rc == 0, err
    assert '"type": "impact"' in out2
