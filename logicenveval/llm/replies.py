"""Pydantic models of every LLM reply kind; their JSON schemas are what servers receive.

Field descriptions are part of the schema and therefore of the prompt: they say precisely what a
model must produce, in the condition language of DESIGN.md §3 where conditions are asked for.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Annotated, Any, Literal, Union

from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Field,
    ModelWrapValidatorHandler,
    PrivateAttr,
    ValidationError,
    ValidationInfo,
    model_validator,
)

from logicenveval.domain.roles import role_named
from logicenveval.llm import meaning
from logicenveval.llm.meaning import MeaningError
from logicenveval.llm.structured import Conjunction, Goal, LiteralDraft, to_text
from logicenveval.llm.vocab import (
    AT_LEAST,
    AT_MOST,
    CONTEXT_KEY,
    COUNT,
    KEYS,
    OTHERS,
    SOME_KEYS,
    Pattern,
    Vocab,
    admits,
)
from logicenveval.model.repeats import repeated

_F = ConfigDict(frozen=True, extra="ignore")

Condition = Annotated[
    str,
    Field(description="a condition in the task condition language, e.g. 'on(toy, floor)', "
          "'not attr(toy, kind, doll)', 'state(fridge, open)', using the task's role names"),
]


# --- behaviour plan derivation (paper §3.1) -------------------------------------------------

class SubtaskDraft(BaseModel):
    model_config = _F
    id: str = Field(description="short snake_case id, e.g. 'tidy_toy'")
    description: str = Field(description="one sentence: what the subtask achieves")
    roles: list[str] = Field(description="task roles this subtask manipulates or inspects")


class DecomposeReply(BaseModel):
    """Mutually independent subtasks (no execution-order dependencies)."""

    model_config = _F
    reasoning: str = Field(default="", description="brief reasoning")
    subtasks: list[SubtaskDraft] = Field(min_length=1)


class FactorDraft(BaseModel):
    model_config = _F
    id: str = Field(description="snake_case factor id, unique in the task, e.g. 'toy_on_floor'")
    question: str = Field(description="the query about the environment, e.g. 'Is there a toy on the floor?'")
    values: dict[str, Condition] = Field(
        min_length=2,
        description="response -> condition; responses mutually exclusive and exhaustive",
    )


class FactorsReply(BaseModel):
    """Uncertain environment factors that change how one subtask must be executed."""

    model_config = _F
    subtask: str
    factors: list[FactorDraft] = Field(default_factory=list)


class PlanLeaf(BaseModel):
    model_config = _F
    plan: list[str] = Field(description="the agent's steps in this situation")
    goal: Condition = Field(default="true", description="condition that must hold after the plan")


class QueryNode(BaseModel):
    model_config = _F
    var: str = Field(description="the factor id this query asks about")
    query: str = Field(default="", description="the query text")
    branches: dict[str, TreeDraft] = Field(min_length=1, description="response -> subtree")


TreeDraft = Annotated[Union[QueryNode, PlanLeaf], Field(union_mode="smart")]  # noqa: UP007
QueryNode.model_rebuild()


class TrajectoryDraft(BaseModel):
    model_config = _F
    description: str = Field(default="", description="the situation in words")
    facts: list[Condition] = Field(description="conditions that hold initially in this situation")


class TrajectoriesReply(BaseModel):
    """Logical trajectories straight from the description (the no-DBP ablation, IFG intents)."""

    model_config = _F
    trajectories: list[TrajectoryDraft] = Field(min_length=1)


# --- environment construction (paper §3.3) ----------------------------------------------------

Wall = Literal["n", "s", "e", "w"]


class DoorDraft(BaseModel):
    model_config = _F
    to: Annotated[str, Vocab("door_targets")] = Field(description="a room id or 'exterior'")
    type: Literal["door", "doorway", "sliding"] = "door"
    width: float = Field(default=0.9, ge=0.6, le=2.0)
    state: Literal["open", "closed"] = "closed"


class WindowDraft(BaseModel):
    model_config = _F
    wall: Wall
    width: float = Field(default=1.2, ge=0.3, le=3.0)
    height: float = Field(default=1.2, ge=0.3, le=2.2)
    sill: float = Field(default=0.9, ge=0.1, le=1.5)
    state: Literal["open", "closed"] = "closed"


class RoomDraft(BaseModel):
    model_config = _F
    id: Annotated[str, Vocab("rooms")]
    type: Annotated[str, Vocab("room_types")] = Field(
        description="room type, e.g. LivingRoom, Kitchen, Bedroom, Bathroom, Study")
    area_m2: float = Field(ge=3.0, le=80.0)
    #: the other rooms only (`OTHERS`, protocol 2 on): Qwen2.5-Coder-1.5B's Holodeck-like scene
    #: made the one-room kitchen adjacent to itself in 3 of 3 attempts
    adjacent_to: list[Annotated[str, Vocab("rooms")]] = Field(default_factory=list, json_schema_extra={OTHERS: "rooms"})
    doors: list[DoorDraft] = Field(default_factory=list)
    windows: list[WindowDraft] = Field(default_factory=list)
    floor_material: str = "wood"
    wall_color: str = "white"


class FloorPlanReply(BaseModel):
    model_config = _F
    rooms: list[RoomDraft] = Field(min_length=1)


def _known_flags(value: dict[str, bool], info: ValidationInfo) -> dict[str, bool]:
    """States keyed by the request's state flags only, where it gives them (`SOME_KEYS`)."""
    words = ((info.context or {}).get(CONTEXT_KEY) or {}).get("state_flags")
    unknown = sorted(set(value) - set(words)) if isinstance(words, list) else []
    if unknown:
        raise ValueError(f"{unknown} are not state flags: use only {words}")
    return value


