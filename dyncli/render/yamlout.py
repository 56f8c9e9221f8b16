"""YAML output: the same records as JSON, safe-dumped.

:func:`dumper` is the one SafeDumper every YAML writer uses (``solve
--format yaml``, ``check --write-key``): besides the plain types it writes
numpy scalars and arrays (``np.float64`` is a ``float`` subclass that
SafeDumper refuses) and any other float/int subclass as plain numbers, so
no result a solver returns can make the dump fail."""

from __future__ import annotations

from functools import lru_cache

from dyncli.render.yamlemit import plain  # (numpy values -> plain ones: defined once, with the writer)


@lru_cache(maxsize=None)
def dumper():
    """A SafeDumper subclass that writes every numeric type as a plain number."""
    import yaml

    class PlainDumper(yaml.SafeDumper):
        """A string with a character that is not printable (U+202E reverses the
        text shown after it) is written double-quoted with every non-ASCII
        character escaped (\\u202e): the same data, shown as written
        (:mod:`dyncli.printable`)."""

        def choose_scalar_style(self):
            if isinstance(self.event.value, str) and not self.event.value.isprintable():
                return '"'
            return super().choose_scalar_style()

        def write_double_quoted(self, text, split=True):
            if text.isprintable():
                return super().write_double_quoted(text, split)
            keep, self.allow_unicode = self.allow_unicode, False
            try:
                return super().write_double_quoted(text, split)
            finally:
                self.allow_unicode = keep

    def fallback(d, data):
        p = plain(data)
        if p is data:
            return d.represent_undefined(data)  # a genuine bug: say so
        return d.represent_data(p)

    PlainDumper.add_multi_representer(bool, lambda d, x: d.represent_bool(bool(x)))
    PlainDumper.add_multi_representer(int, lambda d, x: d.represent_int(int(x)))
    PlainDumper.add_multi_representer(float, lambda d, x: d.represent_float(float(x)))
    PlainDumper.add_representer(None, fallback)
    return PlainDumper


def dumps(records: list[dict], allow_unicode: bool = True) -> str:
    """The records as YAML: by :mod:`dyncli.render.yamlemit` (the same bytes, ~30 × faster) when it
    lays them out, else by PyYAML."""
    from dyncli.render import yamlemit

    try:
        return yamlemit.dumps(records, allow_unicode)
    except yamlemit.Unsupported:
        pass
    import yaml

    return yaml.dump(records, Dumper=dumper(), sort_keys=False, allow_unicode=allow_unicode,
                     default_flow_style=None, width=100)
