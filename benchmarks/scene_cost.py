"""The cost of the ``scene`` type, measured in one run, as ratios (never absolute claims).

1. **Cold**: the CPU time (user + sys of the child, ``getrusage(RUSAGE_CHILDREN)``) of
   ``python -m dyncli solve FILE --format json`` for every ``problems/scenes/*.yaml``, median of
   ``--runs`` interleaved rounds after one untimed warm-up, over the import floor of its route:

   * closed-form, statics, kinematics: the floor of the closed-form types
     (benchmarks/startup_types.py: ``python -c "import numpy, pydantic, yaml, typer, rich"``);
     goal <= 1.3x;
   * ode: a plain ``python -c "import numpy, scipy.integrate"``, and (the goal's own floor, when
     the scene has a hand-written script below) a cold plain scipy script that imports numpy and
     scipy.integrate and integrates the same equations in minimal coordinates at the file's
     rtol; goal <= 1.2x that script (the script's column is printed for a closed-form scene too).

2. **Warm, at equal error** (as benchmarks/runner_cost.py): for the scenes with a hand-written
   script here (``SCRIPTS``: the double pendulum, the pendulum on a cart, the sliding ladder
   through the wall's release, the Atwood machine, the pulled spool), the scene solver in process (the validated model
   reused: no YAML, no validation in the time) at a few rtols (atol = 1e-3 rtol); its error is
   the largest difference of the bodies' positions at the requested times from a tight
   reference (the script at rtol 1e-13), relative to the largest position.  The script
   (``solve_ivp``, DOP853, the Lagrange equations of the minimal coordinates written by hand,
   ``t_eval`` and the events the scene watches or finds) runs on a grid of rtols 10^(-k/4); the
   loosest whose error, and the error at every tighter grid point, is <= the scene's is
   "scipy at equal error".  Both are timed warm (CPU time of this process), interleaved, median
   of ``--repeats``; the ratio scene/scipy is printed (goal <= 1.2).

The scene's agreement with the reference at rtol 1e-13 is printed too: a scene file whose data
differ from the script's (another geometry) shows up there and is skipped, not compared.

Usage: python benchmarks/scene_cost.py [--runs 5] [--repeats 5] [--rtols 1e-6 1e-8 1e-10]
       [--profile]   (cProfile of one warm ODE solve: the top functions inside dyncli/topics/scene/)
"""

from __future__ import annotations

import argparse
import inspect
import math
import os
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from runner_cost import interleaved  # noqa: E402  the benchmarks' one timing loop

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(ROOT))      # this checkout's dyncli, not an installed one

from startup import _env, timed_rounds  # noqa: E402

SCENES = ROOT / "problems" / "scenes"
CF_GOAL, ODE_GOAL, WARM_GOAL = 1.3, 1.2, 1.2
GRID = [10.0 ** (-k / 4) for k in range(16, 53)]       # 1e-4 ... 1e-13
REF_RTOL = 1e-13


# --- the plain scipy scripts: each self-contained (its source is also run cold, as a file) ---------
# (P, at, t_end, rtol, atol) -> {body: [[x1, x2] or None per requested time]}; P: the file's params.

