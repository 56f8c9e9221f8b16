"""A CPU-time limit for work that has no step count to budget (sympy's
simplification, integration and printing of a large expression).

``with limit(1.0): ...`` raises :class:`CpuTimeout` in the block once it has
used 1 s of CPU (``ITIMER_VIRTUAL``: the process's user time, a timer of its
own, so it neither disturbs nor is disturbed by wall-clock alarms).  The
exception is a BaseException: code that catches ``Exception`` as "best
effort" (sympy calls) cannot swallow it.  Only the main thread can take
signals; elsewhere, inside another limit (that one governs), and where the platform has no such timer, the block runs
unlimited.  Callers turn the timeout into a cheaper route or a refusal.
"""

from __future__ import annotations

import contextlib
import signal
import threading


class CpuTimeout(BaseException):
    """The block used more than its CPU time."""


@contextlib.contextmanager
def limit(seconds: float):
    timer = getattr(signal, "ITIMER_VIRTUAL", None)
    if timer is None or threading.current_thread() is not threading.main_thread():
        yield
        return

    def fire(signum, frame):
        raise CpuTimeout(f"more than {seconds:g} s of CPU")

    if signal.getitimer(timer)[0] > 0:   # inside another limit: that one governs
        yield
        return
    old = signal.signal(signal.SIGVTALRM, fire)
    signal.setitimer(timer, seconds)
    try:
        yield
    finally:
        signal.setitimer(timer, 0)
        signal.signal(signal.SIGVTALRM, old)


# ---------------------------------------------------------------------------
# the CPU budget of one solve (issue #29: no document a student could write takes more than ~2 s
# of CPU before it is answered or refused with what to change)

import contextvars  # noqa: E402
import time  # noqa: E402

try:                                    # (POSIX; per thread on Linux)
    import resource as _resource  # noqa: E402
except ImportError:                     # pragma: no cover - Windows
    _resource = None  # type: ignore[assignment]  # the fallback below reads user + system time
_THREAD = getattr(_resource, "RUSAGE_THREAD", None)


def thread_cpu() -> float:
    """This thread's user CPU time (s), the clock of every CPU budget: the work's own time.  The
    kernel's time is left out — mostly page faults, whose cost is the machine's memory system's
    (a sandbox's can make a solve's few hundred thousand of them cost 5 s of system time against
    1 s of work), not the solve's.  Where the platform has no per-thread usage,
    :func:`time.thread_time` (user + system)."""
    if _THREAD is None:
        return time.thread_time()
    return _resource.getrusage(_THREAD).ru_utime

#: the CPU (seconds, this thread's user time: :func:`thread_cpu`) a solve may take when its file sets neither
#: ``accuracy.max_cpu`` nor ``accuracy.max_steps``; a run projected beyond it is refused
SOLVE_CPU = 2.0
#: adaptive work that cannot be projected to its end (root searches, quadratures, find searches)
#: stops once the solve has used this many times its budget
ADAPTIVE = 2.0
#: below this much CPU used, by the solve or by the run being projected, no projection is made
#: (one noisy probe must not refuse a cheap run, nor a retry's first small steps)
GRACE = 0.25

_SOLVE: contextvars.ContextVar = contextvars.ContextVar("dyncli_solve_cpu", default=None)


class solve_budget:
    """The CPU budget of one solve, read by the work budgets of its routes
    (:func:`over_budget`): ``accuracy.max_cpu`` when given; else :data:`SOLVE_CPU` unless
    ``accuracy.max_steps`` is given (a user who sized the work in steps chose it); ``None``
    for types without accuracy controls.  ``with solve_budget(accuracy): ...`` (a class, not a
    generator: it is entered once per solve, a fixed cost of every problem)."""

    __slots__ = ("_limit", "_token")

    def __init__(self, accuracy):
        limit = getattr(accuracy, "max_cpu", None)
        if limit is None and accuracy is not None and getattr(accuracy, "max_steps", None) is None:
            limit = SOLVE_CPU
        self._limit = limit

    def __enter__(self) -> None:
        self._token = _SOLVE.set(None if self._limit is None else (thread_cpu(), float(self._limit)))

    def __exit__(self, *exc) -> None:
        _SOLVE.reset(self._token)


@contextlib.contextmanager
def extra(seconds: float):
    """``seconds`` more CPU for the block (the looser check solve that replaces one refused by the
    budget: the run's own estimate is worth a little more than the budget)."""
    s = _SOLVE.get()
    token = _SOLVE.set(s if s is None or not seconds else (s[0], s[1] + seconds))
    try:
        yield
    finally:
        _SOLVE.reset(token)


def used() -> tuple[float, float] | None:
    """(CPU seconds used by the solve in progress, its budget), or None without a budget."""
    s = _SOLVE.get()
    return None if s is None else (thread_cpu() - s[0], s[1])


def over(margin: float = 1.0) -> float | None:
    """The solve's CPU budget (s) once the solve has used more than ``margin`` times it (work
    that is adaptive, not projected to its end, checks this now and then); else None."""
    s = used()
    return s[1] if s is not None and s[0] > margin * s[1] else None


def over_budget(cpu_leg0: float, done: float, left: float) -> tuple[float, float] | None:
    """(the projected CPU of the solve, its budget) when a run that has used ``thread_cpu() −
    cpu_leg0`` for ``done`` of its span, with ``left`` to go, would end beyond the budget;
    else None."""
    s = used()
    if s is None:
        return None
    spent, limit = s
    if spent > limit:
        return spent, limit
    leg = thread_cpu() - cpu_leg0
    if spent < GRACE or leg < GRACE or left <= 0:    # (a leg's own first steps, e.g. a retry with
        return None                                  # another method, do not project it: its rate settles)
    projected = spent + leg * left / max(done, 1e-300)
    return (projected, limit) if projected > limit else None
