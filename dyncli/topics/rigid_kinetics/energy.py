"""Rigid-body momentum about a point, power and the energy equation (notes
§29, §32, §34) — the additions to ``rigid-energy`` and ``planar-moments``.

* H_O = (x̄ − O) × m v̄ + H̄ (29.25).
* P = m b·v̄ + Σ Fᵢ·vᵢ + Σ Mᵢ·ω (34.19), vᵢ = v̄ + ω × (xᵢ − x̄) the absolute
  velocity of the point where Fᵢ acts (13.8).
* Over a prescribed motion v̄(t), ω(t) on the body axes (Ī constant there):
  T(t) = ½ m v̄·v̄ + ½ ω·Īω, its rate Ṫ = m v̄·dv̄/dt + ω·Ī dω/dt (34.13,
  34.15) — the power P the external forces and moments must supply (34.16)
  — and U = T(t) − T(t₁), the work done since the first time (34.20 with no
  potential energies).  The rates are exact (forward-mode differentiation of
  the expressions, no finite differences).
* planar-moments: F = Σ Fᵢ, ā = F/m (32.6, 32.8), and the moment of the
  forces about the center of mass Σ pᵢ × Fᵢ beside the moment M̄ the motion
  needs (32.13): their difference is the couple that must be added.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from dyncli.errors import InputError, NumericalError
from dyncli.result import Series, Table
from dyncli.topics.rigid_kinetics import equations as eq
from dyncli.vec3 import cross

Vec = tuple[float, float, float]


@dataclass(frozen=True, slots=True)
class Force:
    """A force F [N] applied at the point x [m] (None: the center of mass)."""

    F: Vec
    x: Vec | None = None


@dataclass(frozen=True, slots=True)
class Motion:
    """A prescribed motion v̄(t), ω(t) on the body axes (expressions in t), reported at ``at`` [s]."""

    v: tuple
    omega: tuple
    at: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class Body:
    """What rigid-energy knows beyond Ī, in SI floats: the mass, v̄ and ω (None: from the
    motion's first time), the position x̄ of the center of mass and the point O of H_O (None:
    not given), the forces, couples and body force per unit mass b, the prescribed motion."""

    m: float
    v: Vec | None = None
    omega: Vec | None = None
    x: Vec | None = None
    about: Vec | None = None
    forces: tuple[Force, ...] = ()
    moments: tuple[Vec, ...] = ()
    b: Vec | None = None
    motion: Motion | None = None


def _finite(name: str, *arrays) -> None:
    """InputError unless every component of every (nested) array is finite (plain floats: no numpy)."""
    def ok(a) -> bool:
        return all(ok(c) for c in a) if hasattr(a, "__len__") else math.isfinite(a)

    if not all(ok(a) for a in arrays):
        raise InputError(f"{name} overflows a double (values beyond ~1e308)", name.split()[0])


def _sum(xs) -> float:
    """Σ xs correctly rounded (math.fsum); inf or nan where the sum overflows (then reported by _finite)."""
    xs = [float(x) for x in xs]
    try:
        return math.fsum(xs)
    except (OverflowError, ValueError):     # an overflowing sum, or inf − inf
        return sum(xs)


def initial_state(p: Body):
    """(v̄, ω): as given, or the prescribed motion's values at its first time."""
    v: tuple[float, ...] | list[float] | None = p.v
    w: tuple[float, ...] | list[float] | None = p.omega
    if p.motion is not None and (v is None or w is None):
        from dyncli.expr.jet import vec_jet_at     # plain floats: no numpy

        t0 = p.motion.at[0]
        ev, ew = list(vec_jet_at(p.motion.v, t0)[0]), list(vec_jet_at(p.motion.omega, t0)[0])
        if not all(math.isfinite(c) for c in ev + ew):
            raise NumericalError("the prescribed motion is not finite at its first time")
        v = ev if v is None else v
        w = ew if w is None else w
    return v, w


def momentum_about(res, p: Body, v, H) -> None:
    """``H_O`` (29.25) and ``x``-dependent views when the position is given."""
    if p.x is None:
        return
    O = (0.0, 0.0, 0.0) if p.about is None else p.about
    HO, orbit = eq.angular_momentum_about(p.x, O, p.m, v, H)     # (29.25)
    _finite("x (the position) with H_O", HO)
    res.results["H_O"] = list(HO)
    res.results["H_orbit"] = list(orbit)
    res.equations.append("29.25")


