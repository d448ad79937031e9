"""Mutation-based faults: first-order BT mutants, their classification, and the mutation score."""