#: an object's state flags; from protocol 5 on its keys are the condition language's flags
StateFlags = Annotated[dict[str, bool], AfterValidator(_known_flags),
                       Field(json_schema_extra={SOME_KEYS: "state_flags"})]


class ObjectDraft(BaseModel):
    model_config = _F
    id: Annotated[str, Vocab("object_ids")] = Field(description="unique object id, e.g. 'sofa_1'")
    category: Annotated[str, Vocab("categories")] = Field(description="a catalog category name")
    room: Annotated[str, Vocab("rooms")]
    role: Annotated[str, Vocab("roles")] | None = Field(
        default=None, description="the task role this object plays, if any")
    placement: Annotated[str, Vocab("placements")] = Field(
        description="'floor', 'wall', 'ceiling', 'on:<object id>' or 'inside:<object id>'")
    attributes: dict[str, str] = Field(default_factory=dict)
    states: StateFlags = Field(default_factory=dict)
    description: str = ""


def bind_objects(objects: list[ObjectDraft], info: ValidationInfo) -> list[ObjectDraft]:
    """Scene objects with every role bound, checked for meaning (validation context of `ask`
    from protocol 2 on; otherwise returned as they are).

    An object whose id is a role's name and that gives no `role` plays that role (Qwen2.5 named
    one object per role after the role and left the optional field out): the judge's id rule,
    `domain.roles.role_named`, which binds every method's environments afterwards with the rest
    of the one rule (`domain.roles.prepare_env`); no object may rest on
    or in itself; and every role the request requires (`required_roles` of the vocabulary)
    must end up with an object, else the re-ask names the roles left without one."""
    if not meaning.enabled(info.context):
        return objects
    vocabulary = (info.context or {}).get(CONTEXT_KEY) or {}
    roles = vocabulary.get("roles")
    roles = list(roles) if isinstance(roles, list) else []
    taken = {o.role for o in objects if o.role}
    named = {o.id: role_named(o.id, roles) for o in objects if o.role is None}
    bound = [o.model_copy(update={"role": named[o.id]}) if named.get(o.id) and named[o.id] not in taken
             else o for o in objects]
    problem = meaning.placement_problem([(o.id, o.placement) for o in bound])
    if problem:
        raise MeaningError(problem)
    required = vocabulary.get("required_roles")
    missing = meaning.unbound_roles([(o.id, o.role) for o in bound], list(required or []))
    if missing:
        raise MeaningError(f"role(s) {missing} have no object: add one object per role, with "
                           "`role` set to the role's name (or the role's name as its id)")
    return bound


def unique_bound(objects: Sequence[ObjectDraft], info: ValidationInfo, *,
                 error: type[ValueError] = ValueError) -> list[ObjectDraft]:
    """A scene's objects under unique ids (else `error` names the repeated ones: two objects
    under one id cannot both be placed; a real small model named two objects `living_room`),
    with every role bound (`bind_objects`): the check of every method's scene objects."""
    twice = repeated([o.id for o in objects])
    if twice:
        raise error(f"object ids must be unique; repeated: {twice}")
    return bind_objects(list(objects), info)


