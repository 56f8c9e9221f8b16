"""Rigid-body kinetics: planar moments (32.9-32.13) and kinetic energy
(34.6-34.7) — numeric core, closed forms."""

from __future__ import annotations

import math

from dyncli.direction import norm, unit
from dyncli.result import FrameTable, Result, SolveOptions
from dyncli.topics.inertia.eigen3 import inertia_defect, sym3
from dyncli.topics.rigid_kinetics import energy
from dyncli.topics.rigid_kinetics import equations as eq


def solve_planar_moments(p, options: SolveOptions | None = None) -> Result:
    I13, I23, I33, w, wd = p.I13, p.I23, p.I33, p.omega, p.omega_dot
    H = eq.planar_angular_momentum(I13, I23, I33, w)             # (32.9)
    M = eq.planar_moments(I13, I23, I33, w, wd)                   # (32.12), (32.13a-c)
    purely = I13 == 0.0 and I23 == 0.0
    res = Result(
        {"M": M, "H": H, "purely_planar": purely},
        method="closed-form",
        equations=["32.9", "32.12", "32.13"] + (["32.15"] if purely else []),
    )
    if not purely:
        res.warn("e'3 is not a principal direction (Ī'13 or Ī'23 ≠ 0): moments M̄'1, M̄'2 are needed "
                 "to keep the motion planar")
    dH = [I13 * wd, I23 * wd, I33 * wd]
    wxH = [-w * H[1], w * H[0], 0.0]
    res.views.append(FrameTable(
        "angular momentum balance about the center of mass (32.10-32.13)",
        [("ω", [0.0, 0.0, w]), ("H̄", H), ("δH̄/δt", dH), ("ω×H̄", wxH), ("M̄ = dH̄/dt", M)],
    ))
    energy.translation(res, _forces(p.forces), p.m)
    return res


def _forces(forces) -> tuple[energy.Force, ...]:
    return tuple(energy.Force(f.F, f.x) for f in forces)


def body(p) -> energy.Body:
    """The validated rigid-energy model as plain inputs (SI floats, expressions)."""
    mo = p.motion
    motion = None if mo is None else energy.Motion(tuple(mo.v), tuple(mo.omega), tuple(mo.at))
    return energy.Body(p.m, p.v, p.omega, p.x, p.about, _forces(p.forces), tuple(p.moments), p.b, motion)


def solve_rigid_energy(p, options: SolveOptions | None = None) -> Result:
    m = p.m
    bd = body(p)
    v0, w0 = energy.initial_state(bd)
    v = tuple(float(c) for c in v0)
    w = tuple(float(c) for c in w0)
    I = sym3(p.I)
    H = eq.matvec(I, w)                      # (30.12a)
    G = [m * c for c in v]
    T_trans = eq.translational_kinetic_energy(m, v)     # (34.6)
    T_rot = eq.rotational_kinetic_energy(w, H)          # (34.7)
    T_rot = max(T_rot, 0.0)                  # I is positive-semidefinite: only rounding can make it negative
    res = Result(
        {"T": T_trans + T_rot, "T_trans": T_trans, "T_rot": T_rot, "H": list(H), "G": G},
        method="closed-form",
        equations=["30.12", "34.6", "34.7"],
    )
    lo, tri, scale = inertia_defect(I)
    if tri > 1e-10 * max(scale, 1e-300):
        res.warn(f"I violates the triangle inequality of principal moments (I₁ + I₂ < I₃ by {tri:.6g} kg·m²): "
                 "no positive mass distribution has this inertia tensor")
    nw, nH = norm(w), norm(H)
    if 0 < nw < math.inf and 0 < nH < math.inf:
        c = math.fsum(a * b for a, b in zip(unit(w), unit(H)))      # directions scaled first: ω = 1e-200 is a direction
        res.results["angle_omega_H"] = math.acos(min(max(c, -1.0), 1.0))
    else:
        res.results["angle_omega_H"] = None
        res.warn("angle_omega_H is undefined: ω = 0 or H̄ = 0" if nw == 0 or nH == 0
                 else "angle_omega_H is undefined: |ω| or |H̄| overflows a double")
    res.views.append(FrameTable("vectors on the basis of I", [("v̄", list(v)), ("ω", list(w)), ("H̄ = Īω", list(H)), ("G = m v̄", G)]))
    energy.momentum_about(res, bd, v, H)
    energy.power(res, bd, v, w)
    energy.motion(res, bd, I)
    return res
