"""A bare angle beyond a full turn (``theta: 30`` meant as degrees) is named
with the way to write degrees (``30*deg``), over every angle field of every
type; ``30*deg``, ``0.5`` and ``pi/2`` pass silently."""

from __future__ import annotations

import copy
import math

import pytest
import yaml

from dyncli import registry
from dyncli.angles import declared_angle_fields, degrees_warnings
from dyncli.loader import split_problems, validate
from dyncli.run import solve_one
from tests.conftest import ROOT

IMPACT_ROUGH = {"eta": 0.5, "t": [0, 1, 0]}   # the general model (eta, phi) and its tangent, in place of e


def _template(t: str) -> dict:
    from dyncli.schema import template

    return yaml.safe_load(template(t))       # packaged, or derived from the declared example


def _problem(t: str, path: str, value) -> dict:
    """The type's template with the angle field at ``path`` set to ``value``
    (and what that field needs beside it)."""
    raw = copy.deepcopy(_template(t))
    if t == "impact":
        raw.pop("e")
        raw.update(IMPACT_ROUGH)
    parts = path.split(".")
    if parts[0] == "instant":              # kinematics at one instant: the state instead of position
        raw.pop("position", None)
        raw.pop("distance", None)
        raw.update(coordinates="spherical", at=[], instant={"R": 1, "theta": 0, "phi": 0})
    node = raw
    for p in parts[:-1]:            # `*`: a list's first entry, or a mapping's (a scene's first body)
        node = (node[0] if isinstance(node, list) else next(iter(node.values()))) if p == "*" else node.setdefault(p, {})
    leaf = parts[-1]
    if parts[-2:] in (["orientation", "angle"], ["basis", "angle"], ["basis0", "angle"]):
        node["axis"] = [0, 0, 1]
    node[leaf] = [value, 0, 0] if leaf == "euler313" else value
    return raw


def _concrete(t: str, path: str) -> str:
    """``path`` with each `*` as the template's first entry there: 0 in a list, the first name in
    a mapping (a scene's first body), as the warnings name it."""
    node, out = _template(t), []
    for p in path.split("."):
        if p == "*":
            p = "0" if isinstance(node, list) else next(iter(node))
        out.append(p)
        node = node[int(p)] if isinstance(node, list) else (node.get(p, {}) if isinstance(node, dict) else {})
    return ".".join(out)


def _solve(raw: dict):
    problems, diags = split_problems("angle.yaml", yaml.safe_dump(raw).encode(), ROOT)
    assert not diags, diags
    validate(problems[0])
    return solve_one(problems[0])


CASES = [(t, p) for t in registry.TYPES for p in declared_angle_fields(registry.model_class(t))]


def test_the_angle_fields_are_found():
    """The declarations name the angle fields this test covers (a new one joins by itself)."""
    found = {f"{t}:{p}" for t, p in CASES}
    assert {"precession:theta", "top:theta", "top:psi", "top:phi", "gyroscope:theta0", "impact:phi",
            "motor-bodies:alpha", "bearing-forces:masses.*.alpha", "inertia:parts.*.orientation.angle",
            "inertia:parts.*.orientation.euler313", "inertia:basis.angle", "inertia:basis.euler313"} <= found


@pytest.mark.parametrize("t,path", CASES, ids=[f"{t}:{p}" for t, p in CASES])
@pytest.mark.parametrize("bare", [30, "30", 45.0, -90, 360])
def test_bare_degrees_are_named(t, path, bare):
    o = _solve(_problem(t, path, bare))
    shown = f"{float(bare):g}"
    dotted = _concrete(t, path)
    if o.exit_code == 0:
        hits = [w for w in o.result.warnings if w.startswith(dotted) and f"write {shown}*deg" in w]
        assert len(hits) == 1, o.result.warnings
        assert "radians" in hits[0]
    else:   # refused by the field's range (a friction angle beyond pi/2): the refusal says it too
        assert o.exit_code == 2, o.message
        assert dotted in o.message and f"write {shown}*deg" in o.message, o.message


@pytest.mark.parametrize("t,path", CASES, ids=[f"{t}:{p}" for t, p in CASES])
@pytest.mark.parametrize("value", ["30*deg", 0.5, "pi/2", "-pi/4", 6, "0.25 rad", "30 deg"])
def test_radians_and_degrees_written_as_such_pass(t, path, value):
    o = _solve(_problem(t, path, value))
    if o.exit_code == 0:
        assert not [w for w in o.result.warnings if "*deg" in w], o.result.warnings
    else:
        assert "*deg" not in (o.message or ""), o.message


def test_an_expression_in_t_is_not_bare():
    """bearing-forces' alpha(t) written as an expression is never judged; a bare 30 is."""
    raw = _template("bearing-forces")
    raw["masses"][0]["alpha"] = "30 + t"
    o = _solve(raw)
    assert o.exit_code == 0 and not [w for w in o.result.warnings if "*deg" in w]


