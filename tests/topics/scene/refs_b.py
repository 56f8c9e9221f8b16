"""Independent references for the scene gallery (b): problems/scenes/{compound-pendulum,
falling-rod, yo-yo, double-pendulum, cart-pendulum, slider-crank, four-bar}.yaml.

Nothing here imports dyncli.  Every reference is derived a second way, by hand or with sympy
(sympy only in tests), and evaluated with mpmath at 30 digits:

* closed forms (yo-yo; the release and the bottom of the compound pendulum; the release of the
  falling rod) written out by hand;
* Jacobi elliptic functions for the compound pendulum's whole motion (sn, cn, K, F);
* the falling rod's motion from its Lagrange equation in the angle from the vertical, integrated
  by an extrapolation (Gragg-Bulirsch-Stoer) integrator written here in mpmath, and its event
  time from the energy quadrature t = ∫ dβ/β̇ (two routes; they agree to 1e-25);
* the double pendulum and the pendulum on a spring-held cart from Lagrange's equations in
  minimal coordinates (derived with sympy), integrated by the same extrapolation integrator at
  30 digits; the link tensions and the cart's slider force and couple then by Newton's law on
  each body (the second formulation), never from the Lagrange multipliers of a solver;
* the slider-crank and the four-bar from loop closure (closed form; mpmath findroot for the
  four-bar), their joint forces from a Newton-Euler linear solve of the free-body diagrams
  (`newton_euler`), the drive couple checked against virtual power (drive couple × ω =
  dT/dt + dV/dt).

Each scene's function returns a mapping dotted result path -> expected value (mpf), in the
result shapes of docs/types/scene.md: ``angle.bar.1``, ``reaction.pivot.R.0.1``,
``find.0.t``, ``find.0.x.A.1``.
"""

from __future__ import annotations

import re

from mpmath import mp, mpf

G = "9.81"

# ----------------------------------------------------------------------------------------------
# an extrapolation ODE integrator at working precision (Gragg's modified midpoint + Richardson)
# ----------------------------------------------------------------------------------------------


def _midpoint(f, t, y, H, n):
    h = H / n
    z0 = list(y)
    z1 = [a + h * b for a, b in zip(y, f(t, y))]
    for i in range(1, n):
        z0, z1 = z1, [a + 2 * h * b for a, b in zip(z0, f(t + i * h, z1))]
    fe = f(t + H, z1)
    return [(a + b + h * c) / 2 for a, b, c in zip(z0, z1, fe)]


def _gbs_step(f, t, y, H, tol, levels=16):
    """One extrapolated step of length H; None if it does not converge to tol."""
    table = []
    ns = []
    for j in range(levels):
        n = 2 * (j + 1)
        row = [_midpoint(f, t, y, H, n)]
        for k in range(1, j + 1):
            ratio = (mpf(n) / ns[j - k]) ** 2 - 1
            row.append([a + (a - b) / ratio for a, b in zip(row[k - 1], table[j - 1][k - 1])])
        ns.append(n)
        table.append(row)
        if j >= 3:
            err = max(abs(a - b) for a, b in zip(row[j], table[j - 1][j - 1]))
            scale = max(mpf(1), max(abs(a) for a in row[j]))
            if err <= tol * scale:
                return row[j]
    return None


def integrate(f, t0, y0, t1, hmax=mpf("0.02"), tol=None):
    """y(t1) of y' = f(t, y), y(t0) = y0, at the working precision."""
    tol = tol if tol is not None else mpf(10) ** (-(mp.dps - 4))
    t0, t1 = mpf(t0), mpf(t1)
    y = [mpf(v) for v in y0]
    if t1 == t0:
        return y
    n = int(mp.ceil(abs(t1 - t0) / hmax))
    H = (t1 - t0) / n
    t = t0
    for _ in range(n):
        y = _step(f, t, y, H, tol)
        t += H
    return y


def _step(f, t, y, H, tol, depth=0):
    out = _gbs_step(f, t, y, H, tol)
    if out is not None:
        return out
    if depth > 20:
        raise RuntimeError("reference integrator did not converge")
    half = _step(f, t, y, H / 2, tol, depth + 1)
    return _step(f, t + H / 2, half, H / 2, tol, depth + 1)


class Trajectory:
    """Dense reference: states kept on a grid; state(t) integrates from the grid point below."""

    def __init__(self, f, y0, t_end, grid=mpf("0.05")):
        self.f, self.grid = f, mpf(grid)
        self.states = [[mpf(v) for v in y0]]
        n = int(mp.ceil(mpf(t_end) / self.grid))
        for k in range(n):
            self.states.append(integrate(f, k * self.grid, self.states[-1], (k + 1) * self.grid))

    def __call__(self, t):
        t = mpf(t)
        k = min(int(mp.floor(t / self.grid)), len(self.states) - 1)
        return integrate(self.f, k * self.grid, self.states[k], t)

    def root(self, fun, t_lo, t_hi):
        """The time in [t_lo, t_hi] where fun(t, state) changes sign (bisection, then secant)."""
        a, b = mpf(t_lo), mpf(t_hi)
        fa, fb = fun(a, self(a)), fun(b, self(b))
        assert fa * fb < 0, "no sign change in the bracket"
        for _ in range(30):
            m = (a + b) / 2
            fm = fun(m, self(m))
            if fa * fm <= 0:
                b, fb = m, fm
            else:
                a, fa = m, fm
        return mp.findroot(lambda s: fun(s, self(s)), (a, b), solver="secant", tol=mpf(10) ** (-2 * mp.dps + 8))


