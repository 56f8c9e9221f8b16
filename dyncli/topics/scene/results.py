"""The declaration of scene: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec

SCENE = TypeSpec(
    name="scene",
    plots="plots:plots", symbolic=True,
    title="a planar mechanism described, not derived: bodies, joints, cords, pulleys, pegs, gears, with every joint force",
    sections="§16, §29, §32, §34, §36",
    model="model:Scene",
    solve="solver:solve",
    example="problems/scenes/atwood-massive-pulley.yaml",
    results=[
        R("dof", "DOF", "", "", "degrees of freedom, n − rank J (never by counting)", kind="number", contract=True),
        R("coordinates", "s", "", "", "names of the independent coordinates (result paths: angle.rod, x.A.1)",
          kind="list", contract=True),
        R("route", "", "", "", "closed-form, quadrature, ode, kinematics or statics: the cheapest exact route",
          kind="string", contract=True),
        R("t", "t", "s", "", "the requested times", kind="list"),
        R("x", "x̄", "m", "", "each body's centre (list over `at` of [x1, x2, 0])", kind="mapping", contract=True),
        R("v", "v̄", "m/s", "", "each body's centre velocity", kind="mapping", contract=True),
        R("a", "ā", "m/s²", "16.7, 29.5", "each body's centre acceleration", kind="mapping", contract=True),
        R("angle", "θ", "rad", "", "each rigid body's angle of e'1 from e1 (continuous)", kind="mapping",
          contract=True),
        R("omega", "ω", "rad/s", "13.8", "each rigid body's angular velocity [0, 0, ω]", kind="mapping",
          contract=True),
        R("alpha", "α", "rad/s²", "32.15", "each rigid body's angular acceleration [0, 0, α]", kind="mapping",
          contract=True),
        R("point", "", "", "13.8, 14.8", "each named point's x, v, a (point.BODY.POINT.x)", kind="mapping",
          contract=True),
        R("reaction", "", "N", "16.7, 29.5, 32.15", "each joint's forces on its first-named body by the second "
          "(pin R; slider N, M; contact N, F; rolls N, F, slip_margin; cord T per segment; link T)",
          kind="mapping", contract=True),
        R("drive", "", "", "", "each drive's force [N] or couple [N·m] that the driver applies", kind="mapping",
          contract=True),
        R("force", "", "N", "", "each named load: spring and damper tension, force vector, couple", kind="mapping",
          contract=True),
        R("T", "T", "J", "34.13", "kinetic energy", kind="list", contract=True),
        R("V", "V", "J", "34.20", "potential energy of gravity (0 at x2 = 0) and the springs", kind="list",
          contract=True),
        R("E", "E = T + V", "J", "34.20", "total energy", kind="list", contract=True),
        R("W_nc", "W_nc", "J", "34.20", "work of the non-conservative loads, drives and friction since t = 0",
          kind="list", contract=True),
        R("energy_residual", "E − E₁ − W_nc", "J", "34.20", "the energy balance's residual (an accuracy check)",
          kind="list", contract=True),
        R("events", "", "", "", "one-sided joints: {t, joint, what, state}, what = separates, slack, slips, sticks, "
          "leaves, impact, taut, rests", kind="list", contract=True),
        R("phases", "", "", "", "the motion's phases in order: {t_start, t_end, joints (those made), route, integrals (the names of "
          "the first integrals that hold through it: E, G.0, G.1)}",
          kind="list", contract=True),
        R("impacts", "", "", "28.7, 28.16, 33.2", "each impact: {t, joint, e, impulse (normal, or the cord's "
          "impulsive tension) [N·s], energy_loss [J], impulse_F, v_n_before, v_n_after, slip_before, slip_after "
          "(the point's speed along d̂ [m/s]; a cord: null), course (the slip through the impact, Routh's method: "
          "smooth, sticks, slides, slides, then sticks, slides, then slides back, ...; a cord: null)}", kind="list",
          contract=True),
        R("integrals", "", "", "34.20, 36.10", "first integrals that hold: {name, value, drift, equation}",
          kind="list", contract=True),
        R("equilibria", "", "", "", "`linearize: true`: each rest configuration {coordinates (names), values, x, "
          "angle, V, reaction, stability (stable, unstable, neutral), stable, omega2 [1/s²], frequencies [rad/s], "
          "frequencies_hz, modes (first non-zero component 1), M, K (C, damped), response}", kind="list",
          contract=True),
        R("distance", "", "m", "", "each body's path length since t = 0 (its centre of mass), ∫|v| dt, per body over `at` "
          "(null after the motion stops at the cap on phases)", kind="mapping", contract=True),
        R("find", "", "", "", "answers to the `find` queries (§11): {t, reached, at_end, and the state}",
          kind="list", contract=True),
    ],
)

TYPES = [SCENE]
