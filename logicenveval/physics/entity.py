"""Entity dimension: geometry present, supported, not interpenetrating, inside its room, not
blocking doors, sized like its catalog category."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import Point, Polygon

from logicenveval.domain.catalog import Catalog
from logicenveval.domain.shapes import load_shapes, support_gap
from logicenveval.model.envspec import EnvSpec
from logicenveval.physics.floorplan import room_band
from logicenveval.physics.geometry import (
    Body,
    candidate_array,
    finite,
    mesh_path,
    penetration_depth,
    rect_pairs,
    separated,
)
from logicenveval.physics.report import PhysicsFailure, Tolerances


def _fail(code: str, message: str, objects: list[str], *, rooms: list[str] | None = None,
          measured: float | None = None, tolerance: float | None = None) -> PhysicsFailure:
    return PhysicsFailure(dimension="entity", code=code, objects=objects, rooms=rooms or [],
                          measured=measured, tolerance=tolerance, message=message)


def settles(gap: float, tol: Tolerances) -> bool:
    """A bottom `gap` m above a support (< 0: below it) rests on it: within `support_gap` of it,
    or a short drop above it that AI2-THOR's physics settles on load (`settle_drop`)."""
    return -tol.support_gap <= gap <= max(tol.settle_drop, tol.support_gap)


def rests_on(b: Body, s: Body, tol: Tolerances) -> tuple[bool, str, float]:
    """Whether `b` rests on `s` — its bottom at one of the heights where the shape of `s` holds
    objects (its top for a plain box; a seat, a shelf band: domain.shapes), or a settling drop
    above it, and its centre of mass over the footprint: (holds, reason code, measured)."""
    gap = support_gap(b.bottom, s.bottom, s.top, load_shapes().of(s.obj.category))
    if not settles(gap, tol):
        return False, "not_supported", gap
    outside = float(s.footprint.exterior.distance(Point(b.xz))) if not s.footprint.contains(Point(b.xz)) else 0.0
    if outside > 0:
        return False, "centre_off_support", outside
    return True, "", 0.0


def contained_excess(b: Body, c: Body) -> float:
    """How far (m) the corners of `b` stick out of the box of container `c` — through its top
    too unless the shape of `c` is open at the top (a bottle standing in a sink: domain.shapes)."""
    local = c.to_local(b.corners())
    excess = np.abs(local) - c.half
    shape = load_shapes().of(c.obj.category)
    if shape is not None and shape.open_top:
        excess[:, 1] = np.where(local[:, 1] > 0, 0.0, excess[:, 1])
    return float(np.max(excess, initial=0.0))


def wall_distance(b: Body, poly: Polygon) -> float:
    return float(poly.exterior.distance(b.back_face_segment().centroid))


def _mountable(b: Body, where: str, catalog: Catalog) -> list[PhysicsFailure]:
    """A wall or ceiling object is supported only where the catalog lets its category hang there
    (categories the catalog does not know are not judged, as for sizes)."""
    cat = catalog.get(b.obj.category)
    if cat is None or where in cat.placement:
        return []
    return [_fail("not_supported", f"{b.id} ({b.obj.category}) is mounted on the {where}, but the catalog "
                  f"places it {'/'.join(cat.placement)}", [b.id])]