# ----------------------------------------------------------------------------------------------
# Lagrange's equations in minimal coordinates (sympy) -> mpmath right-hand side
# ----------------------------------------------------------------------------------------------


def lagrange_rhs(lagrangian, q, qd):
    """y' = f(t, y), y = [q..., qd...], from a sympy Lagrangian L(q, qd) (no explicit t).

    d/dt ∂L/∂q̇ − ∂L/∂q = 0  ->  M q̈ = ∂L/∂q − (∂²L/∂q̇∂q) q̇."""
    import sympy as sp

    n = len(q)
    Lq = [sp.diff(lagrangian, v) for v in q]
    Lqd = [sp.diff(lagrangian, v) for v in qd]
    M = sp.Matrix(n, n, lambda i, j: sp.diff(Lqd[i], qd[j]))
    rhs = sp.Matrix(n, 1, lambda i, _j: Lq[i] - sum(sp.diff(Lqd[i], q[j]) * qd[j] for j in range(n)))
    Mf = sp.lambdify([*q, *qd], M, modules="mpmath")
    rf = sp.lambdify([*q, *qd], rhs, modules="mpmath")

    def f(_t, y):
        Mm = mp.matrix(Mf(*y))
        r = mp.matrix(rf(*y))
        qdd = mp.lu_solve(Mm, r)
        return list(y[n:]) + [qdd[i] for i in range(n)]

    return f


# ----------------------------------------------------------------------------------------------
# Newton-Euler of planar free-body diagrams with the joint forces as unknowns
# ----------------------------------------------------------------------------------------------


def cross2(r, F):
    return r[0] * F[1] - r[1] * F[0]


def newton_euler(bodies, unknowns, g):
    """Solve the free-body diagrams for the unknown joint forces.

    bodies: {name: {m, I, x: centre, a: centre acceleration, alpha}} (gravity −g e2 added);
    unknowns: [(name, [(body, point, force per unit, couple per unit), ...]), ...].
    One equation per force component and one moment equation about the centre per body; the
    system must be square (a determinate mechanism)."""
    names = list(bodies)
    rows = 3 * len(names)
    assert rows == len(unknowns), (rows, len(unknowns))
    A = mp.zeros(rows, rows)
    b = mp.zeros(rows, 1)
    for i, nm in enumerate(names):
        bd = bodies[nm]
        b[3 * i] = bd["m"] * bd["a"][0]
        b[3 * i + 1] = bd["m"] * bd["a"][1] + bd["m"] * g
        b[3 * i + 2] = bd["I"] * bd["alpha"]
    for k, (_nm, parts) in enumerate(unknowns):
        for body, point, force, couple in parts:
            if body == "ground":
                continue
            i = names.index(body)
            x = bodies[body]["x"]
            A[3 * i, k] += force[0]
            A[3 * i + 1, k] += force[1]
            A[3 * i + 2, k] += cross2((point[0] - x[0], point[1] - x[1]), force) + couple
    sol = mp.lu_solve(A, b)
    return {nm: sol[k] for k, (nm, _p) in enumerate(unknowns)}


def pin_unknowns(name, P_body, Q_body, point):
    """R = [R1, R2]: force on P_body by Q_body at `point` (and −R on Q_body)."""
    e1, e2 = (1, 0), (-1, 0)
    f1, f2 = (0, 1), (0, -1)
    return [(name + ".0", [(P_body, point, e1, 0), (Q_body, point, e2, 0)]),
            (name + ".1", [(P_body, point, f1, 0), (Q_body, point, f2, 0)])]


# ----------------------------------------------------------------------------------------------
# helpers for result paths
# ----------------------------------------------------------------------------------------------


def vec(c1, c2):
    return [c1, c2, mpf(0)]


def put(out, prefix, value):
    """out[prefix.i...] = value, flattening lists (vectors, tensions)."""
    if isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            put(out, f"{prefix}.{i}", v)
    else:
        out[prefix] = value


def family(path):
    """The quantity a path belongs to (its numeric parts and a leading `find` removed): the values
    at the requested times and at the find answers share one scale."""
    parts = [p for p in path.split(".") if not re.fullmatch(r"\d+", p)]
    if parts[0] == "find" and parts[1:] != ["t"]:
        parts = parts[1:]
    return ".".join(parts)


# ----------------------------------------------------------------------------------------------
# 1. compound pendulum: uniform rod pinned at end1, released from rest
# ----------------------------------------------------------------------------------------------


def compound_pendulum_state(m, L, th0, g, t):
    """Exact state at t (Jacobi elliptic functions): φ = θ + π/2 from the downward vertical,
    sin(φ/2) = k sn(K − ω_n t | k²), k = sin(φ0/2), ω_n² = 3g/(2L)."""
    wn = mp.sqrt(3 * g / (2 * L))
    phi0 = th0 + mp.pi / 2
    k = mp.sin(phi0 / 2)
    K = mp.ellipk(k**2)
    u = K - wn * t
    sn, cn = mp.ellipfun("sn", u, m=k**2), mp.ellipfun("cn", u, m=k**2)
    phi = 2 * mp.asin(k * sn)
    phid = -2 * k * wn * cn
    phidd = -wn**2 * mp.sin(phi)
    return rod_pinned_state(m, L, phi - mp.pi / 2, phid, phidd, g)


