"""Scene gallery A (problems/scenes/): the Atwood machine with a massive pulley, the block on an
incline tied over a pulley (sliding and sticking), the sliding ladder, the disk rolling against a
spring, the pulled spool — motion AND joint forces against references computed here by an
independent route (refs_a.py: hand closed forms; Lagrange's equations with multipliers set up
by sympy; mpmath's Taylor ODE solver and tanh-sinh quadrature at 30 digits), never from dyncli.
Then the edge cases of these scenes: a 1e6 mass ratio across the cord, a pulley of negligible
inertia, friction exactly at the stick/slip limit, a ladder released 1e-6 rad off the vertical.

Tolerances (what each route guarantees, tests/tolerances.py and docs/accuracy.md):

* a closed form (``route`` closed-form or statics): 1e-12 relative to the quantity's scale —
  rounding (~1e-16) times the modest condition numbers of these formulas, with room;
* a numerical route (ode, quadrature): the motion within ``ODE_GLOBAL`` × rtol = 100 × rtol of
  its scale (docs/accuracy.md: the global error of an ODE route is 1-100 × rtol of the state's
  scale), the reactions within 1000 × rtol of theirs: a reaction is one derivative above the
  state (it is solved from the state, λ(q, v)), so it carries the state's error times the
  sensitivity of λ to (q, v) relative to its scale, at most ~10 in these scenes;
* the references themselves agree to 1e-25 (``test_references_agree``), so every tolerance
  above is the engine's alone.
"""

from __future__ import annotations

import math

import mpmath as mp
import pytest
import sympy as sp
import yaml

from tests.conftest import PROBLEMS, solve_one_text
from tests.tolerances import ODE_GLOBAL
from tests.topics.scene import refs_a as R
from tests.topics.scene.common import gallery

MPMATH_DPS = 30
SCENES = PROBLEMS / "scenes"
CLOSED = 1e-12
REACTION_FACTOR = 1000
DEFAULT_RTOL = 1e-10
EXACT_ROUTES = ("closed-form", "statics", "kinematics")


def file_rtol(name) -> float:
    data = yaml.safe_load((SCENES / name).read_text(encoding="utf-8"))
    return float((data.get("accuracy") or {}).get("rtol", DEFAULT_RTOL))


def tols(rec, rtol=DEFAULT_RTOL):
    """(motion, reaction) relative tolerances for the record's route (module docstring)."""
    if rec["results"]["route"] in EXACT_ROUTES:
        return CLOSED, CLOSED
    return ODE_GLOBAL * rtol, REACTION_FACTOR * rtol


def get(res, path):
    node = res
    for part in path.split("."):
        node = node[int(part)] if isinstance(node, list) else node[part]
    return node


def near(got, want, rel, scale, what=""):
    """|got − want| ≤ rel · max(|want|, scale), component by component (vectors too)."""
    if isinstance(want, (list, tuple)):
        assert isinstance(got, list) and len(got) == len(want), f"{what}: {got!r} vs {want!r}"
        for i, (g_, w_) in enumerate(zip(got, want)):
            near(g_, w_, rel, scale, f"{what}[{i}]")
        return
    want = float(want)
    assert got is not None, f"{what}: null, expected {want!r}"
    assert abs(got - want) <= rel * max(abs(want), scale), \
        f"{what}: {got!r} vs {want!r} (diff {got - want:.3e}, allowed {rel * max(abs(want), scale):.3e})"


def f(x) -> float:
    return float(R.mpf(x))


G = float(R.G)


# ---------------------------------------------------------------------------------------------
# the files restate the references' data

def _load(name):
    return yaml.safe_load((SCENES / name).read_text(encoding="utf-8"))


def test_files_state_the_reference_data():
    from dyncli.expr import constant

    def num(v, params):
        return constant(v, params) if isinstance(v, str) else float(v)

    def params(d):
        out = {}
        for k, v in d["params"].items():
            out[k] = num(v, out)
        return out

    d = _load("atwood-massive-pulley.yaml")
    assert params(d) == {k: f(v) for k, v in R.ATWOOD.items()}
    for name, ref in (("incline-pulley-slides.yaml", R.SLIDES), ("incline-pulley-sticks.yaml", R.STICKS)):
        d = _load(name)
        p = params(d)
        assert (p["m1"], p["m2"]) == (ref["m1"], ref["m2"])
        assert p["beta"] == pytest.approx(math.radians(ref["beta"]), rel=1e-15)
        assert d["joints"]["slide"]["mu_s"] == f(ref["mu_s"]) and d["joints"]["slide"]["mu_k"] == f(ref["mu_k"])
    d = _load("sliding-ladder.yaml")
    p = params(d)
    assert (p["m"], p["L"]) == (R.LADDER["m"], R.LADDER["L"])
    assert p["theta0"] == pytest.approx(math.radians(R.LADDER["theta0"]), rel=1e-15)
    d = _load("rolling-disk-spring.yaml")
    p = params(d)
    assert (p["m"], p["R"], p["k"], p["L0"], p["s0"]) == tuple(f(R.DISK[k]) for k in ("m", "R", "k", "L0", "at"))
    assert d["joints"]["roll"]["mu_s"] == f(R.DISK["mu_s"])
    d = _load("pulled-spool.yaml")
    p = params(d)
    assert (p["m"], p["I0"], p["R"], p["r"], p["P"]) == tuple(f(R.SPOOL[k]) for k in ("m", "I", "R", "r", "P"))
    assert d["joints"]["roll"]["mu_s"] == f(R.SPOOL["mu_s"])


