"""The terminal's drawing of dyncli's tables (:mod:`dyncli.render.plain`) by
rich: colour and styles over the same cells.  Imported only when the output
is a terminal (or by the tests that compare the two layouts)."""

from __future__ import annotations

from rich import box as rbox
from rich.console import JustifyMethod
from rich.table import Table as RTable
from rich.text import Text as RText

from dyncli.render.plain import SIMPLE, SQUARE, Table, Text, cell_lines, text_of, cell_len, parts

_BOXES = {SIMPLE: rbox.SIMPLE, SQUARE: rbox.SQUARE}


def text(x, style: str = "") -> RText:
    """A rich Text of a plain str or a :class:`~dyncli.render.plain.Text`."""
    if isinstance(x, Text):
        out = RText()
        for part, st in x.spans:
            out.append(part, style=st or None)
        return out
    return RText(x, style=style or "")


def _cell(x, justify: JustifyMethod) -> RText:
    if isinstance(x, Text):
        out = RText(justify=justify)
        for part, st in x.spans:
            out.append(cell_lines(part), style=st or None)
        return out
    return RText(cell_lines(text_of(x)), justify=justify)


def table(console, t: Table) -> None:
    """Print ``t`` (fitted already) on a rich console: the title and caption
    as the lines of the plain layout, the table by rich."""
    title, body, caption = parts(t)
    rt = RTable(box=_BOXES.get(t.box, rbox.SIMPLE_HEAD), header_style=t.header_style or None, pad_edge=t.pad_edge,
                show_lines=t.show_lines, show_edge=t.show_edge)
    for c in t.columns:
        rt.add_column(_cell(c.header, c.justify), justify=c.justify, style=c.style or None, no_wrap=True)
    for i in range(t.n_rows):
        rt.add_row(*[_cell(c.cells[i], c.justify) for c in t.columns])
    for ln in title:
        line(console, RText(ln, style="italic"))
    # a table that cannot fit (a vector wider than the screen) is drawn at its own width, as off a terminal
    need = max(map(cell_len, body), default=0)
    width = console.width
    if need > width:
        console.width = need
    try:
        console.print(rt, crop=False)
    finally:
        console.width = width
    for ln in caption:
        line(console, RText(ln, style="italic"))


def line(console, t: RText) -> None:
    """One line as it is (a title, a caption, a line broken by the plain layout): never wrapped."""
    console.print(t, no_wrap=True, overflow="ignore", crop=False)