def rod_pinned_state(m, L, th, w, al, g):
    """Centre kinematics and pin force of a rod turning about its end1 at the origin."""
    c, s = mp.cos(th), mp.sin(th)
    x = vec(L / 2 * c, L / 2 * s)
    v = vec(-w * L / 2 * s, w * L / 2 * c)
    a = vec(-al * L / 2 * s - w**2 * L / 2 * c, al * L / 2 * c - w**2 * L / 2 * s)
    R = vec(m * a[0], m * a[1] + m * g)                       # m a = R − m g e2
    T = m * (v[0] ** 2 + v[1] ** 2) / 2 + m * L**2 / 24 * w**2
    V = m * g * x[1]
    return {"angle": th, "omega": w, "alpha": al, "x": x, "v": v, "a": a, "R": R, "T": T, "V": V}


def compound_pendulum_case(m, L, th0, at, g=G, upright=False):
    """Reference mapping for problems/scenes/compound-pendulum.yaml (and its near-upright
    variant, `upright=True`: find = [angle 0 reached, angle −π/2 reached])."""
    with mp.workdps(30):
        m, L, th0, g = mpf(m), mpf(L), mpf(th0), mpf(g)
        out = {}
        for i, t in enumerate(at):
            s = compound_pendulum_state(m, L, th0, g, mpf(t))
            _store_rod(out, s, f"{i}")
        wn = mp.sqrt(3 * g / (2 * L))
        phi0 = th0 + mp.pi / 2
        k = mp.sin(phi0 / 2)
        K = mp.ellipk(k**2)
        if upright:
            # θ = 0 (horizontal): sin(π/4) = k sn(u)  ->  u = F(asin(sin(π/4)/k) | k²), t = (K − u)/ω_n
            u = mp.ellipf(mp.asin(mp.sin(mp.pi / 4) / k), k**2)
            times = [(K - u) / wn, K / wn]
        else:
            times = [K / wn, 2 * K / wn, 3 * K / wn, 4 * K / wn]   # T/4, T/2 (lowest), 3T/4, T (highest)
        for j, t in enumerate(times):
            s = compound_pendulum_state(m, L, th0, g, t)
            out[f"find.{j}.t"] = t
            _store_rod(out, s, None, prefix=f"find.{j}.")
        out["_period"] = 4 * K / wn
        return out


def _store_rod(out, s, idx, prefix="", body="bar", joint="pivot"):
    sfx = f".{idx}" if idx is not None else ""
    out[f"{prefix}angle.{body}{sfx}"] = s["angle"]
    put(out, f"{prefix}omega.{body}{sfx}", vec(0, 0)[:2] + [s["omega"]])
    put(out, f"{prefix}alpha.{body}{sfx}", vec(0, 0)[:2] + [s["alpha"]])
    put(out, f"{prefix}x.{body}{sfx}", s["x"])
    put(out, f"{prefix}v.{body}{sfx}", s["v"])
    put(out, f"{prefix}a.{body}{sfx}", s["a"])
    put(out, f"{prefix}reaction.{joint}.R{sfx}", s["R"])
    out[f"{prefix}T{sfx}"] = s["T"]
    out[f"{prefix}V{sfx}"] = s["V"]


def compound_pendulum_release(m, L, th0, g=G):
    """Closed forms at release (ω = 0): α = −(3g/2L) cos θ0, R = m α (L/2)(−sin θ0, cos θ0) + m g e2."""
    with mp.workdps(30):
        m, L, th0, g = mpf(m), mpf(L), mpf(th0), mpf(g)
        al = -3 * g / (2 * L) * mp.cos(th0)
        R = vec(-m * al * L / 2 * mp.sin(th0), m * al * L / 2 * mp.cos(th0) + m * g)
        return al, R


def compound_pendulum_bottom(m, L, th0, g=G):
    """At the bottom: ω² = 3g(1 − cos φ0)/L, α = 0, R = m g (5 − 3 cos φ0)/2 e2."""
    with mp.workdps(30):
        m, L, th0, g = mpf(m), mpf(L), mpf(th0), mpf(g)
        phi0 = th0 + mp.pi / 2
        return -mp.sqrt(3 * g * (1 - mp.cos(phi0)) / L), m * g * (5 - 3 * mp.cos(phi0)) / 2


# ----------------------------------------------------------------------------------------------
# 2. falling rod on a smooth floor
# ----------------------------------------------------------------------------------------------


def _rod_beta_rhs(L, g):
    # M(β) β̈ + ½ M'(β) β̇² = m g (L/2) sin β,  M = m L² (1/12 + sin²β/4)   (m cancels)
    def f(_t, y):
        b, bd = y
        s, c = mp.sin(b), mp.cos(b)
        return [bd, (g * L / 2 * s - L**2 / 4 * s * c * bd**2) / (L**2 / 12 + L**2 / 4 * s**2)]
    return f


def falling_rod_state(m, L, b0, g, b, bd, bdd=None):
    """State of the rod at angle β from the vertical (end1 on the floor, leaning towards +e1)."""
    s, c = mp.sin(b), mp.cos(b)
    if bdd is None:
        bdd = (g * L / 2 * s - L**2 / 4 * s * c * bd**2) / (L**2 / 12 + L**2 / 4 * s**2)
    x = vec(L / 2 * mp.sin(b0), L / 2 * c)
    v = vec(mpf(0), -L / 2 * s * bd)
    a = vec(mpf(0), -L / 2 * (c * bd**2 + s * bdd))
    N = m * (g + a[1])                                        # m ÿ = N − m g; no horizontal force
    T = m * v[1] ** 2 / 2 + m * L**2 / 24 * bd**2
    return {"angle": mp.pi / 2 - b, "omega": -bd, "alpha": -bdd, "x": x, "v": v, "a": a, "N": N,
            "T": T, "V": m * g * x[1]}


