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

import re
from functools import lru_cache
from typing import Any

WIDTH = 100
_STR = "tag:yaml.org,2002:str"
#: an ASCII word PyYAML's scalar analysis finds nothing in (no indicator, space or break): only its
#: resolver decides between plain and single quotes
_WORD = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.+-]*")


class Unsupported(Exception):
    """A record this writer does not lay out as PyYAML would: dump it with PyYAML."""


@lru_cache(maxsize=1)
def _tools():
    import yaml

    return yaml.emitter.Emitter(None, allow_unicode=True), yaml.emitter.Emitter(None, allow_unicode=False), \
        yaml.resolver.Resolver(), yaml.ScalarNode


@lru_cache(maxsize=4096)
def _string(text: str, unicode: bool):
    """(plain allowed in flow, plain allowed in block, single quotes allowed, len, empty, has a space)."""
    em_u, em_a, resolver, node = _tools()
    if _WORD.fullmatch(text):                   # (PyYAML's analysis of such a word: plain or single-quoted
        implicit = resolver.resolve(node, text, (True, False)) == _STR      # alike, nothing to flag)
        return implicit, implicit, True, len(text), False, False
    if not text.isprintable():
        raise Unsupported("double-quoted")
    a = (em_u if unicode else em_a).analyze_scalar(text)
    implicit = resolver.resolve(node, text, (True, False)) == _STR
    if a.multiline or not (a.allow_single_quoted or (implicit and a.allow_block_plain)):
        raise Unsupported("multiline or double-quoted")
    return (implicit and a.allow_flow_plain, implicit and a.allow_block_plain, a.allow_single_quoted, len(text),
            a.empty, " " in text)


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
    v = repr(x)                     # (lower case already: 'inf', 'nan', '1e-05')
    if v[-1] in "nf":               # nan, inf, -inf
        return ".nan" if x != x else (".inf" if x > 0 else "-.inf")
    if "e" in v and "." not in v:
        return v.replace("e", ".0e", 1)
    return v


def _atom(x) -> str | None:
    """The text of a None, bool, int or float (never split, never quoted); None for anything else."""
    t = type(x)
    if t is float:
        return _float(x)
    if t is int:
        return str(x)
    if x is None:
        return "null"
    if t is bool:
        return "true" if x else "false"
    return None


#: the plain types a node of which is always a scalar (the fast test before :func:`_is_scalar`)
_ATOMS = frozenset((str, int, float, bool, type(None)))


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
    def atom(self, text: str) -> None:
        """A scalar written as it is (no space inside, so never split)."""
        if self.whitespace:
            self.out.append(text)
            self.column += len(text)
        else:
            self.out.append(" " + text)
            self.column += len(text) + 1
        self.whitespace = self.indention = False

    def scalar(self, x, simple_key: bool) -> None:
        a = _atom(x)
        if a is not None:
            self.atom(a)
            return
        flow_plain, block_plain, single, _, empty, spaced = _string(x, self.unicode)
        if (not (simple_key and empty)) and (flow_plain if self.flow else block_plain):
            if not spaced or simple_key:
                if x:
                    self.atom(x)
                return
            self.push(flow=True)
            self.text(x, True)
        elif single:
            self.push(flow=True)
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
        elif t in _ATOMS:
            self.scalar(x, False)
        else:
            p = plain(x)
            if p is x:
                raise Unsupported(f"type {t.__name__}")
            self.node(p, mapping)

    def flow_pairs(self, d: dict) -> list[str] | None:
        """The flow mapping ``d`` as texts key, value, key, value… when every key and value is an
        atom or a plain string without spaces (never split, never quoted), else None."""
        texts = []
        unicode = self.unicode
        for k, v in d.items():
            for x in (k, v):
                a = _atom(x)
                if a is None:
                    if type(x) is not str or not x:
                        return None
                    flow_plain, _, _, n, _, spaced = _string(x, unicode)
                    if not flow_plain or spaced or (x is k and n >= 128):
                        return None
                    a = x
                texts.append(a)
        return texts

    def flow_items(self, texts, pairs: bool = False) -> None:
        """The items of a flow collection already written as texts (atoms: never split), with
        PyYAML's break before an item that starts past the width; with ``pairs`` the texts are
        key, value, key, value… of a flow mapping (``key: value``, the break before a key only)."""
        self.column, self.whitespace, wrote = _lay_flow(texts, self.column, self.whitespace, self.indent or 0,
                                                        self.out, pairs)
        if wrote:
            self.indention = False

    def sequence(self, xs: list, mapping: bool) -> None:
        types = set(map(type, xs))
        if self.flow or not xs or types <= _ATOMS or all(_is_scalar(v) for v in xs):
            self.indicator("[", True, whitespace=True)
            self.flow += 1
            self.push(flow=True)
            if (self.indent or 0) < WIDTH and types <= {int, float, bool, type(None)}:
                self.flow_items(map(_float, xs) if types <= {float} else map(_atom, xs))
            else:
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
        if self.flow or not d or all((type(k) in _ATOMS or _is_scalar(k)) and (type(v) in _ATOMS or _is_scalar(v))
                                     for k, v in d.items()):
            self.indicator("{", True, whitespace=True)
            self.flow += 1
            self.push(flow=True)
            pairs = self.flow_pairs(d) if (self.indent or 0) < WIDTH else None
            if pairs is not None:
                self.flow_items(pairs, pairs=True)
                d = {}
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
        out, unicode = self.out, self.unicode
        for k, v in d.items():
            self.newline_indent()
            if type(k) is str and k:
                flow_plain, block_plain, _, n, _, spaced = _string(k, unicode)
                if n >= 128:
                    raise Unsupported("long key")
                if block_plain and not self.flow:
                    # a plain simple key, then ':' (indicator(":", False)): the column and flags after it
                    out.append((k + ":") if self.whitespace else (" " + k + ":"))
                    self.column += n + 1 + (not self.whitespace)
                    self.whitespace = self.indention = False
                else:
                    self.key(k)
                    self.indicator(":", False)
            else:
                self.key(k)
                self.indicator(":", False)
            t = type(v)
            if t is float or t is int:
                a = _float(v) if t is float else str(v)
                out.append(" " + a)
                self.column += len(a) + 1
            else:
                self.node(v, True)
        self.indent = self.indents.pop()


