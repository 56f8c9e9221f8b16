"""Input model of ``inertia`` problems (docs/types/inertia.md)."""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, field_validator, model_validator

from dyncli.fields import Matrix, Num, ProblemBase, StrictModel, Tensor3, Vec3, Vector
from dyncli.topics.inertia.eigen3 import inertia_defect

#: the fields each shape needs (all others are rejected)
SHAPE_FIELDS: dict[str, tuple[str, ...]] = {
    "point": (),
    "rod": ("length",),
    "box": ("size",),
    "cylinder": ("radius", "height"),
    "disk": ("radius",),
    "ring": ("radius",),
    "sphere": ("radius",),
    "shell": ("radius",),
    "tensor": ("inertia",),
}
GEOMETRY_FIELDS = ("length", "size", "radius", "height", "inertia")


def check_psd(T) -> None:
    """ValueError unless the symmetric tensor T is positive-semidefinite."""
    lo, _tri, scale = inertia_defect(T)       # plain floats (Jacobi): no numpy
    if lo < -1e-12 * max(scale, 1e-300):
        raise ValueError(
            f"not positive-semidefinite (smallest principal moment {lo:.6g}): "
            "it is not an inertia tensor (no mass distribution has it)")


class Orientation(StrictModel):
    """A rotation: exactly one of {axis, angle}, {euler313: [psi, theta, phi]}
    (the notes' 3-1-3 sequence, §38) or {matrix: R} (columns = the rotated
    axes in body components; must be orthonormal with det +1)."""

    axis: Optional[Annotated[Vector, Vec3(nonzero=True, description="rotation axis (body components; normalised)")]] = None
    angle: Optional[Annotated[float, Num(dim="angle", description="rotation angle [rad], right-handed about axis")]] = None
    euler313: Optional[Annotated[Vector, Vec3(dim="angle", description="[psi, theta, phi] [rad]: psi about e3, theta about e'''1, phi about e''3")]] = None
    matrix: Optional[Annotated[Matrix, Tensor3(description="3x3 rotation; its columns are the rotated axes in body components")]] = None

    @model_validator(mode="after")
    def _check(self):
        from dyncli.topics.inertia import rotations

        rotations.from_fields(self.axis, self.angle, self.euler313, self.matrix)  # ValueError -> exit 2
        return self


class Part(StrictModel):
    """One part of a composite body: a standard shape about its own center
    of mass, placed at ``at`` and turned by ``orientation``."""

    shape: Literal["point", "rod", "box", "cylinder", "disk", "ring", "sphere", "shell", "tensor"]
    mass: Annotated[float, Num(gt=0, dim="mass", description="mass of the part [kg] (positive, also for a hole)")]
    at: Annotated[Vector, Vec3(dim="length", description="position of the part's center of mass [m] (body components)")] = (0.0, 0.0, 0.0)
    orientation: Optional[Orientation] = Field(None, description="orientation of the part's axes relative to the body axes")
    hole: bool = Field(False, description="true: subtract this part (a hole or cut-out)")
    length: Optional[Annotated[float, Num(ge=0, dim="length", description="rod: length along the part's e3 [m]")]] = None
    size: Optional[Annotated[Vector, Vec3(dim="length", description="box: edge lengths [a, b, c] along the part's e1, e2, e3 [m]")]] = None
    radius: Optional[Annotated[float, Num(ge=0, dim="length", description="cylinder, disk, ring, sphere, shell: radius [m]")]] = None
    height: Optional[Annotated[float, Num(ge=0, dim="length", description="cylinder: height along the part's e3 [m]")]] = None
    inertia: Optional[Annotated[Matrix, Tensor3(symmetric=True, dim="moment of inertia", description="tensor: 3x3 inertia about the part's center of mass, part axes [kg m²]")]] = None

    @model_validator(mode="after")
    def _geometry(self):
        need = SHAPE_FIELDS[self.shape]
        missing = [f for f in need if getattr(self, f) is None]
        if missing:
            raise ValueError(f"shape '{self.shape}' needs {' and '.join(repr(f) for f in missing)}")
        extra = [f for f in GEOMETRY_FIELDS if f not in need and getattr(self, f) is not None]
        if extra:
            takes = f"it takes {', '.join(repr(f) for f in need)}" if need else "it takes no dimensions"
            raise ValueError(f"{', '.join(repr(f) for f in extra)} does not apply to shape '{self.shape}' ({takes})")
        if self.size is not None and any(c < 0 for c in self.size):
            raise ValueError(f"box size must have non-negative edge lengths, got {list(self.size)}")
        return self

    @field_validator("inertia")
    @classmethod
    def _psd(cls, v):
        if v is not None:
            check_psd(v)
        return v


class Inertia(ProblemBase):
    """Inertia tensor of a composite body (notes §30, §31, §35)."""

    type: Literal["inertia"]
    parts: list[Part] = Field(..., min_length=1, description="the parts of the body")
    about: Optional[Annotated[Vector, Vec3(dim="length", description="point B [m] (body components) for I_about")]] = None
    basis: Optional[Orientation] = Field(None, description="express every result on this basis (columns = new axes e''_i in body components)")
    omega: Optional[Annotated[Vector, Vec3(dim="angular velocity", description="angular velocity ω'_i on the body axes e'_i [rad/s]: adds its components on the basis (35.6) and H̄ (35.3, 35.4)")]] = None
