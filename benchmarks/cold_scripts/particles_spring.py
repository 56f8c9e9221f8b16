"""A student's script: two particles joined by a spring (k = 4, L = 1)."""
import numpy as np
from scipy.integrate import solve_ivp

k, L = 4.0, 1.0


def f(t, y):
    x1, x2, v1, v2 = y[0:3], y[3:6], y[6:9], y[9:12]
    d = x2 - x1
    r = np.sqrt(d @ d)
    F = k * (r - L) * d / r           # on particle 1, toward particle 2 when stretched
    return np.concatenate([v1, v2, F, -F])


y0 = [0, 0, 0, 1.5, 0, 0, 0, 1, 0, 0, 1, 0]
sol = solve_ivp(f, (0, 2), y0, method="DOP853", rtol=1e-10, atol=1e-12, t_eval=[0, 0.5, 1, 1.5, 2])
for t, y in zip(sol.t, sol.y.T):
    print(t, y)
