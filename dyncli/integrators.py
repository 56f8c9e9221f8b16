"""The integrators as dyncli names them: the one method map (``accuracy.method`` -> the stepper
class) and the one rtol floor.  Below both :mod:`dyncli.ode` (the stepping loop and the budget
step with them) and :mod:`dyncli.runner` (the contract the routes call, which re-exports them).

DOP853 (the default, and ``auto``/``ode``/``exact``/``projected``) steps with dyncli's own copy of
scipy's stepper (:mod:`dyncli.dop853`, bit-identical to scipy's), so that a route that steps
explicitly never imports ``scipy.integrate`` (about 0.3 s of a cold start); RK45, Radau and
LSODA, and every class handed to scipy's ``solve_ivp`` driver (``scipy=True``), are scipy's own,
imported only when asked for.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass

@dataclass(frozen=True, slots=True)
class Accuracy:
    """A problem's ``accuracy`` controls as plain values (docs/accuracy.md), the one form the
    topics' plain setups hand their routes: tolerances, method, check solve and work budgets."""

    rtol: float = 1e-10
    atol: float = 1e-12
    method: str = "auto"
    estimate: bool = False
    max_steps: int | None = None
    max_cpu: float | None = None


#: scipy's integrators an ``accuracy.method`` may name
METHODS = ("DOP853", "RK45", "Radau", "LSODA")
#: the names of ``accuracy.method`` that are not scipy's, and the integrator that steps them
ALIASES = {"auto": "DOP853", "ode": "DOP853", "exact": "DOP853", "projected": "DOP853"}
#: the one rtol floor: scipy's smallest rtol (100 machine epsilons; the model refuses below 2.3e-14)
RTOL_FLOOR = 100 * sys.float_info.epsilon * 1.0001


def floor_rtol(rtol: float) -> float:
    """``rtol`` no smaller than scipy allows (:data:`RTOL_FLOOR`)."""
    return max(rtol, RTOL_FLOOR)


def scipy_method(method: str) -> str:
    """The scipy integrator (one of :data:`METHODS`) that steps ``accuracy.method``."""
    name = ALIASES.get(method, method)
    if name not in METHODS:
        raise ValueError(f"unknown integrator {method!r}: one of {', '.join(METHODS + tuple(ALIASES))}")
    return name


def solver_class(method: str, *, scipy: bool = False):
    """The one method map: the stepper class for ``accuracy.method`` — dyncli's DOP853
    (:mod:`dyncli.dop853`) or scipy's ``OdeSolver`` class (always with ``scipy=True``: scipy's
    ``solve_ivp`` driver takes its own classes only)."""
    name = scipy_method(method)
    if name == "DOP853" and not scipy:
        from dyncli.dop853 import DOP853

        return DOP853
    from scipy import integrate as si

    return getattr(si, name)
