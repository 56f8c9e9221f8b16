"""10,000-point sweeps of closed-form types (``dyncli solve --sweep``, issue
target: <= 2 s wall on 2 cores), against the ways to do it without a sweep.

For each case (vibration free and base-excited, with ``find``, a forced motion's ``distance`` over
many turning points; impact) it reports (``--case TEXT``: only the cases whose name holds TEXT):

* ``shell loop``: one ``dyncli solve FILE --set PATH=V -f csv`` process per
  point (``--loop-runs`` processes timed, scaled to N points);
* ``validate every point``: the sweep in one process, each point validated
  in full (what the sweep does when the fast route does not apply);
* ``fast route``: the sweep's own route (the first point validated in full,
  then only the swept fields of a copy of the model), same process;
* ``dyncli --sweep -f csv`` / ``-f json``: the whole command, wall and CPU
  (user + sys) of a fresh process writing to /dev/null.

The in-process rows split the time into validation, solving and output.
Wall times on a shared machine vary with its load; the CPU column is the
steadier number.

Measured (CPU of the whole command, 10⁴ points, the release before → this one interleaved,
medians of 3–5, load 1.2–3.2 on 2 CPUs): free without find as YAML 1.82 → 1.28 s (JSON 1.15 s,
CSV 1.2 s, table 1.9 s); free with its two find queries as YAML 3.52 → 2.82 s, as JSON 2.59 →
2.55 s; the base-excited sweep with find on w, x and v, 10³ points as JSON, 3.07 → 2.56 s.

Usage: python benchmarks/sweep.py [--points N] [--loop-runs K]
"""

from __future__ import annotations

import argparse
import gc
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

CASES = [
    ("vibration, free (5 times)", "problems/vibration/underdamped.yaml", "k", 100.0, 1000.0),
    ("vibration, free without find", "benchmarks/sweep_cases/free-no-find.yaml", "k", 100.0, 1000.0),
    ("vibration, base-excited (6 times)", "problems/vibration/base-excitation.yaml", "k", 100.0, 1000.0),
    ("impact, oblique smooth", "problems/impact/oblique-smooth.yaml", "e", 0.1, 0.9),
    ("vibration, free with find (2 queries)", "problems/vibration/underdamped.yaml", "k", 100.0, 1000.0),
    ("vibration, forced, distance to 20 s", "benchmarks/sweep_cases/forced-distance.yaml", "k", 100.0, 1000.0),
    ("vibration, base, find on w, x, v", "benchmarks/sweep_cases/base-find-w.yaml", "k", 100.0, 1000.0),
]
FORMATS = ("csv", "json", "yaml", "table")


def _env() -> dict:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.update(PYTHONPATH=str(ROOT), NO_COLOR="1")
    return env


def _process(args: list[str]) -> tuple[float, float]:
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "dyncli", *args], cwd=ROOT, env=_env(),
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime


def in_process(path: str, field: str, lo: float, hi: float, n: int, fast: bool) -> dict[str, float]:
    from dyncli.loader import load_paths
    from dyncli.overrides import _full, expand, parse_sweep
    from dyncli.render import emit
    from dyncli.run import solve_one

    spec = f"{field}={lo}:{hi}:{n}"
    gc.disable()
    try:
        t0 = time.process_time()
        problems, _ = load_paths([path])
        a = parse_sweep(spec)
        if fast:
            points = expand(problems, [a])
        else:
            hit = [(a, (field,))]
            points = _full(problems[0], problems[0].raw, hit, hit, [(v,) for v in a.values])
        t1 = time.process_time()
        outcomes = [solve_one(p) for p in points]
        t2 = time.process_time()
        text = emit.dumps("csv", outcomes)
        t3 = time.process_time()
    finally:
        gc.enable()
        gc.collect()
    assert text.count("\n") == n + 1, "one csv row per point"
    return {"validate": t1 - t0, "solve": t2 - t1, "csv": t3 - t2, "total": t3 - t0}


def _formats(path: str, field: str, lo: float, hi: float, n: int) -> None:
    """The whole command in every format: wall and CPU of a fresh process writing to /dev/null."""
    for fmt in FORMATS:
        _process(["solve", path, "--sweep", f"{field}={lo}:{hi}:10", "-f", fmt])   # warm .pyc
        w, c = _process(["solve", path, "--sweep", f"{field}={lo}:{hi}:{n}", "-f", fmt])
        print(f"{'':<36} {'dyncli --sweep -f ' + fmt:<30} {w:7.2f} {c:7.2f}")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=10_000)
    ap.add_argument("--loop-runs", type=int, default=10)
    ap.add_argument("--formats-only", action="store_true", help="only the dyncli --sweep rows, every format")
    ap.add_argument("--case", action="append", default=[], help="only the cases whose name holds this text")
    args = ap.parse_args()
    n = args.points
    print(f"{n:,}-point sweeps; times in seconds (CPU = user + sys of the process)\n")
    print(f"{'case':<36} {'route':<30} {'wall':>7} {'CPU':>7}   split (CPU)")
    for name, path, field, lo, hi in CASES:
        if args.case and not any(c in name for c in args.case):
            continue
        if args.formats_only:
            print(name)
            _formats(path, field, lo, hi, n)
            continue
        loop = [_process(["solve", path, "--set", f"{field}={lo + (hi - lo) * i / args.loop_runs}", "-f", "csv"])
                for i in range(args.loop_runs)]
        scale = n / args.loop_runs
        print(f"{name:<36} {'shell loop (scaled)':<30} {sum(w for w, _ in loop) * scale:7.1f} "
              f"{sum(c for _, c in loop) * scale:7.1f}")
        for label, fast in (("validate every point", False), ("fast route", True)):
            r = in_process(str(ROOT / path), field, lo, hi, n, fast)
            print(f"{'':<36} {label:<30} {'':>7} {r['total']:7.2f}   validate {r['validate']:.2f}, "
                  f"solve {r['solve']:.2f}, csv {r['csv']:.2f}")
        _formats(path, field, lo, hi, n)
    print("\n(the rest of the CPU of the 'dyncli' rows is start-up, loading and JSON/CSV writing)")


if __name__ == "__main__":
    main()