def ladder_script(P, at, t_end, rtol, atol):
    """θ from the floor: θ̈ = −(3g/2L) cos θ while both contacts hold; the wall lets go where
    3 sin θ = 2 sin θ0; then on the floor alone ẍ = 0 (no horizontal force) and
    (L²/4 cos²θ + L²/12) θ̈ = L²/4 cos θ sin θ θ̇² − g L/2 cos θ (Lagrange, by hand);
    find: the rod's angle π − θ = 130°."""
    import math

    from scipy.integrate import solve_ivp

    g, L, th0 = 9.81, P["L"], P["theta0"]
    k, s0 = 1.5 * g / L, 2 * math.sin(th0)

    def rhs(t, y):
        return [y[1], -k * math.cos(y[0])]

    def wall(t, y):
        return 3 * math.sin(y[0]) - s0
    wall.terminal = True

    def find(t, y):
        return y[0] - 50 * math.pi / 180

    def rhs2(t, y):                      # x, θ, ẋ, θ̇ on the floor alone
        c, s = math.cos(y[1]), math.sin(y[1])
        return [y[2], y[3], 0.0, (0.25 * L * L * c * s * y[3] * y[3] - 0.5 * g * L * c) / (L * L * (0.25 * c * c + 1 / 12))]

    def find2(t, y):
        return y[1] - 50 * math.pi / 180

    ts = [t for t in at if t <= t_end]
    sol = solve_ivp(rhs, (0.0, t_end), [th0, 0.0], method="DOP853", rtol=rtol, atol=atol, t_eval=ts,
                    events=[wall, find])
    out = [[L / 2 * math.cos(th), L / 2 * math.sin(th)] for th in sol.y[0]]
    if sol.status == 1:                  # the wall let go: the second phase
        t1, (th, w) = float(sol.t_events[0][0]), sol.y_events[0][0]
        y1 = [L / 2 * math.cos(th), th, -L / 2 * math.sin(th) * w, w]
        sol2 = solve_ivp(rhs2, (t1, t_end), y1, method="DOP853", rtol=rtol, atol=atol,
                         t_eval=[t for t in ts if t > t1], events=[find2])
        out += [[x, L / 2 * math.sin(th)] for x, th in zip(sol2.y[0], sol2.y[1])]
    return {"rod": out + [None] * (len(at) - len(out))}


def atwood_script(P, at, t_end, rtol, atol):
    """The fall of A: (m1 + m2 + Ī/R²) ÿ = −(m1 − m2) g with Ī = M R²/2 (a uniform disk), B rising
    as A falls; find: A at x2 = −2."""
    from scipy.integrate import solve_ivp

    g, m1, m2, M, R = 9.81, P["m1"], P["m2"], P["M"], P["R"]
    a = (m1 - m2) * g / (m1 + m2 + 0.5 * M)

    def rhs(t, y):
        return [y[1], -a]

    def find(t, y):
        return y[0] + 2.0

    sol = solve_ivp(rhs, (0.0, t_end), [-1.0, 0.0], method="DOP853", rtol=rtol, atol=atol, t_eval=at,
                    events=[find])
    return {"A": [[-R, y] for y in sol.y[0]], "B": [[R, -2.5 - y] for y in sol.y[0]]}


def spool_script(P, at, t_end, rtol, atol):
    """The centre's x: (m + Ī/R²) ẍ = P (1 + (r/R) cos(x/R)); watched: slip (μ_s N − |F|, F = m ẍ − P,
    N = m g); find: x = 0.5."""
    import math

    from scipy.integrate import solve_ivp

    g, m, I0, R, r, Pf, mu = 9.81, P["m"], P["I0"], P["R"], P["r"], P["P"], 0.4
    meff = m + I0 / (R * R)

    def rhs(t, y):
        return [y[1], Pf * (1 + r / R * math.cos(y[0] / R)) / meff]

    def slip(t, y):
        return mu * m * g - abs(m * rhs(t, y)[1] - Pf)
    slip.terminal = True

    def find(t, y):
        return y[0] - 0.5

    sol = solve_ivp(rhs, (0.0, t_end), [0.0, 0.0], method="DOP853", rtol=rtol, atol=atol, t_eval=at,
                    events=[slip, find])
    return {"spool": [[x, R] for x in sol.y[0]]}


