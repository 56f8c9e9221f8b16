"""The document memo (dyncli.docmemo): what depends only on a document's plain data is
remembered under a type-exact fingerprint, so equal data shares it and any change -- a swept
param, a value of another type, a mapping changed in place -- is computed afresh; errors are
never remembered; the memo is bounded.  The values are checked against a fresh computation
(the resolver with the memo bypassed) and, for a sweep, against the closed form of the notes
(ωₙ = √(k/m), 17.5b)."""

from __future__ import annotations

import io
import json
import math
import sys

import pytest

from dyncli import docmemo
from dyncli.errors import InputError
from dyncli.expr.params import resolve_params


def test_fingerprint_is_type_exact():
    fp = docmemo.fingerprint
    keys = [fp(x) for x in (1, 1.0, True, "1", 0.0, -0.0, [1], (1,), {"a": 1}, {"a": 1.0}, None)]
    assert len(set(keys)) == len(keys)
    assert fp({"a": [1, 2.5, "x"]}) == fp({"a": [1, 2.5, "x"]})
    assert fp(float("nan")) == fp(float("nan"))
    with pytest.raises(docmemo.Unkeyable):
        fp({"a": object()})
    deep: list = []
    node = deep
    for _ in range(docmemo.DEPTH + 5):
        node.append([])
        node = node[0]
    with pytest.raises(docmemo.Unkeyable):
        fp(deep)


def test_params_remembered_by_content_not_identity():
    raw = {"a": 1.5, "b": "2*a", "c": "sqrt(b)+a"}
    first = resolve_params(raw)
    assert first == {"a": 1.5, "b": 3.0, "c": math.sqrt(3.0) + 1.5}
    first["a"] = 99.0                          # the caller's copy: the memo is not changed
    assert resolve_params(dict(raw)) == {"a": 1.5, "b": 3.0, "c": math.sqrt(3.0) + 1.5}
    raw["a"] = 2                               # changed in place: another key
    assert resolve_params(raw) == {"a": 2.0, "b": 4.0, "c": 4.0}


@pytest.mark.parametrize("raw, where", [({"a": "b", "b": "a"}, "params.a"), ({"a": "nope"}, "params.a"),
                                         ({"a": True}, "params.a")])
def test_params_errors_each_time(raw, where):
    for _ in range(2):
        with pytest.raises(InputError) as err:
            resolve_params(raw)
        assert err.value.path == where


def test_memo_bounded_and_plain_only(monkeypatch):
    monkeypatch.setattr(docmemo, "LIMIT", 8)
    for i in range(50):
        assert resolve_params({"a": i, "b": "a + 1"}) == {"a": float(i), "b": i + 1.0}
    assert docmemo.size() <= 8
    calls = []
    assert docmemo.recall("t", {"x": object()}, lambda: calls.append(1) or 5) == 5
    assert docmemo.recall("t", {"x": object()}, lambda: calls.append(1) or 5) == 5
    assert len(calls) == 2                     # not plain: never remembered


def test_a_swept_param_changes_every_point(tmp_path, monkeypatch):
    """A sweep of a param that the stiffness and a query's time read: each point its own."""
    from dyncli import run

    f = tmp_path / "p.yaml"
    f.write_text("type: vibration\nm: 2\nparams: {kk: 100, T: '2*pi/sqrt(kk/2)'}\nk: kk\nzeta: 0.1\n"
                 "L: 0.3\nx0: 0.35\nfind:\n  - {t: T}\n", encoding="utf-8")
    out = io.StringIO()
    monkeypatch.setattr(sys, "stdout", out)
    assert run.solve_command([str(f)], "json", sweeps=["params.kk=100,400,100"]) == 0
    recs = json.loads(out.getvalue())
    for rec, k in zip(recs, (100, 400, 100)):
        wn = math.sqrt(k / 2)
        assert rec["results"]["omega_n"] == pytest.approx(wn, rel=1e-15)
        assert rec["results"]["find"][0]["t"] == pytest.approx(2 * math.pi / wn, rel=1e-15)


def test_constant_expressions_are_remembered_per_text_and_params_never_their_errors():
    import math

    import pytest

    from dyncli.expr import ExpressionError
    from dyncli.expr.parser import constant

    assert constant("sqrt(k/m)", {"k": 25.0, "m": 1.0}) == 5.0
    assert constant("sqrt(k/m)", {"k": 25.0, "m": 4.0}) == 2.5          # other params: computed afresh
    assert constant("sqrt(k/m)", {"k": 25.0, "m": 1.0}) == 5.0
    assert math.copysign(1.0, constant("-x", {"x": 0.0})) == -1.0
    assert math.copysign(1.0, constant("-x", {"x": -0.0})) == 1.0       # -0.0 and 0.0: two keys
    for _ in range(2):                                                   # an error raised each time
        with pytest.raises(ExpressionError):
            constant("sqrt(", {})
