"""EnvSpec (DESIGN.md §6): one generated environment as immutable, serialisable data.

Units are metres and degrees; y is up and the floor is the x–z plane (AI2-THOR convention).
Geometry (`position`, `size`, `polygon`) is optional so that purely symbolic situation
environments are valid EnvSpecs too; the physics checker reports missing geometry as failures.
Unknown fields are kept (generators may add fields) and ignored by the checker.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from logicenveval.model.repeats import repeated

ENV_SCHEMA = "logicenveval.env/1"

Vec2 = tuple[float, float]
Vec3 = tuple[float, float, float]

RELATION_TYPES: dict[str, int] = {
    "edge": 1,
    "center": 1,
    "wall_mounted": 1,
    "on": 2,
    "inside": 2,
    "near": 2,
    "far": 2,
    "above": 2,
    "in_front_of": 2,
    "side_of": 2,
    "center_aligned": 2,
    "face_to": 2,
}

_Cfg = ConfigDict(frozen=True, extra="allow", populate_by_name=True)


class Room(BaseModel):
    model_config = _Cfg
    id: str = Field(min_length=1)
    type: str = "LivingRoom"
    polygon: list[Vec2] | None = None


class Door(BaseModel):
    model_config = _Cfg
    id: str
    rooms: tuple[str, str]  # a room id, or "exterior"
    segment: tuple[Vec2, Vec2] | None = None
    height: float = 2.1
    type: str = "door"
    state: Literal["open", "closed"] = "closed"


class Window(BaseModel):
    model_config = _Cfg
    id: str
    room: str
    segment: tuple[Vec2, Vec2] | None = None
    sill: float = 0.9
    height: float = 1.2
    state: Literal["open", "closed"] = "closed"


class EnvObject(BaseModel):
    model_config = _Cfg
    id: str = Field(min_length=1)
    category: str = Field(min_length=1)
    room: str
    position: Vec3 | None = None
    yaw: float = 0.0
    size: Vec3 | None = None
    support: str | None = "floor"  # "floor", "wall", "ceiling", an object id, or None if contained
    container: str | None = None
    attributes: dict[str, str] = Field(default_factory=dict)
    states: dict[str, bool] = Field(default_factory=dict)
    mesh: str | None = None


class Relation(BaseModel):
    model_config = _Cfg
    type: str
    args: tuple[str, ...]

    @model_validator(mode="after")
    def _arity(self) -> Relation:
        if self.type not in RELATION_TYPES:
            raise ValueError(f"unknown relation type {self.type!r}; use {sorted(RELATION_TYPES)}")
        if len(self.args) != RELATION_TYPES[self.type]:
            raise ValueError(
                f"relation {self.type!r} takes {RELATION_TYPES[self.type]} argument(s), "
                f"got {len(self.args)}"
            )
        return self


class Agent(BaseModel):
    model_config = _Cfg
    room: str | None = None
    position: Vec2 | None = None


class EnvSpec(BaseModel):
    model_config = _Cfg
    schema_: Literal["logicenveval.env/1"] = Field("logicenveval.env/1", alias="schema")
    task_id: str
    generator: str = "unknown"
    env_id: str
    claimed_trajectory: dict[str, dict[str, str]] | None = None
    wall_height: float = 2.7
    rooms: list[Room] = Field(min_length=1)
    doors: list[Door] = Field(default_factory=list)
    windows: list[Window] = Field(default_factory=list)
    objects: list[EnvObject] = Field(default_factory=list)
    relations: list[Relation] = Field(default_factory=list)
    roles: dict[str, str | None] = Field(default_factory=dict)
    agent: Agent = Field(default_factory=Agent)

    @model_validator(mode="after")
    def _references(self) -> EnvSpec:
        room_ids = {r.id for r in self.rooms}
        if len(room_ids) != len(self.rooms):
            raise ValueError("room ids must be unique")
        ids = [o.id for o in self.objects]
        if len(set(ids)) != len(ids):
            dup = repeated(ids)
            raise ValueError(f"object ids must be unique; repeated: {dup}")
        obj_ids = set(ids)
        for i, o in enumerate(self.objects):
            if o.room not in room_ids:
                raise ValueError(f"objects[{i}] ({o.id}): room {o.room!r} is not one of {sorted(room_ids)}")
            if o.support not in (None, "floor", "wall", "ceiling") and o.support not in obj_ids:
                raise ValueError(f"objects[{i}] ({o.id}): support {o.support!r} is not an object id")
            if o.container is not None and o.container not in obj_ids:
                raise ValueError(f"objects[{i}] ({o.id}): container {o.container!r} is not an object id")
            if o.support == o.id or o.container == o.id:
                raise ValueError(f"objects[{i}] ({o.id}): an object cannot support or contain itself")
        for role, oid in self.roles.items():
            if oid is not None and oid not in obj_ids:
                raise ValueError(f"roles.{role}: {oid!r} is not an object id")
        for i, d in enumerate(self.doors):
            for r in d.rooms:
                if r != "exterior" and r not in room_ids:
                    raise ValueError(f"doors[{i}] ({d.id}): room {r!r} is not a room id or 'exterior'")
        for i, w in enumerate(self.windows):
            if w.room not in room_ids:
                raise ValueError(f"windows[{i}] ({w.id}): room {w.room!r} is not a room id")
        if self.agent.room is not None and self.agent.room not in room_ids:
            raise ValueError(f"agent.room {self.agent.room!r} is not a room id")
        return self

    def obj(self, object_id: str) -> EnvObject:
        for o in self.objects:
            if o.id == object_id:
                return o
        raise KeyError(object_id)

    def to_json_dict(self) -> dict[str, object]:
        return self.model_dump(mode="json", by_alias=True)
