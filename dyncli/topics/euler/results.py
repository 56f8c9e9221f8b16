"""The declaration of euler: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


EULER = TypeSpec(
    name="euler",
    plots="plots:plots", numpy_free=True,
    title="Euler's equations, the torque-free body",
    sections="§39",
    model="model:Euler",
    solve="solver:solve",
    example="problems/gyroscopic/euler-flipping-coin.yaml",
    motion={"rates": {}, "fast": ["omega"]},
    results=[
        R("I", "I (principal)", "kg·m²", "",
          "with `coin`: the principal moments used", kind="vector"),
        R("omega", "ω' (body)", "rad/s", "",
          "ω' (body components) at the `at` times", kind="list", contract=True),
        R("H", "|H̄|", "kg·m²/s", "",
          "|H̄|, the magnitude of the angular momentum (initial value; conserved when torque-free)", kind="number", contract=True),
        R("T", "T", "J", "",
          "the kinetic energy (initial value; conserved when torque-free)", kind="number", contract=True),
        R("lambda", "λ (39.15)", "rad/s", "39.15",
          "axisymmetric body: λ", kind="number", contract=True),
        R("psi_dot", "ψ̇ (39.20)", "rad/s", "39.20",
          "axisymmetric body: precession rate ψ̇ of the symmetry axis about H̄", kind="number", contract=True),
        R("theta", "θ (39.21)", "rad", "39.21",
          "axisymmetric body: nutation angle θ of the symmetry axis from H̄", kind="number", contract=True),
        R("symmetry_axis", "symmetry axis", "", "39.15",
          "axisymmetric body: the number of the axis with the distinct moment", kind="number"),
        R("drift", "drift", "", "",
          "largest relative change of |H| and T (torque-free), or the error of the balances T − T₀ = ∫M·ω dt and |H|² − H₀² = ∫2H̄·M̄ dt (with M)", kind="number", contract=True),
        R("drift_detail", "", "", "",
          "the parts of `drift`: each conserved quantity or balance and its error", kind="mapping"),
        R("m", "m = k²", "", "",
          "asymmetric torque-free body: the elliptic parameter k²", kind="number"),
        R("period", "period of ω", "s", "",
          "asymmetric torque-free body: the period 4K/|λ| of ω (null on the separatrix)", kind="number"),
        R("H_t", "|H̄|(t)", "kg·m²/s", "",
          "with M: |H̄| at the `at` times", example=False),
        R("T_t", "T(t)", "J", "",
          "with M: the kinetic energy T at the `at` times", example=False),
        R("find", "", "", "", "answers to the `find` queries (§11): {t, reached, at_end, and the state at t}",
          kind="list", contract=True),
    ],
)

TYPES = [EULER]
