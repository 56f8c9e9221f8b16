"""The parser's events of a YAML text, read once, for :mod:`dyncli.yamlsafe`.

:class:`Events` iterates the events of the whole stream and enforces, while
parsing (before anything is built), the caps on nesting depth and on the
number of values: scanning deeply nested flow collections costs time
quadratic in the depth (in PyYAML and in libyaml), so the caps must bite
while parsing.  It also keeps what a composer would: the anchors of each
document (a duplicate anchor or an undefined alias is the composer's error,
kept until the stream is read) and, for the first document, the events of
each anchored value so that an alias can be built again from them.
"""

from __future__ import annotations

from typing import Any


class Stop(Exception):
    """Building stops: ``error`` (a YamlError) or None when the reason is an
    anchor error the stream keeps (``Events.composer_error``)."""

    def __init__(self, error: Any = None):
        super().__init__(error)
        self.error = error


class Events:
    """The events of ``text``; ``caps`` = (deepest nesting, most values,
    the exception class raised at a cap, with the message, line, column)."""

    def __init__(self, text: str, loader, caps: tuple):
        import yaml

        self._loader = loader(text)
        self._y = yaml
        self._nodes = (yaml.ScalarEvent, yaml.SequenceStartEvent, yaml.MappingStartEvent, yaml.AliasEvent)
        self._kind = {yaml.ScalarEvent: 3, yaml.AliasEvent: 3, yaml.SequenceStartEvent: 1, yaml.MappingStartEvent: 1,
                      yaml.SequenceEndEvent: 2, yaml.MappingEndEvent: 2, yaml.DocumentStartEvent: 4,
                      yaml.StreamEndEvent: 5}
        self._get = self._loader.get_event
        self.depth = self.values = self.docs = 0
        self.anchors: dict[str, Any] = {}       # name -> its events (first document) or its first event
        self._recording: list[tuple[list, int]] = []   # (events of an anchored collection, its depth)
        self.composer_error: Exception | None = None
        self._done = False
        self._max_depth, self._max_values, self._error = caps

    def is_node(self, ev) -> bool:
        return type(ev) in self._nodes

    def __iter__(self):
        return self

    def __next__(self):
        if self._done:
            raise StopIteration
        return self._see(self._get())

    def plain_scalars(self, take) -> Any:
        """Read a run of plain scalars (no tag, no anchor, outside any
        anchored value being recorded) straight from the parser, each counted
        as :meth:`__next__` counts it and handed to ``take(event)``, while
        ``take`` accepts them (returns True): the fast lane of a long list of
        numbers.  Returns the first event not taken, seen as :meth:`__next__`
        would return it."""
        get, scalar, cap = self._get, self._y.ScalarEvent, self._max_values
        while True:
            ev = get()
            if type(ev) is not scalar or ev.tag is not None or ev.anchor is not None \
                    or not ev.implicit[0] or self._recording:
                return self._see(ev)
            self.values += 1
            if self.values > cap:
                self._cap(ev, f"document has more than {cap} values")
            if not take(ev):
                return ev

    def _see(self, ev):
        """``ev`` counted, capped, recorded and its anchor noted."""
        kind = self._kind.get(type(ev), 0)
        if kind == 3:                                   # a scalar or an alias
            self.values += 1
        elif kind == 1:                                 # a sequence or a mapping starts
            self.depth += 1
            self.values += 1
            if self.depth > self._max_depth:
                self._cap(ev, f"document is nested more than {self._max_depth} levels deep")
        elif kind == 2:                                 # ... ends
            if self._recording:
                self._record(ev)
                self._close()
            self.depth -= 1
            return ev
        elif kind == 4:
            self.docs += 1
            self.anchors = {}
        elif ev is None or kind == 5:
            self._done = True
            self._loader.dispose()
            raise StopIteration
        if self.values > self._max_values:
            self._cap(ev, f"document has more than {self._max_values} values")
        if self._recording:
            self._record(ev)
        if kind == 3 or kind == 1:
            if ev.anchor is not None:
                self._anchor(ev, type(ev))
        return ev

    def recording(self) -> bool:
        """Whether the events read now are recorded (inside an anchored value, for its aliases)."""
        return bool(self._recording)

    def _cap(self, ev, message: str):
        raise self._error(message, ev.start_mark.line + 1, ev.start_mark.column + 1)

    def _record(self, ev) -> None:
        for events, _ in self._recording:
            events.append(ev)

    def _close(self) -> None:
        while self._recording and self._recording[-1][1] == self.depth:
            self._recording.pop()

    def _anchor(self, ev, cls) -> None:
        """A new anchor (registered before its content, as a composer does:
        an alias inside it refers to it), or an alias's check."""
        y = self._y
        if cls is y.AliasEvent:
            if ev.anchor not in self.anchors and self.composer_error is None:
                self.composer_error = y.composer.ComposerError(None, None, "found undefined alias", ev.start_mark)
            return
        name = getattr(ev, "anchor", None)
        if name is None or cls not in self._nodes:
            return
        if name in self.anchors:
            if self.composer_error is None:
                first = self.anchors[name][0].start_mark
                self.composer_error = y.composer.ComposerError(
                    "found duplicate anchor; first occurrence", first, "second occurrence", ev.start_mark)
            return
        events = [ev]
        self.anchors[name] = events
        if cls is not y.ScalarEvent and self.docs == 1:
            self._recording.append((events, self.depth))

    def alias(self, ev) -> list | None:
        """The events of the value an alias names (None: an undefined alias)."""
        return self.anchors.get(ev.anchor)

