"""The motion of a point from its coordinates' jets (notes §4, §5, §7, §8, §12) — numeric core.

Each coordinate comes as (q, q̇, q̈): from expressions in t by forward-mode automatic differentiation
(:mod:`dyncli.expr.jet`, :func:`motion`), or as the numbers of one instant (``instant.py``,
:func:`motion_of_jets`).  Every coordinate system is a rotating basis with the general operator (11.4),
v = δx/δt + ω×x, a = δv/δt + ω×v; :func:`per_time` turns the rows into the per-time results, with the
tangential-normal quantities of §5.  Shared by the solver (expressions in t) and the instant.
"""

from __future__ import annotations

import numpy as np

from dyncli.exact import INPUT_ROUNDING
from dyncli.expr.jet import jet
from dyncli.topics.kinematics import equations as eq
from dyncli.topics.kinematics import frame
from dyncli.topics.kinematics.equations import frame_rows, to_cartesian

#: a path is taken as straight at an instant (rho = null, e_n = null,
#: a_n = 0) when |v×a| <= STRAIGHT_TOL·|v||a|, i.e. when the angle between v
#: and a is below 1e-12 rad: a_n is then below 1e-12·|a|, under the rounding
#: noise of the components (each carries ~1e-16 relative error of its
#: largest term).
STRAIGHT_TOL = 1e-12

BASIS_LABELS = {
    "cartesian": ("e₁", "e₂", "e₃"),
    "polar": ("e_r", "e_θ", "e₃"),
    "cylindrical": ("e_r", "e_θ", "e₃"),
    "spherical": ("e_R", "e_θ", "e_φ"),
}

#: the rows of the frame table (:func:`motion_of_jets`), labelled as the notes write them (11.4)
ROW_LABELS = [("ω", "omega"), ("x", "x"), ("δx/δt", "dx"), ("ω×x", "wx"), ("v", "v"),
              ("δv/δt", "dv"), ("ω×v", "wv"), ("a", "a")]

EQUATIONS = {
    "cartesian": ["4.2", "4.3"],
    "polar": ["7.3", "7.14", "7.16c"],
    "cylindrical": ["8.1", "8.2", "7.14", "7.16c"],
    "spherical": ["12.1", "12.2", "12.8", "11.4"],
}


def motion(coords: str, position: dict, t: np.ndarray) -> dict:
    """Numeric rows of the frame table and the Cartesian x, v, a at times t
    (non-finite entries where a derivative does not exist)."""
    with np.errstate(all="ignore"):
        return _motion(coords, position, t)


def _motion(coords: str, position: dict, t: np.ndarray) -> dict:
    from dyncli.topics.kinematics.model import COORDINATES

    J = {}
    for name in COORDINATES[coords]:
        e = position.get(name)
        J[name] = jet(e, t) if e is not None else (np.zeros_like(t), np.zeros_like(t), np.zeros_like(t))
    return motion_of_jets(coords, J, t.shape)


def motion_of_jets(coords: str, J: dict, shape) -> dict:
    """The rows of :func:`motion` from each coordinate's (q, q̇, q̈), arrays of the given shape
    (from expressions in t, or the numbers of one instant)."""
    rows = frame_rows(coords, J, np)
    rows = {k: tuple(np.broadcast_to(np.asarray(c, dtype=float), shape) for c in v) if k != "basis" else
            tuple(tuple(np.broadcast_to(np.asarray(c, dtype=float), shape) for c in b) for b in v)
            for k, v in rows.items()}
    w, x, dx, dv = rows["omega"], rows["x"], rows["dx"], rows["dv"]
    wx = frame.cross(w, x)
    v = frame.add(dx, wx)                     # (11.4)
    wv = frame.cross(w, v)
    a = frame.add(dv, wv)                     # (11.4) applied to v
    rows.update({"wx": wx, "v": v, "wv": wv, "a": a})
    B = rows["basis"]
    rows["x_cart"] = to_cartesian(x, B)
    rows["v_cart"] = to_cartesian(v, B)
    rows["a_cart"] = to_cartesian(a, B)
    return rows


def _stack(comps, n):
    return np.stack([np.broadcast_to(np.asarray(c, dtype=float), (n,)) for c in comps], axis=1) + 0.0


def _rows_list(arr, ok):
    vals = arr.tolist()
    for i in np.flatnonzero(~ok):
        vals[i] = None
    return vals


def per_time(rows, times):
    """Every per-time result, vectorised over the times.

    §5 quantities are computed from the components on the orthonormal own
    basis (rows of Q, Cartesian components), where the algebra is exact for
    the book's examples; e_t and e_n are then returned in Cartesian
    components."""
    n = len(times)
    if n == 0:
        keys = ("x", "v", "a", "v_basis", "a_basis", "speed", "a_t", "a_n", "rho", "e_t", "e_n")
        return {k: [] for k in keys}, [], [], []
    X, V, A = (_stack(rows[k], n) for k in ("x_cart", "v_cart", "a_cart"))
    VB, AB = _stack(rows["v"], n), _stack(rows["a"], n)
    Q = np.stack([_stack(b, n) for b in rows["basis"]], axis=1)      # Q[i, j, :] = e'_j
    fin = lambda M: np.all(np.isfinite(M.reshape(n, -1)), axis=1)    # noqa: E731
    okx, okv, oka = fin(X), fin(V) & fin(VB), fin(A) & fin(AB)
    okq = fin(Q)
    with np.errstate(all="ignore"):
        speed, et, at, c, amag = eq.tangential_normal(VB, AB)
        an = eq.normal_acceleration(c)
        rho = eq.radius_of_curvature(speed, an)
        en = eq.principal_normal(c, an, et)
        et_c = np.einsum("ij,ijk->ik", et, Q) + 0.0
        en_c = np.einsum("ij,ijk->ik", en, Q) + 0.0
    okva = okv & oka & okq
    # at rest: |v| = 0 to within what the rounding of the given t (4 round-offs, dyncli.exact)
    # can change, |a|·δt — so t = pi on x = cos t is a rest point, not a noise direction
    rest_band = INPUT_ROUNDING * np.abs(np.asarray(times, dtype=float)) * amag
    moving = okva & (speed > 0) & ~(speed <= rest_band)
    is_straight = moving & (an <= STRAIGHT_TOL * amag)          # |v×a| <= tol |v||a|
    curved = moving & ~is_straight
    out = {
        "x": _rows_list(X, okx), "v": _rows_list(V, okv), "a": _rows_list(A, oka),
        "v_basis": _rows_list(VB, okv), "a_basis": _rows_list(AB, oka),
        "speed": [float(s_) if ok else None for s_, ok in zip(speed, okv)],
        "a_t": [float(x) if ok else None for x, ok in zip(at, moving)],
        "a_n": [float(x) if c_ else (0.0 if s_ else None) for x, c_, s_ in zip(an, curved, is_straight)],
        "rho": [float(x) if c_ and np.isfinite(x) else None for x, c_ in zip(rho, curved)],
        "e_t": _rows_list(et_c, moving),
        "e_n": _rows_list(en_c, curved & fin(en_c)),
    }
    undefined = [t for t, ok in zip(times, okx & okva) if not ok]
    rest = [t for t, ok, m_ in zip(times, okva, moving) if ok and not m_]
    straight = [t for t, s_ in zip(times, is_straight) if s_]
    return out, rest, straight, undefined
