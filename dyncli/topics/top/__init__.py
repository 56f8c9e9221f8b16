"""The heavy symmetric top: nutation, precession and reactions (notes §38)."""
