"""scipy's integrators as dyncli names them: the one method map (``accuracy.method`` -> scipy's
``OdeSolver`` class) and the one rtol floor.  Below both :mod:`dyncli.ode` (the stepping loop and
the budget step with them) and :mod:`dyncli.runner` (the contract the routes call, which
re-exports them); scipy is imported only when a class is asked for.
"""

from __future__ import annotations

import sys

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


def solver_class(method: str):
    """The one method map: scipy's ``OdeSolver`` class for ``accuracy.method``."""
    from scipy import integrate as si

    return getattr(si, scipy_method(method))