def power(res, p: Body, v, w) -> None:
    """``power`` and its terms (34.17-34.19) when forces, moments or b are given."""
    if not (p.forces or p.moments or p.b is not None):
        return
    xb = (0.0, 0.0, 0.0) if p.x is None else p.x
    rows, pf = [], []
    for i, f in enumerate(p.forces):
        xi = xb if f.x is None else f.x
        vi = eq.point_velocity(v, w, xi, xb)                # (13.8)
        pf.append(eq.dot(f.F, vi))
        rows.append([f"F{i + 1}", list(f.F), list(xi), list(vi), pf[-1]])
    pm = [eq.dot(M, w) for M in p.moments]
    for i, M in enumerate(p.moments):
        rows.append([f"M{i + 1}", list(M), "", list(w), pm[i]])
    pb = 0.0 if p.b is None else p.m * eq.dot(p.b, v)       # (34.18)
    if p.b is not None:
        rows.append(["m b", [p.m * c for c in p.b], list(xb), list(v), pb])
    P = _sum(pf + pm + [pb])
    _finite("forces (their power)", pf, pm, [pb, P])
    res.results.update(power=P, power_forces=pf, power_moments=pm, power_body=pb)
    res.equations += ["34.17", "34.18", "34.19"]
    res.views.append(Table("mechanical power (34.19): forces at their points, couples with ω",
                           ["", "F or M", "point x", "velocity vᵢ or ω", "power [W]"], rows,
                           note=f"P = {P:.6g} W = dT/dt (34.16)"))


def motion(res, p: Body, I) -> None:
    """``T_motion``, ``T_rate``, ``work`` over a prescribed motion (34.13-34.16, 34.20), evaluated
    at each time in plain floats (exact derivatives: :func:`dyncli.expr.jet.vec_jet_at`)."""
    mo = p.motion
    if mo is None:
        return
    from dyncli.expr.jet import vec_jet_at

    T, Td, vs, ws = [], [], [], []
    for t in mo.at:
        V, W = vec_jet_at(mo.v, t), vec_jet_at(mo.omega, t)      # (order, component)
        e, rate = eq.kinetic_energy_and_rate(p.m, I, V[0], V[1], W[0], W[1])     # (34.13), (34.15)
        T.append(e)
        Td.append(rate)
        vs.append([c + 0.0 for c in V[0]])
        ws.append([c + 0.0 for c in W[0]])
    if not all(math.isfinite(x) for x in T + Td):
        raise NumericalError("the prescribed motion is not finite (or not differentiable) at one of the times 'at'")
    res.results.update(T_motion=T, T_rate=Td, work=[x - T[0] for x in T], v_motion=vs, omega_motion=ws)
    res.equations += ["34.13", "34.15", "34.16", "34.20"]
    res.series.append(Series("t", list(mo.at), ["T_motion", "T_rate", "work"],
                             title="energy over the prescribed motion: P = dT/dt (34.16), U₂/₁ = T₂ − T₁ (34.20)"))
    res.series.append(Series("t", list(mo.at), ["v_motion", "omega_motion"], title="the prescribed motion (on e'ᵢ)"))


def translation(res, forces: tuple[Force, ...], m: float | None) -> None:
    """planar-moments with forces: F, ā (32.6, 32.8), Σ p×F and the couple still needed."""
    if not forces:
        return
    assert m is not None                      # the model asks for m with forces
    Fs = [f.F for f in forces]
    ps = [(0.0, 0.0, 0.0) if f.x is None else f.x for f in forces]
    F = [_sum(f[i] for f in Fs) for i in range(3)]                          # (32.6)
    a = [c / m for c in F]                                                  # (32.8)
    MF = [_sum(c[i] for c in [cross(q, f) for q, f in zip(ps, Fs)]) for i in range(3)]
    couple = [M - c for M, c in zip(res.results["M"], MF)]
    _finite("forces (their resultant or moment)", F, a, MF, couple)
    res.results.update(F=F, a_com=a, M_forces=MF, M_couple=couple)
    res.equations += ["32.5", "32.6", "32.8"]
    if F[2] != 0.0:
        res.warn(f"the forces have a resultant F'3 = {F[2]:.6g} N along e'3: the center of mass accelerates out of "
                 "the plane of motion (32.5 needs F3 = 0)")
