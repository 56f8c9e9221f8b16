"""A student's script: Euler's equations (39.5) with an applied moment."""
import numpy as np
from scipy.integrate import solve_ivp

I1, I2, I3 = 1.0, 2.0, 3.0


def f(t, w):
    return [(0.1 * np.sin(t) + (I2 - I3) * w[1] * w[2]) / I1,
            ((I3 - I1) * w[2] * w[0]) / I2,
            ((I1 - I2) * w[0] * w[1]) / I3]


sol = solve_ivp(f, (0, 5), [0.1, 5, 0.1], method="DOP853", rtol=1e-10, atol=1e-12, t_eval=[0, 1, 2, 3, 4, 5])
for t, y in zip(sol.t, sol.y.T):
    print(t, y)
