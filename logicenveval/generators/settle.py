"""LogicEnvGen's construction sets what its own situation says of one object (issue 46).

The paper's construction instantiates *each* logical trajectory: the selected objects and their
arrangement follow the trajectory's constraints ("object placements align with task-specific
requirements and trajectory constraints", §3.3). A selection reply that leaves one of them out
(Qwen2.5-Coder-1.5B's left the plate clean where its situation said `state(plate, dirty)`, the
toy on the shelf where it said `on(toy, floor)`) would otherwise build an environment of another
situation: every environment of a task then realised the same trajectory. Here the construction
sets what a situation fact states about one object outright — a state flag, an attribute, where
it rests, that it is absent — on the objects the model selected; what no single object's setting
can make true (an object that must exist, one that must not be on the floor) is left to the log and to
`realised_share`. The facts are the generator's own plan's, never the task's ground truth.
"""

from __future__ import annotations

from dataclasses import dataclass

from logicenveval.llm.replies import ObjectDraft
from logicenveval.model.conditions import Not, Pred, parse

#: placements an object rests on without another object
_GROUND = ("floor", "wall", "ceiling")


@dataclass(frozen=True)
class Settled:
    """The selection with the facts set, and what was set (for the construction log)."""

    objects: list[ObjectDraft]
    set: list[str]


def settle(objects: list[ObjectDraft], facts: list[str]) -> Settled:
    """`objects` with each fact that is one literal about a role's object made true: `state`
    and `attr` set (a negated `attr` removes the equal value), `on`/`inside` a role's object or
    the floor as its placement, `not exists` removing the object (what rested on or in it goes
    to the floor); a negated `on`/`inside` of another object puts the object on the floor, the
    one place every room has. Facts of other shapes (an object that must exist, one that must
    not rest on the floor), and facts naming a role no object plays, are left."""
    out = list(objects)
    done: list[str] = []
    for fact in facts:
        cond = parse(fact)
        positive = not isinstance(cond, Not)
        pred = cond.operand if isinstance(cond, Not) else cond
        if not isinstance(pred, Pred):
            continue
        changed = _set(out, pred, positive)
        if changed is not None:
            out = changed
            done.append(fact)
    return Settled(out, done)


def _of(objects: list[ObjectDraft], role: str) -> int | None:
    """The index of the object playing `role` (its `role`, or its id where none plays it)."""
    for i, o in enumerate(objects):
        if o.role == role:
            return i
    return next((i for i, o in enumerate(objects) if o.id == role and o.role is None), None)


def _set(objects: list[ObjectDraft], pred: Pred, positive: bool) -> list[ObjectDraft] | None:
    """The objects with `pred` (or its negation) made true, or None where nothing is set."""
    if not pred.args:
        return None
    i = _of(objects, pred.args[0])
    if i is None:
        return None
    o = objects[i]
    update: dict[str, object] | None = None
    if pred.name == "state" and len(pred.args) == 2 and o.states.get(pred.args[1]) is not positive:
        update = {"states": {**o.states, pred.args[1]: positive}}
    elif pred.name == "attr" and len(pred.args) == 3:
        key, value = pred.args[1], pred.args[2]
        if positive and o.attributes.get(key) != value:
            update = {"attributes": {**o.attributes, key: value}}
        elif not positive and o.attributes.get(key) == value:
            update = {"attributes": {k: v for k, v in o.attributes.items() if k != key}}
    elif pred.name in ("on", "inside") and len(pred.args) == 2:
        placement = _placement(objects, pred.name, pred.args[1], o)
        if positive and placement is not None and placement != o.placement:
            update = {"placement": placement}
        elif not positive and placement == o.placement and placement not in _GROUND:
            update = {"placement": "floor"}  # the one place every room has
    elif pred.name == "exists" and len(pred.args) == 1 and not positive:
        return [p if p.placement not in (f"on:{o.id}", f"inside:{o.id}") else
                p.model_copy(update={"placement": "floor"}) for j, p in enumerate(objects) if j != i]
    if update is None:
        return None
    return [*objects[:i], o.model_copy(update=update), *objects[i + 1:]]


def _placement(objects: list[ObjectDraft], kind: str, target: str, o: ObjectDraft) -> str | None:
    if target in _GROUND:
        return target if kind == "on" else None
    j = _of(objects, target)
    if j is None or objects[j].id == o.id:
        return None
    return f"{kind}:{objects[j].id}"
