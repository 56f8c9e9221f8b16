"""Angular velocity on two bases (notes §35, 35.3-35.7).

ω is given on the body axes e'_i; with A_ij = e''_i·e'_j (35.5a) its
components on the basis e''_i are ω''_i = A_ij ω'_j (35.6a), and the angular
momentum about the center of mass has the same value on either basis:
H̄ = Ī'_ij ω'_j e'_i (35.3) = Ī''_ij ω''_j e''_i (35.4, 35.7).
"""

from __future__ import annotations

from dyncli.errors import InputError
from dyncli.topics.inertia import mat3
from dyncli.topics.inertia import rotations as rot


def add(res, omega, A, I_com_body, I_com_basis, I_about_basis) -> None:
    """Results ``omega_body``, ``omega_basis``, ``A``, ``H_com_body``, ``H_com``, ``H_about``
    (3×3 matrices as lists of rows, plain floats)."""
    w1 = [float(c) for c in omega]
    w2 = mat3.matvec(A, w1)                       # (35.6a)
    H1 = mat3.matvec(I_com_body, w1)              # (35.3)
    H2 = mat3.matvec(I_com_basis, w2)             # (35.4)
    HB = mat3.matvec(I_about_basis, w2)
    if not mat3.finite([w2, H1, H2, HB]):
        raise InputError("the angular momentum I ω overflows a double (values beyond ~1e308)", "omega")
    sw = max(mat3.max_abs(w1), 1e-300)
    sH = max(mat3.max_abs(H1), mat3.max_abs(HB), 1e-300)
    res.results.update({
        "omega_body": w1,
        "omega_basis": rot.clean(w2, sw),
        "A": rot.clean(A, 1.0),
        "H_com_body": rot.clean(H1, sH),
        "H_com": rot.clean(H2, sH),
        "H_about": rot.clean(HB, sH),
    })
    res.equations += ["35.3", "35.4", "35.6"]
