"""Task, roles, variables and ground-truth decision trees (DESIGN.md §4), as frozen pydantic data.

Only structure is checked here (fields, types, condition syntax, references between variables,
trees and roles). Semantic checks that need a solver or the simulator (exclusive/exhaustive
values, policies passing) live in `logicenveval.benchmark_validation`.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Annotated, Any, TypeVar, Union

from pydantic import BaseModel, ConfigDict, Field, StrictBool, field_validator, model_validator

from logicenveval.limits import limit, raise_hint
from logicenveval.model.conditions import (
    AGENT_PREDICATES,
    Cond,
    Holds,
    atoms,
    evaluate,
    parse,
    subject_roles,
)
from logicenveval.model.rooms import ROOM_TYPES

POLICY_KINDS: tuple[str, ...] = ("correct", "counterfactual", "unreachable", "lackbranch")
FAULTY_KINDS: tuple[str, ...] = ("counterfactual", "unreachable", "lackbranch")

_Frozen = ConfigDict(frozen=True, extra="forbid")


def _check_condition(text: str) -> str:
    parse(text)
    return text


class Role(BaseModel):
    """A named object the policies use; generators must bind it to an object of the right kind."""

    model_config = _Frozen
    category: str = Field(min_length=1)
    attributes: dict[str, str] = Field(default_factory=dict)
    description: str | None = None
    #: the description lets the object be absent ("may", "if there are any", "if available"):
    #: an environment without it is well-formed and every predicate about it is false. Strict:
    #: `"yes"`, `"false"` or `1` are refused, not read as a truth value (a typo must not make
    #: a required role optional)
    optional: StrictBool = False


class Constraint(BaseModel):
    """A fact the task description fixes in every situation, with the words that assert it.

    `fact` is a condition on the initial state (`attr(red_box, color, red)`, `state(mark, dirty)`);
    `says` quotes the description. A fact about an optional role binds only when the role is
    present. An environment that violates a constraint is not a valid scenario."""

    model_config = _Frozen
    fact: str = Field(min_length=1)
    says: str = Field(min_length=1)

    @field_validator("fact")
    @classmethod
    def _fact_parses(cls, fact: str) -> str:
        cond = parse(fact)
        agent = [p.name for p in atoms(cond) if p.name in AGENT_PREDICATES]
        if agent:
            raise ValueError(f"predicate {agent[0]!r} speaks about the agent; constraints describe "
                             "the initial environment only")
        return fact

    def condition(self) -> Cond:
        return parse(self.fact)


class Variable(BaseModel):
    """An uncertain factor: a question and its mutually exclusive values, each a condition."""

    model_config = _Frozen
    question: str = Field(min_length=1)
    values: dict[str, str] = Field(min_length=2)

    @field_validator("values")
    @classmethod
    def _values_parse(cls, values: dict[str, str]) -> dict[str, str]:
        for text in values.values():
            cond = parse(text)
            agent = [p.name for p in atoms(cond) if p.name in AGENT_PREDICATES]
            if agent:
                raise ValueError(
                    f"predicate {agent[0]!r} speaks about the agent; variables describe the "
                    "initial environment only"
                )
        return values

    def condition(self, value: str) -> Cond:
        return parse(self.values[value])


class Leaf(BaseModel):
    """A leaf of a decision tree: the plan for this situation and the goal it must achieve."""

    model_config = _Frozen
    plan: list[str] = Field(default_factory=list)
    goal: str = "true"

    @field_validator("goal")
    @classmethod
    def _goal_parses(cls, goal: str) -> str:
        return _check_condition(goal)


class Node(BaseModel):
    """An internal node: a query bound to variable `var`; its edges are the variable's values."""

    model_config = _Frozen
    var: str = Field(min_length=1)
    branches: dict[str, Tree] = Field(min_length=1)


Tree = Annotated[Union[Node, Leaf], Field(union_mode="smart")]  # noqa: UP007
Node.model_rebuild()


class Subtask(BaseModel):
    model_config = _Frozen
    id: str = Field(min_length=1)
    description: str = ""
    tree: Tree


class TaskBrief(BaseModel):
    """What a generator is given (DESIGN.md §4): never variables, subtasks or policies."""

    model_config = _Frozen
    id: str
    description: str
    rooms: list[str]
    roles: dict[str, Role]


