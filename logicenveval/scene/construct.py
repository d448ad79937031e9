"""Scene construction: requests → floor plan → sizes → per-room layout with relaxation → EnvSpec."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from logicenveval.domain.catalog import Catalog, Category
from logicenveval.domain.shapes import load_shapes
from logicenveval.envfiles import env_from_dict
from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import Agent, EnvObject, EnvSpec, Relation
from logicenveval.scene.compat import check_relations
from logicenveval.scene.floorplan import GAP, FloorPlan, plan_floor
from logicenveval.scene.geometry import Rect, edges, subtract
from logicenveval.scene.layout import (
    DEFAULT_SOLVER,
    FLOOR_RELATIONS,
    WALKWAY,
    Box,
    FloorRel,
    Opening,
    Solver,
    WallBox,
    backend,
    cells,
    rect_cells,
)
from logicenveval.scene.objects import resolve_category
from logicenveval.scene.relax import Dropped
from logicenveval.scene.spec import (
    DoorRequest,
    ObjectRequest,
    RelationRequest,
    RelaxationEntry,
    RoomRequest,
    SceneResult,
    SceneSpec,
    WindowRequest,
)

WINDOW_CLEARANCE = 0.3  # metres in front of a window kept free of objects taller than its sill
CONTAINER_MARGIN = 0.01  # wall thickness of containers, metres


@dataclass
class _Pose:
    position: tuple[float, float, float]
    yaw: float
    size: tuple[float, float, float]

    @property
    def extents(self) -> tuple[float, float]:
        """Footprint extents along world x, z."""
        odd = int(round(self.yaw / 90)) % 2 == 1
        return (self.size[2], self.size[0]) if odd else (self.size[0], self.size[2])

    @property
    def top(self) -> float:
        return self.position[1] + self.size[1] / 2

    @property
    def footprint(self) -> Rect:
        ex, ez = self.extents
        return Rect(self.position[0] - ex / 2, self.position[2] - ez / 2, self.position[0] + ex / 2,
                    self.position[2] + ez / 2)


def _r(v: float) -> float:
    return round(v, 4)


def _snap_size(v: float, lo: float, hi: float, grid: float) -> float:
    for c in (round(v / grid), math.floor(v / grid), math.ceil(v / grid)):
        if lo - 1e-9 <= c * grid <= hi + 1e-9 and c > 0:
            return _r(c * grid)
    return _r(v)


class _Builder:
    def __init__(self, spec: SceneSpec, catalog: Catalog, rng: np.random.Generator, solver: Solver) -> None:
        self.spec = spec
        self.solver = backend(solver)
        self.catalog = catalog
        self.rng = rng
        self.g = spec.grid
        self.warnings: list[str] = []
        self.log: list[RelaxationEntry] = []
        self.objects: dict[str, ObjectRequest] = {}
        self.cats: dict[str, Category] = {}
        self.hard: set[str] = set()
        self.sizes: dict[str, tuple[float, float, float]] = {}
        self.poses: dict[str, _Pose] = {}
        self.relations: list[RelationRequest] = []
        self.dropped_rel: set[int] = set()

    # --- input checks -------------------------------------------------------------------------
    def validate(self) -> None:
        rooms = {r.id for r in self.spec.rooms}
        for i, o in enumerate(self.spec.objects):
            if o.id in self.objects:
                raise EnvSpecError(f"object id {o.id!r} repeated", field=f"objects[{i}].id", hint="make ids unique")
            if o.room not in rooms:
                raise EnvSpecError(f"room {o.room!r} is not a requested room", field=f"objects[{i}].room",
                                   hint=f"use one of {sorted(rooms)}")
            name, warn = resolve_category(o.category, self.catalog)
            if warn:
                self.warnings.append(f"{o.id}: {warn}")
            if name != o.category:
                o = o.model_copy(update={"category": name})
            self.objects[o.id] = o
            self.cats[o.id] = self.catalog.categories[name]
        for i, o in enumerate(self.spec.objects):
            ref = o.parent
            if ref is not None and ref not in self.objects:
                raise EnvSpecError(f"{o.id} is placed on/inside unknown object {ref!r}",
                                   field=f"objects[{i}].placement", hint="name an object of the scene")
            if ref is not None and self.objects[ref].room != o.room:
                raise EnvSpecError(f"{o.id} is in room {o.room} but its support/container {ref} is in "
                                   f"{self.objects[ref].room}", field=f"objects[{i}].room",
                                   hint="put both in the same room")
        for o in self.objects.values():  # a support or container of a task object must exist too
            if o.is_task:
                cur: str | None = o.id
                while cur is not None:
                    self.hard.add(cur)
                    ob = self.objects[cur]
                    nxt = ob.parent
                    cur = nxt if nxt not in self.hard else None
        for p in check_relations(list(self.objects.values()), [], self.catalog):
            self._bad_placement(p.objects, p.reason)
        kept = []
        for inc in check_relations(list(self.objects.values()), self.spec.relations, self.catalog):
            for r in inc.relations:
                if isinstance(r, RelationRequest) and id(r) not in self.dropped_rel:
                    self.dropped_rel.add(id(r))
                    self._log_rel(self._room_of(r), r, inc.reason)
        for r in self.spec.relations:
            if id(r) not in self.dropped_rel:
                kept.append(r)
        self.relations = []
        for r in kept:
            rooms_of = {self.objects[a].room for a in r.args if a in self.objects}
            if len(rooms_of) > 1:
                self.dropped_rel.add(id(r))
                self._log_rel(self._room_of(r), r, f"its objects are in different rooms {sorted(rooms_of)}")
            else:
                self.relations.append(r)

    def _bad_placement(self, ids: Sequence[str], reason: str) -> None:
        if not ids or ids[0] not in self.objects:
            return  # already dropped with its support
        o = self.objects[ids[0]]
        if o.id in self.hard:
            raise EnvSpecError(reason, field=f"objects.{o.id}.placement",
                               hint="change the placement to a surface/container that fits, or 'floor'")
        self._drop_object(o.id, reason)

    def _drop_object(self, oid: str, reason: str) -> None:
        if oid not in self.objects:
            return
        o = self.objects.pop(oid)
        self.log.append(RelaxationEntry(room=o.room, kind="object", item=oid, task=False, reason=reason))
        for child in [c for c in self.objects.values() if c.support == oid or c.container == oid]:
            self._drop_object(child.id, f"its support/container {oid} was dropped")

    def _room_of(self, r: RelationRequest) -> str:
        for a in r.args:
            if a in self.objects:
                return self.objects[a].room
        return self.spec.rooms[0].id

    def _rel_task(self, r: RelationRequest) -> bool:
        if r.task is not None:
            return r.task
        return all(a in self.objects and self.objects[a].is_task for a in r.args)

    def _log_rel(self, room: str, r: RelationRequest, reason: str) -> None:
        self.log.append(RelaxationEntry(room=room, kind="relation", item=r.text(), task=self._rel_task(r),
                                        reason=reason))

    # --- sizes --------------------------------------------------------------------------------
    def size_all(self) -> None:
        def depth(oid: str) -> int:
            o = self.objects[oid]
            ref = o.parent
            return 0 if ref is None else 1 + depth(ref)

        for oid in sorted(self.objects, key=depth):
            self.sizes[oid] = self._size(self.objects[oid])
        for pid in list(self.sizes):
            for mode in ("on", "inside"):
                self._share(pid, mode)

    def _share(self, pid: str, mode: str) -> None:
        """Things put together on (or in) one holder drawn so that they can share it: each size
        is drawn alone, up to the holder's top, so two told items on a stool ("a cardboard box
        disposed on a stool, a jacket draped over said stool") may each fill it. Only when the
        drawn footprints exceed the holder's top in cells (no packing can hold them) are the
        items without things of their own drawn at their smallest footprint; a layout that fits
        is left as it is (no draw of the generator changes)."""
        kids = [o.id for o in self.objects.values() if (o.support == pid if mode == "on" else o.container == pid)]
        if len(kids) < 2:
            return
        ps = self.sizes[pid]
        m = CONTAINER_MARGIN if mode == "inside" else 0.0
        shape = load_shapes().of(self.objects[pid].category) if mode == "on" else None
        back = shape.surface()[1] if shape is not None else 0.0
        frame = math.floor((ps[0] - 2 * m) / self.g + 1e-6) * math.floor((ps[2] * (1 - back) - 2 * m) / self.g + 1e-6)
        if sum(cells(self.sizes[k][0], self.g) * cells(self.sizes[k][2], self.g) for k in kids) <= frame:
            return
        held = {o.support for o in self.objects.values()} | {o.container for o in self.objects.values()}
        for k in kids:
            if k in held:
                continue  # a holder of its own keeps the room its things need
            cat, (x, y, z) = self.cats[k], self.sizes[k]
            self.sizes[k] = (_snap_size(cat.size_min[0], cat.size_min[0], x, self.g), y,
                             _snap_size(cat.size_min[2], cat.size_min[2], z, self.g))

    def _size(self, o: ObjectRequest) -> tuple[float, float, float]:
        cat = self.cats[o.id]
        lo, hi = list(cat.size_min), list(cat.size_max)
        kids = [c for c in self.objects.values() if c.support == o.id or c.container == o.id]
        back = self._seat_back(o.id)
        for c in kids:  # leave room for the smallest version of each child
            cmin = self.cats[c.id].size_min
            need = max(cmin[0], cmin[2]) + 2 * CONTAINER_MARGIN + self.g
            for ax in (0, 2):  # things on a seat use its depth in front of the back strip
                lo[ax] = min(hi[ax], max(lo[ax], need / (1 - back) if ax == 2 and c.support == o.id else need))
            if c.container == o.id:
                lo[1] = min(hi[1], max(lo[1], cmin[1] + 2 * CONTAINER_MARGIN))
        if o.size is not None:
            raw = list(o.size)
        else:
            raw = [float(self.rng.uniform(a, b)) for a, b in zip(lo, hi, strict=True)]
        ref = o.parent
        if ref is not None:
            ps = self.sizes[ref]
            m = 2 * CONTAINER_MARGIN if o.container else 0.0
            seat = 0.0 if o.container else self._seat_back(ref)
            cap = [ps[0] - m - self.g, ps[1] - m, ps[2] * (1 - seat) - m - self.g]
            for ax in (0, 2):
                raw[ax] = max(cat.size_min[ax], min(raw[ax], min(cap[0], cap[2])))
            if o.container:
                raw[1] = max(cat.size_min[1], min(raw[1], cap[1]))
        out = [_snap_size(v, cat.size_min[k], cat.size_max[k], self.g) for k, v in enumerate(raw)]
        return (out[0], out[1], out[2])

    def _seat_back(self, oid: str) -> float:
        """The depth fraction of the back strip of a seat things are put on (0: all its top)."""
        shape = load_shapes().of(self.objects[oid].category) if oid in self.objects else None
        return shape.surface()[1] if shape is not None else 0.0

    # --- layout -------------------------------------------------------------------------------
    def _seed(self) -> int:
        return int(self.rng.integers(0, 2**31 - 1))

    def _box(self, oid: str) -> Box:
        """The layout box of a sized object: its footprint in cells; task objects (and their supports) hard."""
        size = self.sizes[oid]
        return Box(oid, size, (cells(size[0], self.g), cells(size[2], self.g)), oid in self.hard)

    def _take(self, room: str, dropped: list[Dropped], rels: Mapping[str, RelationRequest]) -> None:
        for d in dropped:
            t = d.tracked
            if t.kind == "object":
                self._drop_object(t.item, d.reason)
            elif t.item in rels:
                r = rels[t.item]
                if id(r) not in self.dropped_rel:
                    self.dropped_rel.add(id(r))
                    self._log_rel(room, r, d.reason)

    def layout_room(self, rq: RoomRequest, plan: FloorPlan) -> FloorPlan:
        """Lay out one room; its own doors and windows are placed by the floor solve (paper §3.3:
        their positions are variables of the CSP). Returns the plan with them on their walls."""
        rect = plan.rects[rq.id]
        origin = (rect.x0, rect.z0)
        g = self.g
        frame = (int(round(rect.w / g)), int(round(rect.d / g)))
        here = [o for o in self.objects.values() if o.room == rq.id]
        floor = [o for o in here if o.support == "floor"]
        boxes = [self._box(o.id) for o in floor]
        obstacles = [rect_cells(sq, origin, g) for sq in self._door_squares(rq.id, plan, rect)]
        tall = []
        for w in plan.windows:
            if w.room == rq.id and w.segment is not None:
                tall.append((rect_cells(self._strip(w.segment, rect, WINDOW_CLEARANCE), origin, g), w.sill))
        openings = self._openings(rq.id, plan, rect)
        root = {o.id: self._root(o.id) for o in here}
        rels, by_text = self._floor_rels(here, root)
        placed, dropped = self.solver.pack(frame, boxes, seed=self._seed(), timeout_s=self.spec.room_timeout_s,
                                           obstacles=obstacles, tall=tall, walkway=cells(WALKWAY, g), rels=rels,
                                           grid=g, openings=openings)
        if not placed and (boxes or openings):
            raise EnvSpecError(f"room {rq.id}: the task objects do not fit its floor together with the doors, "
                               "windows and walkways", field=f"rooms.{rq.id}",
                               hint="request a larger room area or fewer/smaller task objects")
        plan = plan.placed({op.id: origin[0] + placed[op.id].x0 if op.side in "sn" else origin[1] + placed[op.id].z0
                            for op in openings})
        squares = self._door_squares(rq.id, plan, rect)
        self._take(rq.id, dropped, by_text)
        for b in boxes:
            if b.id in placed:
                p = placed[b.id]
                odd = p.o % 2 == 1
                ex, ez = (b.size[2], b.size[0]) if odd else (b.size[0], b.size[2])
                self.poses[b.id] = _Pose((_r(origin[0] + p.x0 + ex / 2), _r(b.size[1] / 2),
                                          _r(origin[1] + p.z0 + ez / 2)), 90.0 * p.o, b.size)
        self._stack_all([b.id for b in boxes if b.id in self.poses])
        self._walls(rq.id, plan, rect, squares)
        self._stack_all([o.id for o in here if o.support == "wall" and o.id in self.poses])
        self._ceiling(rq.id, rect, squares)
        lost = [o.id for o in here if o.id in self.objects and o.id not in self.poses]
        for oid in lost:  # children of objects placed in no stage (e.g. on a ceiling object)
            if oid in self.hard:
                raise EnvSpecError(f"{oid} has no support the solver can place", field=f"objects.{oid}.placement",
                                   hint="place it on the floor, a wall, or a floor/wall object")
            self._drop_object(oid, "its support could not be placed")
        return plan

    def free_floor(self, room: str, rect: Rect) -> float:
        """Floor area (m²) the room's floor objects leave free: how tight its floor solve is."""
        return rect.area - sum(self.sizes[o.id][0] * self.sizes[o.id][2] for o in self.objects.values()
                               if o.room == room and o.support == "floor")

    def _openings(self, room: str, plan: FloorPlan, rect: Rect) -> list[Opening]:
        """The doors and windows this room's floor solve places: their slot's stretch in this room's
        cells, minus what openings already on that wall line take (with the gap)."""
        g = self.g
        out = []
        placed = [(d.segment, d.id) for d in plan.doors if d.segment is not None]
        placed += [(w.segment, w.id) for w in plan.windows if w.segment is not None]
        for oid, slot in plan.slots.items():
            if slot.owner != room or any(i == oid for _, i in placed):
                continue
            e = slot.edge
            origin = rect.x0 if e.axis == "x" else rect.z0
            k_along, k_across = (0, 1) if e.axis == "x" else (1, 0)
            taken = [(min(a[k_along], b[k_along]) - GAP, max(a[k_along], b[k_along]) + GAP)
                     for (a, b), _ in placed if abs(a[k_across] - e.at) < 1e-6 and abs(b[k_across] - e.at) < 1e-6]
            width = cells(slot.width, g)
            starts = []
            for lo, hi in subtract(slot.lo, slot.hi, taken):
                first = cells(lo - origin, g)
                last = int(math.floor((hi - origin - slot.width) / g + 1e-6))
                if first <= last:
                    starts.append((first, last))
            window = next((w for w in plan.windows if w.id == oid), None)
            out.append(Opening(oid, e.side, tuple(starts), width,  # type: ignore[arg-type]
                               cells(WINDOW_CLEARANCE, g) if window else width,
                               sill=window.sill if window else None))
        return out

    def _ceiling(self, room: str, rect: Rect, squares: list[Rect]) -> None:
        """Ceiling objects touch the ceiling, clear of everything that reaches their height."""
        objs = [o for o in self.objects.values() if o.room == room and o.support == "ceiling"]
        if not objs:
            return
        g, h = self.g, self.spec.wall_height
        origin = (rect.x0, rect.z0)
        tall = [(rect_cells(p.footprint, origin, g), h - p.top - 0.01) for oid, p in self.poses.items()
                if self.objects[oid].room == room]
        tall += [(rect_cells(sq, origin, g), -1.0) for sq in squares]
        boxes = [self._box(o.id) for o in objs]
        frame = (int(round(rect.w / g)), int(round(rect.d / g)))
        placed, dropped = self.solver.pack(frame, boxes, seed=self._seed(), timeout_s=self.spec.room_timeout_s, tall=tall,
                               grid=g)
        if not placed:
            raise EnvSpecError(f"room {room}: the ceiling task objects do not fit", field=f"rooms.{room}",
                               hint="request a larger room or fewer ceiling objects")
        self._take(room, dropped, {})
        for b in boxes:
            if b.id in placed:
                p = placed[b.id]
                ex, ez = (b.size[2], b.size[0]) if p.o % 2 else (b.size[0], b.size[2])
                self.poses[b.id] = _Pose((_r(origin[0] + p.x0 + ex / 2), _r(h - b.size[1] / 2),
                                          _r(origin[1] + p.z0 + ez / 2)), 90.0 * p.o, b.size)

    def _stack_all(self, queue: list[str]) -> None:
        while queue:
            pid = queue.pop(0)
            queue += self._stack(pid)

    def _root(self, oid: str) -> str:
        o = self.objects[oid]
        ref = o.parent
        return oid if ref is None else self._root(ref)

    def _floor_rels(self, here: list[ObjectRequest], root: Mapping[str, str]
                    ) -> tuple[list[FloorRel], dict[str, RelationRequest]]:
        """Floor encodings of this room's relations; relations that hold by placement are kept
        as they are, and the rest (which no encoding guarantees) are dropped with a reason."""
        ids = {o.id for o in here}
        out: list[FloorRel] = []
        by_text: dict[str, RelationRequest] = {}
        for r in self.relations:
            if id(r) in self.dropped_rel or not all(a in ids for a in r.args):
                continue
            reason = self._structural(r)
            if reason == "":
                continue
            roots = tuple(root[a] for a in r.args)
            on_floor = all(self.objects[x].support == "floor" for x in roots)
            direct = roots == tuple(r.args)
            if reason is None and r.type in FLOOR_RELATIONS and on_floor and \
                    (direct or (r.type in ("near", "far") and len(set(roots)) == 2)):
                slack = tuple(0.0 if a == x else max(self.sizes[x][0], self.sizes[x][2])
                              for a, x in zip(r.args, roots, strict=True))
                out.append(FloorRel(r, self._rel_task(r), roots, slack))
                by_text[r.text()] = r
                continue
            self.dropped_rel.add(id(r))
            self._log_rel(self.objects[r.args[0]].room, r,
                          reason or "the layout solver has no encoding for it with these placements")
        return out, by_text

    def _structural(self, r: RelationRequest) -> str | None:
        """'' when `r` holds by placement, a reason when it contradicts it, None otherwise."""
        a = self.objects[r.args[0]]
        if r.type == "on":
            return "" if a.support == r.args[1] else f"{a.id} is placed {a.placement}"
        if r.type == "inside":
            return "" if a.container == r.args[1] else f"{a.id} is placed {a.placement}"
        if r.type == "wall_mounted":
            return "" if a.support == "wall" else f"{a.id} is placed {a.placement}"
        if r.type == "above":
            cur: str | None = a.id
            while cur is not None and cur in self.objects:
                ob = self.objects[cur]
                cur = ob.support if ob.support not in ("floor", "wall", "ceiling", None) else None
                if cur == r.args[1]:
                    return ""
            return "above is only realised by stacking one object on the other"
        return None

    def _door_squares(self, room: str, plan: FloorPlan, rect: Rect) -> list[Rect]:
        out = []
        for d in plan.doors:
            if room in d.rooms and d.segment is not None:
                width = math.dist(d.segment[0], d.segment[1])
                out.append(self._strip(d.segment, rect, width))
        return out

    @staticmethod
    def _strip(seg: tuple[tuple[float, float], tuple[float, float]], rect: Rect, depth: float) -> Rect:
        (ax, az), (bx, bz) = seg
        if abs(az - bz) < 1e-9:  # along x
            lo, hi = min(ax, bx), max(ax, bx)
            return Rect(lo, az, hi, az + depth) if abs(az - rect.z0) < 1e-6 else Rect(lo, az - depth, hi, az)
        lo, hi = min(az, bz), max(az, bz)
        return Rect(ax, lo, ax + depth, hi) if abs(ax - rect.x0) < 1e-6 else Rect(ax - depth, lo, ax, hi)

    def _stack(self, pid: str) -> list[str]:
        """Lay out the objects on and inside `pid` in its own frame; returns the ids placed."""
        parent = self.poses[pid]
        placed_ids: list[str] = []
        for mode in ("on", "inside"):
            kids = [o for o in self.objects.values()
                    if (o.support == pid if mode == "on" else o.container == pid)]
            if not kids:
                continue
            m = CONTAINER_MARGIN if mode == "inside" else 0.0
            # on a seat (a sofa, an armchair, a bed): on its seat in front of its back strip, at
            # the height where things rest on it in AI2-THOR's scenes (domain.shapes)
            shape = load_shapes().of(self.objects[pid].category) if mode == "on" else None
            level, back = shape.surface() if shape is not None else (1.0, 0.0)
            fw, fd = parent.size[0] - 2 * m, parent.size[2] * (1 - back) - 2 * m
            frame = (int(math.floor(fw / self.g + 1e-6)), int(math.floor(fd / self.g + 1e-6)))
            boxes = [self._box(o.id) for o in kids]
            placed, dropped = self.solver.pack(frame, boxes, seed=self._seed(), timeout_s=self.spec.room_timeout_s,
                                   grid=self.g)
            if not placed:
                raise EnvSpecError(f"the objects {[b.id for b in boxes]} do not fit {mode} {pid}",
                                   field=f"objects.{boxes[0].id}.placement",
                                   hint="place fewer or smaller objects there, or use a larger support")
            self._take(self.objects[pid].room, dropped, {})
            yaw = math.radians(parent.yaw)
            for b in boxes:
                if b.id not in placed:
                    continue
                p = placed[b.id]
                ex, ez = (b.size[2], b.size[0]) if p.o % 2 else (b.size[0], b.size[2])
                lx = p.x0 + ex / 2 - fw / 2
                lz = p.z0 + ez / 2 - fd / 2 + parent.size[2] * back / 2
                wx = lx * math.cos(yaw) + lz * math.sin(yaw)
                wz = -lx * math.sin(yaw) + lz * math.cos(yaw)
                bottom = parent.position[1] - parent.size[1] / 2
                base = bottom + level * parent.size[1] if mode == "on" else bottom + m
                self.poses[b.id] = _Pose((_r(parent.position[0] + wx), _r(base + b.size[1] / 2),
                                          _r(parent.position[2] + wz)), (parent.yaw + 90.0 * p.o) % 360, b.size)
                placed_ids.append(b.id)
        return placed_ids

    def _walls(self, room: str, plan: FloorPlan, rect: Rect, squares: list[Rect]) -> None:
        g, h = self.g, self.spec.wall_height
        objs = [o for o in self.objects.values() if o.room == room and o.support == "wall"]
        if not objs:
            return
        depth = max(self.sizes[o.id][2] for o in objs) + 0.02
        order = ["s", "e", "n", "w"]
        es = edges(rect)
        walls: list[tuple[int, list[tuple[int, int, float, float]]]] = []
        stacks: dict[str, tuple[Rect, float]] = {}
        for oid, pose in self.poses.items():
            if self.objects[oid].room == room and self.objects[oid].support != "wall":
                r0 = self._root(oid)
                fp, top = stacks.get(r0, (self.poses[r0].footprint, 0.0))
                stacks[r0] = (fp, max(top, pose.top))
        solids = [*stacks.values(), *((sq, h) for sq in squares)]
        for side in order:
            e = es[side]
            length = int(math.floor((e.hi - e.lo) / g + 1e-6))
            corner = cells(depth, g)  # keep out of the perpendicular walls' objects
            blocked: list[tuple[int, int, float, float]] = [(-1, corner, 0.0, h), (length - corner, length + 1, 0.0, h)]
            spans = [(d.segment, 0.0, h) for d in plan.doors if d.segment is not None]
            spans += [(w.segment, w.sill - 0.05, w.sill + w.height + 0.05) for w in plan.windows
                      if w.segment is not None]
            for (pa, pb), bot, top in spans:
                k_along, k_across = (0, 1) if e.axis == "x" else (1, 0)
                if abs(pa[k_across] - e.at) < 1e-6 and abs(pb[k_across] - e.at) < 1e-6:
                    lo = min(pa[k_along], pb[k_along]) - e.lo - 0.05
                    hi = max(pa[k_along], pb[k_along]) - e.lo + 0.05
                    blocked.append((int(math.floor(lo / g)), cells(hi, g), bot, top))
            for fp, top in solids:
                near = (fp.z0 - e.at < depth if e.inward > 0 else e.at - fp.z1 < depth) if e.axis == "x" else \
                       (fp.x0 - e.at < depth if e.inward > 0 else e.at - fp.x1 < depth)
                if near:
                    lo, hi = (fp.x0, fp.x1) if e.axis == "x" else (fp.z0, fp.z1)
                    blocked.append((int(math.floor((lo - e.lo) / g)) - 1, cells(hi - e.lo, g) + 1, 0.0, top + 0.01))
            walls.append((length, blocked))
        boxes = []
        for o in objs:
            sx, sy, _ = self.sizes[o.id]
            bottom = min(max(1.5 - sy / 2, 0.3), h - 0.1 - sy)
            boxes.append(WallBox(o.id, cells(sx, g), _r(max(bottom, 0.05)), sy, o.id in self.hard))
        placed, dropped = self.solver.pack_walls(walls, boxes, seed=self._seed(), timeout_s=self.spec.room_timeout_s)
        gone = {d.tracked.item for d in dropped if d.tracked.kind == "object"}
        # all of them dropped (a curtain the selection added and no free wall for it) is a layout,
        # not a failure; a wall object that is neither placed nor droppable is
        if any(b.id not in placed and b.id not in gone for b in boxes):
            raise EnvSpecError(f"room {room}: the wall-mounted task objects do not fit its free walls",
                               field=f"rooms.{room}", hint="request a larger room or fewer wall objects")
        self._take(room, dropped, {})
        yaws = {"s": 0.0, "n": 180.0, "w": 90.0, "e": 270.0}
        for b in boxes:
            if b.id not in placed:
                continue
            k, t = placed[b.id]
            e = es[order[k]]
            sx, sy, sz = self.sizes[b.id]
            pos_along = e.lo + t * g + sx / 2
            pos_across = e.at + e.inward * sz / 2
            x, z = (pos_along, pos_across) if e.axis == "x" else (pos_across, pos_along)
            self.poses[b.id] = _Pose((_r(x), _r(b.bottom + sy / 2), _r(z)), yaws[e.side], (sx, sy, sz))

    def agent(self, plan: FloorPlan, room: str) -> Agent:
        rect = plan.rects[room]
        fps = [p.footprint for oid, p in self.poses.items()
               if self.objects[oid].room == room and self.objects[oid].support not in ("wall", "ceiling")]
        x, z = start_point(rect, fps)
        return Agent(room=room, position=(_r(x), _r(z)))


