"""Safe YAML reading with source positions and hard caps.

One pass over PyYAML's parser events (the libyaml-based CSafeLoader when
available, else SafeLoader; :mod:`dyncli.yamlevents`) builds plain data
straight from the events, with no node graph and no Python object
constructed by PyYAML.  Two cheaper readers come first, each giving the same
:class:`Document` or leaving the text to the next (the fixed cost of every
problem, issue #31): the block style problem files are written in is read by
its lines (:class:`_Lines`, no parser), and a document of plain data by
:class:`_Plain` from the parser's events, which hands anything else, with the
events read so far, to the general builder (one parse either way).  The rules:

* only the standard tags (str, int, float, bool, null, map, seq) are allowed
  -- a ``!!python/...`` or any custom tag is invalid input;
* the number of constructed nodes is capped, so alias expansion ("billion
  laughs") fails fast instead of exhausting memory;
* nesting depth, node count and document size are capped (depth and node
  count while parsing, before anything is built);
* duplicate mapping keys are an error;
* every value's (line, col) is recorded under its path tuple -- for a run of
  plain numbers in a list (``at: [0.0, 0.01, ...]`` with 100,000 times), only
  the run's packed marks and texts are kept, each turned into a position when
  a message asks for it (:class:`PathTable`);
* a long flow list of plain numbers is read by a scan of the text
  (:func:`_flow_numbers`), the parser meeting it blanked; anything unexpected
  reads the document again as written (the same values, positions, errors).
"""

from __future__ import annotations

import re
from collections.abc import Iterator, MutableMapping
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


_SHIFT = 32          # a packed mark: line << _SHIFT | column (0-based)


def _unpack(mark: int) -> tuple[int, int]:
    return (mark >> _SHIFT) + 1, (mark & ((1 << _SHIFT) - 1)) + 1


class PathTable(MutableMapping):
    """path tuple -> value: a plain dict (``eager``) and, for the leading run
    of plain numbers of a list, one entry per list (``runs``: the list's path
    -> the run's items, and how to turn an item into the value; None: the item
    is the value), so that a list of 100,000 numbers costs no dict entry per
    number.  A run covers indices ``0 .. len(items) - 1`` of its list; the
    list's other items, if any, are in ``eager``."""

    def __init__(self, eager: dict | None = None):
        self.eager: dict = {} if eager is None else eager
        self.runs: dict[tuple, tuple[Any, Any]] = {}     # (items: a list, or _FlowMarks made lazily)

    def __getitem__(self, path):
        try:
            return self.eager[path]
        except KeyError:
            pass
        if self.runs and path and type(path[-1]) is int:
            run = self.runs.get(path[:-1])
            if run is not None and 0 <= path[-1] < len(run[0]):
                item = run[0][path[-1]]
                return item if run[1] is None else run[1](item)
        raise KeyError(path)

    def __contains__(self, path) -> bool:
        if path in self.eager:
            return True
        if self.runs and type(path) is tuple and path and type(path[-1]) is int:
            run = self.runs.get(path[:-1])
            return run is not None and 0 <= path[-1] < len(run[0])
        return False

    def __setitem__(self, path, value) -> None:
        self.eager[path] = value

    def __delitem__(self, path) -> None:
        if path in self.eager:
            del self.eager[path]
            return
        if path in self:                 # a run's item: the run ends before it, the rest kept one by one
            items, to_value = self.runs.pop(path[:-1])
            for i in range(path[-1] + 1, len(items)):
                self.eager[path[:-1] + (i,)] = items[i] if to_value is None else to_value(items[i])
            if path[-1]:
                self.runs[path[:-1]] = (items[:path[-1]], to_value)
            return
        raise KeyError(path)

    def __iter__(self) -> Iterator:
        yield from self.eager
        for prefix, (items, _) in self.runs.items():
            for i in range(len(items)):
                yield prefix + (i,)

    def __len__(self) -> int:
        return len(self.eager) + sum(len(items) for items, _ in self.runs.values())


@dataclass
class Document:
    data: Any
    # path tuple -> (line, col), 1-based.  ``key_pos`` points at the key of a
    # mapping entry, ``pos`` at the value.
    pos: PathTable = field(default_factory=PathTable)
    key_pos: dict[tuple, tuple[int, int]] = field(default_factory=dict)
    # the source text of scalars YAML read as numbers or booleans (``012345671``,
    # ``1:30``, ``1.50``), by value path; ``path + ("<key>",)`` for mapping keys
    text: PathTable = field(default_factory=PathTable)

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


def _mark(event) -> tuple[int, int]:
    return event.start_mark.line + 1, event.start_mark.column + 1


def load(text: str | bytes) -> Document:
    """Parse one YAML document from ``text`` safely, in one pass over the
    parser's events (no node graph).  Raises YamlError."""
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
        lists = _flow_numbers(text)
        if lists is not None:               # long flow lists of plain numbers: read by a regex scan
            try:
                return _one_pass(lists[0], loader, lists[1])
            except Exception:               # anything unexpected (an error, a list not met as a list):
                pass                        # the text as written, the ordinary way (the same values, errors)
        return _lines_pass(text) or _plain_pass(text, loader)
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


