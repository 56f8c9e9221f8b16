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
from dyncli.fields import Num, ProblemBase, Vector
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


# -- declarations that cannot be misspelt (issue #26 item 4) ------------------------------------------------


def test_a_misspelt_kind_is_an_error_at_declaration_naming_type_and_result():
    from dyncli.declare import DeclarationError

    with pytest.raises(DeclarationError, match=r"type 'toy-typo', result 'period': unknown kind 'nmber' "
                                                r"\(did you mean 'number'\?\)"):
        TypeSpec(name="toy-typo", title="t", sections="§17", model=Toy, solve=toy_solve,
                 results=[R("omega_n", "ωₙ", "rad/s", kind="number"), R("period", "T", "s", kind="nmber")])
    with pytest.raises(DeclarationError, match=r"result 'x': unknown kind 'vectr'"):
        TypeSpec(name="toy-typo", title="t", sections="§17", model=Toy, results=[R("x", kind="list|vectr")])
    # a union of known kinds, and "any", are kinds
    TypeSpec(name="toy-ok", title="t", sections="§17", model=Toy, results=[R("x", kind="list|number"), R("y")])


def test_an_unknown_result_unit_is_an_error_at_declaration_naming_type_and_result():
    from dyncli.declare import DeclarationError
    from dyncli.units import RESULT_UNITS, display_factor

    with pytest.raises(DeclarationError, match=r"type 'toy-typo', result 'omega_n': unknown unit 'rad/sec' "
                                                r"\(did you mean 'rad/s'\?\)"):
        TypeSpec(name="toy-typo", title="t", sections="§17", model=Toy, results=[R("omega_n", "ωₙ", "rad/sec")])
    with pytest.raises(DeclarationError, match=r"result 'F': unknown unit 'newton'"):
        TypeSpec(name="toy-typo", title="t", sections="§17", model=Toy, results=[R("F", "F", "newton")])
    # every unit a result may be declared in is one pint reads (so --units can convert it)
    for unit in RESULT_UNITS:
        assert display_factor(unit, [unit]) is not None, unit


def test_a_misspelt_dimension_is_an_error_when_the_model_is_built_naming_type_and_field():
    from typing import Optional

    from dyncli.fields import StrictModel, Vec3, Vector
    from dyncli.units import UnknownDimension

    with pytest.raises(UnknownDimension, match=r"type 'toy-typo' \(Typo\), field 'L': unknown dimension 'lenght' "
                                               r"\(did you mean 'length'\?\)"):
        class Typo(ProblemBase):
            type: Literal["toy-typo"]
            L: Optional[Annotated[float, Num(gt=0, dim="lenght")]] = None

    with pytest.raises(UnknownDimension, match=r"model Part, field 'v': unknown dimension 'sped'"):
        class Part(StrictModel):
            v: dict[str, Annotated[Vector, Vec3(dim="sped")]]


def test_an_unknown_dimension_never_turns_the_unit_check_off():
    """Every dimension a model declares is known (checked when the model is built), so "3 s" is refused
    for a length; asked for directly, an unknown dimension raises instead of meaning "no unit"."""
    from dyncli import units

    for name in registry.TYPES:
        if registry.available(name):
            registry.model_class(name)          # builds: every declared dimension is known
    with pytest.raises(units.UnitError, match="expected a length"):
        units.parse_quantity("3 s", "length")
    for call in (units.si_unit, lambda d: units.parse_quantity("3 m", d)):
        with pytest.raises(units.UnknownDimension, match="lenght"):
            call("lenght")
    assert units.si_unit("angular velocity") == "rad/s" and units.si_unit(None) == ""


#: the hand lists the capability flags replaced (dyncli/run.py, tests/speed/test_imports.py), as they were
FORMER_HAND_LISTS = {
    "symbolic": ("kinematics", "rotating-frame", "scene", "top"),
    "numpy_free": ("angular-velocity", "bearing-forces", "contact", "euler", "gyroscope", "impact", "inertia",
                   "motor-bodies", "particles", "planar-moments", "precession", "rigid-energy", "rigid-impulse",
                   "rigid-velocity", "rotating-frame", "screw", "spin-change", "top", "vibration"),
}


@pytest.mark.parametrize("capability", sorted(FORMER_HAND_LISTS))
def test_derived_lists_equal_the_former_hand_lists(capability):
    assert sorted(registry.having(capability)) == sorted(FORMER_HAND_LISTS[capability])


def test_an_unknown_capability_is_an_error():
    with pytest.raises(ValueError, match="unknown capability 'numpyfree'"):
        registry.having("numpyfree")
