"""Systems of particles: mass, center of mass, momentum, angular momentum, kinetic energy (notes §24-§27)."""
