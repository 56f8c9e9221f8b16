"""The ``find`` queries of §11 (dyncli/queries.py) on analytic motions: crossing times and
extremes against closed forms, direction and occurrence, touching without crossing, a value
held at the start, windows, ``at_end``, equal extremes, every refused query, and property tests
at the extremes of span, offset and amplitude."""

from __future__ import annotations

import math

import mpmath as mp
import pytest
from hypothesis import assume, given, settings, strategies as st

from dyncli.errors import InputError
from dyncli.expr import constant
from dyncli.queries import AtTime, Extreme, When, answer, parse_queries

EPS = 2.220446049250313e-16
PI = math.pi


class Motion:
    """An analytic motion: ``paths`` maps a name to (f, f') (f' None: no rate known)."""

    def __init__(self, paths, t0=0.0, t_end=10.0, n=10, breaks=None, rate=True):
        self._paths, self.t0, self.t_end, self.use_rate = paths, float(t0), float(t_end), rate
        self.breaks = breaks if breaks is not None else [t0 + (t_end - t0) * k / n for k in range(n)] + [t_end]
        self.calls = 0

    def paths(self):
        return list(self._paths)

    def value(self, path, t):
        self.calls += 1
        return float(self._paths[path][0](t))

    def rate(self, path, t):
        d = self._paths[path][1]
        return None if d is None or not self.use_rate else float(d(t))


def one(raw, motion):
    return answer(parse_queries([raw], lambda x: constant(x, {"a": 0.5})), motion)[0]


def close(t, exact, rel=1e-13):
    return t is not None and abs(t - exact) <= rel * max(abs(exact), 1.0)


SIN = {"x": (math.sin, math.cos)}


# ------------------------------------------------------------------------- crossings

@pytest.mark.parametrize("rate", [True, False])
def test_sin_crossings_direction_and_occurrence(rate):
    m = Motion(SIN, 0, 15, n=7, rate=rate)
    c = math.asin(0.5)
    cases = [({}, [c, PI - c, 2 * PI + c, 3 * PI - c, 4 * PI + c]),
             ({"direction": "up"}, [c, 2 * PI + c, 4 * PI + c]),
             ({"direction": "down"}, [PI - c, 3 * PI - c]),
             ({"direction": "any"}, [c, PI - c, 2 * PI + c])]
    for extra, times in cases:
        for n, exact in enumerate(times, 1):
            a = one({"when": {"x": 0.5}, "occurrence": n, **extra}, m)
            assert a["reached"] and a["at_end"] is None and close(a["t"], exact), (extra, n, a, exact)
    a = one({"when": {"x": 0.5}, "direction": "down", "occurrence": 3}, m)
    assert a == {"t": None, "reached": False, "at_end": None}


def test_value_as_constant_expression_and_param():
    m = Motion(SIN, 0, 10)
    assert close(one({"when": {"x": "sin(pi/6)"}}, m)["t"], PI / 6)
    assert close(one({"when": {"x": "a"}}, m)["t"], PI / 6)
    assert close(one({"t": "pi"}, m)["t"], PI)


def test_two_crossings_inside_one_step_are_seen():
    # sin(20 t) dips below 0.9 and back within one break interval of length 0.3
    m = Motion({"x": (lambda t: math.sin(20 * t), lambda t: 20 * math.cos(20 * t))}, 0, 3, n=10)
    c = math.asin(0.9) / 20
    ts = [one({"when": {"x": 0.9}, "occurrence": k}, m)["t"] for k in (1, 2, 3)]
    assert close(ts[0], c) and close(ts[1], PI / 20 - c) and close(ts[2], 2 * PI / 20 + c)


@pytest.mark.parametrize("rate", [True, False])
def test_damped_oscillation_zeros(rate):
    f = lambda t: math.exp(-0.3 * t) * math.cos(2 * t)                                   # noqa: E731
    df = lambda t: math.exp(-0.3 * t) * (-0.3 * math.cos(2 * t) - 2 * math.sin(2 * t))   # noqa: E731
    m = Motion({"q": (f, df)}, 0, 12, n=9, rate=rate)
    for k in range(1, 7):
        assert close(one({"when": {"q": 0}, "occurrence": k}, m)["t"], (PI / 2 + (k - 1) * PI) / 2)
    # the first upward crossing of -0.2
    t = one({"when": {"q": -0.2}, "direction": "up"}, m)["t"]
    assert close(f(t), -0.2, 1e-14) and df(t) > 0 and PI / 2 < 2 * t < 2 * PI


