"""``--symbolic`` for scenes: the equations in the notes' form.

Each reduced equation is checked (a) against a hand derivation written here with sympy (the
textbook's free-body or energy derivation, never the code under test) and (b) against the
numeric engine's acceleration (or drive couple) at a state of the motion.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

sp = pytest.importorskip("sympy")

from dyncli.loader import load_paths  # noqa: E402
from dyncli.topics.scene import prepare, solver  # noqa: E402
from dyncli.topics.scene.symbolic import derive  # noqa: E402
from tests.conftest import PROBLEMS  # noqa: E402

SCENES = PROBLEMS / "scenes"


def _derive(name: str):
    (lp,), diags = load_paths([str(SCENES / name)])
    assert not diags
    p = lp.model
    scene = prepare.setup(solver._plan(p))
    exprs = {"drive": {n: j.value for n, j in p.joints.items() if j.kind == "drive"},
             "load": {i: (f.F if f.kind == "force" else [f.M]) for i, f in enumerate(p.forces)
                      if f.kind in ("force", "torque")}}
    return derive(scene, exprs), scene


def _sym(D, text: str):
    return next(s for s, t in D.S.text.items() if t == text)


def _values(D, scene, q=None, v=None):
    q = scene.q0 if q is None else q
    v = scene.v0 if v is None else v
    out = dict(D.S.values)
    out.update({s: float(x) for s, x in zip(D.C.q, q)})
    out.update({s: float(x) for s, x in zip(D.C.qd, v)})
    return out


def _sdd(D, sub: dict) -> list[float]:
    """The accelerations of the chosen coordinates from the reduced equations at a state."""
    sdd = [D.C.qdd[j] for j in D.independent]
    eqs = [(e.lhs - e.rhs).subs(sub) for e in D.reduced]
    sol = sp.solve(eqs, sdd, dict=True)[0]
    return [float(sol[a]) for a in sdd]


def _engine_check(D, scene):
    a, _lam, _ = scene.system.solve(scene.q0, scene.v0, 0.0)
    got = _sdd(D, _values(D, scene))
    want = [a[j] for j in D.independent]
    assert np.allclose(got, want, rtol=1e-10, atol=1e-12 * max(1.0, max(abs(w) for w in want)))


def test_atwood_massive_pulley():
    """(Ī + (m_A + m_B) r²) θ̈ = (m_A − m_B) g r: A hangs on the left, so A going down turns the pulley
    counterclockwise; the rope's two tensions differ by Ī θ̈ / r (32.15)."""
    D, scene = _derive("atwood-massive-pulley.yaml")
    th, mA, mB, I, r, g = (_sym(D, n) for n in ("θ_pulley", "m_A", "m_B", "Ī_pulley", "r_pulley", "g"))
    thdd = _sym(D, "θ̈_pulley")
    (eq,) = D.reduced
    hand = (I + (mA + mB) * r ** 2) * thdd - (mA - mB) * g * r
    assert sp.simplify(eq.lhs - eq.rhs - hand) == 0
    T1, T2 = _sym(D, "T_rope,1"), _sym(D, "T_rope,2")
    rot = next(e for e in D.balance if e.label.startswith("pulley (32.15)"))
    assert sp.simplify(rot.rhs - r * (T1 - T2)) == 0
    assert D.energy and sp.simplify(D.energy[0].lhs.diff(th)) != 0
    _engine_check(D, scene)


def test_compound_pendulum():
    """(Ī + m L²/4) θ̈ = −m g (L/2) cos θ (θ of the bar from e1, pivot at end1); energy (34.20)."""
    D, scene = _derive("compound-pendulum.yaml")
    th, thd, thdd = (_sym(D, n) for n in ("θ_bar", "θ̇_bar", "θ̈_bar"))
    m, I, L, g = (_sym(D, n) for n in ("m_bar", "Ī_bar", "L_bar", "g"))
    (eq,) = D.reduced
    hand = (I + m * L ** 2 / 4) * thdd + m * g * L / 2 * sp.cos(th)
    assert sp.simplify(eq.lhs - eq.rhs - hand) == 0
    E = D.energy[0]
    hand_E = (I + m * L ** 2 / 4) * thd ** 2 / 2 + m * g * L / 2 * sp.sin(th)
    assert sp.simplify(E.lhs - hand_E) == 0
    assert sp.simplify(E.rhs - m * g * L / 2 * sp.sin(-sp.pi / 6)) == 0
    _engine_check(D, scene)