def falling_rod_speed(L, b0, g, b):
    """β̇ from energy: β̇² = 12 g (cos β0 − cos β) / (L (1 + 3 sin²β))."""
    return mp.sqrt(12 * g * (mp.cos(b0) - mp.cos(b)) / (L * (1 + 3 * mp.sin(b) ** 2)))


def falling_rod_time(L, b0, g, b1):
    """t(β1) = ∫ dβ/β̇ from β0 (energy quadrature; β = β0 + s² removes the end singularity)."""
    # cos β0 − cos β = 2 sin(β0 + s²/2) sin(s²/2): 2s/β̇ stays finite (and exact) as s -> 0
    def integrand(s):
        b = b0 + s**2
        return 2 / mp.sqrt(12 * g * mp.sin(b0 + s**2 / 2) * mp.sinc(s**2 / 2) / (L * (1 + 3 * mp.sin(b) ** 2)))
    return mp.quad(integrand, [0, mp.sqrt(b1 - b0)])


def falling_rod_case(m, L, b0, at, find_angle, g=G, route="ode"):
    with mp.workdps(30):
        m, L, b0, g = mpf(m), mpf(L), mpf(b0), mpf(g)
        f = _rod_beta_rhs(L, g)
        out = {}

        def store(s, sfx, prefix=""):
            out[f"{prefix}angle.rod{sfx}"] = s["angle"]
            put(out, f"{prefix}omega.rod{sfx}", [mpf(0), mpf(0), s["omega"]])
            put(out, f"{prefix}alpha.rod{sfx}", [mpf(0), mpf(0), s["alpha"]])
            put(out, f"{prefix}x.rod{sfx}", s["x"])
            put(out, f"{prefix}v.rod{sfx}", s["v"])
            put(out, f"{prefix}a.rod{sfx}", s["a"])
            out[f"{prefix}reaction.tip.N{sfx}"] = s["N"]
            out[f"{prefix}reaction.tip.F{sfx}"] = mpf(0)
            out[f"{prefix}T{sfx}"] = s["T"]
            out[f"{prefix}V{sfx}"] = s["V"]

        for i, t in enumerate(at):
            t = mpf(t)
            if route == "ode":
                b, bd = integrate(f, 0, [b0, 0], t)
            else:                                              # invert the quadrature
                b = mp.findroot(lambda bb: falling_rod_time(L, b0, g, bb) - t, b0 + mpf("0.5") * t**2) if t else b0
                bd = falling_rod_speed(L, b0, g, b)
            store(falling_rod_state(m, L, b0, g, b, bd), f".{i}")
        b1 = mp.pi / 2 - mpf(find_angle)
        out["find.0.t"] = falling_rod_time(L, b0, g, b1)
        store(falling_rod_state(m, L, b0, g, b1, falling_rod_speed(L, b0, g, b1)), "", "find.0.")
        return out


def falling_rod_release(m, L, b0, g=G):
    """β̈0 = 6 g sin β0 / (L (1 + 3 sin²β0)),  N0 = m g / (1 + 3 sin²β0)."""
    with mp.workdps(30):
        m, L, b0, g = mpf(m), mpf(L), mpf(b0), mpf(g)
        s = mp.sin(b0)
        return 6 * g * s / (L * (1 + 3 * s**2)), m * g / (1 + 3 * s**2)


# ----------------------------------------------------------------------------------------------
# 3. yo-yo
# ----------------------------------------------------------------------------------------------


def yoyo_case(m, R, r, x0, y0, at, y_find, g=G):
    """a = g/(1 + I/(m r²)), T = m g I/(I + m r²), I = m R²/2; the centre falls, the disk turns
    clockwise with ẏ = r ω (the cord leaves the hub's left side)."""
    with mp.workdps(30):
        m, R, r, x0, y0, g = (mpf(v) for v in (m, R, r, x0, y0, g))
        I = m * R**2 / 2
        a = g / (1 + I / (m * r**2))
        T = m * g * I / (I + m * r**2)
        out = {}

        def store(t, sfx, prefix=""):
            put(out, f"{prefix}x.yoyo{sfx}", vec(x0, y0 - a * t**2 / 2))
            put(out, f"{prefix}v.yoyo{sfx}", vec(mpf(0), -a * t))
            put(out, f"{prefix}a.yoyo{sfx}", vec(mpf(0), -a))
            put(out, f"{prefix}omega.yoyo{sfx}", [mpf(0), mpf(0), -a * t / r])
            put(out, f"{prefix}alpha.yoyo{sfx}", [mpf(0), mpf(0), -a / r])
            put(out, f"{prefix}reaction.string.T{sfx}", [T])
            out[f"{prefix}T{sfx}"] = (m * (a * t) ** 2 + I * (a * t / r) ** 2) / 2

        for i, t in enumerate(at):
            store(mpf(t), f".{i}")
        tf = mp.sqrt(2 * (y0 - mpf(y_find)) / a)
        out["find.0.t"] = tf
        store(tf, "", "find.0.")
        return out, a, T


# ----------------------------------------------------------------------------------------------
# 4. double pendulum (two point masses on two massless links)
# ----------------------------------------------------------------------------------------------