def test_piecewise_crossing_at_a_break_and_kink():
    # x = t up to 1, then 2 - t (a kink at the break 1): reaches 1 at the kink without crossing
    f = lambda t: t if t < 1 else 2 - t                      # noqa: E731
    df = lambda t: 1.0 if t < 1 else -1.0                   # noqa: E731
    for rate in (True, False):
        m = Motion({"x": (f, df)}, 0, 3, breaks=[0, 0.37, 1, 2.2, 3], rate=rate)
        a = one({"when": {"x": 1}}, m)
        assert a["reached"] and close(a["t"], 1.0)
        assert close(one({"when": {"x": 0.5}, "occurrence": 2}, m)["t"], 1.5)
        assert close(one({"when": {"x": 0}, "occurrence": 1}, m)["t"], 2.0)


# ------------------------------------------------------------------------- touching

def test_touch_with_rate_is_exact():
    m = Motion({"x": (math.cos, lambda t: -math.sin(t))}, 0.5, 14, n=11)
    a = one({"when": {"x": 1}}, m)
    assert close(a["t"], 2 * PI)
    assert close(one({"when": {"x": -1}}, m)["t"], PI)
    # a touch of a maximum arrives from below: up; of a minimum from above: down
    assert close(one({"when": {"x": 1}, "direction": "up"}, m)["t"], 2 * PI)
    assert one({"when": {"x": 1}, "direction": "down"}, m)["reached"] is False
    assert close(one({"when": {"x": -1}, "direction": "down", "occurrence": 2}, m)["t"], 3 * PI)


def test_touch_without_rate_within_the_minimisers_resolution():
    m = Motion({"x": (math.cos, None)}, 0.5, 14, n=11)
    assert abs(one({"when": {"x": 1}}, m)["t"] - 2 * PI) < 1e-7
    assert abs(one({"when": {"x": -1}, "occurrence": 2}, m)["t"] - 3 * PI) < 1e-7


@pytest.mark.parametrize("rate,n", [(True, 4), (True, 30), (False, 4), (False, 30)])
def test_damped_touch_of_an_interior_peak(rate, n):
    f = lambda t: math.exp(-0.3 * t) * math.cos(2 * t)                                   # noqa: E731
    df = lambda t: math.exp(-0.3 * t) * (-0.3 * math.cos(2 * t) - 2 * math.sin(2 * t))   # noqa: E731
    tp = (2 * PI - math.atan(0.15)) / 2                     # the second peak; the first crossing is on the way down
    m = Motion({"q": (f, df)}, 0, 12, n=n, rate=rate)
    for fac in (1, 1 + 1e-15, 1 - 1e-15):
        a = one({"when": {"q": f(tp) * fac}, "occurrence": 2}, m)
        assert abs(a["t"] - tp) < (1e-13 if rate else 1e-8)
    assert one({"when": {"q": f(tp) * (1 + 1e-9)}, "occurrence": 2}, m)["reached"] is False
    t = one({"when": {"q": f(tp) * (1 - 1e-9)}, "occurrence": 2}, m)["t"]
    assert close(f(t), f(tp) * (1 - 1e-9), 1e-14) and df(t) > 0


def test_quadratic_touch_and_miss():
    f = lambda t: 4 - (t - 2) ** 2                          # noqa: E731
    m = Motion({"s": (f, lambda t: -2 * (t - 2))}, 0, 5, n=3)
    assert close(one({"when": {"s": 4}}, m)["t"], 2.0)
    assert one({"when": {"s": 4 + 1e-9}}, m)["reached"] is False
    assert close(one({"when": {"s": 4 - 1e-6}}, m)["t"], 2 - 1e-3, 1e-9)
    assert close(one({"when": {"s": 4 - 1e-6}, "occurrence": 2}, m)["t"], 2 + 1e-3, 1e-9)