def double_pendulum_script(P, at, t_end, rtol, atol):
    """Link angles φ1, φ2 from −e2, two point masses (Lagrange, by hand):
    (m1+m2) L1 φ̈1 + m2 L2 c φ̈2 = −m2 L2 s φ̇2² − (m1+m2) g sin φ1,
    L1 c φ̈1 + L2 φ̈2 = L1 s φ̇1² − g sin φ2,   c, s = cos, sin(φ1 − φ2); find: sin φ1 = 0."""
    import math

    from scipy.integrate import solve_ivp

    g, m1, m2, L1, L2 = 9.81, P["m1"], P["m2"], P["L1"], P["L2"]

    def rhs(t, y):
        p1, p2, w1, w2 = y
        d = p1 - p2
        c, s = math.cos(d), math.sin(d)
        a11, a12, a21, a22 = (m1 + m2) * L1, m2 * L2 * c, L1 * c, L2
        b1 = -m2 * L2 * s * w2 * w2 - (m1 + m2) * g * math.sin(p1)
        b2 = L1 * s * w1 * w1 - g * math.sin(p2)
        det = a11 * a22 - a12 * a21
        return [w1, w2, (b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det]

    def find(t, y):
        return math.sin(y[0])

    sol = solve_ivp(rhs, (0.0, t_end), [P["p1"], P["p2"], 0.0, 0.0], method="DOP853", rtol=rtol, atol=atol,
                    t_eval=at, events=[find])
    A = [[L1 * math.sin(p1), -L1 * math.cos(p1)] for p1 in sol.y[0]]
    B = [[a[0] + L2 * math.sin(p2), a[1] - L2 * math.cos(p2)] for a, p2 in zip(A, sol.y[1])]
    return {"A": A, "B": B}


def cart_pendulum_script(P, at, t_end, rtol, atol):
    """The cart's x and the link's φ from −e2 (Lagrange, by hand; spring k, free length L0 to the
    wall at xw; the link hangs from the cart's hook):
    (M+m) ẍ + m l cos φ φ̈ = m l sin φ φ̇² − k (x − xw − L0),   cos φ ẍ + l φ̈ = −g sin φ;
    find: the cart's first turning point (ẋ = 0, rising)."""
    import math

    from scipy.integrate import solve_ivp

    g, M, m, l, k = 9.81, P["M"], P["m"], P["l"], P["k"]
    L0, xw, x0, y0, hx, hy = P.get("L0", 0.8), P.get("xw", -1.0), 0.0, 1.0, 0.0, -0.1

    def rhs(t, y):
        x, p, xd, pd = y
        c, s = math.cos(p), math.sin(p)
        a11, a12, a21, a22 = M + m, m * l * c, c, l
        b1 = m * l * s * pd * pd - k * (x - xw - L0)
        b2 = -g * s
        det = a11 * a22 - a12 * a21
        return [xd, pd, (b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det]

    def find(t, y):
        return y[2]
    find.direction = 1

    sol = solve_ivp(rhs, (0.0, t_end), [x0, P["p0"], 0.0, 0.0], method="DOP853", rtol=rtol, atol=atol,
                    t_eval=at, events=[find])
    cart = [[x, y0] for x in sol.y[0]]
    bob = [[x + hx + l * math.sin(p), y0 + hy - l * math.cos(p)] for x, p in zip(sol.y[0], sol.y[1])]
    return {"cart": cart, "bob": bob}


# --- the same scenes in the engine's own formulation: maximal coordinates, one KKT solve per call ----
# (what "a script of the same equations" is when the equations are the scene's: every point's own
# coordinates, the joints' rows and their multipliers, numpy's solve of [[M, Jᵀ], [J, 0]] per call)

def double_pendulum_kkt(P, at, t_end, rtol, atol):
    """A and B's own coordinates; rows |A|² = L1², |B − A|² = L2² (halved); J̇v from the rows."""
    import numpy as np
    from scipy.integrate import solve_ivp

    g, m1, m2, L1, L2 = 9.81, P["m1"], P["m2"], P["L1"], P["L2"]
    K = np.zeros((6, 6))
    K[:4, :4] = np.diag([m1, m1, m2, m2])
    rhs_f = np.array([0.0, -m1 * g, 0.0, -m2 * g, 0.0, 0.0])

    def rhs(t, y):
        xa, ya, xb, yb, ua, va, ub, vb = y
        dx, dy, du, dv = xb - xa, yb - ya, ub - ua, vb - va
        J = [[xa, ya, 0.0, 0.0], [-dx, -dy, dx, dy]]
        K[4, :4], K[5, :4] = J
        K[:4, 4], K[:4, 5] = J
        rhs_f[4], rhs_f[5] = -(ua * ua + va * va), -(du * du + dv * dv)
        acc = np.linalg.solve(K, rhs_f)
        return [ua, va, ub, vb, acc[0], acc[1], acc[2], acc[3]]

    def find(t, y):
        return y[0]

    p1, p2 = P["p1"], P["p2"]
    xa, ya = L1 * math.sin(p1), -L1 * math.cos(p1)
    y0 = [xa, ya, xa + L2 * math.sin(p2), ya - L2 * math.cos(p2), 0.0, 0.0, 0.0, 0.0]
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=rtol, atol=atol, t_eval=at, events=[find])
    return {"A": sol.y[0:2].T.tolist(), "B": sol.y[2:4].T.tolist()}


def cart_pendulum_kkt(P, at, t_end, rtol, atol):
    """The cart's and the bob's own coordinates; rows: the cart on its track (y = 1), the link
    |bob − hook|² = l² (halved); the spring's force on the cart."""
    import numpy as np
    from scipy.integrate import solve_ivp

    g, M, m, l, k = 9.81, P["M"], P["m"], P["l"], P["k"]
    L0, xw, hy = P.get("L0", 0.8), P.get("xw", -1.0), -0.1
    K = np.zeros((6, 6))
    K[:4, :4] = np.diag([M, M, m, m])
    K[4, 1] = K[1, 4] = 1.0
    f = np.zeros(6)

    def rhs(t, y):
        xc, yc, xb, yb, uc, vc, ub, vb = y
        dx, dy, du, dv = xb - xc, yb - (yc + hy), ub - uc, vb - vc
        K[5, :4] = K[:4, 5] = [-dx, -dy, dx, dy]
        f[0], f[1], f[3] = -k * (xc - xw - L0), -M * g, -m * g
        f[5] = -(du * du + dv * dv)
        acc = np.linalg.solve(K, f)
        return [uc, vc, ub, vb, acc[0], acc[1], acc[2], acc[3]]

    def find(t, y):
        return y[4]
    find.direction = 1

    p0 = P["p0"]
    y0 = [0.0, 1.0, l * math.sin(p0), 1.0 + hy - l * math.cos(p0), 0.0, 0.0, 0.0, 0.0]
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=rtol, atol=atol, t_eval=at, events=[find])
    return {"cart": sol.y[0:2].T.tolist(), "bob": sol.y[2:4].T.tolist()}