def double_pendulum_rhs(m1, m2, L1, L2, g):
    """Lagrange's equations in the link angles φ1, φ2 from −e2 (sympy)."""
    import sympy as sp

    p1, p2, w1, w2 = sp.symbols("p1 p2 w1 w2")
    xA = sp.Matrix([L1 * sp.sin(p1), -L1 * sp.cos(p1)])
    xB = xA + sp.Matrix([L2 * sp.sin(p2), -L2 * sp.cos(p2)])
    q, qd = [p1, p2], [w1, w2]
    vA = xA.jacobian(q) * sp.Matrix(qd)
    vB = xB.jacobian(q) * sp.Matrix(qd)
    T = (m1 * vA.dot(vA) + m2 * vB.dot(vB)) / 2
    V = m1 * g * xA[1] + m2 * g * xB[1]
    return lagrange_rhs(T - V, q, qd)


def double_pendulum_state(m1, m2, L1, L2, g, f, y):
    p1, p2, w1, w2 = y
    _, _, a1, a2 = f(0, y)
    u1 = (mp.sin(p1), -mp.cos(p1))
    u2 = (mp.sin(p2), -mp.cos(p2))
    n1 = (mp.cos(p1), mp.sin(p1))                       # d u/dφ
    n2 = (mp.cos(p2), mp.sin(p2))
    xA = [L1 * u1[0], L1 * u1[1]]
    xB = [xA[0] + L2 * u2[0], xA[1] + L2 * u2[1]]
    vA = [L1 * w1 * n1[0], L1 * w1 * n1[1]]
    vB = [vA[0] + L2 * w2 * n2[0], vA[1] + L2 * w2 * n2[1]]
    aA = [L1 * (a1 * n1[k] - w1**2 * u1[k]) for k in (0, 1)]
    aB = [aA[k] + L2 * (a2 * n2[k] - w2**2 * u2[k]) for k in (0, 1)]
    # second formulation, Newton on each mass: the link pulls B towards A with T2, A towards the
    # pivot with T1 and towards B with T2:  m2 aB = −T2 u2 − m2 g e2,  m1 aA = −T1 u1 + T2 u2 − m1 g e2
    T2 = -(u2[0] * m2 * aB[0] + u2[1] * (m2 * aB[1] + m2 * g))
    T1 = -(u1[0] * (m1 * aA[0] - T2 * u2[0]) + u1[1] * (m1 * aA[1] + m1 * g - T2 * u2[1]))
    T = (m1 * (vA[0] ** 2 + vA[1] ** 2) + m2 * (vB[0] ** 2 + vB[1] ** 2)) / 2
    V = g * (m1 * xA[1] + m2 * xB[1])
    return {"x.A": vec(*xA), "x.B": vec(*xB), "v.A": vec(*vA), "v.B": vec(*vB), "a.A": vec(*aA),
            "a.B": vec(*aB), "reaction.upper.T": T1, "reaction.lower.T": T2, "T": T, "V": V,
            "_phi": (p1, p2)}


def double_pendulum_case(m1, m2, L1, L2, p1, p2, at, t_end, g=G):
    """at-times, and find.0: the first time x.A.1 = 0 (A passes under the pivot)."""
    with mp.workdps(30):
        m1, m2, L1, L2, g = (mpf(v) for v in (m1, m2, L1, L2, g))
        f = double_pendulum_rhs(m1, m2, L1, L2, g)
        traj = Trajectory(f, [mpf(p1), mpf(p2), 0, 0], t_end)
        out = {}

        def store(y, sfx, prefix=""):
            s = double_pendulum_state(m1, m2, L1, L2, g, f, y)
            for k, v in s.items():
                if not k.startswith("_"):
                    put(out, f"{prefix}{k}{sfx}", v)
            return s

        for i, t in enumerate(at):
            store(traj(t), f".{i}")
        # first sign change of sin φ1 on a grid of 0.05 s, then the root
        t_lo = next(k * traj.grid for k in range(len(traj.states) - 1)
                    if mp.sin(traj.states[k][0]) * mp.sin(traj.states[k + 1][0]) <= 0)
        tf = traj.root(lambda _t, y: mp.sin(y[0]), t_lo, t_lo + traj.grid)
        out["find.0.t"] = tf
        store(traj(tf), "", "find.0.")
        return out, traj


# ----------------------------------------------------------------------------------------------
# 5. pendulum on a spring-held cart
# ----------------------------------------------------------------------------------------------


def cart_pendulum_rhs(M, m, l, k, L0, xw, hook, g):
    """Lagrange's equations in (x, φ): x the cart centre's e1 coordinate, φ the link's angle
    from −e2; the link hangs from the cart point `hook` (offset from the centre, the cart keeps
    its angle), the spring joins the cart's centre to the wall point at the same height."""
    import sympy as sp

    x, p, xd, pd = sp.symbols("x p xd pd")
    bob = sp.Matrix([x + hook[0] + l * sp.sin(p), hook[1] - l * sp.cos(p)])
    vb = bob.jacobian([x, p]) * sp.Matrix([xd, pd])
    T = M * xd**2 / 2 + m * vb.dot(vb) / 2
    V = k * (x - xw - L0) ** 2 / 2 + m * g * bob[1]
    return lagrange_rhs(T - V, [x, p], [xd, pd])


