"""The declaration of kinematics: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


KINEMATICS = TypeSpec(
    name="kinematics",
    symbolic=True,
    title="path, tangential-normal and curvilinear coordinates",
    sections="§4, §5, §7, §8, §12",
    model="model:Kinematics",
    solve="solver:solve",
    example="problems/kinematics/helix-cylindrical.yaml",
    results=[
        R("x", "x", "m", "",
          "position, Cartesian components", kind="list|vector", contract=True),
        R("v", "v", "m/s", "",
          "velocity, Cartesian components", kind="list|vector", contract=True),
        R("a", "a", "m/s²", "",
          "acceleration, Cartesian components", kind="list|vector", contract=True),
        R("v_basis", "v (own basis)", "m/s", "",
          "velocity on the coordinates' own basis, always 3 components: (e1, e2, e3), (e_r, e_θ, e3) — polar has a zero third —, (e_R, e_θ, e_φ); on a path (e_t, e_n, e_b)", kind="list|vector", contract=True),
        R("a_basis", "a (own basis)", "m/s²", "",
          "acceleration on the coordinates' own basis, always 3 components (as `v_basis`)", kind="list|vector", contract=True),
        R("speed", "|v|", "m/s", "",
          "|v| = ṡ", kind="list|number", contract=True),
        R("a_t", "a_t", "m/s²", "5.14b",
          "tangential acceleration s̈ = a·e_t", kind="list|number", contract=True),
        R("a_n", "a_n", "m/s²", "5.14b",
          "normal acceleration ṡ²/ρ = |v×a|/|v| ≥ 0", kind="list|number", contract=True),
        R("rho", "ρ", "m", "5.5",
          "radius of curvature |v|³/|v×a| (5.5); `null` where the curvature vanishes", kind="list|number", contract=True),
        R("e_t", "e_t", "", "5.3",
          "unit tangent v/|v|, Cartesian", kind="list|vector", contract=True),
        R("e_n", "e_n", "", "5.5",
          "principal normal, toward the center of curvature, Cartesian", kind="list|vector", contract=True),
        R("F", "F = m a", "N", "",
          "with `m`: the force m·a, Cartesian components", kind="list|vector", contract=True),
        R("F_basis", "F (own basis)", "N", "",
          "with `m`: the force m·a on the coordinates' own basis", kind="list|vector", contract=True),
        R("distance", "D₂/₁", "m", "4.5",
          "D = ∫|v| dt over `distance` (4.5), a scalar", kind="number", contract=True),
    ],
)

TYPES = [KINEMATICS]