# ---------------------------------------------------------------------------------------------
# the two routes of every reference agree (no dyncli involved)

def test_references_agree():
    tiny = mp.mpf("1e-25")
    # Atwood: the closed form and the multipliers, at rest and in motion
    c = R.atwood(**R.ATWOOD)
    s = R.atwood_multipliers(**R.ATWOOD)
    for qv, qdv in (([-0.1, -1, 0.1, -1.5, 0, 0, 0], [0] * 7), ([-0.1, -1.3, 0.1, -1.2, 0, 0, 3], [0, -2, 0, 2, 0, 0, 20])):
        qdd, lam = s.solve(qv, qdv)
        assert abs(qdd[1] + R.mpf(c["a"])) < tiny and abs(qdd[6] - R.mpf(c["alpha"])) < tiny
        for k, ck in (("T1", "T1"), ("T2", "T2"), ("R2", "R_axle")):
            assert abs(lam[k] - R.mpf(c[ck])) < tiny
        assert abs(lam["R1"]) < tiny and abs(lam["gA"]) < tiny
    # incline: sliding (kinetic friction coupled to N) and sticking (a tangential row)
    for ref, mode in ((R.SLIDES, "up"), (R.STICKS, "stick")):
        c = R.incline(ref["m1"], ref["m2"], ref["mu_s"], ref["mu_k"], ref["beta"])
        assert c["stuck"] == (mode == "stick")
        s = R.incline_multipliers(ref["m1"], ref["m2"], ref["mu_k"], ref["beta"], mode)
        b = R.deg(ref["beta"])
        qdd, lam = s.solve([mp.cos(b), mp.sin(b), 3 * mp.cos(b), 3 * mp.sin(b) - 1], [0] * 4)
        F = lam["F"] if mode == "stick" else -R.mpf(ref["mu_k"]) * lam["N"]
        assert abs(lam["N"] - R.mpf(c["N"])) < tiny and abs(lam["T"] - R.mpf(c["T"])) < tiny
        assert abs(F - R.mpf(c["F"])) < tiny and abs(-qdd[3] - R.mpf(c["a"])) < tiny
    # ladder: the hand reactions and θ̈ against the multipliers along the ODE motion; the ODE
    # against the quadrature at the release
    m, L, th0 = R.LADDER["m"], R.LADDER["L"], R.deg(R.LADDER["theta0"])
    s = R.ladder_multipliers(m, L)
    sol = R.ladder_motion(R.LADDER["theta0"], L)
    for t in ("0", "0.25", "0.5", "0.7"):
        th, thd = sol(mp.mpf(t))
        qdd, lam = s.solve([L / 2 * mp.cos(th), L / 2 * mp.sin(th), mp.pi - th],
                           [-L / 2 * mp.sin(th) * thd, L / 2 * mp.cos(th) * thd, -thd])
        Nw, Nf = R.ladder_reactions(th, th0, m, L)
        thd_e, thdd = R.ladder_rates(th, th0, L)
        assert abs(lam["N_w"] - Nw) < tiny and abs(lam["N_f"] - Nf) < tiny
        assert abs(qdd[2] + thdd) < tiny and abs(thd - thd_e) < tiny
    ths, ts = R.ladder_release(th0, L)
    assert abs(sol(ts)[0] - ths) < tiny
    # rolling disk: the closed form against the multipliers
    s = R.disk_multipliers(**R.DISK)
    c0, _anc, d, _n = R.disk_start(**R.DISK)
    Rd = R.mpf(R.DISK["R"])
    for t in ("0", "0.25", "0.5", "1"):
        c = R.disk_closed_form(mp.mpf(t), **R.DISK)
        qdd, lam = s.solve([c0[0] - c["s"] * d[0], c0[1] - c["s"] * d[1], c["s"] / Rd],
                           [-c["sd"] * d[0], -c["sd"] * d[1], c["sd"] / Rd])
        assert abs(lam["F"] - c["F"]) < tiny and abs(lam["N"] - c["N"]) < tiny
        assert abs(qdd[0] + c["sdd"] * d[0]) < tiny
    # spool: the ODE motion against the multipliers and the quadrature
    s = R.spool_multipliers(**R.SPOOL)
    sol = R.spool_motion()
    Rs, m = R.mpf(R.SPOOL["R"]), R.SPOOL["m"]
    for t in ("0", "0.25", "0.5"):
        x, v = sol(mp.mpf(t))
        a = R.spool_accel(x, **R.SPOOL)
        qdd, lam = s.solve([x, Rs, -x / Rs], [v, 0, -v / Rs])
        assert abs(qdd[0] - a) < tiny and abs(lam["F"] - (m * a - R.SPOOL["P"])) < tiny
        assert abs(lam["N"] - m * R.g()) < tiny
    t5 = R.spool_time(mp.mpf("0.5"), **R.SPOOL)
    assert abs(sol(t5)[0] - mp.mpf("0.5")) < tiny


