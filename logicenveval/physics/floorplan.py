"""Floor-plan dimension: room polygons, overlaps, connectivity, doors and windows.

Doors stand on the floor by construction (EnvSpec doors have no bottom), so "bottom on the
floor" reduces to a positive height; "below the ceiling" is height <= wall_height. A window is
embedded in its wall: its segment within the room's outline (horizontally) and sill > 0 and
sill + height <= wall_height (vertically).
"""

from __future__ import annotations

import math
from functools import lru_cache

from shapely.geometry import LineString, Point, Polygon
from shapely.geometry.base import BaseGeometry

from logicenveval.model.envspec import Door, EnvSpec
from logicenveval.physics.geometry import finite, rect_pairs
from logicenveval.physics.report import PhysicsFailure, Tolerances


def _fail(code: str, message: str, *, rooms: list[str] | None = None, objects: list[str] | None = None,
          measured: float | None = None, tolerance: float | None = None) -> PhysicsFailure:
    return PhysicsFailure(dimension="floor_plan", code=code, rooms=rooms or [], objects=objects or [],
                          measured=measured, tolerance=tolerance, message=message)


@lru_cache(maxsize=4096)
def _room_polygon(points: tuple[tuple[float, float], ...]) -> tuple[Polygon, bool, float]:
    """The outline's polygon, whether it is valid, its area: generators lay out many
    environments of a task in the same rooms, so each outline is built and validated once
    (shapely geometries are immutable, so sharing them is safe)."""
    poly = Polygon(points)
    return poly, bool(poly.is_valid), float(poly.area)


@lru_cache(maxsize=8192)
def _grown(points: tuple[tuple[float, float], ...], width: float, outline: bool) -> BaseGeometry:
    poly = _room_polygon(points)[0]
    return (poly.exterior if outline else poly).buffer(width)


def room_band(env: EnvSpec, room_id: str, poly: Polygon, width: float, *,
              outline: bool = False) -> BaseGeometry:
    """`poly` (the valid polygon of room `room_id`, `valid_rooms`) buffered by `width` — its
    outline only with `outline` (the wall band): built once per outline and width."""
    for room in env.rooms:
        if room.id == room_id and room.polygon is not None:
            key = tuple(room.polygon)
            if _room_polygon(key)[0] is poly:
                return _grown(key, width, outline)
    return (poly.exterior if outline else poly).buffer(width)


def valid_rooms(env: EnvSpec, fails: list[PhysicsFailure]) -> dict[str, Polygon]:
    """Polygons of the rooms that are valid simple polygons; a failure for each other room."""
    polys: dict[str, Polygon] = {}
    for room in env.rooms:
        pts = room.polygon
        if pts is None:
            fails.append(_fail("missing_geometry", f"room {room.id} has no polygon", rooms=[room.id]))
            continue
        if len(pts) < 3:
            fails.append(_fail("invalid_polygon", f"room {room.id} polygon has {len(pts)} points (need >= 3)",
                               rooms=[room.id], measured=float(len(pts)), tolerance=3.0))
            continue
        if not finite(*(c for p in pts for c in p)):  # shapely raises on NaN/inf before is_valid
            fails.append(_fail("invalid_polygon", f"room {room.id} polygon has a non-finite coordinate",
                               rooms=[room.id]))
            continue
        poly, valid, area = _room_polygon(tuple(pts))
        if not valid or area <= 0:
            fails.append(_fail("invalid_polygon",
                               f"room {room.id} polygon is not a simple polygon with positive area",
                               rooms=[room.id], measured=area))
            continue
        polys[room.id] = poly
    return polys


def _overlaps(polys: dict[str, Polygon], tol: Tolerances) -> list[PhysicsFailure]:
    """Pairs of rooms (in room order) overlapping by more than the tolerance; only rooms whose
    bounds meet are intersected (a sweep over the bounds, not all pairs)."""
    items = list(polys.items())
    bounds = [p.bounds for _, p in items]
    out = []
    for i, j in rect_pairs(bounds, bounds):
        if i >= j:
            continue
        (a, pa), (b, pb) = items[i], items[j]
        area = float(pa.intersection(pb).area)
        if area > tol.room_overlap_area:
            out.append(_fail("rooms_overlap", f"rooms {a} and {b} overlap by {area:.3f} m²",
                             rooms=[a, b], measured=area, tolerance=tol.room_overlap_area))
    return out


def _connectivity(env: EnvSpec) -> list[PhysicsFailure]:
    ids = [r.id for r in env.rooms]
    if len(ids) < 2:
        return []
    adj: dict[str, set[str]] = {r: set() for r in ids}
    for d in env.doors:
        a, b = d.rooms
        if a in adj and b in adj and a != b:
            adj[a].add(b)
            adj[b].add(a)
    seen = {ids[0]}
    stack = [ids[0]]
    while stack:
        for n in adj[stack.pop()] - seen:
            seen.add(n)
            stack.append(n)
    return [_fail("unreachable_room", f"room {r} cannot be reached from {ids[0]} through doors",
                  rooms=[r]) for r in ids if r not in seen]


def _on_wall(seg: LineString, wall_band: BaseGeometry) -> bool:
    """Whether the segment lies within `wall_band` (a room outline buffered by the tolerance)."""
    return bool(wall_band.contains(seg))


