"""Start-up discipline, checked in fresh interpreters (sys.modules):

* ``--version``, ``--help`` and ``solve --help`` import neither numpy nor scipy
  (nor sympy);
* every example problem in problems/ solved by a closed form or an exact
  (elliptic) route imports neither scipy nor sympy (sympy only where exact
  derivatives need it: list such a type in SYMPY_NEEDED with the reason);
  the top without ``at`` and the gyroscope's exact route included.

Timings are never asserted here; benchmarks/startup.py and
benchmarks/batch.py measure them.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import PROBLEMS, ROOT

SYMPY_NEEDED: dict[str, str] = {
    # "type": "why a closed form of this type needs exact derivatives",
}


def _run(code: str) -> str:
    env = dict(os.environ, PYTHONPATH=str(ROOT), NO_COLOR="1")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, env=env, timeout=300)
    assert p.returncode == 0, p.stderr[-3000:]
    return p.stdout


@pytest.mark.parametrize("args", [["--version"], ["--help"], ["solve", "--help"], ["check", "--help"], ["types"]])
def test_cheap_commands_import_no_numerics(args):
    code = (
        "import sys, runpy\n"
        f"sys.argv = ['dyncli'] + {args!r}\n"
        "try:\n    runpy.run_module('dyncli', run_name='__main__')\nexcept SystemExit:\n    pass\n"
        "print('\\nMODS=' + ','.join(m for m in ('numpy', 'scipy', 'sympy', 'matplotlib', 'pint') if m in sys.modules))\n"
    )
    mods = [ln for ln in _run(code).splitlines() if ln.startswith("MODS=")][-1][5:]
    assert mods == "", f"dyncli {' '.join(args)} imported {mods}"


_SOLVE_EACH = """
import json, sys
from dyncli.loader import load_paths
from dyncli.run import solve_one
HEAVY = ("scipy", "sympy", "matplotlib")
for f in sys.argv[1:]:
    before = {m for m in HEAVY if m in sys.modules}
    problems, _ = load_paths([f])
    methods = []
    for lp in problems:
        o = solve_one(lp)
        methods.append([lp.type, o.result.method if o.result is not None else None])
    after = {m for m in HEAVY if m in sys.modules}
    print("REC=" + json.dumps({"file": f, "methods": methods, "new": sorted(after - before), "had": sorted(before)}))
"""


def _solve_each(files: list[str]) -> list[dict]:
    code = "import sys\nsys.argv = ['x'] + " + repr(files) + "\n" + _SOLVE_EACH
    return [json.loads(ln[4:]) for ln in _run(code).splitlines() if ln.startswith("REC=")]


# closed-form routes whose declared example integrates (benchmarks/startup_types.py's EXTRA)
CLOSED_TEXTS = {
    "force-field (no path), a polynomial field: exact without sympy":
        "type: force-field\nF: ['2*x1*x2 + x3**3', 'x1**2', '3*x1*x3**2']\npoints: [[1, 2, 3]]\n",
}


@pytest.mark.parametrize("name", sorted(CLOSED_TEXTS))
def test_closed_form_texts_import_neither_scipy_nor_sympy(name, tmp_path):
    f = tmp_path / "case.yaml"
    f.write_text(CLOSED_TEXTS[name])
    [r] = _solve_each([str(f)])
    assert r["methods"] and all(m == "closed-form" for _, m in r["methods"]), r
    assert r["new"] == [], f"{name} imported {r['new']}"


#: routes that are formulas evaluated at the requested times (no integrator, no quadrature)
FORMULA_ROUTES = ("closed-form", "exact")
#: exact-route variants not among the examples: the top without `at` (its bounds only)
EXTRA = {"top-no-at.yaml": "type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\ntheta: 0.5\nphi_dot: 150\n"}


def test_closed_forms_import_neither_scipy_nor_sympy(tmp_path):
    files = [str(p.relative_to(ROOT)) for p in sorted(PROBLEMS.rglob("*.yaml")) if "course-example" not in p.parts]
    for name, text in EXTRA.items():
        (tmp_path / name).write_text(text)
        files.append(str(tmp_path / name))
    recs = _solve_each(files)
    closed = [r["file"] for r in recs
              if r["methods"] and all(m in FORMULA_ROUTES for _, m in r["methods"])]
    from dyncli import registry

    # every type with an exact route has an example solved by it here (particle: the Kepler orbit)
    assert set(registry.having("exact")) <= {t for r in recs if r["file"] in closed for t, m in r["methods"] if m == "exact"}
    assert closed, "no closed-form example found"
    # second interpreter: only the closed-form files, so nothing else imported scipy first
    bad = []
    for r in _solve_each(closed):
        types = {t for t, _ in r["methods"]}
        for mod in r["new"]:
            if mod == "sympy" and types <= set(SYMPY_NEEDED):
                continue
            bad.append(f"{r['file']} ({', '.join(sorted(types))}) imported {mod}")
    assert not bad, "\n".join(bad)


#: closed-form (or exact) types whose example problems are solved in plain floats (dyncli.vec3,
#: dyncli.direction, dyncli.elliptic's float paths): solving them never imports numpy (issue 19, cold start).
#: Declared by the flag ``numpy_free`` of each type (dyncli/declare.py).
def numpy_free() -> tuple[str, ...]:
    from dyncli import registry

    return registry.having("numpy_free")


_SOLVE_NUMPY_FREE = """
import json, sys
from dyncli.loader import load_paths
from dyncli.run import solve_one
for f in sys.argv[1:]:
    problems, _ = load_paths([f])
    methods = [[lp.type, o.result.method if o.result is not None else None]
               for lp in problems for o in [solve_one(lp)]]
    print("REC=" + json.dumps({"file": f, "methods": methods, "numpy": "numpy" in sys.modules}))
    if "numpy" in sys.modules:
        break