def _one_pass(text: str, loader, lists: dict | None = None) -> Document:
    """The first document built straight from the event stream, which is
    read to its end.  The errors keep the order of a parse, then a compose,
    then a construction: a syntax error or a cap (raised while parsing) comes
    first, then an anchor error, then an empty file or several documents,
    then the first document's own errors (kept until the stream is read).
    ``lists``: the flow lists of numbers blanked in ``text`` (:func:`_flow_numbers`),
    each to be met as a list (else :class:`_Unmet`)."""
    from dyncli.yamlevents import Events, Stop

    events = Events(text, loader, (MAX_DEPTH, MAX_NODES, YamlError))
    builder = _Builder(events, lists)
    root_seen, second, late = False, None, None
    for ev in events:
        if not events.is_node(ev):
            continue
        if events.docs == 1 and not root_seen:
            root_seen = True
            try:
                builder.doc.data = builder.value(ev, events, (), 0)
            except Stop as stop:
                late = stop.error
        elif events.docs > 1 and second is None:
            second = _mark(ev)
    if events.composer_error is not None:
        raise events.composer_error
    if not root_seen:
        raise YamlError("file is empty: expected a problem (a mapping with 'type')", 1, 1)
    if second is not None:
        raise YamlError("file holds several YAML documents ('---'); use one document with 'problems: [...]'", *second)
    if late is not None:
        raise late
    if lists:
        raise _Unmet()                      # a blanked list was not read as a list (inside a string...)
    return builder.doc


def _lines_pass(text: str) -> Document | None:
    """The :class:`Document` of ``text`` read line by line by :class:`_Lines` when it is written
    in the common block style (see there), else None (the parser reads it)."""
    try:
        return _Lines(text).document()
    except _Bail:
        return None


_KEY = re.compile(r"[A-Za-z_][A-Za-z0-9_.\-]*(?=:(?: |$))").match     # a key of the block style (text)
_FLOW_PLAIN = re.compile(r"[^\s,\[\]{}:#'\"&*!|>%@`?][^,\[\]{}:#]*").match   # a plain scalar inside [...] or {...}
_STARTS = frozenset("[]{},#&*!|>'\"%@`?:")      # what a plain scalar may not start with
#: a row ``key: value``: the key, and the value when it is a plain scalar with no ``#`` (else None)
_ROW = re.compile(r"([A-Za-z_][A-Za-z0-9_.\-]*):(?: +(?:#.*|([^\s\[\]{},#&*!|>'\"%@`?:-][^#]*|-[^\s#][^#]*)|.*))?$").match
_PLAIN_IMPLICIT = (True, False)