# ------------------------------------------------------------------------- held at the start

def test_value_held_at_the_start_counts_when_reached_again():
    # from rest: v = -sin t; {v: 0} is the next turning point, not the release
    m = Motion({"v": (lambda t: -math.sin(t), lambda t: -math.cos(t))}, 0, 10, n=8)
    assert close(one({"when": {"v": 0}}, m)["t"], PI)
    assert close(one({"when": {"v": 0}, "direction": "down"}, m)["t"], 2 * PI)
    # held for a while, then leaves and comes back
    f = lambda t: 0.0 if t <= 1 else math.sin(t - 1)        # noqa: E731
    m = Motion({"x": (f, None)}, 0, 10, breaks=[0, 0.4, 1, 2, 4, 7, 10])
    assert close(one({"when": {"x": 0}}, m)["t"], 1 + PI)


def test_stops_on_the_value_and_stays():
    # the speed reaches 0 at t = 1 and stays (a block that sticks): the stop time, exactly
    f = lambda t: max(1.0 - t, 0.0)                         # noqa: E731
    for rate in (True, False):
        m = Motion({"v": (f, lambda t: -1.0 if t < 1 else 0.0)}, 0, 4, breaks=[0, 1.7, 4], rate=rate)
        assert close(one({"when": {"v": 0}}, m)["t"], 1.0)
    # a plateau on the value in the middle, leaving to the same side: reached at its start
    g = lambda t: min((t - 1) ** 2, 1) if t < 1 else (0.0 if t < 2 else (t - 2) ** 2)   # noqa: E731
    m = Motion({"x": (g, None)}, 0, 3, breaks=[0, 0.45, 1.3, 3])
    assert close(one({"when": {"x": 0}}, m)["t"], 1.0, 1e-12)


def test_touch_at_a_cut_on_the_extreme_is_its_exact_time():
    # a monotone route cuts its pieces at the exact extremes (sin t at π/2): a target equal to the
    # extreme is touched at the cut, as {max: x} answers, not at Brent's minimiser's time (~√eps:
    # 8e-9 s off on euler's closed form, with ω₂ = sin t and {when: {omega.1: 1}})
    for breaks in ([0, PI / 2, 3], [0, 0.4, PI / 2, 2.1, 3]):
        m = Motion({"x": (math.sin, None)}, 0, 3, breaks=breaks, rate=False)
        m.monotone, m.subdivide = True, 1
        assert close(one({"when": {"x": 1}}, m)["t"], PI / 2, 4 * EPS)
        assert close(one({"max": "x"}, m)["t"], PI / 2, 4 * EPS)


def test_touch_at_a_kink_whose_cut_lies_a_little_off_it():
    # |t − 1| on a monotone route whose cut at the kink lies 4e-14 s off it (an interpolant's
    # critical point): the value there, 4e-14, is beyond the rounding, yet 0 is met at t = 1.
    # Before: "not reached" while {min: x} answered 0 at t = 1 (bearing-forces, omega: abs(t-1)).
    # (Without a rate Brent's minimiser places a kink to ~1e-12 only: neither finds it then.)
    f = lambda t: abs(t - 1)                               # noqa: E731
    for breaks in ([0, 0.5, 1 + 4e-14, 3], [0, 1 - 3e-14, 1.7, 3]):
        m = Motion({"x": (f, lambda t: 1.0 if t > 1 else -1.0)}, 0, 3, breaks=breaks)
        m.monotone, m.subdivide = True, 1
        assert close(one({"when": {"x": 0}}, m)["t"], 1.0, 1e-15)
        assert one({"when": {"x": -1e-9}}, m)["reached"] is False
        assert close(one({"when": {"x": "1e-9"}, "occurrence": 2}, m)["t"], 1 + 1e-9, 1e-15)