def cart_pendulum_state(M, m, l, k, L0, xw, y0, hook, g, f, y):
    x, p, xd, pd = y
    _, _, xdd, pdd = f(0, y)
    u = (mp.sin(p), -mp.cos(p))
    n = (mp.cos(p), mp.sin(p))
    piv = (x + hook[0], y0 + hook[1])
    xb = [piv[0] + l * u[0], piv[1] + l * u[1]]
    vb = [xd + l * pd * n[0], l * pd * n[1]]
    ab = [xdd + l * (pdd * n[0] - pd**2 * u[0]), l * (pdd * n[1] - pd**2 * u[1])]
    # bob: m ab = −T u − m g e2
    T = -(u[0] * m * ab[0] + u[1] * (m * ab[1] + m * g))
    # cart: M a = N e2 − k(ℓ − L0) e1 + T u − M g e2 (vertical: 0); moments about the centre:
    # 0 = Ms + hook × (T u)
    N = M * g - T * u[1]
    Ms = -cross2(hook, (T * u[0], T * u[1]))
    spring = k * (x - xw - L0)
    assert abs(M * xdd - (-spring + T * u[0])) < mpf(10) ** (-mp.dps + 8)   # cart's e1 balance
    KE = (M * xd**2 + m * (vb[0] ** 2 + vb[1] ** 2)) / 2
    V = k * (x - xw - L0) ** 2 / 2 + g * (M * y0 + m * xb[1])
    return {"x.cart": vec(x, y0), "v.cart": vec(xd, mpf(0)), "a.cart": vec(xdd, mpf(0)),
            "x.bob": vec(*xb), "v.bob": vec(*vb), "a.bob": vec(*ab), "reaction.hanger.T": T,
            "reaction.rail.N": N, "reaction.rail.M": [mpf(0), mpf(0), Ms], "force.spring": spring,
            "T": KE, "V": V, "angle.cart": mpf(0)}


def cart_pendulum_case(M, m, l, k, L0, xw, x0, y0, hook, p0, at, t_end, g=G):
    """at-times, and find.0: the cart's first turning point {min: x.cart.0} (the lowest x1)."""
    with mp.workdps(30):
        M, m, l, k, L0, xw, x0, y0, g = (mpf(v) for v in (M, m, l, k, L0, xw, x0, y0, g))
        hook = (mpf(hook[0]), mpf(hook[1]))
        f = cart_pendulum_rhs(M, m, l, k, L0, xw, hook, g)
        traj = Trajectory(f, [x0, mpf(p0), 0, 0], t_end)
        out = {}

        def store(y, sfx, prefix=""):
            s = cart_pendulum_state(M, m, l, k, L0, xw, y0, hook, g, f, y)
            for key, v in s.items():
                put(out, f"{prefix}{key}{sfx}", v)

        for i, t in enumerate(at):
            store(traj(t), f".{i}")
        # cart velocity: negative first (the spring pulls towards the wall); first zero after t=0
        ks = [j for j in range(1, len(traj.states) - 1) if traj.states[j][2] * traj.states[j + 1][2] <= 0]
        tf = traj.root(lambda _t, y: y[2], ks[0] * traj.grid, (ks[0] + 1) * traj.grid)
        out["find.0.t"] = tf
        store(traj(tf), "", "find.0.")
        return out, traj


# ----------------------------------------------------------------------------------------------
# 6. slider-crank (0 DOF, crank driven at constant speed)
# ----------------------------------------------------------------------------------------------


def slider_crank_kinematics(r, l, w, t):
    """θ = ω t; x_B = r cos θ + sqrt(l² − r² sin²θ); φ = −asin(r sin θ / l); derivatives by sympy."""
    import sympy as sp

    ts, rs, ls, ws = sp.symbols("t r l w", positive=True)
    th = ws * ts
    A = sp.Matrix([rs * sp.cos(th), rs * sp.sin(th)])
    phi = -sp.asin(rs * sp.sin(th) / ls)
    xB = rs * sp.cos(th) + sp.sqrt(ls**2 - rs**2 * sp.sin(th) ** 2)
    crank = A / 2
    rod = A + ls / 2 * sp.Matrix([sp.cos(phi), sp.sin(phi)])
    subs = {rs: r, ls: l, ws: w}
    ev = {}
    for name, expr in (("crank", crank), ("conrod", rod), ("slider", sp.Matrix([xB, 0]))):
        for d, key in ((0, "x"), (1, "v"), (2, "a")):
            e = expr.diff(ts, d) if d else expr
            fn = sp.lambdify([ts], e.subs(subs), modules="mpmath")
            ev[f"{key}.{name}"] = [mpf(c) for c in fn(t)]
    for name, ang in (("crank", th), ("conrod", phi), ("slider", sp.Integer(0))):
        for d, key in ((0, "angle"), (1, "omega"), (2, "alpha")):
            e = ang.diff(ts, d) if d else ang
            ev[f"{key}.{name}"] = mpf(sp.lambdify([ts], e.subs(subs), modules="mpmath")(t))
    return ev


def slider_crank_forces(r, l, w, m1, m2, m3, size, t, g, kin=None):
    """Pin forces, slider N and couple, drive couple by Newton-Euler of the three bodies."""
    kin = kin or slider_crank_kinematics(r, l, w, t)
    bodies = {
        "crank": {"m": m1, "I": m1 * r**2 / 12},
        "conrod": {"m": m2, "I": m2 * l**2 / 12},
        "slider": {"m": m3, "I": m3 * (size[0] ** 2 + size[1] ** 2) / 12},
    }
    for nm, b in bodies.items():
        b.update(x=kin[f"x.{nm}"], a=kin[f"a.{nm}"], alpha=kin[f"alpha.{nm}"])
    th = kin["angle.crank"]
    A = (r * mp.cos(th), r * mp.sin(th))
    B = tuple(kin["x.slider"][:2])
    unknowns = (pin_unknowns("main", "crank", "ground", (0, 0))
                + pin_unknowns("crankpin", "conrod", "crank", A)
                + pin_unknowns("wrist", "conrod", "slider", B)
                + [("guide.N", [("slider", B, (0, 1), 0)]),
                   ("guide.M", [("slider", B, (0, 0), 1)]),
                   ("motor", [("crank", (0, 0), (0, 0), 1)])])
    return newton_euler(bodies, unknowns, g)


