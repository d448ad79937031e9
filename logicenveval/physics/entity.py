"""Entity dimension: geometry present, supported, not interpenetrating, inside its room, not
blocking doors, sized like its catalog category."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from shapely.geometry import Point, Polygon

from logicenveval.domain.catalog import Catalog
from logicenveval.model.envspec import EnvSpec
from logicenveval.physics.geometry import (
    Body,
    candidate_pairs,
    finite,
    mesh_path,
    penetration_depth,
    rect_pairs,
)
from logicenveval.physics.report import PhysicsFailure, Tolerances


def _fail(code: str, message: str, objects: list[str], *, rooms: list[str] | None = None,
          measured: float | None = None, tolerance: float | None = None) -> PhysicsFailure:
    return PhysicsFailure(dimension="entity", code=code, objects=objects, rooms=rooms or [],
                          measured=measured, tolerance=tolerance, message=message)


def rests_on(b: Body, s: Body, tol: Tolerances) -> tuple[bool, str, float]:
    """Whether `b` rests on the top face of `s`: (holds, reason code, measured)."""
    gap = b.bottom - s.top
    if abs(gap) > tol.support_gap:
        return False, "not_supported", gap
    outside = float(s.footprint.exterior.distance(Point(b.xz))) if not s.footprint.contains(Point(b.xz)) else 0.0
    if outside > 0:
        return False, "unstable", outside
    return True, "", 0.0


def contained_excess(b: Body, c: Body) -> float:
    """How far (m) the corners of `b` stick out of the box of container `c`."""
    local = c.to_local(b.corners())
    return float(np.max(np.abs(local) - c.half, initial=0.0))


def wall_distance(b: Body, poly: Polygon) -> float:
    return float(poly.exterior.distance(b.back_face_segment().centroid))


def _support(b: Body, env: EnvSpec, bodies: dict[str, Body], polys: dict[str, Polygon],
             tol: Tolerances) -> list[PhysicsFailure]:
    o = b.obj
    out: list[PhysicsFailure] = []
    if o.container is not None:
        c = bodies.get(o.container)
        if c is not None:
            excess = contained_excess(b, c)
            if excess > tol.containment:
                out.append(_fail("not_contained", f"{o.id} sticks {excess:.3f} m out of its container "
                                 f"{o.container}", [o.id, o.container], measured=excess, tolerance=tol.containment))
    sup = o.support
    if sup is None:
        if o.container is None:
            out.append(_fail("not_supported", f"{o.id} has neither support nor container", [o.id]))
    elif sup == "floor":
        if o.container is None and abs(b.bottom) > tol.support_gap:
            out.append(_fail("not_supported", f"{o.id} bottom is at y={b.bottom:.3f} m, not on the floor",
                             [o.id], measured=b.bottom, tolerance=tol.support_gap))
    elif sup == "ceiling":
        gap = env.wall_height - b.top
        if abs(gap) > tol.support_gap:
            out.append(_fail("not_supported", f"{o.id} top is {gap:.3f} m below the ceiling",
                             [o.id], measured=gap, tolerance=tol.support_gap))
    elif sup == "wall":
        poly = polys.get(o.room)
        if poly is not None:
            dist = wall_distance(b, poly)
            if dist > tol.wall_gap:
                out.append(_fail("not_on_wall", f"{o.id} back face is {dist:.3f} m from the walls of "
                                 f"{o.room}", [o.id], rooms=[o.room], measured=dist, tolerance=tol.wall_gap))
        if b.bottom <= tol.support_gap:
            out.append(_fail("not_supported", f"wall-mounted {o.id} reaches the floor (bottom "
                             f"{b.bottom:.3f} m)", [o.id], measured=b.bottom, tolerance=tol.support_gap))
    else:
        s = bodies.get(sup)
        if s is not None:
            ok, code, measured = rests_on(b, s, tol)
            if not ok:
                what = ("does not rest on the top of" if code == "not_supported"
                        else "has its centre of mass outside the top of")
                out.append(_fail(code, f"{o.id} {what} {sup} ({measured:+.3f} m)", [o.id, sup],
                                 measured=measured, tolerance=tol.support_gap if code == "not_supported" else 0.0))
    return out


def exempt(a: Body, b: Body) -> bool:
    """Support, containment and same-container pairs may touch or overlap."""
    oa, ob = a.obj, b.obj
    return (oa.support == ob.id or ob.support == oa.id or oa.container == ob.id
            or ob.container == oa.id or (oa.container is not None and oa.container == ob.container))


def collisions(bodies: list[Body], tol: Tolerances, *, broad_phase: bool = True) -> list[PhysicsFailure]:
    if broad_phase:
        pairs = candidate_pairs(bodies)
    else:
        pairs = [(i, j) for i in range(len(bodies)) for j in range(i + 1, len(bodies))]
    out = []
    for i, j in pairs:
        a, b = bodies[i], bodies[j]
        if exempt(a, b):
            continue
        depth = penetration_depth(a, b)
        if depth > tol.penetration:
            out.append(_fail("interpenetration", f"{a.id} and {b.id} interpenetrate by {depth:.3f} m",
                             [a.id, b.id], measured=depth, tolerance=tol.penetration))
    return out


def swing_areas(env: EnvSpec) -> list[tuple[str, Polygon]]:
    """A door-width square on each side of every door (the area its leaf sweeps or a person needs)."""
    out = []
    for d in env.doors:
        if d.segment is None or not finite(*d.segment[0], *d.segment[1]):
            continue
        p, q = np.asarray(d.segment[0], float), np.asarray(d.segment[1], float)
        width = float(np.linalg.norm(q - p))
        if width <= 0:
            continue
        n = np.array([-(q - p)[1], (q - p)[0]])  # normal whose length is the door width
        out.append((d.id, Polygon([tuple(p - n), tuple(q - n), tuple(q + n), tuple(p + n)])))
    return out


def _door_candidates(bodies: list[Body], doors: list[tuple[str, Polygon]]) -> dict[int, list[int]]:
    """Body index -> the doors (in order) whose swing square's bounds meet its footprint's: the
    broad phase of the door test (a body far from every door costs no polygon intersection)."""
    pairs = rect_pairs([b.footprint.bounds for b in bodies], [area.bounds for _, area in doors])
    out: dict[int, list[int]] = {}
    for i, d in pairs:
        out.setdefault(i, []).append(d)
    return out


def _catalog_size(b: Body, catalog: Catalog, tol: Tolerances) -> list[PhysicsFailure]:
    cat = catalog.get(b.obj.category)
    if cat is None:
        return []
    size = 2.0 * b.half
    for axis, (v, lo, hi) in enumerate(zip(size, cat.size_min, cat.size_max, strict=True)):
        lo_t, hi_t = lo * (1 - tol.size_ratio), hi * (1 + tol.size_ratio)
        if not lo_t <= v <= hi_t:
            return [_fail("size_out_of_range", f"{b.id} ({b.obj.category}) size along {'xyz'[axis]} is "
                          f"{v:.3f} m, catalog range is [{lo}, {hi}] m ±{tol.size_ratio:.0%}",
                          [b.id], measured=float(v), tolerance=hi_t if v > hi_t else lo_t)]
    return []


def check_entities(env: EnvSpec, bodies: dict[str, Body], polys: dict[str, Polygon],
                   catalog: Catalog, tol: Tolerances, *, broad_phase: bool = True,
                   mesh_dir: Path | None = None) -> list[PhysicsFailure]:
    fails: list[PhysicsFailure] = []
    for o in env.objects:
        path = mesh_path(o, mesh_dir)
        if path is not None and not path.is_file():
            fails.append(_fail("mesh_not_found", f"{o.id} mesh file {path} does not exist; checked as a box",
                               [o.id]))
        if o.position is None or o.size is None:
            fails.append(_fail("missing_geometry", f"{o.id} has no position or size", [o.id]))
        elif not finite(*o.position, *o.size, o.yaw):
            fails.append(_fail("missing_geometry", f"{o.id} has a non-finite position, size or yaw", [o.id]))
        elif min(o.size) <= 0:
            fails.append(_fail("invalid_size", f"{o.id} size {o.size} has a non-positive extent", [o.id],
                               measured=float(min(o.size)), tolerance=0.0))
    doors = swing_areas(env)
    grown = {rid: poly.buffer(tol.room_margin) for rid, poly in polys.items()}
    blocking = _door_candidates(list(bodies.values()), doors)
    for k, b in enumerate(bodies.values()):
        fails += _catalog_size(b, catalog, tol)
        fails += _support(b, env, bodies, polys, tol)
        if b.top > env.wall_height + tol.support_gap:
            fails.append(_fail("above_ceiling", f"{b.id} top {b.top:.2f} m is above the wall height "
                               f"{env.wall_height} m", [b.id], measured=b.top, tolerance=env.wall_height))
        poly = polys.get(b.obj.room)
        if poly is not None and not grown[b.obj.room].contains(b.footprint):
            out = max(float(poly.distance(Point(c))) for c in b.footprint.exterior.coords)
            fails.append(_fail("outside_room", f"{b.id} footprint leaves room {b.obj.room} by {out:.3f} m",
                               [b.id], rooms=[b.obj.room], measured=out, tolerance=tol.room_margin))
        if b.obj.support == "floor" and b.obj.container is None:
            for door_id, area in (doors[d] for d in blocking.get(k, ())):
                inter = float(area.intersection(b.footprint).area)
                if inter > tol.room_overlap_area:
                    fails.append(_fail("blocks_door", f"{b.id} stands in the swing area of door {door_id} "
                                       f"({inter:.3f} m²)", [b.id, door_id], measured=inter,
                                       tolerance=tol.room_overlap_area))
    fails += collisions(list(bodies.values()), tol, broad_phase=broad_phase)
    return fails


__all__ = ["check_entities", "collisions", "contained_excess", "rests_on", "swing_areas",
           "wall_distance"]