def test_warning_text():
    problems, _ = split_problems("p.yaml", yaml.safe_dump(_problem("precession", "theta", 30)).encode(), ROOT)
    validate(problems[0])
    (w,) = degrees_warnings(problems[0].model, problems[0].raw)
    assert w == f"theta: 30 is read in radians ({math.degrees(30):.4g}°, more than a full turn); " \
                "if you meant degrees, write 30*deg"


def test_a_huge_integer_is_left_to_its_field():
    from dyncli.angles import _bare

    assert _bare(10 ** 400) is None and _bare("9" * 500) is None and _bare("30") == 30.0


def _every_field(model, raw, path=()):
    """(path, value as written) of every angle field given in ``raw``, found by visiting every field
    of every model met (no field left out): the reference for the pruned walk of dyncli.angles."""
    from pydantic import BaseModel

    from dyncli.angles import is_angle

    if not isinstance(raw, dict):
        return
    for name, info in type(model).model_fields.items():
        key = info.alias or name
        if key not in raw:
            continue
        value, written, here = getattr(model, name, None), raw[key], path + (key,)
        if is_angle(info):
            yield here, written
        elif isinstance(value, BaseModel):
            yield from _every_field(value, written, here)
        elif isinstance(value, (list, tuple)) and isinstance(written, list):
            for i, (v, w) in enumerate(zip(value, written)):
                if isinstance(v, BaseModel):
                    yield from _every_field(v, w, here + (i,))
        elif isinstance(value, dict) and isinstance(written, dict):
            for k, v in value.items():
                if isinstance(v, BaseModel) and k in written:
                    yield from _every_field(v, written[k], here + (k,))


def test_the_walk_leaves_out_only_fields_that_hold_no_angle():
    """The angle fields of every example and of every type's template (with each angle field set)
    are those a visit of every field finds."""
    from dyncli.angles import angle_fields
    from dyncli.loader import load_paths

    problems, _ = load_paths([str(p) for p in sorted((ROOT / "problems").rglob("*.yaml"))])
    for t, path in CASES:
        ps, _ = split_problems("angle.yaml", yaml.safe_dump(_problem(t, path, 400)).encode(), ROOT)
        validate(ps[0])
        problems += ps
    checked = 0
    for p in problems:
        if p.model is not None:
            assert list(angle_fields(p.model, p.raw)) == list(_every_field(p.model, p.raw)), p.file
            checked += bool(list(_every_field(p.model, p.raw)))
    assert checked > len(CASES) // 2


def test_a_bare_param_written_in_an_angle_field_is_judged_as_its_value():
    """A scene's body angle written as a parameter whose value is a bare -30 (a student's degrees:
    the compound pendulum released "30° below the horizontal" at -30 rad) is named with the
    parameter; an angle written as an expression of it (th0*deg) is not."""
    raw = yaml.safe_load((ROOT / "problems" / "scenes" / "compound-pendulum.yaml").read_text())
    raw["params"]["th0"] = -30
    o = _solve(raw)
    hits = [w for w in o.result.warnings if w.startswith("bodies.bar.angle (params.th0): -30 is read in radians")]
    assert len(hits) == 1 and "write -30*deg" in hits[0], o.result.warnings
    raw["params"]["th0"] = "-30*deg"
    o = _solve(raw)
    assert not [w for w in o.result.warnings if "*deg" in w], o.result.warnings


@pytest.mark.parametrize("top, warned", [("", True), ("g: g\n", False)])
def test_a_parameter_named_g_is_not_the_gravity_unless_the_file_says_so(top, warned):
    """`params: {g: 1.62}` (the Moon's, meant as gravity) with no `g` of the problem: the
    expressions read 1.62 but the motion falls at 9.81 — warned, with the fix; `g: g` at the top
    level makes it the gravity (a = 1.62 (m1 − m2)/(m1 + m2 + M/2) for the Atwood machine)."""
    text = (ROOT / "problems" / "scenes" / "atwood-massive-pulley.yaml").read_text()
    text = text.replace("params: {m1: 3, m2: 2, M: 1, R: 0.1}", "params: {m1: 3, m2: 2, M: 1, R: 0.1, g: 1.62}") + top
    problems, _ = split_problems("g.yaml", text.encode(), ROOT)
    validate(problems[0])
    o = solve_one(problems[0])
    hits = [w for w in o.result.warnings if w.startswith("params.g is a parameter of the expressions")]
    assert len(hits) == (1 if warned else 0), o.result.warnings
    a = (1.62 if not warned else 9.81) / 5.5
    assert o.result.results["a"]["A"][0][1] == pytest.approx(-a, rel=1e-12)
