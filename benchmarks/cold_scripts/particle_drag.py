"""A student's script: the ball with quadratic drag, m a = -m g e3 - c |v| v."""
import numpy as np
from scipy.integrate import solve_ivp

m, c, g = 0.5, 0.005, 9.81


def f(t, y):
    v = y[3:]
    return np.concatenate([v, -c * np.sqrt(v @ v) * v / m - np.array([0.0, 0.0, g])])


sol = solve_ivp(f, (0, 3), [0, 0, 0, 20, 0, 20], method="DOP853", rtol=1e-10, atol=1e-12, t_eval=[0, 1, 2, 3])
for t, y in zip(sol.t, sol.y.T):
    print(t, y)
