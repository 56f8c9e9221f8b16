"""A solution's results as the Python API gives them (docs/api.md).

:class:`Results` is the ``results`` mapping of ``dyncli.Solution``: a plain
dict of the JSON record's results plus ``t``, the time axis, whenever the
type reports results as lists over the times of ``at`` (vibration, particle,
top, rotating-frame, ...), so that ``sol["x"]`` can be plotted against
``sol["t"]``.  A wrong name is a :class:`KeyError` that names the close
names ("did you mean").
"""

from __future__ import annotations

import difflib


class ResultNameError(KeyError):
    """A result name the solution does not have; the message names the close ones."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


class Results(dict):
    """The results by name; ``results[wrong name]`` raises
    :class:`ResultNameError` (a KeyError) with a "did you mean"."""

    type_name: str = ""

    def __missing__(self, key):
        names, wanted = [str(k) for k in self], str(key)
        lower: dict[str, list[str]] = {}
        for n in names:
            lower.setdefault(n.lower(), []).append(n)        # "x" and "X" are two results
        close = [n for c in difflib.get_close_matches(wanted.lower(), list(lower), n=3, cutoff=0.6) for n in lower[c]]
        close.sort(key=lambda n: (n.lower() != wanted.lower(),                 # the same but for case first
                                  -difflib.SequenceMatcher(None, wanted.lower(), n.lower()).ratio(), n))
        close += [n for n in names if wanted and n.startswith(wanted) and n not in close][:3]
        hint = f" (did you mean {', '.join(repr(c) for c in close)}?)" if close else ""
        raise ResultNameError(f"no result {key!r} in this {self.type_name or 'solution'}{hint}; "
                              f"its results: {', '.join(names)}")


def time_axis(result) -> list | None:
    """The times of a result's series over ``t`` (all the same grid), or None."""
    grids = []
    for s in result.series:
        if s.index_name == "t" and s.index_result is None:
            grid = s.index.tolist() if hasattr(s.index, "tolist") else list(s.index)
            if grid not in grids:
                grids.append(grid)
    return grids[0] if len(grids) == 1 else None


def results_of(result, type_name: str) -> Results:
    """The API's results of a solver's :class:`~dyncli.result.Result`: its
    results, plus ``t`` (the reported times) when they are lists over time."""
    out = Results(result.results)
    out.type_name = type_name
    if "t" not in out:
        times = time_axis(result)
        if times is not None:
            out["t"] = times
    return out


def units_of(result, results) -> dict[str, str]:
    """Result name -> SI unit (from the type's declaration; "" for
    dimensionless numbers, strings and flags), ``t`` in s."""
    units = {name: result.units.get(name, "") for name in results}
    if "t" in units and "t" not in result.results:
        units["t"] = "s"
    return units