def test_sliding_ladder():
    """Smooth wall and floor: the centre is (−L/2 cos θ, L/2 sin θ), so (Ī + m L²/4) θ̈ = −m g (L/2) cos θ;
    the balance laws carry the floor's and the wall's N by name."""
    D, scene = _derive("sliding-ladder.yaml")
    th, thdd = _sym(D, "θ_rod"), _sym(D, "θ̈_rod")
    m, I, L, g = (_sym(D, n) for n in ("m_rod", "Ī_rod", "L_rod", "g"))
    (eq,) = D.reduced
    assert sp.simplify(eq.lhs - eq.rhs - ((I + m * L ** 2 / 4) * thdd + m * g * L / 2 * sp.cos(th))) == 0
    Nf, Nw = _sym(D, "N_at_floor"), _sym(D, "N_at_wall")
    laws = {e.label: e.rhs for e in D.balance}
    assert sp.simplify(laws["rod (29.5), e1"] - Nw) == 0
    assert sp.simplify(laws["rod (29.5), e2"] - (Nf - m * g)) == 0
    _engine_check(D, scene)


def test_rolling_disk_on_incline_with_spring():
    """Rolling (15.8): the centre moves −r θ along the slope; the spring lies along the slope with its
    anchor s0 + L0 from the slope's origin, so ℓ = L0 + r θ (the centre starts at s0) and
    (Ī + m r²) θ̈ = r (m g sin β − k (ℓ − L0)) = r (m g sin β − k r θ)."""
    D, scene = _derive("rolling-disk-spring.yaml")
    th, thdd = _sym(D, "θ_disk"), _sym(D, "θ̈_disk")
    m, I, r, g, k = (_sym(D, n) for n in ("m_disk", "Ī_disk", "r_disk", "g", "k_spring"))
    (eq,) = D.reduced
    hand = (I + m * r ** 2) * thdd - r * (m * g * sp.sin(sp.pi / 6) - k * r * th)
    resid = (eq.lhs - eq.rhs - hand).subs({s: v for s, v in D.S.values.items()})
    for x in (-0.7, 0.0, 0.3, 1.1):              # the geometry's numbers mix with r: compare at states
        for a in (-2.0, 5.0):
            assert abs(float(resid.subs({th: x, thdd: a}))) < 1e-9
    _engine_check(D, scene)


def test_slider_crank_drive_couple():
    """The crank's couple from the reduced equation (the drive's row left out) against the power
    balance M ω = d(T + V)/dt written by hand (θ = ωt, sin φ = −(r/l) sin θ) and against the engine's
    drive results at the requested times."""
    D, scene = _derive("slider-crank.yaml")
    (eq,) = D.reduced
    assert D.S.text[eq.lhs] == "M_motor"
    r, l, w = 0.1, 0.35, 10.0
    m1, m2, m3, g = 0.5, 1.0, 2.0, 9.81
    I1, I2 = m1 * r ** 2 / 12, m2 * l ** 2 / 12
    t = sp.Symbol("t")
    th = w * t
    phi = sp.asin(-r / l * sp.sin(th))
    crank = sp.Matrix([r / 2 * sp.cos(th), r / 2 * sp.sin(th)])
    pin = sp.Matrix([r * sp.cos(th), r * sp.sin(th)])
    rod = pin + l / 2 * sp.Matrix([sp.cos(phi), sp.sin(phi)])
    slider = pin + l * sp.Matrix([sp.cos(phi), sp.sin(phi)])
    T = sum((m * (c.diff(t).T * c.diff(t))[0] / 2 for m, c in ((m1, crank), (m2, rod), (m3, slider))))
    T += I1 * w ** 2 / 2 + I2 * sp.diff(phi, t) ** 2 / 2
    V = g * (m1 * crank[1] + m2 * rod[1] + m3 * slider[1])
    M_hand = sp.diff(T + V, t) / w
    (lp,), _ = load_paths([str(SCENES / "slider-crank.yaml")])
    res = solver.solve(lp.model).results
    ang = {s: _sym(D, s) for s in ("θ_crank", "θ_conrod")}
    for i, ti in enumerate(res["t"]):
        sub = dict(D.S.values)
        sub[ang["θ_crank"]] = res["angle"]["crank"][i]
        sub[ang["θ_conrod"]] = res["angle"]["conrod"][i]
        got = float(eq.rhs.subs(sub))
        assert got == pytest.approx(float(M_hand.subs(t, ti)), rel=1e-9, abs=1e-9)
        assert got == pytest.approx(res["drive"]["motor"][i], rel=1e-8, abs=1e-9)
    assert D.closure, "θ_conrod is tied to θ_crank by the loop's closure"


@pytest.mark.parametrize("name", ["double-pendulum.yaml", "cart-pendulum.yaml", "yo-yo.yaml", "falling-rod.yaml",
                                  "pulled-spool.yaml", "incline-pulley-slides.yaml", "block-on-wedge.yaml",
                                  "drum-on-plank.yaml", "collar-pulled-up-rod.yaml"])
