"""Generate from the code what would otherwise drift, INTO the Markdown files
(so the raw files on a forge show the tables), and check it at build time.

A generated region sits between a start and an end marker::

    <!-- fields: TYPE -->
    ...the table of the type's input fields (name, SI unit, default,
    description), walked from the JSON Schema of its pydantic model...
    <!-- /fields -->

* ``fields: TYPE`` — the field table above;
* ``results: TYPE`` — the table of the type's results (name, symbol, unit,
  meaning, equations) from its declaration (``dyncli/topics/<topic>/
  results.py``); ``results: TYPE/a,b,c`` lists only those results (a page
  that splits its results over several tables), and the region without a
  list then holds every result of the type not listed elsewhere on the page;
* ``results-reference`` — every type's results, binding names marked
  (``docs/reference/results.md``);
* ``types-index`` — the table of every registered type, with its notes
  sections, grouped by chapter;
* ``include: PATH`` (PATH relative to the repository root) — a fenced YAML
  block holding that file, so an example shown in the docs is the file the
  tests solve.

``python docs/hooks.py`` rewrites every region of ``docs/**/*.md`` and the
README with the current content (a start marker without its end marker gets
its region inserted); ``python docs/hooks.py --check`` lists stale regions
(exit 1), as ``tests/docs/test_generated.py`` does.  As an mkdocs hook, a
stale region fails the build (the site never shows what the files do not).
The "Problem types" entry of the nav is expanded into one section per
chapter listing every type that has a page ``docs/types/TYPE.md``.

The command examples (```console blocks) are checked separately, by
``docs/gen_examples.py`` and ``tests/docs/test_examples.py``.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"

# Chapters of the notes used to group types (nav, types index) and the gallery.
CHAPTERS = [
    ("Kinematics of a particle", 1, 12),
    ("Kinematics of rigid bodies", 13, 15),
    ("Kinetics of a particle", 16, 22),
    ("Systems of particles and impact", 23, 28),
    ("Rigid bodies", 29, 36),
    ("Gyroscopes, tops and Euler's equations", 37, 39),
]

COMMON_FIELDS = ("type", "title", "params", "g", "accuracy")


def _path() -> None:
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))


def chapter_of(section: str) -> str:
    """The chapter title for a registry section string such as "§28, §23"."""
    nums = [int(n) for n in re.findall(r"§\s*(\d+)", section)]
    first = min(nums) if nums else 0
    for title, lo, hi in CHAPTERS:
        if lo <= first <= hi:
            return title
    return "Other"


def chapter_label(title: str) -> str:
    for t, lo, hi in CHAPTERS:
        if t == title:
            return f"{t} (§{lo}–§{hi})"
    return title


def types_by_chapter() -> list[tuple[str, list[str]]]:
    """[(chapter title, [type names in registry order])], chapters in order."""
    _path()
    from dyncli import registry

    groups: dict[str, list[str]] = {t: [] for t, _, _ in CHAPTERS}
    for name, info in registry.TYPES.items():
        groups.setdefault(chapter_of(info.sections), []).append(name)
    return [(t, names) for t, names in groups.items() if names]


def type_page(name: str) -> Path:
    return DOCS / "types" / f"{name}.md"


# --------------------------------------------------------------------------
# field tables


def _fmt_default(v) -> str:
    if isinstance(v, bool):
        return "`true`" if v else "`false`"
    if isinstance(v, float):
        return f"`{v:g}`"
    if isinstance(v, (list, tuple)):
        return "`" + json.dumps(_plain(v), ensure_ascii=False).replace('"', "") + "`"
    if isinstance(v, dict):
        return "`" + json.dumps(_plain(v), ensure_ascii=False) + "`" if v else "`{}`"
    if isinstance(v, str):
        return f"`{v}`"
    return f"`{v!r}`"


def _plain(v):
    if isinstance(v, float) and v == int(v) and abs(v) < 1e15:
        return int(v)
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    return v


def _is_number(s: dict) -> bool:
    alts = s.get("anyOf")
    if not alts:
        return s.get("type") == "number"
    types = {a.get("type") for a in alts}
    return types <= {"number", "string"} and "number" in types


def _unwrap(p: dict) -> tuple[dict, bool]:
    """Strip an Optional wrapper: (merged schema, nullable)."""
    alts = p.get("anyOf")
    if alts and any(a.get("type") == "null" for a in alts):
        rest = [a for a in alts if a.get("type") != "null"]
        if len(rest) == 1:
            merged = dict(rest[0])
            for k in ("description", "default", "x-unit", "x-dimension"):
                if k in p and k not in merged:
                    merged[k] = p[k]
            if "default" in p:
                merged["default"] = p["default"]
            return merged, True
        return {**p, "anyOf": rest}, True
    return p, False


def _ref(defs: dict, s: dict) -> tuple[str, dict] | None:
    r = s.get("$ref")
    if r is None and len(s.get("allOf") or ()) == 1:      # pydantic < 2.9 wraps a described $ref
        r = s["allOf"][0].get("$ref")
    if r and r.startswith("#/$defs/"):
        name = r.split("/")[-1]
        return name, defs.get(name, {})
    return None


def _unit(s: dict) -> str:
    u = s.get("x-unit")
    if u:
        return u
    dim = s.get("x-dimension")
    if dim:
        _path()
        from dyncli.units import si_unit

        return si_unit(dim)
    return ""


def _kind(s: dict) -> str:
    if _is_number(s):
        return ""
    t = s.get("type")
    if t == "array":
        items = s.get("items") or {}
        if s.get("minItems") == 3 and s.get("maxItems") == 3:
            if items.get("type") == "array":
                return "3×3 tensor"
            return "vector"
        return "list"
    if "enum" in s:
        return "one of " + ", ".join(f"`{e}`" for e in s["enum"])
    if "const" in s:
        return f"`{s['const']}`"
    if t == "boolean":
        return "true/false"
    if t == "integer":
        return "integer"
    return ""


def _desc(text: str) -> str:
    return " ".join(text.split()).replace("|", "\\|")


def _rows(schema: dict, defs: dict, prefix: str, required: set, skip=(), depth=0) -> list[tuple]:
    rows = []
    for name, p0 in schema.get("properties", {}).items():
        if name in skip:
            continue
        p, nullable = _unwrap(p0)
        full = prefix + name
        if name in required:
            default = "required"
        elif "default" in p and p["default"] is not None:
            default = _fmt_default(p["default"])
        else:
            default = "—"
        desc = p.get("description") or p0.get("description") or ""
        kind = _kind(p)
        sub = None
        ref = _ref(defs, p)
        if ref:
            sub = ("", ref[1])
        elif p.get("type") == "array" and isinstance(p.get("items"), dict):
            r = _ref(defs, p["items"])
            if r:
                sub = ("[]", r[1])
            elif "anyOf" in p["items"] or "oneOf" in p["items"]:
                alts = p["items"].get("oneOf") or p["items"].get("anyOf")
                refs = [_ref(defs, a) for a in alts]
                if all(refs):
                    sub = ("[]", None, [r[1] for r in refs])
        elif p.get("type") == "object" and isinstance(p.get("additionalProperties"), dict):
            ap = p["additionalProperties"]
            r = _ref(defs, ap)
            if r:
                sub = (".NAME", r[1])
            elif not desc.endswith(")") and ap.get("description"):
                desc = f"{desc} ({ap['description']})" if desc else ap["description"]
            unit = _unit(ap)
            if unit and not _unit(p):
                p = {**p, "x-unit": unit}
        elif "oneOf" in p or ("anyOf" in p and not _is_number(p)):
            alts = p.get("oneOf") or p.get("anyOf")
            refs = [_ref(defs, a) for a in alts]
            if refs and all(refs):
                sub = ("", None, [r[1] for r in refs])
        if sub and not desc:
            target = sub[1] if sub[1] is not None else {}
            desc = (target.get("description") or "").split("\n\n")[0]
        if kind and kind not in ("list",) and not (kind == "true/false" and desc):
            desc = f"{kind}: {desc}" if desc else kind
        rows.append((full, _unit(p), default, _desc(desc)))
        if sub and depth < 3:
            if sub[1] is not None:
                rows += _rows(sub[1], defs, f"{full}{sub[0]}.", set(sub[1].get("required", [])), depth=depth + 1)
            else:
                for variant in sub[2]:
                    rows += _variant_rows(variant, defs, f"{full}{sub[0]}", depth + 1)
    return rows


def _variant_rows(variant: dict, defs: dict, prefix: str, depth: int) -> list[tuple]:
    """Rows of one member of a tagged union: the tag value names it."""
    props = variant.get("properties", {})
    tag = next((k for k, v in props.items() if "const" in v or (len(v.get("enum", [])) == 1)), None)
    label = ""
    if tag:
        v = props[tag]
        label = f"{tag}={v.get('const', (v.get('enum') or [''])[0])}"
    rows = [(f"{prefix} ({label})" if label else prefix, "", "", _desc((variant.get("description") or "").split("\n\n")[0]))]
    rows += _rows(variant, defs, f"{prefix}.", set(variant.get("required", [])), skip=(tag,) if tag else (), depth=depth)
    return rows


def fields_table(type_name: str) -> str:
    _path()
    from dyncli import registry

    cls = registry.model_class(type_name)
    sch = cls.model_json_schema()
    defs = sch.get("$defs", {})
    rows = _rows(sch, defs, "", set(sch.get("required", [])), skip=COMMON_FIELDS)
    # defaults given by factories do not appear in the schema: take them from the model
    fields = cls.model_fields
    out = ["| field | unit | default | description |", "|---|---|---|---|"]
    for name, unit, default, desc in rows:
        f = fields.get(name)
        if f is not None and default == "—" and f.default_factory is not None:
            try:
                default = _fmt_default(f.default_factory())
            except Exception:  # noqa: BLE001 - a factory that needs arguments
                pass
        out.append(f"| `{name}` | {unit} | {default} | {desc} |")
    methods = getattr(cls, "accuracy_methods", ("auto",))
    common = ("Every problem also takes `title`, `params`, `g` (gravity, default 9.81 m/s²) "
              "and `accuracy` ([Problem files](../getting-started.md#problem-files))")
    if tuple(methods) != ("auto",):
        common += "; for this type `accuracy.method` is one of " + ", ".join(f"`{m}`" for m in methods)
    return "\n".join(out) + "\n\n" + common + ".\n"


# --------------------------------------------------------------------------
# types index, includes, nav


def types_index() -> str:
    _path()
    from dyncli import registry

    out = []
    for chapter, names in types_by_chapter():
        out += [f"### {chapter_label(chapter)}", "", "| type | notes | what it solves |", "|---|---|---|"]
        for name in names:
            info = registry.TYPES[name]
            link = f"[`{name}`]({name}.md)" if type_page(name).exists() else f"`{name}` (page to come)"
            out.append(f"| {link} | {info.sections} | {info.title} |")
        out.append("")
    return "\n".join(out)


def gallery_rows(label: str) -> str:
    """The gallery's table of the declared examples (``TypeSpec.gallery``) whose type falls in the
    chapter ``label`` ("§16–§22"), one row each: the file, the sections, the declared line."""
    _path()
    from dyncli import registry

    lo, hi = (int(n) for n in re.findall(r"\d+", label)[:2])
    rows = []
    for name, info in registry.TYPES.items():
        nums = [int(n) for n in re.findall(r"§\s*(\d+)", info.sections)]
        if info.gallery and info.example and nums and lo <= min(nums) <= hi:
            rows.append(f"| `{info.example}` | {info.sections}: {info.gallery} |")
    return "\n".join(["| file | what it shows |", "|---|---|"] + rows) if rows else ""


_FIELDS = re.compile(r"<!--\s*fields:\s*([\w-]+)\s*-->")
_INCLUDE = re.compile(r"<!--\s*include:\s*(\S+)\s*-->")


def include(path: str) -> str:
    p = (ROOT / path).resolve()
    if ROOT not in p.parents or not p.is_file():
        raise FileNotFoundError(f"<!-- include: {path} -->: no such file in the repository")
    lang = "yaml" if p.suffix in (".yaml", ".yml") else ""
    text = p.read_text(encoding="utf-8").rstrip("\n")
    return f"```{lang} title=\"{path}\"\n{text}\n```"


def types_nav() -> list:
    nav: list = [{"Overview": "types/index.md"}]
    for chapter, names in types_by_chapter():
        entries = [{name: f"types/{name}.md"} for name in names if type_page(name).exists()]
        if entries:
            nav.append({chapter: entries})
    return nav


def on_config(config, **kwargs):
    nav = config.get("nav") or []
    for item in nav:
        if isinstance(item, dict):
            for key, value in item.items():
                if value == "types/index.md":
                    item[key] = types_nav()
    return config


# --------------------------------------------------------------------------
# generated regions in the files


_REGION = re.compile(r"<!--\s*(?P<kind>fields|include|types-index|results|results-reference|gallery)(?::\s*(?P<arg>\S+?))?\s*-->\n"
                     r"(?:(?P<body>.*?)<!--\s*/(?P=kind)\s*-->\n?)?", re.S)


def _listed(markdown: str) -> dict[str, set]:
    """{type: result names listed by ``results: TYPE/a,b`` regions} of a page."""
    out: dict[str, set] = {}
    for m in _REGION.finditer(markdown):
        if m.group("kind") == "results" and "/" in (m.group("arg") or ""):
            t, _, names = m.group("arg").partition("/")
            out.setdefault(t, set()).update(names.split(","))
    return out


def results_region(arg: str, listed: dict[str, set]) -> str:
    _path()
    from dyncli.resultdocs import region

    return region(arg, listed)


def generate(kind: str, arg: str | None, listed: dict[str, set] | None = None) -> str:
    """The content of a region (ends with a newline)."""
    if kind == "fields":
        text = fields_table(arg)
    elif kind == "results":
        text = results_region(arg, listed or {})
    elif kind == "results-reference":
        _path()
        from dyncli import registry
        from dyncli.resultdocs import reference

        text = reference(registry.TYPES)
    elif kind == "include":
        text = include(arg)
    elif kind == "gallery":
        text = gallery_rows(arg)
    else:
        text = types_index()
    return text.rstrip("\n") + "\n"


def regenerate(markdown: str) -> str:
    """``markdown`` with every region's content generated afresh."""
    listed = _listed(markdown)

    def one(m):
        kind, arg = m.group("kind"), m.group("arg")
        start = m.group(0).split("\n", 1)[0]
        return f"{start}\n{generate(kind, arg, listed)}<!-- /{kind} -->\n"

    return _REGION.sub(one, markdown)


