"""Scene gallery B (problems/scenes/): the compound pendulum, the rod falling on a smooth floor,
the yo-yo, the double pendulum, the pendulum on a spring-held cart, the slider-crank and the
four-bar — motion AND joint forces against references computed here by an independent route
(refs_b.py, never dyncli): hand closed forms, Jacobi elliptic functions, Lagrange's equations in
minimal coordinates (sympy) integrated at 30 digits by an mpmath extrapolation integrator (checked
against mpmath.odefun to 1e-28 while writing it), the energy quadrature, loop closure by mpmath
findroot, and a Newton-Euler linear solve of the free-body diagrams for the joint forces (the
drive couples also by virtual power).  Then the edge cases of these scenes: the compound pendulum
released 1e-6 rad from upright, a four-bar 1e-6 m from its toggle.

Tolerances, relative to each quantity's scale (its largest magnitude among the values compared):

* exact routes (``route`` closed-form, kinematics, statics): 1e-10 — rounding (~1e-16) times
  the modest condition numbers of these mechanisms, with a wide margin;
* numerical routes (quadrature, ode): 1000 × the file's rtol.  docs/accuracy.md: an ODE route's
  global error is 1-100 × rtol of the state's scale; the reactions are one derivative above the
  state (solved from (q, v)) and carry its error times their sensitivity to (q, v), about 10 here;
  the event/extreme times carry the state's error divided by the crossing rate, again O(1) here.
  A route that reports a larger ``error_estimate`` is held to twice that instead (it said so).
* the references agree with each other to 1e-20 or better (test_references_agree), so every
  tolerance above is the engine's alone.
"""

from __future__ import annotations

import functools
import re

import pytest
import yaml
from mpmath import mp, mpf

from tests.conftest import PROBLEMS, lookup, run_cli
from tests.topics.scene.common import gallery
from tests.topics.scene import refs_b as R

SCENES = PROBLEMS / "scenes"
EXACT = 1e-10
NUMERICAL_FACTOR = 1000
DEFAULT_RTOL = 1e-10
EXACT_ROUTES = ("closed-form", "kinematics", "statics")


# ------------------------------------------------------------------------------------ the files
# Each case: the file's params exactly as written (the test refuses to drift from the file), the
# requested times, the expected degrees of freedom and route(s), and the reference.

def _compound():
    return R.compound_pendulum_case(2, "1.2", -mp.pi / 6, [0, "0.25", "0.5", "1.0"])


def _falling_rod():
    return R.falling_rod_case("1.5", 1, 20 * mp.pi / 180, [0, "0.1", "0.2", "0.3"], mp.pi / 4)


def _yoyo():
    out, _a, _T = R.yoyo_case("0.2", "0.05", "0.01", "0.01", "-0.5", [0, "0.5", 1], "-1.5")
    return out


def _double():
    out, _traj = R.double_pendulum_case(1, 2, 1, "0.7", mp.pi / 3, mp.pi / 9, [0, "0.5", 1, "1.5"], "1.5")
    return out


def _cart():
    out, _traj = R.cart_pendulum_case(2, "0.5", "0.6", 40, "0.8", -1, 0, 1, (0, "-0.1"), 40 * mp.pi / 180,
                                      [0, "0.5", 1, "1.5"], "1.5")
    return out


def _slider_crank():
    return R.slider_crank_case("0.1", "0.35", 10, "0.5", 1, 2, ("0.1", "0.05"), [0, "0.05", "0.1", "0.2"],
                               mp.pi / 3)


def _four_bar():
    return R.four_bar_case("0.3", mp.sqrt(mpf("0.26")), "0.4", "0.5", 5, mp.pi / 2, ("0.6", 1, "0.8"),
                           [0, "0.1", "0.2"], (mp.atan(mpf("0.2")), mp.pi / 2))