def _support(b: Body, env: EnvSpec, bodies: dict[str, Body], polys: dict[str, Polygon],
             catalog: Catalog, tol: Tolerances) -> list[PhysicsFailure]:
    """Table 2 "supported by a surface (i.e., not floating)": on the floor, on a supporter's top
    with the centre of mass over it, inside a container, or hung on a wall/ceiling the catalog
    allows (docs/physics.md)."""
    o = b.obj
    out: list[PhysicsFailure] = []
    if o.container is not None:
        c = bodies.get(o.container)
        if c is not None:
            excess = contained_excess(b, c)
            if excess > tol.containment:
                out.append(_fail("not_contained", f"{o.id} sticks {excess:.3f} m out of its container "
                                 f"{o.container}", [o.id, o.container], measured=excess, tolerance=tol.containment))
    cat = catalog.get(o.category)
    if o.container is None and cat is not None and cat.placement == ["inside"]:
        # a part of a piece of furniture (AI2-THOR's Drawer): it lies in a container or nowhere
        out.append(_fail("not_supported", f"{o.id} ({o.category}) is not inside a container, but the "
                         "catalog places it only inside one (a part of its furniture)", [o.id]))
    sup = o.support
    if sup is None:
        if o.container is None:
            out.append(_fail("not_supported", f"{o.id} has neither support nor container", [o.id]))
    elif sup == "floor":
        if o.container is None and not settles(b.bottom, tol):
            out.append(_fail("not_supported", f"{o.id} bottom is at y={b.bottom:.3f} m, not on the floor",
                             [o.id], measured=b.bottom, tolerance=tol.support_gap))
    elif sup == "ceiling":
        out += _mountable(b, "ceiling", catalog)
        gap = env.wall_height - b.top
        if abs(gap) > tol.support_gap:
            out.append(_fail("not_supported", f"{o.id} top is {gap:.3f} m below the ceiling",
                             [o.id], measured=gap, tolerance=tol.support_gap))
    elif sup == "wall":
        out += _mountable(b, "wall", catalog)
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
                what = ("does not rest on a surface of" if code == "not_supported"
                        else "has its centre of mass beside the top of")
                out.append(_fail(code, f"{o.id} {what} {sup} ({measured:+.3f} m)", [o.id, sup],
                                 measured=measured, tolerance=tol.support_gap if code == "not_supported" else 0.0))
    return out


def enclosing(bodies: dict[str, Body] | list[Body]) -> dict[str, frozenset[str]]:
    """Object id -> the containers that enclose it: its own, and those of every object it rests
    on or lies in, transitively (a book on a shelf in a cabinet lies in the cabinet)."""
    objs = {b.id: b.obj for b in (bodies.values() if isinstance(bodies, dict) else bodies)}
    memo: dict[str, frozenset[str]] = {}

    def walk(oid: str, seen: frozenset[str]) -> frozenset[str]:
        if oid in memo:
            return memo[oid]
        o = objs.get(oid)
        if o is None or oid in seen:
            return frozenset()
        out: set[str] = set()
        seen = seen | {oid}
        if o.container is not None:
            out.add(o.container)
            out |= walk(o.container, seen)
        if o.support not in (None, "floor", "wall", "ceiling"):
            out |= walk(o.support, seen)
        memo[oid] = frozenset(out)
        return memo[oid]

    return {oid: walk(oid, frozenset()) for oid in objs}


def exempt(a: Body, b: Body, encl: dict[str, frozenset[str]]) -> bool:
    """A support pair may touch, and an object lies within the containers enclosing it; anything
    else — two objects in one container included — must not interpenetrate (Table 2)."""
    oa, ob = a.obj, b.obj
    return (oa.support == ob.id or ob.support == oa.id or ob.id in encl.get(oa.id, frozenset())
            or oa.id in encl.get(ob.id, frozenset()))


#: a candidate pair is examined while either object is named in fewer interpenetrations than
#: this: a pile of n objects in one place has n²/2 colliding pairs, and listing them all costs
#: quadratic time, memory and output, while a few suffice to fail each object. So every colliding
#: object is still named (at least min(its collisions, cap) times) and a report holds at most
#: cap x n interpenetrations (docs/physics.md).
MAX_COLLISIONS_PER_OBJECT = 8


def _collision(a: Body, b: Body, tol: Tolerances) -> PhysicsFailure | None:
    depth = penetration_depth(a, b)
    if depth <= tol.penetration:
        return None
    return _fail("interpenetration", f"{a.id} and {b.id} interpenetrate by {depth:.3f} m",
                 [a.id, b.id], measured=depth, tolerance=tol.penetration)


