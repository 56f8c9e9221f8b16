"""Small oscillations about an equilibrium (`linearize: true`; §17 generalized; docs/types/scene.md).

In the independent coordinates s of the equilibrium (q = q(s), q̇ = Z ṡ with Z[s] = I and
J Z = 0) the linearized equations are M s̈ + C ṡ + K s = 0 with

    M = Zᵀ M Z,   C = Zᵀ C Z,   K = Zᵀ (∇²V − Σ λ_k ∇²φ_k) Z,

the second term the constraint forces' curvature (λ the joint forces at rest).  Stability from
the eigenvalues ω² of the symmetric pencil (K, M): all positive — stable; one negative —
unstable; zero (within the rounding of the two terms) and none negative — neutral (the
linearization does not decide).  Natural frequencies ω = √ω² ascending, the modes normalised
with their first non-zero component 1.  The response to the initial conditions is the sum of the
modes in closed form (undamped: s − s_eq = Σ u_r (a_r cos ω_r t + b_r sin ω_r t); damped: the
complex modes of the first-order system, Σ c_k φ_k e^{λ_k t}).
"""

from __future__ import annotations

import math

import numpy as np

from . import assembly, curvature, equilibria

EPS = float(np.finfo(float).eps)


def coordinates_at(system, q, preferred: list[int]) -> list[int]:
    """The independent coordinates at q: the scene's own when the joints leave them free there
    (well conditioned), otherwise chosen again at q."""
    J = system.jac(q)
    n = system.n
    dep = [k for k in range(n) if k not in preferred]
    if not J.shape[0]:
        return preferred
    if len(dep) == J.shape[0] and np.linalg.cond(J[:, dep]) < 1e8:
        return preferred
    return assembly.independent(J, n)


def linear_system(system, q, lam, indep: list[int]):
    """(M, C, K, zero tolerance of the ω²) of the reduced linear system at an equilibrium."""
    Z = equilibria.null_basis(system.jac(q), system.n, indep)
    M = Z.T @ (system.mass[:, None] * Z)
    Kv = Z.T @ curvature.potential_hessian(system, q) @ Z
    Kc = Z.T @ curvature.rows_hessian(system, q, lam) @ Z
    K = Kv - Kc
    K = 0.5 * (K + K.T)
    C = Z.T @ curvature.damping_matrix(system, q) @ Z
    Mi = np.linalg.inv(np.linalg.cholesky(M))
    size = max(float(np.linalg.norm(Mi @ Kv @ Mi.T, 2)), float(np.linalg.norm(Mi @ Kc @ Mi.T, 2)))
    return M, 0.5 * (C + C.T), K, 1e-9 * size


def normalised(u) -> list:
    """A mode with its first non-zero component 1 (non-zero: above 1e-9 of its largest)."""
    u = np.asarray(u)
    big = float(np.max(np.abs(u), initial=0.0))
    k = next(i for i in range(len(u)) if abs(u[i]) > 1e-9 * big)
    u = u / u[k]
    u = np.where(np.abs(u) <= 1e-12, 0.0, u)
    return u


def _pair(z) -> list:
    return [float(z.real) + 0.0, float(z.imag) + 0.0]


def analyse(system, q, lam, indep):
    from scipy.linalg import eigh

    M, C, K, tol = linear_system(system, q, lam, indep)
    w2, U = eigh(K, M)
    w2 = np.where(np.abs(w2) <= tol, 0.0, w2)
    if np.all(w2 > 0):
        stability = "stable"
    elif np.any(w2 < 0):
        stability = "unstable"
    else:
        stability = "neutral"
    modes = [normalised(U[:, r]) for r in range(U.shape[1])]
    # a neutral equilibrium whose every zero mode is a free motion of the whole scene (a free
    # cart, a wheel rolling on a floor): its frequencies hold, ω = 0 for that motion (the
    # textbook's rigid-body mode)
    free = stability == "neutral" and _translation_modes(system, q, indep, U[:, w2 == 0.0])
    out = {"stability": stability, "stable": stability == "stable", "omega2": [float(x) for x in w2],
           "frequencies": [math.sqrt(x) for x in w2] if stability == "stable" or free else None,
           "modes": [[float(x) for x in u] for u in modes],
           "M": M.tolist(), "K": K.tolist()}
    out["frequencies_hz"] = None if out["frequencies"] is None else [w / (2 * math.pi) for w in out["frequencies"]]
    damped = bool(np.any(C))
    if damped:
        out["C"] = C.tolist()
        out["damped"] = _damped(M, C, K)
    return out, (M, C, K, w2, modes, damped)


