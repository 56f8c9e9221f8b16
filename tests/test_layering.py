"""The layering of issue #19, checked by importing (not by searching the text):

* the numeric core (``dyncli/topics/*/equations.py`` and the neutral helpers) imports neither
  pydantic nor the renderer ``dyncli.render``, even while its functions run (their doctests);
* no module of ``dyncli/topics`` imports ``dyncli.render``, at import time or while it solves
  every file of ``problems/`` (a wrapper around ``builtins.__import__`` records each import
  statement executed by a topic module, so a lazy import inside a function is caught too).

* no function of a topic below its ``solver.py`` (and outside its input model, ``model.py``)
  receives a pydantic object while every file of ``problems/`` is solved: the physics takes
  plain numbers and the topics' own frozen dataclasses (issue #26, a core of plain numbers —
  checked on the data, not only on the imports).

Each check runs in a fresh interpreter, so what other tests imported does not matter.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: the numeric core: the equations modules plus the neutral helpers and the topics' pure numeric modules
CORE = ["dyncli.numfmt", "dyncli.vec3", "dyncli.exact", "dyncli.errors", "dyncli.result", "dyncli.direction",
        "dyncli.ode", "dyncli.integrators", "dyncli.runner", "dyncli.rootfind", "dyncli.quadrature", "dyncli.elliptic", "dyncli.backends", "dyncli.expr.jet", "dyncli.expr.floatmath",
        "dyncli.expr.derivative",
        "dyncli.topics.vibration.closed_form", "dyncli.topics.vibration.backends", "dyncli.topics.euler.free",
        "dyncli.topics.inertia.rotations", "dyncli.topics.inertia.eigen3", "dyncli.topics.inertia.mat3",
        "dyncli.topics.force_field.polynomial", "dyncli.topics.particle.forces",
        "dyncli.topics.particle.trajectory"] + [
    f"dyncli.topics.{p.parent.name}.equations" for p in sorted(ROOT.glob("dyncli/topics/*/equations.py"))]
FORBIDDEN_IN_CORE = ("pydantic", "dyncli.render")

_CORE_PROBE = r"""
import doctest, importlib, json, sys
found = {}
for name in sys.argv[1:]:
    before = set(sys.modules)
    mod = importlib.import_module(name)
    doctest.testmod(mod)
    found[name] = sorted(m for m in set(sys.modules) - before
                         if m.split(".")[0] == "pydantic" or m.startswith("dyncli.render"))
print(json.dumps(found))
"""

_TOPIC_PROBE = r"""
import builtins, importlib, json, pkgutil, sys
from pathlib import Path
hits = []
real = builtins.__import__

def spy(name, globals=None, locals=None, fromlist=(), level=0):
    importer = (globals or {}).get("__name__", "")
    if importer.startswith("dyncli.topics"):
        full = name
        if level:
            drop = level - 1 if (globals or {}).get("__path__") else level   # a package is its own base
            base = importer.rsplit(".", drop)[0] if drop else importer
            full = base + ("." + name if name else "")
        targets = [full] + [f"{full}.{f}" for f in (fromlist or ())]
        if any(t == "dyncli.render" or t.startswith("dyncli.render.") for t in targets):
            hits.append(f"{importer} imports {full}")
    return real(name, globals, locals, fromlist, level)

builtins.__import__ = spy
import dyncli.topics as T
for m in pkgutil.walk_packages(T.__path__, "dyncli.topics."):
    importlib.import_module(m.name)
from dyncli.loader import load_paths
from dyncli.registry import solver
from dyncli.result import SolveOptions
problems, _ = load_paths([str(p) for p in sorted(Path("problems").rglob("*.yaml"))])
for lp in problems:
    try:
        solver(lp.model.type)(lp.model, SolveOptions())
    except Exception as exc:   # an example that fails is another test's business
        pass
print(json.dumps(sorted(set(hits))))
"""


def _run(code: str, *args: str):
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    out = subprocess.run([sys.executable, "-c", code, *args], cwd=ROOT, env=env,
                         capture_output=True, text=True, timeout=900)   # a hang guard, not a timing: every example under a loaded machine
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_numeric_core_imports_neither_pydantic_nor_renderer():
    found = _run(_CORE_PROBE, *CORE)
    bad = {k: v for k, v in found.items() if v}
    assert not bad, f"the numeric core imports {FORBIDDEN_IN_CORE}: {bad}"


def test_topics_never_import_the_renderer():
    hits = _run(_TOPIC_PROBE)
    assert not hits, "a topic imports dyncli.render (move what it needs to a neutral module such as " \
                     f"dyncli.numfmt): {hits}"


_DATA_PROBE = r"""
import json, sys
from pathlib import Path
from pydantic import BaseModel
from dyncli.loader import load_paths
from dyncli.registry import solver
from dyncli.result import SolveOptions
hits = set()

def prof(frame, event, arg):
    if event != "call":
        return
    mod = frame.f_globals.get("__name__", "")
    if not mod.startswith("dyncli.topics.") or mod.endswith((".solver", ".model")):
        return
    code = frame.f_code
    for name in code.co_varnames[:code.co_argcount + code.co_kwonlyargcount]:
        if isinstance(frame.f_locals.get(name), BaseModel):
            hits.add(f"{mod}.{code.co_name}({name}: {type(frame.f_locals[name]).__name__})")

problems, _ = load_paths([str(p) for p in sorted(Path("problems").rglob("*.yaml"))])
for lp in problems:
    sys.setprofile(prof)
    try:
        solver(lp.model.type)(lp.model, SolveOptions())
    except Exception:   # an example that fails is another test's business
        pass
    finally:
        sys.setprofile(None)
print(json.dumps(sorted(hits)))
"""


def test_no_pydantic_object_below_the_solvers():
    """A core of plain numbers, checked on the data (not only the imports): while every file of
    ``problems/`` is solved, no function of a topic outside its ``solver.py`` (the adapter) and
    ``model.py`` (the input model) receives a pydantic model as an argument — the solver hands the
    physics plain floats, arrays and the topic's own frozen dataclasses, so a notebook can call it
    with numbers."""
    hits = _run(_DATA_PROBE)
    assert not hits, "a function below a topic's solver.py receives the pydantic input model " \
                     f"(hand it plain numbers or a frozen dataclass built in solver.py): {hits}"
