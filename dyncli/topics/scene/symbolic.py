"""A scene's equations in the notes' form (``dyncli solve --symbolic``; sympy, imported lazily).

From the same bodies and joints the numeric engine solves (docs/types/scene.md, "The
equations"):

* the **balance laws** of every body with the joint forces by name: a particle's
  m a = ΣF (16.7); a rigid body's m ā = ΣF (29.5) and Ī α = ΣM about its centre (32.15) —
  each joint's forces are its multipliers λ, entering as Jᵀλ (so the moment of a force about
  the centre comes out of the row's angle column);
* the **constitutive laws** of the loads (a spring's tension k(ℓ − L), a damper's c ℓ̇, kinetic
  friction −μ_k N at a sliding contact, the static bound at a sticking one);
* the **constraint equations** φ(q, t) = 0 of every joint;
* the **reduced equations of motion**, one per degree of freedom: the multipliers eliminated by
  projecting M q̈ = f + Jᵀλ onto the null space of J (q̇ = N ṡ, Nᵀ Jᵀ = 0):
  NᵀMN s̈ = Nᵀ(f − M q̈ₚ), q̈ₚ the part of q̈ that ṡ alone gives (Lagrange's form, 34/36).  A
  drive's row is left out, so its coordinate becomes free and the driver's force or couple
  appears on the right: the equation that gives the drive torque;
* the **energy integral** T + V = E₀ (34.20) where it holds (no drive, damper, kinetic
  friction, time-dependent load or one-sided spring).

When the joints fix the other coordinates linearly in the chosen ones (every pin, slider,
contact, rolling and cord row of a chain), they are solved exactly and everything is written
in the chosen coordinates alone; otherwise (a closed loop with links or angles: the
slider-crank, the four-bar) the dependent coordinates stay as symbols, tied by the constraint
equations.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from . import energy, symbolic_curves
from .symbolic_rows import CarriedFrame, Coords, Eq, Geometry, Symbols, element_rows, exact, tidy

@dataclass
class Derivation:
    S: Symbols
    C: Coords
    balance: list[Eq] = field(default_factory=list)
    laws: list[Eq] = field(default_factory=list)
    constraints: list[Eq] = field(default_factory=list)
    reduced: list[Eq] = field(default_factory=list)
    energy: list[Eq] = field(default_factory=list)
    independent: list[int] = field(default_factory=list)
    explicit: dict = field(default_factory=dict)     # dependent coordinate -> its expression
    velocity: dict = field(default_factory=dict)     # every rate -> its expression in the chosen rates
    notes: list[str] = field(default_factory=list)
    drives: dict = field(default_factory=dict)       # drive force symbol -> coordinate index
    closure: list[Eq] = field(default_factory=list)  # the rows left for the coordinates kept as symbols
    state: tuple = ()                                # (q, q̇) at t = 0, the curves' parameters included
    curves: dict = field(default_factory=dict)       # a joint on a curve -> its parameter's index


@dataclass
class _Parts:
    rows: list = field(default_factory=list)        # (element, φ rows, λ)
    f: list = field(default_factory=list)           # applied generalized forces (named loads)
    subs: dict = field(default_factory=dict)        # named load -> its law (for the reduction)
    M: list = field(default_factory=list)
    g: object = 0


def derive(scene, exprs: dict | None = None) -> Derivation:
    """The equations of ``scene`` (a set-up :class:`.prepare.Scene`); ``exprs`` holds the file's
    expressions in t: ``{"drive": {NAME: Expr}, "load": {INDEX: [Expr...]}}``."""
    exprs = exprs or {}
    system = scene.system
    S = Symbols()
    C = Coords.of(system.names, S)
    G = Geometry(S, C, system.bodies)
    D = Derivation(S, C)
    P = _Parts(f=[sp.Integer(0)] * system.n)
    t = S.new("t", "t", "t")
    g = P.g = S.new("g", "g", "g", system.g, positive=True) if system.g else sp.Integer(0)
    for b in system.bodies:
        m = S.param("m", "m", b.name, b.mass)
        P.M += [m, m]
        P.f[b.index[1]] -= m * g
        if b.rigid:
            P.M.append(S.param("Ī", r"\bar{I}", b.name, b.inertia))
    D.state = (list(scene.q0), list(scene.v0))
    for e in system.elements:
        if getattr(e, "mode", "") == "off":
            raise ValueError(f"no symbolic form for a stop joint ({e.name!r} starts off its surface: each phase "
                             "has its own equations in this release)")
        if e.kind == "rolls" and e.mode == "slip" or e.kind == "cord" and e.slack:
            raise ValueError(f"{e.name!r} starts {'slack' if e.kind == 'cord' else 'slipping'}, a phase without a "
                             "symbolic form in this release")
        if getattr(getattr(e, "surface", None), "carried", False) and getattr(e.surface, "curved", False):
            raise ValueError(f"the {e.kind} {e.name!r} on {e.surface.name!r}, a surface carried by "
                             f"{e.surface.body.name!r}, has no symbolic form in this release")
        if getattr(getattr(e, "surface", None), "pair", False):
            raise ValueError(f"the {e.kind} {e.name!r} between the rims of {e.A.name!r} and {e.B.name!r} has no "
                             "symbolic form in this release")
        if getattr(getattr(e, "surface", None), "corner", False):
            raise ValueError(f"the {e.kind} {e.name!r} on the corner {e.surface.name!r} has no symbolic form in this "
                             "release")
        if getattr(getattr(e, "surface", None), "curved", False):
            if getattr(e, "mode", "") in ("slide", "stick", "slip"):
                raise ValueError(f"the friction of {e.name!r} on the curve {e.surface.name!r} has no symbolic form in "
                                 "this release")
            D.curves[e.name] = symbolic_curves.add_coordinate(e, S, C, P, D, *D.state)
    for e in system.elements:
        drive = None
        if e.kind == "drive":
            from dyncli import symbolic

            drive = symbolic.sym(exprs["drive"][e.name]).subs(symbolic.symbol("t"), t) \
                if e.name in exprs.get("drive", {}) else sp.Function(f"f_{e.name}")(t)
        if e.name in D.curves:
            rows, lam, named = symbolic_curves.rows(e, G, S, D.curves[e.name])
            fric = None
        else:
            rows, lam, named, fric = element_rows(e, G, S, drive)
        P.rows.append((e, rows, lam))
        if e.kind == "drive":
            D.drives[lam[0]] = e.index
        if fric is not None:
            _friction(D, P, G, C, *fric)
    _loads(D, P, G, S, C, system, exprs.get("load", {}), t)
    _balance(D, P, system, C)
    for e, rows, _ in P.rows:
        name = e.name if e.kind != "guide" else f"{e.name.split(':')[0]} guides {e.P.body.name}"
        for k, r in enumerate(rows):
            const = -r.as_independent(*C.q, as_Add=True)[0] if r.has(*C.q) else -r
            D.constraints.append(Eq(name + (f" ({k + 1})" if len(rows) > 1 else ""), tidy(r + const), tidy(const)))
    from .symbolic_reduce import reduce

    reduce(D, P, scene, t)
    if not D.drives and energy.applies(system) is None:
        _energy(D, P, G, scene)
    return D


def _friction(D, P, G, C, F, N, e) -> None:
    """Friction F along d̂ at the contact point; its law (kinetic, or the static bound)."""
    if getattr(e.surface, "carried", False):      # F on P along d̂, −F on W's point under it: F ∂s/∂q
        col = sp.Matrix([CarriedFrame(e.surface, G).along(G.pos(e.P))]).jacobian(C.q)
    else:
        d = sp.Matrix([exact(e.surface.d[0]), exact(e.surface.d[1])])
        col = (d.T * G.pos(e.P).jacobian(C.q))
    for j in range(len(C.q)):
        P.f[j] += F * col[j]
    mu_k = D.S.param("μ", r"\mu", e.name, e.mu_k)
    two = getattr(e, "two_sided", False)        # a rough slider: |N| (N signed), the sign of the phase
    if e.mode == "slide":
        law = (-mu_k * N if e.sign > 0 else mu_k * N) * (int(e.nsign) if two else 1)
        D.laws.append(Eq(f"{e.name}: kinetic friction, sliding {'+' if e.sign > 0 else '−'}d̂"
                         + (f" (N {'>' if e.nsign > 0 else '<'} 0)" if two else ""), F, law))
        P.subs[F] = law
    else:
        mu_s = D.S.param("μ", r"\mu", e.name + ",s", e.mu_s)
        D.laws.append(Eq(f"{e.name}: sticks while", sp.Abs(F), mu_s * (sp.Abs(N) if two else N), "≤"))


def _loads(D, P, G, S, C, system, exprs, t) -> None:
    for i, ld in enumerate(system.loads):
        nm = ld.name or f"{ld.kind}{i + 1}"
        if ld.kind in ("spring", "damper"):
            d = G.pos(ld.P) - G.pos(ld.Q)
            length = sp.sqrt(d[0] ** 2 + d[1] ** 2)
            ell = S.new(f"ℓ_{nm}", f"ℓ_{nm}", rf"\ell_{{\mathrm{{{nm}}}}}")
            T = S.force("T", nm)
            grad = (d.T / ell) * d.jacobian(C.q)          # ∂ℓ/∂q with ℓ by name
            for j in range(len(C.q)):
                P.f[j] -= T * grad[j]
            D.laws.append(Eq(f"{nm}: length", ell, tidy(length)))
            P.subs[ell] = length
            if ld.kind == "spring":
                k, L = S.param("k", "k", nm, ld.k), S.param("L", "L", nm, ld.L)
                law = k * (ell - L)
                note = {"compression": " (0 when stretched)", "tension": " (0 when compressed)"}.get(ld.one_sided or "", "")
                D.laws.append(Eq(f"{nm}: spring tension{note}", T, law))
            else:
                c = S.param("c", "c", nm, ld.c)
                law = c * C.dt(length)
                ldot = S.new(f"ℓ̇_{nm}", f"ℓ̇_{nm}", rf"\dot{{\ell}}_{{\mathrm{{{nm}}}}}")
                D.laws.append(Eq(f"{nm}: damper tension (ℓ̇ = dℓ/dt)", T, c * ldot))
            P.subs[T] = law.subs(ell, length)
        elif ld.kind == "force":
            F = _load_exprs(exprs.get(i), t, ld.F(0.0) if ld.constant else None, 2)
            col = sp.Matrix([F]) * G.pos(ld.P).jacobian(C.q)
            for j in range(len(C.q)):
                P.f[j] += col[j]
            if ld.wound is not None:        # the string's line tangent to the body: −ρ |F| about e3
                P.f[ld.P.body.index[2]] -= exact(ld.wound) * sp.sqrt(F[0] ** 2 + F[1] ** 2)
        else:
            M = _load_exprs(exprs.get(i), t, [ld.M(0.0)] if ld.constant else None, 1)[0]
            P.f[ld.body.index[2]] += M


def _load_exprs(given, t, values, n):
    """The file's expressions of a load in t (or its constant values)."""
    if given is not None:
        from dyncli import symbolic

        return [symbolic.sym(e).subs(symbolic.symbol("t"), t) for e in given]
    if values is not None:
        return [exact(v) for v in values]
    return [sp.Function(f"F{k + 1}")(t) for k in range(n)]  # pragma: no cover - the solver passes every load


