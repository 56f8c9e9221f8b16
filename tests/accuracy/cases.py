"""Problems with exact (50-digit mpmath) references, one per numerical route.

Shared by tests/accuracy/ (the error estimate is present and honest) and
benchmarks/work_precision.py (time, error, nfev against rtol).  Each case
builds its YAML for a given ``rtol`` (atol = rtol * ``atol_factor``) and
``estimate`` flag, and measures the largest absolute error of the solved
record against the reference.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import mpmath as mp

mp.mp.dps = 50


@dataclass
class Case:
    name: str             # e.g. "rectilinear quadrature + events"
    type: str             # problem type
    yaml: Callable[[float, float, bool], str]     # (rtol, atol, estimate) -> YAML text
    error: Callable[[dict], float]                # record -> largest absolute error vs the reference
    atol_factor: float = 1e-3
    scipy_baseline: Callable[[float, float], tuple[float, int]] | None = None   # (rtol, atol) -> (error, nfev)
    # the type reports error_estimate relative to this scale (euler: |ω0|);
    # None: absolute, in the units of the results
    estimate_scale: float | None = None

    def comparable(self, true_error: float) -> float:
        """The true error in the units of the type's error_estimate."""
        return true_error / self.estimate_scale if self.estimate_scale else true_error

    def text(self, rtol: float, estimate: bool = False) -> str:
        return self.yaml(rtol, rtol * self.atol_factor, estimate)


def _acc(rtol, atol, estimate, method="auto"):
    return f"accuracy: {{rtol: {rtol!r}, atol: {atol!r}, method: {method}, estimate: {'true' if estimate else 'false'}}}\n"


def _maxerr(pairs) -> float:
    return max(float(abs(mp.mpf(got) - ref)) for got, ref in pairs)


def _relerr(quantities) -> float:
    """The largest error of every quantity relative to its own scale, the largest exact
    magnitude of that quantity over the answers (rectilinear's error_estimate: t as the time
    since t1 = 0, s, v); ``quantities``: one list of (got, exact) pairs per quantity."""
    return max(_maxerr(pairs) / float(max(abs(ref) for _, ref in pairs)) for pairs in quantities)


# --- rectilinear case 3 (a = -c v): quadrature of (6.8)/(6.10) and events ----------
C3 = mp.mpf("0.5")
V1 = mp.mpf(10)


def _rect3_yaml(rtol, atol, est):
    return ("type: rectilinear\na: '-0.5*v'\nv1: 10\n"
            "find: [{t: 2}, {t: 7}, {v: 1}, {s: 19}]\n" + _acc(rtol, atol, est, "quadrature"))


def _rect3_error(rec):
    f = rec["results"]["find"]
    v = lambda t: V1 * mp.exp(-C3 * t)              # noqa: E731
    s = lambda t: V1 / C3 * (1 - mp.exp(-C3 * t))   # noqa: E731
    t_v1 = mp.log(10) / C3
    t_s19 = -mp.log(1 - mp.mpf(19) * C3 / V1) / C3
    ts = [2, 7, t_v1, t_s19]
    return _relerr([[(f[k]["t"], t) for k, t in enumerate(ts)], [(f[k]["s"], s(t)) for k, t in enumerate(ts)],
                    [(f[k]["v"], v(t)) for k, t in enumerate(ts)]])


def _rect3_scipy(rtol, atol):
    """Plain scipy: t(v) = ∫ dv/a and s(v) = ∫ v dv/a with quad, the event by brentq."""
    from scipy.integrate import quad
    from scipy.optimize import brentq

    nfev = 0

    def a(v):
        nonlocal nfev
        nfev += 1
        return -0.5 * v

    def t_of(v):
        return quad(lambda u: 1 / a(u), 10, v, epsrel=rtol, epsabs=atol)[0]

    def s_of(v):
        return quad(lambda u: u / a(u), 10, v, epsrel=rtol, epsabs=atol)[0]

    find = []
    for T in (2.0, 7.0):
        vv = brentq(lambda v: t_of(v) - T, 1e-12, 10, xtol=atol, rtol=max(rtol, 4.5e-16))
        find.append({"t": T, "s": s_of(vv), "v": vv})
    find.append({"t": t_of(1.0), "s": s_of(1.0), "v": 1.0})
    v19 = brentq(lambda v: s_of(v) - 19, 1e-9, 10, xtol=atol, rtol=max(rtol, 4.5e-16))
    find.append({"t": t_of(v19), "s": 19.0, "v": v19})
    return _rect3_error({"results": {"find": find}}), nfev


