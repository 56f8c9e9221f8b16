"""Chained problems: a ``params`` entry taken from an earlier problem's result in the same file
(``v1: {from: 0, result: vA2.0}``) — the ballistic pendulum, the rules of order, paths and units,
and the same behaviour under --set, --sweep, the Python API and answer files.  References: the
hand derivation of the ballistic pendulum (momentum through the impact, energy through the swing)."""

from __future__ import annotations

import json
import math

import pytest

import dyncli
from tests.conftest import PROBLEMS, run_cli, solve_path, solve_text

G = 9.81
GALLERY = PROBLEMS / "impact" / "ballistic-pendulum.yaml"


def _swing(mA, mB, v, L):
    """Hand derivation: the common velocity mA v/(mA + mB) (28.10, e = 0), then the energy integral
    of the pendulum: cos q_max = 1 − v2²/(2 g L)."""
    v2 = mA * v / (mA + mB)
    return v2, math.acos(1 - v2 * v2 / (2 * G * L))


def test_gallery_ballistic_pendulum_against_the_hand_derivation():
    impact, swing = solve_path(GALLERY)
    v2, qmax = _swing(0.02, 3.5, 350, 1.6)
    assert impact["results"]["vA2"][0] == pytest.approx(v2, rel=1e-14)
    assert swing["results"]["q_dot"][0] == pytest.approx(v2 / 1.6, rel=1e-14)   # the value was taken
    (top,) = swing["results"]["find"]
    assert top["q"] == pytest.approx(qmax, rel=1e-9)       # the quadrature route's turning point
    assert 1.6 * (1 - math.cos(top["q"])) == pytest.approx(v2 * v2 / (2 * G), rel=1e-9)


FILE = """problems:
  - type: impact
    mA: 0.01
    mB: 2
    vA1: [400, 0, 0]
    n: [1, 0, 0]
    e: 0
  - type: constrained-particle
    params:
      v1: {from: 0, result: vA2.0, unit: m/s}
      L: 1.5
    m: 2.01
    curve: {x1: "L*sin(q)", x2: 0, x3: "-L*cos(q)"}
    q_range: [-pi, pi]
    q_dot0: "v1/L"
    forces: [{kind: gravity}]
    t_end: 2
    find: [{max: q}]
"""


def test_a_chain_through_three_problems_and_a_find_path():
    """Problem 2 takes the time of problem 1's highest point (find.0.t): a quarter period."""
    text = FILE + """  - type: rectilinear
    params: {T: {from: 1, result: find.0.t, unit: s}}
    a: 0
    v1: 1
    find: [{t: T}]
"""
    recs = solve_text(text)
    t_top = recs[1]["results"]["find"][0]["t"]
    assert recs[2]["results"]["find"][0]["s"] == pytest.approx(t_top, rel=1e-15)


def _err(text, where, words):
    recs = solve_text(text, "bad.yaml")
    msgs = [r["error"] for r in recs if r.get("error")]
    assert msgs, "expected a refusal"
    assert any(f": {where}: " in m and all(w in m for w in words) for m in msgs), msgs


@pytest.mark.parametrize("old, new, where, words", [
    ("from: 0, result: vA2.0", "from: 1, result: vA2.0", "params.v1.from", ["own results", "cycle"]),
    ("from: 0, result: vA2.0", "from: 5, result: vA2.0", "params.v1.from", ["no problem 5", "holds 2"]),
    ("from: 0, result: vA2.0", "from: -1, result: vA2.0", "params.v1.from", ["earlier problem"]),
    ("result: vA2.0, unit: m/s", "result: vA2", "params.v1.result", ["3 values", "vA2.0, vA2.1, vA2.2"]),
    ("result: vA2.0, unit: m/s", "result: vB3.0", "params.v1.result", ["has no result vB3.0", "did you mean"]),
    ("result: vA2.0, unit: m/s", "result: impact", "params.v1.result", ["True", "not a number"]),
    ("result: vA2.0, unit: m/s", "result: T1", "params.v1.result", ["is null"]),
    ("result: vA2.0, unit: m/s", "result: '1x'", "params.v1.result", ["dotted result path"]),
    ("unit: m/s", "unit: J", "params.v1.unit", ["in m/s, not J", "different kind"]),
    ("unit: m/s", "unit: km/h", "params.v1.unit", ["SI values", "write unit: m/s"]),
    ("unit: m/s", "unit: blorps", "params.v1.unit", ["unknown unit"]),
    ("unit: m/s", "units: m/s", "params.v1.units", ["did you mean 'unit'"]),
    ("{from: 0, result: vA2.0, unit: m/s}", "{from: 0}", "params.v1", ["needs from", "result"]),
    ("mB: 2", "mB: -2", "params.v1", ["problem 0", "was not solved"]),
])
def test_refused_chains_name_the_field(old, new, where, words):
    text = FILE.replace(old, new, 1)
    if "T1" in new:                                      # a fixed wall: T1 is null (a warning says why)
        text = text.replace("mB: 2", "mB: .inf", 1)
    _err(text, where, words)


