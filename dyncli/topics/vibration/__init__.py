"""Vibrations of a spring-mass-damper, free and base-excited (notes §17)."""
