"""The heavy symmetric top: integration of (38.18), nutation bounds, reaction (notes §38)."""
