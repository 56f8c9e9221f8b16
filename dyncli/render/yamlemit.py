"""YAML text of plain records without PyYAML's event machinery: the same bytes as
``yaml.dump(records, Dumper=yamlout.dumper(), sort_keys=False, default_flow_style=None,
width=100)`` for dicts, lists, str, int, float, bool and None (issue #31: a 10⁴-point sweep
spent most of its time in PyYAML's representer, serializer and emitter).

The layout is PyYAML's emitter transcribed for those nodes (its block and flow collections, its
indentation and line-width rules, plain and single-quoted scalars); whether a string may be
plain, and which style it takes, is PyYAML's own analysis and resolver (cached per string).
Anything else — a string that needs double quotes or spans lines, a key of 128 characters or
more, an object met twice (PyYAML writes an anchor), a type of its own — raises
:class:`Unsupported` and the caller dumps with PyYAML instead.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

WIDTH = 100
_STR = "tag:yaml.org,2002:str"


class Unsupported(Exception):
    """A record this writer does not lay out as PyYAML would: dump it with PyYAML."""


@lru_cache(maxsize=1)
def _tools():
    import yaml

    return yaml.emitter.Emitter(None, allow_unicode=True), yaml.emitter.Emitter(None, allow_unicode=False), \
        yaml.resolver.Resolver(), yaml.ScalarNode


@lru_cache(maxsize=4096)
def _string(text: str, unicode: bool):
    """(plain allowed in flow, plain allowed in block, single quotes allowed, len, empty, multiline)."""
    if not text.isprintable():
        raise Unsupported("double-quoted")
    em_u, em_a, resolver, node = _tools()
    a = (em_u if unicode else em_a).analyze_scalar(text)
    implicit = resolver.resolve(node, text, (True, False)) == _STR
    if a.multiline or not (a.allow_single_quoted or (implicit and a.allow_block_plain)):
        raise Unsupported("multiline or double-quoted")
    return implicit and a.allow_flow_plain, implicit and a.allow_block_plain, a.allow_single_quoted, len(text), a.empty


def plain(x: Any) -> Any:
    """numpy scalars/arrays, float/int subclasses and tuples -> plain Python
    values (anything else unchanged)."""
    if type(x) in (int, float, bool, str) or x is None:
        return x
    if isinstance(x, bool):
        return bool(x)
    if isinstance(x, int):
        return int(x)
    if isinstance(x, float):
        return float(x)
    if isinstance(x, tuple):
        return list(x)
    tolist = getattr(x, "tolist", None)        # numpy.generic and numpy.ndarray
    if callable(tolist) and type(x).__module__.startswith("numpy"):
        return tolist()
    return x


def _float(x: float) -> str:
    if x != x:
        return ".nan"
    if x == float("inf"):
        return ".inf"
    if x == float("-inf"):
        return "-.inf"
    v = repr(x).lower()
    return v.replace("e", ".0e", 1) if "." not in v and "e" in v else v


class _Writer:
    """PyYAML's emitter state for the nodes above (column, whitespace, indention, indents)."""

    def __init__(self, unicode: bool):
        self.out: list[str] = []
        self.column, self.whitespace, self.indention = 0, True, True
        self.indent: int | None = None
        self.indents: list[int | None] = []
        self.flow = 0
        self.unicode = unicode
        self.seen: set[int] = set()

    # -- the writer's primitives (yaml.emitter.Emitter's, for these nodes)
    def indicator(self, ind: str, need_ws: bool, whitespace: bool = False, indention: bool = False) -> None:
        data = ind if self.whitespace or not need_ws else " " + ind
        self.whitespace = whitespace
        self.indention = self.indention and indention
        self.column += len(data)
        self.out.append(data)

    def newline_indent(self) -> None:
        indent = self.indent or 0
        if not self.indention or self.column > indent or (self.column == indent and not self.whitespace):
            self.whitespace = self.indention = True
            self.column = 0
            self.out.append("\n")
        if self.column < indent:
            self.whitespace = True
            self.out.append(" " * (indent - self.column))
            self.column = indent

    def push(self, flow: bool = False, indentless: bool = False) -> None:
        self.indents.append(self.indent)
        if self.indent is None:
            self.indent = 2 if flow else 0
        elif not indentless:
            self.indent += 2

    def text(self, text: str, split: bool) -> None:
        """A plain scalar (spaces inside may break the line past the width when ``split``)."""
        if not text:
            return
        if not self.whitespace:
            self.column += 1
            self.out.append(" ")
        self.whitespace = self.indention = False
        if " " not in text or not split:
            self.column += len(text)
            self.out.append(text)
            return
        self._spaced(text, plain=True)

    def quoted(self, text: str, split: bool) -> None:
        self.indicator("'", True)
        self._spaced(text, plain=False, split=split)
        self.indicator("'", False)

    def _spaced(self, text: str, plain: bool, split: bool = True) -> None:
        """write_plain / write_single_quoted over a text without line breaks."""
        spaces, start, end, n = False, 0, 0, len(text)
        while end <= n:
            ch = text[end] if end < n else None
            if spaces:
                if ch != " ":
                    if start + 1 == end and self.column > WIDTH and split and (plain or (start != 0 and end != n)):
                        self.newline_indent()
                        if plain:
                            self.whitespace = self.indention = False
                    else:
                        self.column += end - start
                        self.out.append(text[start:end])
                    start = end
            elif ch is None or ch == " " or (not plain and ch == "'"):
                if start < end:
                    self.column += end - start
                    self.out.append(text[start:end])
                    start = end
            if not plain and ch == "'":
                self.column += 2
                self.out.append("''")
                start = end + 1
            if ch is not None:
                spaces = ch == " "
            end += 1

    # -- nodes
    def scalar(self, x, simple_key: bool) -> None:
        self.push(flow=True)
        if x is None:
            self.text("null", False)
        elif x is True or x is False:
            self.text("true" if x else "false", False)
        elif type(x) is int:
            self.text(str(x), False)
        elif type(x) is float:
            self.text(_float(x), False)
        else:
            flow_plain, block_plain, single, _, empty = _string(x, self.unicode)
            if (not (simple_key and empty)) and (flow_plain if self.flow else block_plain):
                self.text(x, not simple_key)
            elif single:
                self.quoted(x, not simple_key)
            else:
                raise Unsupported("double-quoted")
        self.indent = self.indents.pop()

    def key(self, k) -> None:
        if type(k) is str:
            if _string(k, self.unicode)[3] >= 128 or not k:
                raise Unsupported("long key")
        elif not (k is None or type(k) in (int, float, bool)):
            raise Unsupported("key type")
        self.scalar(k, True)

    def node(self, x, mapping: bool = False) -> None:
        t = type(x)
        if t is dict or t is list:
            if id(x) in self.seen:
                raise Unsupported("an object met twice: an alias")
            self.seen.add(id(x))
            (self.mapping if t is dict else self.sequence)(x, mapping)
        elif x is None or t in (str, int, float, bool):
            self.scalar(x, False)
        else:
            p = plain(x)
            if p is x:
                raise Unsupported(f"type {t.__name__}")
            self.node(p, mapping)

    def sequence(self, xs: list, mapping: bool) -> None:
        if self.flow or not xs or all(_is_scalar(v) for v in xs):
            self.indicator("[", True, whitespace=True)
            self.flow += 1
            self.push(flow=True)
            for i, v in enumerate(xs):
                if i:
                    self.indicator(",", False)
                if self.column > WIDTH:
                    self.newline_indent()
                self.node(v)
            self.indent = self.indents.pop()
            self.flow -= 1
            self.indicator("]", False)
            return
        self.push(indentless=mapping and not self.indention)
        for v in xs:
            self.newline_indent()
            self.indicator("-", True, indention=True)
            self.node(v)
        self.indent = self.indents.pop()

    def mapping(self, d: dict, _mapping: bool) -> None:
        if self.flow or not d or all(_is_scalar(k) and _is_scalar(v) for k, v in d.items()):
            self.indicator("{", True, whitespace=True)
            self.flow += 1
            self.push(flow=True)
            for i, (k, v) in enumerate(d.items()):
                if i:
                    self.indicator(",", False)
                if self.column > WIDTH:
                    self.newline_indent()
                self.key(k)
                self.indicator(":", False)
                self.node(v, True)
            self.indent = self.indents.pop()
            self.flow -= 1
            self.indicator("}", False)
            return
        self.push()
        for k, v in d.items():
            self.newline_indent()
            self.key(k)
            self.indicator(":", False)
            self.node(v, True)
        self.indent = self.indents.pop()


def _is_scalar(x) -> bool:
    """A node PyYAML represents as a plain-tagged scalar (the flow-style test of its representer)."""
    return x is None or type(x) in (str, int, float, bool) or isinstance(x, (int, float)) or (
        not isinstance(x, (dict, list, tuple)) and type(x).__module__.startswith("numpy") and getattr(x, "ndim", 1) == 0)


def dumps(records, allow_unicode: bool = True) -> str:
    """The YAML document of ``records`` (a list or any node above), or :class:`Unsupported`."""
    if type(records) not in (list, dict):
        raise Unsupported("a document that is not a collection")
    w = _Writer(allow_unicode)
    w.node(records)
    w.newline_indent()
    return "".join(w.out)