CASES = {
    "compound-pendulum.yaml": ({"m": 2, "L": 1.2, "th0": "-30*deg"}, [0, 0.25, 0.5, 1.0], 1,
                               ("quadrature", "ode"), _compound),
    # two degrees of freedom by rank (x̄1 and the angle; x̄1 stays put by the momentum integral)
    "falling-rod.yaml": ({"m": 1.5, "L": 1, "b0": "20*deg"}, [0, 0.1, 0.2, 0.3], 2, ("quadrature", "ode"),
                         _falling_rod),
    # the cord hangs vertical from rest; the engine may also keep the disk's swinging freedom (2 DOF,
    # then an ODE route) — the motion is the same closed form either way
    "yo-yo.yaml": ({"m": 0.2, "R": 0.05, "r": 0.01}, [0, 0.5, 1], (1, 2), ("closed-form", "ode"), _yoyo),
    "double-pendulum.yaml": ({"m1": 1, "m2": 2, "L1": 1, "L2": 0.7, "p1": "60*deg", "p2": "20*deg"},
                             [0, 0.5, 1, 1.5], 2, ("ode",), _double),
    "cart-pendulum.yaml": ({"M": 2, "m": 0.5, "l": 0.6, "k": 40, "p0": "40*deg"}, [0, 0.5, 1, 1.5], 2,
                           ("ode",), _cart),
    "slider-crank.yaml": ({"r": 0.1, "l": 0.35, "w": 10, "m1": 0.5, "m2": 1, "m3": 2}, [0, 0.05, 0.1, 0.2], 0,
                          ("kinematics",), _slider_crank),
    "four-bar.yaml": ({"a": 0.3, "b": "sqrt(0.26)", "c": 0.4, "d": 0.5, "w": 5, "m2": 0.6, "m3": 1, "m4": 0.8},
                      [0, 0.1, 0.2], 0, ("kinematics",), _four_bar),
}


@functools.lru_cache(maxsize=None)
def reference(name):
    with mp.workdps(30):
        out = CASES[name][4]()
    return {k: v for k, v in out.items() if not k.startswith("_")}


def file_data(name):
    return yaml.safe_load((SCENES / name).read_text(encoding="utf-8"))


def file_rtol(name) -> float:
    return float((file_data(name).get("accuracy") or {}).get("rtol", DEFAULT_RTOL))


def tolerance(rec, rtol):
    """The relative tolerance for a record (module docstring)."""
    if rec["results"]["route"] in EXACT_ROUTES:
        return EXACT
    est = rec.get("error_estimate")
    return max(NUMERICAL_FACTOR * rtol, 2 * est if isinstance(est, (int, float)) else 0.0)


def compare(res, ref, rel, skip=()):
    """Every reference path against the results; scale = the largest |reference| of the family
    (refs_b.family: the same quantity at every time and find answer; 1 where it is 0 throughout)."""
    scales = {}
    for k, v in ref.items():
        fam = R.family(k)
        scales[fam] = max(scales.get(fam, 0.0), abs(float(v)))
    bad = []
    for k, v in sorted(ref.items()):
        if any(k.startswith(s) for s in skip):
            continue
        got = lookup(res, k)
        want = float(v)
        scale = scales[R.family(k)] or 1.0       # a quantity that is zero throughout: absolute
        if not isinstance(got, (int, float)) or isinstance(got, bool):
            bad.append(f"{k}: {got!r}, expected {want:.12g}")
        elif abs(got - want) > rel * scale:
            bad.append(f"{k}: {got:.15g}, expected {want:.15g} (off {abs(got - want) / scale:.2g} of its scale)")
    assert not bad, f"{len(bad)} of {len(ref)} values off (rel {rel:g}):\n  " + "\n  ".join(bad[:40])


# ------------------------------------------------------------------------------------ the tests


@pytest.mark.parametrize("name", sorted(CASES))
def test_file_matches_the_reference_inputs(name):
    """The file's params and times are the ones the reference is computed for."""
    params, at, *_ = CASES[name]
    data = file_data(name)
    assert data["type"] == "scene"
    assert data["params"] == params
    assert [float(t) for t in data["at"]] == [float(t) for t in at]


@pytest.mark.parametrize("name", sorted(CASES))
def test_dof_route_and_no_event(name):
    _p, _at, dof, routes, _f = CASES[name]
    res = gallery(name)["results"]
    assert res["dof"] in (dof if isinstance(dof, tuple) else (dof,)), res["dof"]
    assert res["route"] in routes, res["route"]
    assert res["events"] == [], res["events"]
    assert all(f.get("reached") for f in res.get("find", [])), res.get("find")


@pytest.mark.parametrize("name", sorted(CASES))
def test_motion_and_joint_forces(name):
    """Motion (x, v, a, angle, omega, alpha), joint forces (reaction.*), drive couples, named
    forces, T and V at every requested time and at every find answer."""
    rec = gallery(name)
    compare(rec["results"], reference(name), tolerance(rec, file_rtol(name)))


