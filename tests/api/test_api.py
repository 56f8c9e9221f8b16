"""The Python API (docs/api.md): sources, solutions, errors, lazy import."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import pytest

import dyncli
from tests.conftest import ROOT, run_cli

SPRING_BUDGET = ("type: particle\nm: 1\nv0: [1, 0, 0]\nforces: [{kind: spring, k: 100}]\nt_end: 100\n"
                 "accuracy: {max_steps: 200}\n")


def test_import_is_light_and_attributes_are_lazy():
    code = ("import sys, dyncli\n"
            "heavy = [m for m in ('numpy', 'pydantic', 'typer', 'rich', 'yaml') if m in sys.modules]\n"
            "assert not heavy, heavy\n"
            "assert dyncli.InputError.__module__ == 'dyncli.errors'\n"
            "assert callable(dyncli.solve) and 'solve' in dir(dyncli)\n")
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
    with pytest.raises(AttributeError):
        dyncli.no_such_thing  # noqa: B018


def test_path_text_and_mapping_give_the_cli_record():
    path = ROOT / "problems/impact/oblique-smooth.yaml"
    rc, out, _ = run_cli("solve", "-f", "json", "problems/impact/oblique-smooth.yaml")
    cli = json.loads(out)[0]
    for source in (str(path), path):
        rec = dyncli.solve(source)[0].to_dict()
        assert rec["results"] == cli["results"] and rec["input_sha256"] == cli["input_sha256"]
    import yaml

    mapping = yaml.safe_load(path.read_text())
    from_text = dyncli.solve(path.read_text())[0]
    from_map = dyncli.solve(mapping)[0]
    assert from_text.results == from_map.results
    assert from_map.to_dict()["input_sha256"] == cli["input_sha256"]
    assert from_map.file == "<dict>" and from_text.file == "<text>"


def test_numpy_values_in_a_mapping_and_in_sweeps():
    np = pytest.importorskip("numpy")
    sols = dyncli.sweep({"type": "vibration", "m": np.float64(1.0), "k": 100}, {"k": np.linspace(100, 400, 4)})
    assert [s["omega_n"] for s in sols] == pytest.approx([math.sqrt(k) for k in (100, 200, 300, 400)], rel=4e-16)
    assert type(sols[0].swept["k"]) is float


def test_numerical_error():
    with pytest.raises(dyncli.NumericalError, match="more than the budget of 200"):
        dyncli.solve(SPRING_BUDGET)


def test_input_error_lists_every_message():
    text = "problems:\n- {type: vibration, m: -1, k: 0}\n- {type: impact, mA: 1}\n- {type: nope}\n"
    with pytest.raises(dyncli.InputError) as info:
        dyncli.solve(text)
    msgs = info.value.messages
    assert str(info.value) == "\n".join(msgs)
    assert all(m.startswith("<text>:") for m in msgs)
    assert any("m: must be > 0" in m for m in msgs) and any("k: must be > 0" in m for m in msgs)
    assert any("unknown problem type 'nope'" in m for m in msgs)
    assert len(msgs) >= 5
    with pytest.raises(dyncli.InputError, match="no such file"):
        dyncli.solve("no/such/file.yaml")
    with pytest.raises(TypeError):
        dyncli.solve(42)


def test_solution_views():
    s = dyncli.solve(str(ROOT / "problems/vibration/underdamped.yaml"))[0]
    assert repr(s) == "<Solution vibration 'Underdamped free vibration': 13 results, method closed-form>"   # 11 and t
    html = s._repr_html_()
    assert html.count("<table>") == 3 and "<th>t</th>" in html      # results, response over t, find and "&lt;" not in s.title
    assert s.table(units="deg").splitlines()[0].startswith("Underdamped free vibration")
    assert " deg" in s.table(units="deg")
    with pytest.raises(dyncli.InputError, match="unknown unit"):
        s.table(units="blah")
