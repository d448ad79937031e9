"""Behaviour plan derivation (paper §3.1): decomposition, factors, decision trees, verification.

The LLM proposes subtasks, uncertain factors and trees (grown one question at a time, in the
task's own vocabulary); rule-guided verification checks
(a) independence of subtasks (no shared factor, no shared tested role), (b) syntax/schema,
(c) every internal node grounded in an identified factor, and (d) every factor value a condition
on the task's roles (DESIGN.md §3) that their kinds can meet (from request protocol 6 on:
`generators.feasibility`) and that can hold at all (from protocol 7 on: `logic.axioms`; a tree
then asks on a path only factors whose every response the path leaves possible). Violations go back to the LLM as feedback, a bounded number
of times (rule (a): the decomposition is asked again with the dependent pairs named; rule (d):
the factors are asked again); what still fails is repaired by rule (merge dependent subtasks,
drop ungrounded factors) and logged, so the plan is always a valid `Task` built from the brief alone.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

from pydantic import BaseModel, ConfigDict, Field, ValidationError, create_model

from logicenveval.domain.catalog import Catalog
from logicenveval.errors import ConditionSyntaxError, LogicEnvEvalError, ModelReplyError
from logicenveval.generators.base import GenerationContext
from logicenveval.generators.feasibility import impossible
from logicenveval.llm.ask import ask, protocol_of
from logicenveval.llm.replies import (
    DecomposeWire,
    FactorDraft,
    FactorsWire,
    LeafWire,
    PlanLeaf,
    QueryNode,
    SubtaskDraft,
    TreeStepReply,
)
from logicenveval.llm.structured import to_text
from logicenveval.llm.vocab import SNAKE, Words
from logicenveval.logic.axioms import Axioms
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


def check_factor(brief: TaskBrief, factor: FactorDraft, catalog: Catalog | None = None,
                 axioms: bool = False) -> list[str]:
    """Rule (d): every value parses and speaks about the task's roles (or rooms/floor); given the
    catalog, every value can hold of the roles' kinds (`feasibility.impossible`); with `axioms`,
    every value can hold at all under the physical axioms (`logic.axioms`: nothing rests on
    itself or in two places, an attribute has one value)."""
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
        reasons = impossible(cond, brief.roles, catalog) if catalog is not None else []
        if axioms and not reasons and not Axioms(brief.roles, [cond]).possible(cond):
            reasons = [f"{text} can never hold: it puts an object on or in itself or in two places, "
                       "or gives one attribute two values"]
        problems += [f"factor {factor.id!r} value {value!r}: {why}; ask about something that can "
                     "differ between environments of this task" for why in reasons]
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


def plan_vocabulary(brief: TaskBrief) -> dict[str, Words]:
    """The words a plan reply may use: the task's roles and rooms, snake_case ids."""
    roles = sorted(brief.roles)
    return {"roles": roles, "places": [*roles, "floor"], "rooms": list(brief.rooms),
            "attr_keys": SNAKE, "attr_values": SNAKE, "ids": SNAKE}


#: bound on the tree_step questions of one subtask (a tree over many factors is cut into leaves)
MAX_TREE_STEPS = 64


def derive_plan(brief: TaskBrief, ctx: GenerationContext, *, max_refinements: int = 2) -> DerivedPlan:
    """Decompose, identify factors and grow trees step by step, with rule-guided refinement.

    Replies are bound to the task's vocabulary (`plan_vocabulary`). A tree is grown one question
    at a time (`tree_step`: which factor next on this path, or act), so its branches are the
    factor's responses and no factor repeats on a path by construction; its leaves' plans come
    in one `tree_leaves` request. A question that stays invalid after its re-asks is repaired by
    rule (no factors for that subtask, a leaf where the tree could not grow) and logged."""
    log = PlanLog()
    vocab = plan_vocabulary(brief)
    subtasks, factors_of = _decompose(brief, ctx, vocab, log, max_refinements, [])
    # request protocol 1 (packs recorded before issue 34) never re-asked the decomposition
    for attempt in range(max_refinements if protocol_of(ctx.model) > 1 else 0):
        feedback = dependence_problems(subtasks, factors_of)
        if not feedback:
            break
        log.add("verify", "refine the decomposition", attempt=attempt, problems=feedback)
        subtasks, factors_of = _decompose(brief, ctx, vocab, log, max_refinements, feedback)
    subtasks, factors_of = _independent(subtasks, factors_of, log)
    trees: dict[str, QueryNode | PlanLeaf] = {}
    for st in subtasks:
        factors = {f.id: f for f in factors_of[st.id]}
        tree = _grow_tree(brief, ctx, st, factors, log)
        problems = check_tree(tree, factors)
        if problems:  # cannot happen by construction; kept as the rule check of the paper
            log.add("verify", "tree rejected", subtask=st.id, problems=problems)
            tree = _prune(tree, factors)
        trees[st.id] = tree
    return DerivedPlan(_as_task(brief, subtasks, factors_of, trees, log), log)


