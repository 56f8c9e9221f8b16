"""The pendulum's plots read the solver's sampler (no second solve) and draw the same motion."""

from __future__ import annotations

import importlib

import pytest

from dyncli import registry


def test_plots_read_the_sampler(monkeypatch):
    from tests.plots.util import solved_path, specs

    solved = solved_path("particle/pendulum.yaml")
    mod = importlib.import_module(registry.TYPES["pendulum"].package + ".solver")

    def boom(*a, **k):
        raise AssertionError("a plot solved the problem again")

    monkeypatch.setattr(mod, "solve", boom)
    plots = specs(solved)
    assert len(plots) == 6                          # θ(t) and the phase portrait, per problem
    motion = plots[0]
    line = motion.lines[0]
    lp, out = solved[0][0], solved[0][1]
    for t, th in zip(lp.model.at, out.results["theta"]):
        assert line.y[line.x.index(t)] == pytest.approx(th, abs=1e-15)
