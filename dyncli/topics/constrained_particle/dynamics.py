"""The equation of motion along the curve, its constraint force and the ODE
route (notes §16, §18, §19.27).

State y = [q, q̇, φ, W_nc, W_N, s]: the parameter and its rate, the angle of the
turning curve, the work of the non-potential forces (uniform, damper, drag,
custom, friction: W̄ of 20.3), the work of the constraint force N (zero on
a fixed curve, where N ⊥ v; not zero on a turning one, §18) and the arc length
s = ∫ |τ| q̇ dt from q0.  Only q, q̇ (and φ when ω varies in time) steer the
integrator's steps: W̄, W_N and s are quadratures of the motion carried by the same
stages (``controlled``, :func:`dyncli.runner.march`), and φ = ω t is exact at a
constant rate, so the steps are those of q, q̇ alone.

Along the unit tangent e_t (τ = Q y', see curve.py), with G = (F − m b)·e_t:

    m |τ| q̈ = G + f,   N = P⊥(m b − F),   f = −μ|N| sign(q̇)  (19.27)

Friction is handled in phases as for ``particle``: a sliding phase keeps the
sign s of q̇ it started with (a continuation through the stop) and ends at
the event q̇ = 0; there the static condition |G| ≤ μ|N| decides between
sticking — a phase with q̇ ≡ 0, the static friction −G, ending when
|G| − μ|N| crosses 0 — and slipping on in the direction of G.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.direction import norm_rows, unit_rows

from dyncli import ode, runner
from dyncli.errors import NumericalError
from dyncli.topics.constrained_particle import equations as eq
from dyncli.topics.particle.work import Term

POTENTIAL = ("gravity", "inverse-square", "spring")
MAX_PHASES = 10000
MAX_STEPS = 20_000


class Model:
    """Curve + forces: everything the route needs, vectorised over states."""

    def __init__(self, p, curve):
        self.p, self.curve, self.m = p, curve, float(p.m)
        from dyncli.topics.particle.forces import Forces
        from dyncli.topics.particle.setup import Setup as ParticleSetup

        # particle's compiled forces (for the right-hand side); raises InputError for an overflowing field
        self.compiled = Forces(ParticleSetup(m=p.m, g=p.g, forces=tuple(f for f in p.forces if f.kind != "friction")))
        self.terms = [Term(f, p) for f in p.forces if f.kind != "friction"]
        self.mu = sum(float(f.mu) for f in p.forces if f.kind == "friction")
        self.q_range = p.q_range
        # the components that steer the steps: q, q̇, and φ when ω varies in time (module docstring)
        self.controlled = 3 if curve.rotating and curve.omega_const is None else 2
        self.closed = False
        if p.q_range is not None:
            ya, yb = curve.y(p.q_range[0])[:, 0], curve.y(p.q_range[1])[:, 0]
            scale = max(1.0, float(np.max(np.abs(ya))))
            self.closed = bool(np.all(np.abs(ya - yb) <= 1e-9 * scale))

    def forces(self, t, x, v):
        """(F_potential, F_other): sums of the potential terms and of the rest."""
        Fc, Fn = np.zeros_like(x), np.zeros_like(x)
        for tm in self.terms:
            f = tm.force(t, x, v)
            if tm.kind in POTENTIAL:
                Fc = Fc + f
            else:
                Fn = Fn + f
        return Fc, Fn

    def potential(self, x):
        V = np.zeros(x.shape[1])
        for tm in self.terms:
            if tm.kind in POTENTIAL:
                V = V + tm._V(x)
        return V

    def evaluate(self, t, Y, mode):
        """Everything at the states Y (5, n) of a phase with ``mode`` =
        ("slide", s) or ("stick", 0)."""
        t = np.atleast_1d(np.asarray(t, float))
        q, qd, phi = Y[0], Y[1], Y[2]
        if mode[0] == "stick":
            qd = np.zeros_like(qd)
        x, v, tau, b, Q, y1, y2 = self.curve.state(t, q, qd, phi, jet=True)
        Fc, Fn = self.forces(t, x, v)
        F = Fc + Fn
        sp = norm_rows(tau.T)                     # scaled first (dyncli.direction)
        et = np.nan_to_num(unit_rows(tau.T).T)
        R = self.m * b - F
        N = R - np.sum(R * et, axis=0) * et
        Nmag = np.linalg.norm(N, axis=0)
        G = -np.sum(R * et, axis=0)
        if mode[0] == "stick":
            ft = -G
            qdd = np.zeros_like(q)
        else:
            ft = eq.sliding_friction(self.mu, Nmag, mode[1])
            qdd = eq.parameter_acceleration(G, ft, self.m, sp)
        a = tau * qdd + b
        return {"x": x, "v": v, "a": a, "tau": tau, "speed": sp, "et": et, "N": N, "Nmag": Nmag, "G": G,
                "ft": ft, "qdd": qdd, "F": F, "Fc": Fc, "Fn": Fn, "Q": Q, "q": q, "qd": qd,
                "y1": y1, "y2": y2}

    def rhs_for(self, mode):  # over 60 lines: the integrator's hot loop, inlined in plain floats on purpose
        """y' = f(t, y) for one state, in plain float arithmetic (the integrator calls it one state
        at a time; the same equations as evaluate()): the curve's y, y', y'' from its derivatives
        compiled once into float closures (:meth:`Curve.float_jet`), the forces from
        :meth:`Forces.plain`.  Everything is computed on the curve's own frame, where x = y and
        τ = y' (dot products and lengths do not change with the frame): b = y'' q̇² + 2 ω k × y' q̇
        + ω̇ k × y + ω² (k (k·y) − y).  A field symmetric about the axis (:meth:`Forces.symmetric_about`:
        gravity along it, dampers, drag) is evaluated there too; any other at the fixed-frame
        x = Q y, v = Q v_r, and turned back by Qᵀ (Rodrigues: Q u = c u + s k × u + (1 − c)(k·u) k)."""
        from dyncli.expr import floatmath
        from dyncli.expr.jet import compile_jet

        curve, m, mu = self.curve, self.m, self.mu
        jet = curve.float_jet()
        forces = self.compiled.plain()
        k1, k2, k3 = (float(c) for c in curve.k)
        rotating, w_const = curve.rotating, curve.omega_const
        omega = compile_jet(curve.omega_expr.ir, "t", floatmath) if rotating and w_const is None else None
        turn = rotating and not self.compiled.symmetric_about((k1, k2, k3))
        vertical = (k1, k2, k3) == (0.0, 0.0, 1.0)
        stick, s = mode[0] == "stick", float(mode[1])
        sqrt, cos, sin, isfinite = math.sqrt, math.cos, math.sin, math.isfinite

        def rhs(t, y):
            yl = y.tolist()
            q, qd = yl[0], yl[1]
            if stick:
                qd = 0.0
            x1, x2, x3, a1, a2, a3, b1, b2, b3 = jet(q)
            qq = qd * qd
            if rotating:
                if omega is None:
                    w, wd = w_const, 0.0
                else:
                    w, wd, _ = omega({"t": float(t)})
                w2, ww = 2 * w * qd, w * w
                if vertical:                      # k = e3: k × y = (−y2, y1, 0), k (k·y) − y = (−y1, −y2, 0)
                    kx1, kx2, kx3, ky = -x2, x1, 0.0, x3
                    v1, v2, v3 = a1 * qd - w * x2, a2 * qd + w * x1, a3 * qd
                    B1 = b1 * qq - w2 * a2 - wd * x2 - ww * x1
                    B2 = b2 * qq + w2 * a1 + wd * x1 - ww * x2
                    B3 = b3 * qq
                else:
                    kx1, kx2, kx3 = k2 * x3 - k3 * x2, k3 * x1 - k1 * x3, k1 * x2 - k2 * x1      # k × y
                    kt1, kt2, kt3 = k2 * a3 - k3 * a2, k3 * a1 - k1 * a3, k1 * a2 - k2 * a1      # k × y'
                    ky = k1 * x1 + k2 * x2 + k3 * x3
                    v1, v2, v3 = a1 * qd + w * kx1, a2 * qd + w * kx2, a3 * qd + w * kx3
                    B1 = b1 * qq + w2 * kt1 + wd * kx1 + ww * (k1 * ky - x1)
                    B2 = b2 * qq + w2 * kt2 + wd * kx2 + ww * (k2 * ky - x2)
                    B3 = b3 * qq + w2 * kt3 + wd * kx3 + ww * (k3 * ky - x3)
                if turn:                          # the field at x = Q y, v = Q v_r, turned back by Qᵀ
                    c, sn = cos(yl[2]), sin(yl[2])
                    d = 1.0 - c
                    dk = d * ky
                    X1, X2, X3 = c * x1 + sn * kx1 + dk * k1, c * x2 + sn * kx2 + dk * k2, c * x3 + sn * kx3 + dk * k3
                    kv1, kv2, kv3 = k2 * v3 - k3 * v2, k3 * v1 - k1 * v3, k1 * v2 - k2 * v1
                    dk = d * (k1 * v1 + k2 * v2 + k3 * v3)
                    V1, V2, V3 = c * v1 + sn * kv1 + dk * k1, c * v2 + sn * kv2 + dk * k2, c * v3 + sn * kv3 + dk * k3
                    C1, C2, C3, N1, N2, N3 = forces(t, X1, X2, X3, V1, V2, V3)
                    kf1, kf2, kf3 = k2 * C3 - k3 * C2, k3 * C1 - k1 * C3, k1 * C2 - k2 * C1
                    dk = d * (k1 * C1 + k2 * C2 + k3 * C3)
                    c1, c2, c3 = c * C1 - sn * kf1 + dk * k1, c * C2 - sn * kf2 + dk * k2, c * C3 - sn * kf3 + dk * k3
                    kf1, kf2, kf3 = k2 * N3 - k3 * N2, k3 * N1 - k1 * N3, k1 * N2 - k2 * N1
                    dk = d * (k1 * N1 + k2 * N2 + k3 * N3)
                    n1, n2, n3 = c * N1 - sn * kf1 + dk * k1, c * N2 - sn * kf2 + dk * k2, c * N3 - sn * kf3 + dk * k3
                else:
                    c1, c2, c3, n1, n2, n3 = forces(t, x1, x2, x3, v1, v2, v3)
            else:
                w = 0.0
                v1, v2, v3 = a1 * qd, a2 * qd, a3 * qd
                B1, B2, B3 = b1 * qq, b2 * qq, b3 * qq
                c1, c2, c3, n1, n2, n3 = forces(t, x1, x2, x3, v1, v2, v3)
            sp = sqrt(a1 * a1 + a2 * a2 + a3 * a3) or math.nan     # a vanishing tangent: the not-finite error below
            e1, e2, e3 = a1 / sp, a2 / sp, a3 / sp
            R1, R2, R3 = m * B1 - c1 - n1, m * B2 - c2 - n2, m * B3 - c3 - n3
            Rt = R1 * e1 + R2 * e2 + R3 * e3
            N1, N2, N3 = R1 - Rt * e1, R2 - Rt * e2, R3 - Rt * e3
            if stick:
                ft, qdd = Rt, 0.0
            else:
                ft = eq.sliding_friction(mu, sqrt(N1 * N1 + N2 * N2 + N3 * N3), s) if mu else 0.0
                qdd = eq.parameter_acceleration(-Rt, ft, m, sp)
            P_nc = (n1 + ft * e1) * v1 + (n2 + ft * e2) * v2 + (n3 + ft * e3) * v3
            P_N = N1 * v1 + N2 * v2 + N3 * v3
            if not isfinite(qdd + P_nc + P_N) and not (isfinite(qdd) and isfinite(P_nc) and isfinite(P_N)):
                # the rate checked here (the runner's check_finite off)
                raise NumericalError(f"the motion is not finite at t = {t:.6g} s, q = {q:.6g} "
                                     "(the curve's tangent vanishes, a force is singular there, or the accelerations overflow)")
            return [qd, qdd, w, P_nc, P_N, sp * qd]

        return rhs


class Phase:
    def __init__(self, t0, t1, sol, mode, steps_t, steps_y):
        self.t0, self.t1, self.sol, self.mode = t0, t1, sol, mode
        self.steps_t, self.steps_y = steps_t, steps_y

    def state(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        if self.t1 > self.t0:
            return self.sol(t)
        return np.repeat(self.steps_y[:, :1], t.size, axis=1)


def _events(model, mode, rtol):
    evs = []
    if mode[0] == "slide" and model.mu > 0:
        s = mode[1]

        def stop(t, y, s=s):
            return s * y[1]
        stop.terminal, stop.direction = True, -1
        evs.append(stop)
    if mode[0] == "stick":
        def release(t, y):
            e = model.evaluate(t, y[:, None], mode)
            return float(abs(e["G"][0]) - model.mu * e["Nmag"][0] * (1 + 20 * rtol))
        release.terminal, release.direction = True, 1
        evs.append(release)
    if model.q_range is not None and not model.closed:
        lo, hi = model.q_range

        def end(t, y, lo=lo, hi=hi):
            return min(y[0] - lo, hi - y[0])
        end.terminal, end.direction = True, -1
        evs.append(end)
    return evs


def _start_mode(model, t, y, rtol):
    """The mode of a phase starting at (t, y): slide in the direction of q̇, or
    (at rest with friction) stick or slip in the direction of G."""
    if y[1] != 0 or model.mu == 0:
        return ("slide", 1.0 if y[1] >= 0 else -1.0)
    e = model.evaluate(t, y[:, None], ("stick", 0))
    G, N = float(e["G"][0]), float(e["Nmag"][0])
    if abs(G) <= model.mu * N * (1 + 10 * rtol):
        return ("stick", 0)
    return ("slide", 1.0 if G > 0 else -1.0)


def integrate(model, rtol, atol, method, max_steps=None, max_step=math.inf):
    """(phases, friction notes, accepted steps) of the motion to t_end, inside one numpy error state
    (a custom force's numpy scalars overflow to inf quietly: the right-hand side checks its rate)."""
    with np.errstate(all="ignore"):
        return _integrate(model, rtol, atol, method, max_steps, max_step)


def _integrate(model, rtol, atol, method, max_steps, max_step):
    p = model.p
    rtol = runner.floor_rtol(rtol)
    max_step = min(max_step, model.compiled.kink_step)     # no step over a one-sided spring's contact
    t_end = float(p.t_end)
    y = np.array([p.q0, p.q_dot0, 0.0, 0.0, 0.0, 0.0], float)
    t = 0.0
    phases, notes = [], []
    budget = ode.Budget(max_steps, default=MAX_STEPS, probe=500)
    budget.leg(0.0, t_end)
    for _ in range(MAX_PHASES):
        mode = _start_mode(model, t, y, rtol)
        if mode[0] == "stick":
            y[1] = 0.0
            notes.append(("stick", t))
        elif phases and model.mu > 0 and y[1] == 0:
            notes.append(("slip", t))
        evs = _events(model, mode, rtol)
        try:
            run = runner.march(model.rhs_for(mode), t, y, t_end, method=method, budget=budget, rtol=rtol, atol=atol,
                               events=evs, max_step=max_step, controlled=model.controlled)
        except ode.StepFailed as exc:
            raise NumericalError(f"the integrator ({method}) failed near t = {exc.t:g}: {exc.reason}") from None
        except (ValueError, ZeroDivisionError, FloatingPointError, OverflowError) as exc:
            raise NumericalError(f"the integrator ({method}) failed near t = {t:g}: {exc}") from None
        if run.status == 1:
            te, ye = run.t_event, run.y_event
            phases.append(Phase(t, te, run.sol, mode, run.t, run.y))
            ev = evs[run.event]
            if ev.__name__ == "end":
                raise NumericalError(f"the particle reaches the end of the wire (q = {ye[0]:.6g}) at t = {te:.6g} s, "
                                     f"before t_end = {t_end:g} s")
            if ev.__name__ == "stop":
                ye[1] = 0.0
            elif ev.__name__ == "release":
                notes.append(("release", te))
            t, y = te, ye
            if te >= t_end:
                break
            continue
        phases.append(Phase(t, float(run.t[-1]), run.sol, mode, run.t, run.y))
        break
    else:
        raise NumericalError(f"friction: more than {MAX_PHASES} stick/slip phases before t_end")
    return phases, notes, budget.n


def make_dense(phases) -> None:
    """Every step's interpolant of the sliding phases made now (:meth:`dyncli.dop853.LazyDense.made`:
    the values it gives when made on first use), so that the phases' solutions evaluate many times
    in one pass over all their steps (:class:`dyncli.dop853.OdeSolution`)."""
    for ph in phases:
        if ph.mode[0] != "stick" and ph.sol is not None:
            for f in ph.sol.interpolants:
                made = getattr(f, "made", None)
                if made is not None:
                    made()


def phase_at(phases, t):
    for ph in phases:
        if ph.t0 <= t <= ph.t1:
            return ph
    return phases[-1]


def states_at(phases, times):
    """The states (5, n) at ``times`` and the mode of each: every phase's dense output called
    once on its times (as :func:`phase_at` assigns them)."""
    last = len(phases) - 1
    idx = [next((i for i, ph in enumerate(phases) if ph.t0 <= t <= ph.t1), last) if last else 0 for t in times]
    Y = np.empty((phases[0].steps_y.shape[0], len(times)))
    for k, ph in enumerate(phases):
        sel = [j for j, i in enumerate(idx) if i == k]
        if sel:
            Y[:, sel] = ph.state([times[j] for j in sel])
    return Y, [phases[i].mode for i in idx]