# ---------------------------------------------------------------------------------------------
# 1. atwood-massive-pulley.yaml

def test_atwood_massive_pulley():
    rec = gallery("atwood-massive-pulley.yaml")
    r = rec["results"]
    assert r["route"] == "closed-form" and rec["method"] == "closed-form"
    assert r["dof"] == 1 and r["events"] == []
    c = {k: f(v) for k, v in R.atwood(**R.ATWOOD).items()}
    a, Rp = c["a"], f(R.ATWOOD["R"])
    tm, tr = tols(rec)
    for i, t in enumerate(r["t"]):
        near(r["x"]["A"][i], [-0.1, -1 - a * t * t / 2, 0], tm, 1, f"x.A.{i}")
        near(r["x"]["B"][i], [0.1, -1.5 + a * t * t / 2, 0], tm, 1, f"x.B.{i}")
        near(r["v"]["A"][i], [0, -a * t, 0], tm, a, f"v.A.{i}")
        near(r["a"]["A"][i], [0, -a, 0], tm, a, f"a.A.{i}")
        near(r["a"]["B"][i], [0, a, 0], tm, a, f"a.B.{i}")
        near(r["x"]["pulley"][i], [0, 0, 0], tm, 1, f"x.pulley.{i}")
        near(r["angle"]["pulley"][i], a * t * t / 2 / Rp, tm, 1, f"angle.pulley.{i}")
        near(r["omega"]["pulley"][i], [0, 0, a * t / Rp], tm, a / Rp, f"omega.pulley.{i}")
        near(r["alpha"]["pulley"][i], [0, 0, c["alpha"]], tm, c["alpha"], f"alpha.pulley.{i}")
        # the cord: A's segment first; the pin: the force on the pulley by the ground
        near(r["reaction"]["rope"]["T"][i], [c["T1"], c["T2"]], tr, c["T1"], f"reaction.rope.T.{i}")
        near(r["reaction"]["axle"]["R"][i], [0, c["R_axle"], 0], tr, c["R_axle"], f"reaction.axle.R.{i}")
        # energy: V from gravity (zero at x2 = 0), no work by the no-slip cord or the pin
        T = (3 + 2 + f(R.atwood(**R.ATWOOD)["I"]) / Rp**2) * (a * t) ** 2 / 2
        V = G * (3 * (-1 - a * t * t / 2) + 2 * (-1.5 + a * t * t / 2))
        near(r["T"][i], T, tm, 10, f"T.{i}")
        near(r["V"][i], V, tm, 10, f"V.{i}")
        near(r["E"][i], G * (3 * -1 + 2 * -1.5), tm, 10, f"E.{i}")
    q = r["find"][0]
    assert q["reached"] is True
    near(q["t"], f(mp.sqrt(2 / R.mpf(R.atwood(**R.ATWOOD)["a"]))), tm, 1, "find.0.t")
    near(q["x"]["A"], [-0.1, -2, 0], tm, 1, "find.0.x.A")
    near(q["reaction"]["rope"]["T"], [c["T1"], c["T2"]], tr, c["T1"], "find.0.reaction.rope.T")


# ---------------------------------------------------------------------------------------------
# 2. incline-pulley-slides.yaml

def test_incline_pulley_slides():
    rec = gallery("incline-pulley-slides.yaml")
    r = rec["results"]
    assert r["route"] == "closed-form" and r["dof"] == 1 and r["events"] == []
    ref = R.SLIDES
    c = {k: f(v) for k, v in R.incline(ref["m1"], ref["m2"], ref["mu_s"], ref["mu_k"], ref["beta"]).items()}
    assert c["stuck"] == 0.0 and c["sign"] == 1.0
    b = math.radians(ref["beta"])
    d = (math.cos(b), math.sin(b))
    sdd = c["a"]
    tm, tr = tols(rec)
    for i, t in enumerate(r["t"]):
        s = 1 + sdd * t * t / 2
        near(r["x"]["A"][i], [s * d[0], s * d[1], 0], tm, 1, f"x.A.{i}")
        near(r["v"]["A"][i], [sdd * t * d[0], sdd * t * d[1], 0], tm, sdd, f"v.A.{i}")
        near(r["a"]["A"][i], [sdd * d[0], sdd * d[1], 0], tm, sdd, f"a.A.{i}")
        near(r["x"]["B"][i], [3 * d[0], 3 * d[1] - 1 - sdd * t * t / 2, 0], tm, 1, f"x.B.{i}")
        near(r["a"]["B"][i], [0, -sdd, 0], tm, sdd, f"a.B.{i}")
        # kinetic friction from t = 0 (the static test at rest decides the direction)
        near(r["reaction"]["slide"]["N"][i], c["N"], tr, c["N"], f"reaction.slide.N.{i}")
        near(r["reaction"]["slide"]["F"][i], c["F"], tr, c["N"], f"reaction.slide.F.{i}")
        near(r["reaction"]["rope"]["T"][i], [c["T"], c["T"]], tr, c["T"], f"reaction.rope.T.{i}")
        # the friction's work, 34.20: E(t) = E(0) + W_nc(t), W_nc = F s
        W = c["F"] * sdd * t * t / 2
        near(r["W_nc"][i], W, tm, 10, f"W_nc.{i}")
        near(r["E"][i] - r["E"][0], W, tm, 10, f"E.{i} - E.0")
    q = r["find"][0]
    assert q["reached"] is True
    near(q["t"], math.sqrt(2 / sdd), tm, 1, "find.0.t")
    near(q["x"]["B"][1], -0.5, tm, 1, "find.0.x.B.1")


