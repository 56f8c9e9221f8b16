"""Helpers for the plot tests: solve a problem file or text in-process, get
its Plot specs (the topic's ``plots`` module via the registry), build the
matplotlib figure and look at its artists."""

from __future__ import annotations

import math

from tests.conftest import PROBLEMS, ROOT


def _solved(problems):
    from dyncli.run import solve_one

    out = []
    for lp in problems:
        assert lp.error is None, str(lp.error)
        o = solve_one(lp)
        assert o.result is not None, o.message
        out.append((lp, o.result))
    return out


def solved_path(rel: str):
    """[(LoadedProblem, Result)] of a problems/ file."""
    from dyncli.loader import load_paths

    problems, diags = load_paths([str(PROBLEMS / rel)])
    assert not diags, diags
    return _solved(problems)


def solved_text(text: str):
    from dyncli.loader import split_problems, validate

    problems, diags = split_problems("test.yaml", text.encode(), ROOT)
    assert not diags, diags
    for p in problems:
        validate(p)
    return _solved(problems)


def specs(solved) -> list:
    """Every Plot spec of the solved problems (as --plot collects them)."""
    from dyncli import registry

    return [spec for lp, res in solved for spec in registry.plots_for(lp.type, lp.model, res)]


def panels(solved):
    from dyncli import registry

    return [(lp.title, spec) for lp, res in solved for spec in registry.plots_for(lp.type, lp.model, res)]


def render_both(tmp_path, pans) -> None:
    """Render to png and svg without error; the files are non-trivial."""
    from dyncli.render import plot as plotting

    for ext in ("png", "svg"):
        f = tmp_path / f"out.{ext}"
        assert plotting.save(pans, str(f)) == len(pans)
        assert f.stat().st_size > 2000


def finite(values) -> bool:
    return all(v is not None and math.isfinite(v) for v in values)


class Fig:
    """A built figure; closes itself."""

    def __init__(self, pans):
        from dyncli.render import plot as plotting

        self.fig = plotting.figure(pans)
        self.axes = self.fig.axes

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        import matplotlib.pyplot as plt

        plt.close(self.fig)


def line_labels(ax) -> list[str]:
    return [ln.get_label() for ln in ax.get_lines()]


def line(ax, label_start: str):
    found = [ln for ln in ax.get_lines() if ln.get_label().startswith(label_start)]
    assert found, f"no line labelled {label_start!r} in {line_labels(ax)}"
    return found[0]


def distinct_styles(ax, labels) -> bool:
    """The named curves differ in line style or marker (grayscale-readable)."""
    keys = [(line(ax, lb).get_linestyle(), line(ax, lb).get_marker()) for lb in labels]
    return len(set(keys)) == len(keys)