# --- rectilinear general (ODE with events): a = -4 s - 0.4 v ------------------------
AL, S1, VV1 = mp.mpf("0.2"), mp.mpf("0.5"), mp.mpf(1)
WD = mp.sqrt(4 - AL ** 2)
BB = (VV1 + AL * S1) / WD


def _osc_s(t):
    return mp.exp(-AL * t) * (S1 * mp.cos(WD * t) + BB * mp.sin(WD * t))


def _osc_v(t):
    return mp.diff(_osc_s, t)


def _rectg_yaml(rtol, atol, est):
    return ("type: rectilinear\na: '-4*s - 0.4*v'\ns1: 0.5\nv1: 1\nt_max: 30\n"
            "find: [{t: 1}, {t: 3}, {t: 10}, {v: 0}, {s: -0.3}]\n" + _acc(rtol, atol, est, "DOP853"))


_T_V0 = None
_T_SM = None


def _rectg_times():
    """The exact times of the five answers: t = 1, 3, 10, the first v = 0, the first s = -0.3."""
    global _T_V0, _T_SM
    if _T_V0 is None:
        _T_V0 = mp.findroot(_osc_v, mp.mpf("0.39"))
        _T_SM = mp.findroot(lambda t: _osc_s(t) + mp.mpf("0.3"), mp.mpf("1.5"))
    return [mp.mpf(1), mp.mpf(3), mp.mpf(10), _T_V0, _T_SM]


def _rectg_error(rec):
    f = rec["results"]["find"]
    ts = _rectg_times()
    return _relerr([[(q["t"], t) for q, t in zip(f, ts)], [(q["s"], _osc_s(t)) for q, t in zip(f, ts)],
                    [(q["v"], _osc_v(t)) for q, t in zip(f, ts)]])


def _rectg_scipy(rtol, atol):
    from scipy.integrate import solve_ivp

    def rhs(t, y):
        return [y[1], -4 * y[0] - 0.4 * y[1]]

    ev_v = lambda t, y: y[1]          # noqa: E731
    ev_s = lambda t, y: y[0] + 0.3    # noqa: E731
    sol = solve_ivp(rhs, (0, 10), [0.5, 1.0], method="DOP853", rtol=rtol, atol=atol, dense_output=True,
                    events=[ev_v, ev_s])
    find = [{"t": t, "s": y[0], "v": y[1]} for t, y in zip((1, 3, 10), sol.sol([1, 3, 10]).T)]
    # plain sign-change event detection misses a crossing inside one long step
    # (at loose rtol the steps span the whole dip below s = -0.3): error = inf
    if not (len(sol.t_events[0]) and len(sol.t_events[1])):
        return float("inf"), int(sol.nfev)
    find.append({"t": sol.t_events[0][0], "s": sol.y_events[0][0][0], "v": 0.0})
    find.append({"t": sol.t_events[1][0], "s": -0.3, "v": sol.y_events[1][0][1]})
    return _rectg_error({"results": {"find": find}}), int(sol.nfev)


# --- particle: gravity + linear drag (exact exponential solution); the error of every reported
# quantity relative to its scale over the run, as the type's error_estimate ------------------
PK = mp.mpf("0.2")      # c/m
PM = mp.mpf("0.5")
G = mp.mpf("9.81")
PV0 = [mp.mpf(20), mp.mpf(0), mp.mpf(20)]
PT = [1, 2, 3]


def _part_exact(t):
    gv = [0, 0, -G]
    e = mp.exp(-PK * t)
    x = [gv[i] * t / PK + (PV0[i] - gv[i] / PK) * (1 - e) / PK for i in range(3)]
    v = [gv[i] / PK + (PV0[i] - gv[i] / PK) * e for i in range(3)]
    return x, v


