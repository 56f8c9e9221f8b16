"""The general route integrates its motion once (issue #31 item 3): the find engine's motion
(:class:`general.Dense`: every step's interpolant, for ``distance`` and the queries of every
motion) replays the route's own march (:class:`general.Record`) instead of integrating again.

The reference is the march it replaces, made afresh: the same DOP853 steps (their ends, every
step's interpolant at its nodes) bit for bit, with and without the replay, forward and backward
of t1, for a bound inside and beyond the recorded march; and the records of the whole route
against the same problem with the replay switched off.  Values are compared exactly: the replay
promises the same doubles, not an accuracy."""

from __future__ import annotations

import numpy as np
import pytest

from dyncli.expr import parse
from dyncli.topics.rectilinear import general, solver
from dyncli.topics.rectilinear.setup import Accuracy, Query, Setup

TSV = ("t", "s", "v")


def _setup(a: str, rtol: float, find=(Query(t=10.0), Query(v=0.0), Query(s=-0.3)), t1: float = 0.0):
    return Setup(a=parse(a, TSV, {}), t1=t1, s1=0.5, v1=1.0, find=tuple(find), t_max=30.0,
                 accuracy=Accuracy(rtol, rtol * 1e-3, "DOP853", False, None, None))


def _same(d1, d2):
    assert d1.breaks == d2.breaks
    assert (d1.start, d1.end) == (d2.start, d2.end)
    assert d1.extremes == d2.extremes
    for f, g, a, b in zip(d1.steps, d2.steps, d1.breaks, d1.breaks[1:]):
        x = np.linspace(a, b, 7)
        assert np.array_equal(f(x), g(x))


@pytest.mark.parametrize("rtol", [1e-5, 1e-8, 1e-11])
@pytest.mark.parametrize("a", ["-4*s - 0.4*v", "-4*s - 0.4*v + sin(2*t)", "-s*abs(s) - 0.1*v*abs(v)"])
@pytest.mark.parametrize("t_end, t_start", [(10.0, None), (3.7, -2.0), (25.0, -6.5)])
def test_dense_replay_takes_the_same_steps(a, rtol, t_end, t_start):
    p = _setup(a, rtol)
    run = general._Run(p, "DOP853", rtol, rtol * 1e-3)
    # the route's own marches (as general.solve makes them): to t1 + t_max forward, stopped early
    stop_at = 7.0
    run.march(p.t1, [p.s1, p.v1], p.t1 + p.t_max, lambda step: step.tb >= stop_at)
    run.march(p.t1, [p.s1, p.v1], -4.0, lambda step: False)
    assert run.records and all(r.steps for r in run.records)
    fresh = general.Dense(p, "DOP853", rtol, rtol * 1e-3, t_end, t_start)
    replayed = general.Dense(p, "DOP853", rtol, rtol * 1e-3, t_end, t_start, run.records)
    _same(fresh, replayed)
    times = [t_end, 0.3 * t_end, p.t1, fresh.breaks[len(fresh.breaks) // 2]]
    assert fresh(p, times) == replayed(p, times)


def test_replay_is_used_and_records_match_a_fresh_motion(monkeypatch):
    p = _setup("-4*s - 0.4*v", 1e-10, find=(Query(t=1.0), Query(t=10.0), Query(v=0.0), Query(s=-0.3),
                                           Query(max="s")))
    used = []
    prefix = general.Record.prefix

    def spy(self, *args):
        out = prefix(self, *args)
        used.append(len(out))
        return out

    monkeypatch.setattr(general.Record, "prefix", spy)
    rec = solver.solve_setup(p).results
    assert used and max(used) > 10           # the march was replayed, not made again
    monkeypatch.setattr(general.Record, "prefix", lambda self, *args: [])
    assert solver.solve_setup(p).results == rec


def test_one_pass_evaluations_equal_one_call_per_step():
    """rootfind.polynomial_extremes over stacked DOP853 steps and Dense at many times: the same
    doubles as one call per step (the stacked arithmetic is the step's own)."""
    from dyncli.rootfind import polynomial_extremes

    p = _setup("-4*s - 0.4*v + sin(2*t)", 1e-9)
    d = general.Dense(p, "DOP853", 1e-9, 1e-12, 12.0)
    pieces = list(zip(d.steps, d.breaks, d.breaks[1:]))
    together = polynomial_extremes(pieces)
    one_by_one = [polynomial_extremes([(lambda t, f=f: f(t), a, b)])[0] for f, a, b in pieces]
    assert together == one_by_one
    ts = sorted(set(d.extremes)) + [-1.0, 13.0]
    assert d(p, ts) == [d(p, [t])[0] for t in ts]
