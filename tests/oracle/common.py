"""Building blocks of the oracle's reference cases (never imports dyncli).

Every reference is computed in mpmath at ``DPS`` digits from the inputs *as the machine reads
them* (each number of a problem document is a double; ``x(v)`` is its exact binary value), so a
tolerance counts only what the route itself may lose.  A case is a plain dict stored in
``cases/<type>.json``:

* ``problem``: the problem document given to ``dyncli.solve`` (plain JSON numbers);
* ``checks``: ``{path, ref, tol, reason}`` with ``ref`` a string of >= 20 significant digits and
  ``tol`` the absolute tolerance the route's guarantee implies (a string), or ``per_estimate``: the
  scale the route's ``error_estimate`` is relative to (then the bound is estimate x scale + ``tol``);
* ``same``: ``{path, value}`` results that must be exactly equal (decisions: booleans, words,
  counts);
* ``expect``: ``"solved"`` (default) or ``"refused"`` (an input or numerical error is the right
  answer, e.g. a start too close to a separatrix to determine the motion).
"""

from __future__ import annotations

import mpmath as mp

DPS = 40
mp.mp.dps = DPS
EPS = mp.mpf(2) ** -52          # the double's machine epsilon
DIGITS = 25                     # significant digits of the stored references


def x(v) -> mp.mpf:
    """The exact value of the double ``v`` (the input as dyncli reads it)."""
    return mp.mpf(float(v))


def s(v) -> str:
    return mp.nstr(mp.mpf(v), DIGITS, strip_zeros=False, min_fixed=-3, max_fixed=3) if v != 0 else "0"


def closed(path, ref, scale=None, cond=1, reason=""):
    """A closed form: 8 ε × the condition number × the quantity's scale (docs/accuracy.md)."""
    scale = abs(mp.mpf(ref)) if scale is None else mp.mpf(scale)
    tol = 8 * EPS * mp.mpf(cond) * scale
    why = f"closed form: 8 eps x cond {mp.nstr(mp.mpf(cond), 3)} x scale {mp.nstr(scale, 3)}"
    return {"path": path, "ref": s(ref), "tol": s(tol), "reason": why + (f"; {reason}" if reason else "")}


def ode(path, ref, rtol, scale, reason=""):
    """An ODE route: 100 × rtol relative to the quantity's scale over the reported times."""
    tol = 100 * mp.mpf(rtol) * mp.mpf(scale)
    why = f"ODE route: 100 x rtol {rtol:g} x scale {mp.nstr(mp.mpf(scale), 3)}"
    return {"path": path, "ref": s(ref), "tol": s(tol), "reason": why + (f"; {reason}" if reason else "")}


def estimated(path, ref, scale, floor=None, reason=""):
    """A quadrature (or an exact route's round-off): the reported error_estimate × the scale it is
    relative to, plus 8 ε × scale for the final rounding."""
    scale = mp.mpf(scale)
    tol = 8 * EPS * scale if floor is None else mp.mpf(floor)
    why = f"error_estimate x scale {mp.nstr(scale, 3)} + {mp.nstr(tol, 3)}"
    return {"path": path, "ref": s(ref), "tol": s(tol), "per_estimate": s(scale),
            "reason": why + (f"; {reason}" if reason else "")}


def absolute(path, ref, tol, reason):
    return {"path": path, "ref": s(ref), "tol": s(tol), "reason": reason}


def same(path, value):
    return {"path": path, "value": value}


def case(name, type_, problem, checks, note, same_=(), expect="solved", known_wrong=None, slow=False):
    """``known_wrong``: what dyncli gets wrong on this case today (the test is an expected failure,
    strict: it fails once fixed, to be removed then); ``slow``: marked ``slow``."""
    problem = {"type": type_, **problem}
    out = {"name": name, "type": type_, "note": note, "expect": expect, "problem": problem,
           "checks": list(checks), "same": list(same_)}
    if known_wrong:
        out["known_wrong"] = known_wrong
    if slow:
        out["slow"] = True
    return out


def vec(v):
    return [mp.mpf(c) for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(p * q for p, q in zip(a, b))


def norm(a):
    return mp.sqrt(dot(a, a))


def vclosed(path, v, cond=1, scale=None, reason=""):
    """closed() per component of a vector, each against the vector's norm as its scale."""
    sc = norm(v) if scale is None else scale
    return [closed(f"{path}.{i}", c, scale=sc, cond=cond, reason=reason) for i, c in enumerate(v)]


def bisect(f, lo, hi, steps=200):
    """The root of f in [lo, hi] (a sign change) by bisection to 2^-steps of the bracket: slow,
    plain and sure — a reference, not a method under test."""
    lo, hi = mp.mpf(lo), mp.mpf(hi)
    flo = f(lo)
    if flo == 0:
        return lo
    assert flo * f(hi) <= 0, "no sign change in the bracket"
    for _ in range(steps):
        mid = (lo + hi) / 2
        fm = f(mid)
        if fm == 0:
            return mid
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return (lo + hi) / 2


def condition(f, args, h="1e-25"):
    """The relative condition number of f at args: the largest |Δf/f| / h over relative
    perturbations h of each argument (mpmath at DPS digits: h far below 1e-16, far above 1e-40)."""
    h = mp.mpf(h)
    f0 = f(*args)
    out = mp.mpf(1)
    for i, a in enumerate(args):
        if a == 0:
            continue
        pert = list(args)
        pert[i] = a * (1 + h)
        out = max(out, abs(f(*pert) - f0) / (h * abs(f0)) if f0 != 0 else mp.mpf(1))
    return out
