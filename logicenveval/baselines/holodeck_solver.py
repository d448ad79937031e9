"""Holodeck's layout solver, re-implemented: DFS over a grid of candidate poses per object.

As in Holodeck (Yang et al., 2024), floor objects are placed one at a time, largest (and
wall-bound) first; each has a grid of candidate poses (positions every `grid` metres, yaw a
multiple of 90°), filtered by hard constraints (inside the room, no collision with placed objects
or door clearances, `edge` = flush against a wall, `near` = footprint gap ≤ 1 m from an already
placed partner) and ranked by soft ones (`face_to`, then closeness to a wall, which keeps the middle of the room
free, then a seeded random tie-break); depth-first
search with backtracking over the best `branch` candidates, within `max_nodes`. When the search
fails the constraints are relaxed (relations dropped, then objects that still cannot be placed are
left out, as Holodeck does). Wall objects go on free wall stretches (not over doors or windows);
small objects on a free spot of their support's top or inside their container.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

NEAR_GAP = 1.0  # DESIGN.md §6: `near` means footprint gap ≤ 1.0 m
EDGE_GAP = 0.01  # distance kept from a wall by `edge` objects
DOOR_CLEARANCE = 0.9  # depth kept free in front of a door, on both sides
MARGIN = 0.02  # gap kept between objects


@dataclass(frozen=True)
class Box:
    """An axis-aligned footprint (centre x, z; extents along x, z) in room coordinates."""

    x: float
    z: float
    fx: float
    fz: float

    def overlaps(self, other: Box, margin: float = MARGIN) -> bool:
        return (abs(self.x - other.x) * 2 < self.fx + other.fx + 2 * margin - 1e-9
                and abs(self.z - other.z) * 2 < self.fz + other.fz + 2 * margin - 1e-9)

    def gap(self, other: Box) -> float:
        dx = max(0.0, abs(self.x - other.x) - (self.fx + other.fx) / 2)
        dz = max(0.0, abs(self.z - other.z) - (self.fz + other.fz) / 2)
        return float(np.hypot(dx, dz))


@dataclass
class FloorItem:
    id: str
    size: tuple[float, float, float]
    edge: bool = False
    near: list[str] = field(default_factory=list)
    face_to: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class Pose:
    box: Box
    yaw: float


@dataclass
class RoomLayout:
    poses: dict[str, Pose]
    dropped: list[str]
    relaxed: list[str]  # relation constraints given up, as "type:a:b"


def _yaw_extents(size: tuple[float, float, float], yaw: float) -> tuple[float, float]:
    return (size[2], size[0]) if yaw in (90.0, 270.0) else (size[0], size[2])


def _axis(lo: float, hi: float, grid: float) -> list[float]:
    if hi < lo - 1e-9:
        return []
    n = int(np.floor((hi - lo) / grid + 1e-9))
    return [lo + i * grid for i in range(n + 1)] + ([hi] if (hi - lo) % grid > 1e-6 else [])


def candidates(item: FloorItem, width: float, depth: float, grid: float) -> list[Pose]:
    """All poses of `item` inside a width × depth room; `edge` items only flush against a wall,
    their back to it (yaw 0 south, 180 north, 90 west, 270 east)."""
    out: list[Pose] = []
    if item.edge:
        for yaw in (0.0, 180.0, 90.0, 270.0):
            fx, fz = _yaw_extents(item.size, yaw)
            if fx > width - 2 * EDGE_GAP or fz > depth - 2 * EDGE_GAP:
                continue
            if yaw in (0.0, 180.0):
                z = fz / 2 + EDGE_GAP if yaw == 0.0 else depth - fz / 2 - EDGE_GAP
                out += [Pose(Box(x, z, fx, fz), yaw) for x in _axis(fx / 2 + EDGE_GAP, width - fx / 2 - EDGE_GAP, grid)]
            else:
                x = fx / 2 + EDGE_GAP if yaw == 90.0 else width - fx / 2 - EDGE_GAP
                out += [Pose(Box(x, z, fx, fz), yaw) for z in _axis(fz / 2 + EDGE_GAP, depth - fz / 2 - EDGE_GAP, grid)]
        return out
    for yaw in (0.0, 90.0):
        fx, fz = _yaw_extents(item.size, yaw)
        for x in _axis(fx / 2 + MARGIN, width - fx / 2 - MARGIN, grid):
            out += [Pose(Box(x, z, fx, fz), yaw) for z in _axis(fz / 2 + MARGIN, depth - fz / 2 - MARGIN, grid)]
    return out


def _faces(pose: Pose, target: Box) -> bool:
    """Whether the object's front (+z at yaw 0, rotated) points towards `target`."""
    rad = np.deg2rad(pose.yaw)
    front = np.array([np.sin(rad), np.cos(rad)])
    to = np.array([target.x - pose.box.x, target.z - pose.box.z])
    norm = float(np.linalg.norm(to))
    return norm > 0 and float(front @ to) / norm > 0.7