@pytest.mark.parametrize("name", sorted(CASES))
def test_energy_balance(name):
    """E = T + V, and without drives or dampers E stays at its initial value (34.20)."""
    rec = gallery(name)
    res = rec["results"]
    rel = tolerance(rec, file_rtol(name))
    E = res["E"]
    scale = max(max(abs(t) for t in res["T"]), max(abs(v) for v in res["V"]))
    for i in range(len(E)):
        assert abs(E[i] - res["T"][i] - res["V"][i]) <= rel * scale
    if "drive" not in res or not res["drive"]:
        assert max(abs(e - E[0]) for e in E) <= rel * scale


def test_references_agree():
    """The second routes of the references: the falling rod's ODE against its quadrature
    inversion, the compound pendulum's elliptic functions against an integration, the drive
    couple's Newton-Euler against virtual power (asserted inside refs_b.four_bar_case), the
    closed forms at release and at the bottom against the general state, the slider-crank's
    derivatives against the hand-differentiated formulas, the four-bar's extremes against the law
    of cosines."""
    with mp.workdps(30):
        tiny = mpf(10) ** -20
        # compound pendulum: release and bottom closed forms vs the elliptic state
        ref = reference("compound-pendulum.yaml")
        al, Rv = R.compound_pendulum_release(2, "1.2", -mp.pi / 6)
        assert abs(ref["alpha.bar.0.2"] - al) < tiny and abs(ref["reaction.pivot.R.0.0"] - Rv[0]) < tiny
        wb, Rb = R.compound_pendulum_bottom(2, "1.2", -mp.pi / 6)
        assert abs(ref["find.0.omega.bar.2"] - wb) < tiny and abs(ref["find.0.reaction.pivot.R.1"] - Rb) < tiny
        g, L, th0 = mpf(R.G), mpf("1.2"), -mp.pi / 6
        y = R.integrate(lambda t, y: [y[1], -3 * g / (2 * L) * mp.cos(y[0])], 0, [th0, 0], mpf(1))
        assert abs(y[0] - ref["angle.bar.3"]) < tiny and abs(y[1] - ref["omega.bar.3.2"]) < tiny
        # falling rod: the ODE route against the quadrature route
        a = reference("falling-rod.yaml")
        b = R.falling_rod_case("1.5", 1, 20 * mp.pi / 180, [0, "0.1", "0.2", "0.3"], mp.pi / 4, route="quad")
        assert max(abs(a[k] - b[k]) for k in a) < tiny
        bdd, N0 = R.falling_rod_release("1.5", 1, 20 * mp.pi / 180)
        assert abs(a["alpha.rod.0.2"] + bdd) < tiny and abs(a["reaction.tip.N.0"] - N0) < tiny
        # yo-yo: a and T against the free-body diagram (m a = T − m g, Ī α = −r T, a = r α)
        ref, acc, T = R.yoyo_case("0.2", "0.05", "0.01", "0.01", "-0.5", [0], "-1.5")
        m, rr, I = mpf("0.2"), mpf("0.01"), mpf("0.2") * mpf("0.05") ** 2 / 2
        assert abs(m * -acc - (T - m * g)) < tiny and abs(I * (-acc / rr) + rr * T) < tiny
        # slider-crank: sympy's derivatives against the hand-differentiated closed forms at 60°
        ref = reference("slider-crank.yaml")
        r, l, w, th = mpf("0.1"), mpf("0.35"), mpf(10), mp.pi / 3
        S = mp.sqrt(l**2 - r**2 * mp.sin(th) ** 2)
        assert abs(ref["find.0.x.slider.0"] - (r * mp.cos(th) + S)) < tiny
        assert abs(ref["find.0.v.slider.0"] + r * w * mp.sin(th) * (1 + r * mp.cos(th) / S)) < tiny
        xdd = -r * w**2 * mp.cos(th) - r**2 * w**2 * (l**2 * mp.cos(2 * th) + r**2 * mp.sin(th) ** 4) / S**3
        assert abs(ref["find.0.a.slider.0"] - xdd) < tiny
        # four-bar: the rocker's extremes by findroot on ω4 = 0 against the law-of-cosines closed form
        ref = reference("four-bar.yaml")
        (t_ext, th_ext), (t_fold, th_fold) = R.four_bar_limits("0.3", mp.sqrt(mpf("0.26")), "0.4", "0.5",
                                                               mp.pi / 2, 5)
        assert abs(ref["find.0.t"] - t_fold) < tiny and abs(ref["find.0.angle.rocker"] - th_fold) < tiny
        assert abs(ref["find.1.t"] - t_ext) < tiny and abs(ref["find.1.angle.rocker"] - th_ext) < tiny


