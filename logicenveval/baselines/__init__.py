"""Baselines of the paper (§5.1): CoT, IFG and a Holodeck-like generator, on LogicEnvGen's setup."""
