"""Property tests: random valid rectilinear problems of every case never crash,
answers are consistent with the queries, and the reported s, v satisfy
ds/dt = v, dv/dt = a along the answer (central differences of t-queries) and
agree with an independent high-accuracy integration of the ODE."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.conftest import solve_text

num = lambda lo, hi: st.floats(lo, hi, allow_nan=False, allow_infinity=False).map(lambda x: round(x, 3))


@st.composite
def acceleration(draw):
    kind = draw(st.sampled_from(["t", "v", "v-grow", "s", "s-unstable", "general"]))
    c = [draw(num(0.0, 3.0)) for _ in range(4)]
    w = draw(num(0.3, 4.0))
    if kind == "t":
        text = f"{c[0] - 1.5} + {c[1]}*sin({w}*t + {c[2]})"
        fn = lambda t, s, v: (c[0] - 1.5) + c[1] * np.sin(w * t + c[2])
    elif kind == "v":
        text = f"{c[0] - 1.5} - {c[1]}*v - {c[2] / 10}*v*abs(v)"
        fn = lambda t, s, v: (c[0] - 1.5) - c[1] * v - c[2] / 10 * v * abs(v)
    elif kind == "v-grow":
        text = f"{c[0] - 1.5} + {c[1] / 3}*v"
        fn = lambda t, s, v: (c[0] - 1.5) + c[1] / 3 * v
    elif kind == "s":
        k = c[0] + 0.2
        text = f"-{k}*s - {c[1] / 3}*s**3 + {c[2] - 1.5}"
        fn = lambda t, s, v: -k * s - c[1] / 3 * s ** 3 + (c[2] - 1.5)
    elif kind == "s-unstable":
        text = f"{c[0] / 2}*s - {c[1]}"
        fn = lambda t, s, v: c[0] / 2 * s - c[1]
    else:
        k = c[0] + 0.2
        text = f"-{k}*s - {c[1] / 3}*v + {c[2]}*sin({w}*t)"
        fn = lambda t, s, v: -k * s - c[1] / 3 * v + c[2] * np.sin(w * t)
    return kind, text, fn


@st.composite
def problems(draw):
    kind, text, fn = draw(acceleration())
    t1 = draw(num(-2.0, 2.0))
    s1 = draw(num(-2.0, 2.0))
    v1 = draw(num(-3.0, 3.0))
    ts = draw(st.lists(num(-2.5, 2.5), min_size=1, max_size=3))
    vs = draw(st.lists(num(-4.0, 4.0), max_size=2))
    ss = draw(st.lists(num(-4.0, 4.0), max_size=2))
    return kind, text, fn, t1, s1, v1, [t1 + x for x in ts], vs, ss


def yaml_of(text, t1, s1, v1, queries, t_max=20.0):
    lines = ["type: rectilinear", f'a: "{text}"', f"t1: {t1}", f"s1: {s1}", f"v1: {v1}",
             f"t_max: {t_max}", "find:"]
    lines += [f"  - {{{k}: {x!r}}}" for k, x in queries]
    return "\n".join(lines) + "\n"


def reference(fn, t1, s1, v1, T):
    """Independent integration (scipy DOP853 at rtol 1e-12) of the ODE to T."""
    from scipy.integrate import solve_ivp

    if T == t1:
        return s1, v1, True
    sol = solve_ivp(lambda t, y: [y[1], fn(t, y[0], y[1])], (t1, T), [s1, v1], method="DOP853",
                    rtol=1e-12, atol=1e-12)
    if sol.status != 0 or not np.all(np.isfinite(sol.y[:, -1])) or abs(sol.y[1, -1]) > 1e6:
        return None, None, False
    return sol.y[0, -1], sol.y[1, -1], True


SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@given(problems())
def test_random_problems_never_crash_and_answers_are_consistent(pb):
    kind, text, fn, t1, s1, v1, ts, vs, ss = pb
    queries = [("t", x) for x in ts] + [("v", x) for x in vs] + [("s", x) for x in ss]
    recs = solve_text(yaml_of(text, t1, s1, v1, queries))
    rec = recs[0]
    assert rec.get("error") is None, rec
    find = rec["results"]["find"]
    assert len(find) == len(queries)
    assert rec["results"]["case"] == {"t": 2, "v": 3, "v-grow": 3, "s": 4, "s-unstable": 4, "general": "general"}[kind]
    assert rec["method"] == "closed-form" or rec.get("error_estimate") is not None
    for (k, x), e in zip(queries, find):
        assert set(e) - {"at_end"} == {"t", "s", "v", "a", "reached", "distance"}
        if not e["reached"]:
            assert all(e[key] is None for key in "tsva")
            continue
        assert all(isinstance(e[key], float) and math.isfinite(e[key]) for key in "tsva")
        if k == "t":
            assert e["t"] == x
            s_ref, v_ref, ok = reference(fn, t1, s1, v1, x)
            if ok:
                scale = 1.0 + abs(s_ref) + abs(v_ref)
                assert abs(e["s"] - s_ref) <= 1e-7 * scale, (e, s_ref)
                assert abs(e["v"] - v_ref) <= 1e-7 * scale, (e, v_ref)
        else:
            assert t1 <= e["t"] <= t1 + 20.0
            assert abs(e[k] - x) <= 1e-8 * (1 + abs(x))
            # the state at that time, computed independently
            s_ref, v_ref, ok = reference(fn, t1, s1, v1, e["t"])
            if ok:
                scale = 1.0 + abs(s_ref) + abs(v_ref)
                assert abs(e["s"] - s_ref) <= 1e-6 * scale and abs(e["v"] - v_ref) <= 1e-6 * scale, (e, s_ref, v_ref)
        assert abs(e["a"] - fn(e["t"], e["s"], e["v"])) <= 1e-9 * (1 + abs(e["a"]))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(problems(), num(-2.0, 2.0))
def test_answers_satisfy_the_equations_of_motion(pb, dt):
    """Central differences of t-queries: (s(T+h) - s(T-h)) / 2h = v(T), (v(T+h) - v(T-h)) / 2h = a(T)."""
    kind, text, fn, t1, s1, v1, *_ = pb
    T = t1 + dt
    h = 1e-3
    recs = solve_text(yaml_of(text, t1, s1, v1, [("t", T - h), ("t", T), ("t", T + h)]))
    m, c, p = recs[0]["results"]["find"]
    if not (m["reached"] and c["reached"] and p["reached"]) or max(abs(m["v"]), abs(p["v"])) > 1e3:
        return
    scale = 1.0 + abs(c["v"]) + abs(c["a"])
    assert abs((p["s"] - m["s"]) / (2 * h) - c["v"]) <= 1e-4 * scale
    assert abs((p["v"] - m["v"]) / (2 * h) - c["a"]) <= 1e-4 * scale * (1 + abs(c["a"]))
