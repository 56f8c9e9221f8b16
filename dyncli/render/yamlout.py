"""YAML output: the same records as JSON, safe-dumped."""

from __future__ import annotations


def dumps(records: list[dict]) -> str:
    import yaml

    return yaml.safe_dump(records, sort_keys=False, allow_unicode=True, default_flow_style=None, width=100)