def test_reduced_equations_match_the_engine(name):
    """Any scene: the reduced equations give the engine's accelerations at t = 0 (a second
    formulation: the engine solves the full system with the multipliers)."""
    D, scene = _derive(name)
    if not D.reduced:
        pytest.skip("no degree of freedom")
    sub = _values(D, scene)
    for e in D.laws:                                  # kinetic friction's N: the engine's multiplier
        if e.rel == "=" and e.lhs.name.startswith("F_"):
            _a, lam, _ = scene.system.solve(scene.q0, scene.v0, 0.0)
            el = next(x for x in scene.system.elements if x.name == e.lhs.name[2:])
            k = scene.system.elements.index(el)
            sub[_sym(D, f"N_{el.name}")] = float(scene.system.lam_of(lam, k)[0])
    a, _lam, _ = scene.system.solve(scene.q0, scene.v0, 0.0)
    got = _sdd(D, sub)
    want = [a[j] for j in D.independent]
    assert np.allclose(got, want, rtol=1e-9, atol=1e-9 * max(1.0, max(abs(x) for x in want)))


def test_block_on_a_sliding_wedge():
    """A surface carried by a body (the wedge's slope): the reduced equations give the
    textbook's wedge acceleration A = m g sin α cos α/(M + m sin² α) (the block's and the
    wedge's momentum and the block's normal acceleration, by hand) and the block's slide
    relative to the wedge s̈ = (M + m) g sin α/(M + m sin² α), α = 30°, m = 1, M = 4."""
    D, scene = _derive("block-on-wedge.yaml")
    assert len(D.reduced) == 2 and any(e.label == "on_slope" for e in D.constraints)
    sub = _values(D, scene)
    g, m, M, al = 9.81, 1.0, 4.0, math.pi / 6
    A = m * g * math.sin(al) * math.cos(al) / (M + m * math.sin(al) ** 2)
    sdd = (M + m) * g * math.sin(al) / (M + m * math.sin(al) ** 2)
    got = dict(zip([scene.system.names[j] for j in D.independent], _sdd(D, sub)))
    assert got["x.wedge.0"] == pytest.approx(A, rel=1e-12)
    assert got["x.block.0"] - got["x.wedge.0"] == pytest.approx(-sdd * math.cos(al), rel=1e-12)


def test_collar_on_a_spun_rough_rod():
    """A line carried by a turning body (the spun rod) with a rough contact on it: the reduced
    equation along the collar's coordinate, at a state of the hand solution (t = 0.2 s: r, ṙ of
    the closed form in the file's header, θ = ω t), gives the collar's acceleration of the polar
    free-body diagram: a = (r̈ − ω² r) e_r + 2 ω ṙ e_θ with r̈ = ω² r − μ N/m, N = 2 m ω ṙ."""
    D, scene = _derive("rough-collar-on-spun-rod.yaml")
    names = scene.system.names
    m, mu, w, L, r0, t = 0.5, 0.3, 4.0, 2.0, 0.5, 0.2
    s1, s2 = w * (-mu + math.sqrt(1 + mu * mu)), w * (-mu - math.sqrt(1 + mu * mu))
    A = r0 * -s2 / (s1 - s2)
    r = A * math.exp(s1 * t) + (r0 - A) * math.exp(s2 * t)
    rd = A * s1 * math.exp(s1 * t) + (r0 - A) * s2 * math.exp(s2 * t)
    th = w * t
    N = 2 * m * w * rd
    rdd = w * w * r - mu * N / m
    c, sn = math.cos(th), math.sin(th)
    state = {"x.rod.0": (L / 2 * c, -L / 2 * w * sn), "x.rod.1": (L / 2 * sn, L / 2 * w * c), "angle.rod": (th, w),
             "x.collar.0": (r * c, rd * c - r * w * sn), "x.collar.1": (r * sn, rd * sn + r * w * c)}
    sub = _values(D, scene, [state[n][0] for n in names], [state[n][1] for n in names])
    sub[_sym(D, "N_sleeve")] = N
    sub[D.C.qdd[names.index("angle.rod")]] = 0.0
    (eq,) = [e for e in D.reduced if "(the drive's force)" not in e.label]
    k = D.independent[[names[j] for j in D.independent].index("x.collar.0")]
    (got,) = sp.solve((eq.lhs - eq.rhs).subs(sub), D.C.qdd[k])
    assert float(got) == pytest.approx((rdd - w * w * r) * c - 2 * w * rd * sn, rel=1e-12)