class _Lines:
    """A reader of the block style every problem file is written in, by its lines (no parser):
    a mapping of ``key: value`` lines (keys are names), a value a plain or quoted scalar on its
    line, a flow list or mapping closed on its line, or a block mapping or list indented under
    its key; list items ``- value`` or ``- key: value`` (a mapping).  It records what the
    parser's events would give :class:`_Plain` -- values, positions (the parser's marks:
    a block collection at its first key or ``-``, a flow one at its bracket, a scalar at its
    first character or quote), texts, runs of plain numbers -- and raises :class:`_Bail` at
    anything else (an empty value, a scalar over several lines, an escape, an anchor, a tag,
    a key that is not a name, a duplicate, a value to refuse, a cap near...): the parser then
    reads the text, which gives the same Document or the error."""

    def __init__(self, text: str):
        lines = text.split("\n")
        if max(map(len, lines)) > 1000 or not text.replace("\n", " ").isprintable():
            raise _Bail           # (a long flow list: the scan of _flow_numbers; a tab, a control character)
        #: (line, indent, content) of the significant lines (not blank, not a comment)
        self.rows: list[tuple[int, int, str]] = [(n, len(raw) - len(c), c.rstrip(" ")) for n, raw in enumerate(lines)
                                                 if (c := raw.lstrip(" ")) and c[0] != "#"]
        # (a document marker or a directive, at the start of a line, is not a key: mapping() bails)
        self.i = 0
        self.doc = Document(None)
        self.pos, self.text, self.key_pos = self.doc.pos.eager, self.doc.text.eager, self.doc.key_pos
        self.count = 0
        self.most = MAX_NODES - 2
        self.deepest = MAX_DEPTH - 2

    def document(self) -> Document:
        if not self.rows or self.rows[0][1] != 0 or _KEY(self.rows[0][2]) is None:
            raise _Bail                         # (a document that is not a mapping of names)
        self.doc.data = self.mapping((), 0, 0)
        if self.i != len(self.rows):
            raise _Bail
        return self.doc

    def counted(self, path: tuple, line: int, col: int, depth: int) -> None:
        self.count += 1
        if self.count > self.most or depth >= self.deepest:
            raise _Bail
        self.pos[path] = (line + 1, col + 1)

    def mapping(self, path: tuple, indent: int, depth: int) -> dict:
        """The block mapping whose first key is the row at ``self.i``, its keys at ``indent``."""
        rows, out = self.rows, {}
        i = self.i
        self.counted(path, rows[i][0], indent, depth)
        n, pos, key_pos, tags = len(rows), self.pos, self.key_pos, _PLAIN_TAGS
        while i < n:
            line, at, content = rows[i]
            if at != indent:
                if at > indent:
                    raise _Bail                 # (a line more indented: a scalar over lines, an error)
                break
            m = _ROW(content)
            if m is None:
                raise _Bail
            key, v = m.group(1, 2)
            if key in out or (tags.get(key) or _tag_of(key)) != _STR:
                raise _Bail                     # (a duplicate, a key YAML reads as true, null...)
            here = path + (key,)
            key_pos[here] = (line + 1, indent + 1)
            i += 1
            if v is not None and ": " not in v and v[-1] != ":":     # a plain scalar (the common line)
                self.count += 2
                if self.count > self.most or i < n and rows[i][1] > indent:
                    raise _Bail                 # (a cap near; the next line more indented: its continuation)
                pos[here] = (line + 1, indent + m.start(2) + 1)
                tag = tags.get(v) or _tag_of(v)
                out[key] = v if tag == _STR else None if tag == _NULL else self.typed(v, tag, here)
                continue
            self.count += 1
            self.i = i
            rest = content[m.end(1) + 1:].lstrip(" ")
            if rest and rest[0] != "#":
                out[key] = self.inline(rest, line, indent + len(content) - len(rest), here, depth + 1)
            elif i == n or rows[i][1] <= indent:
                raise _Bail                     # (an empty value: null, its mark where the next token is)
            elif (nxt := rows[i][2])[0] == "-" and (len(nxt) == 1 or nxt[1] == " "):
                out[key] = self.sequence(here, rows[i][1], depth + 1)
            elif _KEY(nxt) is not None:
                out[key] = self.mapping(here, rows[i][1], depth + 1)
            else:
                raise _Bail
            i = self.i
        self.i = i
        return out

    def sequence(self, path: tuple, indent: int, depth: int) -> list:
        """The block list whose first ``-`` is the row at ``self.i``, at ``indent``."""
        rows, out = self.rows, list[Any]()
        self.counted(path, rows[self.i][0], indent, depth)
        marks: list[int] = []
        texts: list[str] = []
        while self.i < len(rows):
            line, at, content = rows[self.i]
            if at != indent:
                if at > indent:
                    raise _Bail
                break
            if content[0] != "-" or len(content) < 3 or content[1] != " ":
                raise _Bail                     # (not an item, or an item with nothing on its line)
            rest = content[2:].lstrip(" ")
            col = indent + len(content) - len(rest)
            here = path + (len(out),)
            if _KEY(rest) is not None:          # "- key: value ...": a mapping, its keys at col
                self.rows[self.i] = (line, col, rest)
                out.append(self.mapping(here, col, depth + 1))
                continue
            self.i += 1
            if not out or len(marks) == len(out):
                v = rest.split(" #", 1)[0].rstrip(" ") if rest[0] not in _STARTS else ""
                if v and _NUMBER(v) is not None and not (v[0] == "-" and v[1:2] == " "):
                    self.count += 1
                    if self.count > self.most:
                        raise _Bail
                    out.append(float(v) if "." in v else int(v))
                    marks.append(line << _SHIFT | col)
                    texts.append(v)
                    self.next_shallower(indent)
                    continue
            out.append(self.inline(rest, line, col, here, depth + 1))
        if marks:
            self.doc.pos.runs[path] = (marks, _unpack)
            self.doc.text.runs[path] = (texts, None)
        return out

    def next_shallower(self, indent: int) -> None:
        """A plain scalar ends its line: the next row may not be more indented (its continuation)."""
        if self.i < len(self.rows) and self.rows[self.i][1] > indent:
            raise _Bail

    def inline(self, rest: str, line: int, col: int, path: tuple, depth: int) -> Any:
        """The value written on its line from column ``col`` (``rest``, not a comment)."""
        c = rest[0]
        if c == "[" or c == "{":
            value, end = self.flow(rest, 0, line, col, path, depth)
            _comment_only(rest, end)
        elif c == '"' or c == "'":
            end = _closing(rest, 0)
            _comment_only(rest, end)
            self.counted(path, line, col, depth)
            value = rest[1:end - 1]
        else:
            if c in _STARTS or c == "-" and (len(rest) == 1 or rest[1] == " "):
                raise _Bail
            v = rest.split(" #", 1)[0].rstrip(" ")
            if ": " in v or v[-1] == ":":
                raise _Bail
            self.counted(path, line, col, depth)
            value = self.scalar(v, path)
        self.next_shallower(self.rows[self.i - 1][1])
        return value

    def scalar(self, v: str, path: tuple) -> Any:
        tag = _PLAIN_TAGS.get(v) or _tag_of(v)
        return v if tag == _STR else None if tag == _NULL else self.typed(v, tag, path)

    def typed(self, v: str, tag: str, path: tuple) -> Any:
        return _typed(self.text, path, v, tag)

    def flow(self, s: str, j: int, line: int, col0: int, path: tuple, depth: int) -> tuple[Any, int]:
        """The flow list or mapping at ``s[j]`` (``[`` or ``{``) of a line whose ``s[0]`` is at
        column ``col0``, closed on the line, and the index after it."""
        self.counted(path, line, col0 + j, depth)
        is_list = s[j] == "["
        close = "]" if is_list else "}"
        out: Any = [] if is_list else {}
        marks: list[int] = []
        texts: list[str] = []
        n = len(s)
        j = _skip(s, j + 1)
        if j < n and s[j] == close:
            return out, j + 1
        while j < n:
            if is_list:
                here = path + (len(out),)
                if s[j] == "[" or s[j] == "{":
                    value, j = self.flow(s, j, line, col0, here, depth + 1)
                elif len(marks) == len(out) and (m := _FLOW_NUMBER(s, j)) is not None:
                    v = m.group()                 # the leading run of plain numbers (_Builder.numbers)
                    self.count += 1
                    if self.count > self.most:
                        raise _Bail
                    value = float(v) if "." in v else int(v)
                    marks.append(line << _SHIFT | (col0 + j))
                    texts.append(v)
                    j = m.end()
                else:
                    value, j = self.flow_scalar(s, j, line, col0, here, depth + 1)
                out.append(value)
            elif (m := _FLOW_PAIR(s, j)) is not None:     # key: plain scalar (the common entry)
                key, v = m.group(1, 2)
                if key in out or (_PLAIN_TAGS.get(key) or _tag_of(key)) != _STR or depth + 1 >= self.deepest:
                    raise _Bail
                self.count += 2
                if self.count > self.most:
                    raise _Bail
                here = path + (key,)
                self.key_pos[here] = (line + 1, col0 + j + 1)
                self.pos[here] = (line + 1, col0 + m.start(2) + 1)
                out[key] = self.scalar(v, here)
                j = m.end()
            else:
                m = _FLOW_KEY(s, j)
                if m is None:
                    raise _Bail
                key = m.group()
                if key in out or (_PLAIN_TAGS.get(key) or _tag_of(key)) != _STR:
                    raise _Bail
                self.count += 1
                here = path + (key,)
                self.key_pos[here] = (line + 1, col0 + j + 1)
                j = _skip(s, m.end() + 1)
                if j >= n or s[j] == "," or s[j] == "}":
                    raise _Bail                 # (an empty value)
                if s[j] == "[" or s[j] == "{":
                    out[key], j = self.flow(s, j, line, col0, here, depth + 1)
                else:
                    out[key], j = self.flow_scalar(s, j, line, col0, here, depth + 1)
            j = _skip(s, j)
            if j < n and s[j] == close:
                if marks:
                    self.doc.pos.runs[path] = (marks, _unpack)
                    self.doc.text.runs[path] = (texts, None)
                return out, j + 1
            if j >= n or s[j] != ",":
                break
            j = _skip(s, j + 1)
            if j < n and s[j] == close:
                break                           # (a comma before the bracket)
        raise _Bail

    def flow_scalar(self, s: str, j: int, line: int, col0: int, path: tuple, depth: int) -> tuple[Any, int]:
        """A scalar inside a flow collection at ``s[j]`` and the index after it."""
        self.counted(path, line, col0 + j, depth)
        c = s[j]
        if c == '"' or c == "'":
            end = _closing(s, j)
            return s[j + 1:end - 1], end
        m = _FLOW_PLAIN(s, j)
        if m is None or c == "-" and s[j + 1:j + 2] in (" ", ",", "]", "}", ""):
            raise _Bail
        v = m.group().rstrip(" ")
        return self.scalar(v, path), j + len(v)


