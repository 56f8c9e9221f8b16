"""Rigid-body kinematics: velocities of points, angular velocity from point data, screw motion, contact (notes §13, §14, §15)."""
