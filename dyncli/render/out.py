"""Where the tables and lines of a view are printed: :class:`Out` writes dyncli's own layout
(:mod:`dyncli.render.plain`) to a file or pipe, and hands it to rich (:mod:`dyncli.render.richview`,
imported only then) on a terminal."""

from __future__ import annotations

from dyncli.render import plain


class Out:
    """Where a view prints: ``file`` at ``width`` columns (None: natural
    width).  Off a terminal the lines are written directly; on a terminal
    (``terminal``), or when the tests switch :data:`ENABLED` off, through a
    rich console (``rich``, made on first use)."""

    def __init__(self, file, width: int | None, terminal: bool = False, encoding: str = "utf-8",
                 no_color: bool = False, rich=None):
        self.file, self.width, self.terminal, self.encoding = file, width, terminal, encoding
        self.no_color, self._rich = no_color, rich

    @property
    def is_terminal(self) -> bool:
        return self.terminal

    def _console(self):
        if self._rich is None:
            from rich.console import Console

            self._rich = Console(file=self.file, width=self.width or 100_000, no_color=self.no_color,
                                 highlight=False, soft_wrap=False)
        return self._rich

    def print(self, obj="") -> None:
        if not isinstance(obj, (plain.Table, plain.Text, str)):          # a rich renderable (benchmarks of the former views)
            self._console().print(obj)
            return
        if isinstance(obj, plain.Table):
            for t in plain.fit(obj, self.width):
                self._table(t)
            return
        style = obj.style if isinstance(obj, plain.Text) else ""
        for ln in plain.text_lines(plain.text_of(obj), self.width):
            self._line(ln if not isinstance(obj, plain.Text) or len(obj.spans) < 2 or ln != obj.plain else obj, style)

    def _line(self, text, style: str = "") -> None:
        if plain.ENABLED and not self.terminal:
            self.file.write(plain.text_of(text) + "\n")
            return
        from dyncli.render import richview

        richview.line(self._console(), richview.text(text, style))

    def _table(self, t: plain.Table) -> None:
        if plain.ENABLED and not self.terminal:
            self.file.write("\n".join(plain.lines(t)) + "\n")
            return
        from dyncli.render import richview

        richview.table(self._console(), t)


def as_out(console) -> Out:
    """An :class:`Out` for ``console`` (an Out, or a rich Console of the tests)."""
    if isinstance(console, Out):
        return console
    return Out(console.file, console.width, console.is_terminal, console.encoding or "utf-8",
               bool(console.no_color), rich=console)
