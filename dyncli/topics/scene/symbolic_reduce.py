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
from .symbolic_rows import Eq, numeric_jacobian, tidy


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


def _preference(system, D) -> list[int]:
    driven = list(D.drives.values()) + list(D.curves.values())
    angles = [b.index[2] for b in system.bodies if b.rigid and b.index[2] not in driven]
    rest = [j for j in range(len(D.C.q)) if j not in driven and j not in angles]
    return driven + angles + rest


def _linear_part(rows, dep, C, D, q0):
    """Eliminate the dependent coordinates one row at a time, each from a row linear in it with
    a coefficient free of the unsolved ones and non-zero at t = 0: (solution, the coordinates
    left ``a`` (a closed loop's angles), the rows left for them)."""
    num = {**D.S.values, **{q: float(x) for q, x in zip(C.q, q0)}}
    left, todo, sol = list(rows), [C.q[j] for j in dep], {}
    progress = True
    while progress and todo:
        progress = False
        for i, r in enumerate(left):
            q = next((x for x in todo if _solvable(r, x, todo, num)), None)
            if q is None:
                continue
            c = sp.diff(r, q)
            val = tidy(-(r - c * q).expand() / c)
            sol = {k: tidy(v.subs(q, val)) for k, v in sol.items()}
            sol[q] = val
            todo.remove(q)
            left = [tidy(x.subs(q, val)) for k, x in enumerate(left) if k != i]
            progress = True
            break
    return sol, todo, left


def _solvable(r, q, todo, num) -> bool:
    c = sp.diff(r, q)
    if c == 0 or c.has(*todo):
        return False
    try:
        return abs(float(c.subs(num))) > 1e-12
    except (TypeError, ValueError):
        return False


def reduce(D, P, scene, t) -> None:
    system, C = scene.system, D.C
    n = len(C.q)
    rows = [r for e, rs, _ in P.rows if e.kind != "drive" for r in rs]
    Jn = numeric_jacobian(rows, C, D.S.values, D.state[0])
    k = n - (rank(Jn) if rows else 0)
    if k == 0:
        D.notes.append("no degree of freedom: the joints fix every coordinate (statics)")
        return
    idx = choose(Jn, _preference(system, D), k) if rows else list(range(n))
    D.independent = idx
    dep = [j for j in range(n) if j not in idx]
    s, sd, sdd = (sp.Matrix([v[j] for j in idx]) for v in (C.q, C.qd, C.qdd))
    sol, a, left = _linear_part(rows, dep, C, D, D.state[0])
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
