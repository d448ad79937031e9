"""Floor-plan dimension: room polygons, overlaps, connectivity, doors and windows.

Doors stand on the floor by construction (EnvSpec doors have no bottom), so "bottom on the
floor" reduces to a positive height; "below the ceiling" is height <= wall_height.
"""

from __future__ import annotations

from itertools import combinations

from shapely.geometry import LineString, Point, Polygon

from logicenveval.model.envspec import Door, EnvSpec
from logicenveval.physics.report import PhysicsFailure, Tolerances


def _fail(code: str, message: str, *, rooms: list[str] | None = None, objects: list[str] | None = None,
          measured: float | None = None, tolerance: float | None = None) -> PhysicsFailure:
    return PhysicsFailure(dimension="floor_plan", code=code, rooms=rooms or [], objects=objects or [],
                          measured=measured, tolerance=tolerance, message=message)


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
        poly = Polygon(pts)
        if not poly.is_valid or poly.area <= 0:
            fails.append(_fail("invalid_polygon",
                               f"room {room.id} polygon is not a simple polygon with positive area",
                               rooms=[room.id], measured=float(poly.area)))
            continue
        polys[room.id] = poly
    return polys


def _overlaps(polys: dict[str, Polygon], tol: Tolerances) -> list[PhysicsFailure]:
    out = []
    for (a, pa), (b, pb) in combinations(polys.items(), 2):
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


def _on_wall(seg: LineString, poly: Polygon, tol: float) -> bool:
    return bool(poly.exterior.buffer(tol).contains(seg))


def _door(d: Door, env: EnvSpec, polys: dict[str, Polygon], tol: Tolerances) -> list[PhysicsFailure]:
    out: list[PhysicsFailure] = []
    if d.height <= 0 or d.height > env.wall_height - tol.ceiling_margin:
        out.append(_fail("door_height", f"door {d.id} height {d.height} m must be in (0, wall_height "
                         f"{env.wall_height} m]", objects=[d.id], measured=d.height, tolerance=env.wall_height))
    if d.segment is None:
        out.append(_fail("missing_geometry", f"door {d.id} has no segment", objects=[d.id]))
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
        if not _on_wall(seg, poly, tol.on_wall):
            dist = float(poly.exterior.distance(seg.centroid))
            code = "door_exceeds_wall" if dist <= tol.on_wall else "door_not_on_wall"
            out.append(_fail(code, f"door {d.id} is not within a wall of room {r} "
                             f"(midpoint {dist:.3f} m from the wall)", objects=[d.id], rooms=[r],
                             measured=dist, tolerance=tol.on_wall))
    if "exterior" in d.rooms and rooms:
        others = [o for o, p in polys.items() if o not in rooms and _on_wall(seg, p, tol.on_wall)]
        if others:
            out.append(_fail("door_not_exterior", f"exterior door {d.id} is on a wall shared with "
                             f"room {others[0]}", objects=[d.id], rooms=[*rooms, others[0]]))
    if d.rooms[0] == d.rooms[1]:
        out.append(_fail("door_rooms", f"door {d.id} connects {d.rooms[0]} to itself", objects=[d.id]))
    return out


def check_floor_plan(env: EnvSpec, tol: Tolerances) -> tuple[list[PhysicsFailure], dict[str, Polygon]]:
    """Floor-plan failures and the valid room polygons (reused by the other dimensions)."""
    fails: list[PhysicsFailure] = []
    polys = valid_rooms(env, fails)
    fails += _overlaps(polys, tol)
    fails += _connectivity(env)
    for d in env.doors:
        fails += _door(d, env, polys, tol)
    for w in env.windows:
        if w.sill <= 0:
            fails.append(_fail("window_sill", f"window {w.id} sill {w.sill} m is not above the floor",
                               objects=[w.id], rooms=[w.room], measured=w.sill, tolerance=0.0))
        top = w.sill + w.height
        if w.height <= 0 or top > env.wall_height - tol.ceiling_margin:
            fails.append(_fail("window_above_ceiling", f"window {w.id} top {top:.2f} m is above the "
                               f"wall height {env.wall_height} m", objects=[w.id], rooms=[w.room],
                               measured=top, tolerance=env.wall_height))
        if w.segment is None:
            fails.append(_fail("missing_geometry", f"window {w.id} has no segment", objects=[w.id]))
            continue
        seg = LineString(w.segment)
        poly = polys.get(w.room)
        if poly is not None and not _on_wall(seg, poly, tol.on_wall):
            dist = max(float(poly.exterior.distance(Point(c))) for c in seg.coords)
            fails.append(_fail("window_not_on_wall", f"window {w.id} is not within a wall of room {w.room}",
                               objects=[w.id], rooms=[w.room], measured=dist, tolerance=tol.on_wall))
        for d in env.doors:
            if w.room not in d.rooms or d.segment is None:
                continue
            shared = float(LineString(d.segment).buffer(tol.on_wall).intersection(seg).length)
            if shared > tol.on_wall:
                fails.append(_fail("window_overlaps_door", f"window {w.id} overlaps door {d.id} "
                                   f"along {shared:.2f} m of wall", objects=[w.id, d.id], rooms=[w.room],
                                   measured=shared, tolerance=tol.on_wall))
    return fails, polys
