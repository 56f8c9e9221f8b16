"""The declaration of pendulum: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec

PENDULUM = TypeSpec(
    name="pendulum",
    plots="plots:plots",
    title="simple pendulum at any amplitude: exact period, swing, rotation, separatrix",
    sections="§16, §20",
    model="model:Pendulum",
    solve="solver:solve",
    example="problems/particle/pendulum.yaml",
    gallery="a pendulum released at 120°: the exact period 4√(l/g) K(k²) = 2.75409 s against the small-angle "
            "2π√(l/g), θ(t) by Jacobi's sn, the rod's tension; the same pendulum over the top, and on the "
            "separatrix (no period).",
    results=[
        R("omega_n", "ωₙ", "rad/s", "", "small-angle frequency √(g/l)", kind="number", contract=True),
        R("period_small", "T₀", "s", "", "small-angle period 2π√(l/g)", kind="number", contract=True),
        R("regime", "", "", "",
          "`rest`, `swing` (k < 1), `separatrix` (k = 1: no period) or `rotating` (k > 1, over the top)",
          kind="string", contract=True),
        R("k", "k", "", "",
          "√(E/(2mgl)) = √(sin²(θ₀/2) + (θ̇₀/2ωₙ)²): the elliptic modulus of a swing, 1/modulus of a rotation",
          kind="number", contract=True),
        R("period", "T", "s", "",
          "exact period: 4K(k²)/ωₙ (swing), 2K(1/k²)/(kωₙ) for one turn (rotating); null on the separatrix",
          kind="number", contract=True),
        R("period_ratio", "T/T₀", "", "", "the exact period over the small-angle one", kind="number", contract=True),
        R("theta_max", "θ_max", "rad", "", "swing: the amplitude 2 arcsin k", kind="number", contract=True),
        R("theta_slack", "θ_slack", "rad", "",
          "|θ| where the tension vanishes (a string would go slack there); null when it stays positive",
          kind="number", contract=True),
        R("E", "E", "J", "20.5", "with m: the energy ½ml²θ̇² + mgl(1 − cos θ) = 2mglk²",
          kind="number", contract=True),
        R("theta", "θ", "rad", "", "with `at`: θ at each time (from the downward vertical; unwrapped over the top)",
          kind="list", contract=True),
        R("theta_dot", "θ̇", "rad/s", "", "with `at`: θ̇ at each time", kind="list", contract=True),
        R("theta_ddot", "θ̈", "rad/s²", "", "with `at`: θ̈ = −(g/l) sin θ at each time", kind="list", contract=True),
        R("tension", "T_rod", "N", "", "with `at` and m: the rod's pull m(lθ̇² + g cos θ) (negative: compression)",
          kind="list", contract=True),
        R("distance", "", "m", "", "with `at`: the path of the bob since t = 0, l∫|θ̇| dt (exact: turning points "
          "in closed form)", kind="list", contract=True),
        R("find", "", "", "", "answers to the `find` queries (§11): {t, reached, at_end, theta, theta_dot, "
          "theta_ddot, tension, distance}", kind="list", contract=True),
    ],
)

TYPES = [PENDULUM]