def energy_rate(bodies, g):
    """dT/dt + dV/dt = Σ m v·(a + g e2) + I ω α."""
    return sum(b["m"] * (b["v"][0] * b["a"][0] + b["v"][1] * (b["a"][1] + g)) + b["I"] * b["omega"] * b["alpha"]
               for b in bodies.values())


def slider_crank_case(r, l, w, m1, m2, m3, size, at, find_angle, g=G):
    with mp.workdps(30):
        r, l, w, m1, m2, m3, g = (mpf(v) for v in (r, l, w, m1, m2, m3, g))
        size = (mpf(size[0]), mpf(size[1]))
        out = {}

        def store(t, sfx, prefix=""):
            kin = slider_crank_kinematics(r, l, w, t)
            F = slider_crank_forces(r, l, w, m1, m2, m3, size, t, g, kin)
            for nm in ("crank", "conrod", "slider"):
                for key in ("x", "v", "a"):
                    put(out, f"{prefix}{key}.{nm}{sfx}", vec(*kin[f"{key}.{nm}"][:2]))
                out[f"{prefix}angle.{nm}{sfx}"] = kin[f"angle.{nm}"]
                put(out, f"{prefix}omega.{nm}{sfx}", [mpf(0), mpf(0), kin[f"omega.{nm}"]])
                put(out, f"{prefix}alpha.{nm}{sfx}", [mpf(0), mpf(0), kin[f"alpha.{nm}"]])
            for j in ("main", "crankpin", "wrist"):
                put(out, f"{prefix}reaction.{j}.R{sfx}", vec(F[j + ".0"], F[j + ".1"]))
            out[f"{prefix}reaction.guide.N{sfx}"] = F["guide.N"]
            put(out, f"{prefix}reaction.guide.M{sfx}", [mpf(0), mpf(0), F["guide.M"]])
            out[f"{prefix}drive.motor{sfx}"] = F["motor"]
            return kin, F

        for i, t in enumerate(at):
            store(mpf(t), f".{i}")
        t1 = mpf(find_angle) / w
        out["find.0.t"] = t1
        store(t1, "", "find.0.")
        t2 = mp.pi / w                                         # slider's lowest x1: θ = π
        out["find.1.t"] = t2
        store(t2, "", "find.1.")
        return out


# ----------------------------------------------------------------------------------------------
# 7. four-bar (crank driven at constant speed)
# ----------------------------------------------------------------------------------------------


def four_bar_angles(a, b, c, d, th2, guess):
    """Loop closure a e(θ2) + b e(θ3) = d e1 + c e(θ4) by findroot from `guess` (θ3, θ4)."""
    def F(t3, t4):
        return [a * mp.cos(th2) + b * mp.cos(t3) - d - c * mp.cos(t4),
                a * mp.sin(th2) + b * mp.sin(t3) - c * mp.sin(t4)]
    t3, t4 = mp.findroot(F, guess, tol=mpf(10) ** (-2 * mp.dps + 6))
    return t3, t4


def four_bar_rates(a, b, c, th, w2, al2=0):
    """θ̇3, θ̇4 and θ̈3, θ̈4 from the differentiated loop (2×2 linear systems)."""
    th2, th3, th4 = th
    Amat = mp.matrix([[-b * mp.sin(th3), c * mp.sin(th4)], [b * mp.cos(th3), -c * mp.cos(th4)]])
    rhs = mp.matrix([a * w2 * mp.sin(th2), -a * w2 * mp.cos(th2)])
    w3, w4 = mp.lu_solve(Amat, rhs)
    cen = a * w2**2 * mp.cos(th2) + b * w3**2 * mp.cos(th3) - c * w4**2 * mp.cos(th4)
    sen = a * w2**2 * mp.sin(th2) + b * w3**2 * mp.sin(th3) - c * w4**2 * mp.sin(th4)
    rhs2 = mp.matrix([a * al2 * mp.sin(th2) + cen, -a * al2 * mp.cos(th2) + sen])
    a3, a4 = mp.lu_solve(Amat, rhs2)
    return (w3, w4), (a3, a4)


def _rod_centre(base, L, th, w, al):
    c, s = mp.cos(th), mp.sin(th)
    x = (base[0] + L / 2 * c, base[1] + L / 2 * s)
    v = (base[2] - w * L / 2 * s, base[3] + w * L / 2 * c)
    acc = (base[4] - al * L / 2 * s - w**2 * L / 2 * c, base[5] + al * L / 2 * c - w**2 * L / 2 * s)
    return x, v, acc


