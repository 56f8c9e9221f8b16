"""mkdocs hook: generate each problem type's field table from its pydantic
model (so the docs never drift from the code), and the types index.

A page may contain the marker ``<!-- fields: TYPE -->``; it is replaced by a
table of the type's fields (name, unit, default, description) built from the
JSON Schema of the model.  ``<!-- types-index -->`` becomes the table of all
registered types with their notes sections.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _path() -> None:
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))

_FIELDS = re.compile(r"<!--\s*fields:\s*([\w-]+)\s*-->")


def fields_table(type_name: str) -> str:
    from dyncli import registry

    cls = registry.model_class(type_name)
    sch = cls.model_json_schema()
    props = sch.get("properties", {})
    required = set(sch.get("required", []))
    rows = ["| field | unit | default | description |", "|---|---|---|---|"]
    for name, f in cls.model_fields.items():
        if name in ("type",):
            continue
        p = props.get(name, {})
        unit = p.get("x-unit", "")
        if name in required:
            default = "required"
        else:
            d = f.default
            if d is None or callable(getattr(f, "default_factory", None)):
                default = "—" if d is None and f.default_factory is None else "(see below)" if f.default_factory else "—"
            else:
                default = f"`{d!r}`" if not hasattr(d, "model_dump") else "(defaults)"
        desc = (f.description or p.get("description") or "").replace("|", "\\|").replace("\n", " ")
        rows.append(f"| `{name}` | {unit} | {default} | {desc} |")
    return "\n".join(rows)


def types_index() -> str:
    from dyncli import registry

    rows = ["| type | notes | what it solves |", "|---|---|---|"]
    for name, info in registry.TYPES.items():
        rows.append(f"| [`{name}`]({name}.md) | {info.section} | {info.summary} |")
    return "\n".join(rows)


def on_page_markdown(markdown, page, config, files, **kwargs):
    _path()
    markdown = _FIELDS.sub(lambda m: fields_table(m.group(1)), markdown)
    markdown = markdown.replace("<!-- types-index -->", types_index())
    return markdown
