"""Per-task statistics of the benchmark (`tasks stats`): logical size and policy size.

The minimal cover is the smallest set of environments whose trajectories cover every decision path;
for independent subtasks it equals max over subtasks of |paths|. The logic package's `exact`
selector computes it when present; otherwise that closed form is used.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from pathlib import Path

from logicenveval.benchmark import load_tasks
from logicenveval.model.task import POLICY_KINDS, Node, Task
from logicenveval.model.tree import task_paths


@dataclass(frozen=True)
class TaskStats:
    task: str
    rooms: int
    roles: int
    subtasks: int
    variables: int
    decision_paths: int
    trajectories: int
    min_cover: int
    bt_nodes: int  # nodes of the correct policy, all BehaviorTrees counted


def minimal_cover(task: Task) -> int:
    """Size of the smallest set of trajectories covering every decision path of the task."""
    per = task_paths(task)
    try:
        from logicenveval.logic.selectors import get_selector
    except ImportError:
        return max(len(p) for p in per)
    return len(get_selector("exact").select(per))


def bt_nodes(task: Task, directory: Path) -> int:
    """Number of XML nodes of the task's correct policy (0 when it cannot be loaded)."""
    from logicenveval.errors import LogicEnvEvalError
    from logicenveval.sim.loader import load_policy
    from logicenveval.sim.policy import PolicyNode

    rel = task.policies.get("correct")
    if rel is None:
        return 0
    try:
        policy = load_policy(directory / task.id / rel, roles=task.roles, rooms=task.rooms)
    except LogicEnvEvalError:
        return 0

    def count(n: PolicyNode) -> int:
        return 1 + sum(count(c) for c in n.children)

    return sum(count(t) for t in policy.trees.values())


def task_stats(task: Task, directory: Path) -> TaskStats:
    per = task_paths(task)
    used_vars = {n.var for st in task.subtasks for n in _nodes(st.tree)}
    return TaskStats(
        task=task.id, rooms=len(task.rooms), roles=len(task.roles), subtasks=len(task.subtasks),
        variables=len(used_vars), decision_paths=sum(len(p) for p in per),
        trajectories=math.prod(len(p) for p in per), min_cover=minimal_cover(task),
        bt_nodes=bt_nodes(task, directory),
    )


def _nodes(tree: object) -> list[Node]:
    if isinstance(tree, Node):
        return [tree, *[n for child in tree.branches.values() for n in _nodes(child)]]
    return []


def benchmark_stats(directory: str | Path | None = None) -> list[TaskStats]:
    from logicenveval.benchmark import tasks_dir

    d = tasks_dir(directory)
    return [task_stats(t, d) for t in load_tasks(d)]


def totals(rows: list[TaskStats]) -> dict[str, int]:
    """Column sums (the `task` column excluded); policy files counted as 4 per task."""
    out = {f.name: sum(getattr(r, f.name) for r in rows) for f in fields(TaskStats) if f.name != "task"}
    out["tasks"] = len(rows)
    out["policies"] = len(rows) * len(POLICY_KINDS)
    return out


COLUMNS: tuple[str, ...] = tuple(f.name for f in fields(TaskStats))


def to_markdown(rows: list[TaskStats]) -> str:
    """The stats table in GitHub Markdown, with a totals row (for docs/benchmark.md)."""
    head = "| " + " | ".join(COLUMNS) + " |"
    sep = "|" + "|".join("---" if c == "task" else "---:" for c in COLUMNS) + "|"
    lines = [head, sep]
    for r in rows:
        lines.append("| " + " | ".join(str(getattr(r, c)) for c in COLUMNS) + " |")
    t = totals(rows)
    lines.append("| **total** | " + " | ".join(str(t[c]) for c in COLUMNS[1:]) + " |")
    return "\n".join(lines)
