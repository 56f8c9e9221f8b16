"""Impact of two particles, smooth (restitution e) or with friction (eta, phi) (notes §28, §23)."""
