"""The fixed cost of the public API on closed-form problems (issue #31 item 2: warm
``dyncli.solve`` ≤ 0.1 ms beyond the physics).

For each case (a vibration example of each closed-form kind, without its ``at``/``find``
lists so that the physics is the closed form itself) it times, warm, in one process and
interleaved (CPU time, median of rounds):

* ``solve``: ``dyncli.solve(text)`` of the problem as YAML text (parse, validate, solve, wrap);
* ``dict``: ``dyncli.solve(mapping)`` (no YAML parsing);
* ``physics``: the type's solver on the validated model (``vibration.solver.solve(model)``);

and prints the overheads beyond the physics in ms, per file and per problem (a file of the
gallery may hold several problems: the goal is per problem).

Usage: python benchmarks/api_overhead.py [--rounds 7] [--reps 300]
"""

from __future__ import annotations

import argparse
import re
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

GOAL = 0.1          # ms of overhead per closed-form problem beyond its physics (issue #31 item 2)
CASES = ["underdamped", "critical", "overdamped", "undamped", "base-excitation", "force-excitation",
         "rotating-unbalance", "resonance", "sweep"]


def _text(name: str) -> str:
    text = (ROOT / "problems/vibration" / f"{name}.yaml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^( *)find:\n(\1[ -] .*\n)+", "", text)
    return re.sub(r"(?m)^ *(at|find): .*\n", "", text)


def _per_call(fn, reps: int) -> float:
    t0 = time.process_time()
    for _ in range(reps):
        fn()
    return (time.process_time() - t0) / reps * 1e3


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--reps", type=int, default=300)
    args = ap.parse_args()
    import yaml

    import dyncli
    from dyncli.api import load
    from dyncli.topics.vibration import solver

    print(f"{'case':<20} {'problems':>8} {'physics':>9} {'solve(text)':>12} {'solve(dict)':>12} {'overhead':>9} "
          f"{'(dict)':>8} {'per problem':>12}   ms (goal: <= {GOAL} ms per problem)")
    worst = 0.0
    for name in CASES:
        text = _text(name)
        data = yaml.safe_load(text)
        models = [p.model for p in load(text)[0]]
        fns = {"physics": lambda: [solver.solve(m) for m in models], "text": lambda: dyncli.solve(text),
               "dict": lambda: dyncli.solve(data)}
        for f in fns.values():
            f()
        got: dict[str, list[float]] = {k: [] for k in fns}
        for _ in range(args.rounds):
            for k, f in fns.items():
                got[k].append(_per_call(f, args.reps))
        m = {k: statistics.median(v) for k, v in got.items()}
        each = (m['text'] - m['physics']) / len(models)
        worst = max(worst, each)
        print(f"{name:<20} {len(models):8d} {m['physics']:9.4f} {m['text']:12.4f} {m['dict']:12.4f} "
              f"{m['text'] - m['physics']:9.4f} {m['dict'] - m['physics']:8.4f} {each:12.4f}")
    print(f"largest overhead per problem: {worst:.4f} ms ({'met' if worst <= GOAL else 'over the goal'}; "
          f"load average {' '.join(f'{x:.2f}' for x in __import__('os').getloadavg())} on 2 CPUs)")


if __name__ == "__main__":
    main()
