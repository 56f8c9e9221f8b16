"""Record and compare the JSON results of every file of ``problems/`` (issue #19's safety net).

``python -m tests.tools.baseline record`` solves every ``problems/**/*.yaml`` in process and
writes ``tests/data/baseline-results.json``: per problem, its contract record (results, method,
equations, warnings) plus the ``rtol``/``atol`` it ran at. Run it on the code whose results are the
reference (the baseline in the repository was recorded from ``main`` before the refactors of
issue #19), and commit the file; ``python -m tests.tools.baseline add`` records only the files
not recorded yet, ``add FILE ...`` only those files and ``add TYPE`` only the files of
``problems/`` that hold a problem of that type (a new type: its example), each of which must be
new — leaving every other reference value as it is (nothing else is solved again); ``record
FILE ...`` records those files again (an intended change of their results), and only them. ``tests/test_baseline_results.py`` compares the current code with
it through :func:`compare`.

Tolerances (what each route guarantees, docs/accuracy.md):

* ``method == "closed-form"``: ``|new - old| <= 1e-13 * scale``, where ``scale`` is the largest
  magnitude in that result (a vector, a series, a nested table), so a reordered sum that moves
  the last bits passes and a changed formula does not;
* any numerical route (ODE, quadrature): ``|new - old| <= 100 * (rtol * scale + atol)``, the
  integrator's own error control ``rtol*|y| + atol`` times the ``ODE_GLOBAL`` envelope of
  ``tests/tolerances.py``.

Strings, booleans, ``None``, the set of result names, ``method`` and the equation numbers must be
identical; ``error_estimate`` must be present exactly when it was.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"
BASELINE = ROOT / "tests" / "data" / "baseline-results.json"
CLOSED_RTOL = 1e-13
ODE_FACTOR = 100


def problem_files() -> list[Path]:
    return sorted(PROBLEMS.rglob("*.yaml"))


def _accuracy(lp) -> tuple[float, float]:
    acc = getattr(lp.model, "accuracy", None)
    if acc is None:
        return 1e-10, 1e-12
    return float(acc.rtol), float(acc.atol)


def record_file(path: Path) -> list[dict]:
    """The contract records of one problem file, with the accuracy each problem ran at."""
    from dyncli.loader import load_paths
    from dyncli.render.jsonout import dumps
    from dyncli.run import outcome_record, solve_one

    problems, diags = load_paths([str(path)])
    if diags:
        raise AssertionError("; ".join(str(d) for d in diags))
    out = []
    for lp in problems:
        rec = json.loads(dumps([outcome_record(solve_one(lp))]))[0]
        rec["file"] = path.relative_to(ROOT).as_posix()
        rec["rtol"], rec["atol"] = _accuracy(lp)
        out.append(rec)
    return out


def record_all() -> dict[str, list[dict]]:
    return {p.relative_to(ROOT).as_posix(): record_file(p) for p in problem_files()}


def _numbers(v):
    if isinstance(v, bool) or v is None or isinstance(v, str):
        return
    if isinstance(v, (int, float)):
        yield float(v)
    elif isinstance(v, list):
        for x in v:
            yield from _numbers(x)
    elif isinstance(v, dict):
        for x in v.values():
            yield from _numbers(x)


def _scale(v) -> float:
    return max((abs(x) for x in _numbers(v) if math.isfinite(x)), default=0.0)


def _diff(old, new, tol: float, where: str, out: list[str]) -> None:
    """Append to ``out`` one line per place where ``new`` departs from ``old`` beyond ``tol``."""
    num = (int, float)
    if isinstance(old, num) and not isinstance(old, bool) and isinstance(new, num) and not isinstance(new, bool):
        a, b = float(old), float(new)
        if math.isfinite(a) and math.isfinite(b):
            if abs(a - b) > tol:
                out.append(f"{where}: {b!r} != {a!r} (|diff| {abs(a - b):.3g} > {tol:.3g})")
        elif not (a == b or (math.isnan(a) and math.isnan(b))):
            out.append(f"{where}: {b!r} != {a!r}")
    elif isinstance(old, list) and isinstance(new, list):
        if len(old) != len(new):
            out.append(f"{where}: length {len(new)} != {len(old)}")
            return
        for i, (a, b) in enumerate(zip(old, new)):
            _diff(a, b, tol, f"{where}[{i}]", out)
    elif isinstance(old, dict) and isinstance(new, dict):
        if set(old) != set(new):
            out.append(f"{where}: keys {sorted(new)} != {sorted(old)}")
            return
        for k in old:
            _diff(old[k], new[k], tol, f"{where}.{k}", out)
    elif old != new:
        out.append(f"{where}: {new!r} != {old!r}")


def compare(old: dict, new: dict) -> list[str]:
    """Differences between two records of the same problem beyond the route's tolerance."""
    where = f"{old['file']}#{old['index']}"
    out: list[str] = []
    for key in ("type", "method", "equations", "error"):
        if old.get(key) != new.get(key):
            out.append(f"{where} {key}: {new.get(key)!r} != {old.get(key)!r}")
    if ("error_estimate" in old) != ("error_estimate" in new):
        out.append(f"{where}: error_estimate present {'error_estimate' in new}, was {'error_estimate' in old}")
    closed = old.get("method") == "closed-form"
    ro, rn = old.get("results") or {}, new.get("results") or {}
    if set(ro) != set(rn):
        out.append(f"{where}: result names {sorted(rn)} != {sorted(ro)}")
    problem_scale = _scale(ro)
    for name in ro.keys() & rn.keys():
        # a residual or drift is itself an error (of a closed form, its rounding): it may change by
        # the route's error of the problem's scale (the largest number of the record), not of its
        # own tiny size
        errorlike = name.endswith(("_residual", "drift", "_check"))
        scale = problem_scale if errorlike else _scale(ro[name])
        tol = CLOSED_RTOL * scale if closed else ODE_FACTOR * (old["rtol"] * scale + old["atol"])
        _diff(ro[name], rn[name], tol, f"{where} {name}", out)
    if closed and old.get("warnings") != new.get("warnings"):
        out.append(f"{where} warnings: {new.get('warnings')!r} != {old.get('warnings')!r}")
    return out