def start_point(rect: Rect, footprints: Sequence[Rect], step: float = 0.25) -> tuple[float, float]:
    """The point of a `step` grid in `rect` farthest from its walls and the `footprints` (the
    first in x-major order within 1e-9; the centre on a room too small for the grid). The
    clearances of all points are computed at once, with the same float operations as point by
    point; the choice is made point by point."""
    best, score = (rect.x0 + rect.w / 2, rect.z0 + rect.d / 2), -1.0
    xs = rect.x0 + np.arange(1, max(1, int(rect.w / step))) * step
    zs = rect.z0 + np.arange(1, max(1, int(rect.d / step))) * step
    x, z = np.repeat(xs, len(zs)), np.tile(zs, len(xs))
    clear = np.minimum(np.minimum(x - rect.x0, rect.x1 - x), np.minimum(z - rect.z0, rect.z1 - z))
    for f in footprints:
        clear = np.minimum(clear, np.maximum(np.maximum(f.x0 - x, x - f.x1), np.maximum(f.z0 - z, z - f.z1)))
    for k, c in enumerate(clear.tolist()):
        if c > score + 1e-9:
            best, score = (float(x[k]), float(z[k])), c
    return best


def construct_environment(spec: SceneSpec, *, catalog: Catalog, rng: np.random.Generator,
                          solver: Solver = DEFAULT_SOLVER) -> SceneResult:
    """A full EnvSpec for `spec`; enrichment relations/objects are dropped (logged) when unsatisfiable."""
    b = _Builder(spec, catalog, rng, solver)
    b.validate()
    plan = plan_floor(spec.rooms, rng, wall_height=spec.wall_height)
    b.warnings += plan.warnings
    b.size_all()
    order = sorted(spec.rooms, key=lambda r: b.free_floor(r.id, plan.rects[r.id]))
    plan = plan.owned_in([r.id for r in order])
    for rq in order:  # the tightest room first: it places its doors, the roomier neighbours take them
        plan = b.layout_room(rq, plan)
    objects = []
    for o in spec.objects:
        if o.id not in b.objects or o.id not in b.poses:
            continue
        cur = b.objects[o.id]
        p = b.poses[o.id]
        objects.append(EnvObject(id=o.id, category=cur.category, room=o.room, position=p.position, yaw=p.yaw,
                                 size=p.size, support=cur.support, container=cur.container,
                                 attributes=dict(cur.attributes), states={**b.cats[o.id].default_states, **cur.states}))
    kept = {o.id for o in objects}
    relations = [Relation(type=r.type, args=r.args) for r in b.relations
                 if id(r) not in b.dropped_rel and all(a in kept for a in r.args)]
    for r in b.relations:
        if id(r) not in b.dropped_rel and not all(a in kept for a in r.args):
            b._log_rel(b._room_of(r), r, "one of its objects was dropped")
    roles = {o.role: o.id for o in spec.objects if o.role and o.id in kept}
    agent_room = spec.rooms[0].id
    env = env_from_dict({
        "task_id": spec.task_id, "generator": spec.generator, "env_id": spec.env_id,
        "claimed_trajectory": spec.claimed_trajectory, "wall_height": spec.wall_height,
        "rooms": [r.model_dump() for r in plan.rooms], "doors": [d.model_dump() for d in plan.doors],
        "windows": [w.model_dump() for w in plan.windows], "objects": [o.model_dump() for o in objects],
        "relations": [r.model_dump() for r in relations], "roles": roles,
        "agent": b.agent(plan, agent_room).model_dump()}, source=spec.env_id)
    for e in b.log:
        if e.task:
            b.warnings.append(f"task {e.kind} dropped: {e}")
    return SceneResult(env=env, relaxation_log=b.log, warnings=b.warnings)


