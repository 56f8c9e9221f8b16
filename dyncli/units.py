"""Units in problem files (docs/units.md).

A numeric field may be written ``"200 N/m"``, ``"1500 rpm"``, ``"30 deg"``,
``"3 kg*m^2"``, ``"10 lbf"``: a number, then a unit.  The value is checked
against the field's declared dimension (``Num(dim="stiffness")``) and
converted to SI.  pint is imported only when such a string is met: a string
is first read as a constant expression (``"30*deg"``, ``"sqrt(k/m)"``), and
only when that fails and it has the shape *number unit* is it read as a
quantity.  Files without unit strings never import pint.

``params`` may carry units too; they are converted to SI (base units) and
then used as plain numbers in expressions (expressions themselves are
dimensionless arithmetic on SI values).
"""

from __future__ import annotations

import math
import re
from functools import lru_cache

# name -> (pint dimensionality, SI unit shown to users, noun for messages)
DIMENSIONS: dict[str, tuple[str, str, str]] = {
    "dimensionless": ("", "", "a dimensionless number"),
    "mass": ("[mass]", "kg", "a mass"),
    "length": ("[length]", "m", "a length"),
    "time": ("[time]", "s", "a time"),
    "velocity": ("[length]/[time]", "m/s", "a velocity"),
    "acceleration": ("[length]/[time]**2", "m/s²", "an acceleration"),
    "force": ("[mass]*[length]/[time]**2", "N", "a force"),
    "stiffness": ("[mass]/[time]**2", "N/m", "a stiffness"),
    "damping": ("[mass]/[time]", "N·s/m", "a damping coefficient"),
    "angle": ("", "rad", "an angle"),
    "angular_velocity": ("1/[time]", "rad/s", "an angular velocity"),
    "frequency": ("1/[time]", "rad/s", "a frequency"),
    "angular_acceleration": ("1/[time]**2", "rad/s²", "an angular acceleration"),
    "inertia": ("[mass]*[length]**2", "kg·m²", "a moment of inertia"),
    "energy": ("[mass]*[length]**2/[time]**2", "J", "an energy"),
    "work": ("[mass]*[length]**2/[time]**2", "J", "a work"),
    "power": ("[mass]*[length]**2/[time]**3", "W", "a power"),
    "moment": ("[mass]*[length]**2/[time]**2", "N·m", "a moment"),
    "torque": ("[mass]*[length]**2/[time]**2", "N·m", "a moment"),
    "momentum": ("[mass]*[length]/[time]", "N·s", "a momentum"),
    "impulse": ("[mass]*[length]/[time]", "N·s", "an impulse"),
    "angular_momentum": ("[mass]*[length]**2/[time]", "kg·m²/s", "an angular momentum"),
    "area": ("[length]**2", "m²", "an area"),
    "volume": ("[length]**3", "m³", "a volume"),
    "density": ("[mass]/[length]**3", "kg/m³", "a density"),
    "pressure": ("[mass]/[length]/[time]**2", "Pa", "a pressure"),
}

#: units a result may be declared in besides the SI units of :data:`DIMENSIONS` (composites that
#: name no field dimension); every declared result unit is one of :data:`RESULT_UNITS`, checked when
#: the declaration is built (:class:`dyncli.declare.TypeSpec`), so ``--units`` can convert it
EXTRA_RESULT_UNITS: dict[str, str] = {
    "m/rad": "a screw's pitch (length per radian)",
    "1/m": "a curvature",
    "m²/s": "an angular momentum per unit mass (r² θ̇)",
    "kg·m/s": "a linear momentum (= N·s)",
}
RESULT_UNITS = frozenset({v[1] for v in DIMENSIONS.values() if v[1]} | set(EXTRA_RESULT_UNITS))

_ALIASES = {"angular_rate": "angular_velocity", "rate": "angular_velocity", "spin": "angular_velocity",
            "moment_of_inertia": "inertia", "rotational_inertia": "inertia", "distance": "length",
            "position": "length", "speed": "velocity", "ratio": "dimensionless", "coefficient": "dimensionless"}

# a number, then a unit; the look-ahead keeps a number's exponent out of the
# unit ("1e308*10" is an expression that overflows, not 1 of the unit "e308*10")
QUANTITY = re.compile(
    r"^\s*(?P<num>[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?)(?![eE][-+]?\d)\s*"
    r"(?P<unit>(?:1\s*/\s*)?[A-Za-z°µΩ][A-Za-z0-9_°µΩ\s*/^().·²³-]*)$"     # (a unit may be 1/s: per second)
)
MAX_UNIT_TEXT = 80


class UnknownDimension(ValueError):
    """A field declares a dimension this module does not know (a bug in a model: raised when the
    model class is built, naming the type and the field; never a user's error)."""


def normalise_dim(dim: str | None) -> str | None:
    """The name of ``dim`` in :data:`DIMENSIONS` (``"angular velocity"`` -> ``"angular_velocity"``,
    aliases resolved); None for no dimension.  Raises :class:`UnknownDimension` for a name that is
    neither a dimension nor an alias: a misspelt dimension would otherwise turn the check off."""
    if not dim:
        return None
    d = dim.strip().lower().replace(" ", "_").replace("-", "_")
    d = _ALIASES.get(d, d)
    if d not in DIMENSIONS:
        import difflib

        near = difflib.get_close_matches(d, list(DIMENSIONS) + list(_ALIASES), n=1)
        hint = f" (did you mean {near[0]!r}?)" if near else ""
        raise UnknownDimension(f"unknown dimension {dim!r}{hint}; known: {', '.join(DIMENSIONS)}")
    return d


