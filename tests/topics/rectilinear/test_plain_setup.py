"""The plain-numbers core of ``rectilinear`` (issue #26 item 3): a :class:`Setup` built by hand in a
notebook solves without the input model.  References: the closed form of constant acceleration
(notes (6.5a,b): s = s1 + v1 τ + a τ²/2, v = v1 + a τ, τ = t − t1), and the same problem written as
YAML, whose record must be the same, number for number (one conversion, ``solver.plain``)."""

from __future__ import annotations

import math

import pytest

from dyncli.expr import parse
from dyncli.loader import split_problems, validate
from dyncli.topics.rectilinear import solver
from dyncli.topics.rectilinear.setup import Accuracy, Query, Setup, Spring

TSV = ("t", "s", "v")


def _model(text: str):
    ps, _ = split_problems("x.yaml", text)
    validate(ps[0])
    assert ps[0].error is None
    return ps[0].model


def test_hand_built_setup_constant_acceleration_closed_form():
    a, t1, s1, v1 = -2.5, 0.5, 1.0, 4.0
    s = Setup(a=parse(a, TSV, {}), t1=t1, s1=s1, v1=v1,
              find=(Query(t=3.0), Query(v=0.0), Query(s=2.0), Query(max="s")))
    res = solver.solve_setup(s)
    assert res.method == "closed-form" and res.results["case"] == 1
    at_t, turn, at_s, top = res.results["find"]
    tau = 3.0 - t1
    # (6.5a,b), by hand
    assert at_t["s"] == pytest.approx(s1 + v1 * tau + a * tau * tau / 2, rel=1e-15)
    assert at_t["v"] == pytest.approx(v1 + a * tau, rel=1e-15) and at_t["a"] == a
    assert turn["t"] == pytest.approx(t1 - v1 / a, rel=1e-15)
    assert turn["s"] == pytest.approx(s1 - v1 * v1 / (2 * a), rel=1e-15) and turn["v"] == 0.0
    # s = 2: the smaller root of a τ²/2 + v1 τ − (2 − s1) = 0
    tau_s = (-v1 + math.sqrt(v1 * v1 + 2 * a * (2.0 - s1))) / a
    assert at_s["t"] == pytest.approx(t1 + tau_s, rel=1e-14) and at_s["s"] == pytest.approx(2.0, rel=1e-15)
    # the §11 max of s (searched up to the largest t asked, past the turn): the turning point
    assert top["reached"] and top["s"] == pytest.approx(turn["s"], rel=1e-12)
    assert top["t"] == pytest.approx(turn["t"], rel=1e-9)


@pytest.mark.parametrize("yaml_text, setup", [
    ("type: rectilinear\na: -2.5\nt1: 0.5\ns1: 1.0\nv1: 4.0\nfind: [{t: 2.0}, {v: 0}, {s: 2.0}, {max: s}, {t: 2.0}]\n",
     Setup(a=parse(-2.5, TSV, {}), t1=0.5, s1=1.0, v1=4.0,
           find=(Query(t=2.0), Query(v=0.0), Query(s=2.0), Query(max="s"), Query(t=2.0)))),
    ("type: rectilinear\na: 3*t\nv1: 1\nfind: [{t: 1.5}, {v: 4}, {s: 10}]\naccuracy: {estimate: true}\n",
     Setup(a=parse("3*t", TSV, {}), v1=1.0, find=(Query(t=1.5), Query(v=4.0), Query(s=10.0)),
           accuracy=Accuracy(estimate=True))),
    ("type: rectilinear\na: -9.81\ns1: 1.5\nm: 2\nsprings: [{k: 2000, L: 0.5, one_sided: compression}]\n"
     "find: [{v: 0}, {min: s}]\nt_max: 2\n",
     Setup(a=parse(-9.81, TSV, {}), s1=1.5, m=2.0, springs=(Spring(2000.0, L=0.5, one_sided="compression"),),
           find=(Query(v=0.0), Query(min="s")), t_max=2.0)),
])
def test_hand_built_setup_gives_the_yaml_record(yaml_text, setup):
    model = _model(yaml_text)
    assert solver.plain(model) == setup
    by_yaml, by_hand = solver.solve(model), solver.solve_setup(setup)
    assert by_hand.results == by_yaml.results
    assert (by_hand.method, by_hand.equations, by_hand.warnings, by_hand.error_estimate) == \
        (by_yaml.method, by_yaml.equations, by_yaml.warnings, by_yaml.error_estimate)


def test_setup_is_plain_and_frozen():
    s = Setup(a=parse(1, TSV, {}))
    with pytest.raises(AttributeError):
        s.t1 = 2.0      # type: ignore[misc]
    assert Query(v=0.0).kind == "v" and Query(max="s").raw() == {"max": "s"}
