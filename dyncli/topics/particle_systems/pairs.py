"""Internal pair forces of a system of particles (notes §24, §27).

Every pair is central (24.15): the force on particle i from particle j is
f_ij = −φ e, e = (x_i − x_j)/r, r = |x_i − x_j|, and f_ji = −f_ij (24.9), with

* spring:          φ = k (r − L),           potential ½ k (r − L)²
* damper:          φ = c ṙ, ṙ = e·(v_i − v_j) (no potential)
* inverse-square:  φ = K / r²  (attraction for K > 0), potential −K/r

So the internal forces add nothing to G (24.10a) nor, being central, to H_O
(24.10b, Case I).  Their power is (27.10)
P_int = ½ ΣΣ f_ij·(v_i − v_j) = Σ_pairs f_ij·(v_i − v_j) = −Σ_pairs φ ṙ,
which for the conservative kinds is −dV_int/dt (27.11-27.14, with
ψ(x_ij) = V_pair/2 per ordered pair).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, slots=True)
class Pair:
    """A central pair force between the particles ``between`` = (i, j) (24.15): a spring (k [N/m],
    free length L [m]), a damper (c [N·s/m]) or an inverse-square attraction (K [N·m²])."""

    kind: str
    between: tuple[int, int]
    k: float | None = None
    L: float | None = None
    c: float | None = None
    K: float | None = None


def pair_terms(pr, X: np.ndarray, V: np.ndarray):
    """(f_ij on i, φ ṙ-power f_ij·(v_i − v_j), potential, r, ṙ) for one pair;
    X, V of shape (N, 3) (or (N, 3, T) for many times)."""
    i, j = pr.between
    d = X[i] - X[j]
    dv = V[i] - V[j]
    r = np.sqrt(np.sum(d * d, axis=0))
    with np.errstate(divide="ignore", invalid="ignore"):
        e = d / r
        rdot = np.sum(e * dv, axis=0)
        if pr.kind == "spring":
            phi = pr.k * (r - pr.L)
            pot = 0.5 * pr.k * (r - pr.L) ** 2
        elif pr.kind == "damper":
            phi = pr.c * rdot
            pot = np.zeros_like(r)
        else:
            phi = pr.K / (r * r)
            pot = -pr.K / r
        f = -phi * e
        power = -phi * rdot
    if pr.kind == "damper" or pr.kind == "spring":
        # r = 0: the direction is undefined; a damper or a spring of free length 0 exerts no force there
        zero = r == 0
        if np.any(zero):
            f = np.where(zero, 0.0, f)
            power = np.where(zero, 0.0, power)
    return f, power, pot, r, rdot


class PairSet:
    """Every pair of a system as plain arrays, built once per solve, so that one evaluation of the
    internal forces is a few vectorised operations whatever the number of pairs (a loop over
    pairs costs ~60 µs each per evaluation: 45 pairs made a step 15 ms)."""

    def __init__(self, pairs, n: int):
        self.n = n
        self.I = np.array([pr.between[0] for pr in pairs], dtype=int)
        self.J = np.array([pr.between[1] for pr in pairs], dtype=int)
        kind = [pr.kind for pr in pairs]
        num = lambda name, k: np.array([float(getattr(pr, name)) if pr.kind == k else 0.0 for pr in pairs], dtype=float)  # noqa: E731
        self.k, self.L, self.c, self.K = num("k", "spring"), num("L", "spring"), num("c", "damper"), num("K", "inverse-square")
        self.spring = np.array([k == "spring" for k in kind], dtype=bool)
        self.damper = np.array([k == "damper" for k in kind], dtype=bool)
        self.inverse = np.array([k == "inverse-square" for k in kind], dtype=bool)
        self.can_vanish = bool(np.any(self.spring | self.damper))
        self.B = np.zeros((n, len(kind)))           # F = B f: +f on i, −f on j (24.9)
        self.B[self.I, np.arange(len(kind))] = 1.0
        self.B[self.J, np.arange(len(kind))] = -1.0
        self.BT = self.B.T.copy()
        self.only = kind[0] if len(set(kind)) == 1 else None

    def accelerations(self, masses: np.ndarray, X: np.ndarray, V: np.ndarray):
        """(a (N, 3), P_int) under the pair forces alone (24.9: f_ji = −f_ij)."""
        if not self.I.size:
            return np.zeros_like(X), 0.0
        d, dv = self.BT @ X, self.BT @ V          # x_i − x_j, v_i − v_j of every pair
        r = np.sqrt((d * d).sum(axis=1))
        with np.errstate(divide="ignore", invalid="ignore"):
            e = d / r[:, None]
            rdot = (e * dv).sum(axis=1)
            phi = self._phi(r, rdot)
            f = -phi[:, None] * e
            power = -phi * rdot
        if self.can_vanish:
            # r = 0: the direction is undefined; a damper or a spring of free length 0 exerts no force there
            zero = (r == 0) & ~self.inverse
            if zero.any():
                f[zero] = 0.0
                power = np.where(zero, 0.0, power)
        return (self.B @ f) / masses[:, None], float(power.sum())

    def _phi(self, r, rdot):
        """φ of every pair (f_ij = −φ e): k (r − L), c ṙ or K/r² by its kind."""
        if self.only == "spring":
            return self.k * (r - self.L)
        if self.only == "inverse-square":
            return self.K / (r * r)
        if self.only == "damper":
            return self.c * rdot
        return np.where(self.spring, self.k * (r - self.L), 0.0) + np.where(self.damper, self.c * rdot, 0.0) \
            + np.where(self.inverse, self.K / (r * r), 0.0)


def accelerations(pairs, masses: np.ndarray, X: np.ndarray, V: np.ndarray):
    """(a (N, 3), P_int) under the pair forces alone."""
    return PairSet(pairs, len(masses)).accelerations(masses, X, V)


def snapshot(pairs, masses, X, V, O):
    """Static results of the pair forces at one state: the force of each pair,
    their total force and moment about O (24.10), power (27.10), potential."""
    fs, P, Vint, rows = [], [], [], []
    f_tot = np.zeros(3)
    m_tot = np.zeros(3)
    for k, pr in enumerate(pairs):
        f, power, pot, r, rdot = pair_terms(pr, X, V)
        i, j = pr.between
        fs.append((f + 0.0).tolist())
        P.append(float(power))
        Vint.append(float(pot))
        terms_f = [f, -f]
        terms_m = [np.cross(X[i] - O, f), np.cross(X[j] - O, -f)]
        f_tot = f_tot + terms_f[0] + terms_f[1]
        m_tot = m_tot + terms_m[0] + terms_m[1]
        rows.append([str(k), f"{i}–{j}", pr.kind, float(r), float(rdot), f.tolist(), float(power), float(pot)])
    return {
        "f_pairs": fs,
        "f_internal": (f_tot + 0.0).tolist(),
        "m_internal": (m_tot + 0.0).tolist(),
        "P_internal": math.fsum(P),
        "V_internal": math.fsum(Vint),
    }, rows
