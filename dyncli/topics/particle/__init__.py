"""Kinetics of a particle: equation of motion, work and energy (notes §16, §18-§22)."""
