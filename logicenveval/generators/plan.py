"""Behaviour plan derivation (paper §3.1): decomposition, factors, decision trees, verification.

The LLM proposes subtasks, uncertain factors and trees; rule-guided verification checks
(a) independence of subtasks (no shared factor, no shared tested role), (b) syntax/schema,
(c) every internal node grounded in an identified factor, and (d) every factor value a condition
on the task's roles (DESIGN.md §3). Violations go back to the LLM as feedback, a bounded number
of times; what still fails is repaired by rule (merge dependent subtasks, drop ungrounded
factors) and logged, so the plan is always a valid `Task` built from the brief alone.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from pydantic import ValidationError

from logicenveval.errors import ConditionSyntaxError, LogicEnvEvalError
from logicenveval.generators.base import GenerationContext
from logicenveval.llm.ask import ask
from logicenveval.llm.replies import (
    DecomposeReply,
    FactorDraft,
    FactorsReply,
    PlanLeaf,
    QueryNode,
    SubtaskDraft,
    TreeReply,
)
from logicenveval.model.conditions import AGENT_PREDICATES, atoms, parse, subject_roles
from logicenveval.model.rooms import ROOM_TYPES
from logicenveval.model.task import Task, TaskBrief
from logicenveval.validation import first_error


@dataclass
class PlanLog:
    """What happened during derivation: refinements, repairs and their reasons."""

    events: list[dict[str, Any]] = field(default_factory=list)

    def add(self, stage: str, message: str, **extra: Any) -> None:
        self.events.append({"stage": stage, "message": message, **extra})


def _payload(brief: TaskBrief, **extra: Any) -> dict[str, Any]:
    return {"task": brief.model_dump(mode="json"), **extra}


def check_factor(brief: TaskBrief, factor: FactorDraft) -> list[str]:
    """Rule (d): every value parses and speaks about the task's roles (or rooms/floor)."""
    problems = []
    known = set(brief.roles) | set(brief.rooms) | set(ROOM_TYPES) | {"floor"}
    for value, text in factor.values.items():
        try:
            cond = parse(text)
        except ConditionSyntaxError as exc:
            problems.append(f"factor {factor.id!r} value {value!r}: {exc.message} (column {exc.column})")
            continue
        for pred in atoms(cond):
            if pred.name in AGENT_PREDICATES:
                problems.append(f"factor {factor.id!r} value {value!r} uses {pred.name}(...), which "
                                "describes the agent, not the initial environment")
            names = pred.args[:1] if pred.name in ("attr", "state") else pred.args
            for arg in names:
                if arg not in known:
                    problems.append(f"factor {factor.id!r} value {value!r} names {arg!r}, which is not "
                                    f"a role, a room or floor; roles are {sorted(brief.roles)}")
    return problems


def _tree_vars(node: QueryNode | PlanLeaf) -> list[str]:
    if isinstance(node, PlanLeaf):
        return []
    out = [node.var]
    for child in node.branches.values():
        out += _tree_vars(child)
    return out


def check_tree(tree: QueryNode | PlanLeaf, factors: dict[str, FactorDraft]) -> list[str]:
    """Rules (b) and (c): queries grounded in identified factors, branches = their responses."""
    problems = []

    def walk(node: QueryNode | PlanLeaf, path: str) -> None:
        if isinstance(node, PlanLeaf):
            try:
                parse(node.goal)
            except ConditionSyntaxError as exc:
                problems.append(f"{path}: goal {node.goal!r} does not parse: {exc.message}")
            return
        if node.var not in factors:
            problems.append(f"{path}: query {node.var!r} is not one of the identified factors "
                            f"{sorted(factors)}")
            return
        expected = set(factors[node.var].values)
        if set(node.branches) != expected:
            problems.append(f"{path}: branches {sorted(node.branches)} must be exactly the responses "
                            f"{sorted(expected)} of {node.var!r}")
        for value, child in node.branches.items():
            walk(child, f"{path}/{node.var}={value}")

    walk(tree, "root")
    seen = _tree_vars(tree)
    for var in set(seen):
        if seen.count(var) > 1 and _repeats_on_one_path(tree, var):
            problems.append(f"query {var!r} is asked twice on one path")
    return problems


def _repeats_on_one_path(node: QueryNode | PlanLeaf, var: str, seen: bool = False) -> bool:
    if isinstance(node, PlanLeaf):
        return False
    if node.var == var and seen:
        return True
    return any(_repeats_on_one_path(c, var, seen or node.var == var) for c in node.branches.values())


@dataclass
class DerivedPlan:
    task: Task  # the generator's own plan as a Task (its variables and trees, not the GT)
    log: PlanLog

    def as_json(self) -> dict[str, Any]:
        return {
            "subtasks": [s.model_dump(mode="json") for s in self.task.subtasks],
            "factors": {k: v.model_dump(mode="json") for k, v in self.task.variables.items()},
            "log": self.log.events,
        }


