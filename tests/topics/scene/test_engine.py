"""The scene engine's pieces against independent checks (never its own outputs):

* every element's Jacobian against central differences of its rows, and γ = −J̇q̇ against the
  second difference of φ along a motion (the rows' derivatives are written by hand);
* the multipliers against the free-body diagrams: Σ forces and moments on every body, with the
  reported joint forces, gravity and loads, equal m ā and Ī α (29.5, 32.15) — a second
  formulation of the balance laws, body by body;
* events null the later times, the views, the plots, the check solve's honesty.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import PROBLEMS, solve_one_text, solve_path

SCENES = sorted((PROBLEMS / "scenes").glob("*.yaml"))


def _system(text: str):
    from dyncli.loader import split_problems, validate
    from dyncli.topics.scene import prepare, solver
    from tests.conftest import ROOT

    problems, diags = split_problems("t.yaml", text.encode(), ROOT)
    assert not diags
    validate(problems[0])
    p = problems[0].model
    return prepare.setup(solver._plan(p))


LADDER_PEND = """
type: scene
params: {L: 2}
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  rod: {shape: rod, mass: 3, length: L}
  bob: {shape: point, mass: 1, v: [0.3, 0.2]}
  disk: {shape: disk, mass: 2, radius: 0.25, angle: 0.3, omega: -1.1}
joints:
  p: {pin: [rod.end2, [1.5, 1.2]]}
  l: {link: [bob, rod.end1], length: 1, angle: 2.5}
  c: {contact: [rod.end1, floor]}
  r: {rolls: [disk, floor], at: -1}
