"""The JSON writer's long lists of numbers (``jsonout.numbers_json``: pydantic_core's serializer,
its notation mended where it is not ``repr``'s) and its series of flat records written at once
(``_records_json``) give exactly the text of ``json.dumps`` — checked against ``json.dumps`` itself
(never the code under test) on doubles drawn from every bit pattern, the ranges where the two
notations differ (1e-5 ≤ |x| < 1e-4, one-digit exponents, ≥ 1e16), ints of any size and null."""

from __future__ import annotations

import json
import struct

import numpy as np
import pytest

from tests.speed.test_fixed_cost import _reference


def _doubles(n: int, seed: int) -> list[float]:
    """n finite doubles: every bit pattern alike, then each decade from 1e-12 to 1e20, and edges."""
    rng = np.random.default_rng(seed)
    bits = rng.integers(0, 2**64, n, dtype=np.uint64).view(np.float64)
    bits = bits[np.isfinite(bits)]
    dec = rng.random(n) * 10.0 ** rng.integers(-12, 21, n) * np.where(rng.random(n) < 0.5, -1.0, 1.0)
    edges = [0.0, -0.0, 1e-4, -1e-4, 9.999999999999999e-05, 1e-5, 1.5e-5, 1e-6, 1e-9, 1e-10, 1e15, 1e16,
             9999999999999998.0, 1.7976931348623157e308, 5e-324, 2.2250738585072014e-308, 0.1, 1.0, 123.0,
             struct.unpack("<d", struct.pack("<Q", 1))[0]]
    return bits.tolist() + dec.tolist() + edges


def _plain(x) -> str:
    return json.dumps(x, separators=(", ", ": "), allow_nan=False)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_numbers_json_is_json_dumps_for_every_double(seed):
    from dyncli.render.jsonout import numbers_json

    xs = _doubles(60_000, seed)
    assert numbers_json(xs) == _plain(xs) == repr(xs)
    rows = [xs[i:i + 3] for i in range(0, len(xs) - 2, 3)]
    assert numbers_json(rows) == _plain(rows)
    for k in range(0, len(xs), 997):                 # short lists, any mix (the repr path under 64)
        part = xs[k:k + 70]
        assert numbers_json(part) == _plain(part)
        assert numbers_json(part[:5]) == _plain(part[:5])


def test_numbers_json_ints_null_and_nesting():
    from dyncli.render.jsonout import numbers_json

    ints = [0, -1, 7, 2**53 + 1, -(2**70), 10**30] * 20
    assert numbers_json(ints) == _plain(ints)
    mixed = [None if k % 7 == 0 else (k if k % 3 else k * 1e-6) for k in range(200)]
    assert numbers_json(mixed) == _plain(mixed)
    nested = [[[1e-5 * k, -2.5e-7], []] for k in range(100)]
    assert numbers_json(nested) == _plain(nested)


@pytest.mark.parametrize("labels", [("gravity", "drag"), ("custom", "custom#2", "spring"),
                                    ("a:1e-5}", "b"), ('q"uote', "x,y"), ("ü",)])
def test_a_series_of_flat_records_is_written_as_json_dumps(labels):
    """force_terms / power / work at many times (every record the same keys): the layout of
    ``json.dumps(indent=2)`` with each list of numbers on one line; keys that are not plain (a
    quote, a comma, a number's delimiter, non-ASCII) the record-by-record way, the same text."""
    from dyncli.render.jsonout import dumps

    xs = _doubles(3000, 7)
    n = len(labels)
    vectors = [{k: xs[3 * (i * n + j):3 * (i * n + j) + 3] for j, k in enumerate(labels)} for i in range(300)]
    numbers = [{k: xs[i * n + j] for j, k in enumerate(labels)} for i in range(300)]
    ints = [{k: i * (j + 1) for j, k in enumerate(labels)} for i in range(100)]
    rec = [{"results": {"force_terms": vectors, "power": numbers, "n": ints, "t": xs[:500]}, "method": "ode"}]
    assert dumps(rec) == _reference(rec)
    assert json.loads(dumps(rec)) == rec


def test_a_serializer_that_writes_otherwise_is_not_used(monkeypatch):
    """The serializer is checked once against ``json.dumps`` on a probe of every notation; one that
    wrote otherwise (here: no notation mended) is never used, and the text is the same by ``repr``."""
    import pydantic_core

    from dyncli.render import jsonout

    real = pydantic_core.to_json
    monkeypatch.setattr(jsonout, "_PROBE", [])
    real_ok = jsonout._serializer_ok()          # (an older pydantic_core may write otherwise: repr then)
    monkeypatch.setattr(jsonout, "_PROBE", [])
    monkeypatch.setattr(pydantic_core, "to_json", lambda x: real(x).replace(b"e-", b"E-"))
    assert not jsonout._serializer_ok()
    xs = _doubles(2000, 5)
    assert jsonout.numbers_json(xs) == _plain(xs)
    rec = [{"work": [{"a": v, "b": -v} for v in xs[:300]]}]
    assert jsonout.dumps(rec) == _reference(rec)
    monkeypatch.setattr(jsonout, "_PROBE", [])
    monkeypatch.setattr(pydantic_core, "to_json", real)
    assert jsonout._serializer_ok() is real_ok
