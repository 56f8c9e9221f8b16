"""The heavy symmetric top (notes §38) — numeric core.

(38.18) is singular where sin θ = 0 (the 3-1-3 chart breaks down when the
axis passes the vertical).  dyncli therefore integrates the equivalent
non-singular system: the unit quaternion q of the body basis e' and the body
components of ω about O,

    I ω̇ = −ω × Iω + M_O,   M_O = L e'₃ × (−m g e₃)   (38.17),
    q̇ = ½ q ⊗ (0, ω),

and converts back to 3-1-3 angles (38.3)-(38.5) at densely spaced points of
every step, choosing among the equivalent triples (ψ, θ, φ) and
(ψ + π, −θ, φ + π) (plus multiples of 2π) the one continuous with the
previous point — so ψ, θ, φ are continuous and never wrapped.  The rates
follow from ω'' = θ̇ e''₁ + ψ̇ sinθ e''₂ + (ψ̇ cosθ + φ̇) e''₃ (38.11b); the
reaction from R = m g e₃ + m ā (38.16) with ā = ω̇ × x̄ + ω × (ω × x̄).

θ_min, θ_max are the turning points of u = cos θ from the energy and the two
momentum integrals (H·e₃ and ω₃):  u̇² = f(u), a cubic whose coefficients
are expanded about u₀ = cos θ₀ (f(u₀) = θ̇₀² sin²θ₀ exactly), so a steady
precession gives θ_min = θ_max = θ₀ to rounding.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.result import Result, Series, SolveOptions
from dyncli.topics.euler import ode
from dyncli.topics.precession.table38 import table_38_1

SYMBOLS = {"psi": "ψ", "theta": "θ", "phi": "φ", "psi_dot": "ψ̇", "theta_dot": "θ̇", "phi_dot": "φ̇",
           "R": "R (e'')", "theta_min": "θ_min", "theta_max": "θ_max", "drift": "drift",
           "E": "E", "H3": "H·e₃", "omega3": "ω₃"}
UNITS = {"psi": "rad", "theta": "rad", "phi": "rad", "psi_dot": "rad/s", "theta_dot": "rad/s", "phi_dot": "rad/s",
         "R": "N", "theta_min": "rad", "theta_max": "rad", "E": "J", "H3": "kg·m²/s", "omega3": "rad/s"}
VERTICAL = 1e-12


# --------------------------------------------------------------------------- rotations

def qmul(a, b):
    a0, a1, a2, a3 = a
    b0, b1, b2, b3 = b
    return np.array([a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3,
                     a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
                     a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1,
                     a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0])


def quat_313(psi, theta, phi):
    """Quaternion of R = Rz(ψ) Rx(θ) Rz(φ) (body components -> fixed components)."""
    qz1 = np.array([math.cos(psi / 2), 0.0, 0.0, math.sin(psi / 2)])
    qx = np.array([math.cos(theta / 2), math.sin(theta / 2), 0.0, 0.0])
    qz2 = np.array([math.cos(phi / 2), 0.0, 0.0, math.sin(phi / 2)])
    return qmul(qmul(qz1, qx), qz2)


def rotmat(q):
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q)
    w, x, y, z = q
    return np.array([
        [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]])


def vertical_in_body(q):
    """n = e₃ on the body basis (third row of R)."""
    w, x, y, z = q
    return np.array([2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z])


def _near(x, ref):
    """x + 2πk closest to ref."""
    return x + 2 * math.pi * round((ref - x) / (2 * math.pi))


def angles_313(Rm, prev=None):
    """(ψ, θ, φ) of R = Rz(ψ)Rx(θ)Rz(φ), continuous with ``prev``."""
    st = math.hypot(Rm[0, 2], Rm[1, 2])
    th = math.atan2(st, Rm[2, 2])
    if prev is None:
        if st < VERTICAL:
            return 0.0, th, math.atan2(Rm[1, 0], Rm[0, 0]) * (1.0 if Rm[2, 2] > 0 else -1.0)
        return math.atan2(Rm[0, 2], -Rm[1, 2]), th, math.atan2(Rm[2, 0], Rm[2, 1])
    p_psi, p_th, p_phi = prev
    if st < VERTICAL:
        # axis on the vertical: only ψ ± φ is defined; keep ψ from before
        if Rm[2, 2] > 0:
            s = math.atan2(Rm[1, 0], Rm[0, 0])        # ψ + φ
            th_c = _near(0.0, p_th)
            psi = p_psi
            phi = _near(s - psi, p_phi)
        else:
            d = math.atan2(Rm[1, 0], Rm[0, 0])        # ψ − φ (θ = π)
            th_c = _near(math.pi, p_th) if abs(_near(math.pi, p_th) - p_th) <= abs(_near(-math.pi, p_th) - p_th) else _near(-math.pi, p_th)
            psi = p_psi
            phi = _near(psi - d, p_phi)
        return psi, th_c, phi
    psi_c = math.atan2(Rm[0, 2], -Rm[1, 2])
    phi_c = math.atan2(Rm[2, 0], Rm[2, 1])
    # the two families (ψ, θ, φ) and (ψ + π, −θ, φ + π): take the one nearest to prev in all three
    c1 = (_near(psi_c, p_psi), _near(th, p_th), _near(phi_c, p_phi))
    c2 = (_near(psi_c + math.pi, p_psi), _near(-th, p_th), _near(phi_c + math.pi, p_phi))
    d1 = abs(c1[0] - p_psi) + abs(c1[1] - p_th) + abs(c1[2] - p_phi)
    d2 = abs(c2[0] - p_psi) + abs(c2[1] - p_th) + abs(c2[2] - p_phi)
    return c2 if d2 < d1 else c1


# --------------------------------------------------------------------------- turning points

def turning_points(I11, I33, mgL, th0, psid0, thd0, w3):
    """(θ_min, θ_max) from u̇² = f(u), expanded in x = u − cos θ₀."""
    u0, s0 = math.cos(th0), math.sin(th0)
    s2 = s0 * s0
    beta = 2.0 * mgL / I11
    b = I33 * w3 / I11
    P0 = thd0 * thd0 + psid0 * psid0 * s2          # α − β u₀
    R0 = psid0 * s2                                 # a − b u₀
    c0 = s2 * thd0 * thd0
    c1 = -s2 * beta - 2.0 * u0 * P0 + 2.0 * b * R0
    c2 = 2.0 * u0 * beta - P0 - b * b
    c3 = beta
    if abs(c3) * 8.0 <= 1e-17 * (abs(c2) + abs(c1) + abs(c0)):
        c3 = 0.0            # negligible on |x| <= 2 (L -> 0): the quadratic of the torque-free body
    scale = abs(c1) + abs(c2) + abs(c3) + 1e-300

    def f(x):
        return ((c3 * x + c2) * x + c1) * x + c0

    def df(x):
        return (3 * c3 * x + 2 * c2) * x + c1

    def polish(x):
        for _ in range(4):
            d = df(x)
            if d == 0:
                break
            x = x - f(x) / d
        return x

    at_rest = c0 <= 1e-15 * scale
    if at_rest:
        # x = 0 is a root: deflate to c3 x² + c2 x + c1
        roots = _quad_roots(c3, c2, c1)
        if c1 == 0 or abs(c1) <= 1e-14 * (abs(c2) + abs(c3) + abs(P0) + abs(beta)):
            return th0_norm(th0), th0_norm(th0)
        direction = 1.0 if c1 > 0 else -1.0
        cands = [x for x in roots if x * direction > 0]
        other = min(cands, key=abs) if cands else direction * (1.0 - direction * u0)
        xs = sorted([0.0, other])
    else:
        coeffs = [c3, c2, c1, c0]
        while coeffs and coeffs[0] == 0:
            coeffs = coeffs[1:]
        rr = np.roots(coeffs) if len(coeffs) > 1 else np.array([])
        real = [polish(float(z.real)) for z in rr if abs(z.imag) <= 1e-7 * (1 + abs(z))]
        pos = [x for x in real if x > 0]
        neg = [x for x in real if x < 0]
        xp = min(pos) if pos else 1.0 - u0
        xn = max(neg) if neg else -1.0 - u0
        xs = [xn, xp]
    u_lo = min(1.0, max(-1.0, u0 + xs[0]))
    u_hi = min(1.0, max(-1.0, u0 + xs[1]))
    return _acos_near(u_hi, u0, th0), _acos_near(u_lo, u0, th0)


def th0_norm(th0):
    return math.acos(min(1.0, max(-1.0, math.cos(th0)))) if not (0 <= th0 <= math.pi) else th0


def _acos_near(u, u0, th0):
    t0 = th0_norm(th0)
    if u == u0:
        return t0
    return math.acos(u)


def _quad_roots(A, B, C):
    if A == 0:
        return [] if B == 0 else [-C / B]
    d = B * B - 4 * A * C
    if d < 0:
        return []
    sq = math.sqrt(d)
    q = -0.5 * (B + math.copysign(sq, B)) if B != 0 else -0.5 * sq
    out = [q / A]
    out.append(C / q if q != 0 else -q / A)
    return out


# --------------------------------------------------------------------------- solve

def solve(pb, options: SolveOptions | None = None) -> Result:
    m, L, I11, I33, g = pb.m, pb.L, pb.I11, pb.I33, pb.g
    mgL = m * g * L
    Ib = np.array([I11, I11, I33])
    times = np.asarray(pb.at, dtype=float)
    res = Result({}, equations=["38.3", "38.4", "38.5", "38.11b", "38.16", "38.17", "38.18"],
                 symbols=SYMBOLS, units=UNITS)
    th0, ps0, ph0 = pb.theta, pb.psi, pb.phi
    s0, c0 = math.sin(th0), math.cos(th0)
    w2 = np.array([pb.theta_dot, pb.psi_dot * s0, pb.psi_dot * c0 + pb.phi_dot])  # ω on e'' (38.11b)
    cp, sp = math.cos(ph0), math.sin(ph0)
    wb = np.array([cp * w2[0] + sp * w2[1], -sp * w2[0] + cp * w2[1], w2[2]])      # on e' = Rz(φ)ᵀ ω''
    q0 = quat_313(ps0, th0, ph0)
    y0 = np.concatenate([q0, wb])

    k1 = (I11 - I33) / I11          # Euler's equations about O with I = diag(I11, I11, I33)
    gl = mgL / I11

    def fun(t, y):
        q0, q1, q2, q3, w1, w2, w3 = y.tolist()
        inv = 1.0 / (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
        n1 = 2.0 * (q1 * q3 - q0 * q2) * inv
        n2 = 2.0 * (q2 * q3 + q0 * q1) * inv
        return np.array([
            0.5 * (-q1 * w1 - q2 * w2 - q3 * w3),
            0.5 * (q0 * w1 + q2 * w3 - q3 * w2),
            0.5 * (q0 * w2 - q1 * w3 + q3 * w1),
            0.5 * (q0 * w3 + q1 * w2 - q2 * w1),
            gl * n2 + k1 * w2 * w3,       # I11 ω̇1 = M1 − (I33 − I11) ω2 ω3
            -gl * n1 - k1 * w1 * w3,      # I11 ω̇2 = M2 − (I11 − I33) ω1 ω3
            0.0,                          # I33 ω̇3 = 0 (38.18c)
        ])

    def invariants(y):
        q = y[:4] / np.linalg.norm(y[:4])
        w = y[4:]
        n = vertical_in_body(q)
        E = 0.5 * float(w @ (Ib * w)) + mgL * n[2]
        H3 = float((Ib * w) @ n)
        return E, H3, float(w[2])

    E0, H30, w30 = invariants(y0)
    T0 = 0.5 * float(wb @ (Ib * wb))
    scales = (T0 + abs(mgL), math.sqrt(float(np.sum((Ib * wb) ** 2))), float(np.linalg.norm(wb)))
    method = pb.accuracy.method
    mth = "DOP853" if method in ("auto", "projected") else method
    res.method = "ode:projected-DOP853" if method == "projected" else f"ode:{mth}"
    project = _projector(Ib, mgL, E0, H30, w30, max(scales[2], 1e-300)) if method == "projected" else None

    # continuous angles: sample every step densely, unwrap sequentially
    want = {}
    order_t = np.unique(times)
    state = {"prev": None, "dirn": 1.0}
    worst = [0.0, 0.0, 0.0]
    ang0 = (ps0, th0, ph0)

    def angles_at(y, prev):
        return angles_313(rotmat(y[:4]), prev)

    def on_step(t_old, t_new, dense, direction):
        if dense is None:
            state["prev"] = ang0
            if (times == t_old).any():
                want[float(t_old)] = ang0
            return
        ys_end = dense(t_new)
        for k, v in enumerate(invariants(ys_end)):
            ref = (E0, H30, w30)[k]
            worst[k] = max(worst[k], abs(v - ref))
        lo, hi = sorted((t_old, t_new))
        req = order_t[(order_t > lo) & (order_t <= hi)] if direction > 0 else order_t[(order_t >= lo) & (order_t < hi)]
        wmax = float(np.max(np.abs(ys_end[4:]))) + float(np.max(np.abs(dense(t_old)[4:])))
        nsub = max(1, int(math.ceil(wmax * abs(t_new - t_old) / 0.25)))
        grid = list(np.linspace(t_old, t_new, nsub + 1)[1:]) + list(req)
        grid = sorted(set(grid), key=lambda t: (t - t_old) * direction)
        tp = t_old
        for t in grid:
            state["prev"] = _refine(dense, tp, t, state["prev"], angles_at, 0)
            if t in set(req.tolist()):
                want[float(t)] = state["prev"]
            tp = t

    Y, nsteps = ode.integrate(fun, y0, times, method=mth, rtol=pb.accuracy.rtol, atol=pb.accuracy.atol,
                              project=project, on_step=on_step)
    drift_E = worst[0] / max(scales[0], 1e-300)
    drift_H = worst[1] / max(scales[1], 1e-300)
    drift_w = worst[2] / max(scales[2], 1e-300)
    r = res.results
    psi, theta, phi, psid, thd, phid, R = [], [], [], [], [], [], []
    singular = False
    for i, t in enumerate(times):
        y = Y[i]
        a = want.get(float(t))
        if a is None:  # pragma: no cover - defensive
            a = angles_at(y, ang0)
        q = y[:4] / np.linalg.norm(y[:4])
        w = y[4:]
        ps, th, ph = a
        cph, sph = math.cos(ph), math.sin(ph)
        w2 = np.array([cph * w[0] - sph * w[1], sph * w[0] + cph * w[1], w[2]])     # ω on e''
        st, ct = math.sin(th), math.cos(th)
        psi.append(ps)
        theta.append(th)
        phi.append(ph)
        thd.append(float(w2[0]))
        if abs(st) < 1e-9:
            singular = True
            psid.append(None)
            phid.append(None)
        else:
            pd = float(w2[1] / st)
            psid.append(pd)
            phid.append(float(w2[2] - pd * ct))
        # reaction (38.16): R = m g e3 + m ā, ā = ω̇ × x̄ + ω × (ω × x̄), on e'
        n = vertical_in_body(q)
        M = mgL * np.array([n[1], -n[0], 0.0])
        wd = (M - np.cross(w, Ib * w)) / Ib
        xb = np.array([0.0, 0.0, L])
        abar = np.cross(wd, xb) + np.cross(w, np.cross(w, xb))
        Rb = m * g * n + m * abar
        R.append([float(cph * Rb[0] - sph * Rb[1]), float(sph * Rb[0] + cph * Rb[1]), float(Rb[2])])
    if singular:
        res.warn("the axis is on the vertical (sin θ ≈ 0) at a requested time: ψ̇ and φ̇ are not defined "
                 "separately there (only ψ̇ + φ̇ is) and are reported as null")
    r["psi"], r["theta"], r["phi"] = psi, theta, phi
    r["psi_dot"], r["theta_dot"], r["phi_dot"] = psid, thd, phid
    r["R"] = R
    tmin, tmax = turning_points(I11, I33, mgL, th0, pb.psi_dot, pb.theta_dot, w30)
    r["theta_min"], r["theta_max"] = tmin, tmax
    r["E"], r["H3"], r["omega3"] = E0, H30, w30
    r["drift"] = max(drift_E, drift_H, drift_w)
    r["drift_detail"] = {"E": drift_E, "H3": drift_H, "omega3": drift_w}
    if pb.accuracy.estimate:
        r2, a2 = ode.tighter(pb.accuracy.rtol, pb.accuracy.atol)
        Y2, _ = ode.integrate(fun, y0, times, method=mth, rtol=r2, atol=a2, project=project)
        d = 0.0
        for i in range(len(times)):
            A1, A2 = rotmat(Y[i, :4]), rotmat(Y2[i, :4])
            d = max(d, float(np.max(np.abs(A1 - A2))),
                    float(np.max(np.abs(Y[i, 4:] - Y2[i, 4:]))) / max(scales[2], 1e-300))
        res.error_estimate = d
    else:
        res.error_estimate = max(pb.accuracy.rtol, r["drift"])
    if len(times):
        res.series.append(Series("t", times.tolist(), ["psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot", "R"]))
        if psid[0] is not None:
            th, pd, td, fd = theta[0], psid[0], thd[0], phid[0]
            s_, c_ = math.sin(th), math.cos(th)
            w3 = pd * c_ + fd
            tdd = pd * pd * s_ * c_ - I33 / I11 * pd * s_ * w3 + mgL * s_ / I11          # (38.18a)
            pdd = (I33 * w3 * td - 2 * I11 * pd * td * c_) / (I11 * s_)                 # (38.18b)
            fdd = -(pdd * c_ - pd * td * s_)                                            # (38.18c)
            res.views.append(table_38_1(f"Table 38.1 at t = {times[0]:.6g} s", m, L, I11, I33, g, th, pd, td, fd,
                                        pdd, tdd, fdd))
    return res


def _refine(dense, ta, tb, prev, angles_at, depth):
    """Angles at tb continuous with ``prev`` (at ta); bisect where they move fast."""
    a = angles_at(dense(tb), prev)
    if depth < 40 and max(abs(a[0] - prev[0]), abs(a[1] - prev[1]), abs(a[2] - prev[2])) > 0.5:
        tm = 0.5 * (ta + tb)
        if tm != ta and tm != tb:
            mid = _refine(dense, ta, tm, prev, angles_at, depth + 1)
            return _refine(dense, tm, tb, mid, angles_at, depth + 1)
    return a


def _projector(Ib, mgL, E0, H30, w30, wscale):
    """Project (q, ω) onto |q| = 1, ω₃ = ω₃₀, E = E₀, H·e₃ = H₃₀ (min-norm Gauss-Newton)."""
    I11, I33 = Ib[0], Ib[2]

    def project(y):
        y = np.array(y, dtype=float)
        for _ in range(3):
            q, w = y[:4], y[4:]
            n = vertical_in_body(q)
            qq = q @ q
            dn1 = 2 * np.array([-q[2], q[3], -q[0], q[1]])
            dn2 = 2 * np.array([q[1], q[0], q[3], q[2]])
            dn3 = 2 * np.array([q[0], -q[1], -q[2], q[3]])
            g = np.array([qq - 1.0, w[2] - w30, 0.5 * (w @ (Ib * w)) + mgL * n[2] - E0, (Ib * w) @ n - H30])
            J = np.zeros((4, 7))
            J[0, :4] = 2 * q
            J[1, 6] = 1.0
            J[2, :4] = mgL * dn3
            J[2, 4:] = Ib * w
            J[3, :4] = I11 * (w[0] * dn1 + w[1] * dn2) + I33 * w[2] * dn3
            J[3, 4:] = Ib * n
            D = np.array([1, 1, 1, 1, wscale, wscale, wscale])
            Jz = J * D
            dz, *_ = np.linalg.lstsq(Jz, -g, rcond=1e-12)
            y = y + D * dz
            if np.max(np.abs(g)) == 0:
                break
        return y

    return project