class ObjectsReply(BaseModel):
    model_config = _F
    objects: list[ObjectDraft] = Field(min_length=1, max_length=60, json_schema_extra={AT_LEAST: "required_roles"})

    @model_validator(mode="after")
    def _unique_ids(self, info: ValidationInfo) -> ObjectsReply:
        """Refused here (`unique_bound`), so the model is asked again."""
        bound = unique_bound(self.objects, info)
        return self if bound == list(self.objects) else self.model_copy(update={"objects": bound})


#: the fields a scene object's wire shares (protocol 3): one place, the same schema for each
SceneCategory = Annotated[str, Vocab("categories"), Field(description="a catalog category name")]
SceneRoom = Annotated[str, Vocab("rooms")]
ScenePlacement = Annotated[str, Vocab("placements"), Field(
    description="'floor', 'wall', 'ceiling', 'on:<object id>' or 'inside:<object id>'")]


class RoleObjectWire(BaseModel):
    """The object of one role (its id and role are the role's name)."""

    model_config = _F
    category: SceneCategory
    room: SceneRoom
    placement: ScenePlacement
    attributes: dict[str, str] = Field(default_factory=dict)
    states: StateFlags = Field(default_factory=dict)


class OtherObjectWire(BaseModel):
    """An object that plays no role: furniture that holds the role objects, or enrichment."""

    model_config = _F
    id: Annotated[str, Vocab("object_ids")] = Field(description="unique object id, e.g. 'sofa_1'")
    category: SceneCategory
    room: SceneRoom
    placement: ScenePlacement
    attributes: dict[str, str] = Field(default_factory=dict)
    states: StateFlags = Field(default_factory=dict)


#: objects besides the roles' in one selection reply (protocol 3): the offline model's largest
#: selection over all 25 tasks has 11 (lamp_or_pillow_fetch, `benchmarks/reply_bounds.py`), times
#: 1.5 as every measured bound; a looping reply ends here
MAX_OTHER_OBJECTS = 17


def object_slots(roles: Sequence[str]) -> list[str]:
    """One word per object a scene may list from protocol 3 on, its roles then `MAX_OTHER_OBJECTS`
    others: the vocabulary of an `AT_MOST` bound of one item per object."""
    return [*roles, *(f"other_{k}" for k in range(MAX_OTHER_OBJECTS))]


#: a scene's objects from protocol 3 on (LogicEnvGen's selection, Holodeck-like's scene)
RoleObjects = Annotated[dict[str, RoleObjectWire], Field(
    description="one object per required role, keyed by the role's name (its object id)",
    json_schema_extra={KEYS: "required_roles"})]
OtherObjects = Annotated[list[OtherObjectWire], Field(
    max_length=MAX_OTHER_OBJECTS,
    description="furniture that holds the role objects and objects typical of each room")]


def _role_word(vocabulary: dict[str, Any], name: str, role: str, value: str) -> str | None:
    """Why `value` is not one of `role`'s own words `name@role` (the role's category, where its
    object may rest), None when it is or the request gives none."""
    words = vocabulary.get(f"{name}@{role}")
    if words is None or admits(words, value):
        return None
    if isinstance(words, Pattern):
        return f"role_objects.{role}: {name[:-1] if name.endswith('s') else name} {value!r} is not allowed (must match {words.regex})"
    return f"role_objects.{role}: {value!r} is not one of {list(words)}"