# ------------------------------------------------------------------------------------ edge cases

UPRIGHT = """
type: scene
title: Compound pendulum released 1e-6 rad from upright
params: {m: 2, L: 1.2, th0: "pi/2 - 1e-6"}
bodies:
  bar: {shape: rod, mass: m, length: L, angle: th0, x: ["L/2*cos(th0)", "L/2*sin(th0)"]}
joints:
  pivot: {pin: [bar.end1, [0, 0]]}
at: [0, 2, 4]
t_end: 5
accuracy: {estimate: true}      # an unstable start amplifies the steps' errors: measure them
find:
  - {when: {angle.bar: 0}}
  - {when: {angle.bar: "-pi/2"}}
"""


def _run_json(text):
    rc, out, err = run_cli("solve", "-", "--format", "json", input=text)
    recs = None
    if out.strip():
        try:
            import json

            recs = json.loads(out)
        except ValueError:
            recs = None
    return rc, recs, err


def test_compound_pendulum_released_near_upright():
    """1e-6 rad from the unstable equilibrium: the rod must fall (not sit there as a statics
    answer), on the elliptic timetable: horizontal at 4.2874 s, at the bottom at K/ω_n = 4.5391 s,
    with the pin force 4 m g there.  A route that cannot resolve the 1e-6 deviation (an ODE step's
    error relative to π/2 is 1e-4 of it, amplified by e^{ω_n t}) must say so in error_estimate:
    the nominal estimate (rtol × steps) assumes no amplification, so the file asks for the
    measured one (accuracy.estimate, docs/accuracy.md)."""
    rc, recs, err = _run_json(UPRIGHT)
    assert rc == 0, err
    rec = recs[0]
    res = rec["results"]
    assert res["dof"] == 1 and res["route"] in ("quadrature", "ode")
    assert res["events"] == []
    with mp.workdps(30):
        ref = R.compound_pendulum_case(2, "1.2", mp.pi / 2 - mpf("1e-6"), [0, 2, 4], upright=True)
    ref = {k: v for k, v in ref.items() if not k.startswith("_")}
    assert abs(float(ref["find.1.reaction.pivot.R.1"]) - 4 * 2 * 9.81) < 1e-9
    compare(res, ref, tolerance(rec, DEFAULT_RTOL))


def _toggle_four_bar(delta, w, at):
    """A Grashof four-bar whose shortest link c (the rocker side) turns fully: driven at the
    crank a, it has limit (toggle) positions where coupler b and rocker c are collinear,
    |A − O4| = b + c.  With a = 0.3, d = 0.4 and the crank at 90°, |A − O4| = 0.5 exactly; with
    b = 0.35 and c = 0.15 + delta the mechanism is delta from that toggle, the transmission
    angle μ ~ sqrt(delta) small (4.4e-3 rad at delta = 1e-6).  Positions from the loop closure at
    30 digits, written out in full (17 digits) so the file needs no assembly."""
    with mp.workdps(30):
        a, b, c, d = mpf("0.3"), mpf("0.35"), mpf("0.15") + mpf(delta), mpf("0.4")
        A = (mpf(0), a)
        O4 = (d, mpf(0))
        # B: circle (A, b) ∩ circle (O4, c), the intersection above the line A-O4
        dx, dy = O4[0] - A[0], O4[1] - A[1]
        D_ = mp.sqrt(dx**2 + dy**2)
        along = (b**2 - c**2 + D_**2) / (2 * D_)
        h = mp.sqrt(b**2 - along**2)
        B = (A[0] + along * dx / D_ - h * dy / D_, A[1] + along * dy / D_ + h * dx / D_)
        th3 = mp.atan2(B[1] - A[1], B[0] - A[0])
        th4 = mp.atan2(B[1] - O4[1], B[0] - O4[0])
        mu = abs(mp.sin(th4 - th3))
        f = lambda v: repr(float(v))     # noqa: E731
        text = f"""
type: scene
title: Four-bar {delta} m from its toggle
params: {{w: {w}}}
bodies:
  crank: {{shape: rod, mass: 0.6, length: 0.3, angle: "pi/2", x: [0, 0.15]}}
  coupler: {{shape: rod, mass: 1, length: 0.35, angle: {f(th3)}, x: [{f((A[0] + B[0]) / 2)}, {f((A[1] + B[1]) / 2)}]}}
  rocker: {{shape: rod, mass: 0.8, length: {f(c)}, angle: {f(th4)},
           x: [{f((O4[0] + B[0]) / 2)}, {f((O4[1] + B[1]) / 2)}]}}
joints:
  O2: {{pin: [crank.end1, [0, 0]]}}
  A: {{pin: [coupler.end1, crank.end2]}}
  B: {{pin: [coupler.end2, rocker.end2]}}
  O4: {{pin: [rocker.end1, [0.4, 0]]}}
  motor: {{drive: crank.angle, value: "pi/2 + w*t"}}
at: {at}
"""
        # the reference at t = 0 from these very numbers
        geom = dict(a=a, b=b, c=mpf(f(c)), d=d)
    return text, geom, (th3, th4), mu


