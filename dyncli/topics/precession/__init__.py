"""Steady precession of a symmetric top (notes §38, 38.19-38.27)."""