"""


def test_numpy_free_closed_forms_import_no_numpy(tmp_path):
    """Every example of a numpy_free type, solved in one fresh interpreter, leaves numpy unimported
    (the first file that imports it is named).  A ``find`` query is the one exception: its search
    cuts the exact motion at the exact extremes of the results it searches (the sign analysis of
    numpy's Chebyshev interpolants, docs/queries.md), so the examples are solved without it."""
    import yaml

    from dyncli import registry

    examples = [registry.TYPES[t].example for t in numpy_free()]
    assert all(examples), "every numpy_free type declares an example"
    files = []
    for k, name in enumerate(examples):
        data = yaml.safe_load((ROOT / name).read_text(encoding="utf-8"))
        docs = data.get("problems", [data]) if isinstance(data, dict) else []
        if any(isinstance(d, dict) and "find" in d for d in docs):
            for d in docs:
                d.pop("find", None)
            path = tmp_path / f"{k}-{Path(name).name}"
            path.write_text(yaml.safe_dump(data), encoding="utf-8")
            name = str(path)
        files.append(name)
    code = "import sys\nsys.argv = ['x'] + " + repr(files) + "\n" + _SOLVE_NUMPY_FREE
    recs = [json.loads(ln[4:]) for ln in _run(code).splitlines() if ln.startswith("REC=")]
    assert recs and all(m in FORMULA_ROUTES for r in recs for _, m in r["methods"]), recs
    bad = [r["file"] for r in recs if r["numpy"]]
    assert not bad, f"{bad[0]} ({', '.join(sorted({t for t, _ in recs[-1]['methods']}))}) imported numpy"
    assert len(recs) == len(files)


def test_top_without_times_imports_no_numpy(tmp_path):
    """The top without `at` (EXTRA: its nutation bounds only, by the exact route) is solved in plain
    floats: the nutation cubic's roots by the Nutation constants, no evaluation (issue 19)."""
    f = tmp_path / "top-no-at.yaml"
    f.write_text(EXTRA["top-no-at.yaml"])
    code = "import sys\nsys.argv = ['x', " + repr(str(f)) + "]\n" + _SOLVE_NUMPY_FREE
    [rec] = [json.loads(ln[4:]) for ln in _run(code).splitlines() if ln.startswith("REC=")]
    assert rec["methods"] == [["top", "exact"]] and not rec["numpy"], rec


def test_the_command_reads_no_pydantic_plugin_entry_points():
    """The command solves without pydantic's plugin search (importlib.metadata and every
    distribution's entry points); the Python API leaves pydantic alone."""
    code = (
        "import sys, runpy\n"
        "sys.argv = ['dyncli', 'solve', '-f', 'json', 'problems/scenes/yo-yo.yaml']\n"
        "try:\n    runpy.run_module('dyncli', run_name='__main__')\nexcept SystemExit as e:\n"
        "    assert not e.code, e.code\n"
        "print('\\nMETA=' + str('importlib.metadata' in sys.modules))\n"
    )
    out = _run(code)
    record = json.loads(out.split("\nMETA=")[0])
    assert (record[0] if isinstance(record, list) else record)["type"] == "scene"
    assert out.rstrip().endswith("META=False")
    api = _run("import dyncli, sys\ndyncli.solve('problems/scenes/yo-yo.yaml')\n"
               "m = sys.modules.get('pydantic.plugin._loader')\n"
               "print(m is not None and not (m.__doc__ or '').startswith(\"dyncli's stand-in\"))")
    assert api.strip().endswith("True")


def test_the_stand_in_gives_pydantic_its_real_loader_for_anything_else():
    code = (
        "import sys\nfrom dyncli.__main__ import no_pydantic_plugins, PLUGIN_LOADER\n"
        "no_pydantic_plugins()\nstub = sys.modules[PLUGIN_LOADER]\nassert tuple(stub.get_plugins()) == ()\n"
        "assert not hasattr(stub, '__path__')\n"
        "group = stub.PYDANTIC_ENTRY_POINT_GROUP\n"
        "print(group, sys.modules[PLUGIN_LOADER] is not stub)\n"
    )
    assert _run(code).split() == ["pydantic", "True"]
