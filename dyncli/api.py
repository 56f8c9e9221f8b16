"""The Python API (documented with examples in docs/api.md).

``dyncli.solve(source, **overrides)`` solves a problem file, a YAML text or
a mapping and returns one :class:`Solution` per problem;
``dyncli.sweep(source, {path: values}, **overrides)`` one per problem and
point of the sweeps' product.  Invalid input raises
:class:`dyncli.InputError` whose message holds every error, one
``file:line:col: field: what is wrong`` line each (also as ``.messages``);
a failed numerical step raises :class:`dyncli.NumericalError`; a source or
values of the wrong Python type raise TypeError.  Nothing else is raised for
any input (RuntimeError only for a bug in dyncli, with the message asking for
a report).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from dyncli.errors import InputError, NumericalError
from dyncli.results_map import results_of, units_of


class Solution:
    """One solved problem: ``results`` (plain Python and numpy values),
    ``method``, ``equations``, ``warnings``, ``error_estimate``, ``swept``
    (the sweep point's values), and ``to_dict()`` (the JSON record)."""

    def __init__(self, problem, result):
        self._problem, self._result = problem, result
        self.file, self.index, self.type, self.title = problem.file, problem.index, problem.type, problem.title
        self.results: dict[str, Any] = results_of(result, problem.type)   # + "t", did-you-mean (results_map)
        self.method: str = result.method
        self.equations: list[str] = list(result.equations)
        self.warnings: list[str] = list(result.warnings)
        self.error_estimate: float | None = result.error_estimate
        self.swept: dict[str, Any] = dict(problem.swept)

    def __getitem__(self, name: str) -> Any:
        return self.results[name]

    @property
    def units(self) -> dict[str, str]:
        """Result name -> SI unit, from the type's declaration ("" when dimensionless)."""
        return units_of(self._result, self.results)

    def to_frame(self, long: bool = True):
        """A pandas DataFrame (optional extra ``dyncli[frames]``): one row per
        reported time (one row when the results are not over time), columns the
        flattened results, ``df.attrs["units"]`` their SI units (docs/api.md)."""
        from dyncli.frames import frame

        return frame([self], long)

    def to_dict(self) -> dict:
        """The JSON record of ``dyncli solve --format json`` (plain JSON values)."""
        from dyncli.render.jsonout import problem_record

        return problem_record(self._problem, self._result)

    def table(self, digits: int = 6, units: str | None = None) -> str:
        """The terminal view as plain text (as printed to a pipe); ``digits`` 1 to 17,
        ``units`` as ``--units`` ("deg,mm" or a list of names)."""
        from dyncli.render.emit import table_text
        from dyncli.run import parse_units

        if isinstance(digits, bool) or not isinstance(digits, int) or not 1 <= digits <= 17:
            raise TypeError(f"Solution.table: digits must be a whole number from 1 to 17, got {digits!r}")
        if isinstance(units, (list, tuple)) and all(isinstance(u, str) for u in units):
            units = ",".join(units)
        if units is not None and not isinstance(units, str):
            raise TypeError(f"Solution.table: units must be a text such as 'deg,mm' or a list of unit names, got {units!r}")
        return table_text(self._problem, self._result, digits, parse_units(units))

    def _view(self):
        from dyncli.render.view import build

        return [build(self._problem, self._result)]

    def _repr_markdown_(self) -> str:
        from dyncli.render.markdown import markdown

        return markdown(self._view())

    def _repr_html_(self) -> str:
        from dyncli.render.markdown import html_view

        return html_view(self._view())

    def __repr__(self) -> str:
        return f"<Solution {self.type} {self.title!r}: {len(self.results)} results, method {self.method}>"


def _plain(x: Any, where: str = "", _open: tuple = ()) -> Any:
    """numpy values, tuples and paths in a mapping -> plain YAML data.  A
    mapping or list that contains itself, or nested deeper than a problem
    file may be (yamlsafe.MAX_DEPTH), is InputError naming where."""
    if type(x) in _LEAVES:
        return x                  # (what the rest would return, without its questions)
    from dyncli.yamlsafe import MAX_DEPTH

    if isinstance(x, (Mapping, list, tuple)):
        if any(x is o for o in _open):
            raise InputError(f"{where or 'the mapping'}: contains itself (a reference cycle); give plain data")
        if len(_open) >= MAX_DEPTH:
            raise InputError(f"{where or 'the mapping'}: nested more than {MAX_DEPTH} levels deep")
        inner = _open + (x,)
        if isinstance(x, Mapping):
            return {str(k): _plain(v, f"{where}.{k}" if where else str(k), inner) for k, v in x.items()}
        return [_plain(v, f"{where}.{i}" if where else str(i), inner) for i, v in enumerate(x)]
    if hasattr(x, "tolist") and type(x).__module__.startswith("numpy"):
        return _plain(x.tolist(), where, _open)
    if isinstance(x, Path):
        return str(x)
    return x


_LEAVES = frozenset({str, int, float, bool, type(None)})


def load(source: Any):
    """(loaded problems, diagnostics) of a path, a YAML text or a mapping."""
    from dyncli.loader import load_paths, split_problems, validate
    from dyncli.yamlsafe import Document

    if isinstance(source, Mapping):
        try:
            data = _plain(source)
        except InputError as exc:
            raise _input_error([f"<dict>: {exc.message}"]) from None
        problems, diags = split_problems("<dict>", Document(data), _cwd())
    elif isinstance(source, Path) or (isinstance(source, str) and "\n" not in source and ":" not in source.replace("\\", "/").split("/")[-1]):
        return load_paths([str(source)])
    elif isinstance(source, (str, bytes)):
        problems, diags = split_problems("<text>", source, _cwd())
    else:
        raise TypeError(f"dyncli.solve: expected a path, a YAML text or a mapping, got {type(source).__name__}")
    for p in problems:
        validate(p)
    return problems, diags


_CWD: list = [None, None]       # (the working directory's name, its Path): made again when it changes


def _cwd() -> Path:
    """``Path.cwd()``, the Path made once per working directory (every problem asks)."""
    import os

    here = os.getcwd()
    if _CWD[0] != here:
        _CWD[:] = [here, Path(here)]
    return _CWD[1]


def _assigns(overrides: Mapping[str, Any], sweeps: Mapping[str, Any] | None) -> list:
    from dyncli.overrides import Assign

    out = [Assign("override", k.replace("__", "."), (_plain(v, k),)) for k, v in overrides.items()]
    if sweeps is not None and not isinstance(sweeps, Mapping):
        raise TypeError(f"dyncli.sweep: values must be a mapping {{path: values}}, e.g. {{'k': [100, 200]}}; "
                        f"got {type(sweeps).__name__}")
    for k, values in (sweeps or {}).items():
        if not isinstance(k, str):
            raise TypeError(f"dyncli.sweep: a path must be a string such as 'k' or 'base.omega', got {k!r}")
        if not _is_sequence(values):
            raise InputError(f"sweep {k}: give a list of values, e.g. {{{k!r}: [100, 200, 300]}} (got {values!r})")
        vals = tuple(_plain(list(values), k))
        if not vals:
            raise InputError(f"sweep {k}: no values; give a list of values, e.g. {{{k!r}: [100, 200, 300]}}")
        out.append(Assign("sweep", k.replace("__", "."), vals, sweep=True))
    return out


def _is_sequence(values: Any) -> bool:
    """A list, tuple, array or other iterable of values — not a string (its
    characters), a mapping (its keys), a number or a 0-d array."""
    if isinstance(values, (str, bytes, Mapping)) or getattr(values, "ndim", 1) == 0:
        return False
    return hasattr(values, "__iter__")


def _input_error(lines: list[str]) -> InputError:
    from dyncli.printable import line

    lines = [line(x) for x in lines]           # one line each, a long value shortened (as on stderr)
    err = InputError("\n".join(lines))
    err.messages = lines
    return err


def _solve(source: Any, overrides: Mapping[str, Any], sweeps: Mapping[str, Any] | None) -> list[Solution]:
    from dyncli.overrides import expand
    from dyncli.run import solve_one

    problems, diags = load(source)
    try:
        problems = expand(problems, _assigns(overrides, sweeps))
    except InputError as exc:
        raise _input_error([exc.message]) from None
    lines = [str(d) for d in diags] + [ln for p in problems if p.error is not None for ln in p.error.lines()]
    if lines:
        raise _input_error(lines)
    out = []
    for p in problems:
        o = solve_one(p)
        if o.exit_code == 1:
            raise NumericalError(o.message)
        if o.exit_code == 2:               # refused by the solver (values beyond a double ...)
            raise _input_error((o.message or "").split("\n"))
        if o.result is None:               # exit 3: a bug in dyncli, never the input's fault
            raise RuntimeError(o.message)
        out.append(Solution(p, o.result))
    return out


def solve(source: Any, **overrides: Any) -> list[Solution]:
    """Solve ``source`` (a path, a YAML text, or a mapping) with ``overrides``
    (``k=500``; a dotted path as ``**{"base.omega": 3}`` or ``base__omega=3``;
    a ``params`` name).  Returns one :class:`Solution` per problem."""
    return _solve(source, overrides, None)


def sweep(source: Any, values: Mapping[str, Any], **overrides: Any) -> Sweep:
    """Solve for every combination of ``values`` (``{"k": [100, 200],
    "zeta": numpy.linspace(0.1, 0.5, 5)}``): one :class:`Solution` per
    problem and point, each with ``swept``, in a list that also has
    ``to_frame()`` (dyncli.api.Sweep)."""
    return Sweep(_solve(source, overrides, values))


class Sweep(list):
    """The solutions of ``dyncli.sweep``: a list (one :class:`~dyncli.api.Solution`
    per problem and point) that also gives them as a table."""

    def to_frame(self, long: bool = False):
        """A pandas DataFrame: one row per sweep point (``long``: per point and
        reported time), the swept paths then the flattened results as columns;
        ``df.attrs["units"]`` maps each column to its SI unit."""
        from dyncli.frames import frame

        return frame(list(self), long)

    def to_xarray(self, problem: int | None = None):
        """An xarray Dataset on the grid of the swept values (one dimension per
        swept path, plus ``t`` for the results over time) of one problem's
        points (``problem``: its index, needed when the sweep holds several)."""
        from dyncli.xarrays import dataset

        return dataset(list(self), problem)
