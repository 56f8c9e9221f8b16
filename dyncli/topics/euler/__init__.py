"""Euler's equations and the torque-free rigid body (notes §39)."""
