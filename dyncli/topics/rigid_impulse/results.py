"""The declaration of rigid-impulse: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


RIGID_IMPULSE = TypeSpec(
    name="rigid-impulse",
    numpy_free=True,
    title="impulse on a rigid body, center of percussion",
    sections="§33",
    model="model:RigidImpulse",
    solve="solver:solve",
    example="problems/impact/struck-bar.yaml",
    results=[
        R("v2", "v̄₂", "m/s", "33.5",
          "[R/m, 0, 0]", kind="vector", contract=True),
        R("omega2", "ω₂", "rad/s", "33.6, 33.7, 33.8",
          "[0, 0, h R/(m k²)], from M̂ = x₁ × R̂ = h R e'₃ = Ī ω₂", kind="vector", contract=True),
        R("percussion", "p", "m", "33.10",
          "[0, k²/h, 0], relative to the center of mass; null with a warning when h = 0 (pure translation)", kind="vector", contract=True),
        R("I_bar", "Ī", "kg·m²", "",
          "Ī = m k², the moment of inertia about the center of mass", kind="number"),
        R("v_point", "v(x₁)", "m/s", "33.9",
          "velocity of the struck point, v̄₂ + ω₂ × x₁", kind="vector"),
        R("T2", "T₂", "J", "",
          "kinetic energy after, ½ m v̄₂² + ½ Ī ω₂²", kind="number"),
    ],
)

TYPES = [RIGID_IMPULSE]
