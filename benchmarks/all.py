"""Every figure of issue 31 measured in one run, as ratios (CPU time is the
robust number on a shared machine; wall time beside it; rounds interleaved,
medians).

1. warm ``dyncli.solve`` per closed-form type: its CPU time over the
   physics (the type's solver function alone on the validated model) and
   the overhead in ms (goal: <= 0.1 ms);
2. cold start per type: ``dyncli solve FILE`` over the import floor
   (``python -c "import numpy, pydantic, yaml, typer, rich"``), as
   benchmarks/startup_types.py;
3. sweeps of 10^2, 10^3, 10^4 points (10^5 with ``--big``) in every format:
   CPU, wall and peak memory (the child's max RSS) of a fresh process writing
   to /dev/null, over the goals (2 s at 10^4, 150 MB at 10^5), with the
   growth exponent of each (CPU ~ N^k between the two largest sizes);
4. batches of 1, 10, 100 and 1,000 closed-form files (benchmarks/batch.py's
   problems) in table and JSON: CPU, wall, per problem, growth exponent;
5. ``dyncli check --key`` at 30 and 300 submissions (3,000 with ``--big``;
   benchmarks/check_key_batch.py's class): CPU, wall, growth exponent;
6. cold start of the integrating types over a student's scipy script of the
   same problem (goal: <= 1.15), as benchmarks/cold_integrating.py;
7. a particle at 1e3, 1e4, 1e5 requested times (goal: 2 s at 1e5) and the Coulomb
   oscillator's stops (goal: < 1 s), CPU and growth, as benchmarks/many_times.py (issue 29).

Usage: python -m benchmarks.all [--runs 3] [--big] [--only 1,3]
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

SWEEP = ("problems/impact/wall.yaml", "e")          # a closed-form type with vector results
FORMATS = ("table", "json", "yaml", "csv")
#: a child that runs dyncli and writes its own peak memory (KiB) to a file: VmHWM, the high-water
#: mark of its own address space (ru_maxrss would include the forking parent's memory)
_CHILD = ("import resource, runpy, sys, os\nsys.argv = ['dyncli'] + sys.argv[1:]\ntry:\n"
          "    runpy.run_module('dyncli', run_name='__main__')\nexcept SystemExit:\n    pass\nfinally:\n"
          "    hwm = [ln.split()[1] for ln in open('/proc/self/status') if ln.startswith('VmHWM:')]\n"
          "    open(os.environ['DYNCLI_BENCH_RSS'], 'w').write(hwm[0] if hwm else "
          "str(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss))\n")


def _env() -> dict:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.update(PYTHONPATH=str(ROOT), NO_COLOR="1", COLUMNS="120")
    return env


def run(args: list[str], cwd: Path = ROOT) -> tuple[float, float, float]:
    """(wall s, CPU s, peak RSS MB) of ``dyncli ARGS`` in a fresh process, output to /dev/null."""
    import resource

    rss = tempfile.NamedTemporaryFile(delete=False)
    rss.close()
    env = dict(_env(), DYNCLI_BENCH_RSS=rss.name)
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-c", _CHILD, *args], cwd=cwd, env=env, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    text = Path(rss.name).read_text() or "0"
    os.unlink(rss.name)
    return wall, r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime, int(text) / 1024


def rounds(cmds: list[tuple[list[str], Path]], runs: int) -> list[tuple[float, float, float]]:
    """Median (wall, CPU, peak MB) of each command, ``runs`` interleaved rounds."""
    samples: list[list] = [[] for _ in cmds]
    for _ in range(runs):
        for i, (args, cwd) in enumerate(cmds):
            samples[i].append(run(args, cwd))
    return [tuple(statistics.median(x[j] for x in s) for j in range(3)) for s in samples]


def exponent(n1: float, t1: float, n2: float, t2: float) -> float:
    return math.log(t2 / t1) / math.log(n2 / n1) if t1 > 0 and t2 > 0 else float("nan")


def warm(runs: int) -> None:
    """1. warm dyncli.solve over the physics, per closed-form type."""
    import dyncli
    from batch import closed_form_problems
    from dyncli import registry
    from dyncli.api import load
    from dyncli.result import SolveOptions

    print("1. warm dyncli.solve of one closed-form problem (CPU, median of interleaved rounds)")
    print(f"   {'type':<18} {'solve ms':>9} {'physics ms':>10} {'solve/physics':>13} {'overhead ms':>11} {'/0.1 ms goal':>12}")
    seen, cases = set(), []
    for t, text in closed_form_problems():
        if t not in seen:
            seen.add(t)
            p = load(text)[0][0]
            cases.append((t, text, registry.solver(t).__wrapped__, p.model))

    def cpu(fn, n):
        t0 = time.process_time()
        for _ in range(n):
            fn()
        return (time.process_time() - t0) / n

    for t, text, fn, model in cases:
        n = max(5, min(300, int(0.02 / max(cpu(lambda: dyncli.solve(text), 3), 1e-6))))
        a, b = [], []
        for _ in range(max(runs, 3) * 2 + 1):
            a.append(cpu(lambda: dyncli.solve(text), n))
            b.append(cpu(lambda: fn(model, SolveOptions()), n))
        s, ph = statistics.median(a), statistics.median(b)
        print(f"   {t:<18} {s * 1e3:9.3f} {ph * 1e3:10.3f} {s / ph:13.2f} {(s - ph) * 1e3:11.3f} {(s - ph) / 1e-4:12.2f}")


def cold(runs: int) -> None:
    """2. cold start per type over the import floor."""
    from dyncli import registry
    from startup import timed_rounds
    from startup_types import EXTRA

    tmp = Path(tempfile.mkdtemp(prefix="dyncli-all-"))
    files = [(n, str(ROOT / s.example)) for n, s in sorted(registry.TYPES.items()) if s.example]
    for name, text in EXTRA.items():
        f = tmp / (name.split()[0] + ".yaml")
        f.write_text(text)
        files.append((name, str(f)))
    py = sys.executable
    times = timed_rounds([[py, "-c", "import numpy, pydantic, yaml, typer, rich"]] +
                         [[py, "-m", "dyncli", "solve", f] for _, f in files], runs)
    bw, bc = times[0]
    print(f"2. cold start per type over the import floor (wall {bw * 1e3:.0f} ms, CPU {bc * 1e3:.0f} ms; median of {runs})")
    for (name, f), (w, c) in zip(files, times[1:]):
        print(f"   {name + ' (' + Path(f).name + ')':<60} wall/floor {w / bw:5.2f}  CPU/floor {c / bc:5.2f}")


def sweeps(runs: int, big: bool, formats=FORMATS) -> None:
    """3. sweeps per format and size."""
    sizes = [100, 1000, 10_000] + ([100_000] if big else [])
    path, field = SWEEP
    print(f"3. sweeps of {path} over {field} (fresh process to /dev/null; median of {runs}; goals 2 s at 1e4, 150 MB at 1e5)")
    print(f"   {'format':<6} {'points':>7} {'CPU s':>7} {'wall s':>7} {'peak MB':>8} {'CPU/2 s':>8} {'MB/150':>7} "
          f"{'us/point CPU':>12}")
    for fmt in formats:
        cmds = [(["solve", path, "-f", fmt, "--sweep", f"{field}=0:1:{n}"], ROOT) for n in sizes]
        res = rounds(cmds, runs if not big else 1)
        for n, (w, c, mb) in zip(sizes, res):
            print(f"   {fmt:<6} {n:>7} {c:7.2f} {w:7.2f} {mb:8.0f} {c / 2:8.2f} {mb / 150:7.2f} {c / n * 1e6:12.1f}")
        (n1, (_, c1, m1)), (n2, (_, c2, m2)) = list(zip(sizes, res))[-2:]
        print(f"   {fmt:<6} growth {n1}->{n2}: CPU ~ N^{exponent(n1, c1, n2, c2):.2f}, peak memory ~ N^{exponent(n1, m1, n2, m2):.2f}")


def batches(runs: int) -> None:
    """4. batches of files."""
    from batch import closed_form_problems

    probs = closed_form_problems()
    sizes = [1, 10, 100, 1000]
    with tempfile.TemporaryDirectory() as d:
        files = []
        for i in range(sizes[-1]):
            t, text = probs[i % len(probs)]
            f = Path(d) / f"p{i:05d}-{t}.yaml"
            f.write_text(text, encoding="utf-8")
            files.append(str(f))
        print(f"4. batches of closed-form files, one process (median of {runs})")
        for fmt in ("table", "json"):
            res = rounds([(["solve", "-f", fmt, *files[:n]], ROOT) for n in sizes], runs)
            for n, (w, c, mb) in zip(sizes, res):
                print(f"   {fmt:<6} {n:>5} files  CPU {c:6.2f} s  wall {w:6.2f} s  peak {mb:5.0f} MB  "
                      f"marginal CPU {(c - res[0][1]) / max(n - 1, 1) * 1e3:6.2f} ms/file  /5 ms goal "
                      f"{(c - res[0][1]) / max(n - 1, 1) / 5e-3:5.2f}")
            print(f"   {fmt:<6} growth 100->1000: CPU ~ N^{exponent(100, res[2][1] - res[0][1], 1000, res[3][1] - res[0][1]):.2f} "
                  f"(start-up subtracted)")


def check(runs: int, big: bool) -> None:
    """5. check --key."""
    from check_key_batch import make_class

    sizes = [30, 300] + ([3000] if big else [])
    print(f"5. dyncli check --key, 10 questions per submission (median of {runs})")
    res = []
    for n in sizes:
        with tempfile.TemporaryDirectory() as d:
            names = make_class(Path(d), n)
            res.append(rounds([(["check", "--key", "key.yaml", *names, "-f", "json"], Path(d))], runs)[0])
    for n, (w, c, mb) in zip(sizes, res):
        print(f"   {n:>5} submissions  CPU {c:6.2f} s  wall {w:6.2f} s  peak {mb:5.0f} MB  {c / n * 1e3:6.2f} ms CPU/submission")
    print(f"   growth {sizes[-2]}->{sizes[-1]}: CPU ~ N^{exponent(sizes[-2], res[-2][1], sizes[-1], res[-1][1]):.2f}")


def cold_integrating(runs: int) -> None:
    """6. cold start of the integrating types over a student's scipy script."""
    from cold_integrating import report

    print("\n6. ", end="")
    report(max(runs, 5))


def many_times(runs: int) -> None:
    """7. a particle at many times; the Coulomb oscillator."""
    from many_times import report

    print("7. ", end="")
    report(runs, [1000, 10_000, 100_000])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--big", action="store_true", help="also 1e5-point sweeps and 3,000 submissions")
    ap.add_argument("--only", default="1,2,3,4,5,6,7", help="sections to run, e.g. 1,3")
    ap.add_argument("--formats", default=",".join(FORMATS), help="the sweeps' formats, e.g. json,csv")
    args = ap.parse_args()
    only = {int(x) for x in args.only.split(",")}
    load = os.getloadavg()
    print(f"dyncli benchmarks (issue 31); load average {load[0]:.2f} on {os.cpu_count()} CPUs; "
          f"{time.strftime('%Y-%m-%d %H:%M:%S')}")
    for k, section in ((1, lambda: warm(args.runs)), (2, lambda: cold(args.runs)), (3, lambda: sweeps(args.runs, args.big, args.formats.split(","))),
                       (4, lambda: batches(args.runs)), (5, lambda: check(args.runs, args.big)),
                       (6, lambda: cold_integrating(args.runs)), (7, lambda: many_times(args.runs))):
        if k in only:
            section()


if __name__ == "__main__":
    main()