def four_bar_state(a, b, c, d, w, th20, masses, g, t, guess):
    m2, m3, m4 = masses
    th2 = th20 + w * t
    th3, th4 = four_bar_angles(a, b, c, d, th2, guess)
    (w3, w4), (a3, a4) = four_bar_rates(a, b, c, (th2, th3, th4), w)
    z = mpf(0)
    xc, vc, ac = _rod_centre((z, z, z, z, z, z), a, th2, w, z)
    Ax = (a * mp.cos(th2), a * mp.sin(th2))
    Av = (-a * w * mp.sin(th2), a * w * mp.cos(th2))
    Aa = (-a * w**2 * mp.cos(th2), -a * w**2 * mp.sin(th2))
    xb, vb, ab = _rod_centre((Ax[0], Ax[1], Av[0], Av[1], Aa[0], Aa[1]), b, th3, w3, a3)
    xr, vr, ar = _rod_centre((d, z, z, z, z, z), c, th4, w4, a4)
    bodies = {
        "crank": {"m": m2, "I": m2 * a**2 / 12, "x": xc, "v": vc, "a": ac, "omega": w, "alpha": z},
        "coupler": {"m": m3, "I": m3 * b**2 / 12, "x": xb, "v": vb, "a": ab, "omega": w3, "alpha": a3},
        "rocker": {"m": m4, "I": m4 * c**2 / 12, "x": xr, "v": vr, "a": ar, "omega": w4, "alpha": a4},
    }
    B = (d + c * mp.cos(th4), c * mp.sin(th4))
    unknowns = (pin_unknowns("O2", "crank", "ground", (0, 0))
                + pin_unknowns("A", "coupler", "crank", Ax)
                + pin_unknowns("B", "coupler", "rocker", B)
                + pin_unknowns("O4", "rocker", "ground", (d, 0))
                + [("motor", [("crank", (0, 0), (0, 0), 1)])])
    F = newton_euler(bodies, unknowns, g)
    power = energy_rate(bodies, g)                             # virtual power: τ ω = dT/dt + dV/dt
    return {"angles": (th2, th3, th4), "rates": (w, w3, w4), "acc": (z, a3, a4), "bodies": bodies,
            "F": F, "tau_power": power / w}


def four_bar_case(a, b, c, d, w, th20, masses, at, guess0, g=G):
    """at-times; find.0 {max: angle.rocker}, find.1 {min: angle.rocker} (the rocker's limit
    positions: crank and coupler collinear, found here as the zeros of θ̇4 by findroot).

    guess0: (θ3, θ4) of the file's sketch at t = 0; the branch is continued from there."""
    with mp.workdps(30):
        a, b, c, d, w, th20, g = (mpf(v) for v in (a, b, c, d, w, th20, g))
        masses = tuple(mpf(v) for v in masses)
        guess0 = tuple(mpf(v) for v in guess0)
        out = {}
        period = 2 * mp.pi / w
        n = 400                                                # crank steps of 0.9° per turn
        grid = [period * j / n for j in range(n + 1)]
        branch = [four_bar_angles(a, b, c, d, th20, guess0)]
        for t in grid[1:]:
            branch.append(four_bar_angles(a, b, c, d, th20 + w * t, branch[-1]))

        def angles(t):
            j = int(mp.floor((t % period) / period * n))
            return four_bar_angles(a, b, c, d, th20 + w * t, branch[j])

        def store(t, sfx, prefix=""):
            s = four_bar_state(a, b, c, d, w, th20, masses, g, t, angles(t))
            for k, nm in enumerate(("crank", "coupler", "rocker")):
                bd = s["bodies"][nm]
                out[f"{prefix}angle.{nm}{sfx}"] = s["angles"][k]
                put(out, f"{prefix}omega.{nm}{sfx}", [mpf(0), mpf(0), s["rates"][k]])
                put(out, f"{prefix}alpha.{nm}{sfx}", [mpf(0), mpf(0), s["acc"][k]])
                put(out, f"{prefix}x.{nm}{sfx}", vec(*bd["x"]))
                put(out, f"{prefix}v.{nm}{sfx}", vec(*bd["v"]))
                put(out, f"{prefix}a.{nm}{sfx}", vec(*bd["a"]))
            for j in ("O2", "A", "B", "O4"):
                put(out, f"{prefix}reaction.{j}.R{sfx}", vec(s["F"][j + ".0"], s["F"][j + ".1"]))
            out[f"{prefix}drive.motor{sfx}"] = s["F"]["motor"]
            assert abs(s["F"]["motor"] - s["tau_power"]) < mpf(10) ** (-20) * (1 + abs(s["tau_power"]))
            return s

        for i, t in enumerate(at):
            store(mpf(t), f".{i}")

        def w4(t):
            th = angles(t)
            return four_bar_rates(a, b, c, (th20 + w * t, th[0], th[1]), w)[0][1]

        vals = [w4(t) for t in grid]
        zeros = [mp.findroot(w4, (grid[j], grid[j + 1]), solver="anderson")
                 for j in range(n) if vals[j] * vals[j + 1] < 0]
        assert len(zeros) == 2, zeros
        th4s = [angles(t)[1] for t in zeros]
        order = [0, 1] if th4s[0] > th4s[1] else [1, 0]           # max first, then min
        for q, j in enumerate(order):
            out[f"find.{q}.t"] = zeros[j]
            store(zeros[j], "", f"find.{q}.")
        return out


def four_bar_limits(a, b, c, d, th20, w):
    """Closed form of the rocker's limit positions: crank and coupler collinear, |O2 B| = b ± a.

    Returns [(t, θ4), ...] for the extended (b + a) and the folded (b − a) position, t the first
    time after 0 at which the crank reaches that position."""
    with mp.workdps(30):
        a, b, c, d, th20, w = (mpf(v) for v in (a, b, c, d, th20, w))
        res = []
        for rho, flip in ((b + a, 0), (b - a, mp.pi)):
            # triangle O2 O4 B: angle of B at O2 and θ4 from the law of cosines (B above e1)
            psi = mp.acos((rho**2 + d**2 - c**2) / (2 * rho * d))
            th4 = mp.pi - mp.acos((c**2 + d**2 - rho**2) / (2 * c * d))
            th2 = psi + flip
            t = ((th2 - th20) % (2 * mp.pi)) / w
            res.append((t, th4))
        return res