# ---------------------------------------------------------------------------------------------
# 3. incline-pulley-sticks.yaml

def test_incline_pulley_sticks():
    rec = gallery("incline-pulley-sticks.yaml")
    r = rec["results"]
    ref = R.STICKS
    c = {k: f(v) for k, v in R.incline(ref["m1"], ref["m2"], ref["mu_s"], ref["mu_k"], ref["beta"]).items()}
    assert c["stuck"] == 1.0
    assert not [e for e in r["events"] if e["what"] in ("slips", "separates", "slack")], r["events"]
    b = math.radians(ref["beta"])
    x0 = {"A": [math.cos(b), math.sin(b), 0], "B": [3 * math.cos(b), 3 * math.sin(b) - 1, 0]}
    tm, tr = tols(rec)
    for i in range(len(r["t"])):
        for body in ("A", "B"):
            near(r["x"][body][i], x0[body], tm, 1, f"x.{body}.{i}")
            near(r["v"][body][i], [0, 0, 0], tm, 1, f"v.{body}.{i}")
            near(r["a"][body][i], [0, 0, 0], tm, G, f"a.{body}.{i}")
        near(r["reaction"]["slide"]["N"][i], c["N"], tr, c["N"], f"reaction.slide.N.{i}")
        near(r["reaction"]["slide"]["F"][i], c["F"], tr, c["N"], f"reaction.slide.F.{i}")
        near(r["reaction"]["rope"]["T"][i], [c["T"], c["T"]], tr, c["T"], f"reaction.rope.T.{i}")
        assert abs(r["reaction"]["slide"]["F"][i]) <= f(ref["mu_s"]) * r["reaction"]["slide"]["N"][i]


# ---------------------------------------------------------------------------------------------
# 4. sliding-ladder.yaml

def _ladder_state(t, theta0_deg, L):
    th, thd = R.ladder_motion(theta0_deg, L)(mp.mpf(t))
    return th, thd


def test_sliding_ladder_motion_and_reactions():
    name = "sliding-ladder.yaml"
    rec = gallery(name)
    r = rec["results"]
    assert r["dof"] == 1
    m, L, th0d = R.LADDER["m"], R.LADDER["L"], R.LADDER["theta0"]
    th0 = R.deg(th0d)
    ths, ts = R.ladder_release(th0, L)
    tm, tr = tols(rec, file_rtol(name))
    mg = m * G
    lagr = R.ladder_multipliers(m, L)
    for i, t in enumerate(r["t"]):
        if t > ts:          # past the separation: the floor-only phase (below)
            continue
        th, thd = _ladder_state(t, th0d, L)
        # the second formulation at the reference state (the hand formulas agree: test_references_agree)
        qdd, lam = lagr.solve([L / 2 * mp.cos(th), L / 2 * mp.sin(th), mp.pi - th],
                              [-L / 2 * mp.sin(th) * thd, L / 2 * mp.cos(th) * thd, -thd])
        near(r["angle"]["rod"][i], f(mp.pi - th), tm, math.pi, f"angle.rod.{i}")
        near(r["omega"]["rod"][i], [0, 0, f(-thd)], tm, math.sqrt(G / L), f"omega.rod.{i}")
        near(r["alpha"]["rod"][i], [0, 0, f(qdd[2])], tr, G / L, f"alpha.rod.{i}")
        near(r["x"]["rod"][i], [f(L / 2 * mp.cos(th)), f(L / 2 * mp.sin(th)), 0], tm, L, f"x.rod.{i}")
        near(r["v"]["rod"][i], [f(-L / 2 * mp.sin(th) * thd), f(L / 2 * mp.cos(th) * thd), 0], tm,
             math.sqrt(G * L), f"v.rod.{i}")
        near(r["a"]["rod"][i], [f(qdd[0]), f(qdd[1]), 0], tr, G, f"a.rod.{i}")
        near(r["reaction"]["at_wall"]["N"][i], f(lam["N_w"]), tr, mg, f"reaction.at_wall.N.{i}")
        near(r["reaction"]["at_floor"]["N"][i], f(lam["N_f"]), tr, mg, f"reaction.at_floor.N.{i}")
        assert r["reaction"]["at_wall"]["F"][i] in (0, None) and r["reaction"]["at_floor"]["F"][i] in (0, None)
        # the ends stay on their surfaces: foot on the floor, top on the wall
        near(r["point"]["rod"]["end1"]["x"][i], [f(L * mp.cos(th)), 0, 0], tm, L, f"point.rod.end1.x.{i}")
        near(r["point"]["rod"]["end2"]["x"][i], [0, f(L * mp.sin(th)), 0], tm, L, f"point.rod.end2.x.{i}")
    # at release, the hand closed forms
    near(r["reaction"]["at_wall"]["N"][0], 0.75 * mg * math.sin(math.pi / 3) * math.cos(math.pi / 3), tr, mg, "N_w(0)")
    near(r["reaction"]["at_floor"]["N"][0], mg * (1 - 0.75 * 0.25), tr, mg, "N_f(0)")
    # energy: smooth contacts do no work
    E0 = mg * L / 2 * math.sin(math.pi / 3)
    for i, t in enumerate(r["t"]):
        if t <= ts:
            near(r["E"][i], E0, tm, E0, f"E.{i}")