def _door(d: Door, env: EnvSpec, polys: dict[str, Polygon], bands: dict[str, BaseGeometry],
          near: list[str], tol: Tolerances) -> list[PhysicsFailure]:
    """The door's findings; `near` are the rooms whose wall bands' bounds meet its segment's."""
    out: list[PhysicsFailure] = []
    if not 0 < d.height <= env.wall_height - tol.ceiling_margin:
        out.append(_fail("door_height", f"door {d.id} height {d.height} m must be in (0, wall_height "
                         f"{env.wall_height} m]", objects=[d.id], measured=d.height, tolerance=env.wall_height))
    if d.segment is None or not finite(*d.segment[0], *d.segment[1]):
        out.append(_fail("missing_geometry", f"door {d.id} has no finite segment", objects=[d.id]))
        return out
    seg = LineString(d.segment)
    if seg.length <= 0:
        out.append(_fail("door_degenerate", f"door {d.id} has zero width", objects=[d.id], measured=0.0))
        return out
    rooms = [r for r in d.rooms if r != "exterior"]
    for r in rooms:
        if r not in polys:
            continue
        poly = polys[r]
        if not _on_wall(seg, bands[r]):
            dist = float(poly.exterior.distance(seg.centroid))
            code = "door_exceeds_wall" if dist <= tol.on_wall else "door_not_on_wall"
            out.append(_fail(code, f"door {d.id} is not within a wall of room {r} "
                             f"(midpoint {dist:.3f} m from the wall)", objects=[d.id], rooms=[r],
                             measured=dist, tolerance=tol.on_wall))
    if "exterior" in d.rooms and rooms:
        others = [o for o in near if o not in rooms and _on_wall(seg, bands[o])]
        if others:
            out.append(_fail("door_not_exterior", f"exterior door {d.id} is on a wall shared with "
                             f"room {others[0]}", objects=[d.id], rooms=[*rooms, others[0]]))
    if d.rooms[0] == d.rooms[1]:
        out.append(_fail("door_rooms", f"door {d.id} connects {d.rooms[0]} to itself", objects=[d.id]))
    return out


def _bounds(seg: tuple[tuple[float, float], tuple[float, float]] | None,
            grow: float = 0.0) -> tuple[float, float, float, float]:
    """Bounds (x0, z0, x1, z1) of a segment grown by `grow`; NaN (meets nothing) without one."""
    if seg is None:
        return (math.nan,) * 4
    (ax, az), (bx, bz) = seg
    return (min(ax, bx) - grow, min(az, bz) - grow, max(ax, bx) + grow, max(az, bz) + grow)


def check_floor_plan(env: EnvSpec, tol: Tolerances) -> tuple[list[PhysicsFailure], dict[str, Polygon]]:
    """Floor-plan failures and the valid room polygons (reused by the other dimensions)."""
    fails: list[PhysicsFailure] = []
    if not (finite(env.wall_height) and env.wall_height > 0):
        fails.append(_fail("invalid_wall_height", f"wall_height {env.wall_height} is not a positive number",
                           measured=env.wall_height, tolerance=0.0))
    polys = valid_rooms(env, fails)
    fails += _overlaps(polys, tol)
    fails += _connectivity(env)
    bands = {rid: room_band(env, rid, p, tol.on_wall, outline=True) for rid, p in polys.items()}
    band_ids = list(bands)
    near: dict[int, list[str]] = {}
    for k, r in rect_pairs([_bounds(d.segment) for d in env.doors], [b.bounds for b in bands.values()]):
        near.setdefault(k, []).append(band_ids[r])
    for k, d in enumerate(env.doors):
        fails += _door(d, env, polys, bands, near.get(k, []), tol)
    door_at: dict[int, list[int]] = {}  # window -> doors whose segments come within the tolerance
    grown = [_bounds(w.segment, tol.on_wall) for w in env.windows]
    for k, m in rect_pairs(grown, [_bounds(d.segment) for d in env.doors]):
        door_at.setdefault(k, []).append(m)
    for k, w in enumerate(env.windows):  # Table 2: "embedded in the wall and positioned above the floor"
        if not w.sill > 0:
            fails.append(_fail("window_sill", f"window {w.id} sill {w.sill} m is not above the floor",
                               objects=[w.id], rooms=[w.room], measured=w.sill, tolerance=0.0))
        top = w.sill + w.height
        if not (w.height > 0 and top <= env.wall_height - tol.ceiling_margin):
            fails.append(_fail("window_above_ceiling", f"window {w.id} top {top:.2f} m is not within the "
                               f"wall (wall height {env.wall_height} m, window height {w.height} m)",
                               objects=[w.id], rooms=[w.room], measured=top, tolerance=env.wall_height))
        if w.segment is None or not finite(*w.segment[0], *w.segment[1]):
            fails.append(_fail("missing_geometry", f"window {w.id} has no finite segment", objects=[w.id]))
            continue
        seg = LineString(w.segment)
        poly = polys.get(w.room)
        if poly is not None and not _on_wall(seg, bands[w.room]):
            dist = max(float(poly.exterior.distance(Point(c))) for c in seg.coords)
            fails.append(_fail("window_not_on_wall", f"window {w.id} is not within a wall of room {w.room}",
                               objects=[w.id], rooms=[w.room], measured=dist, tolerance=tol.on_wall))
        for d in (env.doors[m] for m in door_at.get(k, ())):
            if w.room not in d.rooms or d.segment is None or not finite(*d.segment[0], *d.segment[1]):
                continue  # a door without finite geometry is its own finding (shapely crashes on NaN)
            shared = float(LineString(d.segment).buffer(tol.on_wall).intersection(seg).length)
            if shared > tol.on_wall:
                fails.append(_fail("window_overlaps_door", f"window {w.id} overlaps door {d.id} "
                                   f"along {shared:.2f} m of wall", objects=[w.id, d.id], rooms=[w.room],
                                   measured=shared, tolerance=tol.on_wall))
    return fails, polys