def _part_all(t):
    """Every reported quantity of the exact motion: x, v, a = g − (c/m) v, T, V = m g x3, E,
    W_nc = E − E1 (the drag is the only non-conservative force), H_O = m x × v."""
    x, v = _part_exact(t)
    T = PM * sum(c * c for c in v) / 2
    V = PM * G * x[2]
    E1 = PM * sum(c * c for c in PV0) / 2
    H = [PM * (x[1] * v[2] - x[2] * v[1]), PM * (x[2] * v[0] - x[0] * v[2]), PM * (x[0] * v[1] - x[1] * v[0])]
    return {"x": x, "v": v, "a": [-PK * v[0], -PK * v[1], -G - PK * v[2]], "T": [T], "V": [V], "E": [T + V],
            "W_nc": [T + V - E1], "H_O": H}


def _part_yaml(rtol, atol, est):
    return ("type: particle\nm: 0.5\nx0: [0, 0, 0]\nv0: [20, 0, 20]\n"
            "forces: [{kind: gravity}, {kind: drag, c: 0.1, power: 1}]\nt_end: 3\nat: [1, 2, 3]\n"
            + _acc(rtol, atol, est))


def _part_error(rec):
    r = rec["results"]
    ref = [_part_all(t) for t in PT]
    errs = []
    for q in ref[0]:
        scale = max(abs(c) for row in ref for c in row[q])
        got = [r[q][i] if isinstance(r[q][i], list) else [r[q][i]] for i in range(len(PT))]
        errs.append(max(abs(mp.mpf(g) - c) for gi, row in zip(got, ref) for g, c in zip(gi, row[q])) / scale)
    return float(max(errs))


def _part_scipy(rtol, atol):
    from scipy.integrate import solve_ivp

    def rhs(t, y):
        return [y[3], y[4], y[5], -0.2 * y[3], -0.2 * y[4], -9.81 - 0.2 * y[5]]

    sol = solve_ivp(rhs, (0, 3), [0, 0, 0, 20, 0, 20], method="DOP853", rtol=rtol, atol=atol, t_eval=PT)
    errs = []
    for i, t in enumerate(PT):
        x, v = _part_exact(t)
        errs += [abs(sol.y[k][i] - float((x + v)[k])) for k in range(6)]
    return max(errs), int(sol.nfev)


# --- top: nutating top, 60-digit elliptic reference (tests/topics/top/gen_exact_reference.py); the error
# of every reported quantity relative to its scale over the run, as the type's error_estimate -----
def _nut_yaml(rtol, atol, est, method):
    from tests.topics.top.exact_reference_data import CASES as REF

    m, L, A, C, ps, th, ph, psd, thd, phd = REF["nutating"]["input"]
    return (f"type: top\nm: {m}\nL: {L}\nI11: {A}\nI33: {C}\npsi: {ps}\ntheta: {th}\nphi: {ph}\n"
            f"psi_dot: {psd}\ntheta_dot: {thd}\nphi_dot: {phd}\nat: {REF['nutating']['times']}\n"
            + _acc(rtol, atol, est, method))


def _nut_error(rec):
    from tests.topics.top.exact_reference_data import CASES as REF

    rows, r = REF["nutating"]["rows"], rec["results"]
    errs = []
    for k, name in enumerate(("psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot")):
        scale = max(abs(row[k]) for row in rows)
        errs.append(max(abs(a - row[k]) for a, row in zip(r[name], rows)) / scale)
    return max(errs)


# --- top: steady precession (slow root of 38.22): θ = θ0, ψ = Ω t, φ = p t -------------
TM, TL, TA, TC, TP = mp.mpf("0.5"), mp.mpf("0.05"), mp.mpf("2e-3"), mp.mpf("1e-3"), mp.mpf(150)
TTH = mp.pi / 6
TG = mp.mpf("9.81")
TT = [1, 2, 5]


