"""The reduced equations of motion of a scene, symbolically (``--symbolic``; see :mod:`.symbolic`).

Chosen coordinates s (a drive's coordinate first, then the bodies' angles, then the
positions: the textbook's choice), every rate q̇ = N(q) ṡ with N spanning the null space of
the constraint Jacobian J (drive rows left out), and the projection of M q̈ = f + Jᵀλ onto it:

    NᵀMN s̈ = Nᵀ (f − M q̈ₚ) (+ the drives' forces on their coordinates),

q̈ₚ = the acceleration with s̈ = 0 (J q̈ₚ = γ).  Nᵀ Jᵀ = 0 removes every joint force.  When the
rows are linear in the other coordinates they are solved exactly (q = q(s), N = ∂q/∂s,
q̈ₚ = ∂(N ṡ)/∂s ṡ); otherwise N and q̈ₚ come from J's blocks and the dependent coordinates
stay as symbols.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .assembly import rank
from .symbolic import Eq, numeric_jacobian, tidy


def choose(J: np.ndarray, prefer: list[int], k: int) -> list[int]:
    """k coordinates, greedily in the order ``prefer``, each kept when the other columns of J
    still have J's rank (so that those are fixed by the rows)."""
    r = rank(J)
    chosen: list[int] = []
    for j in prefer:
        if len(chosen) == k:
            break
        rest = [c for c in range(J.shape[1]) if c not in chosen and c != j]
        if rank(J[:, rest]) == r if J.size else True:
            chosen.append(j)
    return sorted(chosen, key=prefer.index)


def _preference(system, drives: dict) -> list[int]:
    driven = list(drives.values())
    angles = [b.index[2] for b in system.bodies if b.rigid and b.index[2] not in driven]
    rest = [j for j in range(system.n) if j not in driven and j not in angles]
    return driven + angles + rest


def _linear_part(rows, dep, C, D, q0):
    """Split the dependent coordinates into those the rows give linearly (solved exactly, in
    the others) and the rest ``a`` (a closed loop's angles): (solution, a, rows left for a)."""
    qs = [C.q[j] for j in dep]
    lin = [q for q in qs if not any(sp.diff(r, q).has(q) for r in rows)]
    a = [q for q in qs if q not in lin]
    try:
        A, b = sp.linear_eq_to_matrix(rows, lin) if lin else (sp.zeros(len(rows), 0), sp.Matrix(rows))
    except Exception:  # noqa: BLE001 - sympy's NonlinearError: products of them
        return None, qs, rows
    sub = {**D.S.values, **{q: float(x) for q, x in zip(C.q, q0)}}
    An = np.array(A.subs(sub).evalf(), dtype=float) if lin else np.zeros((len(rows), 0))
    pick: list[int] = []
    for i in range(len(rows)):          # rows that fix the linear ones (a nonsingular block)
        if len(pick) < len(lin) and rank(An[pick + [i]]) == len(pick) + 1:
            pick.append(i)
    if len(pick) < len(lin):
        return None, qs, rows
    sol = A[pick, :].LUsolve(b[pick, :]) if lin else []
    sol = {q: tidy(x) for q, x in zip(lin, sol)}
    left = [tidy(r.subs(sol)) for i, r in enumerate(rows) if i not in pick]
    return sol, a, left


def reduce(D, P, scene, t) -> None:
    system, C = scene.system, D.C
    n = system.n
    rows = [r for e, rs, _ in P.rows if e.kind != "drive" for r in rs]
    Jn = numeric_jacobian(rows, C, D.S.values, scene.q0)
    k = n - (rank(Jn) if rows else 0)
    if k == 0:
        D.notes.append("no degree of freedom: the joints fix every coordinate (statics)")
        return
    idx = choose(Jn, _preference(system, D.drives), k) if rows else list(range(n))
    D.independent = idx
    dep = [j for j in range(n) if j not in idx]
    s, sd, sdd = (sp.Matrix([v[j] for j in idx]) for v in (C.q, C.qd, C.qdd))
    sol, a, left = _linear_part(rows, dep, C, D, scene.q0)
    if sol is None:
        D.notes.append("no symbolic reduction: the joints' rows are not linear in any coordinate")
        return
    D.explicit = sol
    qv = sp.Matrix([sol.get(q, q) for q in C.q])
    A_s = sp.zeros(0, k)
    if a:                               # ȧ = A_s ṡ from the rows left: ∂ψ/∂a ȧ + ∂ψ/∂s ṡ = 0
        psi = sp.Matrix(left)
        A_s = (-psi.jacobian(a).LUsolve(psi.jacobian(s))).applyfunc(tidy)
        D.notes.append(", ".join(D.S.text[x] for x in a) + " given by the loop's closure (the constraint equations "
                       "with the other coordinates eliminated)")
        D.closure = [Eq("closure", r, sp.Integer(0)) for r in left]
    adot = A_s * sd
    N = (qv.jacobian(s) + (qv.jacobian(a) * A_s if a else sp.zeros(n, k))).applyfunc(tidy)
    qdot = N * sd
    qdd_p = qdot.jacobian(s) * sd + (qdot.jacobian(a) * adot if a else sp.zeros(n, 1))
    D.velocity = {C.qd[j]: tidy(qdot[j]) for j in range(n)}
    f = sp.Matrix(P.f)
    for _ in range(2):                      # laws in terms of other named loads (ℓ inside T)
        f = f.subs(P.subs)
    f = f.subs(D.explicit).subs(D.velocity)
    Mm = sp.diag(*P.M)
    Meff = (N.T * Mm * N).applyfunc(tidy)
    rhs = N.T * (f - Mm * qdd_p)
    by_coord = {j: force for force, j in D.drives.items()}
    law = _drive_laws(D, P, idx, t)
    for i in range(k):
        terms = [(Meff[i, j], sdd[j]) for j in range(k) if Meff[i, j] != 0]
        lhs = sum((c * x for c, x in terms), sp.Integer(0))
        label = f"along {D.S.text[C.q[idx[i]]]}"
        force = by_coord.get(idx[i])
        if force is None:
            D.reduced.append(Eq(label, lhs, tidy(rhs[i]), terms=terms))
        else:                               # the driver's force or couple the motion needs
            D.reduced.append(Eq(label + " (the drive's force)", force, tidy((lhs - rhs[i]).subs(law))))


def _drive_laws(D, P, idx, t) -> dict:
    """q̇, q̈ of every driven coordinate from its law in t (the drive's rows)."""
    C, law = D.C, {}
    for e, rows, _ in P.rows:
        if e.kind == "drive":
            f = C.q[e.index] - rows[0]
            law[C.qd[e.index]] = sp.diff(f, t)
            law[C.qdd[e.index]] = sp.diff(f, t, 2)
    return law
