"""Kinematics of a point: path, tangential-normal and curvilinear coordinates (notes §4, §5, §7, §8, §12)."""