def test_sliding_ladder_slides_on_along_the_floor():
    """The second phase (the wall let go): against the floor-only formulation of refs_a (the
    momentum along e1 and Lagrange's equation in θ, mpmath at 30 digits)."""
    name = "sliding-ladder.yaml"
    rec = gallery(name)
    r = rec["results"]
    m, L = R.LADDER["m"], R.LADDER["L"]
    ts, vx, sol, floor = R.ladder_floor_phase(R.LADDER["theta0"], m, L)
    tm, tr = tols(rec, file_rtol(name))
    assert [p["joints"] for p in r["phases"]] == [["at_floor", "at_wall"], ["at_floor"]]
    later = [i for i, t in enumerate(r["t"]) if t > ts]
    assert later
    for i in later:
        th, thd = sol(mp.mpf(r["t"][i]))
        near(r["angle"]["rod"][i], f(mp.pi - th), tm, math.pi, f"angle.rod.{i}")
        near(r["omega"]["rod"][i], [0, 0, f(-thd)], tm, math.sqrt(G / L), f"omega.rod.{i}")
        near(r["v"]["rod"][i], [f(vx), f(L / 2 * mp.cos(th) * thd), 0], tm, math.sqrt(G * L), f"v.rod.{i}")
        near(r["x"]["rod"][i][1], f(L / 2 * mp.sin(th)), tm, L, f"x.rod.{i}.1")
        near(r["reaction"]["at_floor"]["N"][i], f(floor(th, thd)), tr, m * G, f"reaction.at_floor.N.{i}")
        assert r["reaction"]["at_wall"]["N"][i] == 0.0
        near(r["E"][i], r["E"][0], tm, r["E"][0], f"E.{i}")


def test_sliding_ladder_leaves_the_wall():
    name = "sliding-ladder.yaml"
    rec = gallery(name)
    r = rec["results"]
    m, L = R.LADDER["m"], R.LADDER["L"]
    th0 = R.deg(R.LADDER["theta0"])
    ths, ts = R.ladder_release(th0, L)
    tm, tr = tols(rec, file_rtol(name))
    assert len(r["events"]) == 1, r["events"]
    ev = r["events"][0]
    assert (ev["joint"], ev["what"]) == ("at_wall", "separates")
    # the event time: N_w crosses zero with slope dN_w/dt ~ mg/s, so the reaction tolerance in time
    near(ev["t"], f(ts), tr, 1, "events.0.t")
    st = ev["state"]
    near(st["angle"]["rod"], f(mp.pi - ths), tr, math.pi, "events.0.state.angle.rod")
    # sin θ* = (2/3) sin θ0 (cos φ* = (2/3) cos φ0 from the vertical)
    near(math.sin(math.pi - st["angle"]["rod"]), 2 / 3 * math.sin(math.pi / 3), tr, 1, "sin θ*")
    near(st["reaction"]["at_wall"]["N"], 0, tr, m * G, "events.0.state.reaction.at_wall.N")
    near(st["reaction"]["at_floor"]["N"], m * G / 4, tr, m * G, "events.0.state.reaction.at_floor.N")
    q = r["find"][0]
    assert q["reached"] is True
    near(q["t"], f(R.ladder_time(R.deg(50), th0, L)), tr, 1, "find.0.t")
    near(q["angle"]["rod"], math.radians(130), tm, math.pi, "find.0.angle.rod")


