"""Inertia tensors of composite bodies (notes §30, §31, §35) — numeric core.

Every part contributes its standard inertia about its own center of mass
(part axes), turned to the body axes (30.37: I' = R I_part Rᵀ, R's columns
being the part axes) and moved to the composite center of mass by the
transfer theorem (31.7); holes contribute with a negative sign (31.3).  The
composite tensor is then moved to B (31.7), expressed on the requested basis
(30.36) and diagonalised with a symmetric eigensolver (30.28-30.31).
Closed forms only, in plain floats (Jacobi's method for the eigenproblem: no numpy).
"""

from __future__ import annotations

import math

from dyncli.errors import InputError
from dyncli.result import Result, SolveOptions, Table
from dyncli.topics.inertia import angular, mat3
from dyncli.topics.inertia import equations as eq
from dyncli.topics.inertia import rotations as rot
from dyncli.topics.inertia.eigen3 import eigvalsh3


#: relative gap below which two principal moments are reported as repeated
REPEAT_RTOL = 1e-10
#: relative gap below which principal axes are flagged as ill-conditioned
NEAR_RTOL = 1e-6


_SHAPES = {
    "rod": lambda m, q: eq.rod_moments(m, q.length),
    "box": lambda m, q: eq.box_moments(m, *q.size),
    "cylinder": lambda m, q: eq.cylinder_moments(m, q.radius, q.height),
    "disk": lambda m, q: eq.disk_moments(m, q.radius),
    "ring": lambda m, q: eq.ring_moments(m, q.radius),
    "sphere": lambda m, q: eq.sphere_moments(m, q.radius),
    "shell": lambda m, q: eq.shell_moments(m, q.radius),
    "point": lambda m, q: (0.0, 0.0, 0.0),
}


def shape_inertia(part):
    """Standard inertia of a part about its own center of mass, on its own
    axes (axis of symmetry e3), for mass ``part.mass`` (positive)."""
    if part.shape == "tensor":
        return rot.sym(part.inertia)
    if part.shape not in _SHAPES:  # pragma: no cover - the model restricts shapes
        raise ValueError(part.shape)
    return mat3.diag(_SHAPES[part.shape](part.mass, part))


def orientation_matrix(o):
    if o is None:
        return mat3.eye()
    return rot.from_fields(o.axis, o.angle, o.euler313, o.matrix)


def composite(parts):
    """(mass, com, I_com, per-part records, scale) in body components."""
    signs = [-1.0 if p.hole else 1.0 for p in parts]
    masses = [float(p.mass) for p in parts]
    xs = [[float(c) for c in p.at] for p in parts]
    m = math.fsum(sg * mm for sg, mm in zip(signs, masses))
    m_abs = math.fsum(masses)
    if not m > 1e-12 * m_abs:
        solid = math.fsum(mm for sg, mm in zip(signs, masses) if sg > 0)
        holes = math.fsum(mm for sg, mm in zip(signs, masses) if sg < 0)
        raise InputError(
            f"the holes remove {holes:.6g} kg from {solid:.6g} kg of solid parts: the remaining mass "
            f"{m:.6g} kg is not positive", _first_hole(parts))
    com = eq.center_of_mass([sg * mm for sg, mm in zip(signs, masses)], xs, m)
    I = [[0.0] * 3 for _ in range(3)]
    scale = 0.0
    recs = []
    for p, sgn, x in zip(parts, signs, xs):
        R = orientation_matrix(p.orientation)
        Ibar = eq.rotated(R, shape_inertia(p))                  # (30.37)
        Tr = rot.transfer_term(p.mass, [a - b for a, b in zip(x, com)])
        Ipart = [[Ibar[i][j] + Tr[i][j] for j in range(3)] for i in range(3)]
        I = [[I[i][j] + sgn * Ipart[i][j] for j in range(3)] for i in range(3)]
        scale += Ipart[0][0] + Ipart[1][1] + Ipart[2][2]
        recs.append((p, sgn, R, Ibar))
    return m, com, rot.sym(I), recs, scale


def _first_hole(parts) -> str:
    return next((f"parts.{k}" for k, p in enumerate(parts) if p.hole), "parts")


def _check_remainder(I_com, scale, res, where):
    """A remainder after holes must be a physical inertia tensor: positive-
    semidefinite, and with I1 + I2 >= I3 (the second-moment tensor
    ∫ρ p⊗p dV = ½tr(I)1 − I positive-semidefinite); otherwise exit 2."""
    lo, tri, s = rot.inertia_defect(I_com)
    tol = 1e-10 * max(scale, s, 1e-300)
    if lo < -tol:
        raise InputError(
            "the holes leave a remainder whose inertia tensor about its center of mass is not "
            f"positive-semidefinite (smallest principal moment {lo:.6g} kg·m²): they remove more "
            "inertia than the solid parts have", where)
    if tri > tol:
        raise InputError(
            "the holes leave a remainder that no positive mass distribution can have: its principal moments "
            f"violate the triangle inequality I₁ + I₂ ≥ I₃ (short by {tri:.6g} kg·m²; the second-moment "
            "tensor ∫ρ p⊗p dV is not positive-semidefinite); a hole probably lies (partly) outside the solid parts",
            where)


