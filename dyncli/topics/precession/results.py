"""The declaration of precession: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


PRECESSION = TypeSpec(
    name="precession",
    numpy_free=True,
    title="steady precession of a top",
    sections="§38",
    model="model:Precession",
    solve="solver:solve",
    example="problems/gyroscopic/precession-below-pmin.yaml",
    results=[
        R("exists", "exists", "", "",
          "a real steady precession exists", kind="bool", contract=True),
        R("Omega_slow", "Ω_slow", "rad/s", "38.22",
          "the root of (38.22) of smaller magnitude (slow precession)", kind="number", contract=True),
        R("Omega_fast", "Ω_fast", "rad/s", "38.22",
          "the root of (38.22) of larger magnitude (fast precession)", kind="number", contract=True),
        R("p_min", "p_min", "rad/s", "38.24",
          "minimum spin (38.24); 0 when no minimum applies (I11 ≤ I33 at cos θ > 0, …)", kind="number", contract=True),
        R("Omega_slow_approx", "Ω₁ (38.27a)", "rad/s", "38.27a",
          "large-spin approximation of the slow root", kind="number", contract=True),
        R("Omega_fast_approx", "Ω₂ (38.27b)", "rad/s", "38.27b",
          "large-spin approximation of the fast root", kind="number", contract=True),
        R("stable_slow", "stable (slow)", "", "",
          "small perturbations of the slow precession stay bounded (null when the root is)", kind="bool", contract=True),
        R("nutation_freq_slow", "ν (slow)", "rad/s", "",
          "ν, the frequency of small nutation about the slow precession", kind="number", contract=True),
        R("stable_fast", "stable (fast)", "", "",
          "small perturbations of the fast precession stay bounded (null when the root is)", kind="bool", contract=True),
        R("nutation_freq_fast", "ν (fast)", "rad/s", "",
          "ν, the frequency of small nutation about the fast precession", kind="number", contract=True),
        R("R_slow", "R (slow)", "N", "38.20",
          "reaction at O on the e'' basis for the slow root", kind="vector", contract=True),
        R("R_fast", "R (fast)", "N", "38.20",
          "reaction at O on the e'' basis for the fast root", kind="vector", contract=True),
        R("p", "p", "rad/s", "38.22",
          "only when `Omega` is given: the spin p for that Ω", example=False),
        R("R", "R", "N", "38.20",
          "only when `Omega` is given: the reaction at O for that precession", example=False),
        R("stable", "stable", "", "",
          "only when `Omega` is given: small perturbations of that precession stay bounded", example=False),
        R("nutation_freq", "ν", "rad/s", "",
          "only when `Omega` is given: ν, the frequency of small nutation about that precession", example=False),
    ],
)

TYPES = [PRECESSION]
