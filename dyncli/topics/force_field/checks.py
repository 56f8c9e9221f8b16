"""Force fields (notes §19): the numeric checks at random points of a box — the curl
verdict when sympy cannot decide, and the single-valuedness of a potential (its
differences against the work along random straight segments, by Gauss-Legendre
quadrature: a field such as -x2/(x1²+x2²) e1 + x1/(x1²+x2²) e2 has zero curl but
no potential around the x3 axis)."""

from __future__ import annotations

import math
from typing import Any

from dyncli.result import Result
from dyncli.topics.force_field.path import segment_work

N_RANDOM = 48          # random points for numeric checks
CURL_RTOL = 1e-8       # numeric check: |curl| above this times max |dF_i/dx_j| at the point is non-zero
N_SEGMENTS = 6         # random segments for the single-valuedness check
#: the largest half-width of the box of random points (a point given at
#: 1e308 would make the box's width overflow a double)
BOX_MAX = 1e300


def box_of(sizes) -> float:
    """Half-width of the box of random test points: 2, or 1.5 times the
    largest coordinate given, at most BOX_MAX."""
    return min(BOX_MAX, max([2.0] + [1.5 * abs(float(v)) for v in sizes]))


def real_somewhere(exprs, envs: list[dict], names=None) -> None:
    """Refuse a component of F that is real and finite at none of the test
    points (``envs``: the random points and the given points, as variable
    mappings of arrays or floats), e.g. ``sqrt(-x1**2 - 1)``: such a field
    has no value anywhere, so no curl, verdict or potential means anything."""
    import numpy as np

    from dyncli.errors import InputError

    for i, e in enumerate(exprs):
        if e.variables and not any(np.any(np.isfinite(np.asarray(e.evaluate(**env), dtype=float))) for env in envs):
            raise InputError(f"component {i + 1} ({e.text!r}) is real and finite at none of the {N_RANDOM} random "
                             "points nor the given points (a square root or logarithm of a negative number "
                             "everywhere?): F must be a real field", f"F.{i}")


def random_points(n: int, scale: float, seed: int = 19):
    """The random test points of the box: a (3, n) array uniform in [−scale, scale]³ from a
    fixed ``seed``, so that every route (sympy's, the exact polynomial one, the potential's
    check) draws the same points and reports the same counterexample on every run."""
    import numpy as np

    rng = np.random.default_rng(seed)
    return rng.uniform(-scale, scale, size=(3, n))


def _derivative_scale(fld, pts) -> Any:
    """Typical size of the first derivatives of F at the points (to judge
    whether a curl value is zero up to rounding)."""
    import numpy as np

    scale = np.zeros(pts.shape[1])
    for d in fld.grad_expr:
        val = np.abs(d.evaluate(x1=pts[0], x2=pts[1], x3=pts[2]))
        scale = np.maximum(scale, np.where(np.isfinite(val), val, 0.0))
    return scale


def numeric_verdict(fld, box: float, res: Result) -> tuple[bool, str]:
    """(conservative?, how): the curl at N_RANDOM random points of the box."""
    import numpy as np

    pts = random_points(N_RANDOM, box)
    curl = fld.curl_at(pts)
    scale = _derivative_scale(fld, pts)
    ok = np.all(np.isfinite(curl), axis=0)
    if not np.any(ok):
        res.warn("the curl could not be evaluated at any random test point (F is undefined there)")
        return False, "undecided (F undefined at the test points)"
    # relative to the derivatives only: an absolute 1e-8 took F = [1e-10 x2, 0, 0] as conservative
    big = np.any(np.abs(curl) > CURL_RTOL * scale, axis=0) & ok
    if np.any(big):
        k = int(np.argmax(big))
        p = [float(v) for v in pts[:, k]]
        return False, f"counterexample: curl != 0 at x = [{p[0]:.4g}, {p[1]:.4g}, {p[2]:.4g}]"
    res.warn(f"sympy could not simplify the curl to 0; the curl vanishes (to rounding) at "
             f"{int(np.sum(ok))} random points, so F is taken as conservative (numeric check)")
    return True, f"numeric (curl = 0 at {int(np.sum(ok))} random points)"


def single_valued(fld, Vnum, box: float) -> tuple[bool, str | None]:
    """Compare V(a) - V(b) with the work of F along random straight segments a -> b."""
    pts = random_points(2 * N_SEGMENTS, box, seed=23)
    checked = 0
    for k in range(N_SEGMENTS):
        a, b = pts[:, 2 * k], pts[:, 2 * k + 1]
        Va, Vb = Vnum(*a), Vnum(*b)
        if not (math.isfinite(Va) and math.isfinite(Vb)):
            continue
        for panels in (8, 32, 128):              # refined where F is peaked (a segment near a singular line)
            U, err = segment_work(fld, a, b, panels)
            if not math.isfinite(U) or err <= 1e-8 * (1.0 + abs(U)):
                break
        if not math.isfinite(U) or err > 1e-8 * (1.0 + abs(U)):     # singular or unresolved: not a test
            continue
        checked += 1
        tol = 1e-7 * (1.0 + abs(U) + abs(Va) + abs(Vb)) + 10 * err
        if abs((Va - Vb) - U) > tol:
            return False, (f"the work from [{a[0]:.3g}, {a[1]:.3g}, {a[2]:.3g}] to [{b[0]:.3g}, {b[1]:.3g}, {b[2]:.3g}] "
                           f"is {U:.6g} but V1 - V2 = {Va - Vb:.6g}")
    return True, None if checked else "no segment could be checked"
