"""Selector interface and the name registry, imported lazily.

`product` (the Cartesian product: the paper's "W/O MTSA"), `mtsa` (paper Algorithm 1),
`exhaustive` (the paper's exponential minimum-set-cover search), `exact` (our polynomial
minimum cover).
"""

from __future__ import annotations

import importlib
from collections.abc import Sequence
from typing import Protocol

from logicenveval.errors import TrajectoryError
from logicenveval.logic.constraints import PathConstraints
from logicenveval.model.tree import DecisionPath, Trajectory

PathsPerSubtask = Sequence[Sequence[DecisionPath]]


class Selector(Protocol):
    name: str

    def select(
        self, paths_per_subtask: PathsPerSubtask, constraints: PathConstraints | None = None
    ) -> list[Trajectory]: ...


_REGISTRY: dict[str, str] = {
    "product": "logicenveval.logic.product:SELECTOR",
    "mtsa": "logicenveval.logic.mtsa:SELECTOR",
    "exhaustive": "logicenveval.logic.exhaustive:SELECTOR",
    "exact": "logicenveval.logic.exact:SELECTOR",
}


def selector_names() -> list[str]:
    return list(_REGISTRY)


def get_selector(name: str) -> Selector:
    if name not in _REGISTRY:
        raise TrajectoryError(
            f"unknown trajectory selector {name!r}",
            field="selector",
            hint=f"use one of {', '.join(_REGISTRY)}",
        )
    module, attr = _REGISTRY[name].split(":")
    selector: Selector = getattr(importlib.import_module(module), attr)
    return selector


def check_inputs(
    paths_per_subtask: PathsPerSubtask, constraints: PathConstraints | None
) -> PathConstraints:
    """Validate selector inputs; returns the constraints to use (empty when None)."""
    if not paths_per_subtask:
        raise TrajectoryError(
            "no subtasks given", field="paths_per_subtask", hint="pass one path list per subtask"
        )
    seen: set[str] = set()
    for i, paths in enumerate(paths_per_subtask):
        if not paths:
            raise TrajectoryError(
                f"subtask #{i} has no decision paths",
                field=f"paths_per_subtask[{i}]",
                hint="every decision tree has at least one leaf; pass tree_paths(subtask)",
            )
        subtasks = {p.subtask for p in paths}
        if len(subtasks) != 1:
            raise TrajectoryError(
                f"subtask #{i} mixes paths of subtasks {sorted(subtasks)}",
                field=f"paths_per_subtask[{i}]",
                hint="group paths by subtask, one list per subtask (task_paths(task))",
            )
        for p in paths:
            if p.key in seen:
                raise TrajectoryError(
                    f"decision path {p.key!r} is given twice",
                    field=f"paths_per_subtask[{i}]",
                    hint="each decision path must appear once",
                )
            seen.add(p.key)
    cons = constraints if constraints is not None else PathConstraints()
    cons.validate(paths_per_subtask)
    return cons


def uncovered(trajectories: Sequence[Trajectory], paths_per_subtask: PathsPerSubtask) -> list[str]:
    """Keys of the decision paths that no trajectory takes, in path order."""
    taken = {p.key for t in trajectories for p in t.paths}
    return [p.key for paths in paths_per_subtask for p in paths if p.key not in taken]
