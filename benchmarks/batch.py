"""Marginal cost per problem of a batch of closed-form problem files solved in
one ``dyncli solve`` call (issue 11 target: <= 5 ms per problem).

Writes N problem files (round-robin over the closed-form example problems of
every available type, each file a single problem) into a temporary
directory, then times ``dyncli solve`` on 1 file and on all N files (median
of R runs each) in table and JSON formats:

    marginal = (T(N) - T(1)) / (N - 1)

CPU time (user + sys of the child) is printed beside wall time: on a shared
machine it is the robust number.

Usage: python benchmarks/batch.py [--n 1000] [--runs 3] [--profile]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def closed_form_problems() -> list[tuple[str, str]]:
    """(type, yaml text) of every single-problem example solved in closed form."""
    from dyncli.loader import load_paths
    from dyncli.run import solve_one

    out = []
    for f in sorted((ROOT / "problems").rglob("*.yaml")):
        if "course-example" in f.parts:
            continue
        problems, diags = load_paths([str(f)])
        if diags or len(problems) != 1:
            continue
        o = solve_one(problems[0])
        if o.result is not None and o.result.method == "closed-form":
            out.append((problems[0].type, f.read_text(encoding="utf-8")))
    return out


def timed(args: list[str], runs: int) -> tuple[float, float]:
    """Median wall time and median CPU time (user + sys of the child: robust
    on a loaded machine) of ``dyncli ARGS``."""
    import resource

    env = dict(os.environ, PYTHONPATH=str(ROOT), NO_COLOR="1", COLUMNS="120")
    ts, cs = [], []
    for _ in range(runs):
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        p = subprocess.run([sys.executable, "-m", "dyncli", *args], cwd=ROOT, env=env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        ts.append(time.perf_counter() - t0)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cs.append(r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)
        if p.returncode != 0:
            raise SystemExit(f"dyncli {' '.join(args[:3])}... exited {p.returncode}: {p.stderr.decode()[-500:]}")
    return statistics.median(ts), statistics.median(cs)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1000)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--profile", action="store_true", help="also print a cProfile of the in-process batch")
    args = ap.parse_args()
    probs = closed_form_problems()
    types = sorted({t for t, _ in probs})
    with tempfile.TemporaryDirectory() as d:
        files = []
        for i in range(args.n):
            t, text = probs[i % len(probs)]
            p = Path(d) / f"p{i:05d}-{t}.yaml"
            p.write_text(text, encoding="utf-8")
            files.append(str(p))
        print(f"{args.n} closed-form problem files over {len(types)} types ({', '.join(types)}), "
              f"median of {args.runs} runs")
        for fmt in ("table", "json"):
            t1, c1 = timed(["solve", "-f", fmt, files[0]], args.runs)
            tn, cn = timed(["solve", "-f", fmt, *files], args.runs)
            marginal = (tn - t1) / (args.n - 1)
            cmarg = (cn - c1) / (args.n - 1)
            print(f"  --format {fmt:<5}: 1 file {t1 * 1000:7.1f} ms, {args.n} files {tn * 1000:8.1f} ms wall; "
                  f"marginal {marginal * 1000:.2f} ms/problem wall, {cmarg * 1000:.2f} ms/problem CPU (target <= 5 ms)")
        if args.profile:
            import cProfile
            import io
            import pstats

            from dyncli.loader import load_paths
            from dyncli.render.jsonout import dumps
            from dyncli.run import outcome_record, solve_one

            pr = cProfile.Profile()
            pr.enable()
            problems, _ = load_paths(files)
            dumps([outcome_record(solve_one(lp)) for lp in problems])
            pr.disable()
            s = io.StringIO()
            pstats.Stats(pr, stream=s).sort_stats("cumulative").print_stats(25)
            print(s.getvalue())


if __name__ == "__main__":
    main()
