"""Issue #29, the Python API misused and the sweeps: the API raises only
InputError, NumericalError or TypeError, each with a message, for any input;
a swept value that is a string or a scalar is refused naming the fix (never
swept by its characters); a field given values twice is refused; the
derivative-jet cache is bounded."""

from __future__ import annotations

import pytest

import dyncli
from tests.conftest import ROOT, run_cli

BASE = {"type": "vibration", "m": 1, "k": 100, "x0": 0.1}
ALLOWED = (dyncli.InputError, dyncli.NumericalError, TypeError)


def _self_referencing():
    d = dict(BASE, params={})
    d["params"]["me"] = d
    return d


def _deep(n=2000):
    d = dict(BASE)
    cur = d
    for _ in range(n):
        cur["x"] = {}
        cur = cur["x"]
    return d


def _cyclic_list():
    x: list = [1]
    x.append(x)
    return x


MISUSE = {
    "self-referencing mapping": lambda: dyncli.solve(_self_referencing()),
    "2,000-deep mapping": lambda: dyncli.solve(_deep()),
    "cyclic override": lambda: dyncli.solve(BASE, k=_cyclic_list()),
    "euler |H| beyond a double": lambda: dyncli.solve(
        {"type": "euler", "coin": {"m": 0.005, "R": 0.012, "h": 0.002}, "omega0": [1e200, 1e200, 1e200], "at": [0, 1]}),
    "euler with NaN H": lambda: dyncli.solve(
        {"type": "euler", "coin": {"m": 1e300, "R": 1e10, "h": 0.002}, "omega0": [1e100, 0, 3], "at": [0, 1]}),
    "gyroscope C beyond a double": lambda: dyncli.solve(
        {"type": "gyroscope", "I1": 1e308, "I2": 1e308, "p": 1e300, "q": 1e300, "at": [0, 1]}),
    "precession m g L beyond a double": lambda: dyncli.solve(
        {"type": "precession", "m": 1e200, "L": 1e200, "I11": 0.006, "I33": 0.002, "theta": 0.5, "p": 200}),
    "masses summing beyond a double": lambda: dyncli.solve(
        {"type": "inertia", "parts": [{"shape": "point", "mass": 1e308, "at": [1, 0, 0]},
                                      {"shape": "point", "mass": 1e308, "at": [-1, 0, 0]}]}),
    "source of a wrong type": lambda: dyncli.solve(42),
    "source a list": lambda: dyncli.solve([BASE]),
    "override an object": lambda: dyncli.solve(BASE, k=object()),
    "override complex": lambda: dyncli.solve(BASE, k=1j),
    "sweep not a mapping": lambda: dyncli.sweep(BASE, 5),
    "sweep path not a string": lambda: dyncli.sweep(BASE, {1: [1, 2]}),
    "sweep empty": lambda: dyncli.sweep(BASE, {"k": []}),
    "sweep unknown path": lambda: dyncli.sweep(BASE, {"nope": [1]}),
    "units unknown": lambda: dyncli.solve(BASE)[0].table(units="furlong"),
    "units not text": lambda: dyncli.solve(BASE)[0].table(units=5),
    "digits negative": lambda: dyncli.solve(BASE)[0].table(digits=-1),
    "digits fractional": lambda: dyncli.solve(BASE)[0].table(digits=2.5),
}


@pytest.mark.parametrize("name", list(MISUSE))
def test_the_api_raises_only_its_documented_errors_with_a_message(name):
    try:
        MISUSE[name]()
    except ALLOWED as exc:
        assert str(exc).strip(), f"{name}: {type(exc).__name__} without a message"
        return
    except BaseException as exc:  # noqa: BLE001 - the point of the test
        pytest.fail(f"{name}: raised {type(exc).__name__}: {exc}")


@pytest.mark.parametrize("value", ["100", 100, 250.5, {"a": 1}, b"100"])
def test_a_swept_string_or_scalar_is_refused_naming_the_fix(value):
    """Never swept character by character ('1', '0', '0') or key by key, never a bare TypeError."""
    with pytest.raises(dyncli.InputError, match=r"sweep k: give a list of values, e\.g\. \{'k': \[100, 200, 300\]\}"):
        dyncli.sweep(BASE, {"k": value})


@pytest.mark.parametrize("value, points", [([100, 200], [100.0, 200.0]), ((300,), [300.0]), (range(100, 301, 200), [100.0, 300.0])])
def test_a_sequence_sweeps_by_element(value, points):
    sols = dyncli.sweep(BASE, {"k": value})
    assert [s.results["omega_n"] ** 2 for s in sols] == pytest.approx(points, rel=1e-12)   # ω² = k/m, m = 1


def test_numpy_values_sweep_by_element_and_a_0d_array_is_refused():
    np = pytest.importorskip("numpy")
    assert len(dyncli.sweep(BASE, {"k": np.linspace(100, 400, 4)})) == 4
    for one in (np.float64(100), np.array(100.0)):
        with pytest.raises(dyncli.InputError, match="give a list of values"):
            dyncli.sweep(BASE, {"k": one})


@pytest.mark.parametrize("args", [
    ["--sweep", "k=1,2", "--sweep", "k=3,4"],
    ["--set", "k=5", "--sweep", "k=3,4"],
    ["--set", "k=5", "--set", "k=6"],
    ["--sweep", "base=[1,2]", "--set", "base.omega=3"],
])
def test_a_field_given_values_twice_is_refused(args):
    rc, out, err = run_cli("solve", str(ROOT / "problems/vibration/base-excitation.yaml"), *args, "-f", "json")
    assert rc == 2 and not out
    assert "both give" in err and len(err.strip().splitlines()) == 1, err


def test_the_derivative_jet_cache_is_bounded():
    from dyncli.expr import jet

    prob = {"type": "kinematics", "coordinates": "cylindrical", "params": {"a": 2, "c": 0.5, "w": 3},
            "position": {"r": "a", "theta": "w*t", "x3": "c*w*t"}, "at": [0, 1]}
    for i in range(jet.CACHE_SIZE + 40):
        dyncli.solve(dict(prob, position=dict(prob["position"], r=f"a + {i}*t")))
    assert len(jet._CACHE) <= jet.CACHE_SIZE


def test_lru_drops_the_least_recently_used():
    from dyncli.expr.jet import Lru

    c = Lru(2)
    c.put("a", 1)
    c.put("b", 2)
    assert c.get("a") == 1          # a is now the most recent
    c.put("c", 3)
    assert c.get("b") is None and c.get("a") == 1 and c.get("c") == 3


@pytest.mark.parametrize("call", [
    lambda: dyncli.solve(dict(BASE, **{"x" * 100_001: 1})),
    lambda: dyncli.sweep(BASE, {"y" * 100_001: [1]}),
    lambda: dyncli.solve(dict(BASE, params={"-" * 100_001: 1})),
])
def test_a_long_user_string_is_shortened_in_the_api_message(call):
    from dyncli.printable import MAX_LINE

    with pytest.raises(dyncli.InputError) as info:
        call()
    assert all(len(m) < MAX_LINE + 100 for m in info.value.messages), [len(m) for m in info.value.messages]
