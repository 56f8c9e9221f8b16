"""The declaration of spin-change, motor-bodies: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


SPIN_CHANGE = TypeSpec(
    name="spin-change",
    numpy_free=True,
    title="spin change of a body whose masses move (H conserved)",
    sections="§36",
    model="model:SpinChange",
    solve="solver:solve_spin_change",
    example="problems/rigid-bodies/spin-change-general.yaml",
    results=[
        R("I_before", "I₁", "kg·m²", "",
          "moment of inertia about the axis before (including I0)", kind="number", contract=True),
        R("I_after", "I₂", "kg·m²", "",
          "moment of inertia about the axis after (including I0)", kind="number", contract=True),
        R("omega", "ω₂", "rad/s", "",
          "angular velocity after", kind="number", contract=True),
        R("H", "H·e", "kg·m²/s", "",
          "conserved angular momentum about the axis, I_before ω₀", kind="number"),
        R("T_before", "T₁", "J", "",
          "kinetic energy before, ½ I₁ ω₁²", kind="number"),
        R("T_after", "T₂", "J", "",
          "kinetic energy after, ½ I₂ ω₂²", kind="number"),
        R("work", "T₂ − T₁", "J", "",
          "T_after − T_before: the work done by the mechanism", kind="number"),
    ],
)

MOTOR_BODIES = TypeSpec(
    name="motor-bodies",
    numpy_free=True,
    title="motor-driven bodies (36.40)",
    sections="§36",
    model="model:MotorBodies",
    solve="solver:solve_motor_bodies",
    example="problems/rigid-bodies/motor-disks.yaml",
    results=[
        R("Omega", "Ω", "rad/s", "36.40",
          "angular velocity of B about e''₂ (36.40)", kind="number", contract=True),
        R("I_axis", "I_axis", "kg·m²", "",
          "IA1 sin²α + (mA L² + IA2) cos²α + IB2", kind="number"),
        R("omega_A", "ω_A", "rad/s", "36.25",
          "ω_A on e'''ᵢ: [Ω sin α + p, Ω cos α, 0] (36.25)", kind="vector"),
    ],
)

TYPES = [SPIN_CHANGE, MOTOR_BODIES]