def _top_yaml(rtol, atol, est):
    return ("type: top\nparams: {m: 0.5, L: 0.05, A: 2.0e-3, C: 1.0e-3, th: 'pi/6', p: 150, g: 9.81}\n"
            "m: m\nL: L\nI11: A\nI33: C\ntheta: th\n"
            "psi_dot: '2*m*g*L/(C*p + sqrt((C*p)**2 - 4*m*g*L*(A - C)*cos(th)))'\nphi_dot: p\nat: [1, 2, 5]\n"
            + _acc(rtol, atol, est, "DOP853"))


def _top_error(rec):
    # the ψ̇ actually used is the double-precision input value
    om = float(2 * TM * TG * TL / (TC * TP + mp.sqrt((TC * TP) ** 2 - 4 * TM * TG * TL * (TA - TC) * mp.cos(TTH))))
    om = mp.mpf(om)
    r = rec["results"]
    pairs = []
    for i, t in enumerate(TT):
        pairs += [(r["psi"][i], om * t), (r["theta"][i], mp.mpf(float(TTH))), (r["phi"][i], TP * t)]
    return _maxerr(pairs)


# --- vibration: DOP853 route against the exact underdamped response -------------------
VZ, VW = mp.mpf("0.1"), mp.mpf(2)
VWD = VW * mp.sqrt(1 - VZ ** 2)
VT = [1, 5, 20]


def _vib_x(t):
    return mp.exp(-VZ * VW * t) * (mp.cos(VWD * t) + VZ * VW / VWD * mp.sin(VWD * t))


def _vib_yaml(rtol, atol, est):
    return ("type: vibration\nm: 1\nk: 4\nzeta: 0.1\nx0: 1\nv0: 0\nat: [1, 5, 20]\n" + _acc(rtol, atol, est, "DOP853"))


def _vib_error(rec):
    r = rec["results"]
    return _maxerr([(r["x"][i], _vib_x(t)) for i, t in enumerate(VT)])


# --- kinematics: arc length of a helix by quadrature -------------------------------------
def _kin_yaml(rtol, atol, est):
    return ("type: kinematics\ncoordinates: cylindrical\nparams: {a: 2, c: 0.5, w: 3}\n"
            "position: {r: 'a*(1 + 0.3*sin(t))', theta: 'w*t', x3: 'c*w*t'}\nat: [0]\ndistance: [0, 2]\n"
            + _acc(rtol, atol, est))


_REFS: dict = {}


def _kin_ref():
    if "kin" not in _REFS:
        a, c, w = 2, mp.mpf("0.5"), 3

        def speed(t):
            r = a * (1 + mp.mpf("0.3") * mp.sin(t))
            rd = a * mp.mpf("0.3") * mp.cos(t)
            return mp.sqrt(rd ** 2 + (r * w) ** 2 + (c * w) ** 2)

        _REFS["kin"] = mp.quad(speed, [0, 1, 2])
    return _REFS["kin"]


def _kin_error(rec):
    return _maxerr([(rec["results"]["distance"], _kin_ref())])


# --- force field: work of a non-conservative field around an ellipse ---------------------
def _ff_yaml(rtol, atol, est):
    return ("type: force-field\nF: ['-x2*x3 + x1**2', 'x1*x3', 'x1*x2']\npoints: [[1, 1, 0]]\n"
            "path: {x1: '2*cos(t)', x2: 'sin(t)', x3: '0.1*t', t_span: [0, 5]}\n" + _acc(rtol, atol, est))


def _ff_ref():
    if "ff" not in _REFS:
        def integrand(t):
            x1, x2, x3 = 2 * mp.cos(t), mp.sin(t), mp.mpf("0.1") * t
            d1, d2, d3 = -2 * mp.sin(t), mp.cos(t), mp.mpf("0.1")
            return (-x2 * x3 + x1 ** 2) * d1 + x1 * x3 * d2 + x1 * x2 * d3

        _REFS["ff"] = mp.quad(integrand, [0, 1, 2, 3, 4, 5])
    return _REFS["ff"]


def _ff_error(rec):
    return _maxerr([(rec["results"]["work"], _ff_ref())])