def solve_floor(
    items: list[FloorItem],
    width: float,
    depth: float,
    obstacles: list[Box],
    rng: np.random.Generator,
    *,
    grid: float = 0.25,
    branch: int = 6,
    max_nodes: int = 4000,
) -> RoomLayout:
    """Poses for `items` in a room (coordinates from its south-west corner), with relaxation."""
    order = sorted(items, key=lambda it: (not it.edge, -it.size[0] * it.size[2], it.id))
    pools = {it.id: candidates(it, width, depth, grid) for it in order}
    for it in order:
        rng.shuffle(pools[it.id])
    result = _dfs(order, pools, obstacles, width, depth, use_relations=True, branch=branch, max_nodes=max_nodes)
    if result is not None:
        return RoomLayout(result, [], [])
    relaxed = [f"{kind}:{it.id}:{o}" for it in order for kind, others in (("near", it.near), ("face_to", it.face_to))
               for o in others]
    result = _dfs(order, pools, obstacles, width, depth, use_relations=False, branch=branch, max_nodes=max_nodes)
    if result is not None:
        return RoomLayout(result, [], relaxed)
    poses: dict[str, Pose] = {}
    dropped: list[str] = []
    for it in order:  # last resort: greedy, leaving out what does not fit
        pose = next((p for p in pools[it.id] if _free(p.box, poses, obstacles)), None)
        if pose is None:
            dropped.append(it.id)
        else:
            poses[it.id] = pose
    return RoomLayout(poses, dropped, relaxed)


def _free(box: Box, poses: dict[str, Pose], obstacles: list[Box]) -> bool:
    return not any(box.overlaps(p.box) for p in poses.values()) and not any(box.overlaps(o, 0.0) for o in obstacles)


def _wall_distance(box: Box, width: float, depth: float) -> tuple[int, int]:
    """Distances to the nearest and second-nearest wall, in 5 cm steps (corners rank first)."""
    d = sorted((box.x - box.fx / 2, width - box.x - box.fx / 2, box.z - box.fz / 2, depth - box.z - box.fz / 2))
    return round(d[0] / 0.05), round(d[1] / 0.05)


def _dfs(order: list[FloorItem], pools: dict[str, list[Pose]], obstacles: list[Box], width: float, depth: float,
         *, use_relations: bool, branch: int, max_nodes: int) -> dict[str, Pose] | None:
    poses: dict[str, Pose] = {}
    budget = [max_nodes]
    near: dict[str, set[str]] = {it.id: set(it.near) for it in order}
    for it in order:  # `near` binds both objects, whichever is placed second
        for other in it.near:
            near.setdefault(other, set()).add(it.id)

    def ranked(it: FloorItem) -> list[Pose]:
        ok: list[tuple[int, tuple[int, int], int, Pose]] = []
        for p in pools[it.id]:
            if not _free(p.box, poses, obstacles):
                continue
            if use_relations and any(n in poses and p.box.gap(poses[n].box) > NEAR_GAP for n in near[it.id]):
                continue
            score = sum(_faces(p, poses[t].box) for t in it.face_to if t in poses) if use_relations else 0
            ok.append((-score, _wall_distance(p.box, width, depth), len(ok), p))
        return [t[-1] for t in sorted(ok, key=lambda t: t[:3])[:branch]]

    def place(i: int) -> bool:
        if i == len(order):
            return True
        for pose in ranked(order[i]):
            budget[0] -= 1
            if budget[0] < 0:
                return False
            poses[order[i].id] = pose
            if place(i + 1):
                return True
            del poses[order[i].id]
        return False

    return dict(poses) if place(0) else None


def wall_spots(width: float, depth: float, blocked: dict[str, list[tuple[float, float]]], length: float,
               step: float = 0.1) -> list[tuple[str, float]]:
    """(wall, centre along the wall) of free stretches of `length`, walls s, n, w, e in turn."""
    out = []
    for wall in ("n", "s", "w", "e"):
        along = width if wall in "ns" else depth
        for c in _axis(length / 2 + 0.1, along - length / 2 - 0.1, step):
            if not any(c + length / 2 > a and c - length / 2 < b for a, b in blocked.get(wall, [])):
                out.append((wall, c))
    return out


def surface_spot(top: Box, size: tuple[float, float, float], taken: list[Box], grid: float = 0.05) -> Box | None:
    """A free footprint of `size` on a support's top (or a container's floor), or None."""
    fx, fz = size[0], size[2]
    xs = _axis(top.x - top.fx / 2 + fx / 2, top.x + top.fx / 2 - fx / 2, grid)
    zs = _axis(top.z - top.fz / 2 + fz / 2, top.z + top.fz / 2 - fz / 2, grid)
    for x in xs:  # packed from the west edge, centred in depth, so that several items fit
        for z in sorted(zs, key=lambda v: abs(v - top.z)):
            box = Box(x, z, fx, fz)
            if not any(box.overlaps(t, 0.005) for t in taken):
                return box
    return None
