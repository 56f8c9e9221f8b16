"""Independent reference routes for the inertia tests (test-only code).

* :func:`plate_minus_disk` integrates ρ[(p·p)1 − p⊗p] over a rectangular
  plate with a circular hole directly, in polar coordinates about the hole
  centre (r from the hole radius to the plate edge along each ray), with
  Gauss-Legendre rules on angular panels split at the corner angles — no
  decomposition into parts and no transfer theorem.
* :func:`polygon_prism` integrates over a prism with a polygonal outline by
  Gauss-Legendre rules on a triangle fan.
* :func:`box_cubature`, :func:`cylinder_cubature` integrate a solid box /
  cylinder with arbitrary placement and rotation about an arbitrary point.
"""

from __future__ import annotations

import math

import numpy as np


def _gl(n, a, b):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


def _tensor_from_moments(M0, M1, M2):
    """mass, first moment, second-moment matrix J = ∫ p⊗p dm -> (m, com, I about origin)."""
    I = np.trace(M2) * np.eye(3) - M2
    return M0, M1 / M0, I


def plate_minus_disk(rho, A, B, t, xc, yc, r, n=40):
    """Plate [−A/2, A/2] × [−B/2, B/2] × [−t/2, t/2] minus the cylinder of
    radius r about (xc, yc).  Returns (mass, com, I about the origin)."""
    corners = [(A / 2, B / 2), (-A / 2, B / 2), (-A / 2, -B / 2), (A / 2, -B / 2)]
    angs = sorted(np.arctan2(cy - yc, cx - xc) % (2 * np.pi) for cx, cy in corners)
    edges = [0.0] + angs + [2 * np.pi]
    M0 = 0.0
    M1 = np.zeros(3)
    M2 = np.zeros((3, 3))
    for a0, a1 in zip(edges[:-1], edges[1:]):
        if a1 - a0 < 1e-15:
            continue
        th, wth = _gl(n, a0, a1)
        for t_, wt in zip(th, wth):
            c, s = np.cos(t_), np.sin(t_)
            # distance to the rectangle boundary along the ray
            cands = []
            if c > 0:
                cands.append((A / 2 - xc) / c)
            if c < 0:
                cands.append((-A / 2 - xc) / c)
            if s > 0:
                cands.append((B / 2 - yc) / s)
            if s < 0:
                cands.append((-B / 2 - yc) / s)
            R = min(cands)
            rr, wr = _gl(6, r, R)          # integrand polynomial in r (degree <= 3 with the Jacobian)
            x = xc + rr * c
            y = yc + rr * s
            w = rho * t * wt * wr * rr     # dz integral gives t (and t³/12 for z²)
            M0 += w.sum()
            M1 += np.array([(w * x).sum(), (w * y).sum(), 0.0])
            M2[0, 0] += (w * x * x).sum()
            M2[1, 1] += (w * y * y).sum()
            M2[0, 1] += (w * x * y).sum()
            M2[2, 2] += w.sum() * t * t / 12.0
    M2[1, 0] = M2[0, 1]
    return _tensor_from_moments(M0, M1, M2)


def polygon_prism(rho, verts, t, n=8):
    """Prism with polygon outline ``verts`` (counter-clockwise, star-shaped
    about vertex 0) in the plane x3 = 0, thickness t (symmetric)."""
    v = np.asarray(verts, dtype=float)
    u, wu = _gl(n, 0.0, 1.0)
    M0 = 0.0
    M1 = np.zeros(3)
    M2 = np.zeros((3, 3))
    for k in range(1, len(v) - 1):
        a, b, c = v[0], v[k], v[k + 1]
        area2 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        # Duffy map of the square onto the triangle: p = a + s(b − a) + s q (c − b), Jacobian s·|area2|
        for s, ws in zip(u, wu):
            for q, wq in zip(u, wu):
                p = a + s * (b - a) + s * q * (c - b)
                w = rho * t * ws * wq * s * abs(area2)
                P = np.array([p[0], p[1], 0.0])
                M0 += w
                M1 += w * P
                M2 += w * np.outer(P, P)
                M2[2, 2] += w * t * t / 12.0
    return _tensor_from_moments(M0, M1, M2)


def box_cubature(rho, size, center, R, B, n=4):
    """Solid box (edges along the columns of R) about point B."""
    a, b, c = size
    x, wx = _gl(n, -a / 2, a / 2)
    y, wy = _gl(n, -b / 2, b / 2)
    z, wz = _gl(n, -c / 2, c / 2)
    X, Y, Z = np.meshgrid(x, y, z, indexing="ij")
    W = rho * np.einsum("i,j,k->ijk", wx, wy, wz)
    local = np.stack([X.ravel(), Y.ravel(), Z.ravel()])
    P = (np.asarray(R) @ local).T + np.asarray(center) - np.asarray(B)
    return _about(P, W.ravel())


def cylinder_cubature(rho, radius, height, center, R, B, n=8):
    """Solid cylinder (axis along column 3 of R) about point B."""
    r, wr = _gl(n, 0.0, radius)
    th = np.linspace(0.0, 2 * np.pi, 4 * n, endpoint=False)   # trapezoid: exact for trig polynomials
    wth = np.full(th.size, 2 * np.pi / th.size)
    z, wz = _gl(n, -height / 2, height / 2)
    Rr, Th, Z = np.meshgrid(r, th, z, indexing="ij")
    W = rho * np.einsum("i,j,k->ijk", wr * r, wth, wz)
    local = np.stack([(Rr * np.cos(Th)).ravel(), (Rr * np.sin(Th)).ravel(), Z.ravel()])
    P = (np.asarray(R) @ local).T + np.asarray(center) - np.asarray(B)
    return _about(P, W.ravel())


def _about(P, W):
    m = W.sum()
    J = np.einsum("n,ni,nj->ij", W, P, P)
    I = np.trace(J) * np.eye(3) - J
    return m, (W @ P) / m, I


def rotation(psi, theta, phi):
    """Independent construction (Rodrigues for each elementary turn)."""
    def rot(axis, a):
        k = np.asarray(axis, float)
        K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        return np.eye(3) + math.sin(a) * K + (1 - math.cos(a)) * K @ K
    R1 = rot([0, 0, 1], psi)
    R2 = rot(R1[:, 0], theta) @ R1              # about the turned e1
    return rot(R2[:, 2], phi) @ R2               # about the turned e3
