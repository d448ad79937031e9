"""Reply models of the baselines' own request kinds (the other kinds reuse llm.replies).

CoT and IFG write whole environments, floor plan included, in one world frame (x east, z north,
y up, metres), as the paper's prompts have the LLM write vertex coordinates: rooms as polygons,
doors and windows as segments on walls, objects with positions. The harness checks what they
wrote and repairs nothing (`baselines.drafts`). Holodeck-like gives rooms by area and objects with
placements only: its own solver places them.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, model_validator

from logicenveval.llm import meaning
from logicenveval.llm.meaning import MeaningError
from logicenveval.llm.replies import (
    FactTrajectoryWire,
    JudgedRelations,
    ObjectDraft,
    OtherObjects,
    PlacedObject,
    RelationDraft,
    RoleObjects,
    RoomDraft,
    SelectionWire,
    bind_objects,
    object_slots,
    unique_bound,
)
from logicenveval.llm.structured import literal_text
from logicenveval.llm.vocab import AT_MOST, CONTEXT_KEY, scene_vocabulary
from logicenveval.model.conditions import STATE_FLAGS
from logicenveval.model.task import TaskBrief

_F = ConfigDict(frozen=True, extra="ignore")

Point = tuple[float, float]


class WrittenRoom(BaseModel):
    model_config = _F
    id: str = Field(description="the room id, one of the task's rooms")
    type: str = Field(description="room type, e.g. LivingRoom, Kitchen, Bedroom, Bathroom, Study")
    polygon: list[Point] = Field(min_length=3, description="the floor outline: its vertices (x, z) in metres, "
                                 "in order around the room")


class WrittenDoor(BaseModel):
    model_config = _F
    rooms: tuple[str, str] = Field(description="the two rooms it joins: two room ids, or a room id and 'exterior'")
    segment: tuple[Point, Point] = Field(description="its two end points (x, z) on the wall between the two rooms "
                                         "(an entrance: on an outside wall)")
    height: float = Field(default=2.1, description="metres; a door stands on the floor")
    type: Literal["door", "doorway", "sliding"] = "door"
    state: Literal["open", "closed"] = "closed"


class WrittenWindow(BaseModel):
    model_config = _F
    room: str
    segment: tuple[Point, Point] = Field(description="its two end points (x, z) on a wall of its room")
    sill: float = Field(default=0.9, description="height of its bottom above the floor, metres")
    height: float = Field(default=1.2, description="metres; sill + height must stay below the ceiling")
    state: Literal["open", "closed"] = "closed"


class WrittenEnvironment(JudgedRelations):
    model_config = _F
    situation: str = Field(default="", description="the situation this environment tests")
    rooms: list[WrittenRoom] = Field(min_length=1)
    doors: list[WrittenDoor] = Field(default_factory=list)
    windows: list[WrittenWindow] = Field(default_factory=list)
    #: objects and relations at most one per object slot (`object_slots`: the roles and
    #: `MAX_OTHER_OBJECTS` others, protocol 4 on; `written_slots`), so a looping reply ends
    objects: list[PlacedObject] = Field(min_length=1, description="positions in the same world frame as the rooms",
                                        json_schema_extra={AT_MOST: "object_slots"})
    relations: list[RelationDraft] = Field(default_factory=list, json_schema_extra={AT_MOST: "object_slots"})

    @model_validator(mode="after")
    def _meaningful(self, info: ValidationInfo) -> WrittenEnvironment:
        """From request protocol 5 on (its requests give the scene's words, `written_words`),
        a written environment is checked as LogicEnvGen's and Holodeck-like's scenes are: ids
        unique, no object on or in itself, an object named after a role plays it
        (`llm.replies.bind_objects`); a finding is re-asked with the same budget. The paper's
        "same problem setup" for every method (issue 46): before, a self-supporting object was a
        final failure on this path only."""
        vocabulary = (info.context or {}).get(CONTEXT_KEY) or {}
        if not meaning.enabled(info.context) or "categories" not in vocabulary:
            return self
        bound = unique_bound(self.objects, info, error=MeaningError)
        return self if bound == list(self.objects) else self.model_copy(update={"objects": bound})


def written_vocabulary(brief: TaskBrief, environments: int, categories: Sequence[str],
                       protocol: int) -> dict[str, Any] | None:
    """What CoT's and IFG's written-environment requests are asked in: nothing before protocol
    4, its bounds (`written_slots`) from 4 on, and the scene's words too (`written_words`) from
    5 on, as every method's scene is."""
    if protocol < 4:
        return None
    vocabulary: dict[str, Any] = written_slots(sorted(brief.roles), environments)
    if protocol >= 5:
        vocabulary.update(written_words(brief, categories))
    return vocabulary


def written_words(brief: TaskBrief, categories: Sequence[str]) -> dict[str, Any]:
    """The scene's words a written environment is asked in from protocol 5 on, as LogicEnvGen's
    selection and Holodeck-like's scene are (`llm.vocab.scene_vocabulary`): the task's rooms,
    room types, the catalog's and the roles' categories, the roles, placements, relation types and
    state flags in the grammar; no role is required (a CoT or IFG situation may lack an object)."""
    return {**scene_vocabulary(list(brief.rooms), sorted(brief.roles),
                               [*categories, *(r.category for r in brief.roles.values())]),
            "state_flags": list(STATE_FLAGS)}


class WrittenEnvironmentsReply(BaseModel):
    """Several complete test environments (CoT) or one (IFG stage 2), floor plans included."""

    model_config = _F
    reasoning: str = Field(default="", description="step-by-step reasoning about the situations")
    #: at most as many as the request asks for (`environment_slots`, protocol 4 on: CoT's "at
    #: most N", IFG's one per intent), so a model repeating environments stops
    environments: list[WrittenEnvironment] = Field(min_length=1, json_schema_extra={AT_MOST: "environment_slots"})


class IntentWire(FactTrajectoryWire):
    """One intent of IFG's stage 1 (protocol 5): a situation of the task, as the literals that
    hold initially, each bound to the task's roles, rooms and flags like LogicEnvGen's factors
    (`llm.structured`), so `not attr(cabinet, opened)` cannot be written; a literal stated both
    ways is refused (re-asked) as no situation."""

    @model_validator(mode="after")
    def _consistent(self, info: ValidationInfo) -> IntentWire:
        if meaning.enabled(info.context):
            texts = [literal_text(f) for f in self.facts]
            both = sorted({t for t in texts if f"not {t}" in texts})
            if both:
                raise MeaningError(f"the intent states {both[0]} and its negation: write one situation, "
                                   "each literal once")
        return self

    def texts(self) -> list[str]:
        """The facts in the condition language, each once."""
        return list(dict.fromkeys(literal_text(f) for f in self.facts))


def written_slots(roles: Sequence[str], environments: int) -> dict[str, list[str]]:
    """The bounds of a `WrittenEnvironmentsReply` from request protocol 4 on (`AT_MOST`): at most
    `environments` environments, each with at most one object, and one relation, per role plus
    `MAX_OTHER_OBJECTS` others. Qwen2.5-Coder-1.5B's IFG replies under protocol 3 repeated a whole
    environment, or `on(plate, counter)`, `on(plate, sink)`, ... until their token bound."""
    return {"environment_slots": [f"environment_{k}" for k in range(environments)],
            "object_slots": object_slots(roles)}


def dropped_relations(written: Iterable[tuple[str, JudgedRelations]]) -> dict[str, Any]:
    """The relations each written environment lost (`judged_relations`), for a generator's
    artifacts (plan.json): `{"dropped_relations": {env_id: [[relation, why], ...]}}`, or nothing
    when none was dropped, so plans of replies without such relations stay as they were."""
    dropped = {env_id: [[r, why] for r, why in part.dropped_relations]
               for env_id, part in written if part.dropped_relations}
    return {"dropped_relations": dropped} if dropped else {}


class HolodeckSceneReply(BaseModel):
    """Holodeck's language stages in one reply: floor plan, objects, spatial relations (no coordinates:
    its own constraint solver places the objects)."""

    model_config = ConfigDict(frozen=True, extra="ignore")
    rooms: list[RoomDraft] = Field(min_length=1)
    objects: list[ObjectDraft] = Field(min_length=1)
    relations: list[RelationDraft] = Field(default_factory=list)

    @model_validator(mode="after")
    def _meaningful(self, info: ValidationInfo) -> HolodeckSceneReply:
        """Roles bound by name and required (`llm.replies.bind_objects`), no room adjacent to
        itself: a scene that leaves a role without an object cannot be evaluated."""
        if meaning.enabled(info.context):
            problem = meaning.adjacency_problem([(r.id, r.adjacent_to) for r in self.rooms])
            if problem:
                raise MeaningError(problem)
        bound = bind_objects(list(self.objects), info)
        return self if bound == list(self.objects) else self.model_copy(update={"objects": bound})


class HolodeckSceneWire(JudgedRelations):
    """Holodeck's language stages in one reply: floor plan, objects (one per required role, keyed
    by the role, then the others), spatial relations (no coordinates: its own constraint solver
    places the objects)."""

    model_config = ConfigDict(frozen=True, extra="ignore")
    rooms: list[RoomDraft] = Field(min_length=1)
    role_objects: RoleObjects
    other_objects: OtherObjects
    #: at most one per object it may list (`relation_slots`): a looping reply ends
    relations: list[RelationDraft] = Field(default_factory=list, json_schema_extra={AT_MOST: "relation_slots"})

    @model_validator(mode="after")
    def _meaningful(self, info: ValidationInfo) -> HolodeckSceneWire:
        """The objects read and checked as LogicEnvGen's keyed selection (`SelectionWire`), no room
        adjacent to itself: protocol 3 asks every method's scene the same way."""
        if meaning.enabled(info.context):
            problem = meaning.adjacency_problem([(r.id, r.adjacent_to) for r in self.rooms])
            if problem:
                raise MeaningError(problem)
        selection = SelectionWire.model_validate(
            {"role_objects": self.role_objects, "other_objects": self.other_objects}, context=info.context)
        if selection.role_objects == self.role_objects and selection.other_objects == self.other_objects:
            return self
        return self.model_copy(update={"role_objects": selection.role_objects, "other_objects": selection.other_objects})

    def draft(self) -> HolodeckSceneReply:
        objects = SelectionWire.model_construct(role_objects=self.role_objects,
                                                other_objects=self.other_objects).draft().objects
        return HolodeckSceneReply.model_construct(rooms=self.rooms, objects=objects, relations=self.relations)