def collisions(bodies: list[Body], tol: Tolerances, *, broad_phase: bool = True) -> list[PhysicsFailure]:
    """Interpenetrations of non-exempt pairs, in pair order (i < j, EnvSpec order).

    With `broad_phase` (the default): sort-and-sweep candidates, a separating-axis prefilter for
    boxes, fcl on the rest, and at most `MAX_COLLISIONS_PER_OBJECT` failures naming one object
    (a pair is examined while either object is below the cap). Without: every pair through fcl,
    every collision reported — the old quadratic path, kept as the baseline of
    `benchmarks/physics_check.py`. Both give the same failures until an object reaches the cap.
    """
    encl = enclosing(bodies)
    if not broad_phase:
        found = (_collision(bodies[i], bodies[j], tol) for i in range(len(bodies))
                 for j in range(i + 1, len(bodies)) if not exempt(bodies[i], bodies[j], encl))
        return [f for f in found if f is not None]
    pairs = candidate_array(bodies)
    pairs = pairs[~separated(bodies, pairs)]
    count = np.zeros(len(bodies), dtype=np.int64)
    cap = MAX_COLLISIONS_PER_OBJECT
    out: list[PhysicsFailure] = []

    def examine(i: int, j: int) -> None:
        a, b = bodies[i], bodies[j]
        if exempt(a, b, encl):
            return
        f = _collision(a, b, tol)
        if f is None:
            return
        count[i] += 1
        count[j] += 1
        full = [x.id for x, n in ((a, count[i]), (b, count[j])) if n == cap]
        if full:
            f = f.model_copy(update={"message": f"{f.message} ({', '.join(full)} now named in {cap} "
                                                "interpenetrations: further pairs among such objects "
                                                "are not examined)"})
        out.append(f)

    if not len(pairs):
        return out
    starts = np.flatnonzero(np.r_[True, pairs[1:, 0] != pairs[:-1, 0]])
    for s, e in zip(starts, [*starts[1:], len(pairs)], strict=True):
        i = int(pairs[s, 0])
        js = pairs[s:e, 1]
        for pos, j in enumerate(js):
            if count[i] >= cap:  # i is full: only partners below the cap still need examining
                rest = js[pos:]
                for k in rest[count[rest] < cap]:
                    examine(i, int(k))
                break
            examine(i, int(j))
    return out


def swing_areas(env: EnvSpec) -> list[tuple[str, Polygon]]:
    """A door-width square on each side of every door (the area its leaf sweeps or a person needs);
    an open boundary between rooms (type `open`) has no leaf and is a whole wall wide: none."""
    out = []
    for d in env.doors:
        if d.type == "open" or d.segment is None or not finite(*d.segment[0], *d.segment[1]):
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
    if not bodies or not doors:
        return {}
    boxes = shapely.bounds(np.array([b.footprint for b in bodies], dtype=object)).tolist()
    pairs = rect_pairs([tuple(r) for r in boxes], [area.bounds for _, area in doors])
    out: dict[int, list[int]] = {}
    for i, d in pairs:
        out.setdefault(i, []).append(d)
    return out


def _inside_rooms(bodies: list[Body], grown: dict[str, Polygon]) -> list[bool]:
    """Whether each body's footprint lies in its room's grown outline (True where the room
    has none): one vectorised test for the whole environment."""
    at = [k for k, b in enumerate(bodies) if b.obj.room in grown]
    out = [True] * len(bodies)
    if at:
        rooms = np.array([grown[bodies[k].obj.room] for k in at], dtype=object)
        feet = np.array([bodies[k].footprint for k in at], dtype=object)
        for k, ok in zip(at, shapely.contains(rooms, feet).tolist(), strict=True):
            out[k] = ok
    return out


def _catalog_size(b: Body, catalog: Catalog, tol: Tolerances) -> list[PhysicsFailure]:
    cat = catalog.get(b.obj.category)
    if cat is None:
        return []
    size = (2.0 * b.half).tolist()  # plain floats: three numpy scalar comparisons cost more
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
    grown = {rid: room_band(env, rid, poly, tol.room_margin) for rid, poly in polys.items()}
    blocking = _door_candidates(list(bodies.values()), doors)
    inside = _inside_rooms(list(bodies.values()), grown)
    for k, b in enumerate(bodies.values()):
        fails += _catalog_size(b, catalog, tol)
        fails += _support(b, env, bodies, polys, catalog, tol)
        if b.top > env.wall_height + tol.support_gap:
            fails.append(_fail("above_ceiling", f"{b.id} top {b.top:.2f} m is above the wall height "
                               f"{env.wall_height} m", [b.id], measured=b.top, tolerance=env.wall_height))
        poly = polys.get(b.obj.room)
        if poly is not None and not inside[k]:
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


__all__ = ["check_entities", "collisions", "contained_excess", "enclosing", "exempt", "rests_on", "settles",
           "swing_areas",
           "wall_distance"]