def test_an_asymptote_is_not_reached():
    # x = (1 + t) e^-t (a critically damped return from rest) is > 0 for every t, its rounding
    # within the tolerance of 0 from t ≈ 37.6 s on: never reached (before: "reached" at t ≈ 37.6)
    f = lambda t: (1 + t) * math.exp(-t)                   # noqa: E731
    for rate in (True, False):
        m = Motion({"x": (f, lambda t: -t * math.exp(-t))}, 0, 100, n=40, rate=rate)
        notes: dict[int, str] = {}
        got = answer(parse_queries([{"when": {"x": 0}}, {"when": {"x": "1e-10"}}]), m, notes)
        assert got[0] == {"t": None, "reached": False, "at_end": None}
        assert "only approaches 0" in notes[0]
        with mp.workdps(30):                                 # a level above the rounding: crossed
            want = mp.findroot(lambda t: (1 + t) * mp.exp(-t) - mp.mpf("1e-10"), 26)
        assert close(got[1]["t"], float(want), 1e-12)
    # a value met at the very end, computed a rounding short of it: reached (at the end)
    m = Motion({"x": (lambda t: 0.1 * t, lambda t: 0.1)}, 0, 3, n=4)
    assert close(one({"when": {"x": math.nextafter(0.1 * 3, 1)}}, m)["t"], 3.0, 1e-14)


def test_reaches_the_value_at_the_end():
    m = Motion({"x": (lambda t: t, lambda t: 1.0)}, 0, 2, n=3)
    assert one({"when": {"x": 2}}, m) == {"t": 2.0, "reached": True, "at_end": None}
    assert one({"when": {"x": 2.5}}, m)["reached"] is False


# ------------------------------------------------------------------------- extremes

@pytest.mark.parametrize("rate", [True, False])
def test_extremes_of_a_damped_oscillation(rate):
    f = lambda t: math.exp(-0.3 * t) * math.cos(2 * t)                                   # noqa: E731
    df = lambda t: math.exp(-0.3 * t) * (-0.3 * math.cos(2 * t) - 2 * math.sin(2 * t))   # noqa: E731
    m = Motion({"q": (f, df)}, 0, 12, n=9, rate=rate)
    tol = 1e-13 if rate else 1e-7
    a = one({"max": "q"}, m)
    assert a == {"t": 0.0, "reached": True, "at_end": True}
    a = one({"min": "q"}, m)
    assert not a["at_end"] and abs(a["t"] - (PI - math.atan(0.15)) / 2) < tol
    a = one({"max": "q", "within": [1, 10]}, m)
    assert not a["at_end"] and abs(a["t"] - (2 * PI - math.atan(0.15)) / 2) < tol
    a = one({"min": "q", "within": [1, 1.2]}, m)              # decreasing there: the window's end
    assert a == {"t": 1.2, "reached": True, "at_end": True}


def test_quadratic_extremes_and_window_ends():
    f = lambda t: 4 - (t - 2) ** 2                          # noqa: E731
    for rate in (True, False):
        m = Motion({"s": (f, lambda t: -2 * (t - 2))}, 0, 5, n=3, rate=rate)
        a = one({"max": "s"}, m)
        assert not a["at_end"] and abs(a["t"] - 2) < (1e-15 if rate else 1e-7)
        assert one({"min": "s"}, m) == {"t": 5.0, "reached": True, "at_end": True}
        assert one({"min": "s", "within": [0, 3.5]}, m) == {"t": 0.0, "reached": True, "at_end": True}
        assert one({"max": "s", "within": ["1/2", 1]}, m) == {"t": 1.0, "reached": True, "at_end": True}
        assert one({"max": "s", "within": [3, 3]}, m) == {"t": 3.0, "reached": True, "at_end": True}


def test_kink_extreme_at_a_break():
    f = lambda t: t if t < 1 else 2 - t                      # noqa: E731
    for rate in (True, False):
        m = Motion({"x": (f, lambda t: 1.0 if t < 1 else -1.0)}, 0, 3, breaks=[0, 0.37, 1, 2.2, 3], rate=rate)
        a = one({"max": "x"}, m)
        assert close(a["t"], 1.0) and a["at_end"] is False


