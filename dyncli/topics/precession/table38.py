"""Table 38.1 of the notes, evaluated numerically (pure Python, no numpy).

Given the 3-1-3 Euler angle θ and the rates and accelerations of ψ, θ, φ,
build the rows Ω, x̄, v̄, δv̄/δt, Ω×v̄, ā, H_O, δH_O/δt, Ω×H_O, Ḣ_O and M_O on
the e'' basis (38.10, 38.14, 38.15, 38.17).  Shared by ``precession`` and
``top``.
"""

from __future__ import annotations

import math

from dyncli.result import FrameTable

BASIS2 = ("e''₁", "e''₂", "e''₃")


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def add(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def rows_38_1(m, L, I11, I33, g, theta, psi_d, theta_d, phi_d, psi_dd, theta_dd, phi_dd):
    """Rows of Table 38.1 (plus the reaction R (38.16) and M_O (38.17))."""
    s, c = math.sin(theta), math.cos(theta)
    Om = [theta_d, psi_d * s, psi_d * c]
    x = [0.0, 0.0, L]
    v = cross(Om, x)
    dv = [L * psi_dd * s + L * psi_d * theta_d * c, -L * theta_dd, 0.0]
    Omv = cross(Om, v)
    a = add(dv, Omv)
    H = [I11 * theta_d, I11 * psi_d * s, I33 * (psi_d * c + phi_d)]
    dH = [I11 * theta_dd, I11 * (psi_dd * s + psi_d * theta_d * c),
          I33 * (psi_dd * c - psi_d * theta_d * s + phi_dd)]
    OmH = cross(Om, H)
    Hdot = add(dH, OmH)
    M = [m * g * L * s, 0.0, 0.0]
    R = [m * a[0], m * (g * s + a[1]), m * (g * c + a[2])]
    return [
        ("Ω", Om), ("x̄", x), ("v̄ = Ω×x̄", v), ("δv̄/δt", dv), ("Ω×v̄", Omv), ("ā", a),
        ("H_O", H), ("δH_O/δt", dH), ("Ω×H_O", OmH), ("Ḣ_O", Hdot), ("M_O", M), ("R", R),
    ]


def table_38_1(title, *args, note=None) -> FrameTable:
    return FrameTable(title, rows_38_1(*args), basis=BASIS2, note=note)
