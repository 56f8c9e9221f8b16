"""dyncli's own tables: the terminal view's tables and lines, laid out
without the table library.

The views (:mod:`dyncli.render.table`, the ``check`` reports) build
:class:`Table` and :class:`Text` objects of this module (the small part of
rich's API they use) and print them on an :class:`Out`:

* off a terminal (a pipe, a file, ``-o``) :func:`lines` lays them out
  directly — rich is never imported: a 10,000-point sweep or a batch prints
  at the speed of JSON;
* on a terminal each fitted table is drawn by rich (colour, styles) from the
  same cells, so the characters are the same (``tests/api/test_plain_tables.py``
  compares the two on every example).

Every table is fitted to the output's width first (:func:`fit`): a cell too
wide is broken at a space outside a vector (``[a, b, c]`` is never cut), a
table still too wide is split into several whose first column repeats
(``(continued)``); a title or caption is one line, centred over its table,
never wrapped; a line of text wider than the width is broken between words.
"""

from __future__ import annotations

import bisect
import re
import unicodedata

SIMPLE, SIMPLE_HEAD, SQUARE = "simple", "simple_head", "square"
ENABLED = True     # the tests switch it off to compare with rich


class box:  # noqa: N801 - rich's spelling (``box.SIMPLE_HEAD``)
    SIMPLE, SIMPLE_HEAD, SQUARE = SIMPLE, SIMPLE_HEAD, SQUARE


def cell_len(text: str) -> int:
    """Columns a string takes in a terminal: wide (East Asian) characters 2,
    combining marks and control characters 0."""
    if text.isascii():
        return len(text)
    n = 0
    for ch in text:
        o = ord(ch)
        if o < 32 or 0x7F <= o < 0xA0 or unicodedata.combining(ch) or unicodedata.category(ch) in ("Mn", "Me"):
            continue
        n += 2 if unicodedata.east_asian_width(ch) in ("W", "F") else 1
    return n


class Text:
    """A line of styled text: ``plain`` and its (text, style) spans."""

    __slots__ = ("plain", "spans", "style")

    def __init__(self, text: str = "", style: str = ""):
        self.plain, self.style = text, style
        self.spans = [(text, style)] if text else []

    def append(self, text: str, style: str = "") -> "Text":
        self.plain += text
        self.spans.append((text, style))
        return self


class Column:
    __slots__ = ("header", "justify", "style", "no_wrap", "overflow", "cells")

    def __init__(self, header, justify="left", style="", no_wrap=False, overflow="fold"):
        self.header, self.justify, self.style = header, justify, style
        self.no_wrap, self.overflow, self.cells = no_wrap, overflow, []


class Table:
    """A table with a header row: ``box`` SIMPLE/SIMPLE_HEAD (a rule under the
    header) or SQUARE (a frame, a rule between rows when ``show_lines``)."""

    def __init__(self, title=None, caption=None, box=SIMPLE_HEAD, header_style="bold", pad_edge=True,
                 show_lines=False, show_edge=True, show_header=True, split=False):
        #: ``split``: a table too wide continues in further tables (its first column repeated)
        #: instead of breaking its cells (a table of records, a wide view)
        self.split = split
        self.title, self.caption, self.box, self.header_style = title, caption, box, header_style
        self.pad_edge, self.show_lines, self.show_edge = pad_edge, show_lines, show_edge
        self.columns: list[Column] = []
        self.n_rows = 0

    def add_column(self, header="", justify="left", style="", no_wrap=False, overflow="fold") -> None:
        self.columns.append(Column(header, justify, style, no_wrap, overflow))

    def add_row(self, *cells) -> None:
        for c, x in zip(self.columns, cells):
            c.cells.append(x)
        for c in self.columns[len(cells):]:
            c.cells.append("")
        self.n_rows += 1


def text_of(x) -> str:
    return x.plain if isinstance(x, Text) else ("" if x is None else str(x))


def cell_lines(s: str) -> str:
    """A cell's lines without trailing spaces (and without a last empty line), as rich draws them."""
    s = "\n".join(ln.rstrip() for ln in s.split("\n"))
    return s[:-1] if s.endswith("\n") else s


# ------------------------------------------------------------------ fitting