# --- adapters for generators (LLM drafts are duck-typed: scene does not import llm) ----------------

def room_requests(rooms: Sequence[Mapping[str, Any]]) -> list[RoomRequest]:
    out = []
    for r in rooms:
        out.append(RoomRequest(
            id=str(r["id"]), type=str(r.get("type", "LivingRoom")),
            area=float(min(max(r.get("area_m2", r.get("area", 20.0)), 3.0), 80.0)),
            adjacent_to=list(r.get("adjacent_to", [])),
            doors=[DoorRequest(**{k: d[k] for k in ("to", "type", "width", "state") if k in d})
                   for d in r.get("doors", [])],
            windows=[WindowRequest(**{k: w[k] for k in ("wall", "width", "height", "sill", "state") if k in w})
                     for w in r.get("windows", [])]))
    return out


def construct_from_drafts(*, brief: Any, env_id: str, generator: str, rooms: Sequence[Mapping[str, Any]],
                          objects: Sequence[Any], relations: Sequence[Any],
                          claimed_trajectory: dict[str, dict[str, str]] | None, catalog: Catalog,
                          rng: np.random.Generator, solver: Solver = DEFAULT_SOLVER) -> SceneResult:
    """`construct_environment` for LLM drafts (objects with id/category/room/role/placement/...)."""
    roles = set(getattr(brief, "roles", {}) or {})
    reqs = []
    for o in objects:
        placement = o.placement if (o.placement in ("floor", "wall", "ceiling")
                                    or o.placement.startswith(("on:", "inside:"))) else "floor"
        reqs.append(ObjectRequest(id=o.id, category=o.category, room=o.room,
                                  role=o.role if o.role in roles else None, placement=placement,
                                  attributes=dict(o.attributes), states=dict(o.states)))
    rels = []
    warnings = []
    for r in relations:
        try:
            rels.append(RelationRequest(type=r.type, args=tuple(r.args)))
        except ValueError as exc:
            warnings.append(f"relation {r.type}({', '.join(r.args)}) ignored: {exc}")
    spec = SceneSpec(task_id=brief.id, env_id=env_id, generator=generator, rooms=room_requests(rooms),
                     objects=reqs, relations=rels, claimed_trajectory=claimed_trajectory)
    res = construct_environment(spec, catalog=catalog, rng=rng, solver=solver)
    return res.model_copy(update={"warnings": warnings + res.warnings}) if warnings else res


