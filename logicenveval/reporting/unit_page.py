"""A unit's report page, written by the worker that computed the unit (`UnitSpec.on_commit`).

The pages were a serial tail of ~1 s after the units (125 pages of the default run). Each page
depends on its unit alone (its environments, verdicts, traces, figures and failures) and on the
run's id and model, so the worker that ran the unit writes it right after committing the unit,
with the same code as `report` (`leaderboard.write_details`): the run's process then writes only
the index and the main page. A resumed run's reused units get their pages from the run's process;
`report RUN_DIR` rewrites every page from the units.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from logicenveval.metrics.compute import TaskMetrics
from logicenveval.metrics.records import UnitRecord
from logicenveval.reporting.details import Source
from logicenveval.reporting.leaderboard import jinja, write_details
from logicenveval.runner.results import per_task_entry, row_status, unit_failures
from logicenveval.runner.unit import UnitSpec


def unit_results(unit: UnitRecord, metrics: TaskMetrics | None, run_id: str, model: str) -> dict[str, Any]:
    """The part of results.json a unit's page reads, made from the unit alone (`metrics`: its
    figures, None when not measured)."""
    errors, found = unit_failures(unit)
    per_task = {} if metrics is None else {unit.task_id: per_task_entry(metrics, unit)}
    return {"run_id": run_id, "model": model, "tasks": [unit.task_id],
            "results": {unit.generator: row_status(
                measured=metrics is not None, not_measured=[] if unit.measured else [unit.task_id],
                budget_hit=[unit.task_id] if metrics is not None and unit.budget_hit is not None else [])},
            "per_task": {unit.generator: per_task}, "failures": {unit.generator: errors + found}}


def write_unit_page(spec: UnitSpec, record: UnitRecord, metrics: TaskMetrics | None, *,
                    model: str, run_id: str | None = None) -> None:
    """`details/<generator>/<task>.html` of one committed unit (an `on_commit` hook: bind
    `model` with `functools.partial`; `committed` calls it with the figures of a measured
    unit). The run id is the run folder's name unless given (a run may be placed in a new
    version of its folder after the hook was bound: runner.placement)."""
    run_dir = Path(spec.run_dir)
    run_id = run_id or run_dir.name
    source = Source(run_dir, unit_results(record, metrics, run_id, model),
                    records={(record.generator, record.task_id): record})
    write_details(run_dir, [source], [record.generator], jinja(), shared=False, index=False)