def _breaks(text: str) -> list[int]:
    """Positions of the spaces a cell may break at: never inside an innermost
    bracket pair (a vector, a tensor row).  One pass: the breaks of a piece cut
    off at one of them are these, less the piece before (wrap relies on it)."""
    spaces: list[int] = []
    atoms: list[tuple[int, int]] = []        # innermost pairs: they hold no other pair
    opened: list[list] = []                  # [start, holds a pair]
    for i, ch in enumerate(text):
        if ch in "[(":
            opened.append([i, False])
        elif ch in "])" and opened:
            start, holds = opened.pop()
            if not holds:
                atoms.append((start, i))
            if opened:
                opened[-1][1] = True
        elif ch == " ":
            spaces.append(i)
    if not atoms:
        return spaces
    atoms.sort()
    out, k = [], 0
    for i in spaces:
        while k < len(atoms) and atoms[k][1] < i:
            k += 1
        if not (k < len(atoms) and atoms[k][0] < i < atoms[k][1]):
            out.append(i)
    return out


def wrap(text: str, width: int) -> str:
    """``text`` broken at allowed spaces into lines of at most ``width``
    columns where it can (a piece that cannot be broken stays whole); a
    value (``[...]``, ``name: value, ...``) only after its commas.  Each line's
    breaks and running widths are found once (linear in its length: a symbolic
    view's expression runs to tens of thousands of characters)."""
    out = []
    for line in text.split("\n"):
        if cell_len(line) <= width:
            out.append(line)
            continue
        every = _breaks(line)
        commas = [i for i in every if line[i - 1] == ","]
        if line.isascii():
            cum: list[int] | range = range(len(line) + 1)
        else:
            cum = [0]
            for ch in line:
                cum.append(cum[-1] + cell_len(ch))
        start, n = 0, len(line)
        while cum[n] - cum[start] > width:
            allowed = commas if line.startswith("[", start) or _VALUE_AT.match(line, start) else every
            first = bisect.bisect_left(allowed, start)
            last = bisect.bisect_right(allowed, cum[start] + width, lo=first, key=lambda i: cum[i]) - 1
            if last < first:                     # nothing fits: the first break, else the piece stays whole
                if first == len(allowed):
                    break
                last = first
            i = allowed[last]
            out.append(line[start:i].rstrip())
            start = i
            while start < n and line[start].isspace():
                start += 1
        out.append(line[start:])
    return "\n".join(out)


_VALUE_AT = re.compile(r"[^ ]+: [-\[\d]")      # the same, matched where a piece starts


def _min_width(text: str) -> int:
    return max((cell_len(p) for ln in text.split("\n") for p in wrap(ln, 1).split("\n")), default=0)


def _width(col: Column, texts: list[str]) -> int:
    return max([cell_len(ln) for x in [cell_lines(text_of(col.header))] + texts for ln in x.split("\n")])


def _total(table: Table, widths: list[int]) -> int:
    edge = 2 if table.pad_edge else 0
    return sum(widths) + 3 * max(len(widths) - 1, 0) + edge + (2 if table.show_edge else 0)


def fit(table: Table, width: int | None) -> list[Table]:
    """The table fitted to ``width`` columns (None: natural width): cells
    broken at spaces outside vectors, then the columns split into several
    tables (the first column repeated) when it is still too wide."""
    cols = table.columns
    texts = [[cell_lines(text_of(x)) for x in c.cells] for c in cols]
    widths = [_width(c, t) for c, t in zip(cols, texts)]
    if width is None or _total(table, widths) <= width or not cols:
        return [table]
    if table.split and len(cols) > 2:
        return _split_table(table, texts, widths, width)
    for k in sorted(range(len(cols)), key=lambda k: -widths[k]):
        excess = _total(table, widths) - width
        if excess <= 0:
            break
        if cols[k].no_wrap:
            continue
        floor = max([_min_width(text_of(cols[k].header))] + [_min_width(x) for x in texts[k]])
        target = max(floor, widths[k] - excess, 8)
        if target < widths[k]:
            texts[k] = [wrap(x, target) for x in texts[k]]
            widths[k] = _width(cols[k], texts[k])
    return [_rebuilt(table, list(range(len(cols))), texts, table.title)]


def _is_label(text: str) -> bool:
    """A cell that names a row (a body, a point), not a number."""
    try:
        float(text.replace("−", "-"))
        return False
    except ValueError:
        return text not in ("", "—", "⋮") and not text.startswith("[")


