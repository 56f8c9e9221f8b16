"""Quantities derived from the state of the top (notes §38): the rates (38.11b), the
reaction at O (38.16a) and the rows of the notes' Table 38.1."""

from __future__ import annotations

import math

from dyncli.topics.top.kinematics import Top

BASIS = ("e''₁", "e''₂", "e''₃")



def rates(top: Top, theta, phi, w):
    """ψ̇, θ̇, φ̇ and S = ψ̇ sinθ from body ω (38.11b); ψ̇ = nan where sinθ = 0 (arrays)."""
    import numpy as np

    c, s = np.cos(phi), np.sin(phi)
    th_dot = w[:, 0] * c - w[:, 1] * s
    S = w[:, 0] * s + w[:, 1] * c
    sth = np.sin(theta)
    with np.errstate(all="ignore"):
        psi_dot = np.where(sth > 0, S / np.where(sth > 0, sth, 1.0), np.nan)
    phi_dot = w[:, 2] - psi_dot * np.cos(theta)
    return psi_dot, th_dot, phi_dot, S


def reaction(top: Top, theta, phi, w):
    """R = mg e3 + m ā (38.16a) on e'' (arrays: one row per time; numpy)."""
    import numpy as np

    return np.column_stack(reaction_on(np, top, theta, phi, w[:, 0], w[:, 1], w[:, 2]))


def reaction_on(xp, top: Top, theta, phi, w1, w2, w3):
    """(R1, R2, R3) = mg e3 + m ā (38.16a) on e'', with ā = ω̇ × x̄ + ω × (ω × x̄), x̄ = L e'_3, from
    body ω on backend xp (:data:`dyncli.backends.FLOAT_OPS` for one time, numpy for arrays)."""
    m, g, L = top.m, top.g, top.L
    sth, cth = xp.sin(theta), xp.cos(theta)
    sp, cp = xp.sin(phi), xp.cos(phi)
    g1, g2 = sth * sp, sth * cp
    wd1 = top.k1 * w2 * w3 + top.kg * g2
    wd2 = -top.k1 * w3 * w1 - top.kg * g1
    a1 = L * (wd2 + w1 * w3)
    a2 = L * (-wd1 + w2 * w3)
    a3 = -L * (w1 * w1 + w2 * w2)
    R1b, R2b = m * (g * g1 + a1), m * (g * g2 + a2)
    R3 = m * (g * cth + a3)
    return R1b * cp - R2b * sp, R1b * sp + R2b * cp, R3


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def table_381(top: Top, theta, psi_dot, theta_dot, omega3, S):
    """Rows of the notes' Table 38.1 on e'' (numbers; None where undefined), in plain floats (an
    overflow gives inf, which the rows show as None)."""
    A, C, L, mgL = top.A, top.C, top.L, top.mgL
    sth, cth = math.sin(theta), math.cos(theta)
    Om3 = psi_dot * cth
    th_dd = S * psi_dot * cth - C / A * S * omega3 + mgL / A * sth          # (38.18a)
    psdd_s = -2.0 * psi_dot * theta_dot * cth + C / A * omega3 * theta_dot  # ψ̈ sinθ (38.18b)
    Om = [theta_dot, S, Om3]
    H = [A * theta_dot, A * S, C * omega3]
    dH = [A * th_dd, A * (psdd_s + psi_dot * theta_dot * cth), 0.0]
    OxH = _cross(Om, H)
    Hdot = [dH[i] + OxH[i] for i in range(3)]
    xb = [0.0, 0.0, L]
    vb = [L * S, -L * theta_dot, 0.0]
    ab = [L * psdd_s + 2 * L * psi_dot * theta_dot * cth,
          -L * th_dd + L * S * psi_dot * cth,
          -L * theta_dot * theta_dot - L * S * S]

    def clean(v):
        return [float(x) + 0.0 if x is not None and math.isfinite(x) else None for x in v]

    return [("Ω", clean(Om)), ("H_O", clean(H)), ("δH_O/δt", clean(dH)), ("Ω×H_O", clean(OxH)),
            ("Ḣ_O", clean(Hdot)), ("x̄", clean(xb)), ("v̄", clean(vb)), ("ā", clean(ab))]


TABLE_FORMULAS = [
    ("Ω", ["θ̇", "ψ̇ sinθ", "ψ̇ cosθ"]),
    ("H_O", ["I11 θ̇", "I11 ψ̇ sinθ", "I33 (ψ̇ cosθ + φ̇)"]),
    ("δH_O/δt", ["I11 θ̈", "I11 (ψ̈ sinθ + ψ̇ θ̇ cosθ)", "I33 (ψ̈ cosθ − ψ̇ θ̇ sinθ + φ̈) = 0"]),
    ("Ω×H_O", ["I33 (ψ̇ cosθ + φ̇) ψ̇ sinθ − I11 ψ̇² sinθ cosθ", "−I33 (ψ̇ cosθ + φ̇) θ̇ + I11 θ̇ ψ̇ cosθ", "0"]),
    ("Ḣ_O", ["mgL sinθ", "0", "0"]),
    ("x̄", ["0", "0", "L"]),
    ("v̄", ["L ψ̇ sinθ", "−L θ̇", "0"]),
    ("ā", ["L ψ̈ sinθ + 2L ψ̇ θ̇ cosθ", "−L θ̈ + L ψ̇² sinθ cosθ", "−L θ̇² − L ψ̇² sin²θ"]),
]
