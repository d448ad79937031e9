"""Conditions as structured JSON on the wire, the condition language inside.

A model writes a condition as a list of literals (a conjunction), each one predicate with named,
vocabulary-bound arguments — `{"predicate": "on", "object": "toy", "support": "floor",
"negated": false}` — instead of a string such as `on(toy, floor)` whose syntax a small model
gets wrong and a grammar cannot check. `to_text` turns a validated list into the condition
language of DESIGN.md §3; `literals_of` is the inverse, for the rule-based models. Every
condition of the benchmark's tasks and of the offline analyser is a conjunction of literals.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.errors import ConditionSyntaxError
from logicenveval.llm.vocab import Vocab
from logicenveval.model.conditions import STATE_FLAGS, And, Cond, Const, Not, Pred, parse

_F = ConfigDict(frozen=True, extra="forbid")

Role = Annotated[str, Vocab("roles", "a role name of the task")]
Flag = Literal[STATE_FLAGS]  # type: ignore[valid-type]


class OnLit(BaseModel):
    model_config = _F
    predicate: Literal["on"]
    object: Role
    support: Annotated[str, Vocab("places", "a role name, or floor")]
    negated: bool


class InsideLit(BaseModel):
    model_config = _F
    predicate: Literal["inside"]
    object: Role
    container: Role
    negated: bool


class InRoomLit(BaseModel):
    model_config = _F
    predicate: Literal["in_room"]
    object: Role
    room: Annotated[str, Vocab("rooms", "a room id of the task")]
    negated: bool


class StateLit(BaseModel):
    model_config = _F
    predicate: Literal["state"]
    object: Role
    flag: Flag
    negated: bool


class AttrLit(BaseModel):
    model_config = _F
    predicate: Literal["attr"]
    object: Role
    key: Annotated[str, Vocab("attr_keys", "attribute name, e.g. color, kind")]
    value: Annotated[str, Vocab("attr_values", "attribute value, e.g. red, novel")]
    negated: bool


class ExistsLit(BaseModel):
    model_config = _F
    predicate: Literal["exists"]
    object: Role
    negated: bool


LiteralDraft = Annotated[Union[OnLit, InsideLit, InRoomLit, StateLit, AttrLit, ExistsLit],  # noqa: UP007
                         Field(discriminator="predicate")]
#: a condition: all literals hold (at least one)
Conjunction = Annotated[list[LiteralDraft], Field(min_length=1, max_length=3)]
#: a goal: all literals hold; empty = nothing to check
Goal = Annotated[list[LiteralDraft], Field(default_factory=list, max_length=3)]


def literal_text(lit: BaseModel) -> str:
    data = lit.model_dump()
    pred = data["predicate"]
    args = [data["object"]] + [data[k] for k in ("support", "container", "room", "flag", "key", "value")
                               if k in data]
    text = f"{pred}({', '.join(args)})"
    return f"not {text}" if data["negated"] else text


def to_text(literals: list[Any]) -> str:
    """The condition-language form of a conjunction (`true` when empty)."""
    return " and ".join(literal_text(lit) for lit in literals) or "true"


_ARG_NAMES = {"on": ("support",), "inside": ("container",), "in_room": ("room",), "state": ("flag",),
              "attr": ("key", "value"), "exists": ()}


def literals_of(text: str) -> list[dict[str, Any]]:
    """The wire form of a condition that is a conjunction of (negated) predicates."""
    cond = parse(text)
    if isinstance(cond, Const) and cond.value:
        return []
    parts: tuple[Cond, ...] = cond.operands if isinstance(cond, And) else (cond,)
    out = []
    for part in parts:
        negated = isinstance(part, Not)
        atom = part.operand if isinstance(part, Not) else part
        if not isinstance(atom, Pred) or atom.name not in _ARG_NAMES:
            raise ConditionSyntaxError(f"{text!r} is not a conjunction of literals",
                                       hint="write conditions as and-ed (negated) predicates")
        item: dict[str, Any] = {"predicate": atom.name, "object": atom.args[0]}
        item.update(zip(_ARG_NAMES[atom.name], atom.args[1:], strict=True))
        item["negated"] = negated
        out.append(item)
    return out
