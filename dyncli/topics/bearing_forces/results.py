"""The declaration of bearing-forces: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


BEARING_FORCES = TypeSpec(
    name="bearing-forces",
    numpy_free=True,
    title="bearing force and moment of spinning arms with a prescribed motion",
    sections="§36",
    model="model:BearingForces",
    solve="solver:solve",
    example="problems/rigid-bodies/bearing-forces.yaml",
    motion={"rates": {"omega": "omega_dot"}, "fast": ["omega"]},
    results=[
        R("omega", "ω", "rad/s", "36.22",
          "the spin ω (prescribed, or from 36.22 for a free shaft)", kind="list", contract=True),
        R("omega_dot", "ω̇", "rad/s²", "36.22",
          "the angular acceleration ω̇ (prescribed, or from 36.22 for a free shaft)", kind="list", contract=True),
        R("I_axis", "Σ m L² sin²α", "kg·m²", "36.21",
          "Σ m L² sin²α, the moment of inertia about the axis", kind="list", contract=True),
        R("G", "G", "kg·m/s", "36.14a",
          "Σ m v", kind="list", contract=True),
        R("H_O", "H_O", "kg·m²/s", "36.14b",
          "Σ x × m v", kind="list", contract=True),
        R("F", "F = Ġ", "N", "36.10, 36.15a",
          "Ġ: the force the bearing applies", kind="list", contract=True),
        R("M_O", "M_O = Ḣ_O", "N·m", "36.11, 36.15b",
          "Ḣ_O: the moment about O (M_O·e'₂ exactly 0 for a free shaft)", kind="list", contract=True),
        R("F1", "F₁", "N", "36.16, 36.18",
          "the bearing's force at x₁ = −h e'₂ (one bearing: without `bearings`)", kind="list", contract=True),
        R("M1", "M₁ = M_O − x₁×F₁", "N·m", "36.16, 36.18",
          "the bearing's moment at x₁ = −h e'₂ (one bearing: without `bearings`)", kind="list", contract=True),
        R("F_A", "F_A", "N", "36.10, 36.11",
          "with `bearings`: the force of bearing A (which also takes the axial load F·e'₂)", kind="list"),
        R("F_B", "F_B", "N", "36.10, 36.11",
          "with `bearings`: the force of bearing B; F_A + F_B = F and y_A e'₂ × F_A + y_B e'₂ × F_B is M_O's part across the shaft", kind="list"),
        R("motor_torque", "M_O·e'₂", "N·m", "36.19",
          "M_O·e'₂: the torque the drive of the shaft supplies (0 when free)", kind="list", contract=True),
        R("T", "T", "J", "27.3",
          "kinetic energy Σ ½ m v·v", kind="list", contract=True),
        R("find", "", "", "", "answers to the `find` queries (§11): {t, reached, at_end, and the state at t}",
          kind="list", contract=True),
    ],
)

TYPES = [BEARING_FORCES]