def _is_scalar(x) -> bool:
    """A node PyYAML represents as a plain-tagged scalar (the flow-style test of its representer)."""
    return x is None or type(x) in (str, int, float, bool) or isinstance(x, (int, float)) or (
        not isinstance(x, (dict, list, tuple)) and type(x).__module__.startswith("numpy") and getattr(x, "ndim", 1) == 0)


class _Slow(Exception):
    """A node the straight-line writer below leaves to :class:`_Writer`."""


@lru_cache(maxsize=4096)
def _token(text: str, unicode: bool, flow: bool, key: bool) -> str | None:
    """``text`` as PyYAML writes it as one token (plain, or single-quoted with ' doubled) when it
    can never be split (no space, or a simple key), else None; :class:`Unsupported` as
    :meth:`_Writer.scalar` raises it."""
    flow_plain, block_plain, single, n, empty, spaced = _string(text, unicode)
    if key and (n >= 128 or not text):
        return None
    if spaced and not key:
        return None
    if (not (key and empty)) and (flow_plain if flow else block_plain):
        return text or None
    if single:
        return "'" + text.replace("'", "''") + "'"
    raise Unsupported("double-quoted")


def _spaced_token(text: str, unicode: bool) -> str:
    """A block value with spaces, as one token: the caller writes it only where it ends within the
    width (PyYAML breaks such a scalar only at a space past the width)."""
    flow_plain, block_plain, single, n, empty, spaced = _string(text, unicode)
    if block_plain and text:
        return text
    if single:
        return "'" + text.replace("'", "''") + "'"
    raise Unsupported("double-quoted")


def _scalar_token(x, unicode: bool, flow: bool, key: bool) -> str:
    t = type(x)
    if t is str:
        tok = _token(x, unicode, flow, key)
        if tok is None:
            raise _Slow
        return tok
    a = _atom(x)
    if a is None:
        raise _Slow
    return a


def _lay_flow(texts, col: int, ws: bool, indent: int, out: list[str], pairs: bool) -> tuple[int, bool, bool]:
    """The items of a flow collection written as texts (atoms: never split) from column ``col``
    (``ws``: after whitespace), PyYAML's break (newline_indent: past the width, always a new
    line) before an item that starts past the width; with ``pairs`` the texts are key, value,
    key, value… (``key: value``, indicator ":" then the value after a space).  Returns the column
    and whitespace state after them, and whether any item was written."""
    first = True
    it = iter(texts)
    for t in it:
        if first:
            first = False
        else:
            out.append(",")
            col += 1
            ws = False
        if col > WIDTH:
            out.append("\n" + " " * indent)
            col, ws = indent, True
        if ws:
            out.append(t)
            col += len(t)
        else:
            out.append(" " + t)
            col += len(t) + 1
        if pairs:
            v = next(it)
            out.append(": " + v)
            col += len(v) + 2
        ws = False
    return col, ws, not first


def _flow(tokens: list[str], col: int, indent: int, out: list[str], close: str, pairs: bool) -> None:
    """The items of a flow collection after its opening bracket (at column ``col``), as
    :meth:`_Writer.flow_items` lays them out, then ``close``."""
    _lay_flow(tokens, col, True, indent, out, pairs)
    out.append(close)