SINGULAR = re.compile(r"toggle|singular|dead|lock|rank|condition|cannot (?:be )?assembl|no (?:longer )?clos", re.I)


def test_four_bar_near_toggle_answers_right_or_refuses():
    """1e-6 m from the toggle (transmission angle μ ≈ 4.4e-3 rad): either a refusal that names the
    condition (exit 2, 'toggle'/'singular'...) or the right answer: ω4 ≈ 367 rad/s for ω2 = 1 rad/s,
    a drive couple of ~2e8 N·m.  The reference uses the file's own numbers; the answer's
    sensitivity to rounding is ~1/μ³ ≈ 1e7, so 1e-6 relative is a fair bar (a wrong branch, a
    least-squares λ or a stale Jacobian is off by O(1))."""
    text, geom, (th3, th4), mu = _toggle_four_bar("1e-6", 1, [0])
    assert 1e-3 < mu < 1e-2
    rc, recs, err = _run_json(text)
    if rc != 0:
        assert rc == 2 and SINGULAR.search(err), (rc, err)
        return
    res = recs[0]["results"]
    with mp.workdps(30):
        a, b, c, d = geom["a"], geom["b"], geom["c"], geom["d"]
        s = R.four_bar_state(a, b, c, d, mpf(1), mp.pi / 2, (mpf("0.6"), mpf(1), mpf("0.8")), mpf(R.G), mpf(0),
                             (th3, th4))
    w3, w4 = s["rates"][1], s["rates"][2]
    a3, a4 = s["acc"][1], s["acc"][2]
    assert abs(float(w4)) > 10          # the rocker whips round near the toggle: ω4 ≫ ω2 = 1
    for path, want in (("omega.coupler.0.2", w3), ("omega.rocker.0.2", w4), ("alpha.coupler.0.2", a3),
                       ("alpha.rocker.0.2", a4), ("drive.motor.0", s["F"]["motor"]),
                       ("reaction.B.R.0.0", s["F"]["B.0"]), ("reaction.B.R.0.1", s["F"]["B.1"])):
        got = lookup(res, path)
        assert isinstance(got, (int, float)), (path, got)
        assert abs(got - float(want)) <= 1e-6 * abs(float(want)), (path, got, float(want))


def test_four_bar_driven_into_its_toggle_does_not_answer_past_it():
    """Driven at ω2 = 1 rad/s towards the toggle 1e-6 m away: the loop cannot close beyond it
    (the crank reaches its limit after ~4e-6 s).  A time after that has no state: the engine must
    refuse (a message naming the toggle/singularity) or stop with nulls there — never report
    numbers for t = 0.01 s."""
    text, _geom, _th, _mu = _toggle_four_bar("1e-6", 1, [0, 0.01])
    rc, recs, err = _run_json(text)
    if rc != 0:
        assert rc in (1, 2) and SINGULAR.search(err), (rc, err)
        return
    res = recs[0]["results"]
    for path in ("angle.rocker.1", "omega.rocker.1.2", "drive.motor.1", "reaction.B.R.1"):
        assert lookup(res, path) is None, (path, lookup(res, path))
    assert recs[0]["warnings"], "nulls without a warning saying why"