CASES: list[Case] = [
    Case("rectilinear quadrature + events (case 3)", "rectilinear", _rect3_yaml, _rect3_error, scipy_baseline=_rect3_scipy,
         estimate_scale=1.0),
    Case("rectilinear ODE + events (general)", "rectilinear", _rectg_yaml, _rectg_error, scipy_baseline=_rectg_scipy,
         estimate_scale=1.0),
    Case("particle ODE (gravity + linear drag)", "particle", _part_yaml, _part_error, scipy_baseline=_part_scipy),
    Case("top ODE (steady precession)", "top", _top_yaml, _top_error),
    # relative estimates: vibration relative to max |x| over the reported times, kinematics to D
    Case("vibration ODE route (DOP853)", "vibration", _vib_yaml, _vib_error,
         estimate_scale=float(max(abs(_vib_x(t)) for t in VT))),
    Case("kinematics quadrature (arc length)", "kinematics", _kin_yaml, _kin_error, estimate_scale=float(_kin_ref())),
    # relative to the work's scale, at least |U| (the stricter comparison)
    Case("force-field quadrature (work)", "force-field", _ff_yaml, _ff_error, estimate_scale=float(abs(_ff_ref()))),
]


def available_cases() -> list[Case]:
    from dyncli import registry

    return [c for c in CASES if registry.available(c.type)]


# --- plain-scipy baselines for the remaining routes ---------------------------------------
def _vib_scipy(rtol, atol):
    from scipy.integrate import solve_ivp

    sol = solve_ivp(lambda t, y: [y[1], -4 * y[0] - 0.4 * y[1]], (0, 20), [1.0, 0.0], method="DOP853",
                    rtol=rtol, atol=atol, t_eval=VT)
    return max(abs(sol.y[0][i] - float(_vib_x(t))) for i, t in enumerate(VT)), int(sol.nfev)


def _top_scipy(rtol, atol):
    """The heavy symmetric top in Euler angles (Lagrange), ψ̇ and φ̇ from the
    conserved p_ψ and ω3; state [θ, θ̇, ψ, φ]."""
    import math

    from scipy.integrate import solve_ivp

    m, L, A, C, p, g, th0 = 0.5, 0.05, 2e-3, 1e-3, 150.0, 9.81, math.pi / 6
    om = 2 * m * g * L / (C * p + math.sqrt((C * p) ** 2 - 4 * m * g * L * (A - C) * math.cos(th0)))
    w3 = om * math.cos(th0) + p
    p_psi = A * om * math.sin(th0) ** 2 + C * w3 * math.cos(th0)

    def rhs(t, y):
        th, thd = y[0], y[1]
        s, c = math.sin(th), math.cos(th)
        psid = (p_psi - C * w3 * c) / (A * s * s)
        thdd = (A * psid * psid * s * c - C * w3 * psid * s + m * g * L * s) / A
        return [thd, thdd, psid, w3 - psid * c]

    sol = solve_ivp(rhs, (0, 5), [th0, 0.0, 0.0, 0.0], method="DOP853", rtol=rtol, atol=atol, t_eval=TT)
    errs = []
    for i, t in enumerate(TT):
        errs += [abs(sol.y[2][i] - om * t), abs(sol.y[0][i] - th0), abs(sol.y[3][i] - p * t)]
    return max(errs), int(sol.nfev)


def _kin_scipy(rtol, atol):
    import math

    from scipy.integrate import quad

    n = 0

    def speed(t):
        nonlocal n
        n += 1
        r, rd = 2 * (1 + 0.3 * math.sin(t)), 0.6 * math.cos(t)
        return math.sqrt(rd * rd + (3 * r) ** 2 + 2.25)

    val = quad(speed, 0, 2, epsrel=rtol, epsabs=atol)[0]
    return abs(val - float(_kin_ref())), n


def _ff_scipy(rtol, atol):
    import math

    from scipy.integrate import quad

    n = 0

    def f(t):
        nonlocal n
        n += 1
        x1, x2, x3 = 2 * math.cos(t), math.sin(t), 0.1 * t
        return (-x2 * x3 + x1 * x1) * (-2 * math.sin(t)) + x1 * x3 * math.cos(t) + x1 * x2 * 0.1

    val = quad(f, 0, 5, epsrel=rtol, epsabs=atol, limit=200)[0]
    return abs(val - float(_ff_ref())), n


