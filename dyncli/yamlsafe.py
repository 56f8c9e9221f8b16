"""Safe YAML reading with source positions and hard caps.

PyYAML's ``compose`` (the libyaml-based CSafeLoader when available, else
SafeLoader) builds a node graph without constructing
any Python object; we then construct plain data ourselves:

* only the standard tags (str, int, float, bool, null, map, seq) are allowed
  -- a ``!!python/...`` or any custom tag is invalid input;
* the number of constructed nodes is capped, so alias expansion ("billion
  laughs") fails fast instead of exhausting memory;
* nesting depth, node count and document size are capped (depth and node
  count while parsing, before composing);
* duplicate mapping keys are an error;
* every value's (line, col) is recorded under its path tuple.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from dyncli.errors import InputError

MAX_BYTES = 2 * 1024 * 1024
MAX_NODES = 200_000
MAX_DEPTH = 40

_STD = "tag:yaml.org,2002:"
_ALLOWED_TAGS = {_STD + t for t in ("str", "int", "float", "bool", "null", "map", "seq")}


class YamlError(InputError):
    def __init__(self, message: str, line: int | None = None, col: int | None = None):
        super().__init__(message)
        self.line = line
        self.col = col


@dataclass
class Document:
    data: Any
    # path tuple -> (line, col), 1-based.  ``key_pos`` points at the key of a
    # mapping entry, ``pos`` at the value.
    pos: dict[tuple, tuple[int, int]] = field(default_factory=dict)
    key_pos: dict[tuple, tuple[int, int]] = field(default_factory=dict)
    # the source text of scalars YAML read as numbers or booleans (``012345671``,
    # ``1:30``, ``1.50``), by value path; ``path + ("<key>",)`` for mapping keys
    text: dict[tuple, str] = field(default_factory=dict)

    def locate(self, path: tuple) -> tuple[int, int] | None:
        """Best position for ``path``: the key of the entry if known, else the
        value, else the nearest ancestor."""
        p = tuple(path)
        while True:
            if p in self.key_pos:
                return self.key_pos[p]
            if p in self.pos:
                return self.pos[p]
            if not p:
                return None
            p = p[:-1]

    def value_pos(self, path: tuple) -> tuple[int, int] | None:
        p = tuple(path)
        while True:
            if p in self.pos:
                return self.pos[p]
            if not p:
                return None
            p = p[:-1]


def _mark(node) -> tuple[int, int]:
    return node.start_mark.line + 1, node.start_mark.column + 1


def load(text: str | bytes) -> Document:
    """Parse one YAML document from ``text`` safely.  Raises YamlError."""
    import yaml

    if isinstance(text, bytes):
        if len(text) > MAX_BYTES:
            raise YamlError(f"file is too large ({len(text)} bytes, at most {MAX_BYTES})")
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise YamlError(f"file is not UTF-8 text (byte {exc.start})") from None
    if len(text) > MAX_BYTES:
        raise YamlError(f"file is too large ({len(text)} characters, at most {MAX_BYTES})")
    if "\x00" in text:
        raise YamlError("file contains a NUL character (binary data?)")
    loader = getattr(yaml, "CSafeLoader", None) or yaml.SafeLoader
    try:
        _precheck(text, loader)
        nodes = list(yaml.compose_all(text, Loader=loader))
    except yaml.MarkedYAMLError as exc:
        m = exc.problem_mark or exc.context_mark
        tab = _tab_near(text, m.line if m is not None else None, m.column if m is not None else None)
        if tab is not None:
            raise YamlError(f"tab character at line {tab[0]}, column {tab[1]}: use spaces for indentation", *tab) from None
        msg = exc.problem or exc.context or "malformed YAML"
        if m is not None:
            raise YamlError(f"YAML syntax error: {msg}", m.line + 1, m.column + 1) from None
        raise YamlError(f"YAML syntax error: {msg}") from None
    except yaml.reader.ReaderError as exc:
        line = text.count("\n", 0, exc.position) + 1
        col = exc.position - (text.rfind("\n", 0, exc.position) + 1) + 1
        raise YamlError(f"control character #x{exc.character:04x} is not allowed in YAML text", line, col) from None
    except yaml.YAMLError as exc:
        raise YamlError(f"YAML error: {' '.join(str(exc).split())}") from None
    except RecursionError:
        raise YamlError("YAML is nested too deeply") from None
    nodes = [n for n in nodes if n is not None]
    if not nodes:
        raise YamlError("file is empty: expected a problem (a mapping with 'type')", 1, 1)
    if len(nodes) > 1:
        line, col = _mark(nodes[1])
        raise YamlError("file holds several YAML documents ('---'); use one document with 'problems: [...]'", line, col)
    doc = Document(None)
    counter = [0]
    doc.data = _construct(nodes[0], (), doc, counter, 0)
    return doc


def _tab_near(text: str, line: int | None, col: int | None) -> tuple[int, int] | None:
    """(line, column), 1-based, of the tab that a YAML syntax error at the
    0-based ``line``/``col`` is about: the character at the error itself, or
    the first tab in the indentation of a line up to the error's (the
    parsers name it as "a character that cannot start any token")."""
    if line is None:
        return None
    lines = text.split("\n")
    if line < len(lines) and col is not None and lines[line][col:col + 1] == "\t":
        return line + 1, col + 1
    for i, ln in enumerate(lines[:line + 1]):
        indent = len(ln) - len(ln.lstrip(" \t"))
        if "\t" in ln[:indent] and ln[indent:] and not ln[indent:].startswith("#"):
            return i + 1, ln.index("\t") + 1
    return None


def _precheck(text: str, loader) -> None:
    """Stream the parser's events once and stop at the first one beyond the
    depth or node caps, before anything is composed.  Scanning deeply nested
    flow collections costs time quadratic in the depth (in PyYAML and in
    libyaml), so the caps must bite while parsing, not after composing."""
    import yaml

    depth = nodes = 0
    starts = (yaml.SequenceStartEvent, yaml.MappingStartEvent)
    ends = (yaml.SequenceEndEvent, yaml.MappingEndEvent)
    for ev in yaml.parse(text, Loader=loader):
        if isinstance(ev, starts):
            depth += 1
            nodes += 1
            if depth > MAX_DEPTH:
                line, col = ev.start_mark.line + 1, ev.start_mark.column + 1
                raise YamlError(f"document is nested more than {MAX_DEPTH} levels deep", line, col)
        elif isinstance(ev, ends):
            depth -= 1
        elif isinstance(ev, (yaml.ScalarEvent, yaml.AliasEvent)):
            nodes += 1
        if nodes > MAX_NODES:
            line, col = ev.start_mark.line + 1, ev.start_mark.column + 1
            raise YamlError(f"document has more than {MAX_NODES} values", line, col)


def _construct(node, path: tuple, doc: Document, counter: list[int], depth: int) -> Any:
    import yaml

    counter[0] += 1
    if counter[0] > MAX_NODES:
        line, col = _mark(node)
        raise YamlError(
            f"document expands to more than {MAX_NODES} values (alias bomb?)", line, col
        )
    if depth > MAX_DEPTH:
        line, col = _mark(node)
        raise YamlError(f"document is nested more than {MAX_DEPTH} levels deep", line, col)
    line, col = _mark(node)
    doc.pos.setdefault(path, (line, col))
    tag = node.tag
    if tag == _STD + "timestamp" and isinstance(node, yaml.ScalarNode):
        raise YamlError(f"{node.value!r} reads as a date; write a number (or quote it for text)", line, col)
    if tag not in _ALLOWED_TAGS:
        raise YamlError(f"YAML tag {tag!r} is not allowed (only plain data: no tags)", line, col)
    if isinstance(node, yaml.ScalarNode):
        if tag != _STD + "str" and tag != _STD + "null":
            doc.text[path] = node.value
        try:
            return _scalar(node)
        except (ValueError, OverflowError):
            shown = node.value if len(node.value) <= 40 else node.value[:37] + "..."
            raise YamlError(f"cannot read value {shown!r} ({len(node.value)} characters)", line, col) from None
    if isinstance(node, yaml.SequenceNode):
        return [_construct(n, path + (i,), doc, counter, depth + 1) for i, n in enumerate(node.value)]
    if isinstance(node, yaml.MappingNode):
        out: dict = {}
        for knode, vnode in node.value:
            if knode.tag == _STD + "merge" or (isinstance(knode, yaml.ScalarNode) and knode.value == "<<" and knode.tag != _STD + "str"):
                kl, kc = _mark(knode)
                raise YamlError("YAML merge keys ('<<') are not supported", kl, kc)
            if not isinstance(knode, yaml.ScalarNode):
                kl, kc = _mark(knode)
                raise YamlError("mapping keys must be plain names", kl, kc)
            key = _construct(knode, path + ("<key>",), doc, counter, depth + 1)
            doc.pos.pop(path + ("<key>",), None)
            ktext = doc.text.pop(path + ("<key>",), None)
            if not isinstance(key, (str, int)) or isinstance(key, bool):
                key = str(knode.value)
            if key in out:
                kl, kc = _mark(knode)
                raise YamlError(f"duplicate key {key!r}", kl, kc)
            doc.key_pos[path + (key,)] = _mark(knode)
            if ktext is not None:
                doc.text[path + (key, "<key>")] = ktext
            out[key] = _construct(vnode, path + (key,), doc, counter, depth + 1)
        return out
    raise YamlError("unsupported YAML node", line, col)  # pragma: no cover


def _scalar(node) -> Any:
    """Construct a plain scalar the way SafeLoader would, for the std tags."""
    import yaml

    tag = node.tag
    val = node.value
    if tag == _STD + "str":
        return val
    if tag == _STD + "null":
        return None
    if tag == _STD + "bool":
        return val.lower() in ("yes", "true", "on", "y")
    if tag == _STD + "int":
        return yaml.SafeLoader.construct_yaml_int(_DUMMY, node)
    if tag == _STD + "float":
        return yaml.SafeLoader.construct_yaml_float(_DUMMY, node)
    return val  # pragma: no cover


class _Dummy:
    inf_value = float("inf")
    nan_value = float("nan")

    def construct_scalar(self, node):
        return node.value


_DUMMY = _Dummy()
