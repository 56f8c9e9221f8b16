"""Rigid-body kinetics: planar moments and kinetic energy (notes §32, §34)."""
