"""Metrics of DESIGN.md §7 as pure functions over evaluation records."""