def test_a_forward_reference_is_refused():
    text = FILE.replace("  - type: impact\n", "  - type: impact\n    params: {w: {from: 1, result: q.0}}\n", 1)
    _err(text, "params.w.from", ["comes after this one", "forward reference"])


def test_one_problem_files_cannot_chain():
    _err("type: rectilinear\nparams: {T: {from: 0, result: case}}\na: 0\nfind: [{t: 1}]\n", "params.T.from",
         ["several problems"])


def test_a_failed_source_fails_its_chain_with_the_same_code(tmp_path):
    f = tmp_path / "c.yaml"
    f.write_text(FILE.replace("mB: 2", "mB: -2", 1))
    code, out, err = run_cli("solve", str(f), "--format", "json")
    assert code == 2
    assert "mB: must be > 0" in err and "params.v1: problem 0" in err


def _cli_json(tmp_path, *args):
    f = tmp_path / "c.yaml"
    f.write_text(FILE)
    code, out, err = run_cli("solve", str(f), "--format", "json", *args)
    assert code == 0, err
    return json.loads(out)


def test_sweep_of_the_source_repeats_the_chain_per_point(tmp_path):
    recs = _cli_json(tmp_path, "--sweep", "mA=0.01,0.02", "--sweep", "L=1,2")
    swings = [r for r in recs if r["index"] == 1]
    assert len(swings) == 4
    for r in swings:
        mA, L = r["swept"]["mA"], r["swept"]["L"]
        assert r["results"]["find"][0]["q"] == pytest.approx(_swing(mA, 2, 400, L)[1], rel=1e-8)


def test_set_replaces_the_chain_with_a_number(tmp_path):
    recs = _cli_json(tmp_path, "--set", "v1=3")
    assert recs[1]["results"]["q_dot"][0] == pytest.approx(2.0, rel=1e-15)


def test_python_api_solve_and_sweep():
    sols = dyncli.solve(FILE)
    assert sols[1].results["find"][0]["q"] == pytest.approx(_swing(0.01, 2, 400, 1.5)[1], rel=1e-8)
    sw = dyncli.sweep(FILE, {"mA": [0.01, 0.03]})
    got = [(s.swept["mA"], s.results["find"][0]["q"]) for s in sw if s.index == 1]
    assert [m for m, _ in got] == [0.01, 0.03]
    for m, q in got:
        assert q == pytest.approx(_swing(m, 2, 400, 1.5)[1], rel=1e-8)
    with pytest.raises(dyncli.InputError, match="params.v1.unit"):
        dyncli.solve(FILE.replace("unit: m/s", "unit: J"))


def test_validate_and_answer_files(tmp_path):
    f = tmp_path / "c.yaml"
    f.write_text(FILE)
    code, out, _ = run_cli("validate", str(f))
    assert code == 0 and "v1 from problem 0's vA2.0: checked when solved" in out
    q = _swing(0.01, 2, 400, 1.5)[1]
    (tmp_path / "a.yaml").write_text(f"problem: c.yaml\nindex: 1\nanswers:\n  find.0.q: {q:.6f}\n")
    code, out, err = run_cli("check", str(tmp_path / "a.yaml"))
    assert code == 0, out + err
    # an answer file's params reach the source through the chained problem's own names
    text = FILE.replace("      L: 1.5\n", "      L: 1.5\n      mA: 0.01\n").replace("mA: 0.01\n    mB", "mA: mA\n    mB", 1)
    text = text.replace("  - type: impact\n", "  - type: impact\n    params: {mA: 0.01}\n", 1)
    f.write_text(text)
    q3 = _swing(0.03, 2, 400, 1.5)[1]
    (tmp_path / "a.yaml").write_text(f"problem: c.yaml\nindex: 1\nparams: {{mA: 0.03}}\nanswers:\n  find.0.q: {q3:.6f}\n")
    code, out, err = run_cli("check", str(tmp_path / "a.yaml"))
    assert code == 0, out + err


def test_a_keys_variant_reaches_the_source_through_the_chained_problems_params(tmp_path):
    text = FILE.replace("  - type: impact\n    mA: 0.01\n", "  - type: impact\n    params: {mA: 0.01}\n    mA: mA\n", 1)
    text = text.replace("      L: 1.5\n", "      L: 1.5\n      mA: 0.01\n", 1)
    (tmp_path / "bp.yaml").write_text(text)
    (tmp_path / "key.yaml").write_text('variants:\n  salt: "s"\n  params:\n    mA: {choice: [0.02, 0.03]}\n'
                                       'questions:\n  - {id: "1", problem: bp.yaml, index: 1, answer: find.0.q}\n')
    code, out, err = run_cli("variant", str(tmp_path / "key.yaml"), "--student", "bob", "--format", "yaml")
    assert code == 0, err
    mA = float(out.split("mA:")[1].split()[0])
    q = _swing(mA, 2, 400, 1.5)[1]
    (tmp_path / "bob.yaml").write_text(f'student: bob\nanswers:\n  "1": {q:.6f}\n')
    code, out, err = run_cli("check", "--key", str(tmp_path / "key.yaml"), str(tmp_path / "bob.yaml"))
    assert code == 0, out + err
