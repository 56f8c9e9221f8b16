"""The declaration of inertia: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


INERTIA = TypeSpec(
    name="inertia",
    numpy_free=True,
    title="inertia tensors, composite bodies, principal axes",
    sections="§30, §31, §35",
    model="model:Inertia",
    solve="solver:solve",
    example="problems/inertia/box-about-corner.yaml",
    results=[
        R("mass", "m", "kg", "",
          "total mass (holes subtracted)", kind="number", contract=True),
        R("com", "x̄", "m", "",
          "center of mass", kind="vector", contract=True),
        R("I_com", "Ī", "kg·m²", "",
          "Ī, about the center of mass", kind="tensor", contract=True),
        R("I_about", "I_B", "kg·m²", "31.7",
          "I_B (31.7); equals `I_com` without `about`", kind="tensor", contract=True),
        R("principal_moments", "I₁ ≤ I₂ ≤ I₃", "kg·m²", "",
          "eigenvalues of `I_about`, ascending", kind="vector", contract=True),
        R("principal_axes", "[e₁* e₂* e₃*]", "", "",
          "3×3, column k = unit principal direction of moment k; a proper rotation (right-handed)", kind="tensor", contract=True),
        R("radii_of_gyration", "k", "m", "30.8",
          "sqrt(Iₖ/m) (30.8); 0 for a zero moment", kind="vector", contract=True),
        R("p_bar", "p̄", "m", "",
          "p̄ = x̄ − x_B", kind="vector"),
        R("I_transfer", "m[(p̄·p̄)1 − p̄⊗p̄]", "kg·m²", "",
          "m[(p̄·p̄)1 − p̄⊗p̄]", kind="tensor"),
        R("principal_gap", "min ΔI", "kg·m²", "",
          "smallest difference between consecutive principal moments", kind="number"),
        R("principal_axes_unique", "", "", "",
          "false when moments are repeated", kind="bool"),
        R("principal_axes_note", "", "", "",
          "which axes are arbitrary (any orthonormal basis of the eigenspace is valid)", kind="string"),
        R("omega_body", "ω'ᵢ", "rad/s", "",
          "ω'ᵢ as given", kind="vector", contract=True),
        R("omega_basis", "ω''ᵢ = Aᵢⱼω'ⱼ", "rad/s", "35.6a",
          "ω''ᵢ = Aᵢⱼ ω'ⱼ (35.6a), the components on `basis` (= `omega_body` without a basis)", kind="vector", contract=True),
        R("A", "Aᵢⱼ = e''ᵢ·e'ⱼ", "", "35.5a",
          "Aᵢⱼ = e''ᵢ·e'ⱼ (35.5a): row i is e''ᵢ in body components (the transpose of the `basis` matrix)", kind="tensor", contract=True),
        R("H_com_body", "Ī'ᵢⱼω'ⱼ", "kg·m²/s", "35.3",
          "H̄ = Ī'ᵢⱼ ω'ⱼ e'ᵢ on the body axes (35.3)", kind="vector", contract=True),
        R("H_com", "Ī''ᵢⱼω''ⱼ", "kg·m²/s", "",
          "the same vector on e''ᵢ, Ī''ᵢⱼ ω''ⱼ (35.4, 35.7): `A` · `H_com_body`", kind="vector", contract=True),
        R("H_about", "I''_Bᵢⱼω''ⱼ", "kg·m²/s", "",
          "I''_B ω'' on e''ᵢ: the angular momentum about B when B is a fixed point of the body", kind="vector", contract=True),
    ],
)

TYPES = [INERTIA]
