"""The declaration of rigid-velocity, angular-velocity, screw, contact: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


RIGID_VELOCITY = TypeSpec(
    name="rigid-velocity",
    numpy_free=True,
    title="velocity and acceleration of points of a rigid body",
    sections="§13",
    model="model:RigidVelocity",
    solve="solver:solve_rigid_velocity",
    example="problems/kinematics/rolling-wheel-points.yaml",
    results=[
        R("v", "v_P", "m/s", "13.8",
          "mapping name → v_P = v_B + ω×x_{P/B} (m/s)", kind="mapping", contract=True),
        R("a", "a_P", "m/s²", "13.9",
          "mapping name → a_P = a_B + ω̇×x_{P/B} + ω×(ω×x_{P/B}) (m/s²)", kind="mapping", contract=True),
        R("omega", "ω", "rad/s", "15.9",
          "with `rolling`: ω = (v_B × x_{C/B})/|x_{C/B}|², from v_C = 0 at the contact; with `rotations`: Σ ω_k (Ω + ω_rel)", kind="vector"),
        R("alpha", "ω̇", "rad/s²", "11.7",
          "with `rolling`: ω̇ = (a_B × x_{C/B})/|x_{C/B}|²; with `rotations`: Σ ω̇_k + Σ W_{k−1} × ω_k (Ω̇ + ω̇_rel + Ω × ω_rel)", kind="vector"),
        R("alpha_coupling", "Ω×ω_rel", "rad/s²", "11.7",
          "with `rotations`: the part of ω̇ from the frames turning the relative spins, Σ W_{k−1} × ω_k (Ω × ω_rel)", kind="vector"),
    ],
)

ANGULAR_VELOCITY = TypeSpec(
    name="angular-velocity",
    numpy_free=True,
    title="angular velocity from the velocities of points",
    sections="§13",
    model="model:AngularVelocity",
    solve="solver:solve_angular_velocity",
    example="problems/kinematics/three-point-omega.yaml",
    results=[
        R("omega", "ω", "rad/s", "",
          "three points: the angular velocity (rad/s), 13.13 — or 13.17 when ω lies in the plane of the points", kind="vector", contract=True),
        R("omega_in_plane", "", "", "13.13, 13.17",
          "three points: true when v_{A/B}·x_{C/B} ≈ 0, i.e. ω lies in the plane of the points and (13.13) is 0/0, so (13.17) applies", kind="bool"),
        R("rigid", "", "", "13.7",
          "the data satisfy v_{P/Q}·x_{P/Q} = 0 (13.7) for every pair within the tolerance below", kind="bool", contract=True),
        R("rigid_residual", "", "", "",
          "max over pairs of |v_{P/Q}·e_{P/Q}| / max(max |v_{P/Q}|, 10⁻⁹·max |v_P|): the rate of change of a distance relative to the largest relative speed (relative speeds below 10⁻⁹ of the absolute speeds are rounding noise of v_P − v_Q); 0 when nothing moves", kind="number"),
        R("omega_n", "ωₙ", "rad/s", "13.20",
          "two points: the part of ω normal to x_{A/B}, (x_{A/B}×v_{A/B})/L² (13.20); the component along the line cannot be found from two points", kind="vector", contract=True),
    ],
)

SCREW = TypeSpec(
    name="screw",
    numpy_free=True,
    title="instantaneous screw axis of a rigid body",
    sections="§14",
    model="model:Screw",
    solve="solver:solve_screw",
    example="problems/kinematics/screw-axis.yaml",
    results=[
        R("e_omega", "e_ω", "", "14.1",
          "ω/|ω|", kind="vector", contract=True),
        R("advance_speed", "v_B·e_ω", "m/s", "14.3",
          "v_B·e_ω, the velocity component shared by all points (m/s)", kind="number", contract=True),
        R("xD", "x_D", "m", "14.7",
          "absolute position of the point D of the axis nearest B: x_B + ω×v_B/ω² (m)", kind="vector", contract=True),
        R("pitch", "pitch", "m/rad", "",
          "advance_speed/|ω| (m/rad)", kind="number", contract=True),
        R("pure_translation", "", "", "",
          "true when ω = 0", kind="bool"),
        R("instant_center", "x_C", "m", "14.9",
          "planar motion (v_B ⟂ ω): the point at rest, x_B + ω×v_B/ω² (m); `null` otherwise", kind="vector", contract=True),
    ],
)

CONTACT = TypeSpec(
    name="contact",
    numpy_free=True,
    title="contact of two bodies: rolling, slipping, separating",
    sections="§15",
    model="model:Contact",
    solve="solver:solve_contact",
    example="problems/kinematics/rolling-disk.yaml",
    results=[
        R("vM1", "v_M'", "m/s", "13.8",
          "velocity of the material point M′ of the first body: v + ω×r", kind="vector", contract=True),
        R("vM2", "v_M''", "m/s", "13.8",
          "velocity of the material point M″ of the second body: v + ω×r", kind="vector", contract=True),
        R("v_rel", "v_M'/M''", "m/s", "15.8",
          "v_{M′/M″} = vM1 − vM2 (m/s)", kind="vector", contract=True),
        R("approach", "v_M'/M''·n", "m/s", "15.8",
          "v_rel·n: > 0 approaching, < 0 separating, 0 maintaining contact (m/s)", kind="number", contract=True),
        R("slip", "slip velocity", "m/s", "",
          "v_rel − (v_rel·n) n, the slip velocity (m/s)", kind="vector", contract=True),
        R("slip_speed", "|slip|", "m/s", "",
          "|slip| (m/s)", kind="number", contract=True),
        R("rolling", "", "", "15.9",
          "true when v_rel = 0: in contact and no slip", kind="bool", contract=True),
        R("state", "", "", "",
          "`rolling`, `slipping` (contact maintained, slip ≠ 0), `separating` (approach < 0) or `approaching` (approach > 0, a warning: bodies in contact would interpenetrate — an impact)", kind="string"),
    ],
)

TYPES = [RIGID_VELOCITY, ANGULAR_VELOCITY, SCREW, CONTACT]
