"""Typed requests of scene construction and its typed result.

Generators turn LLM replies into these requests; everything downstream is deterministic given a
`numpy.random.Generator`, so a scene can be rebuilt and tested without a model.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from logicenveval.model.envspec import RELATION_TYPES, EnvSpec

_Cfg = ConfigDict(frozen=True, extra="forbid")

Wall = Literal["n", "s", "e", "w"]


class DoorRequest(BaseModel):
    model_config = _Cfg
    to: str = Field(min_length=1)  # a room id or "exterior"
    type: str = "door"
    width: float = Field(default=0.9, ge=0.6, le=2.0)
    state: Literal["open", "closed"] = "closed"


class WindowRequest(BaseModel):
    model_config = _Cfg
    wall: Wall = "n"
    width: float = Field(default=1.2, ge=0.3, le=3.0)
    height: float = Field(default=1.2, ge=0.3, le=2.2)
    sill: float = Field(default=0.9, ge=0.1, le=1.5)
    state: Literal["open", "closed"] = "closed"


class RoomRequest(BaseModel):
    model_config = _Cfg
    id: str = Field(min_length=1)
    type: str = "LivingRoom"
    area: float = Field(default=20.0, ge=3.0, le=80.0)  # target floor area in m²
    adjacent_to: list[str] = Field(default_factory=list)
    doors: list[DoorRequest] = Field(default_factory=list)
    windows: list[WindowRequest] = Field(default_factory=list)


#: the placements that name no object
SURFACES = ("floor", "wall", "ceiling")


class ObjectRequest(BaseModel):
    """One object to place; `placement` is `floor`, `wall`, `ceiling`, `on:<id>` or `inside:<id>`."""

    model_config = _Cfg
    id: str = Field(min_length=1)
    category: str = Field(min_length=1)
    room: str = Field(min_length=1)
    role: str | None = None
    placement: str = "floor"
    task: bool | None = None  # None: a task object iff it plays a role
    size: tuple[float, float, float] | None = None  # None: sampled within the catalog range
    attributes: dict[str, str] = Field(default_factory=dict)
    states: dict[str, bool] = Field(default_factory=dict)

    @field_validator("placement")
    @classmethod
    def _placement(cls, v: str) -> str:
        if v in SURFACES or (v.startswith(("on:", "inside:")) and v.split(":", 1)[1]):
            return v
        raise ValueError(f"placement {v!r} must be 'floor', 'wall', 'on:<object id>' or 'inside:<object id>'")

    @property
    def is_task(self) -> bool:
        return self.task if self.task is not None else self.role is not None

    @property
    def support(self) -> str | None:
        """`floor`, `wall`, `ceiling`, an object id, or None when contained."""
        if self.placement.startswith("on:"):
            return self.placement[3:]
        if self.placement.startswith("inside:"):
            return None
        return self.placement

    @property
    def container(self) -> str | None:
        return self.placement[7:] if self.placement.startswith("inside:") else None

    @property
    def parent(self) -> str | None:
        """The object it rests on or in; None when it stands on the floor, a wall or the ceiling."""
        support = self.support
        return self.container or (support if support not in SURFACES else None)


class RelationRequest(BaseModel):
    model_config = _Cfg
    type: str
    args: tuple[str, ...]
    task: bool | None = None  # None: a task relation iff all its arguments are task objects

    @model_validator(mode="after")
    def _arity(self) -> RelationRequest:
        if self.type not in RELATION_TYPES:
            raise ValueError(f"unknown relation type {self.type!r}; use one of {sorted(RELATION_TYPES)}")
        if len(self.args) != RELATION_TYPES[self.type]:
            raise ValueError(f"relation {self.type!r} takes {RELATION_TYPES[self.type]} argument(s), got {len(self.args)}")
        return self

    def text(self) -> str:
        return f"{self.type}({', '.join(self.args)})"


class SceneSpec(BaseModel):
    model_config = _Cfg
    task_id: str
    env_id: str
    generator: str = "unknown"
    rooms: list[RoomRequest] = Field(min_length=1)
    objects: list[ObjectRequest] = Field(default_factory=list)
    relations: list[RelationRequest] = Field(default_factory=list)
    claimed_trajectory: dict[str, dict[str, str]] | None = None
    wall_height: float = Field(default=2.7, ge=2.2, le=5.0)
    grid: float = Field(default=0.05, ge=0.01, le=0.05)  # layout grid in metres (1–5 cm)
    #: the layout budget of a room, in seconds of deterministic solver work as calibrated (not
    #: wall clock: `scene.relax`), so a room that runs out does so on every machine alike
    room_timeout_s: float = Field(default=10.0, gt=0)


class RelaxationEntry(BaseModel):
    """One thing the solver gave up, and why (fed back to generators and reports)."""

    model_config = ConfigDict(frozen=True)
    room: str
    kind: Literal["relation", "object"]
    item: str  # relation text or object id
    task: bool
    reason: str

    def __str__(self) -> str:
        what = "task" if self.task else "enrichment"
        return f"{self.room}: dropped {what} {self.kind} {self.item}: {self.reason}"


class SceneResult(BaseModel):
    model_config = ConfigDict(frozen=True)
    env: EnvSpec
    relaxation_log: list[RelaxationEntry] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list)
