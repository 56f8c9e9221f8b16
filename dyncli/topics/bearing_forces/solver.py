"""Bearing force and moment of spinning arms (notes §36, Fig. 36.4,
Table 36.1, 36.10-36.22) — numeric core, closed forms.

The shaft turns about the fixed axis e'2 with ω = ω e'2 (36.12); the basis
e'_i turns with it.  Mass k sits at x = L (sin α e'1 + cos α e'2) with α(t)
prescribed, so with the general operator (11.4), as in Table 36.1:

    δx/δt = L α̇ (cos α e'1 − sin α e'2),   ω × x = −ω L sin α e'3,
    v = [L α̇ cos α, −L α̇ sin α, −ω L sin α],
    x × m v = m L² [−ω sin α cos α, ω sin²α, −α̇],

G = Σ m v, H_O = Σ x × m v (36.14), and the balance laws of the massless
link (36.10, 36.11) give the load the bearing applies:

    F = Ġ = δG/δt + ω × G,   M_O = Ḣ_O = δH_O/δt + ω × H_O.

For the notes' two equal masses at ∓α these are (36.15a) and the corrected
(36.15b): F = −2 m L d/dt(α̇ sin α) e'2, M_O = 2 m L² d/dt(ω sin²α) e'2
(the notes print ω̇ where ω belongs).  The bearing at x1 = −h e'2 carries
F1 = F and M1 = M_O − x1 × F1 (36.16-36.18).

Free shaft (``omega0``): M_O·e'2 = 0 (36.19), so H_O·e'2 = I ω is constant
(36.21), I(t) = Σ m L² sin²α, and ω = ω0 I(0)/I(t) (36.22);
ω̇ = −ω İ/I, İ = Σ 2 m L² sin α cos α α̇.

The time derivatives of the user's expressions are exact (forward-mode
differentiation, no finite differences), in plain floats at each time (no numpy).
"""

from __future__ import annotations

import math

from dyncli.errors import InputError, NumericalError
from dyncli.result import FrameTable, Result, Series, SolveOptions
from dyncli.topics.bearing_forces import equations as eq
from dyncli.expr import floatmath as fm
from dyncli.expr.jet import jet_at
from dyncli.vec3 import add, scale


def _arms(p, t: float):
    """Per mass: (m, L, α, α̇, α̈) at t."""
    return [(mm.m, mm.L) + jet_at(mm.alpha, t) for mm in p.masses]


def _placed(mm, v, dv, H, dH):
    """One mass's v, δv/δt, x × m v and its rate from its own arm plane to e'ᵢ (the azimuth β), with
    its pivot at y e'₂: x × m v gains y e'₂ × m v (y e'₂ turns with the basis: δ/δt of it is
    y e'₂ × m δv/δt)."""
    if mm.beta != 0.0:
        cb, sb = fm.cos(mm.beta), fm.sin(mm.beta)
        v, dv, H, dH = (eq.turn_about_axis(X, cb, sb) for X in (v, dv, H, dH))
    if mm.y != 0.0:
        H = add(H, scale(eq.spin_cross(mm.y, v), mm.m))            # y e'₂ × v has the form of ω e'₂ × v
        dH = add(dH, scale(eq.spin_cross(mm.y, dv), mm.m))
    return v, dv, H, dH


def _axial_inertia(arms) -> float:
    """I = Σ m L² sin²α (36.21)."""
    return sum(m * L * L * (fm.sin(a) * fm.sin(a)) for m, L, a, _, _ in arms)


def _rate(p, t: float, arms):
    """(ω, ω̇, I) at t: prescribed, or the free shaft (36.21-36.22)."""
    I = _axial_inertia(arms)
    if p.omega is not None:
        w, wd, _ = jet_at(p.omega, t)
        return w, wd, I
    I0 = _axial_inertia(_arms(p, 0.0))
    H = I0 * p.omega0
    if I0 == 0.0 and p.omega0 != 0.0:
        raise InputError("every mass starts on the axis (I(0) = Σ m L² sin²α = 0): a free shaft has no angular "
                         "momentum to keep; give omega0: 0 or a prescribed omega", "omega0")
    if H == 0.0:
        return 0.0, 0.0, I
    if I == 0.0:
        raise NumericalError(f"at t = {t:.6g} s every mass is on the axis (I = 0): the free shaft would spin "
                             "infinitely fast (36.22)")
    Idot = sum(2.0 * m * L * L * fm.sin(a) * fm.cos(a) * ad for m, L, a, ad, _ in arms)
    w = eq.free_shaft_rate(H, I)                                 # (36.22)
    return w, -w * Idot / I, I