def _decompose(brief: TaskBrief, ctx: GenerationContext, vocab: dict[str, Words], log: PlanLog,
               max_refinements: int, feedback: list[str]) -> tuple[list[SubtaskDraft], dict[str, list[FactorDraft]]]:
    """Subtasks (`decompose_task`, with rule (a)'s feedback when re-asked) and their factors."""
    extra = {"feedback": feedback} if feedback else {}
    decomposition = ask(ctx.model, "decompose_task", _payload(brief, **extra), DecomposeWire,
                        seed=ctx.seed, vocabulary=vocab)
    subtasks = [SubtaskDraft(id=s.id, description=s.description, roles=list(s.roles))
                for s in decomposition.subtasks if s.roles or s.description]
    subtasks = [s for i, s in enumerate(subtasks) if s.id not in {t.id for t in subtasks[:i]}]
    factors_of: dict[str, list[FactorDraft]] = {}
    for st in subtasks:
        factors_of[st.id] = _identify(brief, ctx, vocab, log, st, max_refinements)
    return subtasks, factors_of


def _identify(brief: TaskBrief, ctx: GenerationContext, vocab: dict[str, Words], log: PlanLog,
              st: SubtaskDraft, max_refinements: int) -> list[FactorDraft]:
    """The subtask's factors, re-asked with rule (d)'s feedback; ungrounded ones dropped. Packs
    recorded before protocol 6 were not asked again for a value their kinds cannot meet, nor
    before protocol 7 for a value no environment can meet, so their replay asks the same."""
    catalog = ctx.catalog if protocol_of(ctx.model) >= 6 else None
    axioms = protocol_of(ctx.model) >= 7
    feedback: list[str] = []
    checked: list[tuple[FactorDraft, list[str]]] = []  # each draft with its problems
    for attempt in range(max_refinements + 1):
        try:
            reply = ask(ctx.model, "identify_factors",
                        _payload(brief, subtask=st.model_dump(), feedback=feedback),
                        FactorsWire, seed=ctx.seed, vocabulary=vocab)
        except ModelReplyError as exc:
            log.add("identify_factors", "no valid reply; the subtask keeps no factors",
                    subtask=st.id, error=exc.message)
            return []
        checked = [(d, check_factor(brief, d, catalog, axioms)) for d in (f.draft() for f in reply.factors)]
        feedback = [p for _, problems in checked for p in problems]
        if not feedback:
            break
        log.add("identify_factors", "refine", subtask=st.id, attempt=attempt, problems=feedback)
    good = [f for f, problems in checked if not problems]
    dropped = [f.id for f, problems in checked if problems]
    if dropped:
        log.add("identify_factors", "dropped factors that stay ungrounded", subtask=st.id,
                factors=dropped)
    return good


def _tested(factors: list[FactorDraft]) -> set[str]:
    return {r for f in factors for t in f.values.values() for r in subject_roles(parse(t))}


def dependence_problems(subtasks: list[SubtaskDraft], factors_of: dict[str, list[FactorDraft]]) -> list[str]:
    """Rule (a) as feedback: one line per pair of subtasks sharing a factor id or a tested role."""
    problems = []
    for i, a in enumerate(subtasks):
        for b in subtasks[i + 1:]:
            shared = sorted({f.id for f in factors_of[a.id]} & {f.id for f in factors_of[b.id]}
                            | _tested(factors_of[a.id]) & _tested(factors_of[b.id]))
            if shared:
                problems.append(f"subtasks {a.id} and {b.id} both depend on {', '.join(shared)}: they "
                                "are not independent; make them one subtask or split them so that no "
                                "uncertain factor or tested object is shared")
    return problems


