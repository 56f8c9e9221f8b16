"""What a failed particle integration says about its cause (notes §19): the hint added to the
step budget's refusal (a stiff decaying mode, or the time scale the steps must resolve) and to a
non-finite force (the particle fell into an inverse-square centre or reached a spring anchor)."""

from __future__ import annotations

import numpy as np

from dyncli import ode
from dyncli.topics.particle.forces import Forces, NonFiniteForce


def _stiffness(rhs, t: float, y) -> tuple[float, bool]:
    """The largest |eigenvalue| of the Jacobian of rhs at (t, y) (finite
    differences) and whether it is stiff-like (a real, decaying mode) rather
    than an oscillation.  (0, False) if it cannot be computed."""
    try:
        f0 = np.asarray(rhs(t, y))
        J = np.empty((7, 7))
        for j in range(7):
            d = 1e-7 * max(abs(y[j]), 1e-3)
            yj = y.copy()
            yj[j] += d
            J[:, j] = (np.asarray(rhs(t, yj)) - f0) / d
        if not np.all(np.isfinite(J)):
            return 0.0, False
        lam = np.linalg.eigvals(J)
    except (NonFiniteForce, ArithmeticError, ValueError, np.linalg.LinAlgError):
        return 0.0, False
    k = int(np.argmax(np.abs(lam)))
    big = lam[k]
    return float(abs(big)), bool(big.real < 0 and abs(big.imag) <= abs(big.real))


def budget_message(over: ode.OverBudget, method: str, rhs=None) -> tuple[str, bool]:
    """The budget's refusal message with a hint on what limits the steps; and
    whether the run is stiff for an explicit method (an implicit one would
    take long steps)."""
    msg = str(over)
    stiff = False
    if rhs is not None and over.y is not None and method in ("DOP853", "RK45"):
        rho, decaying = _stiffness(rhs, over.t, over.y)
        if decaying and over.h * rho > 1.0:
            stiff = True
            msg += (f" (the problem is stiff near t = {over.t:.3g} s: a decaying mode with rate {rho:.3g} 1/s "
                    f"limits the {method} steps to about {over.h:.3g} s; accuracy.method: LSODA or Radau "
                    "takes long steps there)")
        elif rho > 0 and over.h * rho > 0.05:
            msg += (f" (the motion has a time scale of about {1 / rho:.3g} s near t = {over.t:.3g} s, "
                    "which the steps must resolve)")
    return msg, stiff


def singularity_hint(F: Forces, x) -> str:
    for c, _, R0 in F.inv:
        R = float(np.linalg.norm(x - c))
        if R < 1e-3 * R0:
            return f" (the particle falls into the centre of the inverse-square field: R = {R:.3g} m)"
    for a, _, L, _ in F.springs:
        R = float(np.linalg.norm(x - a))
        if L > 0 and R < 1e-3 * L:
            return f" (the particle reaches the anchor of a spring with free length L > 0: R = {R:.3g} m)"
    return ""
