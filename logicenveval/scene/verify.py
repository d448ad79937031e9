"""Quick geometric self-check of constructed scenes, independent of the solver's encoding.

It re-measures the physics thresholds of DESIGN.md §7 on axis-aligned boxes (yaw is a multiple
of 90° in constructed scenes): used by the tests and by `benchmarks/layout.py` next to the
physics checker, so a solver bug shows up even if the two share a blind spot.
"""

from __future__ import annotations

import itertools
import math

from logicenveval.domain.catalog import Catalog
from logicenveval.domain.shapes import load_shapes
from logicenveval.model.envspec import EnvObject, EnvSpec

TOL = 0.01


def _box(o: EnvObject) -> tuple[float, float, float, float, float, float]:
    if o.position is None or o.size is None:
        raise ValueError(f"{o.id} has no geometry")
    odd = int(round(o.yaw / 90)) % 2 == 1
    ex, ez = (o.size[2], o.size[0]) if odd else (o.size[0], o.size[2])
    x, y, z = o.position
    return (x - ex / 2, y - o.size[1] / 2, z - ez / 2, x + ex / 2, y + o.size[1] / 2, z + ez / 2)


def _holders(oid: str, objs: dict[str, EnvObject]) -> set[str]:
    """The containers `oid` lies in, transitively through containers and supports (a fork in a
    drawer in a cabinet lies in the cabinet too), as the physics checker's `enclosing` reads them."""
    out: set[str] = set()
    seen: set[str] = set()
    todo = [oid]
    while todo:
        o = objs.get(todo.pop())
        if o is None or o.id in seen:
            continue
        seen.add(o.id)
        if o.container is not None:
            out.add(o.container)
            todo.append(o.container)
        if o.support not in (None, "floor", "wall", "ceiling"):
            todo.append(o.support)
    return out


def _room_rect(env: EnvSpec, rid: str) -> tuple[float, float, float, float]:
    poly = next(r.polygon for r in env.rooms if r.id == rid)
    if poly is None:
        raise ValueError(f"room {rid} has no polygon")
    xs, zs = [p[0] for p in poly], [p[1] for p in poly]
    return min(xs), min(zs), max(xs), max(zs)


def _gap(a: tuple[float, ...], b: tuple[float, ...]) -> float:
    gx = max(0.0, b[0] - a[3], a[0] - b[3])
    gz = max(0.0, b[2] - a[5], a[2] - b[5])
    return math.hypot(gx, gz)


