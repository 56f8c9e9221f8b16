"""A forced vibration's ``find`` and ``distance`` answers do not depend on the route to the
turning points: the plain-float search (a cold solve: no numpy import) and the vectorised one on
numpy arrays (a long grid, numpy loaded, or the process's float budget spent — e.g. the later
points of a ``--sweep``) give the same doubles, bit for bit, so an answer never depends on what
the process solved before it (its place in a sweep)."""

from __future__ import annotations

import pytest

from tests.conftest import ROOT, solve_one_text

BASE_FIND_W = (ROOT / "benchmarks/sweep_cases/base-find-w.yaml").read_text()

BASE = """type: vibration
m: 1
k: {k}
zeta: 0.05
L: 0.2
x0: 0.2
base: {{amplitude: 0.002, omega: 30}}
t_end: 2
at: [0.7, 1.9]
find:
  - {{when: {{x: 0.2}}, direction: up, occurrence: 3}}
  - {{max: x, within: [1, 1.5]}}
  - {{min: w}}
  - {{min: x, within: [1, 2]}}
  - {{when: {{v: 0}}, occurrence: 2}}
  - {{max: v, within: [0.2, 1.8]}}
"""

FORCE = """type: vibration
m: 2
k: 800
zeta: 0.1
x0: 0.01
v0: -0.2
force: {amplitude: 10, omega: 15}
t_end: 3
at: [0.5, 2.9]
find:
  - {min: x, within: [1, 2]}
  - {max: v}
  - {when: {v: 0}, occurrence: 4}
  - {max: x, within: [2, 3]}
"""

UNBALANCE = """type: vibration
m: 40
k: 100000
zeta: 0.02
unbalance: {m0: 0.5, e: 0.02, omega: 47}
t_end: 1.5
at: [0.3, 1.4]
find:
  - {max: x}
  - {min: x, within: [0.5, 1]}
  - {when: {v: 0}, occurrence: 7}
  - {max: v, within: [1, 1.5]}
"""

LONG = """type: vibration
m: 1
k: 400
zeta: 0.01
x0: 0.01
base: {amplitude: 0.002, omega: 19.5}
t_end: 60
at: [59]
find:
  - {min: x, within: [40, 41]}
  - {max: w, within: [55, 56]}
  - {when: {v: 0}, occurrence: 300}
"""

NEAR_RESONANCE = """type: vibration
m: 1
k: 400
zeta: 0.01
x0: 0.001
force: {amplitude: 1, omega: 20.2}
t_end: 4
at: [3.9]
find:
  - {max: x, within: [2, 3]}
  - {when: {v: 0}, occurrence: 9}
  - {min: v, within: [1, 2]}
"""

OVERDAMPED = """type: vibration
m: 1
k: 100
zeta: 1.5
x0: 0.05
base: {amplitude: 0.01, omega: 7}
t_end: 3
at: [2.5]
find:
  - {max: x, within: [1, 2]}
  - {when: {v: 0}, occurrence: 3}
  - {min: w}
"""

HUGE = """type: vibration
m: 1
k: 800
zeta: 0.05
L: 0.2
x0: -0.2
v0: 1.0e+300
base: {amplitude: 0.001, omega: 30}
t_end: 3
at: [0.5, 2.9]
find:
  - {when: {v: 0}, occurrence: 5}
  - {min: x, within: [1, 2]}
"""
# (HUGE: the bound's squares overflow; both searches scale them alike)

CASES = {"huge": HUGE, "near-resonance": NEAR_RESONANCE, "overdamped": OVERDAMPED, "base-find-w": BASE_FIND_W, "base-k133": BASE.format(k=133.1103678929766),
         "base-k400": BASE.format(k=400), "base-k977": BASE.format(k=977.3), "force": FORCE,
         "unbalance": UNBALANCE, "long": LONG}


def _answers(text: str, arrays: bool, monkeypatch) -> tuple:
    from dyncli.topics.vibration import find

    with monkeypatch.context() as mp:
        mp.setattr(find, "_on_arrays", lambda n: arrays)
        r = solve_one_text(text)["results"]
    return r["find"], r.get("distance")


@pytest.mark.parametrize("name", list(CASES))
def test_float_and_array_routes_give_the_same_doubles(name, monkeypatch):
    floats = _answers(CASES[name], False, monkeypatch)      # a cold solve: plain floats
    arrays = _answers(CASES[name], True, monkeypatch)       # numpy loaded / budget spent / long grid
    assert all(e["reached"] for e in floats[0]), floats[0]
    assert arrays == floats                                   # ==: bit for bit, every field


def test_sweep_point_is_its_own_solve(monkeypatch):
    """A point late in a sweep (numpy loaded, budget spent) answers as the same problem solved cold."""
    from dyncli.topics.vibration import find

    monkeypatch.setattr(find, "_spent", [0])
    monkeypatch.setattr(find, "FLOAT_BUDGET", 10 ** 9)
    cold = _answers(BASE_FIND_W, False, monkeypatch)
    monkeypatch.setattr(find, "FLOAT_BUDGET", 0)              # the budget spent: the array route
    assert find._on_arrays(10) is True
    late = solve_one_text(BASE_FIND_W)["results"]
    assert (late["find"], late.get("distance")) == cold