for _c, _b in zip(CASES[3:], (_top_scipy, _vib_scipy, _kin_scipy, _ff_scipy)):
    _c.scipy_baseline = _b


# --- euler: torque-free body integrated (DOP853) vs the exact solution ----------------------
# a triaxial body: exact ω(t) from Jacobi elliptic functions (mpmath), the
# classical solution of (39.5) with M = 0 for H² < 2 T I2 (rotation near axis 3)
EI = [mp.mpf(1), mp.mpf(2), mp.mpf(3)]
EW0 = [mp.mpf("0.1"), mp.mpf(0), mp.mpf(2)]
ET = [1, 5, 20]


def _euler_exact(t):
    """ω(t) of the torque-free triaxial body I1 < I2 < I3 with ω2(0) = 0 and
    H² > 2 T I2 (spin near axis 3): ω1 = a cn τ, ω2 = b sn τ, ω3 = c dn τ
    (the classical Jacobi-elliptic solution of (39.5) with M = 0)."""
    I1, I2, I3 = EI
    w10, w20, w30 = EW0
    H2 = (I1 * w10) ** 2 + (I2 * w20) ** 2 + (I3 * w30) ** 2
    E2 = I1 * w10 ** 2 + I2 * w20 ** 2 + I3 * w30 ** 2       # 2T
    a = mp.sqrt((E2 * I3 - H2) / (I1 * (I3 - I1)))
    b = mp.sqrt((E2 * I3 - H2) / (I2 * (I3 - I2)))
    c = mp.sqrt((H2 - E2 * I1) / (I3 * (I3 - I1)))
    lam = mp.sqrt((I3 - I2) * (H2 - E2 * I1) / (I1 * I2 * I3))
    m = (I2 - I1) * (E2 * I3 - H2) / ((I3 - I2) * (H2 - E2 * I1))
    u = lam * t
    # ω̇2(0) = (I3 − I1)/I2 ω3 ω1 > 0 for ω1, ω3 > 0: ω2 = +b sn
    return [a * mp.ellipfun("cn", u, m=m), b * mp.ellipfun("sn", u, m=m), c * mp.ellipfun("dn", u, m=m)]


def _euler_yaml(rtol, atol, est):
    return ("type: euler\nI: [1, 2, 3]\nomega0: [0.1, 0, 2]\nat: [1, 5, 20]\n" + _acc(rtol, atol, est, "DOP853"))


def _euler_error(rec):
    r = rec["results"]
    w = r.get("omega")
    pairs = []
    for i, t in enumerate(ET):
        pairs += list(zip(w[i], _euler_exact(t)))
    return _maxerr(pairs)


def _euler_scipy(rtol, atol):
    from scipy.integrate import solve_ivp

    I1, I2, I3 = 1.0, 2.0, 3.0

    def rhs(t, w):
        return [(I2 - I3) / I1 * w[1] * w[2], (I3 - I1) / I2 * w[2] * w[0], (I1 - I2) / I3 * w[0] * w[1]]

    sol = solve_ivp(rhs, (0, 20), [0.1, 0.0, 2.0], method="DOP853", rtol=rtol, atol=atol, t_eval=ET)
    errs = []
    for i, t in enumerate(ET):
        ex = _euler_exact(t)
        errs += [abs(sol.y[k][i] - float(ex[k])) for k in range(3)]
    return max(errs), int(sol.nfev)


CASES.append(Case("euler ODE (torque-free, DOP853)", "euler", _euler_yaml, _euler_error, scipy_baseline=_euler_scipy,
                  estimate_scale=float(mp.sqrt(sum(w * w for w in EW0)))))

# the top's two routes on a nutating top (appended: the scipy baselines above are matched by position)
CASES.append(Case("top ODE (nutating)", "top", lambda r, a, e: _nut_yaml(r, a, e, "DOP853"), _nut_error,
                  estimate_scale=1.0))
CASES.append(Case("top exact (nutating)", "top", lambda r, a, e: _nut_yaml(r, a, e, "auto"), _nut_error,
                  estimate_scale=1.0))