def _split_table(table: Table, texts, widths, width) -> list[Table]:
    """Columns too wide for a table of their own (with the first) broken,
    then the columns packed into tables that fit ``width``; each repeats
    the first column (and the second when it names the rows: ``body``)."""
    keys = [0, 1] if len(widths) > 3 and texts[1] and all(_is_label(x) for x in texts[1]) else [0]
    for k in range(len(keys), len(widths)):
        room = width - _total(table, [widths[i] for i in keys] + [0])
        if widths[k] > room and not table.columns[k].no_wrap:
            texts[k] = [wrap(x, max(room, 8)) for x in texts[k]]
            widths[k] = _width(table.columns[k], texts[k])
    groups: list[list[int]] = [[]]
    for k in range(len(keys), len(widths)):
        trial = keys + groups[-1] + [k]
        if groups[-1] and _total(table, [widths[i] for i in trial]) > width:
            groups.append([])
        groups[-1].append(k)
    out = []
    for g, ks in enumerate(groups):
        title = table.title if g == 0 else (f"{table.title} (continued)" if table.title else None)
        out.append(_rebuilt(table, keys + ks, texts, title, caption=g == len(groups) - 1))
    return out


def _rebuilt(table: Table, ks: list[int], texts, title, caption: bool = True) -> Table:
    t = Table(title, table.caption if caption else None, table.box, table.header_style, table.pad_edge,
              table.show_lines, table.show_edge)
    for k in ks:
        c = table.columns[k]
        t.add_column(c.header, c.justify, c.style, c.no_wrap, c.overflow)
        t.columns[-1].cells = [x if isinstance(x, Text) and text_of(x) == s else
                               (Text(s, x.style or (x.spans[0][1] if x.spans else "")) if isinstance(x, Text) else s)
                               for x, s in zip(c.cells, texts[k])]
    t.n_rows = table.n_rows
    return t


# ------------------------------------------------------------------ layout

def lines(table: Table) -> list[str]:
    """The lines of a fitted table (title and caption included), as rich
    draws them without colour."""
    title, body, caption = parts(table)
    return title + body + caption


def parts(table: Table) -> tuple[list[str], list[str], list[str]]:
    """The title's, the table's and the caption's lines of a fitted table."""
    cols = table.columns
    cells = [[cell_lines(text_of(x)).split("\n") for x in c.cells] for c in cols]
    heads = [cell_lines(text_of(c.header)) for c in cols]
    widths = [max([cell_len(ln) for ln in h.split("\n")] + [cell_len(ln) for cl in cc for ln in cl])
              for h, cc in zip(heads, cells)]
    square = table.box == SQUARE
    edge = " " if table.pad_edge else ""
    v = "│" if square else " "
    left, right = (v + edge, edge + v) if table.show_edge else (edge, edge)
    total = _total(table, widths)

    def row(texts: list[str]) -> str:
        parts = []
        for text, w, c in zip(texts, widths, cols):
            pad = " " * (w - cell_len(text))
            parts.append(pad + text if c.justify == "right" else text + pad)
        return left + f" {v} ".join(parts) + right

    def rule(a: str, mid: str, b: str) -> str:
        return a + mid.join("─" * (w + 2) for w in widths) + b if table.show_edge else \
            "─" * total

    inner_rule = rule("├", "┼", "┤") if square else (" " + "─" * (total - 2) + " " if table.show_edge else "─" * total)
    hl = [h.split("\n") for h in heads]
    n = max(map(len, hl), default=1)
    hl = [[""] * (n - len(h)) + h for h in hl]            # a header sits at the bottom of its row
    body = [row([h[k] for h in hl]) for k in range(n)]
    body.append(inner_rule)
    for i in range(table.n_rows):
        if square and i and table.show_lines:
            body.append(inner_rule)
        height = max((len(cc[i]) for cc in cells), default=1)
        body += [row([cc[i][k] if k < len(cc[i]) else "" for cc in cells]) for k in range(height)]
    if table.show_edge:
        top, bottom = (rule("┌", "┬", "┐"), rule("└", "┴", "┘")) if square else (" " * total, " " * total)
        body = [top] + body + [bottom]
    return _label(table.title, total), body, _label(table.caption, total)


def _label(label, total: int) -> list[str]:
    """A title or caption: one line centred over the table, never wrapped."""
    if not label:
        return []
    text = text_of(label)
    n = cell_len(text)
    if n >= total:
        return [text]
    left = (total - n) // 2
    return [" " * left + text + " " * (total - left - n)]


def text_lines(text: str, width: int | None) -> list[str]:
    """A line of text broken between words to ``width`` (None: one line)."""
    if width is None or cell_len(text) <= width or "\n" in text:
        return text.split("\n")
    out, cur = [], ""
    for word in text.split(" "):
        trial = f"{cur} {word}" if cur else word
        if cur and cell_len(trial) > width:
            out.append(cur)
            cur = word
        else:
            cur = trial
    return out + [cur]