def env_from_placed(*, brief: Any, env_id: str, generator: str, plan: FloorPlan,
                    placed: Sequence[Any], relations: Sequence[Any],
                    openings: Mapping[str, tuple[tuple[float, float], tuple[float, float]]],
                    claimed_trajectory: dict[str, dict[str, str]] | None, catalog: Catalog) -> EnvSpec:
    """An EnvSpec with the model's own coordinates (no solver: the no-CAS ablation): its objects,
    and its door and window segments (`openings`, by id) on the rooms and wall stretches of `plan`;
    an opening it did not place keeps no segment (the floor-plan check reports it)."""
    plan = plan.placed({})
    ids = {o.id for o in placed}
    room_ids = {r.id for r in plan.rooms}
    objs = []
    for o in placed:
        name, _ = resolve_category(o.category, catalog)
        support: str | None = "floor"
        container = None
        if o.placement.startswith("on:") and o.placement[3:] in ids:
            support = o.placement[3:]
        elif o.placement.startswith("inside:") and o.placement[7:] in ids:
            support, container = None, o.placement[7:]
        elif o.placement in ("wall", "ceiling"):
            support = o.placement
        objs.append({"id": o.id, "category": name, "room": o.room if o.room in room_ids else plan.rooms[0].id,
                     "position": list(o.position), "size": list(o.size), "yaw": o.yaw, "support": support,
                     "container": container, "attributes": dict(o.attributes),
                     "states": {**catalog.categories[name].default_states, **dict(o.states)}})
    rels = []
    for r in relations:
        try:
            rels.append(Relation(type=r.type, args=tuple(r.args)).model_dump())
        except ValueError:
            continue
    roles_set = set(getattr(brief, "roles", {}) or {})
    doors = [d.model_copy(update={"segment": openings.get(d.id)}) for d in plan.doors]
    windows = [w.model_copy(update={"segment": openings.get(w.id)}) for w in plan.windows]
    return env_from_dict({
        "task_id": brief.id, "generator": generator, "env_id": env_id, "claimed_trajectory": claimed_trajectory,
        "rooms": [r.model_dump() for r in plan.rooms], "doors": [d.model_dump() for d in doors],
        "windows": [w.model_dump() for w in windows], "objects": objs, "relations": rels,
        "roles": {o.role: o.id for o in placed if o.role in roles_set},
        "agent": {"room": plan.rooms[0].id}}, source=env_id)
