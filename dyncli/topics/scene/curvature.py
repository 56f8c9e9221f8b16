"""Second derivatives of a scene's rows and potential, analytic (docs/types/scene.md: equilibria).

Every row of a joint is a linear functional c·r of body points, a body coordinate, or the
length |r_P − r_Q| of a link; a point of a rigid body r = x + Q(θ) p has one second derivative,
∂²r/∂θ² = −Q(θ) p.  From these:

* :func:`rows_hessian` — Σ_k w_k ∇²φ_k for weights w (the multipliers: the constraint-force
  curvature of the linearized system);
* :func:`potential_hessian` — ∇²V of gravity (0), springs (k (∇s ∇sᵀ + s ∇²|d|)) and
  constant forces (−∇²(F·r_P));
* :func:`damping_matrix` — the dampers' C (the generalized force −C q̇ at rest);
* :func:`rest_hessians` — Σ_k λ_k ∇²φ_k − ∇²V at many configurations at once (the Jacobian of
  the equilibrium search's Newton from all its starts: links and springs in columns, every
  other joint and load row by row by the forms above).

No finite differences: the tests compare these with differences of the Jacobians.
"""

from __future__ import annotations

import math

import numpy as np

from .system import Point


def point_hessian(P: Point, q, c, n: int) -> np.ndarray:
    """∇²(c·r_P) for a constant 2-vector c: only the body angle's diagonal entry, −c·Q(θ)p."""
    H = np.zeros((n, n))
    if P.body is not None and P.turns_with_body:
        k = P.body.index[2]
        H[k, k] = -float(np.asarray(c, float) @ P.arm(q))
    return H


def length_terms(P: Point, Q: Point, q, n: int):
    """(|d|, e, ∇|d|, ∇²|d|) of d = r_P − r_Q."""
    d = P.pos(q) - Q.pos(q)
    ln = math.hypot(d[0], d[1])
    e = d / ln
    D = P.jac(q, n) - Q.jac(q, n)
    grad = e @ D
    perp_proj = np.eye(2) - np.outer(e, e)
    H = D.T @ perp_proj @ D / ln + point_hessian(P, q, e, n) - point_hessian(Q, q, e, n)
    return ln, e, grad, H


def span_hessian(sp, q, n: int) -> np.ndarray:
    """∇² of a spanning segment's length (elements.Spanning): D_Δᵀ n nᵀ D_Δ / ℓ plus u·∇²X_b −
    u·∇²X_a, with D_Δ the Jacobian of X_b − X_a (its disk angles enter linearly)."""
    u1, u2, ell, *_ = sp.geometry(q)
    u, nrm = np.array([u1, u2]), np.array([-u2, u1])
    g = nrm @ (sp.B.jac(q, n) - sp.A.jac(q, n))
    return np.outer(g, g) / ell + point_hessian(sp.B, q, u, n) - point_hessian(sp.A, q, u, n)


def _element_hessian(el, q, w, n: int) -> np.ndarray:
    if hasattr(el, "hessian"):          # an element on a curve (dyncli/topics/scene/curved.py)
        return el.hessian(q, w, n)
    kind = el.kind
    if kind == "pin":
        return point_hessian(el.P, q, w[:2], n) - point_hessian(el.Q, q, w[:2], n)
    if kind == "slider":
        return point_hessian(el.body_point, q, w[0] * np.array(el.surface.n), n)
    if kind == "contact":
        c = w[0] * np.array(el.surface.n)
        if el.mode == "stick":
            c = c + w[1] * np.array(el.surface.d)
        return point_hessian(el.P, q, c, n)
    if kind == "link":
        return w[0] * length_terms(el.P, el.Q, q, n)[3]
    if kind == "guide":
        return point_hessian(el.P, q, w[0] * el.w, n)
    if kind == "cord":
        H = np.zeros((n, n))
        for r, run in enumerate(el.runs):
            for seg in run:
                if seg.spanning is not None:        # n nᵀ/ℓ on X_b − X_a, and the points' own turns
                    H += w[r] * span_hessian(seg.spanning, q, n)
                    continue
                if seg.turning is not None:         # a string's from its tangent point held fixed
                    P, T, _got = seg.anchor(q)
                    H += w[r] * length_terms(P, T, q, n)[3]
                    continue
                for end, sign in ((seg.b, 1.0), (seg.a, -1.0)):
                    if end.point is not None:
                        H += sign * point_hessian(end.point, q, w[r] * seg.u, n)
        return H
    return np.zeros((n, n))          # rolls, drive: rows affine in q


