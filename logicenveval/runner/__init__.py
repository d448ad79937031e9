"""Run orchestration: units of (generator, task), executors, resumable store, results."""
