"""Behaviour simulator: symbolic world, BT.CPP v4 loader, BT execution, verdicts."""
