"""Typed outcome of a physics check: failures per PhyPR dimension (paper Table 2).

A report is data, never an exception, so that runs can store it in `samples.jsonl` and the
leaderboard can count pass rates per dimension. The three PhyPR dimensions hold exactly the
paper's constraints; our extra plausibility checks (`EXTENDED_CODES`) are reported apart, in
`extended`, so that PhyPR means what the paper's PhyPR means (docs/fidelity.md).
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

Dimension = Literal["floor_plan", "entity", "relation"]
DIMENSIONS: tuple[Dimension, ...] = ("floor_plan", "entity", "relation")

#: failure codes of checks the paper's Table 2 does not list: catalog size ranges, door swing
#: areas, objects through the ceiling, rooms unreachable by doors, windows over doors. They go
#: to `PhysicsReport.extended`. (A centre of mass beside its supporter and a window through the
#: ceiling are Table 2 failures: "not floating", "embedded in the wall"; docs/physics.md.)
EXTENDED_CODES: frozenset[str] = frozenset({
    "size_out_of_range", "blocks_door", "above_ceiling", "unreachable_room", "window_overlaps_door",
})


class Tolerances(BaseModel):
    """Every threshold the checker uses, in metres / m² / fractions (see docs/physics.md)."""

    model_config = ConfigDict(frozen=True, extra="forbid")
    room_overlap_area: float = 1e-4
    on_wall: float = 0.02          # door/window segment distance to a wall line
    door_floor: float = 0.02       # door bottom is y = 0 by definition; kept for completeness
    ceiling_margin: float = 0.0    # door/window top must be <= wall_height - margin
    support_gap: float = 0.02      # |bottom - support top|
    settle_drop: float = 0.10      # a bottom this far above a support settles onto it (docs/physics.md)
    penetration: float = 0.01      # deepest allowed interpenetration between unrelated objects
    wall_gap: float = 0.05         # wall-mounted back face to wall
    containment: float = 0.02      # contained box may stick out of its container by this much
    room_margin: float = 0.02      # footprint may stick out of its room polygon by this much
    size_ratio: float = 0.10       # catalog size range widened by ±10 %
    near_gap: float = 1.0          # DESIGN.md §6
    far_distance: float = 2.5      # DESIGN.md §6
    edge_gap: float = 0.1
    center_ratio: float = 0.25     # centre within 25 % of the room's smaller extent of its centroid
    facing_angle: float = 45.0     # degrees: half-angle of the front cone
    align_offset: float = 0.1      # center_aligned: lateral offset of centres


DEFAULT_TOLERANCES = Tolerances()


class PhysicsFailure(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")
    dimension: Dimension
    code: str
    objects: list[str] = Field(default_factory=list)
    rooms: list[str] = Field(default_factory=list)
    measured: float | None = None
    tolerance: float | None = None
    message: str


class DimensionReport(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")
    passed: bool
    failures: list[PhysicsFailure] = Field(default_factory=list)

    @classmethod
    def of(cls, failures: list[PhysicsFailure]) -> DimensionReport:
        return cls(passed=not failures, failures=failures)


class PhysicsReport(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")
    floor_plan: DimensionReport
    entity: DimensionReport
    relation: DimensionReport
    #: the extra plausibility checks (`EXTENDED_CODES`); each failure keeps the dimension it
    #: was found in. Not part of PhyPR or `passed`.
    extended: DimensionReport = Field(default_factory=lambda: DimensionReport(passed=True))

    @property
    def passed(self) -> bool:
        """The paper's PhyPR: all three dimensions pass (extended checks not included)."""
        return self.floor_plan.passed and self.entity.passed and self.relation.passed

    def failures(self) -> list[PhysicsFailure]:
        """Every failure, the extended checks' included (for renders and logs)."""
        return [*self.floor_plan.failures, *self.entity.failures, *self.relation.failures,
                *self.extended.failures]

    def failed_dimensions(self) -> set[Dimension]:
        return {d for d in DIMENSIONS if not getattr(self, d).passed}


__all__ = ["DIMENSIONS", "DEFAULT_TOLERANCES", "EXTENDED_CODES", "Dimension", "DimensionReport", "PhysicsFailure",
           "PhysicsReport", "Tolerances"]