def _reduced_matches_engine_away_from_start(text: str, moved: dict, rates: dict) -> None:
    """The reduced equations of the scene ``text`` give the engine's accelerations at a state away
    from the start: the coordinates ``moved`` placed (the rest by the joints), ``rates`` given."""
    from dyncli.loader import split_problems, validate
    from tests.conftest import ROOT

    (lp,), _ = split_problems("t.yaml", text.encode(), ROOT)
    validate(lp)
    scene = prepare.setup(solver._plan(lp.model))
    D = derive(scene, {})
    q, v = scene.q0.copy(), scene.v0.copy()
    names = scene.system.names
    for k, x in moved.items():
        q[names.index(k)] = x
    q = scene.system.project_position(q, 0.0)
    for k, x in rates.items():
        v[names.index(k)] = x
    v = scene.system.project_velocity(q, v, 0.0)
    a, _lam, _ = scene.system.solve(q, v, 0.0)
    got = _sdd(D, _values(D, scene, q, v))
    want = [a[j] for j in D.independent]
    assert np.allclose(got, want, rtol=1e-9, atol=1e-12), (got, want)


def test_a_cord_segment_turning_over_a_round_pulley():
    """A segment from a pulley of radius 0.1 to a block on a table below its level turns with the
    block (√(D² − ρ²) + c (ψ − ψ0), the arc included): the reduced equation gives the engine's
    acceleration at a state away from the start (the segment steeper, the block moving; the
    rope's other end placed by the cord)."""
    from tests.topics.scene.common import TABLE_PULLEY

    _reduced_matches_engine_away_from_start(TABLE_PULLEY % ("-2", "0.1", "[0]"), {"x.A.0": -0.6}, {"x.A.0": 1.5})


def test_a_moving_pulley_whose_segments_lean():
    """A disk hanging in a loop whose strands lean (elements.Spanning: ℓ + (ρ_b − ρ_a)(ψ − ψ0)
    less the disk's turn, per segment): the reduced equations give the engine's accelerations at a
    state away from the start (the disk moved aside and up, everything moving)."""
    from tests.topics.scene.test_turning_cords import LOOP

    _reduced_matches_engine_away_from_start(LOOP, {"x.P.0": 0.16, "x.P.1": -0.8}, {"x.P.0": 0.3, "angle.P": 4.0})


def test_cli_text_and_latex():
    from tests.conftest import run_cli

    code, out, err = run_cli("solve", str(SCENES / "compound-pendulum.yaml"), "--symbolic", env={"COLUMNS": "200"})
    assert code == 0, err
    assert "(L_bar² m_bar/4 + Ī_bar) θ̈_bar = -L_bar g m_bar cos(θ_bar)/2" in out
    assert "no symbolic view" not in err
    code, tex, err = run_cli("solve", str(SCENES / "compound-pendulum.yaml"), "--symbolic", "--format", "latex")
    assert code == 0, err
    assert r"\ddot{\theta}_{\mathrm{bar}}" in tex and tex.isascii()


def test_bowl_and_loop_in_the_curve_parameter():
    """On a curve the contact point's parameter is the coordinate: a disk rolling in a bowl of
    radius R, (R − r)² (m + Ī/r²) q̈ = −m g (R − r) sin q; a block in a loop, m R² q̈ = −m g R sin q
    (the bead on a wire); each against the engine's tangential acceleration along the motion."""
    for name, R, rad in (("ball-in-bowl.yaml", sp.Rational(1, 2), "r_ball"), ("loop-the-loop.yaml", sp.Rational(1, 2), None)):
        D, scene = _derive(name)
        (eq,) = D.reduced
        body = "ball" if rad else "block"
        joint = "roll" if rad else "track"
        qc, qdd = _sym(D, f"q_{joint}"), _sym(D, f"q̈_{joint}")
        m, g = _sym(D, f"m_{body}"), _sym(D, "g")
        if rad:
            r, I = _sym(D, rad), _sym(D, "Ī_ball")
            hand = (R - r) ** 2 * (m + I / r ** 2) * qdd + m * g * (R - r) * sp.sin(qc)
        else:
            hand = m * R ** 2 * qdd + m * g * R * sp.sin(qc)
        assert sp.simplify(eq.lhs - eq.rhs - hand) == 0, name
        (lp,), _ = load_paths([str(SCENES / name)])
        res = solver.solve(lp.model).results
        for k in range(2):
            x, a = res["x"][body][k], res["a"][body][k]
            centre_y = 0.0 if rad else 0.5
            phi = math.atan2(x[0], centre_y - x[1])
            tangent = (math.cos(phi), math.sin(phi))
            rho = math.hypot(x[0], centre_y - x[1])          # the path's radius: R − r, or R
            sub = dict(D.S.values)
            sub[qc] = phi
            want = (a[0] * tangent[0] + a[1] * tangent[1]) / rho
            got = float(sp.solve((eq.lhs - eq.rhs).subs(sub), qdd)[0])
            assert got == pytest.approx(want, rel=1e-9, abs=1e-9)