def _skip(s: str, j: int) -> int:
    """The index of the first character from ``j`` that is not a space."""
    n = len(s)
    while j < n and s[j] == " ":
        j += 1
    return j


def _typed(texts, path: tuple, v: str, tag: str) -> Any:
    """The value of a plain scalar of ``tag`` other than str and null (its text kept in
    ``texts``), as the builder makes it; anything else (a date: the builder refuses it, an int
    of more digits than Python reads) is :class:`_Bail`."""
    if tag != _INT and tag != _FLOAT and tag != _BOOL:
        raise _Bail
    texts[path] = v
    try:
        if tag != _BOOL and _NUMBER(v) is not None:
            return float(v) if "." in v else int(v)
        return _scalar(tag, v)
    except (ValueError, OverflowError, IndexError):
        raise _Bail from None


def _closing(s: str, j: int) -> int:
    """The index after the quote that closes the quoted scalar at ``s[j]`` on its line (no
    escape, no doubled quote: those are the parser's)."""
    q = s[j]
    end = s.find(q, j + 1)
    if end < 0 or "\\" in s[j:end] or s[end + 1:end + 2] == q:
        raise _Bail
    return end + 1


def _comment_only(s: str, end: int) -> None:
    """Nothing after ``s[:end]`` on its line but spaces and a comment after a space."""
    tail = s[end:]
    if tail and (tail[0] != " " or tail.lstrip(" ")[:1] not in ("", "#")):
        raise _Bail


_FLOW_KEY = re.compile(r"[A-Za-z_][A-Za-z0-9_.\-]*(?=: )").match
#: ``key: value`` in a flow mapping, the value a plain scalar (as :data:`_FLOW_PLAIN`) ending at ``,`` or ``}``
_FLOW_PAIR = re.compile(r"([A-Za-z_][A-Za-z0-9_.\-]*): +([^\s,\[\]{}:#'\"&*!|>%@`?-][^,\[\]{}:#]*?"
                        r"|-[^\s,\[\]{}:#][^,\[\]{}:#]*?) *(?=[,}])").match
