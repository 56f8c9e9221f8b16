"""The fixed cost per problem, by structure (no timing is asserted;
``python -m benchmarks.all`` measures it):

* a sweep streams: with ``--format json|yaml`` the first record reaches the
  output before the last point is solved, and the output is the same bytes
  as the whole-output writer's;
* the YAML is read in one pass over the parser's events (no node graph, no
  second parse), with the same data and positions as PyYAML's own loader;
* a JSON record is written by one ``json.dumps`` call, the output equal to
  an independent encoder (``json.dumps(indent=2)`` with every list of numbers
  joined onto one line) for every example of problems/.
"""

from __future__ import annotations

import io
import json
import re
import sys

import pytest
import yaml

from tests.conftest import ROOT

EXAMPLES = sorted((ROOT / "problems").rglob("*.yaml"))


class _Watch(io.StringIO):
    """stdout that notes how many points were solved at its first write."""

    def __init__(self, solved: list):
        super().__init__()
        self.solved, self.first = solved, None

    def write(self, s):
        if self.first is None and s:
            self.first = len(self.solved)
        return super().write(s)


@pytest.mark.parametrize("fmt", ["json", "yaml"])
def test_a_sweep_streams(monkeypatch, fmt):
    from dyncli import run
    from dyncli.render import emit

    solved: list = []
    real = run.solve_one
    monkeypatch.setattr(run, "solve_one", lambda lp, options=None: solved.append(lp) or real(lp, options))
    out = _Watch(solved)
    monkeypatch.setattr(sys, "stdout", out)
    code = run.solve_command([str(ROOT / "problems/impact/wall.yaml")], fmt, sweeps=["e=0:1:40"])
    assert code == 0 and len(solved) == 40
    assert out.first is not None and out.first < 40          # written before the last point was solved
    monkeypatch.setattr(sys, "stdout", io.StringIO())
    outcomes = [real(lp) for lp in solved]
    assert out.getvalue() == emit.dumps(fmt, outcomes)        # the same bytes as the whole-output writer


def test_a_streamed_sweep_keeps_no_point(monkeypatch):
    """The points are made one at a time: none is kept once written."""
    import gc
    import weakref

    from dyncli import run

    refs: list = []
    real = run.solve_one

    def solve(lp, options=None):
        o = real(lp, options)
        refs.append(weakref.ref(o.result))
        return o

    monkeypatch.setattr(run, "solve_one", solve)
    monkeypatch.setattr(sys, "stdout", io.StringIO())
    assert run.solve_command([str(ROOT / "problems/impact/wall.yaml")], "json", sweeps=["e=0:1:30"]) == 0
    gc.collect()
    assert sum(r() is not None for r in refs) <= 1


def _positions(node, path=(), out=None):
    """(path -> (line, col)) of every value, from PyYAML's node graph: the
    independent route for the one-pass reader's positions."""
    out = {} if out is None else out
    out.setdefault(path, (node.start_mark.line + 1, node.start_mark.column + 1))
    if isinstance(node, yaml.SequenceNode):
        for i, n in enumerate(node.value):
            _positions(n, path + (i,), out)
    elif isinstance(node, yaml.MappingNode):
        for k, v in node.value:
            _positions(v, path + (yaml.safe_load(k.value) if k.tag != "tag:yaml.org,2002:str" else k.value,), out)
    return out


@pytest.mark.parametrize("path", EXAMPLES[::3], ids=lambda p: p.name)
def test_yaml_one_pass_matches_pyyaml(path, monkeypatch):
    from dyncli import yamlsafe

    text = path.read_text(encoding="utf-8")
    calls = []
    monkeypatch.setattr(yaml, "compose_all", lambda *a, **k: calls.append("compose") or [])
    doc = yamlsafe.load(text)
    assert not calls                                             # no node graph
    assert doc.data == yaml.safe_load(text)
    assert doc.pos == _positions(yaml.compose(text, Loader=yaml.SafeLoader))


@pytest.mark.parametrize("text, message", [
    ("a: &x 1\nb: &x 2\n", "second occurrence"),
    ("a: *nowhere\n", "found undefined alias"),
    ("a: &r [1, *r]\n", "nested more than"),
    ("a: !!float ''\n", "cannot read value"),
    ("a: 1\n---\nb: 2\n", "several YAML documents"),
    ("a: 1\na: 2\nb: [\n", "YAML syntax error"),            # the syntax error before the duplicate key
])
def test_yaml_errors_in_parse_order(text, message):
    from dyncli import yamlsafe

    with pytest.raises(yamlsafe.YamlError) as err:
        yamlsafe.load(text)
    assert message in err.value.message


def _reference(records) -> str:
    """``json.dumps(indent=2)``, then every list of numbers joined onto one
    line (from its innermost lists out)."""
    text = json.dumps(records, indent=2, ensure_ascii=False)
    num = r"[ \n0-9.eE+\-,nul]"
    inner = r"\[(?:[ 0-9.eE+\-,nul]|\[(?:[ 0-9.eE+\-,nul]|\[[ 0-9.eE+\-,nul]*\])*\])*\]"
    pattern = re.compile(r"\[\n(?:" + num + "|" + inner + r")*\]")
    while True:
        new = pattern.sub(lambda m: re.sub(r"\s", "", m.group(0)).replace(",", ", "), text)
        if new == text:
            return text
        text = new


