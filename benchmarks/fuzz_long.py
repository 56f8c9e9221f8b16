"""The long fuzzing run (minutes; outside CI).

Grows documents from every available type's examples and template with the
mutators of tests/fuzz/harness.py (structural mutation, extreme numeric
perturbation, text damage, multi-problem files, random expressions) and
feeds them in-process through the loader, the solvers and both renderers.
Prints the outcome counts per type and every distinct failure (an exit 3, an
escaping exception, NaN in JSON, more than 2 s of CPU) with the seed that
reproduces it:

    python benchmarks/fuzz_long.py --seconds 300
    python benchmarks/fuzz_long.py --replay 12345        # one document, printed
    python benchmarks/fuzz_long.py --type top --seconds 600   # one type only (replay with --type too)
"""

from __future__ import annotations

import argparse
import random
import sys
import time
import traceback
import warnings
from collections import Counter, defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tests.fuzz.harness import (available_types, dump_yaml, mutate, mutate_text, perturb_numbers,  # noqa: E402
                                random_expression, run_document, seeds_by_type)


def document(seed: int, types: list[str], seeds: dict) -> tuple[str, str, str]:
    rnd = random.Random(seed)
    t = types[seed % len(types)]
    mode = rnd.choice(["perturb", "perturb", "mutate", "both", "text", "multi", "expr"])
    base = rnd.choice(seeds[t])
    if mode == "perturb":
        doc = perturb_numbers(base, rnd)
    elif mode == "mutate":
        doc = mutate(base, rnd)
    elif mode == "both":
        doc = mutate(perturb_numbers(base, rnd), rnd)
    elif mode == "multi":
        doc = {"problems": [perturb_numbers(rnd.choice(seeds[rnd.choice(types)]), rnd) for _ in range(rnd.randint(2, 5))]}
    elif mode == "expr":
        doc = dict(base)
        keys = [k for k in doc if k not in ("type", "title")]
        if keys:
            doc[rnd.choice(keys)] = random_expression(rnd)
    else:
        doc = base
    text = dump_yaml(doc, rnd)
    if mode == "text" or rnd.random() < 0.1:
        text = mutate_text(text, rnd)
    return t, mode, text


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seconds", type=float, default=180.0, help="time budget (default 180)")
    ap.add_argument("--start", type=int, default=0, help="first seed")
    ap.add_argument("--replay", type=int, default=None, help="print and run the document of one seed")
    ap.add_argument("--hang", type=float, default=20.0, help="wall seconds after which a document counts as hung")
    ap.add_argument("--type", action="append", default=None,
                    help="fuzz only this problem type (repeatable; give the same for --replay)")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    types = [t for t in available_types()]
    seeds = seeds_by_type()
    types = [t for t in types if t in seeds and (not args.type or t in args.type)]
    if not types:
        ap.error(f"no fuzzable type among {args.type}")
    if args.replay is not None:
        t, mode, text = document(args.replay, types, seeds)
        print(f"# seed {args.replay}: {t} ({mode})\n{text}")
        rep = run_document(text)
        print(rep)
        rep.check()
        return 0
    counts: dict[str, Counter] = defaultdict(Counter)
    failures: dict[tuple, tuple] = {}
    slowest = (0.0, None)
    t_end = time.time() + args.seconds
    seed = args.start
    n = 0
    import signal

    def _alarm(signum, frame):
        raise TimeoutError(f"document took more than {args.hang} s (wall)")

    signal.signal(signal.SIGALRM, _alarm)
    while time.time() < t_end:
        t, mode, text = document(seed, types, seeds)
        try:
            signal.setitimer(signal.ITIMER_REAL, args.hang)
            try:
                rep = run_document(text)
            finally:
                signal.setitimer(signal.ITIMER_REAL, 0)
            rep.check()
            for c in rep.codes:
                counts[t][c] += 1
            if rep.seconds > slowest[0]:
                slowest = (rep.seconds, seed)
        except Exception as exc:  # noqa: BLE001 - every failure is reported
            counts[t]["FAIL"] += 1
            key = (type(exc).__name__, str(exc).splitlines()[0][:160] if str(exc) else "")
            if key not in failures:
                failures[key] = (seed, t, mode, traceback.format_exc(limit=-4))
                print(f"failure at seed {seed} ({t}, {mode}): {key[0]}: {key[1]}", flush=True)
        seed += 1
        n += 1
    print(f"{n} documents (seeds {args.start}..{seed - 1}) in {args.seconds:.0f} s; slowest {slowest[0] * 1000:.0f} ms CPU "
          f"(seed {slowest[1]})")
    print(f"{'type':<16} {'exit 0':>7} {'exit 1':>7} {'exit 2':>7} {'FAIL':>5}")
    for t in types:
        c = counts[t]
        print(f"{t:<16} {c[0]:>7} {c[1]:>7} {c[2]:>7} {c['FAIL']:>5}")
    for (kind, msg), (s, t, mode, tb) in failures.items():
        print(f"\nFAILURE {kind}: {msg}\n  replay: python benchmarks/fuzz_long.py --replay {s}   ({t}, {mode})\n{tb}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
