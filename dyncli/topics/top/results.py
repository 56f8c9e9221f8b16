"""The declaration of top: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


TOP = TypeSpec(
    name="top",
    plots="plots:plots", numpy_free=True, symbolic=True, exact=True,
    title="the heavy symmetric top: nutation and reactions",
    sections="§38",
    model="model:Top",
    solve="solver:solve",
    example="problems/gyroscopic/top-near-vertical.yaml",
    motion={"rates": {"psi": "psi_dot", "theta": "theta_dot", "phi": "phi_dot"}, "fast": ["psi_dot", "theta_dot", "phi_dot"]},
    results=[
        R("theta_min", "θ_min", "rad", "",
          "lower turning point of the nutation, from the energy and momentum integrals", kind="number", contract=True),
        R("theta_max", "θ_max", "rad", "",
          "upper turning point of the nutation, from the energy and momentum integrals", kind="number", contract=True),
        R("invariants", "", "", "",
          "`{E, H_e3, omega3}`: the three conserved quantities from the initial state", kind="mapping"),
        R("psi", "ψ", "rad", "",
          "Euler angle ψ at each time in `at`, continuous (not wrapped to ±π)", kind="list", contract=True),
        R("theta", "θ", "rad", "",
          "Euler angle θ at each time in `at`, in [0, π]", kind="list", contract=True),
        R("phi", "φ", "rad", "",
          "Euler angle φ at each time in `at`, continuous (not wrapped to ±π)", kind="list", contract=True),
        R("psi_dot", "ψ̇", "rad/s", "",
          "ψ̇ at each time; null where sinθ = 0 exactly (only ψ̇ ± φ̇ exists there)", kind="list", contract=True),
        R("theta_dot", "θ̇", "rad/s", "",
          "θ̇ at each time", kind="list", contract=True),
        R("phi_dot", "φ̇", "rad/s", "",
          "φ̇ at each time; null where sinθ = 0 exactly (only ψ̇ ± φ̇ exists there)", kind="list", contract=True),
        R("R", "", "N", "38.16a",
          "list of vectors: reaction at O on e'' (38.16a): R = mg e3 + m ā", kind="list", contract=True),
        R("drift", "", "", "",
          "largest relative change over the run of E, H_O·e3 and ω3 (below)", kind="number", contract=True),
        R("find", "", "", "", "answers to the `find` queries (§11): {t, reached, at_end, and the state at t}",
          kind="list", contract=True),
    ],
)

TYPES = [TOP]