def test_sliding_ladder_route():
    """One degree of freedom with an energy integral (34.20): the energy quadrature is on request
    (accuracy.method: quadrature) in this release, the ODE route by default (docs/types/scene.md)."""
    r = gallery("sliding-ladder.yaml")["results"]
    assert r["route"] == "ode", r["route"]


# ---------------------------------------------------------------------------------------------
# 5. rolling-disk-spring.yaml

def test_rolling_disk_spring():
    rec = gallery("rolling-disk-spring.yaml")
    r = rec["results"]
    assert r["route"] == "closed-form" and r["dof"] == 1 and r["events"] == []
    D = R.DISK
    c0, _anc, d, _n = R.disk_start(**D)
    c0, d = [f(x) for x in c0], [f(x) for x in d]
    Rd, m = f(D["R"]), D["m"]
    tm, tr = tols(rec)
    lagr = R.disk_multipliers(**D)
    E0 = m * G * c0[1]
    for i, t in enumerate(r["t"]):
        c = {k_: f(v) for k_, v in R.disk_closed_form(mp.mpf(t), **D).items()}
        s, sd, sdd = c["s"], c["sd"], c["sdd"]
        near(r["x"]["disk"][i], [c0[0] - s * d[0], c0[1] - s * d[1], 0], tm, 1, f"x.disk.{i}")
        near(r["v"]["disk"][i], [-sd * d[0], -sd * d[1], 0], tm, c["delta"] * c["omega_n"], f"v.disk.{i}")
        near(r["a"]["disk"][i], [-sdd * d[0], -sdd * d[1], 0], tm, G, f"a.disk.{i}")
        near(r["angle"]["disk"][i], s / Rd, tm, 1, f"angle.disk.{i}")
        near(r["omega"]["disk"][i], [0, 0, sd / Rd], tm, c["delta"] * c["omega_n"] / Rd, f"omega.disk.{i}")
        near(r["alpha"]["disk"][i], [0, 0, sdd / Rd], tm, G / Rd, f"alpha.disk.{i}")
        near(r["reaction"]["roll"]["N"][i], c["N"], tr, c["N"], f"reaction.roll.N.{i}")
        near(r["reaction"]["roll"]["F"][i], c["F"], tr, c["N"], f"reaction.roll.F.{i}")
        near(r["reaction"]["roll"]["slip_margin"][i], f(D["mu_s"]) * c["N"] - abs(c["F"]), tr, c["N"],
             f"reaction.roll.slip_margin.{i}")
        near(r["force"]["spring"][i], c["spring"], tr, m * G, f"force.spring.{i}")
        near(r["E"][i], E0, tm, E0, f"E.{i}")
        # the second formulation at the same state
        _qdd, lam = lagr.solve([c0[0] - s * d[0], c0[1] - s * d[1], s / Rd], [-sd * d[0], -sd * d[1], sd / Rd])
        near(r["reaction"]["roll"]["F"][i], f(lam["F"]), tr, c["N"], f"reaction.roll.F.{i} (multipliers)")
    q = r["find"][0]
    c = R.disk_closed_form(0, **D)
    assert q["reached"] is True and q.get("at_end") is False
    near(q["t"], f(mp.pi / c["omega_n"]), tm, 1, "find.0.t")
    near(q["x"]["disk"][1], c0[1] - 2 * f(c["delta"]) * d[1], tm, 1, "find.0.x.disk.1")


# ---------------------------------------------------------------------------------------------
# 6. pulled-spool.yaml

def test_pulled_spool():
    name = "pulled-spool.yaml"
    rec = gallery(name)
    r = rec["results"]
    assert r["dof"] == 1 and r["events"] == []
    # the force acts at a point that turns with the spool: its generalized force depends on the
    # position only, so the motion has an energy integral; an ODE route is also exact to rtol
    assert r["route"] in ("quadrature", "ode"), r["route"]
    S = R.SPOOL
    m, P, Rs, rh = S["m"], S["P"], f(S["R"]), f(S["r"])
    tm, tr = tols(rec, file_rtol(name))
    sol = R.spool_motion()
    lagr = R.spool_multipliers(**S)
    vscale = 3.0
    for i, t in enumerate(r["t"]):
        x, v = sol(mp.mpf(t))
        a = R.spool_accel(x, **S)
        qdd, lam = lagr.solve([x, Rs, -x / Rs], [v, 0, -v / Rs])
        x, v, a = f(x), f(v), f(a)
        near(r["x"]["spool"][i], [x, Rs, 0], tm, 1, f"x.spool.{i}")
        near(r["v"]["spool"][i], [v, 0, 0], tm, vscale, f"v.spool.{i}")
        near(r["a"]["spool"][i], [a, 0, 0], tr, a, f"a.spool.{i}")
        near(r["angle"]["spool"][i], -x / Rs, tm, math.pi, f"angle.spool.{i}")
        near(r["omega"]["spool"][i], [0, 0, -v / Rs], tm, vscale / Rs, f"omega.spool.{i}")
        near(r["alpha"]["spool"][i], [0, 0, f(qdd[2])], tr, a / Rs, f"alpha.spool.{i}")
        near(r["reaction"]["roll"]["N"][i], f(lam["N"]), tr, m * G, f"reaction.roll.N.{i}")
        near(r["reaction"]["roll"]["F"][i], f(lam["F"]), tr, m * G, f"reaction.roll.F.{i}")
        near(r["reaction"]["roll"]["F"][i], m * a - P, tr, m * G, f"reaction.roll.F.{i} (29.5)")
        near(r["point"]["spool"]["hub"]["x"][i], [x + rh * math.sin(x / Rs), Rs + rh * math.cos(x / Rs), 0], tm, 1,
             f"point.spool.hub.x.{i}")
    # at t = 0 the closed form (1 + r/R) P / (m + Ī/R²)
    a0 = f(R.mpf(P * (1 + S["r"] / S["R"]) / (m + S["I"] / S["R"] ** 2)))
    near(r["a"]["spool"][0][0], a0, tr, a0, "a.spool.0.0")
    near(r["reaction"]["roll"]["F"][0], m * a0 - P, tr, m * G, "reaction.roll.F.0")
    q = r["find"][0]
    assert q["reached"] is True
    near(q["t"], f(R.spool_time(mp.mpf("0.5"), **S)), tr, 1, "find.0.t")
    near(q["x"]["spool"][0], 0.5, tm, 1, "find.0.x.spool.0")


