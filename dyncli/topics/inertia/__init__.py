"""Inertia tensors, composite bodies, transfer theorem and principal axes (notes §30, §31, §35)."""
