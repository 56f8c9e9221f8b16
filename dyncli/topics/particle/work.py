"""Power and work of each force of a ``particle`` problem (notes §18-§20).

For every term of the force list, at the requested times:

* its force vector F_i (the friction term: −μN v/|v| while sliding, the
  static reaction −F_other, shared in proportion to μN, while stuck);
* its mechanical power P_i = F_i·v (18.1);
* its work since t = 0, U_i = ∫ P_i dt (18.2).

The work of a potential force is exact from its potential, U = −(V − V1)
(19.8): gravity (19.23), inverse-square gravity (19.20b), a spring (19.26b),
and a uniform force, U = F·(x − x1) (19.15).  Every other term is integrated
along the computed motion: Gauss–Legendre quadrature (8 nodes) of P_i over
each accepted step of the integrator, evaluated on its dense output.

Two checks: the powers add up to Ṫ = m a·v (18.5), and the works add up to
T − T1 (18.7): ``work_residual`` = max |Σ U_i − (T − T1)| over the times.
"""

from __future__ import annotations

from itertools import repeat

import numpy as np

from dyncli.topics.particle import equations as eq

GL_NODES = 8
POTENTIAL_KINDS = ("gravity", "inverse-square", "spring", "uniform")


def quadrature_terms(p) -> int:
    """How many force terms have no potential (their work is a quadrature along the motion)."""
    return sum(f.kind not in POTENTIAL_KINDS for f in p.forces)


def labels(forces) -> list[str]:
    """One label per force term: its kind (a custom term's ``name`` if given),
    with #2, #3, ... for repeats."""
    out: list[str] = []
    for f in forces:
        base = (getattr(f, "name", None) or f.kind) if f.kind == "custom" else f.kind
        lab, n = base, 1
        while lab in out:
            n += 1
            lab = f"{base}#{n}"
        out.append(lab)
    return out


class Term:
    """One force term as a vectorised function of (t, x, v), arrays (3, n)."""

    def __init__(self, f, p):
        self.f, self.kind = f, f.kind
        m = float(p.m)
        self.m, self.g = m, float(p.g)
        if f.kind == "inverse-square":
            g = p.g if f.g is None else f.g
            R0 = float(f.R0)
            self.c, self.mu = np.asarray(f.center, float)[:, None], m * g * R0 * R0   # inf, never OverflowError
        elif f.kind == "spring":
            self.c = np.asarray(f.anchor, float)[:, None]
        elif f.kind == "friction":
            self.muN = float(f.mu) * float(f.N)

    def force(self, t, x, v):
        """F_i at the states (3, n), or a (3, 1) column for a constant force."""
        f, k = self.f, self.kind
        if k == "uniform":
            return np.asarray(f.F, float)[:, None]
        if k == "gravity":
            return np.array([[0.0], [0.0], [-self.m * self.g]])
        if k == "inverse-square":
            r = x - self.c
            return -self.mu * r / np.sqrt((r * r).sum(axis=0)) ** 3
        if k == "spring":
            r = x - self.c
            R = np.sqrt((r * r).sum(axis=0))
            on = eq.engaged(f.one_sided, R, f.L)
            return (-f.k * r if f.L == 0 else -f.k * (R - f.L) * r / np.where(R > 0, R, 1.0)) * on
        if k == "damper" or (k == "drag" and f.power == 1):
            return -f.c * v
        if k == "drag":
            return -f.c * np.sqrt((v * v).sum(axis=0)) * v
        if k == "friction":
            sp = np.sqrt((v * v).sum(axis=0))
            return -self.muN * v / np.where(sp > 0, sp, 1.0)
        env = {"t": t, "x1": x[0], "x2": x[1], "x3": x[2], "v1": v[0], "v2": v[1], "v3": v[2]}   # custom
        return np.stack([np.broadcast_to(np.asarray(e.evaluate(**env), float), x.shape[1:]) for e in f.F])

    def exact_work(self, x, x1):
        """U since t = 0 from the potential (19.8), or None (quadrature)."""
        k, f = self.kind, self.f
        if k == "uniform":
            return np.asarray(f.F, float) @ (x - x1[:, None])
        if k not in POTENTIAL_KINDS:
            return None
        return -(self._V(x) - self._V(x1[:, None]))

    def _V(self, x):
        k, f = self.kind, self.f
        if k == "gravity":
            return self.m * self.g * x[2]
        r = x - self.c
        R = np.sqrt((r * r).sum(axis=0))
        if k == "inverse-square":
            return -self.mu / R
        return 0.5 * f.k * (R - f.L) ** 2 * eq.engaged(f.one_sided, R, f.L)


def _sliding_dirs(F, t, X, V):
    """The direction −F_friction/μN at the states: v/|v|, or (at v = 0 inside
    a sliding phase, i.e. slipping off from rest) the direction of the net
    other force."""
    sp = np.sqrt((V * V).sum(axis=0))
    d = V / np.where(sp > 0, sp, 1.0)
    for j in np.flatnonzero(sp == 0):
        Fo = F.other(float(t[j]), X[:, j])
        n = float(np.linalg.norm(Fo))
        d[:, j] = Fo / n if n > 0 else 0.0
    return d