# The objects of a scene from protocol 3 on. A list of objects with an optional `role` let
# Qwen2.5-Coder-1.5B repeat one object eight times and leave roles out; keyed by role (grammar:
# one required property per role the situation requires, `KEYS`), every role is written once and
# a loop ends at `MAX_OTHER_OBJECTS`. The docstring is the schema's description, sent.
class SelectionWire(BaseModel):
    """The objects of the scene: one per required role, keyed by the role, then the others."""

    model_config = _F
    role_objects: RoleObjects
    other_objects: OtherObjects

    @model_validator(mode="after")
    def _checked(self, info: ValidationInfo) -> SelectionWire:
        vocabulary = (info.context or {}).get(CONTEXT_KEY) or {}
        roles = vocabulary.get("roles")
        unknown = [r for r in self.role_objects if isinstance(roles, list) and r not in roles]
        if unknown:
            raise ValueError(f"role_objects keys {unknown} are not roles of the task: use {roles}")
        reply = self._read()
        for role, o in reply.role_objects.items():
            problem = _role_word(vocabulary, "categories", role, o.category) or _role_word(
                vocabulary, "placements", role, o.placement)
            if problem:
                raise ValueError(problem)
        ids = [*reply.role_objects, *(o.id for o in reply.other_objects)]
        twice = repeated(ids)
        if twice:
            raise ValueError(f"object ids must be unique (a role object's id is its role); repeated: {twice}")
        if meaning.enabled(info.context):
            problem = meaning.placement_problem([(o.id, o.placement) for o in reply.draft().objects])
            if problem:
                raise MeaningError(problem)
            missing = [r for r in vocabulary.get("required_roles") or [] if r not in reply.role_objects]
            if missing:
                raise MeaningError(f"role(s) {missing} have no object: add each under role_objects")
        return reply

    def _read(self) -> SelectionWire:
        """The reply as meant, where only one reading exists: an other object that repeats a
        role object field for field is that object (Qwen2.5-Coder-1.5B listed its `sink` role
        again under other_objects), and a placement target that is no object's id but the
        category of exactly one object names that object (it placed the role objects
        `on:kitchen_counter`, the category of its one counter, `counter`)."""
        others = [o for o in self.other_objects if o.id not in self.role_objects
                  or o.model_dump(exclude={"id"}) != self.role_objects[o.id].model_dump()]
        objects = [*((r, o.category) for r, o in self.role_objects.items()), *((o.id, o.category) for o in others)]
        ids = {oid for oid, _ in objects}
        holders: dict[str, list[str]] = {}
        for oid, category in objects:
            holders.setdefault(category, []).append(oid)

        def read(placement: str) -> str:
            kind, _, target = placement.partition(":")
            if kind in ("on", "inside") and target not in ids | meaning.SURFACES and len(holders.get(target, [])) == 1:
                return f"{kind}:{holders[target][0]}"
            return placement

        role_objects = {r: o.model_copy(update={"placement": read(o.placement)}) for r, o in self.role_objects.items()}
        other_objects = [o.model_copy(update={"placement": read(o.placement)}) for o in others]
        if role_objects == self.role_objects and other_objects == self.other_objects:
            return self
        return self.model_copy(update={"role_objects": role_objects, "other_objects": other_objects})

    def draft(self) -> ObjectsReply:
        roles = [ObjectDraft(id=role, role=role, **o.model_dump()) for role, o in self.role_objects.items()]
        return ObjectsReply.model_construct(
            objects=[*roles, *(ObjectDraft(**o.model_dump()) for o in self.other_objects)])


#: a relation's fields, the same in every reply that writes relations
RelationType = Annotated[str, Vocab("relation_types"), Field(
    description="edge, center, wall_mounted, on, inside, near, far, above, in_front_of, side_of, center_aligned, face_to")]
RelationArgs = Annotated[list[Annotated[str, Vocab("object_ids")]], Field(min_length=1, max_length=2,
                                                                          description="object ids")]


class RelationDraft(BaseModel):
    model_config = _F
    type: RelationType
    args: RelationArgs

    @model_validator(mode="after")
    def _arity(self) -> RelationDraft:
        """`inside` with one object would reach the solver and crash it: refused here, so the
        model is asked again (seen with a real small model)."""
        from logicenveval.model.envspec import RELATION_TYPES

        wanted = RELATION_TYPES.get(self.type)
        if wanted is not None and len(self.args) != wanted:
            raise ValueError(f"relation {self.type!r} takes {wanted} object id(s), got {self.args}")
        return self


class RelationsReply(BaseModel):
    model_config = _F
    relations: list[RelationDraft] = Field(default_factory=list, max_length=80)


class RelationItemWire(BaseModel):
    """A relation as written (protocol 3): its arity and its objects are judged with the
    checker's other findings (`RelationsWire.split`), not by refusing the whole reply."""

    model_config = _F
    type: RelationType
    args: RelationArgs