def _translation_modes(system, q, indep, U0) -> bool:
    """Whether the zero modes U0 (columns, in the coordinates ``indep``) are all free motions of
    the whole scene: translations along axes it is free to translate along
    (SceneSystem.translations), or along which its disks roll (SceneSystem.rolling_translations)."""
    free = [system.translation(axis) for axis in system.translations(q)] + system.rolling_translations(q)
    if not free:
        return False
    Z = equilibria.null_basis(system.jac(q), system.n, indep)
    T = np.stack(free, axis=1)
    V = Z @ U0                                      # the zero modes in q
    fit = np.linalg.lstsq(T, V, rcond=None)[0]
    return bool(float(np.max(np.abs(T @ fit - V), initial=0.0)) <= 1e-9 * max(float(np.max(np.abs(V), initial=0.0)), 1e-300))


def _state_matrix(M, C, K):
    d = M.shape[0]
    Minv = np.linalg.inv(M)
    A = np.zeros((2 * d, 2 * d))
    A[:d, d:] = np.eye(d)
    A[d:, :d] = -Minv @ K
    A[d:, d:] = -Minv @ C
    return A


def _damped(M, C, K) -> dict:
    """The complex modes of M s̈ + C ṡ + K s = 0: eigenvalues λ = −ζω ± iω_d (one of each pair,
    ω_d ≥ 0, ascending in |λ|), their displacement shapes (first non-zero component 1, as
    [re, im]), damped frequencies and damping ratios."""
    d = M.shape[0]
    lam, V = np.linalg.eig(_state_matrix(M, C, K))
    keep = [k for k in range(2 * d) if lam[k].imag > 0 or (lam[k].imag == 0)]
    keep = sorted(keep, key=lambda k: (abs(lam[k]), lam[k].real))
    out: dict[str, list] = {"eigenvalues": [], "modes": [], "frequencies": [], "damping_ratios": []}
    overdamped = _overdamped_ratios(M, C, K)
    for k in keep:
        z = lam[k]
        out["eigenvalues"].append(_pair(z))
        out["modes"].append([_pair(c) for c in normalised(V[:d, k])])
        out["frequencies"].append(abs(float(z.imag)))
        zeta = -float(z.real) / abs(z) + 0.0 if abs(z) > 0 else None      # (+ 0.0: no −0.0)
        if z.imag == 0 and z.real < 0:
            zeta = next((zr for (mr, cr, kr, zr) in overdamped
                         if abs(mr * z.real * z.real + cr * z.real + kr) <= 1e-8 * (mr * z.real * z.real + kr)), zeta)
        out["damping_ratios"].append(zeta)
    return out


def _overdamped_ratios(M, C, K) -> list[tuple[float, float, float, float]]:
    """(m_r, c_r, k_r, ζ_r) of each overdamped mode (ζ_r = c_r/(2 √(k_r m_r)) > 1) when the
    damping decouples in the undamped modes (one degree of freedom always; C proportional): a
    real eigenvalue λ of that mode (m_r λ² + c_r λ + k_r = 0) reports the mode's ζ, not 1 (the
    ratio −λ/|λ| of a real root alone).  Empty where C does not decouple: each real root keeps 1."""
    import scipy.linalg

    try:
        w2, U = scipy.linalg.eigh(K, M)
    except (np.linalg.LinAlgError, ValueError):
        return []
    Cm = U.T @ C @ U
    off = Cm - np.diag(np.diag(Cm))
    if float(np.max(np.abs(off), initial=0.0)) > 1e-9 * max(float(np.max(np.abs(Cm))), 1e-300):
        return []
    Mm, Km = np.diag(U.T @ M @ U), np.diag(U.T @ K @ U)
    out = []
    for mr, cr, kr in zip(Mm, np.diag(Cm), Km):
        if mr > 0 and kr > 0 and cr > 0 and cr * cr > 4 * kr * mr:
            out.append((float(mr), float(cr), float(kr), float(cr / (2 * math.sqrt(kr * mr)))))
    return out