def load() -> dict[str, list[dict]]:
    return json.loads(BASELINE.read_text())


def type_files(name: str) -> list[str]:
    """The files of ``problems/`` that hold a problem of type ``name`` (its declared example first)."""
    import yaml

    from dyncli import registry

    spec = registry.TYPES[name]
    out = [spec.example] if spec.example else []
    for f in problem_files():
        data = yaml.safe_load(f.read_text(encoding="utf-8"))
        items = data.get("problems", [data]) if isinstance(data, dict) else []
        rel = f.relative_to(ROOT).as_posix()
        if rel not in out and any(isinstance(i, dict) and i.get("type") == name for i in items):
            out.append(rel)
    return out


def expand(args: list[str]) -> list[str]:
    """FILE arguments as they are; a registered type name as its files (:func:`type_files`)."""
    from dyncli import registry

    out: list[str] = []
    for a in args:
        if not a.endswith((".yaml", ".yml")) and a in registry.TYPES:
            files = type_files(a)
            if not files:
                raise SystemExit(f"type {a!r} has no example in problems/ (declare TypeSpec.example)")
            out += [str(ROOT / f) for f in files]
        elif not a.endswith((".yaml", ".yml")):
            raise SystemExit(f"{a!r} is neither a problem file nor a registered type")
        else:
            out.append(a)
    return out


def add(paths: list[str]) -> list[str]:
    """Record the files of ``problems/`` that the baseline does not hold yet (or only ``paths``,
    each of which must be new): a new type or example is added without re-recording, and so
    without rewriting, any other file's reference values."""
    base = load() if BASELINE.exists() else {}
    files = [Path(p).resolve() for p in paths] if paths else problem_files()
    names = [p.relative_to(ROOT).as_posix() for p in files]
    again = [n for n in names if n in base and paths]
    if again:
        raise SystemExit(f"already recorded: {', '.join(again)} (an intended change of results: `record`)")
    new = [(n, p) for n, p in zip(names, files) if n not in base]
    for n, p in new:
        base[n] = record_file(p)
    BASELINE.write_text(json.dumps(base, indent=1, sort_keys=True) + "\n")
    return [n for n, _ in new]


def record_again(paths: list[str]) -> list[str]:
    """Record again only the files ``paths`` (each recorded already: an intended change of their
    results, said in the commit), leaving every other file's reference values as they are."""
    base = load()
    names = [Path(p).resolve().relative_to(ROOT).as_posix() for p in paths]
    missing = [n for n in names if n not in base]
    if missing:
        raise SystemExit(f"not recorded yet: {', '.join(missing)} (a new file: `add`)")
    for n in names:
        base[n] = record_file(ROOT / n)
    BASELINE.write_text(json.dumps(base, indent=1, sort_keys=True) + "\n")
    return names


USAGE = ("usage: python -m tests.tools.baseline record          (every file, after an intended change)\n"
         "       python -m tests.tools.baseline record FILE ...  (only those files, after an intended change)\n"
         "       python -m tests.tools.baseline add [FILE ...]   (only files not recorded yet)\n"
         "       python -m tests.tools.baseline add TYPE         (only the example files of a new type)")


def main(argv: list[str]) -> int:
    if argv[:1] == ["add"]:
        added = add(expand(argv[1:]))
        print(f"added {len(added)} file(s) to {BASELINE.relative_to(ROOT)}: {', '.join(added) or 'none'}")
        return 0
    if argv[:1] != ["record"]:
        print(USAGE, file=sys.stderr)
        return 2
    if argv[1:]:
        again = record_again(argv[1:])
        print(f"recorded {len(again)} file(s) again in {BASELINE.relative_to(ROOT)}: {', '.join(again)}")
        return 0
    BASELINE.parent.mkdir(parents=True, exist_ok=True)
    BASELINE.write_text(json.dumps(record_all(), indent=1, sort_keys=True) + "\n")
    print(f"wrote {BASELINE.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
