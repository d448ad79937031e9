"""Cross-subtask constraints: pairs of decision paths that cannot hold in one environment.

Subtasks are independent in the paper; in real tasks two subtasks may test the same variable or
share one physical object, so some path pairs are contradictory. A small frozen set of forbidden
path-key pairs expresses that and keeps selectors hashable and reproducible.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from logicenveval.errors import TrajectoryError
from logicenveval.model.task import Task
from logicenveval.model.tree import DecisionPath, Trajectory, task_paths


@dataclass(frozen=True, slots=True)
class PathConstraints:
    """Forbidden unordered pairs of decision-path keys (from different subtasks)."""

    forbidden: frozenset[frozenset[str]] = frozenset()

    @classmethod
    def of_pairs(cls, pairs: Iterable[tuple[str, str]]) -> PathConstraints:
        return cls(frozenset(frozenset(p) for p in pairs))

    def allows(self, a: DecisionPath, b: DecisionPath) -> bool:
        return frozenset((a.key, b.key)) not in self.forbidden

    def admits(self, paths: Sequence[DecisionPath]) -> bool:
        """True when no two paths of a (partial) trajectory form a forbidden pair."""
        if not self.forbidden:
            return True
        keys = [p.key for p in paths]
        return not any(
            frozenset((keys[i], keys[j])) in self.forbidden
            for i in range(len(keys))
            for j in range(i + 1, len(keys))
        )

    def admits_trajectory(self, trajectory: Trajectory) -> bool:
        return self.admits(trajectory.paths)

    def validate(self, paths_per_subtask: Sequence[Sequence[DecisionPath]]) -> None:
        """Every pair must name two existing paths of different subtasks."""
        subtask_of = {p.key: i for i, paths in enumerate(paths_per_subtask) for p in paths}
        for pair in sorted(self.forbidden, key=sorted):
            keys = sorted(pair)
            unknown = [k for k in keys if k not in subtask_of]
            if unknown:
                raise TrajectoryError(
                    f"forbidden pair {keys} names unknown decision path(s) {unknown}",
                    field="constraints.forbidden",
                    hint="use DecisionPath.key values of the given subtasks' paths",
                )
            if len(keys) != 2 or subtask_of[keys[0]] == subtask_of[keys[1]]:
                raise TrajectoryError(
                    f"forbidden pair {keys} is not two paths of different subtasks",
                    field="constraints.forbidden",
                    hint="paths of one subtask never co-occur; only list cross-subtask pairs",
                )


def task_constraints(task: Task) -> PathConstraints:
    """Pairs of paths of different subtasks that assign different values to a shared variable."""
    per = task_paths(task)
    pairs: list[tuple[str, str]] = []
    for i in range(len(per)):
        for j in range(i + 1, len(per)):
            for a in per[i]:
                va = a.assignment()
                for b in per[j]:
                    if any(va.get(var, val) != val for var, val in b.steps):
                        pairs.append((a.key, b.key))
    return PathConstraints.of_pairs(pairs)
