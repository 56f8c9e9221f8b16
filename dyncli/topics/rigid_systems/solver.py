"""Systems of point masses and rigid bodies with massless links (notes §36)
— numeric core, closed forms.

spin-change: with no moment about the fixed axis, H_O·e is conserved
(36.11, 36.20-36.21), and for masses turning with the body about the axis
H_O·e = I ω with I = I0 + Σ m (|x|² − (x·e)²); so ω = ω0 I_before/I_after
(36.22 for the arms of Fig. 36.4).

motor-bodies: H_O·e''2 = 0 (36.31) with (36.34)-(36.39) gives (36.40).
"""

from __future__ import annotations

import math

from dyncli.direction import unit
from dyncli.errors import InputError
from dyncli.result import Result, SolveOptions, Table
from dyncli.topics.rigid_systems import equations as eq


def axial_inertia(masses, attr: str, e: tuple[float, ...]) -> tuple[float, list[float]]:
    """Σ m d² about the axis through the origin along unit e, and each d."""
    total, dists = 0.0, []
    for mm in masses:
        d = eq.distance_from_axis([float(c) for c in getattr(mm, attr)], e)
        total += mm.m * d * d if math.isfinite(d) else math.inf
        dists.append(d)
    return total, dists


def _finite(x: float) -> float | None:
    return x if math.isfinite(x) else None


def solve_spin_change(p, options: SolveOptions | None = None) -> Result:
    e = unit(p.axis, "axis", "the axis")     # scaled: [0, 0, 1e-200] is e3
    Ib, db = axial_inertia(p.masses, "before", e)
    Ia, da = axial_inertia(p.masses, "after", e)
    I_before, I_after = p.I0 + Ib, p.I0 + Ia
    for name, I in (("before", I_before), ("after", I_after)):
        if not math.isfinite(I):
            raise InputError(f"the moment of inertia about the axis {name} the change, I0 + Σ m d², overflows a "
                             "double (values beyond ~1e308)", "masses")
    H = I_before * p.omega0
    if not math.isfinite(H):
        raise InputError(f"the angular momentum I ω0 = {I_before:.6g} kg·m² × {p.omega0:.6g} rad/s overflows a "
                         "double (values beyond ~1e308)", "omega0")
    res = Result({}, method="closed-form", equations=["36.11", "36.20", "36.21", "36.22"])
    if I_after == 0.0:
        if H != 0.0:
            raise InputError(
                f"after the change every mass lies on the axis and I0 = 0, so I_after = 0 cannot carry the "
                f"angular momentum H = {H:.6g} kg·m²/s about the axis (the spin would be infinite)", "masses")
        omega = None
        res.warn("omega is undefined: I_after = 0 and the angular momentum about the axis is 0")
    else:
        omega = eq.spin_after(p.omega0, I_before, I_after)     # (36.22)
        if not math.isfinite(omega):
            raise InputError(f"the spin after the change ω = ω0 I_before/I_after = {p.omega0:.6g} × "
                             f"{I_before:.6g}/{I_after:.6g} rad/s overflows a double (values beyond ~1e308)", "masses")
    # T = ½ I ω² = ½ H ω (36.22): no overflow of ω² where T itself is representable
    T1 = _finite(eq.axial_kinetic_energy(H, p.omega0))
    T2 = None if omega is None else _finite(eq.axial_kinetic_energy(H, omega))
    work = None if T1 is None or T2 is None else _finite(T2 - T1)
    res.results.update({
        "I_before": I_before, "I_after": I_after, "omega": omega, "H": H,
        "T_before": T1, "T_after": T2, "work": work,
    })
    if omega is None:
        res.warn("T_after and work are undefined because omega is")
    else:
        for name, T in (("T_before", T1), ("T_after", T2), ("work", work)):
            if T is None:
                res.warn(f"{name} overflows a double (|value| beyond ~1e308): reported as null")
    rows = [[k, mm.m, db[k], da[k]] for k, mm in enumerate(p.masses)]
    res.views.append(Table("distance of each mass from the axis", ["#", "m [kg]", "before [m]", "after [m]"], rows,
                           note=f"axis e = [{', '.join(f'{c:.6g}' for c in e)}] through the origin; "
                                "T₂ − T₁ is the work done by the mechanism that moves the masses"))
    return res


def solve_motor_bodies(p, options: SolveOptions | None = None) -> Result:
    s, c = math.sin(p.alpha), math.cos(p.alpha)
    # moment of inertia of the whole system about the fixed axis e''2 with A locked
    I_orbit, I_axis = eq.motor_axis_inertia(p.IA1, p.IA2, p.IB2, p.mA, p.L, s, c)
    if not (math.isfinite(I_orbit) and math.isfinite(I_axis)):
        raise InputError(f"the moment of inertia about the fixed axis, IA1 sin²α + (mA L² + IA2) cos²α + IB2, "
                         f"overflows a double with L = {p.L:.6g} m (values beyond ~1e308)", "L")
    if not I_axis > 0:
        raise InputError("the system has no inertia about the fixed axis (IA1 sin²α + (mA L² + IA2) cos²α + IB2 = 0): "
                         "Ω is undefined", "IB2")
    Omega = eq.motor_base_spin(p.IA1, p.p, s, I_axis)          # (36.40)
    omega_A = eq.motor_angular_velocity(Omega, p.p, s, c)       # (36.25) on e'''_i
    H_A = [p.IA1 * omega_A[0], I_orbit * omega_A[1], 0.0]   # (36.35c,d) on e'''_i
    res = Result(
        {"Omega": Omega, "I_axis": I_axis, "omega_A": omega_A},
        method="closed-form",
        equations=["36.25", "36.31", "36.35", "36.37", "36.39", "36.40"],
    )
    if p.IA1 > 2 * p.IA2 * (1 + 1e-12):
        res.warn(f"IA1 = {p.IA1:.6g} > 2·IA2 = {2 * p.IA2:.6g}: an axisymmetric body must have IA1 ≤ 2 IA2 "
                 "(triangle inequality of principal moments)")
    res.views.append(Table("angular momentum about O (36.37), components on e'''₁, e'''₂, e''₂", ["term", "e'''₁", "e'''₂", "e''₂"], [
        ["body A (spin + transverse + orbit)", H_A[0], H_A[1], ""],
        ["body B", "", "", p.IB2 * Omega],
        ["total · e''₂ (36.39)", "", "", H_A[0] * s + H_A[1] * c + p.IB2 * Omega],
    ], note="e'''₁ = shaft of the motor = cos α e''₁ + sin α e''₂ (36.24a); ω_A is on e'''ᵢ"))
    return res
