"""Rectilinear motion (notes §6): cases 1-4 and the general ODE."""