# the gyroscope's two routes on the §37 swing from 0 to π (the gallery file), against the
# 30-digit Taylor integration of (37.12) in tests/topics/gyroscope/gyroscope_reference_data.py;
# errors relative to the scales of the exact route's estimate (π for θ, √(2|a| + 2|b|) for θ̇)
def _gyro_yaml(rtol, atol, est, method):
    return ("type: gyroscope\nI1: 0.01\nI2: 0.006\np: 100\nq: 1\nat: [0.05, 0.1, 0.2, 0.33]\n"
            + _acc(rtol, atol, est, method))


def _gyro_error(rec):
    from tests.topics.gyroscope.gyroscope_reference_data import CASES as GREF

    rows = GREF["zero_to_pi"]["rows"]
    r = rec["results"]
    s_thd = math.sqrt(2 * 0.004 / 0.006 + 2 * 2 * 0.01 * 100 / 0.006)
    return max(max(abs(x - row[0]) / math.pi, abs(y - row[1]) / s_thd)
               for x, y, row in zip(r["theta"], r["theta_dot"], rows))


CASES.append(Case("gyroscope ODE (0 to π)", "gyroscope", lambda r, a, e: _gyro_yaml(r, a, e, "DOP853"), _gyro_error,
                  estimate_scale=1.0))
CASES.append(Case("gyroscope exact (0 to π)", "gyroscope", lambda r, a, e: _gyro_yaml(r, a, e, "auto"), _gyro_error,
                  estimate_scale=1.0))


# rectilinear's other quadrature routes (appended: the scipy baselines above are matched by position);
# errors relative to each quantity's scale over the answers, as the type's error_estimate
def _rect2_yaml(rtol, atol, est):
    # case 2, a = cos t: v = 1 + sin t, s = t + 1 - cos t (s1 = 0, v1 = 1)
    return ("type: rectilinear\na: 'cos(t)'\nv1: 1\n"
            "find: [{t: 2}, {t: 7}, {v: 1.5}, {s: 3}]\n" + _acc(rtol, atol, est, "quadrature"))


def _rect2_error(rec):
    f = rec["results"]["find"]
    s = lambda t: t + 1 - mp.cos(t)                 # noqa: E731
    v = lambda t: 1 + mp.sin(t)                     # noqa: E731
    ts = [mp.mpf(2), mp.mpf(7), mp.pi / 6, mp.findroot(lambda t: s(t) - 3, 2)]
    return _relerr([[(f[k]["t"], t) for k, t in enumerate(ts)], [(f[k]["s"], s(t)) for k, t in enumerate(ts)],
                    [(f[k]["v"], v(t)) for k, t in enumerate(ts)]])


def _rect4_yaml(rtol, atol, est):
    # case 4, a = -4 s: s = 0.5 cos 2t + 0.5 sin 2t (s1 = 0.5, v1 = 1), periodic
    return ("type: rectilinear\na: '-4*s'\ns1: 0.5\nv1: 1\n"
            "find: [{t: 1}, {t: 7}, {v: 0}, {s: -0.3}]\n" + _acc(rtol, atol, est, "quadrature"))


def _rect4_error(rec):
    f = rec["results"]["find"]
    s = lambda t: (mp.cos(2 * t) + mp.sin(2 * t)) / 2   # noqa: E731
    v = lambda t: mp.cos(2 * t) - mp.sin(2 * t)         # noqa: E731
    ts = [mp.mpf(1), mp.mpf(7), mp.pi / 8, mp.findroot(lambda t: s(t) + mp.mpf("0.3"), 1.2)]
    return _relerr([[(f[k]["t"], t) for k, t in enumerate(ts)], [(f[k]["s"], s(t)) for k, t in enumerate(ts)],
                    [(f[k]["v"], v(t)) for k, t in enumerate(ts)]])


CASES.append(Case("rectilinear quadrature + roots (case 2)", "rectilinear", _rect2_yaml, _rect2_error,
                  estimate_scale=1.0))
CASES.append(Case("rectilinear quadrature + turning points (case 4)", "rectilinear", _rect4_yaml, _rect4_error,
                  estimate_scale=1.0))
