"""`dyncli new TYPE` templates: each solves (exit 0) and is the gallery's
example of its type — the file named on its "# Gallery: PATH" line, with the
same results.  A type without a packaged dyncli/templates/TYPE.yaml gets its
template derived from its declared example (dyncli.schema.example_template)."""

from __future__ import annotations

import re

import pytest

from dyncli import registry
from dyncli.schema import example_template, template
from tests.conftest import ROOT, run_cli, solve_one_text, solve_path

TEMPLATES = ROOT / "dyncli" / "templates"


def _template_or_skip(name):
    if not (TEMPLATES / f"{name}.yaml").exists():
        if not registry.available(name):
            pytest.skip(f"type {name} is not implemented yet")
        if example_template(registry.TYPES[name]) is None:
            pytest.fail(f"{name}: no dyncli/templates/{name}.yaml and no declared example to derive it from")
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


def test_a_derived_template_is_the_example_itself():
    """No second hand-written file: a type without a packaged template prints its example (the
    first problem of a ``problems:`` list, comments kept) under the two header lines."""
    spec = registry.TYPES["pendulum"]
    text = example_template(spec)
    example = (ROOT / spec.example).read_text(encoding="utf-8")
    assert text.splitlines()[1] == f"# Gallery: {spec.example} (the same problem, with its answers)"
    comments = [ln for ln in example.splitlines() if ln.startswith("#")]
    assert all(ln in text.splitlines() for ln in comments)
