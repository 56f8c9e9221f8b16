"""Problem files for ``dyncli check`` (both modes): each file read once per
resolved path (only inside the fence, see :mod:`dyncli.check.safe`), each
problem solved once per canonical content — the problem mapping after
``params`` overrides or variant substitution, plus its folder — so many
submissions over the same problems (or the same drawn numbers) share a solve.
"""

from __future__ import annotations

import json
import os
from functools import cached_property, lru_cache
from pathlib import Path
from typing import Any

from dyncli.check.safe import RefError, looks_like_problem_file, resolve_problem, shown
from dyncli.errors import InputError
from dyncli.loader import Diagnostic, LoadedProblem, read_source, split_problems, validate


def _display(path: Path) -> str:
    try:
        rel = os.path.relpath(path, Path.cwd())
    except ValueError:  # pragma: no cover - other drive on Windows
        return str(path)
    return str(path) if rel.startswith("..") else rel



class ProblemFiles:
    """Problem files read once per resolved path, each solve once per
    canonical content (shared by both modes of ``dyncli check``)."""

    def __init__(self, options=None, root: Path | None = None):
        self.options = options
        self.root = root
        self._files: dict[str, tuple[list[LoadedProblem], list[Diagnostic]]] = {}
        self._solved: dict[str, Any] = {}
        self._plain: dict[int, tuple[Any, Solved]] = {}
        self.solves = 0

    def read(self, ref: str, base_dir: Path, where: Diagnostic) -> tuple[list[LoadedProblem], Diagnostic | None]:
        """The problems of the file ``ref`` names (relative to ``base_dir``).
        ``where`` positions a refusal (its message is replaced)."""
        def refuse(message: str) -> tuple[list, Diagnostic]:
            return [], Diagnostic(where.file, where.line, where.col, where.path, message)

        try:
            resolved = resolve_problem(ref, base_dir, self.root)
        except RefError as exc:
            return refuse(str(exc))
        key = str(resolved)
        if key not in self._files:
            try:
                display, data = read_source(_display(resolved))
            except InputError:
                return refuse(f"problem file '{shown(ref)}' cannot be read")
            ps, ds = split_problems(display, data, resolved.parent)
            if ds or not ps or not looks_like_problem_file(ps[0].doc.data if ps[0].doc else None):
                # not a problem file: say so without echoing any of its content
                at = f" (YAML error at line {ds[0].line})" if ds and ds[0].line else ""
                ps, ds = [], [Diagnostic(where.file, where.line, where.col, where.path,
                                         f"'{shown(ref)}' is not a problem file{at}: expected 'type' with a "
                                         f"problem type, or 'problems: [...]'; run 'dyncli validate' on it")]
            for p in ps:
                validate(p)
            self._files[key] = (ps, ds)
        ps, ds = self._files[key]
        return ps, (ds[0] if ds else None)

    def solve(self, lp: LoadedProblem, validated: bool = True):
        """The outcome of ``lp`` (solved once per content); with
        ``validated=False`` it is validated only when not cached yet."""
        from dyncli.run import solve_one

        key = _canonical(lp)
        if key is not None and key in self._solved:
            return self._solved[key]
        if not validated:
            validate(lp)
        if lp.error is None:
            self.solves += 1
        outcome = solve_one(lp, self.options)
        if key is not None:
            self._solved[key] = outcome
        return outcome


    def results(self, outcome) -> Solved:
        """The plain results of a successful solve, with what grading derives
        from them, computed once per solve."""
        hit = self._plain.get(id(outcome))
        if hit is None:
            from dyncli.render.jsonout import jsonable

            hit = self._plain[id(outcome)] = (outcome, Solved(jsonable(outcome.result.results)))   # keeps its id
        return hit[1]


class Solved:
    """A solve's results as plain data; ``scale`` (round-off zeros) and
    ``index`` (the result paths, for "did you mean") on first use."""

    def __init__(self, results: Any):
        self.results = results

    @cached_property
    def scale(self) -> float:
        from dyncli.check.zeros import scale_of

        return scale_of(self.results)

    @cached_property
    def index(self):
        from dyncli.check.paths import PathIndex, available_paths

        return PathIndex(available_paths(self.results))


def _canonical(lp: LoadedProblem) -> str | None:
    try:
        body = json.dumps(lp.raw, sort_keys=True, default=str, allow_nan=True)
    except (TypeError, ValueError):  # pragma: no cover - plain YAML data always dumps
        return None
    return (_resolved(str(lp.base_dir)) if lp.base_dir is not None else "") + "\n" + body


@lru_cache(maxsize=256)
def _resolved(folder: str) -> str:
    return str(Path(folder).resolve())