def si_unit(dim: str | None) -> str:
    """The SI unit users see for ``dim`` ("" for none or dimensionless); an unknown dimension raises."""
    d = normalise_dim(dim)
    return DIMENSIONS[d][1] if d else ""


def looks_like_quantity(text: str) -> bool:
    if len(text) > 4000:       # the number may be long (a 401-digit integer is "too large"), not unbounded
        return False
    m = QUANTITY.match(text)
    return m is not None and len(m.group("unit")) <= MAX_UNIT_TEXT


class UnitError(ValueError):
    pass


@lru_cache(maxsize=1)
def registry():
    import pint

    # pint parses its definitions file on every start (~0.3 s); with
    # cache_folder=":auto:" it keeps the parsed registry in the user's cache
    # directory (validated against the definitions' hash) and starts in ~0.04 s.
    # A cache that cannot be read or written only costs the parse.
    try:
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except Exception:  # noqa: BLE001 - any cache problem: build it without the cache
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True)


# Hz counts cycles per second: for an angular rate (a field or result in rad/s) 1 Hz is
# 2π rad/s, as 1 rpm is 2π/60 rad/s; pint's Hz is a bare 1/s, which would read "5 Hz"
# as 5 rad/s without a word.
_HZ = re.compile(r"(?<![A-Za-z])([kMGTmunµ]?)Hz(?![A-Za-z])")


def is_angular(unit_text: str | None) -> bool:
    """True for an SI unit of an angular quantity (rad, rad/s, rad/s²)."""
    return unit_text is not None and "rad" in unit_text


def clean_unit(unit: str, angular: bool = False) -> str:
    """A unit text as pint reads it (``m/s²`` -> ``m/s**2``; ``angular``: Hz as cycles per second)."""
    if angular:
        unit = _HZ.sub(r"(\1cycle/second)", unit)
    return (unit.replace("²", "**2").replace("³", "**3").replace("·", "*").replace("^", "**")
            .replace("°", "degree ").strip())



def parse_quantity(text: str, dim: str | None = None) -> float:
    """``"200 N/m"`` -> 200.0 (SI), checked against ``dim``.  Raises UnitError."""
    m = QUANTITY.match(text)
    if not m:
        raise UnitError(f"{text!r} is neither an expression nor a number with a unit")
    num = float(m.group("num"))
    if not math.isfinite(num):
        raise UnitError(f"number {m.group('num')[:40]!r} is too large")
    unit_text = m.group("unit").strip()
    if len(unit_text) > MAX_UNIT_TEXT:
        raise UnitError("unit is too long")
    ureg = registry()
    import pint

    d = normalise_dim(dim)
    try:
        unit = ureg.parse_units(clean_unit(unit_text, angular=d is not None and is_angular(DIMENSIONS[d][1])))
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError, AttributeError,
            TypeError, ValueError, SyntaxError, KeyError) as exc:
        name = getattr(exc, "unit_names", None) or unit_text
        if isinstance(name, (list, tuple)):
            name = name[0] if name else unit_text
        raise UnitError(f"unknown unit {name!r} in {text!r}") from None
    except Exception:  # noqa: BLE001 - pint raises assorted errors on garbage
        raise UnitError(f"cannot read the unit {unit_text!r} in {text!r}") from None
    q = ureg.Quantity(num, unit)
    if d is not None:
        want, si, noun = DIMENSIONS[d]
        want_dim = ureg.get_dimensionality(want) if want else ureg.get_dimensionality("")
        if q.dimensionality != want_dim:
            shown = f"{m.group('num')} {unit_text}"
            raise UnitError(f"expected {noun}" + (f" ({si})" if si else "") + f", got {shown}")
    try:
        base = q.to_base_units()
    except Exception:  # noqa: BLE001
        raise UnitError(f"cannot convert {text!r} to SI") from None
    return float(base.magnitude)


def display_factor(si_unit_text: str, wanted: list[str]) -> tuple[float, str] | None:
    """For ``--units``: the first unit in ``wanted`` compatible with
    ``si_unit_text``, as (factor SI -> wanted, wanted).  None if none fits."""
    if not si_unit_text or not wanted:
        return None
    ureg = registry()
    try:
        src = ureg.Quantity(1.0, ureg.parse_units(clean_unit(si_unit_text)))
    except Exception:  # noqa: BLE001
        return None
    for w in wanted:
        try:
            tgt = ureg.parse_units(clean_unit(w, angular=is_angular(si_unit_text)))
        except Exception:  # noqa: BLE001
            continue
        if src.dimensionality == ureg.Quantity(1.0, tgt).dimensionality:
            # angles: only convert quantities that are angles (rad), not plain numbers
            if src.dimensionless and "rad" not in si_unit_text and "rev" not in w and "deg" not in w:
                continue
            if src.dimensionless and "rad" not in si_unit_text:
                continue
            return float(src.to(tgt).magnitude), w
    return None
