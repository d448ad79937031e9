"""GT evaluation of one environment: which decision paths it realises, and is it well-formed.

Well-formedness comes first (DESIGN.md §7): every GT tree must reach exactly one leaf, and every
task role must be bound to an object unless it is optional (the description lets it be absent)
or the reached path itself requires `not exists(role)`. Validity then also needs the task's
explicit constraints (`constraint_problems`): an environment that violates one is well-formed
(it is judged) but not a valid scenario.
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
    from logicenveval.domain.roles import RoleBinding
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


def coverage(task: Task, holds: Holds, bound_roles: Mapping[str, str | None],
             binding: RoleBinding | None = None) -> Coverage:
    """Evaluate the GT trees on `holds` (the initial state) given `role -> object id or None`.

    With the `binding` that produced `bound_roles`, an unbound role gets one message: its
    ambiguity (already among the binding's problems, so not repeated here) or what the nearest
    objects lack (`binding.why`)."""
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
    for role, spec in task.roles.items():
        if bound_roles.get(role) is not None or role in absent_ok or spec.optional:
            continue
        if binding is not None and role in binding.candidates:
            continue
        lacks = binding.why.get(role) if binding is not None else None
        problems.append(f"role {role} is not bound to an object and no reached path allows it"
                        + (f": {lacks}" if lacks else ""))
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


def constraint_problems(task: Task, env: EnvSpec, holds: Holds) -> list[str]:
    """One message per task constraint `env` violates, naming the fact, the description's words
    and what the environment has instead."""
    out = []
    for c in task.violated(holds, env.roles):
        out.append(f"violates the task's constraint {c.fact} (the description: \"{c.says}\")"
                   + _instead(c.condition(), env))
    return out


def _instead(cond: Cond, env: EnvSpec) -> str:
    """What the environment has instead of a violated one-atom fact (`; red_box (box_2) has
    color=blue`); "" for compound facts."""
    negated = isinstance(cond, Not)
    p = cond.operand if isinstance(cond, Not) else cond
    if not isinstance(p, Pred) or p.name == "exists":
        return ""
    oid = env.roles.get(p.args[0], p.args[0])
    obj = next((o for o in env.objects if o.id == oid), None)
    if obj is None:
        return f"; {p.args[0]} is not in the environment" if not negated else ""
    who = p.args[0] if oid == p.args[0] else f"{p.args[0]} ({oid})"
    if p.name == "attr" and not negated:
        got = obj.attributes.get(p.args[1])
        return f"; {who} has " + (f"{p.args[1]}={got}" if got is not None else f"no {p.args[1]}")
    if p.name == "state":
        return f"; {who} is {'' if negated else 'not '}{p.args[1]}"
    if p.name in ("on", "inside") and not negated:
        return f"; {who} is " + (f"inside {obj.container}" if obj.container else f"on {obj.support}")
    return ""


def coverage_of_env(task: Task, env: EnvSpec, catalog: Catalog | None = None) -> Coverage:
    """`coverage` on an EnvSpec through the simulator's initial-state predicate evaluator."""
    from logicenveval.sim.world import holds_initial  # the simulator is heavy; import on use

    return coverage(task, holds_initial(env, catalog), env.roles)