KKT = {"double-pendulum.yaml": double_pendulum_kkt, "cart-pendulum.yaml": cart_pendulum_kkt}


SCRIPTS = {   # file -> (script, defaults of its params: the gallery's values, tests/topics/scene)
    "double-pendulum.yaml": (double_pendulum_script, {"m1": 1, "m2": 2, "L1": 1, "L2": 0.7,
                                                      "p1": math.pi / 3, "p2": math.pi / 9}),
    "cart-pendulum.yaml": (cart_pendulum_script, {"M": 2, "m": 0.5, "l": 0.6, "k": 40, "p0": 40 * math.pi / 180}),
    "sliding-ladder.yaml": (ladder_script, {"m": 10, "L": 5, "theta0": math.pi / 3}),
    "atwood-massive-pulley.yaml": (atwood_script, {"m1": 3, "m2": 2, "M": 1, "R": 0.1}),
    "pulled-spool.yaml": (spool_script, {"m": 5, "I0": 0.2, "R": 0.3, "r": 0.15, "P": 20}),
}


# --- helpers ----------------------------------------------------------------------------------------

def file_data(path: Path) -> dict:
    import yaml

    return yaml.safe_load(path.read_text(encoding="utf-8"))


def params(data: dict, defaults: dict) -> dict:
    ns = {k: getattr(math, k) for k in ("pi", "sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "exp", "log")}
    ns["deg"] = math.pi / 180
    out = dict(defaults)
    for k, v in (data.get("params") or {}).items():
        try:
            out[k] = float(eval(str(v), {"__builtins__": {}}, dict(ns, **out)))   # noqa: S307 (a trusted gallery)
        except Exception:  # noqa: BLE001
            pass
    return out


def route_of(path: Path) -> str:
    """The records' route, from one CLI run (it doubles as a warm-up)."""
    import json

    out = subprocess.run([sys.executable, "-m", "dyncli", "solve", str(path), "--format", "json"], cwd=ROOT,
                         env=_env(), capture_output=True, text=True).stdout
    try:
        data = json.loads(out)
        rec = data[0] if isinstance(data, list) else data
        return str(rec["results"]["route"]) if rec.get("results") else "error"
    except (ValueError, KeyError, IndexError, TypeError):
        return "?"


def cold_script(tmp: Path, name: str, fn, P: dict, at, t_end, rtol, atol) -> Path:
    f = tmp / ("plain_" + name.replace("-", "_").replace(".yaml", ".py"))
    f.write_text("import numpy, scipy.integrate\n\n" + inspect.getsource(fn)
                 + f"\n\nprint({fn.__name__}({P!r}, {list(at)!r}, {t_end!r}, {rtol!r}, {atol!r}))\n")
    return f


def positions(rec: dict, bodies) -> dict:
    x = rec["results"]["x"]
    return {b: [None if v is None else v[:2] for v in x[b]] for b in bodies}


def error(got: dict, ref: dict, offset: dict) -> float:
    """Largest position difference over the bodies and times, relative to the largest position
    (``offset``: the scene's placement of the script's origin, from t = 0)."""
    scale = max(abs(c) for b in ref for v in ref[b] if v is not None for c in v) or 1.0
    err = 0.0
    for b in ref:
        for g, r in zip(got[b], ref[b]):
            if (g is None) != (r is None):
                return math.inf
            if g is not None:
                err = max(err, max(abs(gc - offset[b][k] - rc) for k, (gc, rc) in enumerate(zip(g, r))))
    return err / scale


def load_line() -> str:
    a = os.getloadavg()
    return f"load average {a[0]:.2f} {a[1]:.2f} {a[2]:.2f} on {os.cpu_count()} CPUs"


# --- 1. cold -----------------------------------------------------------------------------------------

def cold(runs: int) -> None:
    files = sorted(SCENES.glob("*.yaml"))
    routes = {f: route_of(f) for f in files}
    tmp = Path(tempfile.mkdtemp(prefix="dyncli-scene-cost-"))
    py = sys.executable
    cmds = [[py, "-c", "import numpy, pydantic, yaml, typer, rich"], [py, "-c", "import numpy, scipy.integrate"]]
    plain = {}
    for f in files:
        if f.name in SCRIPTS:
            data = file_data(f)
            fn, defaults = SCRIPTS[f.name]
            acc = data.get("accuracy") or {}
            at = [float(t) for t in data.get("at", [])]
            t_end = float(data.get("t_end", max(at)))
            plain[f] = len(cmds)
            cmds.append([py, str(cold_script(tmp, f.name, fn, params(data, defaults), at, t_end,
                                             float(acc.get("rtol", 1e-10)), float(acc.get("atol", 1e-12))))])
    first = len(cmds)
    cmds += [[py, "-m", "dyncli", "solve", str(f), "--format", "json"] for f in files]
    times = timed_rounds(cmds, runs)
    cf_floor, ode_floor = times[0][1], times[1][1]
    print(f"1. cold: CPU of `python -m dyncli solve FILE --format json` over its route's floor "
          f"(median of {runs}); {load_line()}")
    print(f"   closed-form floor `import numpy, pydantic, yaml, typer, rich`: CPU {cf_floor * 1e3:.0f} ms; "
          f"ODE floor `import numpy, scipy.integrate`: CPU {ode_floor * 1e3:.0f} ms (ratio of the two "
          f"{ode_floor / cf_floor:.2f})")
    print(f"   {'scene':<30} {'route':<12} {'CPU/floor':>9} {'goal':>5} {'CPU/script':>10}  "
          f"(script: the cold plain scipy script of the same equations, ODE goal {ODE_GOAL}x)")
    over = []
    for i, f in enumerate(files):
        c = times[first + i][1]
        r = routes[f]
        if r == "ode":
            floor, goal = ode_floor, ODE_GOAL
            s = f"{c / times[plain[f]][1]:10.2f}" if f in plain else f"{'-':>10}"
            judged = c / times[plain[f]][1] if f in plain else c / floor
        else:
            floor, goal = cf_floor, CF_GOAL
            s = f"{c / times[plain[f]][1]:10.2f}" if f in plain else f"{'':>10}"
            judged = c / floor
        flag = "  > goal" if judged > goal else ""
        if flag:
            over.append(f.stem)
        print(f"   {f.stem:<30} {r:<12} {c / floor:9.2f} {goal:5.1f} {s}{flag}")
    print(f"   over their goal: {', '.join(over) or 'none'}")


# --- 2. warm at equal error --------------------------------------------------------------------------

def scene_at(path: Path, rtol: float):
    """(record, the solver call alone) of the scene file at rtol (atol = 1e-3 rtol, no estimate)."""
    import yaml

    from dyncli import registry
    from dyncli.loader import split_problems, validate
    from dyncli.result import SolveOptions
    from tests.conftest import solve_text

    data = file_data(path)
    data["accuracy"] = {"rtol": rtol, "atol": rtol * 1e-3, "estimate": False}
    text = yaml.safe_dump(data, sort_keys=False)
    rec = solve_text(text, path.name)[0]
    (lp,), _ = split_problems(path.name, text.encode(), ROOT)
    validate(lp)
    fn = registry.solver(lp.type)
    return rec, (lambda: fn(lp.model, SolveOptions()))


def warm(rtols, repeats: int) -> list[Path]:
    names = [n for n in SCRIPTS if (SCENES / n).exists()]
    print()
    print(f"2. warm at equal error: the scene solver (in process, solver only) over a plain solve_ivp DOP853 "
          f"script in minimal coordinates, CPU time, median of {repeats}; {load_line()}")
    print(f"   error: the bodies' positions at the requested times against the script at rtol {REF_RTOL:g}, "
          f"relative to the largest; goal <= {WARM_GOAL}x")
    print(f"   {'scene':<18} {'rtol':>6} {'scene ms':>8} {'error':>8} | {'scipy rtol':>10} {'ms':>7} {'error':>8} | "
          f"{'ratio':>5}")
    used = []
    for name in names:
        path = SCENES / name
        data = file_data(path)
        fn, defaults = SCRIPTS[name]
        P = params(data, defaults)
        at = [float(t) for t in data.get("at", [])]
        t_end = float(data.get("t_end", max(at)))
        ref = fn(P, at, t_end, REF_RTOL, REF_RTOL * 1e-3)
        rec, _ = scene_at(path, REF_RTOL)
        if rec.get("error") or not set(ref) <= set(rec["results"]["x"]):
            print(f"   {path.stem:<18} skipped: {rec.get('error') or 'other bodies'}")
            continue
        got = positions(rec, ref)
        offset = {b: [g - r for g, r in zip(got[b][0], ref[b][0])] for b in ref}
        agree = error(got, ref, offset)
        print(f"   {path.stem:<18} scene at rtol {REF_RTOL:g} vs the script's reference: {agree:.1e} "
              f"(route {rec['results'].get('route')})")
        if not agree < 1e-8:
            print(f"   {'':<18} skipped: the file's scene is not the script's (another geometry or data)")
            continue
        used.append(path)

        def script_err(r):
            return error(fn(P, at, t_end, r, r * 1e-3), ref, {b: [0.0, 0.0] for b in ref})

        for rtol in rtols:
            rec, solve = scene_at(path, rtol)
            e = error(positions(rec, ref), ref, offset)
            best = None
            for r in reversed(GRID):
                es = script_err(r)
                if es > e:
                    break
                best = (r, es)
            if best is None:
                t_d, = interleaved([solve], repeats)
                print(f"   {path.stem:<18} {rtol:6.0e} {t_d * 1e3:8.2f} {e:8.1e} | scipy never reaches this error "
                      f"on the grid")
                continue
            r_s, e_s = best
            t_d, t_s = interleaved([solve, lambda: fn(P, at, t_end, r_s, r_s * 1e-3)], repeats)
            flag = "  > goal" if t_d / t_s > WARM_GOAL else ""
            print(f"   {path.stem:<18} {rtol:6.0e} {t_d * 1e3:8.2f} {e:8.1e} | {r_s:10.1e} {t_s * 1e3:7.2f} "
                  f"{e_s:8.1e} | {t_d / t_s:5.2f}{flag}")
            if name in KKT:
                kkt_row(KKT[name], P, at, t_end, ref, e, t_d, repeats)
    return used


def kkt_row(kkt, P, at, t_end, ref, e: float, t_d: float, repeats: int) -> None:
    """The same comparison against the scene's own equations written as a script (maximal
    coordinates, numpy's KKT solve per call: :data:`KKT`) at equal error."""
    best = None
    for r in reversed(GRID):
        es = error(kkt(P, at, t_end, r, r * 1e-3), ref, {b: [0.0, 0.0] for b in ref})
        if es > e:
            break
        best = (r, es)
    if best is None:
        print(f"   {'  same equations':<18} {'':>6} {'':>8} {'':>8} | the KKT script never reaches this error")
        return
    (t_k,) = interleaved([lambda: kkt(P, at, t_end, best[0], best[0] * 1e-3)], repeats)
    print(f"   {'  same equations':<18} {'':>6} {'':>8} {'':>8} | {best[0]:10.1e} {t_k * 1e3:7.2f} {best[1]:8.1e} | "
          f"{t_d / t_k:5.2f}  (a KKT script: maximal coordinates, numpy solve per call)")


def profile(path: Path, rtol: float = 1e-10, top: int = 10) -> None:
    """cProfile of warm solves: the functions inside dyncli/topics/scene/ by cumulative time."""
    import cProfile
    import pstats

    _, solve = scene_at(path, rtol)
    solve()
    pr = cProfile.Profile()
    pr.enable()
    for _ in range(3):
        solve()
    pr.disable()
    st = pstats.Stats(pr)
    total = st.total_tt
    rows = []
    for (file, line, func), (_cc, nc, tt, ct, _callers) in st.stats.items():
        if "topics/scene/" in file.replace(os.sep, "/"):
            rows.append((ct, tt, nc, f"{Path(file).name}:{line}({func})"))
    rows.sort(reverse=True)
    print()
    print(f"3. profile: {path.stem} at rtol {rtol:g}, 3 warm solves ({total * 1e3 / 3:.1f} ms each under cProfile); "
          f"top {top} in dyncli/topics/scene/ by cumulative time")
    print("   cumulative  own   calls/solve  function (the first rows nest: solve > run > _phase)")
    for ct, tt, nc, label in rows[:top]:
        print(f"   {ct / total * 100:7.1f} % {tt / total * 100:5.1f} % {nc // 3:>9}  {label}")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--rtols", type=float, nargs="+", default=[1e-6, 1e-8, 1e-10])
    ap.add_argument("--no-cold", action="store_true")
    ap.add_argument("--profile", action="store_true")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    t0 = time.perf_counter()
    if not args.no_cold:
        cold(args.runs)
    used = warm(args.rtols, args.repeats)
    if args.profile and used:
        profile(used[0])
    print(f"\n(benchmark wall time {time.perf_counter() - t0:.0f} s)")


if __name__ == "__main__":
    main()
