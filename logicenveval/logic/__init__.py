"""Logical trajectories: selectors over decision paths (paper §3.2) and the JI reference set."""