def rows_hessian(system, q, lam) -> np.ndarray:
    """Σ_k λ_k ∇²φ_k over every row of every joint."""
    n = system.n
    H = np.zeros((n, n))
    for i, el in enumerate(system.elements):
        w = system.lam_of(lam, i)
        if np.any(w):
            H += _element_hessian(el, q, w, n)
    return H


def potential_hessian(system, q) -> np.ndarray:
    """∇²V of the conservative loads (gravity is linear in q: no term)."""
    n = system.n
    H = np.zeros((n, n))
    for ld in system.loads:
        if ld.kind == "spring":
            ln, _e, grad, Hl = length_terms(ld.P, ld.Q, q, n)
            s = ln - ld.L
            if ld.one_sided == "compression" and s > 0 or ld.one_sided == "tension" and s < 0:
                continue
            H += ld.k * (np.outer(grad, grad) + s * Hl)
        elif ld.kind == "force":
            F = np.array(ld.F(0.0), dtype=float)
            H -= point_hessian(ld.P, q, F, n)
    return H


def damping_matrix(system, q) -> np.ndarray:
    """C with the dampers' generalized force −C q̇ (linear in the rates)."""
    n = system.n
    C = np.zeros((n, n))
    for ld in system.loads:
        if ld.kind == "damper":
            _ln, _e, grad, _H = length_terms(ld.P, ld.Q, q, n)
            C += ld.c * np.outer(grad, grad)
    return C


def _point_hessian_many(P: Point, X, c1, c2, H) -> None:
    """H (k, n, n) += ∇²(c·r_P) at every state of the Stack X (c1, c2: columns)."""
    if P.body is not None and P.turns_with_body:
        a = P.arms_many(X)
        assert a is not None, "a point turning with its body has an arm"
        k = P.body.index[2]
        H[:, k, k] -= c1 * a[0] + c2 * a[1]


def _length_terms_many(P: Point, Q: Point, X, n: int):
    """:func:`length_terms` at every state of the Stack X: (|d|, ∇|d|, ∇²|d|) as (k,), (k, n), (k, n, n)."""
    (p1, p2), (q1, q2) = P.xy_many(X), Q.xy_many(X)
    d1, d2 = p1 - q1, p2 - q2
    ln = np.hypot(d1, d2)
    e1, e2 = d1 / ln, d2 / ln
    D = np.zeros((X.k, 2, n))
    P.add_jac2_many(D, X, 1.0)
    Q.add_jac2_many(D, X, -1.0)
    grad = e1[:, None] * D[:, 0] + e2[:, None] * D[:, 1]
    proj = np.empty((X.k, 2, 2))
    proj[:, 0, 0], proj[:, 1, 1] = 1.0 - e1 * e1, 1.0 - e2 * e2
    proj[:, 0, 1] = proj[:, 1, 0] = -e1 * e2
    H = np.swapaxes(D, 1, 2) @ proj @ D / ln[:, None, None]
    _point_hessian_many(P, X, e1, e2, H)
    _point_hessian_many(Q, X, -e1, -e2, H)
    return ln, grad, H


def rest_hessians(system, Q, LAM) -> np.ndarray:
    """Σ_k λ_k ∇²φ_k − ∇²V at the configurations Q (k, n) with the multipliers LAM (k, m): what
    :func:`rows_hessian` minus :func:`potential_hessian` give row by row, links and springs
    computed in columns for all rows at once (an element or load of another kind row by row)."""
    k, n = Q.shape
    X = system.stack(Q)
    H = np.zeros((k, n, n))
    for i, el in enumerate(system.elements):
        W = LAM[:, system.offsets[i]:system.offsets[i] + el.rows]
        if not el.rows or not np.any(W):
            continue
        if el.kind == "link" and not hasattr(el, "hessian"):
            w = W[:, 0]
            Hl = _length_terms_many(el.P, el.Q, X, n)[2]
            H += np.where((w != 0)[:, None, None], w[:, None, None] * Hl, 0.0)
            continue
        for r in range(k):
            if np.any(W[r]):
                H[r] += _element_hessian(el, Q[r], W[r], n)
    for ld in system.loads:
        if ld.kind == "spring":
            ln, grad, Hl = _length_terms_many(ld.P, ld.Q, X, n)
            s = ln - ld.L
            on = ~((s > 0) if ld.one_sided == "compression" else (s < 0) if ld.one_sided == "tension" else np.zeros(k, bool))
            G = ld.k * (grad[:, :, None] * grad[:, None, :] + s[:, None, None] * Hl)
            H -= np.where(on[:, None, None], G, 0.0)
        elif ld.kind == "force":
            F = np.array(ld.F(0.0), dtype=float)
            for r in range(k):
                H[r] += point_hessian(ld.P, Q[r], F, n)
    return H
