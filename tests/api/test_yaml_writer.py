"""dyncli's own YAML writer (issue #31) gives PyYAML's bytes: over the records of every
problems/ file (the recorded baseline), the live sweep records of the vibration examples, and
shapes chosen to reach PyYAML's line-width, quoting and indentation rules."""

import json
from pathlib import Path

import pytest
import yaml

from dyncli.render import yamlemit, yamlout

ROOT = Path(__file__).resolve().parents[2]


def _pyyaml(records, unicode=True):
    return yaml.dump(records, Dumper=yamlout.dumper(), sort_keys=False, allow_unicode=unicode,
                     default_flow_style=None, width=100)


def _same(records, unicode=True):
    try:
        got = yamlemit.dumps(records, unicode)
    except yamlemit.Unsupported:
        return None
    assert got == _pyyaml(records, unicode)
    assert yamlout.dumps(records, unicode) == got
    return True


def test_every_problem_files_records():
    data = json.loads((ROOT / "tests/data/baseline-results.json").read_text(encoding="utf-8"))
    laid_out = [_same(recs) for recs in data.values()]
    assert all(laid_out), "every record of the examples is laid out by dyncli's writer"
    for recs in data.values():
        _same(recs, unicode=False)       # (non-ASCII text without unicode: PyYAML's double quotes)


@pytest.mark.parametrize("name", sorted(p.name for p in (ROOT / "problems/vibration").glob("*.yaml")))
def test_vibration_sweep_records(name):
    import dyncli

    outs = dyncli.sweep(str(ROOT / "problems/vibration" / name), {"m": [0.5, 1.0, 2.5]})
    from dyncli.render.jsonout import problem_record

    recs = [problem_record(o._problem, o._result, None, 0) for o in outs]
    assert _same(recs)
    assert "".join(yamlout.dumps([r]) for r in recs) == "".join(_pyyaml([r]) for r in recs)


SHAPES = [
    [{"a": [1.0] * 40, "b": {"c": [0.1234567890123 * k for k in range(30)], "d": []}, "e": {}}],
    [{"title": "word " * 40, "q": "it's a 'quoted': text " * 8, "n": None, "t": True, "i": -3}],
    [{"yes": "yes", "1.5": "1.5", "null": "", "k": "~", "dash": "- x", "colon": "a: b", "hash": "a #b"}],
    [{"nested": [[1, 2], [3, [4, 5]]], "find": [{"t": 1.0, "x": [1e-300, 1e300, float("inf"), -0.0]}]}],
    [{"f": [1e16, 1e-5, 12345678901234567890, float("nan"), -float("inf")], "u": "αβγ ω* ≤ 2π"}],
    {"top": {"m": {"x": 1}}, "list": [{"a": 1}, {"b": [2]}]},
]


@pytest.mark.parametrize("i", range(len(SHAPES)))
@pytest.mark.parametrize("unicode", [True, False])
def test_shapes(i, unicode):
    _same(SHAPES[i], unicode)


def test_refused_shapes_fall_back():
    shared = [1, 2]
    for recs in ([{"a": shared, "b": shared}], [{"s": "line\nbreak"}], [{"k" * 130: 1}], [{"c": "\x1b[31m"}]):
        with pytest.raises(yamlemit.Unsupported):
            yamlemit.dumps(recs)
        assert yamlout.dumps(recs) == _pyyaml(recs)
