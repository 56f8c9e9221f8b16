"""The declaration of rectilinear: one entry per result (see dyncli/declare.py)."""

from dyncli.declare import R, TypeSpec


RECTILINEAR = TypeSpec(
    name="rectilinear",
    plots="plots:plots",
    title="straight-line motion, cases 1-4 (a const, a(t), a(v), a(s))",
    sections="§6",
    model="model:Rectilinear",
    solve="solver:solve",
    example="problems/rectilinear/case1-constant-acceleration.yaml",
    results=[
        R("case", "case", "", "",
          "1, 2, 3, 4 or `\"general\"`", contract=True),
        R("find", "", "", "",
          "one entry per query, in order: `{t, s, v, a, reached, distance}` (and `at_end` for max/min; SI units)", kind="list", contract=True),
        R("period", "", "s", "",
          "case 4 with two turning points only: the period of the oscillation [s]", kind="number"),
        R("t", "t", "s", "", "time of a `find` entry", part_of="find"),
        R("s", "s", "m", "", "position of a `find` entry", part_of="find"),
        R("v", "v", "m/s", "", "velocity of a `find` entry", part_of="find"),
        R("a", "a", "m/s²", "", "acceleration of a `find` entry", part_of="find"),
        R("distance", "", "m", "", "distance travelled since t1, ∫|v| dt, of a `find` entry", part_of="find"),
        R("at_end", "", "", "", "`max`/`min` queries: the extreme lies at an end of the window", part_of="find"),
    ],
)

TYPES = [RECTILINEAR]