def test_json_one_dumps_per_record_and_same_text(monkeypatch):
    from dyncli.loader import load_paths
    from dyncli.render import jsonout
    from dyncli.run import outcome_record, solve_one

    problems, _ = load_paths([str(p) for p in EXAMPLES])
    records = [outcome_record(solve_one(p)) for p in problems]
    calls = []
    real = json.dumps
    monkeypatch.setattr(jsonout.json, "dumps", lambda *a, **k: calls.append(1) or real(*a, **k))
    text = jsonout.dumps(records)
    monkeypatch.undo()
    assert len(calls) == len(records)
    assert text == _reference(records)
    assert json.loads(text) == json.loads(json.dumps(records))


def _texts(node, path=(), out=None):
    """(path -> source text) of every scalar PyYAML resolves to neither str nor null."""
    out = {} if out is None else out
    if isinstance(node, yaml.ScalarNode):
        if node.tag not in ("tag:yaml.org,2002:str", "tag:yaml.org,2002:null"):
            out[path] = node.value
    elif isinstance(node, yaml.SequenceNode):
        for i, n in enumerate(node.value):
            _texts(n, path + (i,), out)
    elif isinstance(node, yaml.MappingNode):
        for k, v in node.value:
            _texts(v, path + (k.value,), out)
    return out


@pytest.mark.parametrize("text", [
    "at: [" + ", ".join(repr(k / 7) for k in range(3000)) + "]\n",
    # every edge of the numbers' fast lane, over lines, with comments, then a break of the run
    "at: [0, -0, +5, 12, -0.0, +1.5, 1., 3.25e+3, 1.0e-2, 00.5, 1.0e5, 1e5, 012, 0x1F, 1_000,\n"
    "     # a comment\n     1:30, .5, .inf, -.inf, 7, 8.5, true, null, '9', 10, [1, 2.5], {a: 1}, 11]\n",
    "a:\n  - 1\n  - 2.5\n  - 1e3\n  - -4\nb: [1, 2, 3]\nc: &r [1, 2]\nd: *r\ne: [&x 1, *x, 2]\n",
    # long flow lists (read by a scan of the text, yamlsafe._flow_numbers): floats after ", ",
    # ints, mixed, over lines, no spaces, exponents, and texts that only look like such a list
    "at: [" + ", ".join(repr(k / 7 * 10.0 ** (k % 40 - 20)) for k in range(400)) + "]\n",     # 1e-13: a text
    "at: [" + ", ".join(f"{k / 7 * 10.0 ** (k % 40 - 20):.{k % 17 + 1}e}" for k in range(400)) + "]\n",
    "at: [" + ",".join(str(k * 37 - 999) for k in range(300)) + "]\nb: [0.5,   1.5 ,2.5]\n",
    "at: [\n  " + ",\n  ".join(f"{k}.{k % 7}" if k % 3 else str(k) for k in range(300)) + "\n  ]\nx: 1\n",
    "at: [" + ", ".join(["1.5"] * 100) + ", 1.0e5, " + ", ".join(["2.5"] * 100) + "]\n",      # 1.0e5: a text
    "at: [" + ", ".join(["1.5"] * 100) + ", 012, " + ", ".join(["2.5"] * 100) + "]\n",        # 012: octal
    "at: [" + ", ".join(["1.5"] * 100) + ", 1e+5, 1.2.3, -.5, 00.5, 1." + "]\n",
    "at: [" + ", ".join(["1.5"] * 100) + "\n 2.5, 3.5]\n",                   # a break inside an item: folded
    "at: [" + ", ".join(["1.5"] * 150) + ",]\n",
    "t: '[" + ", ".join(["1.5"] * 150) + "]'\nat: [1]\n",                    # inside a quoted string
    "t: |\n  [" + ", ".join(["1.5"] * 150) + "]\nat: [1]\n",                # inside a block scalar
    "t: 1  # [" + ", ".join(["1.5"] * 150) + "]\nat: [1]\n",                  # inside a comment
    "at: &l [" + ", ".join(["1.5"] * 150) + "]\nb: *l\n",                     # anchored, and its alias
    "at: !!seq [" + ", ".join(["1.5"] * 150) + "]\n",
    "at: [[" + ", ".join(["1.5"] * 150) + "], [" + ", ".join(["2"] * 150) + "]]\n",
    "at:\n  - [" + ", ".join(["-1.25e-3"] * 150) + "]\n  - 3\n",
    "é: x\nat: [" + ", ".join(["1.5"] * 150) + "]  # ü\n",
])
def test_yaml_number_runs_same_values_positions_and_texts(text):
    from dyncli import yamlsafe

    doc = yamlsafe.load(text)
    node = yaml.compose(text, Loader=yaml.SafeLoader)
    assert doc.data == yaml.safe_load(text)
    assert [type(x) for x in doc.data["at" if "at" in doc.data else "a"]] == \
        [type(x) for x in yaml.safe_load(text)["at" if "at" in doc.data else "a"]]
    expected = _positions(node)
    assert doc.pos == expected and dict(doc.pos) == expected and len(doc.pos) == len(expected)
    for path, lc in expected.items():
        assert path in doc.pos and doc.pos[path] == lc and doc.locate(path) is not None
    assert ("at", 10**6) not in doc.pos and ("nowhere",) not in doc.pos
    assert dict(doc.text) == _texts(node)