@pytest.mark.parametrize("rate", [True, False])
def test_equal_extremes_the_first(rate):
    m = Motion(SIN, 0, 4 * PI + 1, n=13, rate=rate)
    assert abs(one({"max": "x"}, m)["t"] - PI / 2) < (1e-13 if rate else 1e-7)
    assert abs(one({"min": "x"}, m)["t"] - 3 * PI / 2) < (1e-13 if rate else 1e-7)
    m = Motion({"x": (math.cos, lambda t: -math.sin(t))}, 0, 2 * PI, n=5, rate=rate)
    assert one({"max": "x"}, m) == {"t": 0.0, "reached": True, "at_end": True}
    m = Motion({"x": (lambda t: 3.0, lambda t: 0.0)}, 1, 2, n=4, rate=rate)
    assert one({"min": "x"}, m) == {"t": 1.0, "reached": True, "at_end": True}


def test_least_value_of_a_body_that_sticks_is_at_the_stop():
    # a speed² that falls to 0 at the stop t = 1 (a break, where the phase before leaves rounding:
    # 3e-30) and stays 0 to the end, on a monotone motion (the ODE routes' cut steps): the least
    # value is reached at the stop, not at the end of the motion (first of equal extremes)
    f = lambda t: (1 - t) ** 2 if t < 1 else (3e-30 if t == 1 else 0.0)          # noqa: E731
    df = lambda t: -2 * (1 - t) if t < 1 else 0.0                                  # noqa: E731
    for rate in (True, False):
        for breaks in ([0, 0.5, 1, 5], [0, 0.5, 1, 1.000001, 2, 5]):
            m = Motion({"T": (f, df)}, 0, 5, breaks=breaks, rate=rate)
            m.monotone, m.subdivide = True, 1
            assert one({"min": "T"}, m) == {"t": 1.0, "reached": True, "at_end": False}
            assert one({"min": "T", "within": [0.5, 3]}, m) == {"t": 1.0, "reached": True, "at_end": False}
    # still rising at the end of the window (its rate not 0), by less than the tolerance: the end
    for rate in (True, False):
        m = Motion({"x": (lambda t: 1 + 1e-13 * t, lambda t: 1e-13)}, 0, 5, breaks=[0, 4.99, 5], rate=rate)
        m.monotone, m.subdivide = True, 1
        assert one({"max": "x"}, m) == {"t": 5.0, "reached": True, "at_end": True}


def test_window_clipped_to_the_motion():
    m = Motion(SIN, 0, 10)
    assert one({"max": "x", "within": [20, 30]}, m) == {"t": None, "reached": False, "at_end": None}
    a = one({"max": "x", "within": [-5, 1]}, m)
    assert a == {"t": 1.0, "reached": True, "at_end": True}


def test_at_time():
    m = Motion(SIN, 1, 10)
    assert one({"t": 1}, m) == {"t": 1.0, "reached": True, "at_end": None}
    assert one({"t": 10}, m)["reached"] and not one({"t": 10.5}, m)["reached"]
    assert one({"t": 0.5}, m) == {"t": None, "reached": False, "at_end": None}


def test_answers_in_order_and_frozen_queries():
    qs = parse_queries([{"t": 1}, {"when": {"x.A.1": 0}, "direction": "up", "occurrence": 2.0},
                        {"min": "theta", "within": ["pi", "2*pi"]}], constant)
    assert qs == [AtTime(1.0, 0), When("x.A.1", 0.0, "up", 2, 1), Extreme("theta", "min", (PI, 2 * PI), 2)]
    with pytest.raises(AttributeError):
        qs[0].t = 2
    assert parse_queries([], constant) == [] and parse_queries(None, constant) == []
    m = Motion({"x.A.1": (math.sin, math.cos), "theta": (math.cos, None)}, 0, 13)
    out = answer(qs, m)    # sin: 0 held at the start, up through 0 at 2 pi and 4 pi
    assert [a["reached"] for a in out] == [True, True, True] and close(out[1]["t"], 4 * PI)
    assert close(out[2]["t"], PI) and out[2]["at_end"] is True


# ------------------------------------------------------------------------- refused