def response(lin, ds, dv, times) -> dict:
    """The linear response to s − s_eq = ds, ṡ = dv at t = 0, as a sum of modes in closed form."""
    M, C, K, w2, modes, damped = lin
    if not damped:
        a, b = [], []
        for r, u in enumerate(modes):
            mu = float(u @ M @ u)
            a.append(float(u @ M @ ds) / mu)
            b.append(float(u @ M @ dv) / ((math.sqrt(w2[r]) if w2[r] > 0 else 1.0) * mu))
        s = [sum((np.array(u) * _modal(a[r], b[r], w2[r], t) for r, u in enumerate(modes)), np.zeros(len(ds)))
             for t in times]
        return {"a": a, "b": b, "ds": [[float(x) for x in si] for si in s]}
    d = M.shape[0]
    lam, V = np.linalg.eig(_state_matrix(M, C, K))
    z0 = np.concatenate([ds, dv])
    if np.linalg.cond(V) < 1e8:
        c = np.linalg.solve(V, z0)
        zs = [(V @ (c * np.exp(lam * t))).real for t in times]
    else:                               # a defective pair (critical damping): the exponential itself
        from scipy.linalg import expm

        A = _state_matrix(M, C, K)
        zs = [expm(A * t) @ z0 for t in times]
    return {"a": None, "b": None, "ds": [[float(x) for x in z[:d]] for z in zs]}


def _modal(a: float, b: float, w2: float, t: float) -> float:
    """One mode's amplitude at t: a cos ωt + b sin ωt, or a + b t for a free motion (ω = 0)."""
    if w2 == 0.0:
        return a + b * t
    w = math.sqrt(w2)
    return a * math.cos(w * t) + b * math.sin(w * t)


def results(scene, times, warn) -> list:
    """The `equilibria` result: every rest configuration found, lowest potential first, each
    with its stability and linear system; the response to the initial conditions about the
    stable equilibrium nearest the initial configuration."""
    s, q0, v0 = scene.system, scene.q0, scene.v0
    preferred = [s.names.index(c) for c in scene.coords]
    found = equilibria.find(s, q0, preferred, warn)
    found.sort(key=lambda e: s.potential(e[0]))
    scale = np.where([nm.startswith("angle.") for nm in s.names], 1.0, assembly.length_scale(q0, s))
    out, lins = [], []
    tiny = 64 * EPS * assembly.length_scale(q0, s)
    for q, lam in found:
        q = np.where(np.abs(q) <= tiny, 0.0, q)         # rounding about an exact 0 (an upright rest)
        indep = coordinates_at(s, q, preferred)
        entry, lin = analyse(s, q, lam, indep)
        out.append({"coordinates": [s.names[k] for k in indep], "values": [float(q[k]) + 0.0 for k in indep],
                    **_configuration(s, q, lam), **entry, "response": None})
        lins.append((indep, lin))
    # about a stable rest, or a neutral one whose zero modes are free motions (their frequencies
    # given: the motion along them is a + b t)
    stable = [k for k, e in enumerate(out) if e["stable"] or e["frequencies"] is not None]
    if stable:
        k = min(stable, key=lambda k: float(np.max(np.abs((found[k][0] - q0) / scale))))
        indep, lin = lins[k]
        ds = q0[indep] - found[k][0][indep]
        r = response(lin, ds, v0[indep], times)
        r["s"] = [[float(found[k][0][j]) + x for j, x in zip(indep, row)] for row in r.pop("ds")]
        out[k]["response"] = r
    return out


def _configuration(s, q, lam) -> dict:
    """Every body's centre and angle, the potential and the joint forces at rest."""
    x, angle, reaction = {}, {}, {}
    for b in s.bodies:
        i = b.index
        x[b.name] = [float(q[i[0]]) + 0.0, float(q[i[1]]) + 0.0, 0.0]
        if b.rigid:
            angle[b.name] = float(q[i[2]]) + 0.0
    v = np.zeros(s.n)
    for k, e in enumerate(s.elements):
        if e.kind != "guide":
            reaction[e.name] = e.report(s.lam_of(lam, k), q, v, 0.0)
    return {"x": x, "angle": angle, "V": s.potential(q), "reaction": reaction}


def refusal(scene) -> str | None:
    """Why `linearize` does not apply to this scene (None when it does)."""
    s = scene.system
    if scene.dof == 0:
        return ("linearize needs a scene that can move (at least one degree of freedom): this one has none; "
                "remove `linearize`")
    for e in s.elements:
        if e.kind == "drive":
            return (f"the drive {e.name!r} prescribes a motion in time, so the scene has no equilibrium: remove "
                    "the drive or `linearize`")
        if e.kind == "contact" and (e.mu_s or e.mu_k):
            return (f"the contact {e.name!r} has friction: where it rests depends on how it got there (static "
                    "friction is not decided by equilibrium alone); make it smooth or remove `linearize`")
    for ld in s.loads:
        if ld.kind in ("force", "torque") and not ld.constant:
            return f"{ld.label} depends on time, so the scene has no equilibrium: make it constant or remove `linearize`"
    return None