def _flow_node(x, col: int, indent: int, out: list[str], unicode: bool, seen: set) -> None:
    """A flow list or dict of scalars, its opening bracket at column ``col`` (after a space)."""
    if id(x) in seen:
        raise _Slow
    seen.add(id(x))
    if indent >= WIDTH:
        raise _Slow
    if type(x) is list:
        out.append(" [")
        _flow([_scalar_token(v, unicode, True, False) for v in x], col + 2, indent, out, "]", False)
    else:
        toks = []
        for k, v in x.items():
            toks.append(_scalar_token(k, unicode, True, True))
            toks.append(_scalar_token(v, unicode, True, False))
        out.append(" {")
        _flow(toks, col + 2, indent, out, "}", True)


def _kind(x) -> int:
    """0 an atom or str, 1 a flow collection (empty, or of plain scalars), 2 a block one; _Slow else."""
    t = type(x)
    if t in _ATOMS:
        return 0
    if t is list:
        if not x:
            return 1
        types = set(map(type, x))
        if types <= _ATOMS:
            return 1
        if types <= _NODES:
            return 2
    elif t is dict:
        if not x:
            return 1
        types = set(map(type, x.values()))
        if types <= _ATOMS:
            if not set(map(type, x)) <= _ATOMS:
                raise _Slow
            return 1
        if types <= _NODES:
            return 2
    raise _Slow


_NODES = _ATOMS | {list, dict}


def _block_map(d: dict, indent: int, out: list[str], unicode: bool, seen: set, head0: str) -> None:
    """A block mapping at ``indent``; its first key after ``head0`` (after '- ', or a new line)."""
    if id(d) in seen:
        raise _Slow
    seen.add(id(d))
    pad = "\n" + " " * indent
    head = head0
    for k, v in d.items():
        kt = _scalar_token(k, unicode, False, True)
        line = head + kt + ":"
        head = pad
        col = indent + len(kt) + 1
        t = type(v)
        if t is float:
            out.append(line + " " + _float(v))
            continue
        kind = _kind(v)
        if kind == 0:
            if t is str:
                tok = _token(v, unicode, False, False)
                if tok is None:
                    if not v:
                        out.append(line)
                        continue
                    tok = _spaced_token(v, unicode)
                    if col + 1 + len(tok) > WIDTH:
                        raise _Slow
            else:
                tok = _atom(v)
                if tok is None:             # (not a scalar this writer knows: the general one)
                    raise _Slow
            out.append(line + " " + tok)
        elif kind == 1:
            if not v:
                out.append(line + (" []" if t is list else " {}"))
                continue
            out.append(line)
            _flow_node(v, col, indent + 2, out, unicode, seen)
        elif t is dict:
            out.append(line)
            _block_map(v, indent + 2, out, unicode, seen, pad + "  ")
        else:
            out.append(line)
            _block_items(v, indent, out, unicode, seen)


def _block_items(xs: list, indent: int, out: list[str], unicode: bool, seen: set) -> None:
    """A block sequence at ``indent`` (the items' '- ' at that column)."""
    if id(xs) in seen:
        raise _Slow
    seen.add(id(xs))
    pad = "\n" + " " * indent
    for v in xs:
        kind = _kind(v)
        if kind == 2 and type(v) is dict:
            _block_map(v, indent + 2, out, unicode, seen, pad + "- ")
        elif kind == 1:
            if not v:
                out.append(pad + ("- []" if type(v) is list else "- {}"))
                continue
            out.append(pad + "-")
            _flow_node(v, indent + 1, indent + 2, out, unicode, seen)
        else:                                   # (a scalar item, or a list in a list)
            raise _Slow


def _straight(records: list, unicode: bool) -> str:
    """The common shape written in straight lines: a list of block records, each a mapping of
    scalars, flow collections of scalars, block mappings and lists of records; _Slow else."""
    out: list[str] = []
    seen: set[int] = {id(records)}
    head = "- "
    for rec in records:
        if type(rec) is not dict or _kind(rec) != 2:
            raise _Slow
        _block_map(rec, 2, out, unicode, seen, head)
        head = "\n- "
    out.append("\n")
    return "".join(out)


def dumps(records, allow_unicode: bool = True) -> str:
    """The YAML document of ``records`` (a list or any node above), or :class:`Unsupported`."""
    if type(records) not in (list, dict):
        raise Unsupported("a document that is not a collection")
    if type(records) is list and records:
        try:
            return _straight(records, allow_unicode)
        except _Slow:
            pass
    w = _Writer(allow_unicode)
    w.node(records)
    w.newline_indent()
    return "".join(w.out)
