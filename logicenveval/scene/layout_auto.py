"""The `auto` layout backend: picks Z3 or CP-SAT per sub-problem (floor, surface, walls) by measurement.

Both backends enforce the same constraints, so the choice only moves time. Measured per floor with
`benchmarks/layout.py --crossover` (5 rooms per size and area factor, three runs, 2026-11-23,
docs/scene.md): on sparse floors of 4-7 boxes (6-8 % of the floor covered) Z3 is consistently
faster (median time 0.60-0.82x CP-SAT's); on crowded ones (18-33 % covered) it is a toss-up
(0.51-1.44x, differing between runs); from 8 boxes on CP-SAT wins (Z3 1.2-4.9x, minutes on large
dense floors); 3 boxes are a tie. CP-SAT is faster on every surface, container, ceiling and wall
sub-problem measured (Z3 3-13x slower: its model building dominates these ~1 ms solves).
"""

from __future__ import annotations

from collections.abc import Sequence

from logicenveval.scene.layout import (
    Box,
    FloorRel,
    Obstacle,
    Opening,
    Placed,
    Solver,
    WallBox,
    WallSegment,
    backend,
)
from logicenveval.scene.relax import Dropped

#: floors (packings with a walkway) of this many boxes go to Z3 when they are sparse
Z3_FLOOR_BOXES = range(4, 8)
#: ... i.e. when the boxes' footprints cover less than this share of the floor: between the
#: measured sparse floors (6-8 %, Z3 faster in every run) and the crowded ones (18-33 %, no
#: consistent winner, so CP-SAT stays); nothing was measured in between
Z3_FLOOR_FILL = 0.15


def choose(frame: tuple[int, int], boxes: Sequence[Box], walkway: int) -> Solver:
    """The backend `auto` uses for one packing: Z3 for small sparse floors, CP-SAT otherwise."""
    if not walkway or len(boxes) not in Z3_FLOOR_BOXES:
        return "cpsat"
    area = frame[0] * frame[1]
    fill = sum(b.cells[0] * b.cells[1] for b in boxes) / area if area else 1.0
    return "z3" if fill < Z3_FLOOR_FILL else "cpsat"


def pack(frame: tuple[int, int], boxes: Sequence[Box], *, seed: int, timeout_s: float,
         obstacles: Sequence[Obstacle] = (), tall: Sequence[tuple[Obstacle, float]] = (),
         walkway: int = 0, rels: Sequence[FloorRel] = (), grid: float = 0.05,
         free_rotation: bool = True, openings: Sequence[Opening] = ()) -> tuple[dict[str, Placed], list[Dropped]]:
    """See `scene.layout.Backend.pack`; solved by the backend `choose` names."""
    return backend(choose(frame, boxes, walkway)).pack(
        frame, boxes, seed=seed, timeout_s=timeout_s, obstacles=obstacles, tall=tall, walkway=walkway,
        rels=rels, grid=grid, free_rotation=free_rotation, openings=openings)


def pack_walls(walls: Sequence[WallSegment], boxes: Sequence[WallBox], *, seed: int,
               timeout_s: float) -> tuple[dict[str, tuple[int, int]], list[Dropped]]:
    """See `scene.layout.Backend.pack_walls`: always CP-SAT (faster on every wall set measured)."""
    return backend("cpsat").pack_walls(walls, boxes, seed=seed, timeout_s=timeout_s)