@pytest.mark.parametrize("raw,path,words", [
    ({"t": 1}, "find", ["list"]),
    ([3], "find.0", ["mapping"]),
    ([{"whn": {"x": 1}}], "find.0.whn", ["did you mean 'when'"]),
    ([{"max": "x", "withn": [0, 1]}], "find.0.withn", ["did you mean 'within'"]),
    ([{"direction": "up"}], "find.0", ["one of t, when, max, min or event"]),
    ([{"max": "x", "min": "x"}], "find.0.min", ["two queries"]),
    ([{"t": 1, "occurrence": 2}], "find.0.occurrence", ["goes with when"]),
    ([{"when": {"x": 1}, "within": [0, 1]}], "find.0.within", ["goes with max and min"]),
    ([{"t": "tt"}], "find.0.t", ["constant expression", "'tt' is not a number"]),
    ([{"t": True}], "find.0.t", ["boolean"]),
    ([{"t": "1/0"}], "find.0.t", ["constant expression"]),
    ([{"when": {"x": "y + 1"}}], "find.0.when.x", ["value of x", "unknown name"]),
    ([{"when": {"x": None}}], "find.0.when.x", ["null"]),
    ([{"when": {"x": [1, 2]}}], "find.0.when.x", ["a list"]),
    ([{"when": {"x": 1, "y": 2}}], "find.0.when", ["one result"]),
    ([{"when": "x"}], "find.0.when", ["one result"]),
    ([{"when": {1: 2}}], "find.0.when", ["result path"]),
    ([{"when": {"x": 1}, "direction": "upp"}], "find.0.direction", ["did you mean 'up'"]),
    ([{"when": {"x": 1}, "direction": 1}], "find.0.direction", ["up, down or any"]),
    ([{"when": {"x": 1}, "occurrence": 0}], "find.0.occurrence", ["from 1"]),
    ([{"when": {"x": 1}, "occurrence": -2}], "find.0.occurrence", ["from 1"]),
    ([{"when": {"x": 1}, "occurrence": 1.5}], "find.0.occurrence", ["whole number"]),
    ([{"when": {"x": 1}, "occurrence": True}], "find.0.occurrence", ["whole number"]),
    ([{"max": "x", "within": [2, 1]}], "find.0.within", ["reversed", "[1, 2]"]),
    ([{"max": "x", "within": [1]}], "find.0.within", ["[t1, t2]"]),
    ([{"max": "x", "within": 3}], "find.0.within", ["[t1, t2]"]),
    ([{"min": "x", "within": [0, "q"]}], "find.0.within.1", ["window's end"]),
    ([{"min": "x", "within": [".inf", 1]}], "find.0.within.0", ["window's start"]),
    ([{"min": "x", "within": [float("-inf"), 1]}], "find.0.within.0", ["finite"]),
    ([{"max": 3}], "find.0.max", ["result path"]),
    ([{"min": ""}], "find.0.min", ["result path"]),
    ([{"t": 1}, {"when": {"x": 1}, "occurrence": 0}], "find.1.occurrence", ["from 1"]),
])
def test_refused(raw, path, words):
    with pytest.raises(InputError) as exc:
        parse_queries(raw, constant)
    assert exc.value.path == path
    for w in words:
        assert w in exc.value.message, exc.value.message


@pytest.mark.parametrize("raw,path", [({"when": {"x.A.2": 0}}, "find.0.when"), ({"max": "x.A.2"}, "find.0.max"),
                                      ({"min": "x.A.2"}, "find.0.min")])
def test_unknown_path(raw, path):
    m = Motion({"x.A.1": (math.sin, math.cos), "theta": (math.cos, None)}, 0, 1)
    with pytest.raises(InputError) as exc:
        answer(parse_queries([raw], constant), m)
    assert exc.value.path == path and "'x.A.2'" in exc.value.message and "did you mean 'x.A.1'" in exc.value.message