def test_pulled_spool_force_entry_is_reported():
    """The named applied force is reported under force.pull at every time (a constant 20 N
    along e1; the lead's working contract says 'the magnitude' for force entries, §10 leaves
    the shape open: either shape is accepted here)."""
    r = gallery("pulled-spool.yaml")["results"]
    for val in r["force"]["pull"]:
        assert val in (20, [20, 0, 0]), val


# ---------------------------------------------------------------------------------------------
# edge cases of these scenes

ATWOOD_LIGHT = """
type: scene
params: {{m1: {m1}, m2: {m2}}}
bodies:
  A: {{shape: point, mass: m1, x: [-0.1, -10]}}
  B: {{shape: point, mass: m2, x: [0.1, -10.5]}}
joints:
  rope: {{cord: [A, {{pulley: [0, 0], radius: 0.1}}, B]}}
at: [0, 1]
"""


def test_atwood_mass_ratio_1e6_is_exact():
    """a = g (m1 − m2)/(m1 + m2) = g (1 − 2/(10⁶ + 1)) and T = 2 m1 m2 g/(m1 + m2), exact rationals.
    T is well-conditioned in the data (condition 1 in each input): a route computing it as
    m1 (g − a) would lose six digits to cancellation, and fails here by design."""
    rec = solve_one_text(ATWOOD_LIGHT.format(m1="1e6", m2=1))
    r = rec["results"]
    assert r["route"] == "closed-form" and r["dof"] == 1
    m1, m2 = sp.Integer(10**6), sp.Integer(1)
    a = f(R.G * (m1 - m2) / (m1 + m2))
    T = f(2 * m1 * m2 * R.G / (m1 + m2))
    assert a == pytest.approx(G * (1 - 2e-6 + 2e-12), rel=1e-15)
    for i, t in enumerate(r["t"]):
        near(r["a"]["A"][i], [0, -a, 0], CLOSED, a, f"a.A.{i}")
        near(r["a"]["B"][i], [0, a, 0], CLOSED, a, f"a.B.{i}")
        near(r["x"]["A"][i], [-0.1, -10 - a * t * t / 2, 0], CLOSED, 10, f"x.A.{i}")
        near(r["reaction"]["rope"]["T"][i], [T, T], CLOSED, T, f"reaction.rope.T.{i}")


def test_atwood_pulley_of_negligible_inertia():
    """Ī = 1e-12 kg·m²: T1 − T2 = Ī a/R² ≈ 2e-10 N, both tensions within 1e-12 of the closed form
    (the multipliers' linear solve resolves them: Ī/R² = 1e-10 kg beside 5 kg is well within a
    double's reach)."""
    text = """
type: scene
params: {m1: 3, m2: 2, R: 0.1}
bodies:
  pulley: {mass: 1, I: 1e-12, radius: R, x: [0, 0], angle: 0}
  A: {shape: point, mass: m1, x: ["-R", -1]}
  B: {shape: point, mass: m2, x: [R, -1.5]}
joints:
  axle: {pin: [pulley, ground]}
  rope: {cord: [A, pulley, B]}
at: [0, 1]
"""
    r = solve_one_text(text)["results"]
    assert r["route"] == "closed-form"
    c = R.atwood(3, 2, 1, sp.Rational(1, 10), I=sp.Rational(1, 10**12))
    T1, T2 = f(c["T1"]), f(c["T2"])
    for i in range(len(r["t"])):
        got1, got2 = r["reaction"]["rope"]["T"][i]
        near(got1, T1, CLOSED, T1, f"T1.{i}")
        near(got2, T2, CLOSED, T2, f"T2.{i}")
        # the difference itself, to rounding of T (~1e-14 N) — an equal-tension shortcut
        # (a light pulley) would give 0 and pass the line above, not this one
        assert abs((got1 - got2) - f(c["T1"] - c["T2"])) <= CLOSED * T1, (got1 - got2, f(c["T1"] - c["T2"]))
        near(r["a"]["A"][i], [0, -f(c["a"]), 0], CLOSED, G, f"a.A.{i}")
        near(r["reaction"]["axle"]["R"][i], [0, f(c["R_axle"]), 0], CLOSED, f(c["R_axle"]), f"axle.{i}")


