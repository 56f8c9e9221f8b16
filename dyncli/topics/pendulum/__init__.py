"""The simple pendulum at any amplitude: the exact period by the complete elliptic integral and the
motion by Jacobi's elliptic functions (notes §7, §16, §20)."""
