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


# -- property: random records with tricky strings (issue #31)

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

TRICKY = ["", " ", " lead", "trail ", "a: b", "a:b", "a #b", "#x", "- x", "-", "'q'", '"dq"', "it's",
          "yes", "no", "on", "off", "y", "n", "Yes", "NO", "true", "False", "null", "Null", "~", "1e3", "012",
          "0x1f", "1_000", "1:30", "+1", "-0", ".5", ".inf", "-.inf", ".nan", "1.0", "2001-12-14", "0.1.0",
          "αβγ", "ω* ≤ 2π", "line\nbreak", "tab\there", "\u202e", "a  b", "[x]", "{y}", "x,y", "?", "!", "&a",
          "*a", "%", "@", "`", "|", ">", "---", "...", "a" * 130, "word " * 30, "17.20", "17.5b", "<<", "="]

_text = st.one_of(st.sampled_from(TRICKY), st.text(max_size=12),
                  st.text(alphabet="ab :#'-.,0123456789 eE+~\n", max_size=10))
#: the texts dyncli's records mostly hold (printable, one line): the writer's own layout reached
_word = st.one_of(st.sampled_from([t for t in TRICKY if t.isprintable()]),
                  st.text(alphabet="abxyz_ :#'-.,0123456789 eE+~αω", max_size=12),
                  st.text(alphabet="abcdef0123456789", min_size=1, max_size=64))


def _records_of(text, long_lists=False):
    key = text.filter(lambda k: 0 < len(k) < 128) if long_lists else text
    atom = st.one_of(st.none(), st.booleans(), st.integers(-10**20, 10**20),
                     st.floats(allow_nan=True, allow_infinity=True), text)
    node = st.recursive(atom, lambda inner: st.one_of(
        st.lists(inner, max_size=6), st.dictionaries(key, inner, max_size=6),
        st.lists(st.floats(), max_size=20 if long_lists else 6)), max_leaves=30)
    return st.lists(st.dictionaries(key, node, max_size=8), max_size=3)


_records = st.one_of(_records_of(_text), _records_of(_word, True))


def _same_data(a, b):
    if isinstance(a, float) and a != a:
        return isinstance(b, float) and b != b
    if isinstance(a, dict):
        return isinstance(b, dict) and list(a) == list(b) and all(_same_data(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return isinstance(b, list) and len(a) == len(b) and all(map(_same_data, a, b))
    return type(a) is type(b) and a == b


@settings(max_examples=300, deadline=None)
@given(_records, st.booleans())
def test_random_records_read_back_as_todays_output(records, unicode):
    """The writer's text reads back (PyYAML's safe_load) to the records, and is PyYAML's own bytes
    whenever dyncli's writer lays the records out (else PyYAML wrote them)."""
    text = yamlout.dumps(records, unicode)
    assert text == _pyyaml(records, unicode)
    assert _same_data(yaml.safe_load(text), records)
    try:
        own = yamlemit.dumps(records, unicode)
    except yamlemit.Unsupported:
        return
    assert own == text