def solve(p, options: SolveOptions | None = None) -> Result:
    res = Result({}, method="closed-form", equations=["30.20", "31.3", "31.7"])
    _warn_tensor_parts(res, p)
    m, com, I_com, recs, scale = composite(p.parts)
    if not (math.isfinite(m) and mat3.finite(com) and mat3.finite(I_com)):
        raise InputError("the mass, center of mass or inertia tensor overflows a double (values beyond ~1e308)", "parts")
    if any(part.hole for part in p.parts):
        _check_remainder(I_com, scale, res, _first_hole(p.parts))
    B, pbar, T, I_B, tscale = _about(p, m, com, I_com, scale)
    A, lab = _basis(res, p)
    com_b, B_b, pbar_b = mat3.matvec(A, com), mat3.matvec(A, B), mat3.matvec(A, pbar)
    Ic_b, T_b, IB_b = (rot.sym(eq.rotated(A, X)) for X in (I_com, T, I_B))
    if not mat3.finite([Ic_b, T_b, IB_b]):
        raise InputError("the inertia tensor on the requested basis overflows a double (values beyond ~1e308)",
                         "basis" if p.basis is not None else ("about" if p.about is not None else "parts"))

    lam, axes, groups, lscale = rot.principal(IB_b, repeat_rtol=REPEAT_RTOL)
    lam = [max(x, 0.0) for x in lam]  # tiny negatives are rounding (checked above)
    res.equations += ["30.30", "30.31", "30.8"]
    radii = [eq.radius_of_gyration(x, m) for x in lam]
    L = max(mat3.max_abs(com_b), mat3.max_abs(B_b), 1e-300)
    res.results.update({
        "mass": m,
        "com": rot.clean(com_b, L),
        "I_com": rot.clean(Ic_b, tscale),
        "I_about": rot.clean(IB_b, tscale),
        "principal_moments": rot.clean(lam, tscale),
        "principal_axes": rot.clean(axes, 1.0),
        "radii_of_gyration": radii,
        "p_bar": rot.clean(pbar_b, L),
        "I_transfer": rot.clean(T_b, tscale),
        "principal_gap": min(lam[1] - lam[0], lam[2] - lam[1]),
        "principal_axes_unique": not groups,
        "principal_axes_note": _axes_note(lam, groups, lscale),
    })
    _warn_principal(res, lam, groups, lscale)
    if p.omega is not None:
        angular.add(res, p.omega, A, rot.sym(I_com), Ic_b, IB_b)
    _views(res, p, recs, lab, A, m, Ic_b, T_b, IB_b, pbar_b, lam, axes, radii, tscale)
    return res


def _warn_tensor_parts(res, p) -> None:
    for k, part in enumerate(p.parts):
        if part.shape == "tensor":
            lo, tri, s = rot.inertia_defect(part.inertia)
            if tri > 1e-10 * max(s, 1e-300):
                res.warn(f"parts.{k}.inertia violates the triangle inequality of principal moments "
                         f"(I₁ + I₂ < I₃ by {tri:.6g} kg·m²): no positive mass distribution has it")


def _about(p, m, com, I_com, scale):
    """(B, p̄, transfer term, I_B, tensor scale): the transfer theorem (31.7) to B (the center
    of mass when ``about`` is not given)."""
    B = list(com) if p.about is None else [float(c) for c in p.about]
    pbar = [a - b for a, b in zip(com, B)]
    T = rot.transfer_term(m, pbar)                      # overflow -> inf, rejected just below
    I_B = [[I_com[i][j] + T[i][j] for j in range(3)] for i in range(3)]
    tscale = max(scale + m * (pbar[0] * pbar[0] + pbar[1] * pbar[1] + pbar[2] * pbar[2]) * 2.0, 1e-300)
    if not (mat3.finite(T) and mat3.finite(I_B) and math.isfinite(tscale)):
        raise InputError(
            f"B is so far from the center of mass (|p̄| = {math.hypot(*pbar):.6g} m) that the transfer "
            "term m[(p̄·p̄)1 − p̄⊗p̄] (31.7) overflows a double (values beyond ~1e308)", "about")
    return B, pbar, T, I_B, tscale


