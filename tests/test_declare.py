"""Adding a type takes one declaration: a test-only toy type, registered at
test time from one :class:`~dyncli.declare.TypeSpec`, is validated, solved,
rendered (symbols and units from the declaration, a per-point pattern
result), documented (the generated results table) and described by the
results schema — with no other file of the project touched.  A solver that
produces an undeclared key is stopped as a bug (exit 3)."""

from __future__ import annotations

import io
import math
from typing import Annotated, Literal

import pytest
from pydantic import Field

from dyncli import registry
from dyncli.declare import R, TypeSpec, UndeclaredResult
from dyncli.fields import Num, ProblemBase
from dyncli.result import Result
from tests.conftest import solve_text


class Toy(ProblemBase):
    type: Literal["toy-spring"]
    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")] = Field(...)
    k: Annotated[float, Num(gt=0, description="spring constant [N/m]")] = Field(...)
    points: dict[str, float] = Field(default_factory=dict, description="name: amplitude [m]")
    bug: bool = False


def toy_solve(p, options=None) -> Result:
    wn = math.sqrt(p.k / p.m)
    res = Result({"omega_n": wn, "period": 2 * math.pi / wn}, equations=["17.5b"])
    for name, amp in p.points.items():
        res.results[f"vmax_{name}"] = amp * wn
    if p.bug:
        res.results["surprise"] = 1.0
    return res


TOY = TypeSpec(
    name="toy-spring",
    title="a test-only spring-mass oscillator",
    sections="§17",
    model=Toy,
    solve=toy_solve,
    plots=None,
    example="problems/vibration/free-underdamped.yaml",
    results=[
        R("omega_n", "ωₙ", "rad/s", "17.5b", "natural frequency √(k/m)", kind="number", contract=True),
        R("period", "T", "s", "", "period 2π/ωₙ", kind="number"),
        R("vmax_{point}", "v_max({point})", "m/s", "", "largest speed of the named point, amplitude × ωₙ", kind="number"),
    ],
)

TEXT = "type: toy-spring\ntitle: toy\nm: 2\nk: 8\npoints: {A: 0.5, tip: 1}\n"


@pytest.fixture
def toy():
    registry.register(TOY, package="tests.test_declare")
    yield TOY
    registry.unregister(TOY.name)


def test_toy_type_is_registered_validated_and_solved(toy):
    assert "toy-spring" in registry.TYPES and registry.available("toy-spring")
    [rec] = solve_text(TEXT)
    assert rec.get("error") is None, rec
    r = rec["results"]
    assert r["omega_n"] == 2.0 and r["period"] == pytest.approx(math.pi, rel=4e-16)
    assert r["vmax_A"] == 1.0 and r["vmax_tip"] == 2.0
    [bad] = solve_text("type: toy-spring\nm: -1\nk: 8\n")
    assert bad["error"] and "m" in bad["error"]


def test_toy_symbols_and_units_come_from_the_declaration(toy):
    from dyncli.loader import split_problems, validate
    from dyncli.render.table import make_console, render
    from dyncli.run import solve_one

    [lp], _ = split_problems("toy.yaml", TEXT.encode())
    validate(lp)
    out = solve_one(lp)
    assert out.exit_code == 0
    res = out.result
    assert res.symbols["omega_n"] == "ωₙ" and res.units["omega_n"] == "rad/s"
    assert res.symbols["vmax_tip"] == "v_max(tip)" and res.units["vmax_tip"] == "m/s"
    buf = io.StringIO()
    render(make_console(buf), lp, res)
    text = buf.getvalue()
    assert "toy-spring (§17)" in text
    for cell in ("ωₙ", "rad/s", "v_max(A)", "m/s"):
        assert cell in text, cell


def test_an_undeclared_key_is_a_bug(toy):
    with pytest.raises(UndeclaredResult, match="surprise"):
        TOY.check({"omega_n": 1.0, "surprise": 2})
    [rec] = solve_text(TEXT + "bug: true\n")
    assert rec["exit_code"] == 3
    assert "internal error" in rec["error"] and "undeclared" in rec["error"] and "surprise" in rec["error"]


def test_toy_docs_table_and_results_schema(toy):
    import sys

    from tests.conftest import ROOT

    sys.path.insert(0, str(ROOT / "docs"))
    try:
        import hooks
    finally:
        sys.path.remove(str(ROOT / "docs"))
    page = "# toy\n\n<!-- results: toy-spring -->\n"
    assert hooks.stale_regions(page) == ["<!-- results: toy-spring -->"]
    done = hooks.regenerate(page)
    assert hooks.stale_regions(done) == []
    assert "| `omega_n` | ωₙ | rad/s | natural frequency √(k/m) | 17.5b |" in done
    assert "| `vmax_{point}` | v_max({point}) | m/s |" in done

    from dyncli.schema import results_json_schema

    sch = results_json_schema("toy-spring")
    assert set(sch["properties"]) == {"omega_n", "period"} and sch["additionalProperties"] is False
    [(pattern, sub)] = sch["patternProperties"].items()
    assert sub["x-unit"] == "m/s"
    import re

    assert re.match(pattern, "vmax_tip") and not re.match(pattern, "omega_n")


def test_declarations_import_nothing_heavy():
    """The registry reads every declaration at start-up: no numpy, scipy,
    sympy or pydantic, and no topic package (its solver) until a type is solved."""
    import subprocess
    import sys

    from tests.conftest import ROOT

    code = ("import sys, dyncli.registry as r; assert len(r.TYPES) > 20; "
            "print(sorted(m for m in sys.modules if m.split('.')[0] in ('numpy', 'scipy', 'sympy', 'pydantic') "
            "or (m.startswith('dyncli.topics.') and not m.endswith('.results'))))")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]", out.stdout
