"""A fast, plain-text layout of the simple rich tables of the terminal view,
character for character what rich prints without colour.

Laying out a table with rich measures every cell several times (about 7 ms
for a typical problem); a batch of problems or a sweep piped to a file spends
most of its time there.  When the output is not a terminal (no colour, no
terminal width to fit), :func:`print_table` writes the same lines directly:
the columns at the width of their widest cell, a space of padding on each
side, the header rule of ``box.SIMPLE``/``box.SIMPLE_HEAD``, the title and
caption centred.  Any table outside that subset (another box, row lines, a
title wider than the table, a table wider than the console, a column with a
fixed width, non-UTF output) is printed by rich as before;
``tests/api/test_plain_tables.py`` checks the two agree on every example.
"""

from __future__ import annotations

from typing import Any

ENABLED = True     # the tests switch it off to compare with rich
_SIMPLE = None


def _simple_boxes():
    global _SIMPLE
    if _SIMPLE is None:
        from rich import box

        _SIMPLE = (box.SIMPLE, box.SIMPLE_HEAD, box.SQUARE)
    return _SIMPLE


def _square(table) -> bool:
    return table.box is _simple_boxes()[2]


def _plain(x: Any) -> str | None:
    """The text a cell shows (rich markup rendered), None for a renderable
    that is not a string or text that rich would lay out differently."""
    from rich.cells import cell_len

    if isinstance(x, str):
        if "[" not in x and "\\" not in x:
            text = x
        else:
            from rich.markup import render

            text = render(x).plain
        if "\t" in text or "\r" in text:          # rich expands these itself
            return None
        # rich trims spaces at line ends and keeps zero-width marks its own way: leave those to it
        if any(ln != ln.strip(" ") or (ln and cell_len(ln[0]) == 0) for ln in text.split("\n")):
            return None
        return text
    return None


def _fits(table, console) -> bool:
    if table.box not in _simple_boxes() or not table.show_header or table.show_footer:
        return False
    if table.show_lines if not _square(table) else not table.pad_edge:     # SQUARE: the frame views
        return False
    if table.expand or table.width is not None or table.min_width or table.leading or table.row_styles:
        return False
    if tuple(table.padding) != (0, 1, 0, 1) or not table.show_edge or table.collapse_padding:
        return False
    if console.is_terminal or not (console.encoding or "").lower().replace("-", "").startswith("utf"):
        return False
    return all(c.width is None and c.min_width is None and c.max_width is None and c.ratio is None
               and c.justify in ("left", "right") and c.vertical == "top" for c in table.columns)


def _columns(table, cell_len) -> list | None:
    """(header, cell lines per row, width, justify) per column, or None."""
    cols = []
    for c in table.columns:
        head = _plain(c.header)
        texts = [_plain(x) for x in c._cells]
        if head is None or "\n" in head or any(x is None for x in texts):
            return None
        cells = [x.split("\n") for x in texts if x is not None]
        width = max([cell_len(head)] + [cell_len(ln) for lines in cells for ln in lines])
        if width == 0:
            return None                       # rich keeps a column of width 0 its own way
        cols.append((head, cells, width, c.justify))
    return cols


def layout(table, console) -> list[str] | None:
    """The lines rich prints for ``table`` on ``console``, or None when the
    table is outside the supported subset."""
    from rich.cells import cell_len

    if not _fits(table, console) or any(r.end_section for r in table.rows[:-1]):
        return None
    cols = _columns(table, cell_len)
    if cols is None:
        return None
    square = _square(table)
    edge = " " if table.pad_edge else ""
    sep, left, right = ("│", "│" + edge, edge + "│") if square else (" ", " " + edge, edge + " ")
    inner = sum(w for _, _, w, _ in cols) + 3 * max(len(cols) - 1, 0) + 2 * len(edge)
    total = inner + 2
    if total > console.width:
        return None

    def line(texts: list[str]) -> str:
        parts = []
        for text, (_, _, w, just) in zip(texts, cols):
            pad = " " * (w - cell_len(text))
            parts.append(pad + text if just == "right" else text + pad)
        return left + f" {sep} ".join(parts) + right

    def rule(a: str, mid: str, b: str) -> str:
        return a + mid.join("─" * (w + 2) for _, _, w, _ in cols) + b

    body = [line([h for h, _, _, _ in cols]), rule("├", "┼", "┤") if square else " " + "─" * inner + " "]
    for i in range(len(table.rows)):
        if square and i:
            body.append(rule("├", "┼", "┤"))
        height = max((len(cells[i]) for _, cells, _, _ in cols), default=1)
        body += [line([cells[i][k] if k < len(cells[i]) else "" for _, cells, _, _ in cols]) for k in range(height)]
    top, bottom = (rule("┌", "┬", "┐"), rule("└", "┴", "┘")) if square else (" " * total, " " * total)
    title, caption = _label(table.title, total, cell_len), _label(table.caption, total, cell_len)
    if title is None or caption is None:
        return None
    return title + [top] + body + [bottom] + caption


def _label(label, total: int, cell_len) -> list[str] | None:
    """A title or caption centred over the table ([] for none), None when
    rich would wrap it."""
    if not label:
        return []
    text = _plain(label)
    if text is None or "\n" in text or cell_len(text) > total:
        return None
    return [_centred(text, total, cell_len)]


def _centred(text: str, width: int, cell_len) -> str:
    left = (width - cell_len(text)) // 2
    return " " * left + text + " " * (width - left - cell_len(text))


def print_text(console, text) -> None:
    """``console.print(text)`` for a one-line rich Text (or str), written
    directly when it is plain output that needs no wrapping."""
    from rich.cells import cell_len

    plain = text if isinstance(text, str) else text.plain
    if (ENABLED and not console.is_terminal and not any(c in plain for c in "\n\t\r")
            and cell_len(plain) <= console.width
            and (console.encoding or "").lower().replace("-", "").startswith("utf")):
        console.file.write(plain + "\n")
    else:
        console.print(text)


def print_table(console, table) -> None:
    """``console.print(table)``, laid out by :func:`layout` when it can."""
    lines = layout(table, console) if ENABLED and type(table).__name__ == "Table" else None
    if lines is None:
        console.print(table)
        return
    console.file.write("\n".join(lines) + "\n")