#: a plain number (as :data:`_NUMBER` reads it) that ends where a flow scalar ends
_FLOW_NUMBER = re.compile(r"[-+]?(?:0|[1-9][0-9]*|[0-9]+\.[0-9]*(?:[eE][-+][0-9]+)?)(?= *[,\]])").match


def _tag_of(value: str) -> str:
    """The tag a plain scalar's text resolves to (remembered by its text, as :func:`_resolved`
    remembers it by text and implicit flags)."""
    import yaml

    if not _RESOLVER:
        _RESOLVER.append(yaml.resolver.Resolver())
    tag = _RESOLVER[0].resolve(yaml.ScalarNode, value, _PLAIN_IMPLICIT)
    if len(_PLAIN_TAGS) < 4096:
        _PLAIN_TAGS[value] = tag
    return tag


_PLAIN_TAGS: dict[str, str] = {}      # a plain scalar's text -> its resolved tag (for _Lines)


class _Bail(Exception):
    """:class:`_Plain` meets what only :class:`_Builder` handles (an anchor, an alias, a tag, a
    key that is not text, a value to refuse, a cap near): the events read so far are handed over."""


class _Replay:
    """A loader whose events are ``seen`` (already read from ``loader``) and then the rest of
    ``loader``'s: :func:`_one_pass` carries on where :class:`_Plain` stopped, with no second parse."""

    def __init__(self, seen: list, loader):
        self._seen, self._i, self._loader = seen, 0, loader

    def get_event(self):
        if self._i < len(self._seen):
            self._i += 1
            return self._seen[self._i - 1]
        return self._loader.get_event()

    def dispose(self) -> None:
        self._loader.dispose()


def _plain_pass(text: str, loader) -> Document:
    """The document of ``text`` read by :class:`_Plain` (a document of plain data: no anchor, alias
    or tag, text keys, nothing to refuse, far from the caps: every problem file as usually written),
    else by :func:`_one_pass`, which is handed the events read so far -- one parse either way, and
    the same :class:`Document` (data, positions, texts, runs) or the same error."""
    ld = loader(text)
    plain = _Plain(ld.get_event)
    try:
        doc = plain.document()
    except _Bail:
        return _one_pass(text, lambda _text: _Replay(plain.seen, ld))
    ld.dispose()
    return doc


def _resolved(ev) -> str:
    """The tag of a scalar event with no tag of its own, as a composer resolves it (remembered
    by its text: a document repeats its keys and numbers)."""
    key = (ev.value, ev.implicit)
    tag = _TAGS.get(key)
    if tag is None:
        import yaml

        if not _RESOLVER:
            _RESOLVER.append(yaml.resolver.Resolver())
        tag = _RESOLVER[0].resolve(yaml.ScalarNode, ev.value, ev.implicit)
        if len(_TAGS) < 4096:
            _TAGS[key] = tag
    return tag


_RESOLVER: list = []        # the resolver (stateless: no path resolvers), made at the first use