def test_yaml_number_run_errors_and_caps_unchanged(monkeypatch):
    from dyncli import yamlsafe

    with pytest.raises(yamlsafe.YamlError) as err:
        yamlsafe.load("at: [1, 2.5, 3, !!float '', 4]\n")
    assert "cannot read value" in err.value.message and (err.value.line, err.value.col) == (1, 17)
    with pytest.raises(yamlsafe.YamlError) as err:
        yamlsafe.load("at: [1, 2, 2017-01-01]\n")
    assert "reads as a date" in err.value.message and (err.value.line, err.value.col) == (1, 12)
    monkeypatch.setattr(yamlsafe, "MAX_NODES", 50)
    with pytest.raises(yamlsafe.YamlError) as err:
        yamlsafe.load("a: &a [" + ", ".join(["1"] * 20) + "]\nb: [*a, *a, *a]\n")
    assert "alias bomb" in err.value.message
    with pytest.raises(yamlsafe.YamlError) as err:
        yamlsafe.load("at: [" + ", ".join(["1"] * 60) + "]\n")
    assert "more than 50 values" in err.value.message
    for text in ("at: [" + ", ".join(["1.5"] * 60) + "]\n",                   # a scanned list: the same caps
                 "a: [" + ", ".join(["1.5"] * 40) + "]\nb: [" + ", ".join(["2.5"] * 40) + "]\n"):
        with pytest.raises(yamlsafe.YamlError) as err:
            yamlsafe.load(text)
        assert "more than 50 values" in err.value.message


def test_yaml_scanned_flow_list_errors_and_positions_as_written():
    """A long flow list read by the scan (yamlsafe._flow_numbers) keeps every other error where the
    parser puts it, and its items' positions are those of the text as written."""
    from dyncli import yamlsafe

    long = "[" + ", ".join(f"{k}.5" for k in range(200)) + "]"
    with pytest.raises(yamlsafe.YamlError) as err:
        yamlsafe.load(f"at: {long}\nb: [1, 2\nc: 3\n")
    with pytest.raises(yamlsafe.YamlError) as plain:
        yamlsafe.load("at: [1]\nb: [1, 2\nc: 3\n")
    assert (err.value.message, err.value.line) == (plain.value.message, plain.value.line)
    with pytest.raises(yamlsafe.YamlError) as err:
        yamlsafe.load(f"at: {long}\nat: 1\n")
    assert "duplicate key 'at'" in err.value.message and (err.value.line, err.value.col) == (2, 1)
    doc = yamlsafe.load(f"x: 1\nat:   {long[:600]}\n   {long[600:]}\n")
    node = yaml.compose(f"x: 1\nat:   {long[:600]}\n   {long[600:]}\n", Loader=yaml.SafeLoader)
    assert doc.pos == _positions(node) and doc.pos[("at", 199)] == _positions(node)[("at", 199)]
    del doc.pos[("at", 150)]                          # a run cut at an item: the rest kept one by one
    assert doc.pos[("at", 151)] == _positions(node)[("at", 151)] and ("at", 150) not in doc.pos


@pytest.mark.parametrize("chunk", [1, 50, 1 << 20])
def test_a_streamed_record_is_written_in_joined_chunks(monkeypatch, chunk):
    """A record's pieces are joined into writes of about ``CHUNK`` characters: the same bytes
    as the whole-output writer, in fewer writes than pieces (a tiny chunk: one per piece)."""
    from dyncli import run
    from dyncli.render import emit, jsonout, stream

    monkeypatch.setattr(stream, "CHUNK", chunk)
    writes: list[str] = []

    class Out(io.StringIO):
        def write(self, s):
            writes.append(s)
            return super().write(s)

    out = Out()
    monkeypatch.setattr(sys, "stdout", out)
    assert run.solve_command([str(ROOT / "problems/vibration/underdamped.yaml")], "json", sweeps=["k=100,400,900"]) == 0
    monkeypatch.setattr(sys, "stdout", io.StringIO())
    from dyncli.loader import load_paths
    from dyncli.overrides import expand, parse_sweep

    lps, _ = load_paths([str(ROOT / "problems/vibration/underdamped.yaml")])
    outcomes = [run.solve_one(lp) for lp in expand(lps, [parse_sweep("k=100,400,900")])]
    assert out.getvalue() == emit.dumps("json", outcomes)
    pieces = sum(len(jsonout.encode_parts(run.outcome_record(o), "  ")) + 1 for o in outcomes)
    assert len(writes) == (pieces + 1 if chunk == 1 else 4 if chunk == 1 << 20 else len(writes))
    assert len(writes) <= pieces + 1 and all(len(w) < chunk + 2000 for w in writes)
