"""One place for each numerical policy (issue #26): no module under ``dyncli/topics/`` imports
scipy's integrators, quadratures or root finders (``scipy.integrate``, ``scipy.optimize``) or
calls ``solve_ivp``, ``quad`` or ``brentq`` (or their relatives) of its own; only the runner's
modules may — ``dyncli/ode.py``, ``dyncli/runner.py``, ``dyncli/quadrature.py`` and
``dyncli/rootfind.py``.  Checked on the source with ``ast`` (a lazy import inside a function is
caught as well), not by a text search.  And the one Brent gives scipy's brentq's doubles."""

from __future__ import annotations

import ast
import math
import random
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[1] / "dyncli"
ALLOWED = {"ode.py", "runner.py", "quadrature.py", "rootfind.py"}
FORBIDDEN_MODULES = ("scipy.integrate", "scipy.optimize")
#: scipy's drivers, quadratures and root finders, by the names a topic would call them
FORBIDDEN_CALLS = {"solve_ivp", "odeint", "quad", "quad_vec", "dblquad", "tplquad", "nquad", "fixed_quad",
                   "quadrature", "romberg", "simpson", "trapezoid", "brentq", "brenth", "ridder", "bisect",
                   "newton", "toms748", "root_scalar", "fsolve", "root", "minimize_scalar", "fminbound"}
TOPICS = sorted((PKG / "topics").rglob("*.py"))


def _violations(path: Path):
    src = path.read_text(encoding="utf-8")
    tree = ast.parse(src)
    rel = path.relative_to(PKG.parent)
    runner_names = set()        # names bound from the runner's modules (calls of those are the point)
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for a in node.names:
                if a.name == "scipy" or a.name.startswith(FORBIDDEN_MODULES):
                    yield f"{rel}:{node.lineno} imports {a.name}"
        elif isinstance(node, ast.ImportFrom):
            mod = node.module or ""
            if mod.startswith(FORBIDDEN_MODULES) or (mod == "scipy" and any(
                    a.name in ("integrate", "optimize") for a in node.names)):
                yield f"{rel}:{node.lineno} imports from {mod}"
            if mod.startswith("dyncli.") and mod.split(".")[1] in {f[:-3] for f in ALLOWED} or node.level:
                runner_names.update(a.asname or a.name for a in node.names)
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            f = node.func
            if isinstance(f, ast.Name) and f.id in FORBIDDEN_CALLS and f.id not in runner_names:
                yield f"{rel}:{node.lineno} calls {f.id}() (not the runner's)"
            elif isinstance(f, ast.Attribute) and f.attr in FORBIDDEN_CALLS:
                base = f.value
                owner = base.id if isinstance(base, ast.Name) else None
                if owner not in ("runner", "ode", "quadrature", "rootfind", "bisect", "self"):
                    yield f"{rel}:{node.lineno} calls {ast.unparse(f)}() (not the runner's)"


@pytest.mark.parametrize("path", TOPICS, ids=[str(p.relative_to(PKG)) for p in TOPICS])
def test_topic_uses_the_one_runner(path):
    found = list(_violations(path))
    assert not found, ("a topic's numerics go through dyncli.runner / dyncli.ode (ODE), dyncli.quadrature "
                       "(quadrature) and dyncli.rootfind (roots):\n" + "\n".join(found))


def test_the_check_catches_what_it_should(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("def f():\n    from scipy.integrate import solve_ivp\n    import scipy.optimize as so\n"
                   "    so.brentq(g, 0, 1)\n    return solve_ivp(g, (0, 1), [0])\n"
                   "from scipy import integrate\n")
    rel = bad.relative_to(tmp_path)
    found = list(_violations_at(bad, tmp_path))
    assert len(found) == 5, found
    assert all(str(rel) in m for m in found)


def _violations_at(path, root):
    global PKG
    saved, PKG = PKG, root / "x"
    try:
        return list(_violations(path))
    finally:
        PKG = saved


def test_one_brent_is_scipys_brentq_bit_for_bit():
    from scipy.optimize import brentq as scipy_brentq

    from dyncli.rootfind import brentq

    rng = random.Random(26)
    n = 0
    for _ in range(600):
        c = [rng.uniform(-3, 3) for _ in range(4)]

        def f(x, c=c):
            return ((c[0] * x + c[1]) * x + c[2]) * x + c[3] + math.sin(3 * x)

        a, b = -5.0, rng.choice([5.0, 1e-3, 50.0])
        if f(a) * f(b) >= 0:
            continue
        for xtol, rtol in ((2e-12, 8.9e-16), (1e-300, 4 * 2.220446049250313e-16), (1e-15, 1e-15)):
            assert brentq(f, a, b, xtol=xtol, rtol=rtol, maxiter=200) == scipy_brentq(f, a, b, xtol=xtol, rtol=rtol,
                                                                                         maxiter=200)
            n += 1
    assert n > 500
    with pytest.raises(ValueError, match="different signs"):
        brentq(lambda x: x * x + 1.0, -1.0, 1.0)
    with pytest.raises(ValueError, match="NaN"):
        brentq(lambda x: math.nan if x > 0 else -1.0, -1.0, 1.0)
    with pytest.raises(RuntimeError):
        brentq(lambda x: x ** 3 - 0.3, 0.0, 1.0, xtol=1e-300, maxiter=2)
