"""Bombs through the real command line, in a subprocess under resource limits.

Generated (not stored) documents near the 2 MB cap — alias bombs, 2 MB of
nesting, 2 MB wide lists, an oversize file, a 2000-character expression, the
longest params chain — go through ``python -m dyncli solve`` in ONE process
limited to 1 GiB of address space and 60 s of CPU: each file must get its
own one-line diagnostic (or a solution), the exit code must be 0, 1 or 2,
and no traceback may appear.  A few mutated documents also go through stdin.
"""

from __future__ import annotations

import json
import os
import random
import resource
import subprocess
import sys
import time

from tests.conftest import ROOT
from tests.fuzz.harness import dump_yaml, mutate, perturb_numbers, seeds_by_type

MEM = 1 << 30
CPU = 60


def _limits():
    resource.setrlimit(resource.RLIMIT_AS, (MEM, MEM))
    resource.setrlimit(resource.RLIMIT_CPU, (CPU, CPU))


def _cli(args, input=None):
    env = dict(os.environ, PYTHONPATH=str(ROOT), NO_COLOR="1", COLUMNS="120",
               OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", MKL_NUM_THREADS="1")
    t0 = time.perf_counter()
    p = subprocess.run([sys.executable, "-m", "dyncli", *args], input=input, capture_output=True, cwd=ROOT,
                       env=env, preexec_fn=_limits, timeout=300)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace"), \
        time.perf_counter() - t0


def _bombs() -> dict[str, bytes]:
    cap = 2 * 1024 * 1024
    laughs = 'a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol","lol"]\n' + "".join(
        f"{c}: &{c} [*{p},*{p},*{p},*{p},*{p},*{p},*{p},*{p},*{p},*{p}]\n" for p, c in zip("abcdefghijk", "bcdefghijkl"))
    n = (cap - 100) // 2
    return {
        "laughs.yaml": laughs.encode(),
        "deep-flow.yaml": ("type: rectilinear\na: " + "[" * n + "]" * n).encode()[: cap - 10],
        "deep-map.yaml": ("type: rectilinear\na: " + "{a: " * (cap // 8)).encode()[: cap - 10],
        "deep-block.yaml": "".join(" " * i + f"k{i}:\n" for i in range(1900)).encode(),
        "wide-list.yaml": ("type: vibration\nm: 1\nk: 1\nat: [" + ",".join(["1"] * ((cap - 100) // 2)) + "]\n").encode(),
        "wide-map.yaml": ("type: rectilinear\na: 1\nparams: {" + ",".join(f"p{i}: {i}" for i in range(150_000)) + "}\n").encode()[: cap - 10],
        "oversize.yaml": b"type: rectilinear\na: 1\ntitle: " + b"x" * (cap + 10) + b"\n",
        "long-title.yaml": b"type: rectilinear\na: 1\nfind: [{t: 1}]\ntitle: " + b"x" * (cap - 100) + b"\n",
        "long-expression.yaml": ("type: rectilinear\na: '" + "+".join(["1"] * 1000) + "'\nfind: [{t: 1}]\n").encode(),
        "too-long-expression.yaml": ("type: rectilinear\na: '" + "1+" * 200_000 + "1'\n").encode(),
        "power-tower.yaml": ("type: rectilinear\na: '" + "**".join(["9"] * 500) + "'\n").encode(),
        "params-chain.yaml": ("type: rectilinear\na: p0\nfind: [{t: 1}]\nparams:\n" + "".join(
            f"  p{i}: p{i + 1}+1\n" for i in range(999)) + "  p999: 1\n").encode(),
        "huge-digits.yaml": ("type: rectilinear\na: 1\nv1: " + "9" * 1_000_000 + "\n").encode(),
        "huge-float.yaml": ("type: rectilinear\na: 1\nv1: 1." + "9" * 1_000_000 + "e5\n").encode(),
        "many-keys.yaml": ("type: rectilinear\na: 1\n" + "".join(f"k{i}: {i}\n" for i in range(100_000))).encode()[: cap - 10],
    }


def test_bombs_in_one_limited_process(tmp_path):
    names = []
    for name, data in _bombs().items():
        (tmp_path / name).write_bytes(data)
        names.append(str(tmp_path / name))
    rc, out, err, secs = _cli(["solve", "--format", "json", *names])
    assert rc in (0, 1, 2), err[-2000:]
    assert "Traceback" not in err and "internal error" not in err, err[-2000:]
    records = json.loads(out)          # stdout holds only JSON
    solved = {r["file"] for r in records if r.get("results") is not None}
    lines = err.splitlines()
    for n in names:
        assert n in solved or any(ln.startswith(n) for ln in lines), f"no diagnostic for {n}:\n{err[-3000:]}"
    assert all(len(ln) < 5000 for ln in lines), "a diagnostic echoes megabytes of input"
    print(f"{len(names)} bombs in {secs:.2f} s wall")


def test_mutated_documents_through_stdin():
    rnd = random.Random(2024)
    seeds = seeds_by_type()
    docs = []
    for t in sorted(seeds):
        base = rnd.choice(seeds[t])
        docs.append(perturb_numbers(base, rnd) if rnd.random() < 0.5 else mutate(base, rnd))
    text = dump_yaml({"problems": docs}, rnd).encode()
    for fmt in ("json", "table"):
        rc, out, err, _ = _cli(["solve", "--format", fmt, "-"], input=text)
        assert rc in (0, 1, 2), err
        assert "Traceback" not in err and "internal error" not in err, err
        if fmt == "json":
            json.loads(out)


def test_binary_and_garbage_through_stdin():
    rnd = random.Random(7)
    for data in (bytes(rnd.randrange(256) for _ in range(3000)), b"\xff\xfe" + "type: x".encode("utf-16-le"),
                 b"type: rectilinear\na: 1\x00", b"\x1b[31mtype: rectilinear\n"):
        rc, out, err, _ = _cli(["solve", "-"], input=data)
        assert rc == 2 and err.strip() and "Traceback" not in err, (rc, err)
