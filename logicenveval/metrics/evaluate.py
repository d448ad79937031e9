"""GT evaluation of one environment: which decision paths it realises, and is it well-formed.

Well-formedness comes first (DESIGN.md §7): every GT tree must reach exactly one leaf, and every
task role must be bound to an object unless the reached path itself requires `not exists(role)`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.model.conditions import (
    And,
    Cond,
    Holds,
    Not,
    Pred,
    atoms,
    evaluate,
    subject_roles,
)
from logicenveval.model.task import Task
from logicenveval.model.tree import DecisionPath, Trajectory, atomic_conditions, evaluate_task

if TYPE_CHECKING:
    from logicenveval.domain.catalog import Catalog
    from logicenveval.model.envspec import EnvSpec


class Coverage(BaseModel):
    model_config = ConfigDict(frozen=True)
    #: `DecisionPath.key` of every tree that reached a leaf, in subtask order
    covered_paths: list[str] = Field(default_factory=list)
    #: `Trajectory.key` when every tree reached a leaf, else None
    trajectory: str | None = None
    #: atomic conditions (variable, value) the environment realises, on a reached path or not
    #: (paper Def. 1: the variable takes the value in the environment)
    conditions: list[tuple[str, str]] = Field(default_factory=list)
    well_formed: bool = False
    problems: list[str] = Field(default_factory=list)


def _absent_roles(cond: Cond) -> set[str]:
    """Roles whose absence the condition requires (`not exists(r)` as a top-level conjunct)."""
    if isinstance(cond, Not) and isinstance(cond.operand, Pred) and cond.operand.name == "exists":
        return {cond.operand.args[0]}
    if isinstance(cond, And):
        return set().union(*(_absent_roles(c) for c in cond.operands))
    return set()


def coverage(task: Task, holds: Holds, bound_roles: Mapping[str, str | None]) -> Coverage:
    """Evaluate the GT trees on `holds` (the initial state) given `role -> object id or None`."""
    reached: list[DecisionPath] = []
    problems: list[str] = []
    for outcome in evaluate_task(task, holds):
        if outcome.path is None:
            held = list(outcome.holding_values)
            why = "no value holds" if not held else f"several values hold {held}"
            problems.append(
                f"subtask {outcome.subtask}: variable {outcome.stuck_var} reaches no leaf ({why})"
            )
        else:
            reached.append(outcome.path)
    absent_ok: set[str] = set()
    for path in reached:
        for var, value in path.steps:
            absent_ok |= _absent_roles(task.variables[var].condition(value))
    for role in task.roles:
        if bound_roles.get(role) is None and role not in absent_ok:
            problems.append(f"role {role} is not bound to an object and no reached path allows it")
    conditions = realised_conditions(task, holds, bound_roles)
    complete = len(reached) == len(task.subtasks)
    return Coverage(
        covered_paths=[p.key for p in reached],
        trajectory=Trajectory(tuple(reached)).key if complete else None,
        conditions=list(conditions),
        well_formed=not problems,
        problems=problems,
    )


def realised_conditions(task: Task, holds: Holds, bound_roles: Mapping[str, str | None]) -> list[tuple[str, str]]:
    """Every (variable, value) of C_total (paper Def. 1) that the environment realises: exactly one
    of the variable's values holds, and every role its values speak of is present unless they
    ask about existence itself (a toy's kind is no value of a room without a toy)."""
    out: list[tuple[str, str]] = []
    edges = set(atomic_conditions(task))
    for name in dict.fromkeys(v for v, _ in atomic_conditions(task)):
        var = task.variables[name]
        conds = [var.condition(value) for value in var.values]
        about_existence = any(a.name == "exists" for c in conds for a in atoms(c))
        if not about_existence and any(bound_roles.get(r) is None for c in conds for r in subject_roles(c)
                                       if r in task.roles):
            continue
        held = [value for value, c in zip(var.values, conds, strict=True) if evaluate(c, holds)]
        if len(held) == 1 and (name, held[0]) in edges:
            out.append((name, held[0]))
    return out


def coverage_of_env(task: Task, env: EnvSpec, catalog: Catalog | None = None) -> Coverage:
    """`coverage` on an EnvSpec through the simulator's initial-state predicate evaluator."""
    from logicenveval.sim.world import holds_initial  # the simulator is heavy; import on use

    return coverage(task, holds_initial(env, catalog), env.roles)
