"""Systems of particles (notes §24-§27) — numeric core.

m = Σ m_i, m x̄ = Σ m_i x_i (24.12); G = Σ m_i v_i = m v̄ (24.13);
H_O = Σ (x_i − O) × m_i v_i (24.4a) = (x̄ − O) × m v̄ + H̄ (25.7 with B at the
center of mass); H̄ = Σ p_i × m_i ṗ_i (25.8) with p_i = x_i − x̄;
T = Σ ½ m_i v_i·v_i = ½ m v̄·v̄ + Σ ½ m_i ṗ_i·ṗ_i (27.8).

Sums use math.fsum; the relative quantities are formed from the relative
positions and velocities (never as T − T_com), so T_rel is exact 0 for a
rigid translation and never negative.
"""

from __future__ import annotations

import math

from dyncli.errors import InputError
from dyncli.result import Result, SolveOptions, Table
from dyncli.topics.particle_systems import equations as eq


def _finite(x) -> bool:
    if isinstance(x, (list, tuple)):
        return all(math.isfinite(c) for c in x)
    return math.isfinite(x)


def solve(p, options: SolveOptions | None = None) -> Result:
    ms = [q.m for q in p.particles]
    xs = [tuple(q.x) for q in p.particles]
    vs = [tuple(q.v) for q in p.particles]
    O = tuple(p.about)
    M = eq.fsum(ms)                                                       # (24.12)
    if not math.isfinite(M):
        raise InputError("the total mass overflows a double", "particles")
    fr = [m / M for m in ms]       # mass fractions avoid overflowing m_i x_i for huge masses
    com = eq.weighted_mean(fr, xs)                                        # (24.12)
    v_com = eq.weighted_mean(fr, vs)                                      # (24.13)
    G = eq.linear_momentum(ms, vs)                                        # (24.13)
    H_O = eq.angular_momentum(ms, eq.relative(xs, O), vs)                 # (24.4a)
    ps, pds = eq.relative(xs, com), eq.relative(vs, v_com)                # (27.6)
    H_com = eq.angular_momentum(ms, ps, pds)                              # (25.8)
    T = eq.kinetic_energy(ms, vs)                                         # (27.8)
    T_com = eq.center_of_mass_kinetic_energy(M, v_com)
    T_rel = eq.kinetic_energy(ms, pds)

    res = Result({}, method="closed-form", equations=["24.12", "24.13", "24.4a", "25.7", "25.8", "27.8"])
    r = res.results
    for name, val in (("mass", M), ("com", com), ("v_com", v_com), ("G", G), ("H_O", H_O),
                      ("H_com", H_com), ("T", T), ("T_com", T_com), ("T_rel", T_rel)):
        if _finite(val):
            r[name] = val
        else:
            r[name] = None
            res.warn(f"{name} overflows a double (masses, positions or velocities too large): reported as null")

    rows = []
    for i, (m, x, v, pp, pd) in enumerate(zip(ms, xs, vs, ps, pds)):
        rows.append([str(i), m, list(x), list(v), list(pp), list(pd)])
    res.views.append(Table("Particles relative to the center of mass", ["#", "m", "x", "v", "p = x − x̄", "ṗ = v − v̄"],
                           rows, note="(27.6) x = x̄ + p, v = v̄ + ṗ"))
    res.views.append(Table("Kinetic energy split (27.8)", ["T", "½ m v̄·v̄", "Σ ½ mᵢ ṗᵢ·ṗᵢ"],
                           [[r["T"], r["T_com"], r["T_rel"]]]))
    _internal(p, res, ms, xs, vs, O)
    return res


def _internal(p, res, ms, xs, vs, O) -> None:
    """The pair forces (24.9-24.15, 27.10-27.14) and the motion under them."""
    if not p.pairs and p.t_end is None:
        return
    import numpy as np

    from dyncli.topics.particle_systems import motion, pairs

    masses, X, V, Ov = (np.array(a, dtype=float) for a in (ms, xs, vs, O))
    plain_pairs = tuple(pairs.Pair(pr.kind, tuple(pr.between), pr.k, pr.L, pr.c, pr.K) for pr in p.pairs)
    if p.pairs:
        with np.errstate(all="ignore"):
            vals, rows = pairs.snapshot(plain_pairs, masses, X, V, Ov)
        if not all(_finite(v) for v in (vals["f_internal"], vals["m_internal"], vals["P_internal"], vals["V_internal"])):
            raise InputError("the pair forces overflow a double (values beyond ~1e308)", "pairs")
        res.results.update(vals)
        res.equations += ["24.9", "24.10", "24.15", "27.10", "27.11", "27.12"]
        res.views.append(Table("Internal pair forces (24.15): f on the first particle from the second",
                               ["#", "pair", "kind", "r", "ṙ", "f", "f·(vᵢ − vⱼ)", "potential"], rows,
                               note="P_int = Σ f·(vᵢ − vⱼ) (27.10); Σ f = 0 and Σ x × f = 0 (24.10, central forces)"))
    if p.t_end is not None:
        from dyncli import motion_find
        from dyncli.topics.particle.solver import accuracy

        q = motion_find.extended(p)         # the motion runs to the end of every window searched (§11)
        setup = motion.Motion(plain_pairs, tuple(q.at), float(q.t_end), accuracy(q.accuracy), tuple(q.find), q.params)
        motion.solve_motion(setup, res, masses, X, V, Ov)
        res.equations += ["24.1", "24.11", "24.18", "27.14"]


