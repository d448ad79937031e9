"""Floor plans: rectilinear rooms by boustrophedon strip slicing; doors and windows assigned to wall
stretches, their positions along them left to the layout solver.

Rooms are ordered breadth-first over the requested adjacency and laid into rows of at most three
(alternating direction), so that rooms adjacent in the request are usually adjacent in the plan.
Rows share one width, each row's depth follows its total area, so rooms never overlap and the
outline is a rectangle. Requested adjacencies the slicing cannot honour are warned about; a door is
added between touching rooms wherever needed to keep every room reachable.

Each door and window gets a `Slot`: the wall stretch it goes on (a door on the longest wall its
rooms share, an entrance or window on an exterior stretch), with room reserved for every opening
of that stretch. Where along the stretch is a variable of the layout solve of the slot's owner
room (paper §3.3: "the doorway and window positions" are variables of the CSP; `scene.construct`).
`place_by_rule` fixes them without a solver instead (seeded positions; the no-CAS ablation).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import Door, Room, Window
from logicenveval.model.repeats import repeated
from logicenveval.scene.geometry import EPS, Edge, Rect, edges, shared, subtract
from logicenveval.scene.spec import DoorRequest, RoomRequest

MIN_SIDE = 2.0  # metres: narrower rooms cannot hold furniture and a walkway
CORNER = 0.15  # door and window clearance from wall corners
GAP = 0.1  # metres between two openings on one wall
ROW_MAX = 3


@dataclass(frozen=True)
class Slot:
    """Where a door or window may go: along `edge` (of the owner room's rectangle) between `lo`
    and `hi` (corner clearance applied), `width` long. `owner` is the room whose layout solve
    places it (a door's first room in request order)."""

    owner: str
    edge: Edge
    lo: float
    hi: float
    width: float

    def segment(self, start: float) -> tuple[tuple[float, float], tuple[float, float]]:
        """The wall segment of the opening that starts at `start` (metres along the edge)."""
        return (self.edge.point(_snap(start, 0.001)), self.edge.point(_snap(start + self.width, 0.001)))


@dataclass(frozen=True)
class FloorPlan:
    rooms: list[Room]
    rects: dict[str, Rect]
    doors: list[Door]  # `segment` None until placed (layout solver or `place_by_rule`)
    windows: list[Window]
    warnings: list[str] = field(default_factory=list)
    slots: dict[str, Slot] = field(default_factory=dict)  # door/window id -> its wall stretch

    def opening_requests(self) -> list[dict[str, object]]:
        """Each door and window as a writer without a solver is asked to place it: id, kind, rooms,
        size, and the wall stretch (two end points) it goes on."""
        out: list[dict[str, object]] = []
        for d in self.doors:
            e, slot = self.slots[d.id].edge, self.slots[d.id]
            out.append({"id": d.id, "kind": "door", "rooms": list(d.rooms), "width": slot.width, "height": d.height,
                        "wall_from": list(e.point(slot.lo)), "wall_to": list(e.point(slot.hi))})
        for w in self.windows:
            e, slot = self.slots[w.id].edge, self.slots[w.id]
            out.append({"id": w.id, "kind": "window", "rooms": [w.room], "width": slot.width, "sill": w.sill,
                        "height": w.height, "wall_from": list(e.point(slot.lo)), "wall_to": list(e.point(slot.hi))})
        return out

    def owned_in(self, order: list[str]) -> FloorPlan:
        """The plan whose doors are placed by whichever of their rooms comes first in `order` (the
        order the rooms are laid out in), each slot on that room's edge of the same wall."""
        rank = {r: k for k, r in enumerate(order)}
        slots = dict(self.slots)
        for d in self.doors:
            rooms = [r for r in d.rooms if r != "exterior"]
            owner = min(rooms, key=lambda r: rank.get(r, len(rank)))
            old = slots[d.id]
            if owner != old.owner:
                edge = next(e for e in edges(self.rects[owner]).values()
                            if e.axis == old.edge.axis and abs(e.at - old.edge.at) < EPS and e.inward != old.edge.inward)
                slots[d.id] = replace(old, owner=owner, edge=edge)
        return replace(self, slots=slots)

    def placed(self, starts: dict[str, float]) -> FloorPlan:
        """The plan with the openings of `starts` (id -> metres along its slot's edge) on their walls."""
        def seg(oid: str, old: tuple[tuple[float, float], tuple[float, float]] | None
                ) -> tuple[tuple[float, float], tuple[float, float]] | None:
            return self.slots[oid].segment(starts[oid]) if oid in starts else old

        return replace(self, doors=[d.model_copy(update={"segment": seg(d.id, d.segment)}) for d in self.doors],
                       windows=[w.model_copy(update={"segment": seg(w.id, w.segment)}) for w in self.windows])


def _snap(v: float, grid: float = 0.05) -> float:
    return round(round(v / grid) * grid, 4)


def _order(rooms: list[RoomRequest]) -> list[RoomRequest]:
    by_id = {r.id: r for r in rooms}
    nbrs: dict[str, list[str]] = {r.id: [] for r in rooms}
    for r in rooms:
        for o in [*r.adjacent_to, *(d.to for d in r.doors)]:
            if o in by_id and o != r.id:
                nbrs[r.id].append(o)
                nbrs[o].append(r.id)
    seen: list[str] = []
    for start in by_id:
        if start in seen:
            continue
        queue = [start]
        seen.append(start)
        while queue:
            cur = queue.pop(0)
            for n in nbrs[cur]:
                if n not in seen:
                    seen.append(n)
                    queue.append(n)
    return [by_id[i] for i in seen]


def _layout(order: list[RoomRequest], rng: np.random.Generator) -> dict[str, Rect]:
    n = len(order)
    if n == 1:
        ratio = float(rng.uniform(1.0, 1.5))
        w = max(MIN_SIDE, _snap(math.sqrt(order[0].area * ratio)))
        d = max(MIN_SIDE, _snap(order[0].area / w))
        return {order[0].id: Rect(0.0, 0.0, w, d)}
    n_rows = math.ceil(n / ROW_MAX)
    per_row = math.ceil(n / n_rows)
    rows = [order[i:i + per_row] for i in range(0, n, per_row)]
    total = sum(r.area for r in order)
    width = _snap(max(math.sqrt(total * float(rng.uniform(1.1, 1.6))), MIN_SIDE * per_row))
    rects: dict[str, Rect] = {}
    z = 0.0
    for k, row in enumerate(rows):
        row_area = sum(r.area for r in row)
        depth = max(MIN_SIDE, _snap(row_area / width))
        widths = [max(MIN_SIDE, r.area / depth) for r in row]
        scale = width / sum(widths)
        widths = [w * scale for w in widths]
        if min(widths) < MIN_SIDE:  # rebalance: give every room at least MIN_SIDE
            widths = [max(MIN_SIDE, w) for w in widths]
            extra = sum(widths) - width
            big = [i for i, w in enumerate(widths) if w > MIN_SIDE]
            for i in big:
                widths[i] -= extra / len(big)
        items = list(zip(row, widths, strict=True))
        if k % 2 == 1:
            items.reverse()
        x = 0.0
        for j, (r, w) in enumerate(items):
            x1 = width if j == len(items) - 1 else _snap(x + w)
            rects[r.id] = Rect(x, z, x1, _snap(z + depth))
            x = x1
        z = _snap(z + depth)
    return rects


def _shared_wall(a: Rect, b: Rect) -> tuple[Edge, tuple[float, float]] | None:
    ea, eb = edges(a), edges(b)
    best: tuple[Edge, tuple[float, float]] | None = None
    for s in ea.values():
        for t in eb.values():
            span = shared(s, t)
            if span and (best is None or span[1] - span[0] > best[1][1] - best[1][0]):
                best = (s, span)
    return best


def _exterior(rid: str, rects: dict[str, Rect]) -> list[tuple[Edge, float, float]]:
    out = []
    for e in edges(rects[rid]).values():
        cuts = []
        for oid, o in rects.items():
            if oid == rid:
                continue
            for f in edges(o).values():
                span = shared(e, f)
                if span:
                    cuts.append(span)
        out += [(e, lo, hi) for lo, hi in subtract(e.lo, e.hi, cuts)]
    return out


class _Stretches:
    """Room left on each wall stretch, so that every opening assigned to one fits with `GAP`s."""

    def __init__(self) -> None:
        self.widths: dict[tuple[str, float, float, float], list[float]] = {}

    def reserve(self, e: Edge, lo: float, hi: float, width: float) -> bool:
        key = (e.axis, round(e.at, 4), round(lo, 4), round(hi, 4))
        taken = self.widths.setdefault(key, [])
        if sum(taken) + GAP * len(taken) + width > hi - lo - 2 * CORNER + EPS:
            return False
        taken.append(width)
        return True


def plan_floor(rooms: list[RoomRequest], rng: np.random.Generator, *, wall_height: float = 2.7) -> FloorPlan:
    """Rooms, and doors and windows with their wall stretches (not yet positions: `Slot`); deterministic
    given `rng`."""
    if not rooms:
        raise EnvSpecError("no rooms requested", field="rooms", hint="request at least one room")
    ids = [r.id for r in rooms]
    dup = repeated(ids)
    if dup:
        raise EnvSpecError(f"room ids repeated: {dup}", field="rooms", hint="give each room a unique id")
    if "exterior" in ids:
        raise EnvSpecError("'exterior' is reserved", field="rooms.id", hint="rename the room")
    warnings: list[str] = []
    rects = _layout(_order(rooms), rng)
    for r in rooms:
        if abs(rects[r.id].area - r.area) > 0.25 * r.area:
            warnings.append(f"room {r.id}: area {rects[r.id].area:.1f} m² instead of {r.area:.1f} m² "
                            "(rooms keep at least 2 m per side and share the plan's width)")
    stretches = _Stretches()
    slots: dict[str, Slot] = {}
    doors: list[Door] = []
    parent = {i: i for i in ids}

    def find(i: str) -> str:
        while parent[i] != i:
            i = parent[i]
        return i

    def add_door(a: str, b: str, req: DoorRequest) -> bool:
        if b == "exterior":
            walls = sorted(_exterior(a, rects), key=lambda t: -(t[2] - t[1]))
        else:
            sw = _shared_wall(rects[a], rects[b])
            walls = [(sw[0], *sw[1])] if sw else []
        for e, lo, hi in walls:
            if not stretches.reserve(e, lo, hi, req.width):
                continue
            door = Door(id=f"d{len(doors)}", rooms=(a, b), segment=None, type=req.type, state=req.state)
            doors.append(door)
            slots[door.id] = Slot(a, e, lo + CORNER, hi - CORNER, req.width)
            if b != "exterior":
                parent[find(a)] = find(b)
            return True
        return False

    pairs: dict[frozenset[str], DoorRequest] = {}
    exterior: tuple[str, DoorRequest] | None = None
    for r in rooms:
        for d in r.doors:
            if d.to == "exterior":
                exterior = exterior or (r.id, d)
            elif d.to in rects and d.to != r.id:
                pairs.setdefault(frozenset((r.id, d.to)), d)
            else:
                warnings.append(f"room {r.id}: door to unknown room {d.to!r} ignored")
        for o in r.adjacent_to:
            if o in rects and o != r.id:
                pairs.setdefault(frozenset((r.id, o)), DoorRequest(to=o))
            elif o != "exterior":
                warnings.append(f"room {r.id}: adjacency to unknown room {o!r} ignored")
    for pair, req in pairs.items():
        a, b = sorted(pair, key=ids.index)
        if not add_door(a, b, req):
            warnings.append(f"rooms {a} and {b} share no wall long enough for a door in this plan")
    for a in ids:  # keep every room reachable
        for b in ids:
            if a < b and find(a) != find(b):
                first, second = sorted((a, b), key=ids.index)
                add_door(first, second, DoorRequest(to=second))
    ext_room, ext_req = exterior or (ids[0], DoorRequest(to="exterior"))
    if not add_door(ext_room, "exterior", ext_req):
        warnings.append(f"room {ext_room}: no exterior wall free for the entrance door")
    windows = _windows(rooms, rects, stretches, slots, wall_height, warnings)
    out_rooms = [Room(id=r.id, type=r.type, polygon=rects[r.id].polygon()) for r in rooms]
    return FloorPlan(rooms=out_rooms, rects=rects, doors=doors, windows=windows, warnings=warnings, slots=slots)


def _windows(rooms: list[RoomRequest], rects: dict[str, Rect], stretches: _Stretches, slots: dict[str, Slot],
             wall_height: float, warnings: list[str]) -> list[Window]:
    out: list[Window] = []
    for r in rooms:
        ext = _exterior(r.id, rects)
        for w in r.windows:
            height = min(w.height, wall_height - 0.1 - w.sill)
            if height < 0.3:
                warnings.append(f"room {r.id}: window on {w.wall} does not fit below the ceiling; skipped")
                continue
            walls = sorted(ext, key=lambda t: (t[0].side != w.wall, -(t[2] - t[1])))
            placed = False
            for e, lo, hi in walls:
                width = _snap(min(w.width, hi - lo - 2 * CORNER))
                if width < 0.3 or not stretches.reserve(e, lo, hi, width):
                    continue
                if e.side != w.wall:
                    warnings.append(f"room {r.id}: wall {w.wall} is not exterior; window put on {e.side}")
                win = Window(id=f"w{len(out)}", room=r.id, segment=None, sill=w.sill, height=round(height, 3),
                             state=w.state)
                out.append(win)
                slots[win.id] = Slot(r.id, e, lo + CORNER, hi - CORNER, width)
                placed = True
                break
            if not placed:
                warnings.append(f"room {r.id}: no exterior wall free for a window; skipped")
    return out


def place_by_rule(plan: FloorPlan, rng: np.random.Generator) -> FloorPlan:
    """Every opening at a seeded position of its stretch, without a solver (the no-CAS ablation:
    only the layout solver would place them otherwise): the openings of a stretch in order, the
    stretch's spare length split among the gaps before, between and after them at random."""
    groups: dict[tuple[str, float, float, float], list[str]] = {}
    for oid, slot in plan.slots.items():
        groups.setdefault((slot.edge.axis, round(slot.edge.at, 4), round(slot.lo, 4), round(slot.hi, 4)),
                          []).append(oid)
    starts: dict[str, float] = {}
    for ids in groups.values():
        first = plan.slots[ids[0]]
        spare = first.hi - first.lo - sum(plan.slots[i].width for i in ids) - GAP * (len(ids) - 1)
        shares = rng.dirichlet(np.ones(len(ids) + 1)) * max(spare, 0.0)
        at = first.lo
        for oid, share in zip(ids, shares, strict=False):
            at += float(share)
            starts[oid] = math.floor(at * 1000) / 1000  # mm: never past the reserved room
            at = starts[oid] + plan.slots[oid].width + GAP
    return plan.placed(starts)
