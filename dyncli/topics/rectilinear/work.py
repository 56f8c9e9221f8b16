"""The work budget of the quadrature routes (cases 2, 3 and 4).

Every evaluation of a is counted, plus the Python overhead of each call
(``CALL``, ``SCALAR``, ``QUAD`` evaluations' worth); one solve may do at most
``STEP`` · ``accuracy.max_steps`` evaluations' worth (one step = two 30-point
quadrature panels, ``PER_STEP`` of them in cases 3 and 4; default
``dyncli.ode.MAX_STEPS``), else NumericalError (exit 1) with one message
naming the budget (:class:`OverWork`, the runner's OverBudget): a few tenths of a second to ~1.5 s of CPU at the default.
"""

from __future__ import annotations

from dyncli import cputime, ode

STEP = 60                   # evaluations of a per budget step (two 30-point quadrature panels)
# the Python overhead of one call, in evaluations of a (vectorised evaluation ~0.1 µs a point;
# a call of the expression ~20 µs, a scalar call ~5 µs, a quadrature call ~100 µs)
CALL, SCALAR, QUAD = 200, 50, 1000
CPU_EVERY = 20_000          # charged units between two looks at the solve's CPU (dyncli.cputime)
# the work here is counted, not projected to its end (an ODE's is): refused only at this multiple of
# the budget, so that a slow but finishing solve (a kinked spring, ~2-3 s) is not cut short
CPU_MARGIN = 4.0
# cases 3 and 4 evaluate a on long arrays (the substituted integrands, the energy inside
# t(s)): measured, a point costs 0.01-0.06 µs there against ~60 µs a call, so a point counts
# 1/32 of an evaluation and a step twice the work; the default budget is then ~0.3-0.7 s
# (case 2) and ~0.5-3 s (cases 3, 4: a power with a variable exponent is the slowest) of CPU
PER_POINT = {2: 1.0, 3: 1 / 32, 4: 1 / 32}
PER_STEP = {2: 1, 3: 2, 4: 2}


class OverWork(ode.OverBudget):
    """A quadrature solve refused by its work budget: the runner's :class:`dyncli.ode.OverBudget`,
    so that a check solve over the budget takes the runner's one fallback (ode.check_solve)."""

    def __init__(self, message: str):
        Exception.__init__(self, message)


class Work:
    """Counts the work of one solve of case ``case`` against its budget."""

    def __init__(self, p, case: int):
        self.case = case
        self.steps = int(p.accuracy.max_steps or ode.MAX_STEPS)
        self.limit = STEP * self.steps * PER_STEP.get(case, 1)
        self.n = 0

    def call(self, points: int) -> None:
        """One vectorised evaluation of a at ``points`` points."""
        self.charge(int(points * PER_POINT.get(self.case, 1.0)) + CALL)

    def charge(self, n: int, where: str = "") -> None:
        self.n += n
        if self.n // CPU_EVERY != (self.n - n) // CPU_EVERY:      # now and then: the solve's CPU budget
            if (limit := cputime.over(CPU_MARGIN)) is not None:
                raise OverWork(f"case {self.case}: the quadratures and root searches{where} took more than "
                               f"{CPU_MARGIN:g} × the CPU budget of {limit:g} s: shorten the time span (t_max), "
                               "loosen accuracy.rtol, or raise accuracy.max_cpu")
        if self.n > self.limit:
            raise OverWork(
                f"case {self.case}: the quadratures and root searches need more than {self.steps} steps{where} "
                f"(one step: {STEP} evaluations of a, or the same work in call overhead), more than the budget "
                f"of {self.steps}: shorten the time span (t_max), loosen accuracy.rtol, or raise accuracy.max_steps")
