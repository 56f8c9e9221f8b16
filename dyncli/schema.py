"""JSON Schema of problem files and commented templates (``dyncli new``)."""

from __future__ import annotations

from importlib import resources
from typing import Any


def json_schema(type_name: str | None = None) -> dict[str, Any]:
    from pydantic import TypeAdapter

    from dyncli import registry

    if type_name is not None:
        if type_name not in registry.TYPES:
            raise KeyError(type_name)
        sch = registry.model_class(type_name).model_json_schema()
        sch["title"] = f"dyncli problem: {type_name}"
        sch["$schema"] = "https://json-schema.org/draft/2020-12/schema"
        return sch
    union = registry.problem_union()
    one = TypeAdapter(union).json_schema()
    defs = one.pop("$defs", {})
    problem = one
    sch = {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "dyncli problem file",
        "description": "One problem (a mapping with 'type') or {problems: [...]}.",
        "anyOf": [
            problem,
            {
                "type": "object",
                "properties": {"problems": {"type": "array", "items": problem, "minItems": 1}},
                "required": ["problems"],
                "additionalProperties": False,
            },
        ],
        "$defs": defs,
    }
    return sch


def results_json_schema(type_name: str | None = None) -> dict[str, Any]:
    """JSON Schema of the ``results`` object of one type's JSON records (or,
    for all types, ``$defs`` with one schema per type), from the declarations:
    each result's description carries its meaning, unit and equations."""
    from dyncli import registry
    from dyncli.declare import results_schema

    if type_name is not None:
        if type_name not in registry.TYPES:
            raise KeyError(type_name)
        return results_schema(registry.TYPES[type_name])
    defs = {name: results_schema(spec) for name, spec in registry.TYPES.items()}
    for d in defs.values():
        d.pop("$schema", None)
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "dyncli results, per problem type",
        "description": "The 'results' object of a JSON record is the schema of its 'type' in $defs.",
        "$defs": defs,
    }


def template(type_name: str) -> str:
    """The template ``dyncli new TYPE`` prints: a hand-commented ``dyncli/templates/<type>.yaml``
    when the package has one (the older types), else the type's declared example itself
    (:func:`example_template`: one file, so the template and the gallery cannot drift), else
    (an installed wheel, which carries no ``problems/``) one generated from the model's fields."""
    try:
        return (resources.files("dyncli") / "templates" / f"{type_name}.yaml").read_text(encoding="utf-8")
    except (FileNotFoundError, OSError):
        pass
    from dyncli import registry

    info = registry.TYPES[type_name]
    derived = example_template(info)
    if derived is not None:
        return derived
    cls = registry.model_class(type_name)
    lines = [f"# dyncli problem: {type_name} — {info.title} (notes {info.sections})", f"type: {type_name}", "title: my problem"]
    for name, f in cls.model_fields.items():
        if name in ("type", "title", "params", "accuracy", "g"):
            continue
        desc = f" # {f.description}" if f.description else ""
        if f.is_required():
            lines.append(f"{name}:  # required{desc.replace(' #', ' —', 1)}")
        else:
            d = f.default
            lines.append(f"# {name}: {d!r}{desc}")
    return "\n".join(lines) + "\n"


def _first_item(lines: list[str]) -> list[str] | None:
    """The lines of the first entry of a top-level ``problems:`` list, dedented to a mapping."""
    try:
        start = lines.index("problems:") + 1
    except ValueError:
        return None
    items = [i for i in range(start, len(lines)) if lines[i].lstrip().startswith("- ")]
    if not items:
        return None
    first = lines[items[0]]
    indent = len(first) - len(first.lstrip()) + 2
    end = next((i for i in items[1:] if len(lines[i]) - len(lines[i].lstrip()) == indent - 2), len(lines))
    body = [first[indent:]] + [ln[indent:] if ln[:indent].strip() == "" else ln for ln in lines[items[0] + 1:end]]
    while body and not body[-1].strip():
        body.pop()
    return body


def example_template(info) -> str | None:
    """The declared example of a type (``TypeSpec.example``) as its template: a first line naming
    the type, a ``# Gallery:`` line, the example's comments and its (first) problem, or None when
    the example is not on disk.  The problem is the example's text, comments kept; when it cannot
    be cut from a ``problems:`` list as text, the first problem as plain YAML."""
    from pathlib import Path

    import yaml

    path = Path(__file__).resolve().parent.parent / info.example if info.example else None
    if path is None or not path.is_file():
        return None
    lines = path.read_text(encoding="utf-8").splitlines()
    data = yaml.safe_load("\n".join(lines))
    head = [f"# dyncli problem: {info.name} — {info.title} (notes {info.sections})",
            f"# Gallery: {info.example} (the same problem, with its answers)"]
    if isinstance(data, dict) and "problems" in data:
        comments = [ln for ln in lines[:lines.index("problems:")] if ln.startswith("#")]
        mine = next(i for i, p in enumerate(data["problems"]) if p.get("type") == info.name)
        body = _first_item(lines) if mine == 0 else None
        if body is None or yaml.safe_load("\n".join(body)) != data["problems"][mine]:
            body = yaml.safe_dump(data["problems"][mine], sort_keys=False, allow_unicode=True).splitlines()
        lines = comments + body
        data = data["problems"][mine]
    return "\n".join(head + lines + _unset_fields(info.name, data)) + "\n"


def _unset_fields(type_name: str, given) -> list[str]:
    """A commented line for each field of the model that the example leaves out."""
    from dyncli import registry

    cls = registry.model_class(type_name)
    props = cls.model_json_schema().get("properties", {})
    out = []
    for name, f in cls.model_fields.items():
        if name in ("type", "title", "params", "accuracy") or name in (given or {}):
            continue
        d = "" if f.is_required() else ("null" if f.default is None else f.default)
        d = [] if f.default_factory is not None else d
        prop = props.get(name, {})
        desc = f.description or prop.get("description") or next(
            (a["description"] for a in prop.get("anyOf", []) if "description" in a), None)
        out.append(f"# {name}: {d}" + (f"   # {desc}" if desc else ""))
    return ["# optional, with their defaults:"] + out if out else []