# A scene's relations from protocol 3 on: at most one per object (`AT_MOST` over
# `relation_slots`), so a looping reply ends. Qwen2.5-Coder-1.5B wrote `on(sofa_1, sofa_1)`
# at the end of a good reply, then only that in two re-asks, and `center(counter, sink)` with
# two objects: refusing the reply lost the scene; the paper's checker refines and then drops a
# relation it rejects, and so these are judged with its findings.
class RelationsWire(BaseModel):
    model_config = _F
    relations: list[RelationItemWire] = Field(default_factory=list, max_length=80,
                                              json_schema_extra={AT_MOST: "relation_slots"})

    def split(self) -> tuple[list[RelationDraft], list[tuple[dict[str, Any], str]]]:
        """The well-formed relations, each once, and the others with why: (relation, reason)."""
        from logicenveval.model.envspec import RELATION_TYPES

        good: list[RelationDraft] = []
        bad: list[tuple[dict[str, Any], str]] = []
        seen: set[tuple[str, tuple[str, ...]]] = set()
        for r in self.relations:
            wanted = RELATION_TYPES.get(r.type)
            text = f"{r.type}({', '.join(r.args)})"
            if wanted is not None and len(r.args) != wanted:
                bad.append((r.model_dump(), f"{text} takes {wanted} object id(s), not {len(r.args)}"))
            elif len(r.args) == 2 and r.args[0] == r.args[1]:
                bad.append((r.model_dump(), f"{text} relates {r.args[0]} to itself; name two different objects"))
            elif (r.type, tuple(r.args)) not in seen:
                seen.add((r.type, tuple(r.args)))
                good.append(RelationDraft(type=r.type, args=list(r.args)))
        return good, bad


#: a relation the reply wrote that no checker can use, with why: (relation as written, reason)
DroppedRelation = tuple[dict[str, Any], str]


def judged_relations(data: Any, info: ValidationInfo) -> tuple[Any, list[DroppedRelation]]:
    """A reply's `relations` as the grammar lets a model write them, with the ones of the wrong
    arity or relating an object to itself taken out and said why (`RelationsWire.split`).

    The grammar lets every relation type take one or two objects; refusing a whole scene for one
    `edge(vase, side_table)` (seen live with Qwen2.5-Coder-1.5B on Holodeck-like's scene) lost
    every object of it, where LogicEnvGen's path drops the one relation. Every reply that writes
    relations reads them here, so the grammar and the validator agree for every method. Relations
    that do not parse at all are left in place: the reply's own validation words that error."""
    if not isinstance(data, dict) or not isinstance(data.get("relations"), list):
        return data, []
    try:
        wire = RelationsWire.model_validate({"relations": data["relations"]}, context=info.context)
    except ValidationError:
        return data, []
    good, bad = wire.split()
    if not bad:
        return data, []
    return {**data, "relations": [r.model_dump() for r in good]}, bad


class JudgedRelations(BaseModel):
    """A reply part whose relations are read by `judged_relations`: the dropped ones stay on
    record (`dropped_relations`), for the generator's log and the reasons a user reads."""

    _dropped: list[DroppedRelation] = PrivateAttr(default_factory=list)

    @model_validator(mode="wrap")
    @classmethod
    def _judge_relations(cls, data: Any, handler: ModelWrapValidatorHandler[Any],
                         info: ValidationInfo) -> Any:
        data, dropped = judged_relations(data, info)
        out = handler(data)
        if dropped:
            out._dropped = dropped
        return out

    @property
    def dropped_relations(self) -> list[DroppedRelation]:
        return list(self._dropped)


class PlacedObject(ObjectDraft):
    position: tuple[float, float, float] = Field(description="bounding-box centre x, y, z in metres (y up)")
    size: tuple[float, float, float] = Field(description="extent along x, y, z in metres")
    yaw: float = Field(default=0.0, description="rotation about y in degrees")


class OpeningPlacement(BaseModel):
    model_config = _F
    id: str = Field(description="the id of a door or window of the floor plan")
    segment: tuple[tuple[float, float], tuple[float, float]] = Field(
        description="its two end points (x, z) in metres, on its wall stretch")


class PlacementReply(BaseModel):
    """Objects, doors and windows with coordinates chosen by the model itself (no solver: no-CAS)."""

    model_config = _F
    objects: list[PlacedObject] = Field(min_length=1)
    relations: list[RelationDraft] = Field(default_factory=list)
    openings: list[OpeningPlacement] = Field(default_factory=list, description="where each door and window goes")


# --- vocabulary-bound wire forms of LogicEnvGen's requests (llm.vocab, llm.structured) -----------

class RoomWire(RoomDraft):
    #: whole square metres: llama.cpp's grammar bounds integers, not decimals (a small model
    #: wrote 1.2 m² rooms)
    area_m2: int = Field(ge=3, le=80)
    adjacent_to: list[Annotated[str, Vocab("rooms")]] = Field(default_factory=list,
                                                             json_schema_extra={OTHERS: "rooms"})


