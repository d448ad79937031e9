"""What a layout backend solves: boxes in a cell frame, wall objects on wall segments, relations.

Everything is on an integer grid (`grid` metres per cell). Object sizes are snapped to the grid
when the catalog range allows, so a placed box is exactly its cell box. Orientation `o` in 0..3 is
yaw `90*o`; the front of an object is +z after yaw (AI2-THOR), i.e. +z, +x, -z, -x.
Backends (`layout_z3`, `layout_cpsat`) implement the same `pack`/`pack_walls` contract and are
looked up by name with `backend`, imported only when used; `layout_auto` dispatches each packing to
one of them by its size and density.
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Literal, Protocol, get_args

from logicenveval.errors import EnvSpecError
from logicenveval.phases import phase
from logicenveval.scene.geometry import Rect
from logicenveval.scene.relax import Dropped
from logicenveval.scene.spec import RelationRequest

#: metres of free floor in front of each task object for the agent to approach. A walkway strip is
#: exclusive: clear of the other boxes, of the other strips and of door squares (CP-SAT packs box +
#: strip as one rectangle in the floor's NoOverlap2D). Until issue 38 floors of fewer than 16 boxes
#: kept each strip clear of the other boxes only, with one NoOverlap2D per strip: that took half
#: of the offline run's floor solves (docs/scene.md "Exclusive walkways")
WALKWAY = 0.45

#: floors with at least this many boxes get CP-SAT's stronger NoOverlap2D propagation (timetabling
#: and try-edge reasoning). Measured per floor on `benchmarks/layout.py` rooms (docs/scene.md): up
#: to 15 boxes it costs 1.2-2.9x, from 20 boxes it pays (0.3-1.3x at 20, 0.05-0.4x at 30-50: a
#: dense 40-box floor 1.4 s -> 0.09 s); no effect on Z3.
STRONG_NO_OVERLAP_FROM = 16

NEAR_AXIS = 0.7  # per-axis footprint gap: sqrt(2)*0.7 < 1.0 m (DESIGN §6 near)
FAR = 2.5
IN_FRONT_GAP = NEAR_AXIS + 0.25  # in_front_of / side_of: gap along one axis only, < 1.0 m
#: the relation types a backend encodes on a floor (`FloorRel`); others hold by placement or are dropped
FLOOR_RELATIONS = frozenset({"edge", "center", "near", "far", "center_aligned", "in_front_of", "face_to", "side_of"})

Solver = Literal["z3", "cpsat", "auto"]
SOLVERS: tuple[str, ...] = get_args(Solver)
DEFAULT_SOLVER: Solver = "cpsat"


@dataclass(frozen=True)
class Box:
    id: str
    size: tuple[float, float, float]  # exact extents x, y, z (metres) before yaw
    cells: tuple[int, int]  # footprint extents in cells (x, z) before yaw
    task: bool


@dataclass(frozen=True)
class Placed:
    """Footprint corner (x0, z0) in metres, orientation 0..3 (yaw = 90*o)."""

    x0: float
    z0: float
    o: int


@dataclass(frozen=True)
class FloorRel:
    """A relation to enforce on the floor, arguments mapped to floor objects.

    `slack[i]` is how far (metres) argument i may lie from its floor object (objects on surfaces).
    """

    rel: RelationRequest
    task: bool
    args: tuple[str, ...]
    slack: tuple[float, ...]


@dataclass(frozen=True)
class WallBox:
    id: str
    length: int  # cells along the wall
    bottom: float
    height: float
    task: bool


Obstacle = tuple[int, int, int, int]  # x0, z0, x1, z1 in cells
WallSegment = tuple[int, list[tuple[int, int, float, float]]]  # length, blocked (lo, hi, bottom, top)
Side = Literal["s", "n", "w", "e"]

#: cells kept between two openings on one side of a floor (`floorplan.GAP` = 0.1 m at 5 cm)
OPENING_GAP_CELLS = 2


@dataclass(frozen=True)
class Opening:
    """A door or window whose position along one side of a floor frame the solver chooses
    (paper §3.3: "the doorway and window positions" are variables of the CSP).

    `side` is `s` (z = 0), `n` (z = D), `w` (x = 0) or `e` (x = W) of the frame; `starts` the
    inclusive ranges of cells where it may start along that side; `width` its cells along the
    side; `depth` the cells of clearance in front of it, kept free of every box for a door (its
    swing square) or, with `sill`, of the boxes taller than the sill (a window). Openings on one
    side keep `gap` cells apart, and door clearances do not overlap each other or the obstacles.
    """

    id: str
    side: Side
    starts: tuple[tuple[int, int], ...]
    width: int
    depth: int
    sill: float | None = None  # None: a door
    gap: int = OPENING_GAP_CELLS


def opening_rect(op: Opening, t: Any, frame: tuple[int, int]) -> tuple[Any, Any, Any, Any]:
    """(x0, z0, x1, z1) of an opening's clearance when it starts at cell `t` (an int or a solver
    expression)."""
    W, D = frame
    if op.side == "s":
        return t, 0, t + op.width, op.depth
    if op.side == "n":
        return t, D - op.depth, t + op.width, D
    if op.side == "w":
        return 0, t, op.depth, t + op.width
    return W - op.depth, t, W, t + op.width


def opening_start(op: Opening, t: int, frame: tuple[int, int], grid: float) -> Placed:
    """The `Placed` a backend returns for an opening: its start point on its side, in metres."""
    W, D = frame
    x, z = {"s": (t, 0), "n": (t, D), "w": (0, t), "e": (W, t)}[op.side]
    return Placed(x * grid, z * grid, 0)


class Backend(Protocol):
    """A layout backend module: `pack` places floor/surface boxes, `pack_walls` wall objects."""

    def pack(self, frame: tuple[int, int], boxes: Sequence[Box], *, seed: int, timeout_s: float,
             obstacles: Sequence[Obstacle] = (), tall: Sequence[tuple[Obstacle, float]] = (),
             walkway: int = 0, rels: Sequence[FloorRel] = (), grid: float = 0.05,
             free_rotation: bool = True, openings: Sequence[Opening] = ()) -> tuple[dict[str, Placed], list[Dropped]]:
        """Non-overlapping boxes in a `frame` of cells; obstacles in cells; `tall` only for taller boxes;
        doors and windows on the frame's sides at positions the solver chooses (`Opening`).

        Returns placements (corner in cells times `grid`) of the boxes kept, each opening's start
        point on its side (`opening_start`), and the relaxation drops. Task boxes and openings are
        hard; if they cannot be placed, nothing is returned.
        """

    def pack_walls(self, walls: Sequence[WallSegment], boxes: Sequence[WallBox], *, seed: int,
                   timeout_s: float) -> tuple[dict[str, tuple[int, int]], list[Dropped]]:
        """Wall objects on wall segments: per wall its length and blocked stretches (lo, hi, bottom, top).

        A stretch blocks a box whose vertical extent meets [bottom, top]. Returns (wall index, start cell).
        """


def backend(name: str) -> Backend:
    """The layout backend called `name`: 'z3', 'cpsat' or 'auto' (per sub-problem, `layout_auto`)."""
    if name not in SOLVERS:
        raise EnvSpecError(f"unknown layout solver {name!r}", field="solver",
                           hint=f"use one of {', '.join(SOLVERS)} (docs/scene.md compares them)")
    return _Timed(importlib.import_module(f"logicenveval.scene.layout_{name}"))


class _Timed:
    """A backend whose packings count as the `layout` phase of a unit (`logicenveval.phases`)."""

    def __init__(self, mod: Any) -> None:
        self._mod = mod

    def pack(self, *args: Any, **kwargs: Any) -> tuple[dict[str, Placed], list[Dropped]]:
        with phase("layout"):
            out: tuple[dict[str, Placed], list[Dropped]] = self._mod.pack(*args, **kwargs)
        return out

    def pack_walls(self, *args: Any, **kwargs: Any) -> tuple[dict[str, tuple[int, int]], list[Dropped]]:
        with phase("layout"):
            out: tuple[dict[str, tuple[int, int]], list[Dropped]] = self._mod.pack_walls(*args, **kwargs)
        return out

    def __getattr__(self, attr: str) -> Any:
        return getattr(self._mod, attr)


def cells(v: float, grid: float) -> int:
    """`v` metres in whole cells, rounded up (sizes never shrink)."""
    return int(math.ceil(v / grid - 1e-6))


def rect_cells(r: Rect, origin: tuple[float, float], grid: float) -> Obstacle:
    """A world rectangle as cells relative to `origin`, rounded outwards."""
    return (int(math.floor((r.x0 - origin[0]) / grid + 1e-6)), int(math.floor((r.z0 - origin[1]) / grid + 1e-6)),
            cells(r.x1 - origin[0], grid), cells(r.z1 - origin[1], grid))
