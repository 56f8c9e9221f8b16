"""Impulse on a rigid body in planar motion and its center of percussion (notes §33)."""
