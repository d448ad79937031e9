"""In which order and grouping a run hands its units to workers: longest first, short tail.

Results never depend on it (a unit's random generator is seeded from its names, and results.json
is built in (generator, task) order), only the wall time does: a long unit started last leaves the
other workers idle until it ends (longest-processing-time-first scheduling).
"""

from __future__ import annotations

from collections.abc import Sequence

from logicenveval.runner.unit import UnitSpec

#: relative cost of one unit by generator, where no measurement says otherwise. Measured on the
#: default offline run (results.json `timing.phases`, 25 tasks): a LogicEnvGen unit (solver
#: layouts of several environments, each judged with mutants) takes 5-15x a baseline's.
STATIC_COST: dict[str, float] = {"logicenvgen": 10.0}
DEFAULT_COST = 1.0


def unit_cost(spec: UnitSpec) -> float:
    """The static estimate of a unit's time (LogicEnvGen and its ablations are the long ones)."""
    return next((cost for prefix, cost in STATIC_COST.items() if spec.generator.startswith(prefix)),
                DEFAULT_COST)


def hand_offs(specs: Sequence[UnitSpec], workers: int) -> list[tuple[UnitSpec, ...]]:
    """Hand-offs for `workers` processes, longest expected first.

    With at least 4 tasks per worker, the units of one task travel together (they share the
    worker's memoised task analysis, parsed policies and mutants), except the cheapest `2 *
    workers` tasks, whose units go one by one at the end so that the last hand-off is one short
    unit, not a whole task. With fewer tasks every unit is its own hand-off, longest first.
    Ties keep the given order, so the schedule is a pure function of the specs.
    """
    if workers <= 1:
        return [(s,) for s in specs]
    by_task: dict[str, list[UnitSpec]] = {}
    for spec in specs:
        by_task.setdefault(spec.task_id, []).append(spec)
    if len(by_task) < 4 * workers:
        return [(s,) for s in sorted(specs, key=lambda s: -unit_cost(s))]
    tasks = sorted(by_task.values(), key=lambda group: -sum(unit_cost(s) for s in group))
    whole, split = tasks[: len(tasks) - 2 * workers], tasks[len(tasks) - 2 * workers:]
    singles = sorted((s for group in split for s in group), key=lambda s: -unit_cost(s))
    return [tuple(group) for group in whole] + [(s,) for s in singles]
