"""Decision paths, logical trajectories and evaluation of GT trees on a state.

A decision path is a root-to-leaf path of one subtask's tree, i.e. a set of (variable, value)
constraints; a logical trajectory picks one path per subtask (paper §3.2, DESIGN.md §4).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from logicenveval.model.conditions import Cond, Holds, conjunction, evaluate, parse
from logicenveval.model.task import Leaf, Node, Subtask, Task


@dataclass(frozen=True, slots=True)
class DecisionPath:
    subtask: str
    steps: tuple[tuple[str, str], ...]  # (variable, value) from the root down
    goal: str = "true"
    plan: tuple[str, ...] = ()

    @property
    def key(self) -> str:
        """Stable id, e.g. `tidy_toy:toy_on_floor=yes/toy_kind=doll`."""
        return self.subtask + ":" + "/".join(f"{v}={x}" for v, x in self.steps)

    def assignment(self) -> dict[str, str]:
        return dict(self.steps)


@dataclass(frozen=True, slots=True)
class Trajectory:
    """One decision path per subtask, in the task's subtask order."""

    paths: tuple[DecisionPath, ...]

    @property
    def key(self) -> str:
        return " | ".join(p.key for p in self.paths)

    def as_claim(self) -> dict[str, dict[str, str]]:
        """The EnvSpec `claimed_trajectory` form: subtask -> {variable: value}."""
        return {p.subtask: p.assignment() for p in self.paths}

    def assignment(self) -> dict[str, str]:
        out: dict[str, str] = {}
        for p in self.paths:
            out.update(p.steps)
        return out


def tree_paths(subtask: Subtask) -> list[DecisionPath]:
    """All root-to-leaf paths of a subtask's tree, depth-first in branch order."""
    out: list[DecisionPath] = []

    def walk(node: Node | Leaf, steps: tuple[tuple[str, str], ...]) -> None:
        if isinstance(node, Leaf):
            out.append(DecisionPath(subtask.id, steps, node.goal, tuple(node.plan)))
            return
        for value, child in node.branches.items():
            walk(child, (*steps, (node.var, value)))

    walk(subtask.tree, ())
    return out


def task_paths(task: Task) -> list[list[DecisionPath]]:
    """Paths per subtask, in subtask order."""
    return [tree_paths(st) for st in task.subtasks]


def all_path_keys(task: Task) -> list[str]:
    return [p.key for paths in task_paths(task) for p in paths]


def atomic_conditions(task: Task) -> list[tuple[str, str]]:
    """C_total of paper Def. 1: every (variable, value) that appears on some tree edge."""
    seen: dict[tuple[str, str], None] = {}
    for paths in task_paths(task):
        for p in paths:
            for step in p.steps:
                seen.setdefault(step, None)
    return list(seen)


@dataclass(frozen=True, slots=True)
class TreeOutcome:
    """Result of evaluating one subtask's GT tree on a state."""

    subtask: str
    path: DecisionPath | None
    #: when `path` is None: the variable at which no branch (or more than one) held
    stuck_var: str | None = None
    holding_values: tuple[str, ...] = ()

    @property
    def reached(self) -> bool:
        return self.path is not None


def evaluate_tree(task: Task, subtask: Subtask, holds: Holds) -> TreeOutcome:
    """Follow the tree on `holds`; exactly one branch must hold at every internal node."""
    node: Node | Leaf = subtask.tree
    steps: list[tuple[str, str]] = []
    while isinstance(node, Node):
        var = task.variables[node.var]
        true_values = tuple(v for v in node.branches if evaluate(var.condition(v), holds))
        if len(true_values) != 1:
            return TreeOutcome(subtask.id, None, node.var, true_values)
        steps.append((node.var, true_values[0]))
        node = node.branches[true_values[0]]
    return TreeOutcome(subtask.id, DecisionPath(subtask.id, tuple(steps), node.goal, tuple(node.plan)))


def evaluate_task(task: Task, holds: Holds) -> list[TreeOutcome]:
    return [evaluate_tree(task, st, holds) for st in task.subtasks]


def goal_of(outcomes: Iterable[TreeOutcome]) -> Cond | None:
    """Conjunction of the reached leaves' goals; None when some tree reached no leaf."""
    goals: list[Cond] = []
    for o in outcomes:
        if o.path is None:
            return None
        goals.append(parse(o.path.goal))
    return conjunction(goals)


def trajectory_from_claim(task: Task, claim: Mapping[str, Mapping[str, str]]) -> Trajectory:
    """Resolve a `{subtask: {var: value}}` claim to the decision paths it names.

    Raises KeyError/ValueError with a readable message when the claim does not match a path.
    """
    chosen: list[DecisionPath] = []
    for st, paths in zip(task.subtasks, task_paths(task), strict=True):
        wanted = dict(claim.get(st.id, {}))
        match = [p for p in paths if p.assignment() == wanted]
        if len(match) != 1:
            raise ValueError(
                f"claim for subtask {st.id!r} {wanted} matches no decision path; valid: "
                + "; ".join(p.key for p in paths)
            )
        chosen.append(match[0])
    return Trajectory(tuple(chosen))


def trajectory_from_assignment(task: Task, assignment: Mapping[str, str]) -> Trajectory:
    """Resolve a flat `var=value` assignment (e.g. from `--situation`) to a trajectory.

    Each subtask follows its tree using the given values; every variable met on the way must be
    assigned, and assigned variables must exist.
    """
    unknown = set(assignment) - set(task.variables)
    if unknown:
        raise ValueError(
            f"unknown variable(s) {sorted(unknown)}; task {task.id!r} has {sorted(task.variables)}"
        )
    chosen: list[DecisionPath] = []
    for st in task.subtasks:
        node: Node | Leaf = st.tree
        steps: list[tuple[str, str]] = []
        while isinstance(node, Node):
            if node.var not in assignment:
                raise ValueError(
                    f"subtask {st.id!r} needs a value for {node.var!r} "
                    f"(one of {list(node.branches)})"
                )
            value = assignment[node.var]
            if value not in node.branches:
                raise ValueError(
                    f"{node.var}={value!r} is not a value; use one of {list(node.branches)}"
                )
            steps.append((node.var, value))
            node = node.branches[value]
        chosen.append(DecisionPath(st.id, tuple(steps), node.goal, tuple(node.plan)))
    return Trajectory(tuple(chosen))
