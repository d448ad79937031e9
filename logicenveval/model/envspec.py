"""EnvSpec (DESIGN.md §6): one generated environment as immutable, serialisable data.

Units are metres and degrees; y is up and the floor is the x–z plane (AI2-THOR convention).
Geometry (`position`, `size`, `polygon`) is optional so that purely symbolic situation
environments are valid EnvSpecs too; the physics checker reports missing geometry as failures.
Unknown fields are kept (generators may add fields) and ignored by the checker.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from logicenveval.model.conditions import STATE_FLAGS
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


#: floor coordinates, shared by the descriptions below
_XZ = "[x, z] in metres on the floor (y is up; AI2-THOR's frame)"


class Room(BaseModel):
    """A room: its id, its AI2-THOR-style type and its floor outline."""

    model_config = _Cfg
    id: str = Field(min_length=1, description="Unique room id; task room names are resolved against ids "
                    "and types (`living_room` names a room with id `living_room` or type `LivingRoom`).")
    type: str = Field("LivingRoom", description="AI2-THOR-style room type: Kitchen, LivingRoom, Bedroom, "
                      "Bathroom, Study, Hallway, LaundryRoom, DiningRoom, KidsRoom, ...")
    polygon: list[Vec2] | None = Field(None, description=f"The floor outline, a simple polygon of {_XZ}, "
                                       "any orientation; null in purely symbolic environments (the "
                                       "physics checker then reports missing geometry).")


class Door(BaseModel):
    """A door or doorway between two rooms, or a room and the outside."""

    model_config = _Cfg
    id: str = Field(description="Door id (unique among doors).")
    rooms: tuple[str, str] = Field(description='The two sides: room ids, one of them may be "exterior".')
    segment: tuple[Vec2, Vec2] | None = Field(None, description=f"The opening on the shared wall: two "
                                              f"points {_XZ}; null when not placed.")
    height: float = Field(2.1, description="Height of the opening, metres.")
    type: str = Field("door", description='"door" (with a leaf that swings) or "doorway" (no leaf).')
    state: Literal["open", "closed"] = Field("closed", description="open or closed; the agent walks "
                                             "through closed doors too (it opens them).")


class Window(BaseModel):
    """A window on an outer wall of a room."""

    model_config = _Cfg
    id: str = Field(description="Window id (unique among windows).")
    room: str = Field(description="The room id whose outer wall holds the window.")
    segment: tuple[Vec2, Vec2] | None = Field(None, description=f"The window on the outer wall: two points "
                                              f"{_XZ}; null when not placed.")
    sill: float = Field(0.9, description="Height of the sill above the floor, metres.")
    height: float = Field(1.2, description="Height of the window opening, metres.")
    state: Literal["open", "closed"] = Field("closed", description="open or closed.")


class EnvObject(BaseModel):
    """One object: what it is, where it is, what it rests on or is inside, its attributes and states."""

    model_config = _Cfg
    id: str = Field(min_length=1, description="Unique object id in the file; roles and relations name it.")
    category: str = Field(min_length=1, description="What the object is: a catalog key, a synonym, an "
                          "AI2-THOR type, any case or plural (mapped once to the catalog key; "
                          "docs/envspec.md, 'Categories').")
    room: str = Field(description="The id of the room it is in.")
    position: Vec3 | None = Field(None, description="Centre of the bounding box, [x, y, z] in metres "
                                  "(y up); an object on the floor has y == size[1] / 2.")
    yaw: float = Field(0.0, description="Rotation about +y in degrees; yaw 0 faces +z, yaw 90 faces +x.")
    size: Vec3 | None = Field(None, description="Bounding-box extents along x, y, z before the yaw, metres; "
                              "the physics checker compares them with the catalog's range.")
    support: str | None = Field("floor", description='What it rests on or hangs from: "floor", "wall", '
                                '"ceiling", an object id, or null when it is inside a container.')
    container: str | None = Field(None, description="The id of the container it is directly inside, or null.")
    attributes: dict[str, str] = Field(default_factory=dict, description='Attributes as strings, e.g. '
                                       '{"kind": "doll", "color": "red"}; domains per category in '
                                       "docs/catalog.md.")
    states: dict[str, bool] = Field(default_factory=dict, description="State flags (open, toggled_on, "
                                    "dirty, wet, filled, cooked, sliced, broken); flags not given take "
                                    "the catalog's default_states.")
    mesh: str | None = Field(None, description="A mesh file, relative to the EnvSpec's folder, that the "
                             "physics checker uses instead of the box; null: the box.")


class Relation(BaseModel):
    """A spatial relation the generator asked for; the physics checker verifies it."""

    model_config = _Cfg
    type: str = Field(description="Unary: edge, center, wall_mounted; binary: on, inside, near, far, "
                      "above, in_front_of, side_of, center_aligned, face_to (docs/physics.md).")
    args: tuple[str, ...] = Field(description="The object ids it relates: one for a unary, two for a "
                                  "binary relation.")

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
    """Where the agent starts, with an empty hand, near nothing."""

    model_config = _Cfg
    room: str | None = Field(None, description="The room id it starts in; null: the first room.")
    position: Vec2 | None = Field(None, description=f"Its start point, {_XZ}; optional.")


class EnvSpec(BaseModel):
    """One generated environment (docs/envspec.md): rooms, doors, windows, objects, relations,
    the objects playing the task's roles and the agent's start."""

    model_config = _Cfg
    schema_: Literal["logicenveval.env/1"] = Field("logicenveval.env/1", alias="schema",
                                                   description="Format version.")
    task_id: str = Field(description="The task the environment is for (`python -m logicenveval tasks list`).")
    generator: str = Field("unknown", description="The tool that made it.")
    env_id: str = Field(description="Unique within the task's folder; becomes the file name in run folders.")
    claimed_trajectory: dict[str, dict[str, str]] | None = Field(
        None, description="{subtask: {variable: value}}: what the generator meant to realise; recorded, "
        "never trusted (the harness evaluates the ground-truth trees itself).")
    wall_height: float = Field(2.7, description="Height of every wall, metres.")
    rooms: list[Room] = Field(min_length=1, description="The rooms, at least one.")
    doors: list[Door] = Field(default_factory=list, description="Doors and doorways between rooms.")
    windows: list[Window] = Field(default_factory=list, description="Windows on outer walls.")
    objects: list[EnvObject] = Field(default_factory=list, description="The objects (at most 2,000, "
                                     "LOGICENVEVAL_MAX_ENV_OBJECTS).")
    relations: list[Relation] = Field(default_factory=list, description="The spatial relations the "
                                      "generator asked for (the physics checker verifies them).")
    roles: dict[str, str | None] = Field(default_factory=dict, description="{role: object id or null}: "
                                         "which object plays each task role; roles left out are bound by "
                                         "the harness by category and attributes.")
    agent: Agent = Field(default_factory=Agent, description="Where the agent starts.")

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


def unknown_state_flags(env: EnvSpec) -> list[str]:
    """One problem per object that states a flag the condition language has no word for
    (`conditions.STATE_FLAGS`): such an environment says something no task can read. Real
    replies put their schema's own words there (`"states": {"additionalProperties": false}`:
    9 of Qwen2.5-Coder-1.5B's 11 scenes). A problem of the environment, as an unbound role is:
    `lint` reports it and the scorer counts the environment ill-formed."""
    return _unknown(env, "states", STATE_FLAGS, "state flag(s)", f"state flags are {', '.join(STATE_FLAGS)}")


def unknown_attribute_keys(env: EnvSpec, known: Collection[str]) -> list[str]:
    """One problem per object that states an attribute key outside `known` (for a task:
    `domain.attributes.attribute_keys`), as `unknown_state_flags` does for state flags."""
    return _unknown(env, "attributes", known, "attribute(s)",
                    f"attributes a task can read: {', '.join(sorted(known))}")


def _unknown(env: EnvSpec, field: Literal["states", "attributes"], known: Collection[str], what: str,
             listed: str) -> list[str]:
    """`object <id> states unknown <what> [...] (<listed>)` per object whose `field` has keys
    outside `known`."""
    out = []
    for o in env.objects:
        unknown = sorted(set(getattr(o, field)) - set(known))
        if unknown:
            out.append(f"object {o.id} states unknown {what} {unknown} ({listed})")
    return out