def _basis(res, p):
    """(A, labels): the change of basis (30.36) I'' = A I' Aᵀ with A = Rᵀ, or the body axes."""
    if p.basis is not None:
        res.equations.append("30.36")
        return mat3.transpose(orientation_matrix(p.basis)), ("e''₁", "e''₂", "e''₃")
    return mat3.eye(), ("e'₁", "e'₂", "e'₃")


def _axes_note(lam, groups, scale) -> str:
    if scale == 0.0:
        return "all principal moments are zero (a point mass at B): every orthonormal basis is a principal basis"
    if not groups:
        return "distinct principal moments: the principal axes are unique up to sign"
    parts = []
    for g in groups:
        ks = " = ".join(f"I{k + 1}" for k in g)
        if len(g) == 3:
            parts.append(f"{ks}: every direction is principal; any orthonormal basis is valid")
        else:
            parts.append(f"{ks}: any orthonormal basis of their eigenspace (the plane of axes "
                         f"{' and '.join(str(k + 1) for k in g)}) is a valid choice of these principal axes")
    return "; ".join(parts)


def _warn_principal(res, lam, groups, scale):
    if scale == 0.0:
        res.warn("all principal moments are zero (a single point mass at B): the principal axes are arbitrary; "
                 "the identity basis is reported")
        return
    for g in groups:
        if len(g) == 2:
            res.warn(f"principal moments {g[0] + 1} and {g[1] + 1} are equal ({lam[g[0]]:.6g} kg·m²): any orthonormal "
                     "pair of axes in their eigenspace is principal; the reported pair is the canonical choice "
                     "(projections of the basis vectors)")
        elif len(g) == 3:
            res.warn(f"all principal moments are equal ({lam[0]:.6g} kg·m²): every direction is principal; "
                     "the basis vectors are reported")
    for k in range(2):
        d = lam[k + 1] - lam[k]
        if REPEAT_RTOL * scale < d <= NEAR_RTOL * scale:
            res.warn(f"principal moments {k + 1} and {k + 2} are nearly repeated (gap {d:.3g} kg·m², relative "
                     f"{d / scale:.3g}): their principal axes are ill-conditioned (an error δ in the tensor turns "
                     "them by about δ/gap rad)")
    for k in range(3):
        if lam[k] == 0.0:
            res.warn(f"principal moment {k + 1} is zero: all the mass lies on the line through B along principal "
                     f"axis {k + 1} (radius of gyration 0)")


def _views(res, p, recs, lab, A, m, Ic, T, IB, pbar, lam, axes, radii, scale):
    def c(x):
        return rot.clean(x, scale)

    rows = []
    for k, (part, sgn, R, Ibar) in enumerate(recs):
        mom = eigvalsh3(Ibar)
        rows.append([str(k), part.shape + (" (hole)" if part.hole else ""), sgn * part.mass,
                     rot.clean(mat3.matvec(A, part.at), max(1e-300, mat3.max_abs(part.at))),
                     c(mom)])
    res.views.append(Table("parts", ["#", "shape", "mass [kg]", "center [m]", "own principal moments [kg·m²]"], rows,
                           note="holes count with negative mass (31.3); center on the " + ("basis e''ᵢ" if p.basis is not None else "body axes e'ᵢ")))
    Icc, Tc, IBc = c(Ic), c(T), c(IB)
    if p.about is not None:
        cols = [""] + [f"Ī ·{j}" for j in "123"] + [f"+Δ ·{j}" for j in "123"] + [f"=I_B ·{j}" for j in "123"]
        trows = [[lab[i]] + Icc[i] + Tc[i] + IBc[i] for i in range(3)]
        pb = ", ".join(f"{x:.6g}" for x in pbar)
        res.views.append(Table("transfer theorem (31.7): I_B = Ī + m[(p̄·p̄)1 − p̄⊗p̄]", cols, trows,
                               note=f"Δ = m[(p̄·p̄)1 − p̄⊗p̄], m = {m:.6g} kg, p̄ = [{pb}] m (center of mass from B); row i, column j on {' '.join(lab)} [kg·m²]"))
    else:
        cols = [""] + [f"Ī {b}" for b in lab]
        res.views.append(Table("inertia about the center of mass Ī [kg·m²]", cols,
                               [[lab[i]] + Icc[i] for i in range(3)]))
    ax = rot.clean(axes, 1.0)
    prow = [["moment [kg·m²]"] + c(lam), ["radius of gyration [m]"] + list(radii)]
    prow += [[lab[i]] + ax[i] for i in range(3)]
    res.views.append(Table("principal moments and directions (columns)", ["", "axis 1", "axis 2", "axis 3"], prow,
                           note="each column is a unit principal direction on " + " ".join(lab) + "; right-handed"))
