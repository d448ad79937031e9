"""Reply model of the Holodeck-like scene request (the other baselines reuse llm.replies)."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.llm.replies import ObjectDraft, RelationDraft, RoomDraft


class HolodeckSceneReply(BaseModel):
    """Holodeck's language stages in one reply: floor plan, objects, spatial relations (no coordinates:
    its own constraint solver places the objects)."""

    model_config = ConfigDict(frozen=True, extra="ignore")
    rooms: list[RoomDraft] = Field(min_length=1)
    objects: list[ObjectDraft] = Field(min_length=1)
    relations: list[RelationDraft] = Field(default_factory=list)
