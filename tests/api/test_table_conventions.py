"""What the table views state beside the numbers: an accuracy check relative
to its scale (``energy_residual``: relative in the tables, absolute in JSON),
and the free-vibration phase's range written above the results."""

from __future__ import annotations

import io
import json
import math

from dyncli.render import out
from tests.conftest import ROOT

SATELLITE = "problems/particle/satellite-inverse-square.yaml"


def _solved(path: str):
    from dyncli.loader import load_paths
    from dyncli.run import solve_one

    problems, _ = load_paths([str(ROOT / path)])
    return [solve_one(lp) for lp in problems]


def _table(o, units=None) -> str:
    from dyncli.render.table import render

    buf = io.StringIO()
    render(out.Out(buf, 100, no_color=True), o.problem, o.result, 6, units)
    return buf.getvalue()


def test_energy_residual_relative_in_tables_absolute_in_json():
    from dyncli.render.jsonout import dumps
    from dyncli.run import outcome_record

    [o] = _solved(SATELLITE)
    r = o.result
    resid, scale = r.results["energy_residual"], r.scales["energy_residual"]
    # the scale is the largest energy the balance E − E1 = W_nc holds: at least |E1| = |T0 + V0|
    assert scale >= abs(r.results["E"][0]) > 0
    row = next(ln.split() for ln in _table(o).splitlines() if ln.startswith(" energy_residual"))
    shown, unit = float(row[2]), " ".join(row[3:])
    assert math.isclose(shown, resid / scale, rel_tol=1e-2, abs_tol=1e-300)
    assert unit.startswith("relative to ") and unit.endswith(" J")
    assert math.isclose(float(unit.split()[2]), scale, rel_tol=1e-2)
    rec = json.loads(dumps([outcome_record(o)]))[0]
    assert rec["results"]["energy_residual"] == resid            # JSON: the absolute value in J
    kj = next(ln.split() for ln in _table(o, ["kJ"]).splitlines() if ln.startswith(" energy_residual"))
    assert math.isclose(float(kj[5]), scale / 1e3, rel_tol=1e-2) and kj[6] == "kJ"


def test_free_phase_convention_stated_above_the_results():
    [o] = _solved("problems/vibration/underdamped.yaml")
    lines = _table(o).splitlines()
    note = next(i for i, ln in enumerate(lines) if "φ in (−π, π]" in ln)
    head = next(i for i, ln in enumerate(lines) if ln.split()[:2] == ["result", "symbol"])
    assert note < head and "[0, 2π)" in lines[note]
    # the rule it states: the notes' phase φ + 2π (φ < 0) has the same sine and cosine
    phi = o.result.results["phi"]
    notes = phi + 2 * math.pi if phi < 0 else phi
    assert 0 <= notes < 2 * math.pi and math.isclose(math.sin(notes), math.sin(phi), abs_tol=1e-15)
    forced = _solved("problems/vibration/force-excitation.yaml")[0]
    assert "φ in (−π, π]" not in _table(forced)                   # the forced phase: no free-phase note
