"""The reference minimal trajectory set used by JI: `exact` on the task's GT trees.

Subtasks that test a shared variable cannot take contradicting paths together, so the task's own
consistency pairs (`task_constraints`) are applied; for the paper's independent subtasks this is
the plain max_i |paths_i| cover.
"""

from __future__ import annotations

from collections.abc import Iterable

from logicenveval.logic.constraints import task_constraints
from logicenveval.logic.exact import exact_cover
from logicenveval.model.task import Task
from logicenveval.model.tree import Trajectory, task_paths


def reference_set(task: Task) -> list[Trajectory]:
    return list(exact_cover(task_paths(task), task_constraints(task)).trajectories)


def jaccard(a: Iterable[str], b: Iterable[str]) -> float:
    """|A ∩ B| / |A ∪ B| over trajectory keys; 0.0 when both are empty."""
    sa, sb = set(a), set(b)
    union = sa | sb
    return len(sa & sb) / len(union) if union else 0.0
