"""The declaration of gyroscope: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


GYROSCOPE = TypeSpec(
    name="gyroscope",
    plots="plots:plots", numpy_free=True, exact=True,
    title="the gyroscope of §37: θ(t) and moments",
    sections="§37",
    model="model:Gyroscope",
    solve="solver:solve",
    example="problems/gyroscopic/gyroscope-0-to-pi.yaml",
    motion={"rates": {"theta": "theta_dot"}, "fast": ["theta_dot"]},
    results=[
        R("theta", "θ", "rad", "37.12",
          "θ at the `at` times (continuous, not wrapped)", kind="list", contract=True),
        R("theta_dot", "θ̇", "rad/s", "37.12",
          "θ̇ at the `at` times", kind="list", contract=True),
        R("M", "M̄ (e'')", "N·m", "37.11",
          "moment M̄ = Ḣ on e'' at the `at` times (Table 37.1); its e''₃ part is 0 (37.11)", kind="list", contract=True),
        R("theta_min", "θ_min", "rad", "37.13",
          "lower turning point of θ from (37.13); null when θ circulates", kind="number", contract=True),
        R("theta_max", "θ_max", "rad", "37.13",
          "upper turning point of θ from (37.13); null when θ circulates", kind="number", contract=True),
        R("C", "C (37.13)", "J", "37.13",
          "the constant of (37.13)", kind="number"),
        R("drift", "drift", "", "",
          "largest change of C over the run, relative to ½Ī₂θ̇₀² + ½", kind="number"),
        R("find", "", "", "", "answers to the `find` queries (§11): {t, reached, at_end, and the state at t}",
          kind="list", contract=True),
    ],
)

TYPES = [GYROSCOPE]
