"""The registry of problem types, built from the topics' declarations.

Each topic package ``dyncli/topics/<topic>/`` declares its types once, in
``results.py`` (``TYPES = [TypeSpec(...), ...]``, see :mod:`dyncli.declare`):
name, the notes' sections, input model, solver, plots, template, example and
one entry per result.  The registry finds every topic package that has such a
module (so adding a type touches its own package only), orders the types by
the notes' sections, and imports models and solvers lazily, only for the
types a run needs, so start-up stays fast (the declarations import nothing
heavy).  :func:`problem_union` builds the pydantic discriminated union on
``type`` over every registered model (used by ``dyncli schema`` and the
tests).  :func:`register` adds a type at run time (the test suite's toy
type).
"""

from __future__ import annotations

import importlib
import os
import re
from typing import Any, Callable

from dyncli.declare import CAPABILITIES, TypeSpec

_TOPICS = os.path.join(os.path.dirname(__file__), "topics")

#: A topic package holding one type is named after it (``constrained-particle`` in
#: ``dyncli/topics/constrained_particle``).  The packages named otherwise, and why; exactly these
#: (tests/test_code_shape.py): a new package is named after its type, or gets its line here.
PACKAGE_NAMES: dict[str, str] = {
    "particle_systems": "holds `particles` (§24-§27, systems of particles); `particles` beside the "
                        "`particle` package would differ by one letter from a different topic",
    "rigid_kinematics": "one chapter's four types: rigid-velocity, angular-velocity (§13), screw (§14) "
                        "and contact (§15), one model module of rigid-body kinematics",
    "rigid_kinetics": "rigid-body kinetics, two types on one model and one set of equations: "
                      "planar-moments (§32) and rigid-energy (§34)",
    "rigid_systems": "§36's systems of rigid bodies and point masses, two types on one model: "
                     "spin-change (H conserved) and motor-bodies (36.40)",
}


def _first_section(spec: TypeSpec) -> int:
    nums = [int(n) for n in re.findall(r"§\s*(\d+)", spec.sections)]
    return min(nums) if nums else 0


def _declarations(entry: str, path: str):
    """The module ``dyncli.topics.<entry>.results``, loaded from its file
    without importing the topic package (nor searching sys.path): start-up
    reads the declarations of every type, and imports the topic itself only
    for the type it solves.  Registered in ``sys.modules`` so a later import
    reuses it."""
    import sys
    from importlib import util

    name = f"dyncli.topics.{entry}.results"
    mod = sys.modules.get(name)
    if mod is None:
        spec = util.spec_from_file_location(name, path)
        assert spec is not None and spec.loader is not None    # a .py file has a spec and a loader
        mod = util.module_from_spec(spec)
        sys.modules[name] = mod
        spec.loader.exec_module(mod)
    return mod


def _discover() -> dict[str, TypeSpec]:
    found: list[TypeSpec] = []
    for entry in sorted(os.listdir(_TOPICS)):
        path = os.path.join(_TOPICS, entry, "results.py")
        if not os.path.isfile(path):
            continue
        for spec in _declarations(entry, path).TYPES:
            spec.package = f"dyncli.topics.{entry}"
            found.append(spec)
    found.sort(key=_first_section)   # stable: declaration order within a section
    return {s.name: s for s in found}


TYPES: dict[str, TypeSpec] = _discover()


def register(spec: TypeSpec, package: str = "") -> TypeSpec:
    """Add (or replace) a type at run time; returns it."""
    if package:
        spec.package = package
    TYPES[spec.name] = spec
    return spec


def unregister(name: str) -> None:
    TYPES.pop(name, None)


def spec(name: str) -> TypeSpec:
    return TYPES[name]


def having(capability: str) -> tuple[str, ...]:
    """The names of the types that declare ``capability`` (one of
    :data:`dyncli.declare.CAPABILITIES`), in the registry's order: every list
    of types with a capability is this, never written by hand."""
    if capability not in CAPABILITIES:
        raise ValueError(f"unknown capability {capability!r}; capabilities: {', '.join(CAPABILITIES)}")
    return tuple(n for n, s in TYPES.items() if getattr(s, capability))


_LOADED: dict[str, Any] = {}     # "module:attr" -> the object (looked up once: every solve asks)


def _load(ref: Any) -> Any:
    if not isinstance(ref, str):
        return ref
    found = _LOADED.get(ref)
    if found is None:
        mod, _, attr = ref.partition(":")
        found = _LOADED[ref] = getattr(importlib.import_module(mod), attr)
    return found


def available(name: str) -> bool:
    """True when the type's model and solver modules exist."""
    info = TYPES[name]
    if _AVAILABLE.get(name) is info:
        return True
    try:
        _load(info.ref(info.model))
        _load(info.ref(info.solve))
    except (ImportError, AttributeError):
        return False
    _AVAILABLE[name] = info
    return True


_AVAILABLE: dict[str, Any] = {}     # name -> the declaration found available (every problem asks)


def model_class(name: str):
    info = TYPES[name]
    return _load(info.ref(info.model))


def solver(name: str) -> Callable:
    """The type's solver, wrapped so that its :class:`~dyncli.result.Result`
    is checked against the declaration (an undeclared key raises
    :class:`~dyncli.declare.UndeclaredResult`, a bug: exit 3) and gets the
    declared symbols and units."""
    info = TYPES[name]
    fn = _load(info.ref(info.solve))

    def solve(model, options=None):
        from dyncli.cputime import solve_budget

        with solve_budget(getattr(model, "accuracy", None)):
            result = fn(model, options) if options is not None else fn(model)
            if info.motion is not None and getattr(model, "find", None):
                from dyncli.motion_find import resolved

                resolved(model, result, fn, info.motion.get("rates", {}), info.motion.get("fast", ()))
        return info.attach(result)

    solve.__wrapped__ = fn  # type: ignore[attr-defined]  # functools' convention; mypy knows no attributes of a function
    solve.__name__ = getattr(fn, "__name__", "solve")
    return solve


def plots_for(name: str, problem, result) -> list:
    """Plot specs for a solved problem: ``result.plots`` plus whatever the
    type's plots function draws (declared ``plots``, usually
    ``"plots:plots"``: ``dyncli.topics.<topic>.plots:plots(problem, result) -> list[Plot]``),
    imported only for ``--plot``."""
    out = list(result.plots)
    info = TYPES[name]
    if info.plots is None:
        return out
    return out + list(_load(info.ref(info.plots))(problem, result))


def problem_union():
    """The discriminated union (on ``type``) of every registered model."""
    from typing import Annotated, Union

    from pydantic import Field

    models = tuple(model_class(n) for n in TYPES if available(n))
    if len(models) == 1:
        return models[0]
    return Annotated[Union[models], Field(discriminator="type")]