def loads(p, t: float) -> dict:
    """Every vector (3-tuples) and scalar at the time t, in plain floats."""
    arms = _arms(p, t)
    w, wd, I = _rate(p, t, arms)
    G = dG = H = dH = (0.0, 0.0, 0.0)
    T = 0.0
    for mm, (m, L, a, ad, add_) in zip(p.masses, arms):
        s, c = fm.sin(a), fm.cos(a)
        mL2 = m * L * L
        v, dv, Hk, dHk = _placed(mm, eq.arm_velocity(L, s, c, ad, w),                # Table 36.1
                                 eq.arm_velocity_rate(L, s, c, ad, add_, w, wd),
                                 eq.arm_angular_momentum(mL2, s, c, ad, w),
                                 eq.arm_angular_momentum_rate(mL2, s, c, ad, add_, w, wd))
        G = add(G, scale(v, m))
        dG = add(dG, scale(dv, m))
        H = add(H, Hk)
        dH = add(dH, dHk)
        T += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    wxG = eq.spin_cross(w, G)                                # ω e'2 × G
    wxH = eq.spin_cross(w, H)
    F = add(dG, wxG)                                         # (36.10)
    M = add(dH, wxH)                                         # (36.11)
    if p.omega is None:
        M = (M[0], 0.0, M[2])    # a free shaft: ω is defined by M_O·e'2 = 0 (36.19); only rounding would remain
    out = dict(omega=w, omega_dot=wd, I_axis=I, G=G, H_O=H, F=F, M_O=M, motor_torque=M[1], T=T,
               dG=dG, wxG=wxG, dH=dH, wxH=wxH)
    if p.bearings is None:
        out.update(F1=F, M1=eq.bearing_moment(M, (0.0, -p.h + 0.0, 0.0), F))     # (36.16b)
    else:
        out["F_A"], out["F_B"] = eq.two_bearings(F, M, p.bearings.A, p.bearings.B)
    return out


def _finite(x) -> bool:
    return all(math.isfinite(c) for c in x) if isinstance(x, tuple) else math.isfinite(x)


def _plain(x):
    return [c + 0.0 for c in x] if isinstance(x, tuple) else x + 0.0


def solve(p, options: SolveOptions | None = None) -> Result:
    times = [float(ti) for ti in p.at]
    qs = [loads(p, ti) for ti in times]
    pair = ("F1", "M1") if p.bearings is None else ("F_A", "F_B")
    names = ("omega", "omega_dot", "I_axis", "G", "H_O", "F", "M_O") + pair + ("motor_torque", "T")
    if not all(_finite(q[n]) for q in qs for n in names):
        raise NumericalError("the loads are not finite at one of the times 'at' (the prescribed angles or rate are "
                             "not finite or not differentiable there, or the values overflow)")
    one = ["36.16", "36.17", "36.18"] if p.bearings is None else []         # the one bearing at −h e'₂
    res = Result({}, method="closed-form", equations=["11.4", "36.10", "36.11", "36.14", "36.15"] + one)
    for n in names:
        res.results[n] = [_plain(q[n]) for q in qs]
    if p.omega0 is not None:
        res.equations += ["36.19", "36.20", "36.21", "36.22"]
    # one row per time (vectors stacked in the results table would lose their t)
    for names_, title in ((["omega", "omega_dot", "I_axis", "motor_torque"], "shaft rate and the torque about the axis"),
                          (["T", "G", "H_O"], "kinetic energy and momenta (on e'ᵢ)"),
                          (["F", "M_O"], "the bearing's load at O (on e'ᵢ)"),
                          ((["F1", "M1"], "the load at the bearing x₁ = −h e'₂ (on e'ᵢ)") if p.bearings is None
                           else (["F_A", "F_B"], "the forces of the bearings A and B (on e'ᵢ)"))):
        res.series.append(Series("t", list(p.at), names_, title=title))
    q = qs[0]
    res.views.append(FrameTable(
        f"Table 36.1 at t = {times[0]:.6g} s (components on e'ᵢ)",
        [("ω", [0.0, float(q["omega"]), 0.0])] + [(label, list(q[n])) for label, n in (
            ("G", "G"), ("δG/δt", "dG"), ("ω×G", "wxG"), ("Ġ = F", "F"), ("H_O", "H_O"), ("δH_O/δt", "dH"),
            ("ω×H_O", "wxH"), ("Ḣ_O = M_O", "M_O"))],
    ))
    return res