def _balance(D, P, system, C) -> None:
    """m ẍ = ΣF per body (16.7, 29.5) and Ī θ̈ = ΣM about the centre (32.15)."""
    gen = [sp.Integer(0)] * len(C.q)
    for _e, rows, lam in P.rows:
        for r, lm in zip(rows, lam):
            for j, q in enumerate(C.q):
                dr = sp.diff(r, q)
                if dr != 0:
                    gen[j] += dr * lm
    named = [s for s in D.S.text if s not in C.q and s not in C.qd and s not in C.qdd]
    for b in system.bodies:
        eqn = "16.7" if not b.rigid else "29.5"
        for k, j in enumerate(b.index):
            rhs = sp.expand(gen[j] + P.f[j])
            rhs = sp.collect(rhs, [s for s in named if rhs.has(s)])
            label = f"{b.name} ({'32.15' if k == 2 else eqn})" + (f", e{k + 1}" if k < 2 else "")
            D.balance.append(Eq(label, P.M[j] * C.qdd[j], rhs, terms=[(P.M[j], C.qdd[j])]))


def _energy(D, P, G, scene) -> None:
    """T + V = E₀ (34.20) along the reduced coordinates, E₀ from the state at t = 0."""
    system, C = scene.system, D.C
    T = sum((m * v ** 2 for m, v in zip(P.M, C.qd)), sp.Integer(0)) / 2
    V = sum((-f * q for f, q in zip(_gravity(P, system), C.q)), sp.Integer(0))
    for i, ld in enumerate(system.loads):
        if ld.kind == "spring":
            nm = ld.name or f"spring{i + 1}"
            k = next(s for s in D.S.text if D.S.text[s] == f"k_{nm}")
            L = next(s for s in D.S.text if D.S.text[s] == f"L_{nm}")
            d = G.pos(ld.P) - G.pos(ld.Q)
            V += k * (sp.sqrt(d[0] ** 2 + d[1] ** 2) - L) ** 2 / 2
        elif ld.kind == "force":
            V -= (sp.Matrix([[exact(x) for x in ld.F(0.0)]]) * G.pos(ld.P))[0]
        elif ld.kind == "torque":
            V -= exact(ld.M(0.0)) * C.q[ld.body.index[2]]
    state = {**{q: exact(x) for q, x in zip(C.q, D.state[0])}, **{v: exact(x) for v, x in zip(C.qd, D.state[1])}}
    T = tidy(T.subs(D.velocity).subs(D.explicit))
    V = tidy(V.subs(D.explicit))
    E0 = tidy((T + V).subs(state))
    D.energy.append(Eq("T + V = E₀ (34.20)", T + V, E0))
    D.energy.append(Eq("T", sp.Symbol("T"), T))
    D.energy.append(Eq("V", sp.Symbol("V"), V))


def _gravity(P, system):
    """The generalized force of gravity alone (−m g on every e2 coordinate)."""
    g = [sp.Integer(0)] * len(P.M)
    for b in system.bodies:
        g[b.index[1]] = -P.M[b.index[0]] * P.g
    return g