at: [0]
"""


def _fd_check(system, q, v):
    n = system.n
    for e in system.elements:
        J = e.jac(q)
        h = 1e-6
        Jfd = np.zeros_like(J)
        for k in range(n):
            dq = np.zeros(n)
            dq[k] = h
            Jfd[:, k] = (e.phi(q + dq, 0.0) - e.phi(q - dq, 0.0)) / (2 * h)
        assert np.allclose(J, Jfd, atol=1e-8), (e.kind, J, Jfd)
        # φ(q + v τ + ½ a τ²) with J a = γ: the second derivative along the path vanishes
        a = np.linalg.lstsq(J, e.gamma(q, v, 0.0), rcond=None)[0]
        tau = 1e-4
        f = [e.phi(q + v * s + 0.5 * a * s * s, 0.0) for s in (-tau, 0.0, tau)]
        second = (f[0] - 2 * f[1] + f[2]) / tau ** 2
        assert np.allclose(second, 0.0, atol=2e-5), (e.kind, second)


def test_jacobians_and_gamma_against_differences():
    sc = _system(LADDER_PEND.replace("at: [0]", "at: [0]\ng: 9.81"))
    rng = np.random.default_rng(1)
    for _ in range(5):
        q = sc.q0 + rng.normal(scale=0.3, size=sc.system.n)
        v = rng.normal(size=sc.system.n)
        _fd_check(sc.system, q, v)


def _balance(rec_results, k, bodies, joints, g=9.81):
    """Σ F = m ā and Σ M = Ī α on every body, from the reported joint forces (the free-body
    diagrams written again, independently of the engine's rows)."""
    r = rec_results
    force = {b: np.array([0.0, -bodies[b]["m"] * g]) for b in bodies}
    moment = {b: 0.0 for b in bodies}

    def apply(b, F, at):
        if b is None:
            return
        force[b] += F
        if at is not None:
            arm = np.array(at) - np.array(r["x"][b][k][:2])
            moment[b] += arm[0] * F[1] - arm[1] * F[0]

    for name, (kind, P, Q) in joints.items():
        rep = r["reaction"][name]
        if kind == "pin":
            R = np.array(rep["R"][k][:2])
            apply(P[0], R, P[1])
            apply(Q[0], -R, Q[1])
        elif kind == "link":
            d = np.array(P[1]) - np.array(Q[1])
            e = d / np.linalg.norm(d)
            T = rep["T"][k]
            apply(P[0], -T * e, P[1])
            apply(Q[0], T * e, Q[1])
        elif kind == "contact":
            n, dd = np.array(Q["n"]), np.array(Q["d"])
            apply(P[0], rep["N"][k] * n + rep["F"][k] * dd, P[1])
        elif kind == "rolls":
            n, dd = np.array(Q["n"]), np.array(Q["d"])
            c = np.array(r["x"][P][k][:2]) - Q["R"] * n
            apply(P, rep["N"][k] * n + rep["F"][k] * dd, c)
    for b, spec in bodies.items():
        ma = spec["m"] * np.array(r["a"][b][k][:2])
        assert np.allclose(force[b], ma, atol=1e-9 * max(1.0, np.abs(ma).max())), (b, force[b], ma)
        if spec.get("I") is not None:
            Ia = spec["I"] * r["alpha"][b][k][2]
            assert math.isclose(moment[b], Ia, abs_tol=1e-9 * max(1.0, abs(Ia))), (b, moment[b], Ia)


def test_multipliers_are_the_free_body_forces():
    rec = solve_one_text(LADDER_PEND.replace("at: [0]", "at: [0, 0.05]\naccuracy: {rtol: 1e-12}"))
    r = rec["results"]
    pts = r["point"]["rod"]
    for k in range(2):
        e1, e2 = pts["end1"]["x"][k][:2], pts["end2"]["x"][k][:2]
        bodies = {"rod": {"m": 3, "I": 3 * 4 / 12}, "bob": {"m": 1}, "disk": {"m": 2, "I": 2 * 0.25 ** 2 / 2}}
        floor = {"n": (0.0, 1.0), "d": (1.0, 0.0), "R": 0.25}
        joints = {"p": ("pin", ("rod", e2), (None, None)),
                  "l": ("link", ("bob", r["x"]["bob"][k][:2]), ("rod", e1)),
                  "c": ("contact", ("rod", e1), floor),
                  "r": ("rolls", "disk", floor)}
        _balance(r, k, bodies, joints)


def test_ladder_continues_past_the_wall_on_the_floor_alone():
    """Past the separation the ladder slides on the floor alone (a second phase): the later
    times are reported, the wall's N is 0 there, the horizontal momentum (no horizontal force
    once the wall lets go) and the energy (smooth floor) are kept."""
    rec = solve_path(PROBLEMS / "scenes" / "sliding-ladder.yaml")[0]
    r = rec["results"]
    t_ev = r["events"][0]["t"]
    assert [(p["joints"], p["route"]) for p in r["phases"]] == [(["at_floor", "at_wall"], "ode"), (["at_floor"], "ode")]
    assert r["phases"][0]["t_end"] == r["phases"][1]["t_start"] == t_ev
    assert [p["integrals"] for p in r["phases"]] == [["E"], ["E", "G.0"]]      # 34.20; 36.10 once the wall is gone
    st = r["events"][0]["state"]
    assert abs(st["reaction"]["at_wall"]["N"]) < 1e-6 * st["reaction"]["at_floor"]["N"]
    vx = st["v"]["rod"][0]
    for k, t in enumerate(r["t"]):
        assert r["x"]["rod"][k] is not None
        if t > t_ev:
            assert r["reaction"]["at_wall"]["N"][k] == 0.0
            assert abs(r["v"]["rod"][k][0] - vx) <= 1e-12 * abs(vx)
            assert abs(r["E"][k] - r["E"][0]) <= 1e-8 * abs(r["E"][0])
    assert not any("stops at t" in w for w in rec["warnings"])


def test_check_solve_is_honest_on_the_ladder():
    """accuracy.estimate: the estimate bounds the actual error against a tight solve."""
    text = (PROBLEMS / "scenes" / "sliding-ladder.yaml").read_text()
    loose = solve_one_text(text.replace("type: scene", "type: scene\naccuracy: {rtol: 1.0e-7, estimate: true}"))
    tight = solve_one_text(text.replace("type: scene", "type: scene\naccuracy: {rtol: 1.0e-13}"))
    err = abs(loose["results"]["events"][0]["t"] - tight["results"]["events"][0]["t"]) / tight["results"]["events"][0]["t"]
    assert loose["error_estimate"] is not None
    assert err <= loose["error_estimate"] * 1.01


@pytest.mark.parametrize("path", SCENES, ids=[p.name for p in SCENES])
def test_terminal_tables_read_like_the_notes(path):
    from tests.conftest import run_cli

    code, out, err = run_cli("solve", str(path))
    assert code == 0, err
    assert "bodies (centres on e1, e2)" in out
    assert "Traceback" not in out + err
    assert "'x':" not in out                 # no raw nesting in the tables


def test_plot_draws_the_mechanism_and_the_forces(tmp_path):
    from tests.conftest import run_cli

    png = tmp_path / "ladder.png"
    code, _, err = run_cli("solve", str(PROBLEMS / "scenes" / "sliding-ladder.yaml"), "--plot", str(png))
    assert code == 0, err
    assert png.exists() and png.stat().st_size > 10_000


def test_find_at_time_matches_the_requested_time():
    text = (PROBLEMS / "scenes" / "atwood-massive-pulley.yaml").read_text()
    rec = solve_one_text(text.replace("find: [", "find: [{t: 0.5}, "))
    r = rec["results"]
    assert r["find"][0]["reached"] is True
    assert r["find"][0]["x"]["A"] == r["x"]["A"][r["t"].index(0.5)]


def test_one_sided_spring_switches_without_stalling():
    """A point dropped onto a spring that only pushes: the spring switches on at its free length
    and off again on the way up (new phases, no event); the drop is free fall until then and the
    energy is kept through both switches (the phases restart exactly at the switch)."""
    rec = solve_one_text("""
type: scene
bodies:
  A: {shape: point, mass: 1, x: [0, 1]}
forces:
  - {spring: [A, [0, -1]], k: 1000, L: 1.5, one_sided: compression, name: pad}
at: [0, 0.3, 0.5, 1]
accuracy: {rtol: 1.0e-11}
""")
    r = rec["results"]
    assert r["events"] == []
    assert abs(r["x"]["A"][1][1] - (1 - 0.5 * 9.81 * 0.09)) < 1e-9          # still falling freely
    assert r["force"]["pad"][1] == 0.0
    E0 = r["E"][0]
    assert all(abs(E - E0) <= 1e-8 * abs(E0) for E in r["E"])


def test_a_block_held_by_friction_slips_when_the_push_exceeds_mu_s_N():
    """F = 5 t on a block at rest on a rough floor: it sticks (the static test) until
    5 t = μ_s m g, then slips (an event) and slides with kinetic friction μ_k N."""
    rec = solve_one_text("""
type: scene
surfaces:
  floor: {through: [0, 0], direction: [1, 0]}
bodies:
  A: {shape: point, mass: 2, x: [0, 0]}
joints:
  f: {contact: [A, floor], mu_s: 0.5, mu_k: 0.4}
forces:
  - {force: A, F: ["5*t", 0], name: push}
at: [0, 1, 3]
""")
    r = rec["results"]
    assert r["dof"] == 1 and r["route"] == "ode"
    ev = r["events"]
    assert [(e["joint"], e["what"]) for e in ev] == [("f", "slips")]
    assert abs(ev[0]["t"] - 0.5 * 2 * 9.81 / 5) <= 1e-9
    assert r["reaction"]["f"]["F"][1] == -5.0
    # sliding from t_s: m ẍ = 5 t − μ_k m g, from rest at x = 0
    ts, t = 0.5 * 2 * 9.81 / 5, 3.0
    x = 1.25 * ((t**3 - ts**3) / 3 - ts**2 * (t - ts)) - 0.4 * 9.81 * (t - ts) ** 2 / 2
    assert abs(r["x"]["A"][2][0] - x) <= 1e-7 * x
    assert abs(r["reaction"]["f"]["F"][2] + 0.4 * 2 * 9.81) <= 1e-12 * 8


def _solved_gallery(name: str):
    """The Result (its views' and plots' data included) of problems/scenes/NAME."""
    from dyncli import registry
    from dyncli.loader import split_problems, validate
    from dyncli.result import SolveOptions

    path = PROBLEMS / "scenes" / name
    (lp,), _ = split_problems(path.name, path.read_bytes(), path.parent)
    validate(lp)
    return registry.solver(lp.type)(lp.model, SolveOptions())


def test_the_drawing_puts_a_line_where_it_is_and_past_every_body_on_it():
    # a surface with a length is drawn from its `through` point to its end; one without runs past
    # every body drawn (the block landed beyond the dome's span used to lie off the drawn floor)
    from dyncli.topics.scene.plots import _mechanism

    def drawn(name):
        res = _solved_gallery(name)
        return res, {ln.label: ln for ln in _mechanism(res, res.extra["scene_draw"]).lines if ln.label}

    res, lines = drawn("block-off-dome.yaml")
    floor = lines["surface floor"]
    assert min(floor.x) < -2 and max(floor.x) > max(x[0] for x in res.results["x"]["P"])
    res, lines = drawn("block-on-table-pulley.yaml")      # table: through [-3, 0], length 3
    assert lines["surface table"].x == [-3.0, 0.0] and lines["surface table"].y == [0.0, 0.0]


def test_the_drawing_draws_every_cord_from_tangent_point_to_tangent_point():
    # the cords at each requested time: straight segments tangent to the pulleys and disks they
    # pass (the circles drawn already), a string over a round post with its wound arc on the post
    from dyncli.topics.scene.plots import _mechanism

    def solved(name):
        res = _solved_gallery(name)
        return res, res.extra["scene_draw"]["cords"]

    res, cords = solved("atwood-massive-pulley.yaml")        # R = 0.1 about the origin; A left, B right
    r = res.results
    assert len(cords) == len(r["t"])
    for j, lines in enumerate(cords):
        (a, ta), (tb, b) = lines
        assert a == pytest.approx(r["x"]["A"][j][:2], abs=1e-12) and b == pytest.approx(r["x"]["B"][j][:2], abs=1e-12)
        assert ta == pytest.approx((-0.1, 0.0), abs=1e-12) and tb == pytest.approx((0.1, 0.0), abs=1e-12)
    res, cords = solved("collar-pulled-up-rod.yaml")         # a point pulley at [b, H] = [0.8, 1.2]
    r = res.results
    for j, lines in enumerate(cords):
        (c, p1), (p2, w) = lines
        assert c == pytest.approx(r["x"]["collar"][j][:2], abs=1e-12) and w == pytest.approx(r["x"]["W"][j][:2], abs=1e-12)
        assert p1 == pytest.approx((0.8, 1.2), abs=1e-12) and p2 == pytest.approx((0.8, 1.2), abs=1e-12)
    res, cords = solved("ball-winds-onto-post.yaml")         # post ρ = 0.05 at the origin, tied at [-0.1, 0]
    r = res.results
    wound = 0
    for j, lines in enumerate(cords):
        (pts,) = lines
        assert pts[0] == pytest.approx((-0.1, 0.0)) and pts[-1] == pytest.approx(r["x"]["ball"][j][:2], abs=1e-12)
        on_post = pts[1:-1]
        wound += bool(on_post)
        assert all(math.hypot(*p) == pytest.approx(0.05, rel=1e-12) for p in on_post)
        if on_post:                      # the free part leaves the post on its tangent
            (t1, t2), (b1, b2) = on_post[-1], pts[-1]
            assert abs(t1 * (b1 - t1) + t2 * (b2 - t2)) <= 1e-9
    assert wound >= 2
    plot = _mechanism(res, res.extra["scene_draw"])
    assert [ln.label for ln in plot.lines].count("cords") == 1 and any(ln.style == "--" for ln in plot.lines)


@pytest.mark.parametrize("t_end", [0.5, 1.0, 3.0])
def test_a_bumper_between_two_carts_is_an_elastic_impact_whatever_the_span(t_end):
    """Two free carts (2 kg at 3 m/s, 3 kg at rest, 1 m apart, g = 0) and a compression-only
    spring between them (k = 1500 N/m, free length 0.4 m).  By hand: the spring comes on at
    t = 0.6/3 = 0.2 s, acts for half a period of the relative motion, π √(μ/k) with μ = 6/5 kg,
    and the carts leave with the elastic impact's velocities (m_A − m_B) v/(m_A + m_B) = −0.6 and
    2 m_A v/(m_A + m_B) = 2.4 m/s, the energy kept.  Before, over a long span the first step
    straddled the switch with the spring read by sign, the switch was found on the bent
    interpolant at 0.179 s, and 1 % of the energy was lost (t_end 1 and 3)."""
    import math

    rec = solve_one_text(f"""
type: scene
g: 0
bodies:
  A: {{shape: point, mass: 2, x: [0, 0], v: [3, 0]}}
  B: {{shape: point, mass: 3, x: [1, 0]}}
forces:
  - {{spring: [A, B], k: 1500, L: 0.4, one_sided: compression, name: bumper}}
at: [0, {t_end}]
accuracy: {{rtol: 1e-10}}
""")
    r = rec["results"]
    on, off = r["phases"][1]["t_start"], r["phases"][2]["t_start"]
    assert on == pytest.approx(0.2, rel=1e-9)
    assert off - on == pytest.approx(math.pi * math.sqrt(1.2 / 1500), rel=1e-7)
    assert r["v"]["A"][1][0] == pytest.approx(-0.6, rel=1e-7)
    assert r["v"]["B"][1][0] == pytest.approx(2.4, rel=1e-7)
    assert abs(r["energy_residual"][1]) <= 1e-7 * 9.0


def test_an_energy_balance_off_beyond_the_estimate_is_warned():
    """outcome._energy_check: a residual E − E₁ − W_nc beyond 100 × the error estimate of the
    energy's scale is warned (naming the time, the size and the fix); within it, silent; a
    closed form (exact) is never checked."""
    from dyncli.result import Result
    from dyncli.topics.scene.outcome import _energy_check

    def res(resid, est, route="ode"):
        r = Result({"t": [0.0, 1.0], "T": [9.0, 8.9], "V": [0.0, 0.0], "E": [9.0, 8.9], "W_nc": [0.0, 0.0],
                    "energy_residual": [0.0, resid]}, error_estimate=est)
        _energy_check(r, route)
        return r.warnings

    (w,) = res(-0.1033, 2.5e-9)
    assert "off by 0.103 J at t = 1 s" in w and "accuracy.rtol" in w
    assert res(1e-9, 2.5e-9) == []
    assert res(-0.1033, 2.5e-9, "closed-form") == []