def _term_forces(terms, F, t, X, V, rest):
    """(len(terms), 3, n) forces at the states; ``rest`` marks states of a
    rest (stuck) phase, where friction is the static reaction."""
    out = np.empty((len(terms),) + X.shape)
    for i, tm in enumerate(terms):
        out[i] = tm.force(t, X, V)
    fr = [i for i, tm in enumerate(terms) if tm.kind == "friction"]
    if fr and F.muN > 0:
        d = _sliding_dirs(F, t, X, V)
        for i in fr:
            out[i] = -terms[i].muN * d
        for j in np.flatnonzero(rest):
            Fo = F.other(float(t[j]), X[:, j])
            for i in fr:
                out[i][:, j] = -Fo * (terms[i].muN / F.muN)
    return out


_GL: list = []


def _gl_integrals(phase, terms, F, a, b):
    """∫_a^b P_i dt for the intervals [a_k, b_k] of one ODE phase: (len(terms), K)."""
    if not _GL:
        _GL.extend(np.polynomial.legendre.leggauss(GL_NODES))
    xg, wg = _GL
    a, b = np.asarray(a, float), np.asarray(b, float)
    half = 0.5 * (b - a)
    tt = (0.5 * (a + b))[:, None] + half[:, None] * xg[None, :]
    flat = tt.ravel()
    Y = phase.sol(flat) if phase.t1 > phase.t0 else np.repeat(phase.steps_y[:, :1], flat.size, axis=1)
    X, V = Y[0:3], Y[3:6]
    Fi = _term_forces(terms, F, flat, X, V, np.zeros(flat.size, bool))
    P = np.sum(Fi * V[None], axis=1).reshape(len(terms), *tt.shape)
    return np.sum(P * wg[None, None, :], axis=2) * half[None, :]


def _quadrature_work(traj, terms, F, times):
    """U_i(t) = ∫_0^t P_i dt at the times, for every term (the potential
    terms are overwritten by their exact values afterwards)."""
    from .trajectory import OdePhase

    n = len(terms)
    out = np.zeros((n, len(times)))
    done = np.zeros(n)                 # work up to the start of the current phase
    order = np.argsort(times)
    ts = np.asarray(times, float)[order]
    k = 0
    for ph in traj.phases:
        if not isinstance(ph, OdePhase) or ph.t1 <= ph.t0:
            while k < len(ts) and ts[k] <= ph.t1:
                out[:, order[k]] = done
                k += 1
            continue
        st = np.asarray(ph.steps_t, float)
        cum = np.concatenate([np.zeros((n, 1)), np.cumsum(_gl_integrals(ph, terms, F, st[:-1], st[1:]), axis=1)], axis=1)
        j0 = k
        while k < len(ts) and ts[k] <= ph.t1:
            k += 1
        if k > j0:
            tq = ts[j0:k]
            idx = np.clip(np.searchsorted(st, tq, side="right") - 1, 0, len(st) - 1)
            part = _gl_integrals(ph, terms, F, st[idx], tq)
            out[:, order[j0:k]] = done[:, None] + cum[:, idx] + part
        done = done + cum[:, -1]
    while k < len(ts):
        out[:, order[k]] = done
        k += 1
    return out


def add(res, p, F, traj, S) -> None:
    """Add ``force_terms``, ``power``, ``work`` and ``work_residual`` to res (``S``: the motion at
    the requested times, report.at_times)."""
    from dyncli.result import Series

    terms = [Term(f, p) for f in p.forces]
    labs = labels(p.forces)
    times = S["t"]
    t, Y = np.asarray(times, float), S["Y"]
    X, V = Y[0:3], Y[3:6]
    Fi = _term_forces(terms, F, t, X, V, S["rest"])
    P = (Fi * V).sum(axis=1)
    with np.errstate(all="ignore"):
        U = _works(p, traj, terms, F, times, X, Y[6])
    T1 = 0.5 * F.m * sum(float(c) * float(c) for c in p.v0)
    resid = float(abs(U.sum(axis=0) - (S["T"] - T1)).max()) if t.size else 0.0
    Fl, Pl, Ul = (Fi.transpose(2, 0, 1) + 0.0).tolist(), (P.T + 0.0).tolist(), (U.T + 0.0).tolist()
    keyed = lambda rows: list(map(dict, map(zip, repeat(labs), rows)))    # noqa: E731  (no Python call per row)
    res.results["force_terms"], res.results["power"], res.results["work"] = keyed(Fl), keyed(Pl), keyed(Ul)
    res.results["work_residual"] = resid
    for name, title in (("force_terms", "Fᵢ (each force)"), ("power", "Pᵢ = Fᵢ·v"),
                        ("work", "Uᵢ = ∫ Pᵢ dt")):
        res.series.append(Series("t", list(times), [name], title=title))   # one column per force
    for number in ("18.1", "18.2", "18.7", "19.8"):
        if number not in res.equations:
            res.equations.append(number)


def _works(p, traj, terms, F, times, X, W_nc):
    """U_i at the times: exact from the potential (19.8) where there is one; the one term without
    a potential: W_nc (20.3) less the uniform terms' work; several: a quadrature each."""
    quad = [i for i, tm in enumerate(terms) if tm.kind not in POTENTIAL_KINDS]
    U = _quadrature_work(traj, terms, F, times) if len(quad) > 1 else np.zeros((len(terms), len(times)))
    x1 = np.asarray(p.x0, float)
    for i, tm in enumerate(terms):
        ex = tm.exact_work(X, x1)
        if ex is not None:
            U[i] = ex
    if len(quad) == 1:
        uni = [i for i, tm in enumerate(terms) if tm.kind == "uniform"]
        U[quad[0]] = W_nc - U[uni].sum(axis=0) if uni else W_nc
    return U