def stale_regions(markdown: str) -> list[str]:
    """Start markers whose region is missing or differs from what the code generates."""
    out = []
    listed = _listed(markdown)
    for m in _REGION.finditer(markdown):
        if m.group("body") is None or m.group("body") != generate(m.group("kind"), m.group("arg"), listed):
            out.append(m.group(0).split("\n", 1)[0])
    return out


def generated_files() -> list[Path]:
    return [ROOT / "README.md"] + sorted(DOCS.rglob("*.md"))


def main(argv: list[str]) -> int:
    check = "--check" in argv
    bad = 0
    for f in generated_files():
        text = f.read_text(encoding="utf-8")
        stale = stale_regions(text)
        if not stale:
            continue
        bad += len(stale)
        rel = f.relative_to(ROOT)
        if check:
            for marker in stale:
                print(f"{rel}: stale generated region {marker} (run: python docs/hooks.py)")
        else:
            f.write_text(regenerate(text), encoding="utf-8")
            print(f"{rel}: regenerated {len(stale)} region(s)")
    return 1 if (check and bad) else 0


def on_page_markdown(markdown, page, config, files, **kwargs):
    _path()
    stale = stale_regions(markdown)
    if stale:
        raise ValueError(f"{page.file.src_path}: stale generated region(s) {', '.join(stale)}: "
                         "run python docs/hooks.py")
    return markdown


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
