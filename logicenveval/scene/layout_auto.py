"""The `auto` layout backend: picks Z3 or CP-SAT per sub-problem (floor, surface, walls) by measurement.

Both backends enforce the same constraints, so the choice only moves time. The rule is what
`benchmarks/layout.py --crossover` measures. On 2026-11-23 (load 2-3.4) Z3 was faster on sparse
floors of 4-7 boxes, so `auto` sent those to Z3. Since then exclusive walkway strips made CP-SAT's
floor model a third to a half cheaper; re-measured on an idle machine (2026-11-27, 3-5 rooms per
size, area factors 1, 0.35 and 0.25, docs/scene.md) Z3's median time is 1.05-1.92x CP-SAT's on
every floor size and fill (3-8 boxes, 6-54 % covered) and up to 5.9x on 8 boxes; CP-SAT was
already faster on every surface, container, ceiling and wall sub-problem (Z3 3-13x slower). So
`auto` now sends every sub-problem to CP-SAT, as the default does, until a measurement finds a
sub-problem where Z3 wins.
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


def choose(frame: tuple[int, int], boxes: Sequence[Box], walkway: int) -> Solver:
    """The backend `auto` uses for one packing: CP-SAT, faster on every floor, surface and wall
    sub-problem measured (see the module docstring)."""
    return "cpsat"


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