BLOCK_AT_LIMIT = """
type: scene
params: {{m: 2, beta: "{beta}*deg"}}
surfaces:
  slope: {{through: [0, 0], direction: ["cos(beta)", "sin(beta)"]}}
bodies:
  A: {{shape: point, mass: m, x: ["cos(beta)", "sin(beta)"]}}
joints:
  slide: {{contact: [A, slope], mu_s: "{mu_s}", mu_k: 0.3}}
at: [0, 1]
"""


@pytest.mark.parametrize("beta, mu_s", [(30, "tan(beta)"), (45, "1"), (20, "tan(20*deg)")])
def test_block_exactly_at_the_stick_slip_limit_stays(beta, mu_s):
    """μ_s = tan β: the friction needed, m g sin β, equals μ_s N = tan β · m g cos β in exact
    arithmetic; in doubles the two may differ by an ulp either way (sin(π/4) and cos(π/4) do).
    Coulomb's static test holds with equality, so the block stays at rest, decided exactly (a
    rounding-level shortfall must not start a slide with μ_k = 0.3 < μ_s)."""
    rec = solve_one_text(BLOCK_AT_LIMIT.format(beta=beta, mu_s=mu_s))
    r = rec["results"]
    assert not [e for e in r["events"] if e["what"] in ("slips", "separates")], r["events"]
    c = {k: f(v) for k, v in R.block_limit(2, beta).items()}
    b = math.radians(beta)
    for i in range(len(r["t"])):
        near(r["x"]["A"][i], [math.cos(b), math.sin(b), 0], CLOSED, 1, f"x.A.{i}")
        near(r["v"]["A"][i], [0, 0, 0], CLOSED, 1, f"v.A.{i}")
        near(r["a"]["A"][i], [0, 0, 0], CLOSED, G, f"a.A.{i}")
        near(r["reaction"]["slide"]["N"][i], c["N"], CLOSED, c["N"], f"reaction.slide.N.{i}")
        near(r["reaction"]["slide"]["F"][i], c["F"], CLOSED, c["N"], f"reaction.slide.F.{i}")


def test_ladder_released_just_off_the_vertical_still_leaves_the_wall():
    """φ0 = 1e-6 rad from the vertical (N_w(0) = (3mg/4) sin θ0 cos θ0 ≈ 7.4e-5 N > 0): the ladder
    creeps off the unstable equilibrium for ~8 s and the wall still lets go at
    cos φ* = (2/3) cos φ0.  The time is checked loosely: the route's absolute tolerance on the
    angle (atol) is a relative error of atol/φ0 in the tiny initial deviation, which shifts the
    time by ~(atol/φ0)/λ, λ = sqrt(3g/2L) (the growth rate of the deviation): 1e-4 is 100 × that."""
    text = """
type: scene
params: {m: 10, L: 5, theta0: "pi/2 - 1e-6"}
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
  wall: {through: [0, 0], direction: [0, -1]}
bodies:
  rod: {shape: rod, mass: m, length: L, angle: "pi - theta0", x: ["L/2*cos(theta0)", "L/2*sin(theta0)"]}
joints:
  at_floor: {contact: [rod.end1, floor]}
  at_wall: {contact: [rod.end2, wall]}
at: [0, 10]
"""
    rec = solve_one_text(text)
    r = rec["results"]
    assert r["dof"] == 1
    assert r["reaction"]["at_wall"]["N"][0] == pytest.approx(0.75 * 10 * G * math.cos(math.pi / 2 - 1e-6), rel=1e-6)
    assert len(r["events"]) == 1, r["events"]
    ev = r["events"][0]
    assert (ev["joint"], ev["what"]) == ("at_wall", "separates")
    th0 = mp.pi / 2 - mp.mpf("1e-6")
    th = math.pi - ev["state"]["angle"]["rod"]            # θ* from the floor = φ* from the vertical's complement
    near(math.sin(th), f(2 * mp.sin(th0) / 3), REACTION_FACTOR * DEFAULT_RTOL, 1, "cos φ* = (2/3) cos φ0")
    ths, ts = R.ladder_release(th0, 5)
    near(ev["t"], f(ts), 1e-4, 1, "events.0.t")
    assert r["x"]["rod"][1] is not None    # t = 10 s: the motion goes on past the event (phases)
    assert r["phases"][0]["t_end"] == ev["t"] and r["phases"][1]["joints"] == ["at_floor"]
