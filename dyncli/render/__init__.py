"""Renderers: JSON, YAML and rich tables.  They know nothing of any topic:
they draw :class:`dyncli.result.Result` objects generically."""
