"""Environment generators: LogicEnvGen, its ablations, and (via `baselines`) CoT, IFG, Holodeck."""
