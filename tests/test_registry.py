"""Every registered problem type is complete: model, solver, example, docs page, template."""

from __future__ import annotations

import typing

import pytest

from dyncli import registry
from dyncli.schema import example_template
from tests.conftest import PROBLEMS, ROOT


@pytest.mark.parametrize("name", list(registry.TYPES))
def test_type_has_model_and_solver(name):
    assert registry.available(name), f"{name}: model or solver module missing"
    cls = registry.model_class(name)
    lit = cls.model_fields["type"].annotation
    assert typing.get_args(lit) == (name,)
    assert callable(registry.solver(name))


@pytest.mark.parametrize("name", list(registry.TYPES))
def test_type_has_example_docs_and_template(name):
    import yaml

    found = False
    for f in PROBLEMS.rglob("*.yaml"):
        data = yaml.safe_load(f.read_text())
        items = data.get("problems", [data]) if isinstance(data, dict) else []
        if any(isinstance(i, dict) and i.get("type") == name for i in items):
            found = True
            break
    assert found, f"no example of {name} in problems/"
    assert (ROOT / "docs" / "types" / f"{name}.md").exists(), f"docs/types/{name}.md missing"
    spec = registry.TYPES[name]
    # the template: a packaged dyncli/templates/TYPE.yaml (the older types), else derived from the
    # declared example (dyncli.schema.example_template: no second hand-written file)
    assert spec.template == f"dyncli/templates/{name}.yaml"  # packaged: dyncli new reads it from there
    assert (ROOT / spec.template).exists() or example_template(spec) is not None, f"template for {name} missing"
    assert spec.example and (ROOT / spec.example).exists(), f"{name}: declared example {spec.example!r} missing"
    data = yaml.safe_load((ROOT / spec.example).read_text(encoding="utf-8"))
    items = data.get("problems", [data]) if isinstance(data, dict) else []
    assert any(isinstance(i, dict) and i.get("type") == name for i in items), f"{spec.example} has no {name} problem"


def test_every_topic_package_declares_its_types():
    """Adding a type touches its own package: the registry lists no type by
    hand, it reads every ``dyncli/topics/<topic>/results.py``."""
    topics = {p.parent.name for p in (ROOT / "dyncli" / "topics").glob("*/results.py")}
    assert {s.package.rsplit(".", 1)[1] for s in registry.TYPES.values()} == topics
    src = (ROOT / "dyncli" / "registry.py").read_text(encoding="utf-8")
    assert not [n for n in registry.TYPES if f'"{n}"' in src], "registry.py names a type"


def test_union_is_discriminated():
    from pydantic import TypeAdapter

    u = registry.problem_union()
    schema = TypeAdapter(u).json_schema()
    assert schema  # builds


def test_numeric_cores_do_not_import_pydantic():
    for info in registry.TYPES.values():
        mod = info.ref(info.solve).split(":")[0]
        path = ROOT / (mod.replace(".", "/") + ".py")
        import re

        text = path.read_text()
        assert not re.search(r"^\s*(import pydantic|from pydantic)", text, re.M), f"{path} imports pydantic"


def test_capability_flags_match_what_each_type_does():
    """``plots``: the topic package has a plots module; ``exact``: the model accepts
    ``accuracy.method: exact``.  (``symbolic`` and ``numpy_free`` are checked by running the
    examples: tests/api/test_output.py, tests/speed/test_imports.py.)"""
    import importlib.util

    for name, info in registry.TYPES.items():
        has_module = importlib.util.find_spec(info.package + ".plots") is not None
        assert (info.plots is not None) == has_module, f"{name}: plots={info.plots!r} but plots module: {has_module}"
        methods = registry.model_class(name).accuracy_methods
        assert info.exact == ("exact" in methods), f"{name}: exact={info.exact} but accuracy methods {methods}"