class Task(BaseModel):
    model_config = _Frozen
    id: str = Field(min_length=1, pattern=r"^[a-z0-9_]+$")
    description: str = Field(min_length=1)
    rooms: list[str] = Field(min_length=1)
    roles: dict[str, Role] = Field(min_length=1)
    variables: dict[str, Variable]
    subtasks: list[Subtask] = Field(min_length=1)
    policies: dict[str, str] = Field(default_factory=dict)
    #: facts the description fixes in every situation (docs/task-format.md, "Constraints")
    constraints: list[Constraint] = Field(default_factory=list)

    @field_validator("roles")
    @classmethod
    def _few_roles(cls, roles: dict[str, Role]) -> dict[str, Role]:
        return _bounded(roles, "roles", "max_task_roles")

    @field_validator("constraints")
    @classmethod
    def _few_constraints(cls, constraints: list[Constraint]) -> list[Constraint]:
        return _bounded(constraints, "constraints", "max_task_constraints")

    @model_validator(mode="after")
    def _references(self) -> Task:
        ids = [s.id for s in self.subtasks]
        if len(set(ids)) != len(ids):
            raise ValueError(f"subtask ids must be unique, got {ids}")
        known = set(self.roles) | set(self.rooms) | set(ROOM_TYPES) | {"floor"}
        said = _words(self.description)
        for k, c in enumerate(self.constraints):
            _check_args(c.condition(), known, f"constraints.{k}.fact")
            if _words(c.says) not in said:
                raise ValueError(f"constraints.{k}.says: {c.says!r} is not in the task description; "
                                 "quote the words of the description that assert the fact")
            if len(content_words(c.says)) < MIN_QUOTE_WORDS:
                raise ValueError(f"constraints.{k}.says: {c.says!r} quotes fewer than "
                                 f"{MIN_QUOTE_WORDS} content words; quote the phrase of the "
                                 "description that asserts the fact, not a word it happens to hold")
        for name, var in self.variables.items():
            for value, text in var.values.items():
                _check_args(parse(text), known, f"variables.{name}.values.{value}")
        seen_vars: dict[str, str] = {}
        for st in self.subtasks:
            for path, node in _walk(st.tree, f"subtasks.{st.id}.tree"):
                if isinstance(node, Node):
                    if node.var not in self.variables:
                        raise ValueError(f"{path}: variable {node.var!r} is not declared")
                    declared = set(self.variables[node.var].values)
                    if set(node.branches) != declared:
                        raise ValueError(
                            f"{path}: branches {sorted(node.branches)} must be exactly the values "
                            f"{sorted(declared)} of variable {node.var!r}"
                        )
                    owner = seen_vars.setdefault(node.var, st.id)
                    if owner != st.id:
                        raise ValueError(
                            f"{path}: variable {node.var!r} is used by subtasks {owner!r} and "
                            f"{st.id!r}; subtasks must be independent"
                        )
                else:
                    _check_args(parse(node.goal), known, f"{path}.goal")
        for kind in self.policies:
            if kind not in POLICY_KINDS:
                raise ValueError(f"policies: unknown kind {kind!r}; use {list(POLICY_KINDS)}")
        return self

    def brief(self) -> TaskBrief:
        return TaskBrief(id=self.id, description=self.description, rooms=self.rooms, roles=self.roles)

    def violated(self, holds: Holds, roles: Mapping[str, str | None]) -> list[Constraint]:
        """The constraints that do not hold in `holds`, given `role -> object id or None`.

        A constraint naming a role that `roles` leaves unbound is not checked: for an optional
        role the description asserts it only of an object that is there, and a required role
        left unbound already makes the environment ill-formed (one message, not two)."""
        absent = {r for r in self.roles if roles.get(r) is None}
        out = []
        for c in self.constraints:
            cond = c.condition()
            if any(a in absent for p in atoms(cond) for a in p.args):
                continue
            if not evaluate(cond, holds):
                out.append(c)
        return out

    def subtask(self, subtask_id: str) -> Subtask:
        for st in self.subtasks:
            if st.id == subtask_id:
                return st
        raise KeyError(subtask_id)

    def subtask_roles(self, subtask: Subtask) -> set[str]:
        """Roles tested by the variables of one subtask (first predicate arguments)."""
        roles: set[str] = set()
        for _, node in _walk(subtask.tree, ""):
            if isinstance(node, Node):
                for text in self.variables[node.var].values.values():
                    roles |= subject_roles(parse(text))
        return roles & set(self.roles)


#: content words a constraint's `says` must hold at least: one word ("the", "kitchen") occurs in
#: almost any description, so it would let a fact be invented; every shipped quote names at least
#: an object and what is said of it ("a ceiling lamp", "The floor is stained")
MIN_QUOTE_WORDS = 2
#: function words that carry no content of their own (articles, pronouns, prepositions,
#: conjunctions, auxiliaries): a quote of only these asserts nothing
_FUNCTION_WORDS = """
a an the this that these those it its they them their there here he she his her we our
you your i me my one ones some any all each every no not of in on at to into onto from by with
for as and or but if then so than is are was were be been being am has have had do does did
can could may might must shall should will would s t d ll re ve m
"""
FUNCTION_WORDS = frozenset(_FUNCTION_WORDS.split())


def content_words(text: str) -> list[str]:
    """The words of `text` that are not function words (`FUNCTION_WORDS`)."""
    return [w for w in _words(text).split() if w not in FUNCTION_WORDS]


_Sized = TypeVar("_Sized", dict[str, Role], list[Constraint])


def _bounded(items: _Sized, what: str, name: str) -> _Sized:
    """`items`, unless there are more than the limit `name` of them (every situation of the
    task is solved with all of them: their number drives the time of validation and of units)."""
    cap = limit(name)
    if len(items) > cap:
        raise ValueError(f"{len(items)} {what}, more than the limit of {cap}; "
                         + raise_hint(name))
    return items


def _words(text: str) -> str:
    """`text` lower-cased with runs of non-letters as one space (quotes match despite punctuation)."""
    return " " + " ".join(re.findall(r"[a-z0-9]+", text.lower())) + " "


def _walk(tree: Node | Leaf, path: str) -> list[tuple[str, Node | Leaf]]:
    out: list[tuple[str, Node | Leaf]] = [(path, tree)]
    if isinstance(tree, Node):
        for value, child in tree.branches.items():
            out.extend(_walk(child, f"{path}.branches.{value}"))
    return out


def _check_args(cond: Cond, known: set[str], where: str) -> None:
    for pred in atoms(cond):
        names = pred.args[:1] if pred.name in ("attr", "state") else pred.args
        for arg in names:
            if arg not in known:
                raise ValueError(
                    f"{where}: {pred.name}(...) names {arg!r}, which is neither a role nor a room "
                    "of the task nor 'floor'"
                )


def task_from_dict(data: dict[str, Any]) -> Task:
    """Validate a task dictionary (pydantic errors propagate; callers attach the file name)."""
    return Task.model_validate(data)
