"""Pure data and logic: conditions, tasks, decision trees, trajectories, EnvSpec. No I/O."""
