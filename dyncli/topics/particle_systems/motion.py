"""Motion of a system of particles under its internal pair forces alone
(notes §24, §27): m_i a_i = Σ_j f_ij (24.1 with F_i = 0).

Integrated with an explicit Runge–Kutta method (DOP853 by default) on the
state (x_i, v_i, W) where Ẇ = P_int (27.10) is the work done by the
internal forces since t = 0.  Reported over ``at``: G, H_O, T, V_int, P_int,
W, the center of mass and each particle's position, and the checks of the
balance laws: G and H_O do not change (24.11, 24.18 with no external force),
and T(t) − T(0) = W(t) (the energy equation with P = P_int).

Runge–Kutta methods keep every linear invariant, so G stays constant to
rounding; H_O is quadratic and drifts by about the integration tolerance.
``error_estimate``: the runner's check solve (:func:`dyncli.ode.check_solve`, tolerances
÷ ode.CHECK_DIV); the largest difference of the positions and of the velocities, each relative
to its own scale over the run (:func:`dyncli.ode.relative_difference`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Mapping

import numpy as np

from dyncli import ode, runner
from dyncli.errors import NumericalError
from dyncli.result import Series
from dyncli.topics.particle.setup import Accuracy
from dyncli.topics.particle_systems import pairs as pf

MAX_STEPS = 200_000


@dataclass(frozen=True, slots=True)
class Motion:
    """The motion asked of a system (§24): under its ``pairs`` alone, reported at ``at`` [s] up to
    ``t_end``; the §11 ``find`` queries as given, with the problem's ``params``."""

    pairs: tuple[pf.Pair, ...]
    at: tuple[float, ...]
    t_end: float
    accuracy: Accuracy = Accuracy()
    find: tuple = ()
    params: Mapping[str, Any] = field(default_factory=dict)


def _integrate(p, masses, X0, V0, rtol, atol, method, on_step=None):
    """The state rows at the times of ``at`` (and, with ``on_step``, every step's interpolant
    to t_end: the ``find`` queries' motion)."""
    n = len(masses)
    pairs = pf.PairSet(p.pairs, n)

    def rhs(t, y):
        X = y[:3 * n].reshape(n, 3)
        V = y[3 * n:6 * n].reshape(n, 3)
        A, P = pairs.accelerations(masses, X, V)
        return np.concatenate([V.ravel(), A.ravel(), [P]])

    y0 = np.concatenate([X0.ravel(), V0.ravel(), [0.0]])
    times = list(p.at) + ([float(p.t_end)] if on_step is not None else [])
    Y, _ = ode.integrate(rhs, y0, times, method=method, rtol=rtol, atol=atol, on_step=on_step,
                         max_steps=p.accuracy.max_steps or MAX_STEPS)
    return Y[:len(p.at)]


def _quantities(p, masses, Y, O):
    n = len(masses)
    T_ = Y.shape[0]
    X = Y[:, :3 * n].reshape(T_, n, 3)
    V = Y[:, 3 * n:6 * n].reshape(T_, n, 3)
    W = Y[:, 6 * n]
    M = float(masses.sum())
    mv = masses[None, :, None] * V
    G = mv.sum(axis=1)
    H = np.cross(X - O, mv).sum(axis=1)
    T = 0.5 * (masses[None, :] * np.sum(V * V, axis=2)).sum(axis=1)
    com = (masses[None, :, None] * X).sum(axis=1) / M
    Xs, Vs = np.transpose(X, (1, 2, 0)), np.transpose(V, (1, 2, 0))   # (N, 3, T)
    Vint = np.zeros(T_)
    Pint = np.zeros(T_)
    for pr in p.pairs:
        _, power, pot, _, _ = pf.pair_terms(pr, Xs, Vs)
        Vint += pot
        Pint += power
    return X, G, H, T, com, Vint, Pint, W


def solve_motion(p, res, masses, X0, V0, O) -> None:
    """Fill the ``*_motion`` results, the checks and ``error_estimate``."""
    from dyncli.topics.particle_systems import find

    acc = p.accuracy
    method = runner.scipy_method(acc.method)

    steps = find.Steps()
    Y = _integrate(p, masses, X0, V0, acc.rtol, acc.atol, method, on_step=steps)
    X, G, H, T, com, Vint, Pint, W = _quantities(p, masses, Y, O)
    if not all(np.isfinite(a).all() for a in (X, G, H, T, Vint, Pint, W)):
        raise NumericalError("the motion under the pair forces is not finite (two particles of an "
                             "inverse-square pair collide?)")
    check = ode.check_solve(res, lambda r2, a2: _integrate(p, masses, X0, V0, r2, a2, method), acc.rtol, acc.atol)
    if check is not None:
        Y2, k = check[0], 3 * len(masses)
        res.error_estimate = ode.relative_difference([(Y[:, :k], Y2[:, :k]), (Y[:, k:2 * k], Y2[:, k:2 * k])])
    res.method = f"ode:{method}"
    # the changes are counted from the initial state at t = 0, whatever times 'at' reports
    # (T[0], G[0] are at the first reported time: with at: [1, 2] they missed the change before it)
    mv0 = masses[:, None] * V0
    G0, H0 = mv0.sum(axis=0), np.cross(X0 - O, mv0).sum(axis=0)
    T0 = 0.5 * float((masses * np.sum(V0 * V0, axis=1)).sum())
    Gs = max(float(np.max(np.abs(G))), float(np.abs(G0).max()), float(np.sqrt(masses.sum() * 2 * max(np.max(T), T0))), 1e-300)
    Hs = max(float(np.max(np.abs(H))), float(np.abs(H0).max()), 1e-300)
    r = res.results
    r.update({
        "x_motion": {str(i): X[:, i, :].tolist() for i in range(len(masses))},
        "com_motion": com.tolist(),
        "G_motion": G.tolist(),
        "H_O_motion": H.tolist(),
        "T_motion": T.tolist(),
        "V_internal_motion": Vint.tolist(),
        "P_internal_motion": Pint.tolist(),
        "W_internal": W.tolist(),
        "G_drift": float(np.max(np.abs(G - G0))) / Gs,
        "H_drift": float(np.max(np.abs(H - H0))) / Hs if Hs > 1e-300 else 0.0,
        "energy_residual": float(np.max(np.abs(T - T0 - W))),
    })
    # the energies the residual balances: T, its start T0 and the work W
    res.scales["energy_residual"] = max(float(np.max(np.abs(T))), T0, float(np.max(np.abs(W))))
    res.series.append(Series("t", list(p.at), ["T_motion", "V_internal_motion", "P_internal_motion", "W_internal"],
                             title="energy under the internal forces: T − T(0) = W (27.10)"))
    find.report(p, res, steps, lambda Y: _quantities(p, masses, Y, O), len(masses))
    res.series.append(Series("t", list(p.at), ["x_motion"], title="positions of the particles"))
    res.series.append(Series("t", list(p.at), ["distance"], title="path length of each particle since t = 0, ∫|vᵢ| dt"))
    res.series.append(Series("t", list(p.at), ["com_motion", "G_motion", "H_O_motion"],
                             title="center of mass and momenta over time (G_drift, H_drift: their changes)"))
    if not math.isfinite(r["H_drift"]):  # pragma: no cover - guarded by the finiteness check above
        r["H_drift"] = None