def _grow_tree(brief: TaskBrief, ctx: GenerationContext, st: SubtaskDraft,
               factors: dict[str, FactorDraft], log: PlanLog) -> QueryNode | PlanLeaf:
    """The subtask's tree, one `tree_step` question per node, then its leaves' plans.

    The root must ask one of the identified factors (they were identified because they change
    what the agent does); below it the model may act at any point."""
    base = _payload(brief, subtask=st.model_dump(), factors=[f.model_dump() for f in factors.values()])
    budget = [MAX_TREE_STEPS]
    leaves: list[list[tuple[str, str]]] = []
    opened = _open_factors(brief, factors) if protocol_of(ctx.model) >= 7 else None

    def grow(path: list[tuple[str, str]]) -> QueryNode | PlanLeaf:
        asked = {var for var, _ in path}
        remaining = [f for f in factors if f not in asked]
        if opened is not None:
            remaining = [f for f in remaining if opened(path, f)]
        if not remaining or budget[0] <= 0:
            leaves.append(path)
            return PlanLeaf(plan=[st.description], goal="true")
        budget[0] -= 1
        try:
            step = ask(ctx.model, "tree_step",
                       {**base, "path": [{"factor": v, "response": x} for v, x in path]},
                       TreeStepReply, seed=ctx.seed,
                       vocabulary={"next_steps": [*remaining, ACT] if path else remaining})
        except ModelReplyError as exc:
            log.add("tree_step", "no valid reply; a leaf here", subtask=st.id,
                    path=dict(path), error=exc.message)
            leaves.append(path)
            return PlanLeaf(plan=[st.description], goal="true")
        if step.next == ACT:
            leaves.append(path)
            return PlanLeaf(plan=[st.description], goal="true")
        var = step.next
        return QueryNode(var=var, query=factors[var].question,
                         branches={value: grow([*path, (var, value)]) for value in factors[var].values})

    tree = grow([])
    if not factors:
        return tree
    try:
        reply = ask(ctx.model, "tree_leaves",
                    {**base, "leaves": [[{"factor": v, "response": x} for v, x in p] for p in leaves]},
                    leaves_reply(len(leaves)), seed=ctx.seed, vocabulary=plan_vocabulary(brief))
    except ModelReplyError as exc:
        log.add("tree_leaves", "no valid reply; leaves keep the subtask description",
                subtask=st.id, error=exc.message)
        return tree
    plans = {tuple(p): leaf for p, leaf in zip(leaves, reply.leaves, strict=True)}  # type: ignore[attr-defined]

    def fill(node: QueryNode | PlanLeaf, path: list[tuple[str, str]]) -> QueryNode | PlanLeaf:
        if isinstance(node, PlanLeaf):
            leaf = plans[tuple(path)]
            return PlanLeaf(plan=list(leaf.plan), goal=to_text(list(leaf.goal)))
        return QueryNode(var=node.var, query=node.query, branches={
            v: fill(c, [*path, (node.var, v)]) for v, c in node.branches.items()})

    return fill(tree, [])


def _open_factors(brief: TaskBrief,
                  factors: dict[str, FactorDraft]) -> Callable[[list[tuple[str, str]], str], bool]:
    """Whether a factor is still open on a path: each of its responses can hold together with the
    responses the path took (`logic.axioms`). A factor the path decides ("is the bottle on the
    floor?" after "on the vanity? yes"), or one a response of which the path rules out, is not
    offered there, so no planned situation contradicts itself (from request protocol 7 on; a
    tree's branches stay exactly its query's responses, rule (c))."""
    conds = {(f, v): parse(t) for f, d in factors.items() for v, t in d.values.items()}
    axioms = Axioms(brief.roles, conds.values())

    def opened(path: list[tuple[str, str]], factor: str) -> bool:
        facts = [conds[step] for step in path]
        return all(axioms.possible(*facts, conds[factor, v]) for v in factors[factor].values)

    return opened


#: the `tree_step` answer that ends a path with a leaf
ACT = "act"


@lru_cache(maxsize=64)
def leaves_reply(n: int) -> type[BaseModel]:
    """The `tree_leaves` reply model for exactly `n` leaves (listed in the request's order)."""
    model: type[BaseModel] = create_model(
        "LeavesReply", __config__=ConfigDict(frozen=True, extra="ignore"),
        leaves=(list[LeafWire], Field(min_length=n, max_length=n,
                                      description="one entry per listed situation, in order")))
    return model


def _independent(
    subtasks: list[SubtaskDraft], factors_of: dict[str, list[FactorDraft]], log: PlanLog
) -> tuple[list[SubtaskDraft], dict[str, list[FactorDraft]]]:
    """Rule (a) by rule, once the re-asks did not make the subtasks independent: subtasks that
    share a factor id or a tested role are merged."""
    merged: list[SubtaskDraft] = []
    merged_factors: dict[str, list[FactorDraft]] = {}
    for st in subtasks:
        tested = _tested(factors_of[st.id])
        ids = {f.id for f in factors_of[st.id]}
        target = next((m for m in merged if ids & {f.id for f in merged_factors[m.id]}
                       or tested & _tested(merged_factors[m.id])), None)
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
