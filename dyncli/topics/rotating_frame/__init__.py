"""Rotating frames: the general operator (11.4), relative acceleration (11.11) and the δ/δt table (notes §10, §11)."""