def derive_plan(brief: TaskBrief, ctx: GenerationContext, *, max_refinements: int = 2) -> DerivedPlan:
    """Decompose, identify factors and build trees with bounded rule-guided refinement."""
    log = PlanLog()
    decomposition = ask(ctx.model, "decompose_task", _payload(brief), DecomposeReply, seed=ctx.seed)
    subtasks = [s for s in decomposition.subtasks if s.roles or s.description]
    factors_of: dict[str, list[FactorDraft]] = {}
    for st in subtasks:
        feedback: list[str] = []
        for attempt in range(max_refinements + 1):
            reply = ask(ctx.model, "identify_factors",
                        _payload(brief, subtask=st.model_dump(), feedback=feedback),
                        FactorsReply, seed=ctx.seed)
            feedback = [p for f in reply.factors for p in check_factor(brief, f)]
            if not feedback:
                break
            log.add("identify_factors", "refine", subtask=st.id, attempt=attempt, problems=feedback)
        good = [f for f in reply.factors if not check_factor(brief, f)]
        dropped = [f.id for f in reply.factors if f not in good]
        if dropped:
            log.add("identify_factors", "dropped factors that stay ungrounded", subtask=st.id,
                    factors=dropped)
        factors_of[st.id] = good
    subtasks, factors_of = _independent(subtasks, factors_of, log)
    trees: dict[str, QueryNode | PlanLeaf] = {}
    for st in subtasks:
        factors = {f.id: f for f in factors_of[st.id]}
        feedback = []
        tree: QueryNode | PlanLeaf = PlanLeaf(plan=[st.description], goal="true")
        for attempt in range(max_refinements + 1):
            kind = "build_tree" if attempt == 0 else "refine_tree"
            reply_tree = ask(ctx.model, kind, _payload(
                brief, subtask=st.model_dump(), factors=[f.model_dump() for f in factors.values()],
                feedback=feedback, tree=tree.model_dump() if attempt else None), TreeReply, seed=ctx.seed)
            tree = reply_tree.tree
            feedback = check_tree(tree, factors)
            if not feedback:
                break
            log.add(kind, "refine", subtask=st.id, attempt=attempt, problems=feedback)
        if feedback:
            tree = _prune(tree, factors)
            log.add("build_tree", "pruned queries that stay ungrounded", subtask=st.id)
        trees[st.id] = tree
    return DerivedPlan(_as_task(brief, subtasks, factors_of, trees, log), log)


def _independent(
    subtasks: list[SubtaskDraft], factors_of: dict[str, list[FactorDraft]], log: PlanLog
) -> tuple[list[SubtaskDraft], dict[str, list[FactorDraft]]]:
    """Rule (a): subtasks that share a factor id or a tested role are merged."""
    merged: list[SubtaskDraft] = []
    merged_factors: dict[str, list[FactorDraft]] = {}
    for st in subtasks:
        tested = {r for f in factors_of[st.id] for t in f.values.values() for r in subject_roles(parse(t))}
        ids = {f.id for f in factors_of[st.id]}
        target = next((m for m in merged if ids & {f.id for f in merged_factors[m.id]} or tested & {
            r for f in merged_factors[m.id] for t in f.values.values() for r in subject_roles(parse(t))}), None)
        if target is None:
            merged.append(st)
            merged_factors[st.id] = list(factors_of[st.id])
            continue
        log.add("verify", "merged dependent subtasks", into=target.id, merged=st.id)
        idx = merged.index(target)
        merged[idx] = SubtaskDraft(id=target.id, description=f"{target.description}; {st.description}",
                                   roles=list(dict.fromkeys(target.roles + st.roles)))
        known = {f.id for f in merged_factors[target.id]}
        merged_factors[target.id] = merged_factors.pop(target.id) + [
            f for f in factors_of[st.id] if f.id not in known]
    return merged, merged_factors


def _prune(node: QueryNode | PlanLeaf, factors: dict[str, FactorDraft]) -> QueryNode | PlanLeaf:
    """Drop ungrounded queries (keep their first branch) and fix branch sets to the responses."""
    if isinstance(node, PlanLeaf):
        return node if _parses(node.goal) else PlanLeaf(plan=node.plan, goal="true")
    if node.var not in factors:
        return _prune(next(iter(node.branches.values())), factors)
    first = next(iter(node.branches.values()))
    branches = {v: _prune(node.branches.get(v, first), factors) for v in factors[node.var].values}
    return QueryNode(var=node.var, query=node.query, branches=branches)


def _parses(text: str) -> bool:
    try:
        parse(text)
    except ConditionSyntaxError:
        return False
    return True


def _node_json(node: QueryNode | PlanLeaf) -> dict[str, Any]:
    if isinstance(node, PlanLeaf):
        return {"plan": list(node.plan), "goal": node.goal}
    return {"var": node.var, "branches": {v: _node_json(c) for v, c in node.branches.items()}}


def _as_task(
    brief: TaskBrief,
    subtasks: list[SubtaskDraft],
    factors_of: dict[str, list[FactorDraft]],
    trees: dict[str, QueryNode | PlanLeaf],
    log: PlanLog,
) -> Task:
    used: set[str] = set()
    variables: dict[str, Any] = {}
    subtask_json = []
    for st in subtasks:
        factors = {f.id: f for f in factors_of[st.id]}
        tree = trees[st.id]
        for var in _tree_vars(tree):
            if var in used and var not in variables:
                continue
            used.add(var)
            variables[var] = {"question": factors[var].question, "values": dict(factors[var].values)}
        subtask_json.append({"id": st.id, "description": st.description, "tree": _node_json(tree)})
    data = {"id": brief.id, "description": brief.description, "rooms": brief.rooms,
            "roles": {k: v.model_dump() for k, v in brief.roles.items()},
            "variables": variables, "subtasks": subtask_json}
    try:
        return Task.model_validate(data)
    except (ValidationError, LogicEnvEvalError) as exc:
        msg = first_error(exc)[1] if isinstance(exc, ValidationError) else str(exc)
        log.add("verify", "plan rejected by the task schema; falling back to one leaf per subtask",
                error=msg)
        data["variables"] = {}
        data["subtasks"] = [{"id": s.id, "description": s.description, "tree": {"plan": [], "goal": "true"}}
                            for s in subtasks]
        return Task.model_validate(data)