class _Plain:
    """The :class:`Document` of a document of plain data, built straight from the parser's events
    with what :class:`_Builder` would record (values, positions, texts, the runs of plain numbers of
    a list); anything else raises :class:`_Bail` (``seen``: every event read, for :class:`_Replay`).
    (The common entry, a key and a plain scalar, is read in :meth:`mapping` itself: this pass is a
    fixed cost of every problem.)"""

    def __init__(self, get):
        import yaml

        self.seen: list = []
        self.get, self.keep = get, self.seen.append
        self.doc = Document(None)
        self.pos, self.text = self.doc.pos.eager, self.doc.text.eager
        self.count = 0
        self.most = MAX_NODES - 2                 # (read now: the caps are the module's, tests lower them)
        self.deepest = MAX_DEPTH - 2
        self.y = yaml
        self.scalar, self.mapping_end, self.sequence_end = yaml.ScalarEvent, yaml.MappingEndEvent, yaml.SequenceEndEvent

    def next(self):
        ev = self.get()
        self.keep(ev)
        return ev

    def document(self) -> Document:
        y, nxt = self.y, self.next
        if type(nxt()) is not y.StreamStartEvent or type(nxt()) is not y.DocumentStartEvent:
            raise _Bail                           # (an empty stream: the builder's message)
        data = self.value(nxt(), (), 0)
        if type(nxt()) is not y.DocumentEndEvent or type(nxt()) is not y.StreamEndEvent:
            raise _Bail                           # (several documents)
        self.doc.data = data
        return self.doc

    def value(self, ev, path: tuple, depth: int) -> Any:
        if type(ev) is self.y.AliasEvent or ev.tag is not None or ev.anchor is not None or depth >= self.deepest:
            raise _Bail
        self.count += 1
        if self.count > self.most:
            raise _Bail
        m = ev.start_mark
        self.pos[path] = (m.line + 1, m.column + 1)
        cls = type(ev)
        if cls is self.scalar:
            v = ev.value
            tag = _TAGS.get((v, ev.implicit)) or _resolved(ev)
            return v if tag == _STR else None if tag == _NULL else self.typed(path, v, tag)
        if cls is self.y.MappingStartEvent:
            return self.mapping(path, depth)
        return self.sequence(path, depth)

    def typed(self, path: tuple, v: str, tag: str) -> Any:
        return _typed(self.text, path, v, tag)

    def sequence(self, path: tuple, depth: int) -> list:
        get, keep, scalar, number = self.get, self.keep, self.scalar, _NUMBER
        out: list = []
        marks: list[int] = []
        texts: list[str] = []
        ev = get()
        keep(ev)
        while type(ev) is scalar and ev.tag is None and ev.anchor is None and ev.implicit[0] \
                and number(ev.value) is not None:     # the leading run of plain numbers (_Builder.numbers)
            self.count += 1
            if self.count > self.most:
                raise _Bail
            v, m = ev.value, ev.start_mark
            try:
                out.append(float(v) if "." in v else int(v))
            except ValueError:                    # (an int of more digits than Python reads)
                raise _Bail from None
            marks.append(m.line << _SHIFT | m.column)
            texts.append(v)
            ev = get()
            keep(ev)
        if marks:
            self.doc.pos.runs[path] = (marks, _unpack)
            self.doc.text.runs[path] = (texts, None)
        end = self.sequence_end
        while type(ev) is not end:
            out.append(self.value(ev, path + (len(out),), depth + 1))
            ev = get()
            keep(ev)
        return out

    def mapping(self, path: tuple, depth: int) -> dict:
        get, keep, scalar, end = self.get, self.keep, self.scalar, self.mapping_end
        pos, key_pos, tags = self.pos, self.doc.key_pos, _TAGS
        out: dict = {}
        while True:
            kev = get()
            keep(kev)
            if type(kev) is not scalar:
                if type(kev) is end:
                    return out
                raise _Bail                       # (a key that is a list or a mapping, an alias)
            key = kev.value
            if kev.tag is not None or kev.anchor is not None or key in out or key == "<key>" \
                    or (tags.get((key, kev.implicit)) or _resolved(kev)) != _STR:
                raise _Bail                       # (a key not text, a duplicate: the builder's)
            m = kev.start_mark
            here = path + (key,)
            key_pos[here] = (m.line + 1, m.column + 1)
            ev = get()
            keep(ev)
            if type(ev) is scalar and ev.tag is None and ev.anchor is None:
                self.count += 2                   # the key and its value
                if self.count > self.most:
                    raise _Bail
                m = ev.start_mark
                pos[here] = (m.line + 1, m.column + 1)
                v = ev.value
                tag = tags.get((v, ev.implicit)) or _resolved(ev)
                out[key] = v if tag == _STR else None if tag == _NULL else self.typed(here, v, tag)
            else:
                self.count += 1
                out[key] = self.value(ev, here, depth + 1)


_STR, _NULL, _INT, _FLOAT, _BOOL = (_STD + t for t in ("str", "null", "int", "float", "bool"))


class _Unmet(Exception):
    """A flow list of numbers read by :func:`_flow_numbers` is not where the parser says a plain
    list of the document starts (inside a quoted string, a comment, an anchored value, beyond a
    cap...): the document is read again as written."""


#: a flow list long enough to be worth a scan (characters between its brackets)
_SCAN_FROM = 256
_FLOW = re.compile(r"\[([-+0-9.eE, \n]{%d,})\]" % _SCAN_FROM)
_TOKEN = r"[-+]?(?:0|[1-9][0-9]*)(?:\.[0-9]*(?:[eE][-+][0-9]+)?)?"     # (within _NUMBER's texts)
# plain numbers (as :data:`_NUMBER` reads them) separated by commas, spaces and line breaks only
# around the commas (a line break inside an entry would fold two numbers into one text)
_FLOW_LIST = re.compile(rf"[ \n]*{_TOKEN}(?:[ \n]*,[ \n]*{_TOKEN})*[ \n]*").fullmatch
_TEXTS = re.compile(r"[^ \n,]+").findall
_BLANK = str.maketrans({c: " " for c in "-+0123456789.eE,"})


def _flow_numbers(text: str) -> tuple[str, dict] | None:
    """``text`` with every long flow list of plain numbers (``at: [0.0, 0.001, ...]`` with 1e5
    times) blanked between its brackets (the same length, its line breaks kept: every other
    position unchanged, and the parser meets ``[  ...  ]``, an empty list), and ``{index of its
    "[": (its values, its items' texts, the text between the brackets)}``; None when there is
    none.  The items are read here at C speed (not an event of the parser each);
    :meth:`_Builder.scanned` puts them in the list the parser starts at that index."""
    found = []
    for m in _FLOW.finditer(text):
        got = _flow_items(m.group(1))
        if got is not None:
            found.append((m.start(), m.group(1), got))
    if not found:
        return None
    parts, last, lists = [], 0, {}
    for at, inner, (values, texts) in found:
        lists[at] = (values, texts, inner)
        parts += [text[last:at + 1], inner.translate(_BLANK)]
        last = at + 1 + len(inner)
    parts.append(text[last:])
    return "".join(parts), lists


