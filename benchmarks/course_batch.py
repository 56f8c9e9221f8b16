"""Benchmark: a whole course in two processes — 1,000 students x 10
questions (5 problems with statement text, a chain of carries).

1. ``dyncli variant KEY --roster roster.csv -o sheets/ --format markdown``:
   1,000 sheets in ONE process (the answers' units solved once per
   question, not per student);
2. ``dyncli check --key KEY --roster roster.csv SUBMISSIONS... --format csv
   -o gradebook.csv --stats``: the gradebook and the class statistics in
   ONE process.

Prints the wall and CPU time of each, the per-student cost, and the cost of
the old way for sheets (one ``dyncli variant --student`` process per
student, measured on 20 and scaled) as a ratio.  Nothing here is asserted.

Run from the project root:  python benchmarks/course_batch.py [N_STUDENTS]
"""

from __future__ import annotations

import csv
import re
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from check_key_batch import KEY, make_class  # noqa: E402

TEXTS = "problems:\n" + "".join(
    f'  - {{problem: hw.yaml, index: {j}, text: "A cart moving at {{v{j}}} m/s brakes at {{a{j}:.2g}} m/s² '
    f'from s = {{s{j}}} m."}}\n' for j in range(5))


def run(args: list[str], cwd: Path, env: dict) -> tuple[float, float, subprocess.CompletedProcess]:
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run([sys.executable, "-m", "dyncli", *args], cwd=cwd, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime), p


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        names = make_class(tmp, n)
        key = KEY.replace("questions:\n", TEXTS + "questions:\n", 1)
        key = re.sub(r"\{id: (\w+), ", lambda m: f'{{id: {m.group(1)}, text: "How far (in m)? ({m.group(1)})", ', key)
        (tmp / "key.yaml").write_text(key, encoding="utf-8")
        with open(tmp / "roster.csv", "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(["student", "section"])
            w.writerows([f"student{i:03d}@example.edu", i % 3] for i in range(n))
        wall, cpu, p = run(["variant", "key.yaml", "--roster", "roster.csv", "-o", "sheets", "--format", "markdown"],
                           tmp, env)
        assert p.returncode == 0, p.stderr
        print(f"sheets: {n} students x 10 questions in one process: wall {wall:.2f} s, CPU {cpu:.2f} s "
              f"({1000 * cpu / n:.2f} ms CPU per student, start-up included); {p.stderr.strip()}")
        k = min(20, n)
        c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        for i in range(k):
            subprocess.run([sys.executable, "-m", "dyncli", "variant", "key.yaml", "--student",
                            f"student{i:03d}@example.edu", "--format", "markdown"], cwd=tmp, env=env,
                           capture_output=True, check=True)
        c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        one = ((c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime)) / k
        print(f"  one process per student (measured on {k}): {1000 * one:.0f} ms CPU each -> {one * n:.0f} s for "
              f"{n}; the roster call is {one * n / cpu:.0f}x cheaper")
        wall, cpu, p = run(["check", "--key", "key.yaml", "--roster", "roster.csv", *names, "--format", "csv",
                            "-o", "gradebook.csv", "--stats"], tmp, env)
        rows = sum(1 for _ in open(tmp / "gradebook.csv", encoding="utf-8")) - 1
        print(f"grading: {n} submissions x 10 questions, gradebook ({rows} rows) and stats in one process: "
              f"exit {p.returncode}, wall {wall:.2f} s, CPU {cpu:.2f} s ({1000 * cpu / n:.2f} ms CPU per student)")
        print("  " + p.stderr.strip().splitlines()[-1])
        print("\n".join("  " + ln for ln in p.stdout.splitlines()[:3]))


if __name__ == "__main__":
    main()