@pytest.mark.parametrize("raw,path", [({"when": {"v": 1}}, "find.0.when"), ({"max": "x.A"}, "find.0.max")])
def test_a_vector_asks_for_a_component(raw, path):
    # before: "no result 'v' to search (did you mean 'V'?)", which leads away from v.0
    m = Motion({"x.A.0": (math.sin, math.cos), "x.A.1": (math.sin, math.cos), "V": (math.cos, None),
                "v.0": (math.cos, None), "v.1": (math.cos, None), "v.2": (math.cos, None)}, 0, 1)
    with pytest.raises(InputError) as exc:
        answer(parse_queries([raw], constant), m)
    name = path and (raw.get("max") or next(iter(raw["when"])))
    assert exc.value.path == path and f"'{name}' is not one number" in exc.value.message
    assert f"{name}.0" in exc.value.message


@pytest.mark.parametrize("raw,path", [({"max": "x3"}, "find.0.max"), ({"when": {"v1": 0}}, "find.0.when")])
def test_the_notes_component_names_point_to_the_component_counted_from_0(raw, path):
    # before: "no result 'x3' to search; the scalar results are E, T, V, ..." (no way to x.2)
    m = Motion({f"{k}.{i}": (math.sin, math.cos) for k in "xv" for i in range(3)} | {"E": (math.cos, None)}, 0, 1)
    with pytest.raises(InputError) as exc:
        answer(parse_queries([raw], constant), m)
    name = raw.get("max") or next(iter(raw["when"]))
    comp = f"{name[0]}.{int(name[1]) - 1}"
    assert exc.value.path == path and f"'{comp}'" in exc.value.message and "counting from 0" in exc.value.message


# ------------------------------------------------------------------------- properties

def _sine(A, t0, span, periods, n, rate=True):
    w = 2 * PI * periods / span
    return Motion({"x": (lambda t: A * math.sin(w * (t - t0)), lambda t: A * w * math.cos(w * (t - t0)))},
                  t0, t0 + span, n=n, rate=rate), w


amplitude = st.floats(-250, 250).map(lambda e: 10.0 ** e)
offset = st.sampled_from([0.0, 1.0, -3e3, 1e6, -1e9])
span = st.floats(-6, 6).map(lambda e: 10.0 ** e)


@settings(max_examples=60, deadline=None, database=None)
@given(A=amplitude, t0=offset, span=span, periods=st.floats(1.3, 4.0), n=st.integers(4, 30),
       c=st.one_of(st.just(0.0), st.floats(1e-3, 0.95), st.floats(-0.95, -1e-3)))
def test_property_crossings(A, t0, span, periods, n, c):
    assume(abs(t0) / span < 1e6)                # the time resolution eps |t| well inside a period
    m, w = _sine(A, t0, span, periods, n)
    theta = math.asin(c) if c > 0 else (PI - math.asin(c) if c < 0 else PI)    # c = 0: held at the start
    exact = t0 + theta / w
    t = one({"when": {"x": A * c}}, m)["t"]
    # the time itself is known to eps |t|; the phase w (t - t0) to eps |t| w
    tol = 64 * EPS * (abs(t0) + span) / max(math.sqrt(1 - c * c), 0.3)
    assert t is not None and abs(t - exact) <= tol, (t, exact, tol)


@settings(max_examples=60, deadline=None, database=None)
@given(A=amplitude, t0=offset, span=span, periods=st.floats(1.3, 4.0), n=st.integers(4, 30),
       rate=st.booleans())
def test_property_extremes(A, t0, span, periods, n, rate):
    assume(abs(t0) / span < 1e6)
    m, w = _sine(A, t0, span, periods, n, rate)
    tol = 64 * EPS * (abs(t0) + span) if rate else 1e-7 * span + 64 * EPS * abs(t0)
    a = one({"max": "x"}, m)
    assert not a["at_end"] and abs(a["t"] - (t0 + PI / 2 / w)) <= tol, (a, t0 + PI / 2 / w)
    a = one({"min": "x"}, m)
    assert not a["at_end"] and abs(a["t"] - (t0 + 1.5 * PI / w)) <= tol
    # a touch of the maximum, reached from below
    a = one({"when": {"x": A}, "direction": "up"}, m)
    assert a["reached"] and abs(a["t"] - (t0 + PI / 2 / w)) <= (tol if rate else 1e-6 * span + 64 * EPS * abs(t0))