def _flow_items(inner: str) -> tuple[list, list[str]] | None:
    """(values, texts) of the items of a flow list whose text between the brackets is ``inner``
    (made of the characters of numbers, commas, spaces and line breaks) when every item is a plain
    number that YAML reads as :data:`_NUMBER` does (the same values), else None.  The common case
    — floats with their dot, each after ", " — is decided by string operations: no line break,
    no other space, no empty item; then every item has exactly one dot (a float, not an int or a
    text such as ``1.2.3``), every exponent is signed (``1.0e5`` is text in YAML 1.1), and
    ``float`` reads each (so each is ``[-+]?[0-9]*.[0-9]*([eE][-+][0-9]+)?``, YAML's float, whose
    value is ``float``'s).  Any other list is checked item by item by a regular expression."""
    compact = inner.replace(", ", ",")
    if " " not in compact and "\n" not in compact:
        texts = compact.split(",")
        if inner.count(".") == len(texts) and "" not in texts and \
                inner.count("e") + inner.count("E") == sum(inner.count(e) for e in ("e+", "e-", "E+", "E-")):
            try:
                return list(map(float, texts)), texts
            except ValueError:
                return None
    if not _FLOW_LIST(inner):
        return None
    texts = _TEXTS(inner)
    try:
        return [float(v) if "." in v else int(v) for v in texts], texts
    except ValueError:                          # (an int of more digits than Python reads)
        return None


class _FlowMarks:
    """The packed marks (line << _SHIFT | column, 0-based) of the items of a flow list read by
    :func:`_flow_numbers`, made when a message first asks for one (a list of 1e5 times read
    without error never needs them): ``inner`` the text between its brackets, ``line``/``col``
    its ``[``'s."""

    def __init__(self, inner: str, line: int, col: int, n: int):
        self.inner, self.line, self.col, self.n, self.marks = inner, line, col, n, None

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, i):
        if self.marks is None:
            marks, inner = [], self.inner
            for m in re.finditer(r"[^ \n,]+", inner):
                k = m.start()
                nl = inner.count("\n", 0, k)
                col = self.col + 1 + k if not nl else k - inner.rfind("\n", 0, k) - 1
                marks.append((self.line + nl) << _SHIFT | col)
            self.marks = marks
        return self.marks[i]


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


_TAGS: dict[tuple, str] = {}      # (plain scalar's text, implicit) -> its resolved tag

# the plain scalars YAML 1.1 reads as a decimal int (no "0" prefix: octal) or a
# float with a dot (its exponent signed), with no "_": exactly Python's int()/float()
# of the text, the int/float resolver's and constructor's value
_NUMBER = re.compile(r"[-+]?(?:0|[1-9][0-9]*|[0-9]+\.[0-9]*(?:[eE][-+][0-9]+)?)").fullmatch


