"""The CPU budget of one solve (issue #29: no document takes more than ~2 s of CPU on an ODE
before it is answered or refused with what to change).  The clock is replaced by one that
advances a fixed amount per reading, so each decision here is deterministic; no timing is
asserted."""

from __future__ import annotations

import numpy as np
import pytest

from dyncli import cputime
from dyncli.topics.particle_systems import pairs as pf
from tests.conftest import solve_text

LONG = """
type: particles
particles:
  - {m: 1, x: [-0.5, 0, 0], v: [0, -0.3, 0]}
  - {m: 1, x: [0.5, 0, 0], v: [0, 0.3, 0]}
pairs:
  - {between: [0, 1], kind: inverse-square, K: 1}
at: [30]
"""


class _Clock:
    """The budgets' clock (cputime.thread_cpu) advancing ``tick`` seconds per reading."""

    def __init__(self, tick: float):
        self.now, self.tick = 0.0, tick

    def __call__(self) -> float:
        self.now += self.tick
        return self.now


@pytest.fixture
def slow_clock(monkeypatch):
    monkeypatch.setattr(cputime, "thread_cpu", _Clock(0.2))


def test_default_budget_refuses_a_run_projected_beyond_it(slow_clock):
    rec = solve_text(LONG)[0]
    assert rec["error"] and "s of CPU" in rec["error"] and "accuracy.max_cpu" in rec["error"]
    assert "budget of 2 s" in rec["error"]


def test_max_cpu_raises_the_budget(slow_clock):
    rec = solve_text(LONG + "accuracy: {max_cpu: 1e6}\n")[0]
    assert rec.get("error") is None
    assert rec["results"]["x_motion"]["0"][0] is not None


def test_max_steps_given_means_the_file_sized_the_work(slow_clock):
    rec = solve_text(LONG + "accuracy: {max_steps: 1000000}\n")[0]
    assert rec.get("error") is None


def test_a_refused_check_solve_falls_back_to_the_looser_one(monkeypatch):
    # the main run fits; the check solve (at rtol/100) is refused by the budget: the looser solve
    # gives the estimate, and the warning names the CPU budget
    from dyncli import ode

    real = ode.Budget.tick
    runs = {"n": 0}

    def tick(self, t, t_old=None, y=None):
        if self.n == 0 and self._n_leg == 0:
            runs["n"] += 1
        if runs["n"] == 2 and self.n >= 40:
            raise ode.OverCpu(self.goal, 3.0, 2.0, 1e4, t, y)
        return real(self, t, t_old, y)
    monkeypatch.setattr(ode.Budget, "tick", tick)
    rec = solve_text(LONG.replace("at: [30]", "at: [5]"))[0]
    assert rec.get("error") is None
    assert any("CPU budget of the solve (accuracy.max_cpu)" in w for w in rec["warnings"])
    assert rec["error_estimate"] is not None


def test_no_budget_outside_a_solve():
    assert cputime.used() is None
    assert cputime.over_budget(0.0, 1.0, 1.0) is None


@pytest.mark.parametrize("kinds", [("spring",), ("inverse-square",), ("damper",),
                                   ("spring", "damper", "inverse-square", "spring")])
def test_vectorised_pair_forces_equal_the_sum_over_pairs(kinds):
    """The pair set's one-pass forces against the sum of each pair's own terms (24.9, 27.10)."""
    rng = np.random.default_rng(7)
    n = 6

    class Pr:
        def __init__(self, i, j, kind):
            self.between, self.kind = (i, j), kind
            self.k, self.L, self.c, self.K = 3.0, 0.4, 0.7, -2.5

    pairs = [Pr(i, j, kinds[(i + j) % len(kinds)]) for i in range(n) for j in range(i + 1, n)]
    m = rng.uniform(0.5, 2.0, n)
    X, V = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
    A, P = pf.PairSet(pairs, n).accelerations(m, X, V)
    F, P_ref = np.zeros((n, 3)), 0.0
    for pr in pairs:
        f, power, _, _, _ = pf.pair_terms(pr, X, V)
        F[pr.between[0]] += f
        F[pr.between[1]] -= f
        P_ref += power
    assert A == pytest.approx(F / m[:, None], rel=1e-13, abs=1e-13)
    assert P == pytest.approx(P_ref, rel=1e-13, abs=1e-13)


def test_quadrature_routes_share_the_budget(slow_clock):
    """rectilinear's quadratures and root searches look at the solve's CPU as they count their
    work: a run over the budget is refused naming accuracy.max_cpu (a block bouncing on a
    one-sided spring, asked where it next leaves it)."""
    text = ("type: rectilinear\nparams: {m: 2, k: 800, h: 0.5}\na: \"g - k/m*max(s - h, 0)\"\n"
            "s1: 0\nv1: 1\nfind: [{when: {s: h}, direction: down}]\n")
    rec = solve_text(text)[0]
    # refused by the quadratures' own count or by the find search's (each names the budget)
    assert rec["error"] and "accuracy.max_cpu" in rec["error"]
    assert "× the CPU budget" in rec["error"] or "× the solve's CPU budget" in rec["error"]


HOOP_FIND = """
type: constrained-particle
m: 1
curve: {x1: "0.5*sin(q)", x2: 0, x3: "-0.5*cos(q)"}
q_range: [-pi, pi]
q0: 1
forces: [{kind: gravity}]
at: [0, 1]
find: [{min: q}, {max: N.1}]
"""


def test_find_searches_within_the_budget(slow_clock):
    """Every state a `find` search reads is a solve: the search stops at twice the solve's budget
    with what to change (a bead of 1e-301 kg took 9 s of CPU in 96 states of its quadrature)."""
    rec = solve_text(HOOP_FIND)[0]
    # refused by the search, or by the quadrature of one of its states (both at 2 × the budget)
    assert rec["error"] and "accuracy.max_cpu" in rec["error"] and "× the solve's CPU budget" in rec["error"]
    rec = solve_text(HOOP_FIND + "accuracy: {max_cpu: 1e6}\n")[0]
    assert rec.get("error") is None and rec["results"]["find"][0]["reached"] is True


def test_a_root_search_stops_at_twice_the_budget(slow_clock):
    """all_roots looks at the solve's CPU every 64 cells and stops at twice its budget with what
    to change (a bead on a hoop of 5e7 m turning about a tilted axis searched its equilibria for
    13 s); outside a solve it has no budget."""
    from types import SimpleNamespace

    import numpy as np

    from dyncli.errors import NumericalError
    from dyncli.rootfind import all_roots

    f = lambda x: np.sin(50.0 * x)      # noqa: E731  many cells, many roots
    assert len(all_roots(f, 0.0, 200.0, budget=10_000)[0]) > 1000
    with cputime.solve_budget(SimpleNamespace(max_cpu=1.0, max_steps=None)):
        with pytest.raises(NumericalError, match="root search .* accuracy.max_cpu"):
            all_roots(f, 0.0, 200.0, budget=10_000)
