"""The instructor path: ``dyncli check --write-key PROBLEM.yaml...`` solves
the problems and prints an answer file holding every result, which
``dyncli check`` accepts unchanged (and grades 100%).

* one problem -> one check mapping; several -> ``{tolerance, checks: [...]}``
  (a check per problem, with ``index`` for multi-problem files);
* ``problem:`` is the path relative to the key's directory (``--output``'s
  directory, else the current directory);
* results are flattened to dotted keys: mappings and per-query lists split
  into entries (``find.1.t``), vectors and tensors stay whole;
* numbers are written with full precision (``repr``).
"""

from __future__ import annotations

import os
from collections.abc import Set as AbstractSet
from pathlib import Path
from typing import Any

from dyncli.check.compare import DEFAULT_ATOL, DEFAULT_RTOL


def _is_num(x: Any) -> bool:
    return (isinstance(x, (int, float)) and not isinstance(x, bool)) or x is None


def _is_vector(x: Any) -> bool:
    return isinstance(x, list) and len(x) == 3 and all(_is_num(c) for c in x) and any(c is not None for c in x)


def _is_tensor(x: Any) -> bool:
    return isinstance(x, list) and len(x) == 3 and all(_is_vector(r) for r in x)


def plain(x: Any) -> Any:
    """Plain YAML data: numpy scalars and float/int subclasses become
    float/int (a safe dumper represents only the exact built-in types)."""
    if isinstance(x, dict):
        return {str(k) if not isinstance(k, (str, int)) else k: plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [plain(v) for v in x]
    if isinstance(x, bool) or x is None or isinstance(x, str):
        return x
    if type(x).__module__.startswith("numpy") and hasattr(x, "item"):
        return plain(x.item())
    if isinstance(x, int):
        return int(x)
    if isinstance(x, float):
        return float(x)
    return x


def flatten_results(results: dict, series_names: AbstractSet[str] = frozenset()) -> dict[str, Any]:
    """Results -> {dotted key: value} as the key file lists them."""
    results = plain(results)
    out: dict[str, Any] = {}

    def rec(x: Any, key: str, split: bool) -> None:
        if isinstance(x, dict) and x:
            for k, v in x.items():
                rec(v, f"{key}.{k}", False)
        elif isinstance(x, list) and x and (split or not (_is_vector(x) or _is_tensor(x))):
            for i, v in enumerate(x):
                rec(v, f"{key}.{i}", False)
        else:
            out[key] = x

    for name, value in results.items():
        rec(value, str(name), name in series_names)
    return out


def _key_dumper():
    """SafeDumper writing lists (vectors, tensors) in flow style and
    mappings in block style, so every answer sits on its own line."""
    from dyncli.render.yamlout import dumper

    class KeyDumper(dumper()):
        pass

    def seq(dumper, data):
        flow = not any(isinstance(x, dict) for x in data)
        return dumper.represent_sequence("tag:yaml.org,2002:seq", data, flow_style=flow)

    KeyDumper.add_representer(list, seq)
    return KeyDumper


def _rel(path: Path, base: Path) -> str:
    try:
        return Path(os.path.relpath(path.resolve(), base.resolve())).as_posix()
    except ValueError:  # pragma: no cover - other drive on Windows
        return path.resolve().as_posix()


def write_key(names: list[str], key_dir: Path | None = None, options=None) -> tuple[str, list[str], int]:
    """Solve ``names`` and build the key text.  Returns (text, diagnostics, exit code)."""
    import yaml

    from dyncli.loader import load_paths
    from dyncli.render.jsonout import jsonable
    from dyncli.run import solve_one, worst

    key_dir = key_dir or Path.cwd()
    if "-" in names:
        return "", ["--write-key needs problem files (the key refers to them by path), not '-'"], 2
    problems, diags = load_paths(names)
    messages = [str(d) for d in diags]
    codes = [2] * len(diags)
    checks = []
    comments = []
    counts: dict[str, int] = {}
    for lp in problems:
        counts[lp.file] = counts.get(lp.file, 0) + 1
    for lp in problems:
        o = solve_one(lp, options)
        codes.append(o.exit_code)
        if o.exit_code != 0 or o.result is None:
            messages.append(o.message or f"{lp.file}: could not solve")
            continue
        res = o.result
        series = {n for s in res.series for n in s.names}
        answers = flatten_results(jsonable(res.results), series)
        check: dict[str, Any] = {"problem": _rel(Path(lp.file), key_dir)}
        if counts[lp.file] > 1:
            check["index"] = lp.index
        check["title"] = lp.title
        check["answers"] = answers
        checks.append(check)
        for w in res.warnings:
            comments.append(f"# {lp.file} ({lp.title}): warning: {w}")
    if not checks:
        return "", messages, worst(codes) or 2
    tol = {"rtol": DEFAULT_RTOL, "atol": DEFAULT_ATOL}
    if len(checks) == 1:
        c = checks[0]
        doc = {"problem": c["problem"], **({"index": c["index"]} if "index" in c else {}),
               "title": c["title"], "tolerance": tol, "answers": c["answers"]}
    else:
        doc = {"tolerance": tol, "checks": checks}
    head = ["# Answer key written by `dyncli check --write-key` (check it with `dyncli check` on this file).",
            "# Edit tolerances (rtol/atol or sigfigs) and per-answer points ({value: ..., points: 2}) as needed;",
            "# delete answers you do not want to grade."]
    body = yaml.dump(doc, Dumper=_key_dumper(), sort_keys=False, allow_unicode=True, default_flow_style=False, width=100)
    return "\n".join(head + comments) + "\n" + body, messages, worst(codes)