class FloorPlanWire(BaseModel):
    """The floor plan of LogicEnvGen: one entry per room of the task (grammar: `maxItems`)."""

    model_config = _F
    rooms: list[RoomWire] = Field(min_length=1, json_schema_extra={COUNT: "rooms"})

    @model_validator(mode="after")
    def _distinct(self, info: ValidationInfo) -> FloorPlanWire:
        ids = [r.id for r in self.rooms]
        twice = repeated(ids)
        if twice:
            raise ValueError(f"room {twice[0]!r} is listed twice; list each room once")
        if meaning.enabled(info.context):
            problem = meaning.adjacency_problem([(r.id, r.adjacent_to) for r in self.rooms])
            if problem:
                raise MeaningError(problem)
        return self

    def draft(self) -> FloorPlanReply:
        return FloorPlanReply(rooms=[RoomDraft(**r.model_dump()) for r in self.rooms])


# --- plan requests ----------------------------------------------------------------------------
# Conditions are lists of literals with enumerated roles/rooms/flags; `plan.py` converts them to
# the internal drafts above (condition-language strings) after validation.

class SubtaskWire(BaseModel):
    model_config = _F
    id: Annotated[str, Vocab("ids", "short snake_case id, e.g. 'tidy_toy'")]
    description: str = Field(max_length=200, description="one short sentence: what the subtask achieves")
    roles: list[Annotated[str, Vocab("roles")]] = Field(
        max_length=8, description="task roles this subtask manipulates or inspects")


class DecomposeWire(BaseModel):
    """Mutually independent subtasks (no execution-order dependencies)."""

    model_config = _F
    subtasks: list[SubtaskWire] = Field(min_length=1, max_length=6)

    @model_validator(mode="after")
    def _meaningful(self, info: ValidationInfo) -> DecomposeWire:
        """SmolLM2 wrote the schema's own description string as every subtask's description."""
        if meaning.enabled(info.context):
            texts = [f.description or "" for f in SubtaskWire.model_fields.values()]
            problem = meaning.subtask_problem([(s.id, s.description) for s in self.subtasks],
                                              [*texts, self.__doc__ or ""])
            if problem:
                raise MeaningError(problem)
        return self


class ResponseWire(BaseModel):
    model_config = _F
    response: Annotated[str, Vocab("ids", "short snake_case answer, e.g. 'yes', 'no', 'novel'")]
    condition: Conjunction = Field(description="what holds in the environment when this is the answer")


class FactorWire(BaseModel):
    model_config = _F
    id: Annotated[str, Vocab("ids", "snake_case factor id, unique in the task, e.g. 'toy_on_floor'")]
    question: str = Field(max_length=150,
                          description="the query about the environment, e.g. 'Is there a toy on the floor?'")
    responses: list[ResponseWire] = Field(
        min_length=2, max_length=5, description="mutually exclusive answers that cover every situation")

    @model_validator(mode="after")
    def _distinct(self, info: ValidationInfo) -> FactorWire:
        names = [r.response for r in self.responses]
        twice = repeated(names)
        if twice:
            fix = f"; rename one of the two {twice[0]!r} responses" if meaning.enabled(info.context) else ""
            raise ValueError(f"factor {self.id!r} gives the response {twice[0]!r} twice{fix}")
        if meaning.enabled(info.context):
            problem = meaning.factor_problem(self.id, [
                (r.response, [lit.model_dump() for lit in r.condition]) for r in self.responses])
            if problem:
                raise MeaningError(problem)
        return self

    def draft(self) -> FactorDraft:
        return FactorDraft(id=self.id, question=self.question,
                           values={r.response: to_text(r.condition) for r in self.responses})


class FactorsWire(BaseModel):
    """Uncertain environment factors that change how one subtask must be executed."""

    model_config = _F
    factors: list[FactorWire] = Field(default_factory=list, max_length=6)


class TreeStepReply(BaseModel):
    """One step of growing a decision tree: the factor to ask next on this path, or `act`."""

    model_config = _F
    next: Annotated[str, Vocab("next_steps", "a factor id not yet asked on this path, or act")]


class LeafWire(BaseModel):
    model_config = _F
    plan: list[Annotated[str, Field(max_length=200)]] = Field(min_length=1, max_length=8,
                                                                description="the agent's steps")
    goal: Goal = Field(description="conditions that must hold after the plan (may be empty)")


class FactTrajectoryWire(BaseModel):
    model_config = _F
    description: str = Field(max_length=300, description="the situation in words")
    facts: list[LiteralDraft] = Field(default_factory=list, max_length=24,
                                      description="what holds initially in this situation")


class TrajectoriesWire(BaseModel):
    """Logical trajectories straight from the description (the no-DBP ablation)."""

    model_config = _F
    trajectories: list[FactTrajectoryWire] = Field(min_length=1, max_length=16)