class _Builder:
    """Plain data and its positions from the events of one document (the
    standard tags only, the constructed values capped: aliases are built
    again from their anchor's events, so an alias bomb stops at the cap)."""

    def __init__(self, events, lists: dict | None = None):
        import yaml

        self.events, self.doc, self.count = events, Document(None), 0
        self.lists = lists              # the flow lists of numbers read by _flow_numbers, by index
        self.pos, self.text = self.doc.pos.eager, self.doc.text.eager
        self.resolver = yaml.resolver.Resolver()
        self.y = yaml

    def tag(self, ev) -> str:
        """The event's tag, resolved as a composer would (plain scalars' tags
        remembered by their text: a document repeats its keys and numbers)."""
        y = self.y
        tag = ev.tag
        if tag is None or tag == "!":
            if type(ev) is y.ScalarEvent:
                key = (ev.value, ev.implicit)
                tag = _TAGS.get(key)
                if tag is None:
                    tag = self.resolver.resolve(y.ScalarNode, ev.value, ev.implicit)
                    if len(_TAGS) < 4096:
                        _TAGS[key] = tag
                return tag
            kind = y.SequenceNode if type(ev) is y.SequenceStartEvent else y.MappingNode
            tag = self.resolver.resolve(kind, None, ev.implicit)
        return tag

    def value(self, ev, it, path: tuple, depth: int) -> Any:
        """The value that starts with event ``ev`` (its content read from ``it``)."""
        y = self.y
        if type(ev) is y.AliasEvent:
            ev, it = self.replay(ev)
        self.count += 1
        line, col = _mark(ev)
        if self.count > MAX_NODES:
            raise _stop(f"document expands to more than {MAX_NODES} values (alias bomb?)", line, col)
        if depth > MAX_DEPTH:
            raise _stop(f"document is nested more than {MAX_DEPTH} levels deep", line, col)
        self.pos.setdefault(path, (line, col))
        tag, cls = self.tag(ev), type(ev)
        if tag == _STD + "timestamp" and cls is y.ScalarEvent:
            raise _stop(f"{ev.value!r} reads as a date; write a number (or quote it for text)", line, col)
        if tag not in _ALLOWED_TAGS:
            raise _stop(f"YAML tag {tag!r} is not allowed (only plain data: no tags)", line, col)
        if cls is y.ScalarEvent:
            if tag != _STD + "str" and tag != _STD + "null":
                self.text[path] = ev.value
            try:
                return _scalar(tag, ev.value)
            except (ValueError, OverflowError, IndexError):     # IndexError: an empty "!!float"
                shown = ev.value if len(ev.value) <= 40 else ev.value[:37] + "..."
                raise _stop(f"cannot read value {shown!r} ({len(ev.value)} characters)", line, col) from None
        if cls is y.SequenceStartEvent:
            if self.lists and ev.start_mark.index in self.lists:
                return self.scanned(ev, it, path, depth)
            out: list[Any] = []
            if it is self.events and depth < MAX_DEPTH:
                child = self.numbers(path, out)
                if type(child) is y.SequenceEndEvent:
                    return out
                out.append(self.value(child, it, path + (len(out),), depth + 1))
            for child in it:
                if type(child) is y.SequenceEndEvent:
                    return out
                out.append(self.value(child, it, path + (len(out),), depth + 1))
            return out
        return self.mapping(it, path, depth)

    def scanned(self, ev, it, path: tuple, depth: int) -> list:
        """The list of numbers :func:`_flow_numbers` read, whose blanked ``[ ... ]`` starts at
        ``ev``: the same values, counts and caps as :meth:`numbers` (a cap reached, an anchor,
        a tag or a list met otherwise than directly: :class:`_Unmet`, read again as written)."""
        assert self.lists is not None           # (called only for a list it holds)
        out, texts, inner = self.lists.pop(ev.start_mark.index)
        events, n = self.events, len(texts)
        if it is not events or not depth < MAX_DEPTH or ev.anchor is not None or ev.tag is not None \
                or events.recording() or events.values + n > MAX_NODES or self.count + n > MAX_NODES:
            raise _Unmet()
        end = next(it)
        if type(end) is not self.y.SequenceEndEvent:
            raise _Unmet()
        events.values += n
        self.count += n
        m = ev.start_mark
        self.doc.pos.runs[path] = (_FlowMarks(inner, m.line, m.column, n), _unpack)
        self.doc.text.runs[path] = (texts, None)
        return out

    def numbers(self, path: tuple, out: list) -> Any:
        """The leading run of plain numbers of the list at ``path`` read into
        ``out`` straight from the parser (the same values, counts and caps as
        :meth:`value`), their marks and texts kept per run; returns the first
        event after the run."""
        marks: list[int] = []
        texts: list[str] = []
        number, shift = _NUMBER, _SHIFT

        def take(ev) -> bool:
            v = ev.value
            if number(v) is None:
                return False
            try:
                x = float(v) if "." in v else int(v)
            except ValueError:          # an int of more digits than Python reads: refused by value()
                return False
            self.count += 1
            m = ev.start_mark
            if self.count > MAX_NODES:
                raise _stop(f"document expands to more than {MAX_NODES} values (alias bomb?)", m.line + 1, m.column + 1)
            out.append(x)
            marks.append(m.line << shift | m.column)
            texts.append(v)
            return True

        try:
            return self.events.plain_scalars(take)
        finally:
            if marks:
                self.doc.pos.runs[path] = (marks, _unpack)
                self.doc.text.runs[path] = (texts, None)

    def mapping(self, it, path: tuple, depth: int) -> dict:
        y, doc = self.y, self.doc
        out: dict = {}
        for kev in it:
            if type(kev) is y.MappingEndEvent:
                return out
            kit = it
            if type(kev) is y.AliasEvent:
                kev, kit = self.replay(kev)
            kl, kc = _mark(kev)
            ktag = self.tag(kev)
            if ktag == _STD + "merge" or (type(kev) is y.ScalarEvent and kev.value == "<<" and ktag != _STD + "str"):
                raise _stop("YAML merge keys ('<<') are not supported", kl, kc)
            if type(kev) is not y.ScalarEvent:
                raise _stop("mapping keys must be plain names", kl, kc)
            key = self.value(kev, kit, path + ("<key>",), depth + 1)
            self.pos.pop(path + ("<key>",), None)
            ktext = self.text.pop(path + ("<key>",), None)
            if not isinstance(key, (str, int)) or isinstance(key, bool):
                key = str(kev.value)
            if key in out:
                raise _stop(f"duplicate key {key!r}", kl, kc)
            doc.key_pos[path + (key,)] = (kl, kc)
            if ktext is not None:
                self.text[path + (key, "<key>")] = ktext
            out[key] = self.value(next(it), it, path + (key,), depth + 1)
        return out  # pragma: no cover - the stream always closes a mapping

    def replay(self, ev):
        """The first event of the value an alias names, and its other events."""
        from dyncli.yamlevents import Stop

        events = self.events.alias(ev)
        if events is None:
            raise Stop(None)        # the stream keeps the composer's error
        rest = iter(events)
        return next(rest), rest


def _stop(message: str, line: int, col: int):
    from dyncli.yamlevents import Stop

    return Stop(YamlError(message, line, col))


def _scalar(tag: str, val: str) -> Any:
    """Construct a plain scalar the way SafeLoader would, for the std tags."""
    import yaml

    if tag == _STD + "str":
        return val
    if tag == _STD + "null":
        return None
    if tag == _STD + "bool":
        return val.lower() in ("yes", "true", "on", "y")
    if tag == _STD + "int":
        return yaml.SafeLoader.construct_yaml_int(_DUMMY, val)
    if tag == _STD + "float":
        return yaml.SafeLoader.construct_yaml_float(_DUMMY, val)
    return val  # pragma: no cover


class _Dummy:
    inf_value = float("inf")
    nan_value = float("nan")

    def construct_scalar(self, value):
        return value         # the scalar's text itself stands for its node


_DUMMY = _Dummy()