def geometric_failures(env: EnvSpec, catalog: Catalog) -> list[str]:
    """Independent re-check of the physics thresholds (floor plan, entity, relation)."""
    bad: list[str] = []
    rects = {r.id: _room_rect(env, r.id) for r in env.rooms}
    for (ida, ra), (idb, rb) in itertools.combinations(rects.items(), 2):
        if min(ra[2], rb[2]) - max(ra[0], rb[0]) > TOL and min(ra[3], rb[3]) - max(ra[1], rb[1]) > TOL:
            bad.append(f"rooms {ida} {idb} overlap")

    def on_wall(seg: tuple[tuple[float, float], tuple[float, float]], r: tuple[float, float, float, float]) -> bool:
        (ax, az), (bx, bz) = seg
        if abs(az - bz) < 1e-6 and (abs(az - r[1]) < 1e-6 or abs(az - r[3]) < 1e-6):
            return r[0] - 1e-6 <= min(ax, bx) and max(ax, bx) <= r[2] + 1e-6
        if abs(ax - bx) < 1e-6 and (abs(ax - r[0]) < 1e-6 or abs(ax - r[2]) < 1e-6):
            return r[1] - 1e-6 <= min(az, bz) and max(az, bz) <= r[3] + 1e-6
        return False

    squares = []
    for d in env.doors:
        assert d.segment is not None
        for rid in d.rooms:
            if rid != "exterior" and not on_wall(d.segment, rects[rid]):
                bad.append(f"door {d.id} not on a wall of {rid}")
        (ax, az), (bx, bz) = d.segment
        w = math.dist(d.segment[0], d.segment[1])
        if abs(az - bz) < 1e-6:
            squares.append((min(ax, bx), az - w, max(ax, bx), az + w))
        else:
            squares.append((ax - w, min(az, bz), ax + w, max(az, bz)))
    for wdw in env.windows:
        assert wdw.segment is not None
        if not on_wall(wdw.segment, rects[wdw.room]) or wdw.sill <= 0 or wdw.sill + wdw.height > env.wall_height:
            bad.append(f"window {wdw.id} misplaced")
    objs = {o.id: o for o in env.objects}
    boxes = {o.id: _box(o) for o in env.objects}
    for o in env.objects:
        b = boxes[o.id]
        cat = catalog.categories[o.category]
        assert o.size is not None
        for k in range(3):
            if not cat.size_min[k] - 1e-6 <= o.size[k] <= cat.size_max[k] + 1e-6:
                bad.append(f"{o.id} size {o.size} outside catalog range")
        r = rects[o.room]
        if b[0] < r[0] - TOL or b[2] < r[1] - TOL or b[3] > r[2] + TOL or b[5] > r[3] + TOL:
            bad.append(f"{o.id} outside room {o.room}")
        if o.support == "floor" and abs(b[1]) > TOL:
            bad.append(f"{o.id} floats above the floor")
        if o.support == "wall":
            touches = min(abs(b[0] - r[0]), abs(b[2] - r[1]), abs(b[3] - r[2]), abs(b[5] - r[3])) <= TOL
            if not touches or b[1] <= 0:
                bad.append(f"{o.id} not mounted on a wall")
        if o.support == "ceiling" and abs(b[4] - env.wall_height) > TOL:
            bad.append(f"{o.id} does not touch the ceiling")
        if o.support not in (None, "floor", "wall", "ceiling"):
            s = boxes[o.support]
            cx, cz = (b[0] + b[3]) / 2, (b[2] + b[5]) / 2
            shape = load_shapes().of(objs[o.support].category)  # a seat holds things on its seat
            level = s[1] + (shape.surface()[0] if shape is not None else 1.0) * (s[4] - s[1])
            if abs(b[1] - level) > TOL or not (s[0] <= cx <= s[3] and s[2] <= cz <= s[5]):
                bad.append(f"{o.id} does not rest on {o.support}")
        if o.container is not None:
            c = boxes[o.container]
            if any(b[k] < c[k] - TOL for k in range(3)) or any(b[k] > c[k] + TOL for k in range(3, 6)):
                bad.append(f"{o.id} not inside {o.container}")
        if o.support != "wall" and b[1] < 2.0:
            for sq in squares:
                if min(b[3], sq[2]) - max(b[0], sq[0]) > TOL and min(b[5], sq[3]) - max(b[2], sq[1]) > TOL:
                    bad.append(f"{o.id} blocks a door")
    holders = {o.id: _holders(o.id, objs) for o in env.objects}
    for oa, oc in itertools.combinations(env.objects, 2):
        if oa.support == oc.id or oc.support == oa.id or oc.id in holders[oa.id] or oa.id in holders[oc.id]:
            continue
        ba, bc = boxes[oa.id], boxes[oc.id]
        if all(min(ba[k + 3], bc[k + 3]) - max(ba[k], bc[k]) > TOL for k in range(3)):
            bad.append(f"{oa.id} and {oc.id} interpenetrate")
    for rel in env.relations:
        ids = rel.args
        if rel.type == "near" and _gap(boxes[ids[0]], boxes[ids[1]]) > 1.0:
            bad.append(f"near{ids} fails")
        if rel.type == "far":
            p, q = objs[ids[0]].position, objs[ids[1]].position
            if p is None or q is None or math.hypot(p[0] - q[0], p[2] - q[2]) < 2.5:
                bad.append(f"far{ids} fails")
        if rel.type == "on" and objs[ids[0]].support != ids[1]:
            bad.append(f"on{ids} fails")
        if rel.type == "inside" and objs[ids[0]].container != ids[1]:
            bad.append(f"inside{ids} fails")
        if rel.type == "edge":
            eb, er = boxes[ids[0]], rects[objs[ids[0]].room]
            if min(abs(eb[0] - er[0]), abs(eb[2] - er[1]), abs(eb[3] - er[2]), abs(eb[5] - er[3])) > TOL:
                bad.append(f"edge{ids} fails")
    return bad
