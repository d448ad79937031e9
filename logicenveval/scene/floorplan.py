"""Floor plans: rectilinear rooms by boustrophedon strip slicing, doors on shared walls, windows outside.

Rooms are ordered breadth-first over the requested adjacency and laid into rows of at most three
(alternating direction), so that rooms adjacent in the request are usually adjacent in the plan.
Rows share one width, each row's depth follows its total area, so rooms never overlap and the
outline is a rectangle. Requested adjacencies the slicing cannot honour are warned about; a door is
added between touching rooms wherever needed to keep every room reachable.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import Door, Room, Window
from logicenveval.scene.geometry import EPS, Edge, Rect, edges, shared, subtract
from logicenveval.scene.spec import DoorRequest, RoomRequest

MIN_SIDE = 2.0  # metres: narrower rooms cannot hold furniture and a walkway
CORNER = 0.15  # door and window clearance from wall corners
ROW_MAX = 3


@dataclass(frozen=True)
class FloorPlan:
    rooms: list[Room]
    rects: dict[str, Rect]
    doors: list[Door]
    windows: list[Window]
    warnings: list[str] = field(default_factory=list)


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


class _Openings:
    """Occupied stretches per wall line, so doors and windows never overlap."""

    def __init__(self) -> None:
        self.used: dict[tuple[str, float], list[tuple[float, float]]] = {}

    def place(self, e: Edge, lo: float, hi: float, width: float, rng: np.random.Generator,
              gap: float) -> float | None:
        key = (e.axis, round(e.at, 4))
        free = subtract(lo + CORNER, hi - CORNER, [(a - gap, b + gap) for a, b in self.used.get(key, [])])
        fits = [(u, v) for u, v in free if v - u >= width - EPS]
        if not fits:
            return None
        u, v = fits[int(rng.integers(len(fits)))]
        last = max(u, v - width)
        start = min(max(_snap(float(rng.uniform(u, last))), u), last)
        self.used.setdefault(key, []).append((start, start + width))
        return start


def plan_floor(rooms: list[RoomRequest], rng: np.random.Generator, *, wall_height: float = 2.7) -> FloorPlan:
    """Rooms, doors and windows for the requested rooms; deterministic given `rng`."""
    if not rooms:
        raise EnvSpecError("no rooms requested", field="rooms", hint="request at least one room")
    ids = [r.id for r in rooms]
    dup = sorted({i for i in ids if ids.count(i) > 1})
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
    openings = _Openings()
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
            start = openings.place(e, lo, hi, req.width, rng, gap=req.width + 0.1)
            if start is None:
                continue
            seg = (e.point(start), e.point(_snap(start + req.width, 0.001)))
            doors.append(Door(id=f"d{len(doors)}", rooms=(a, b), segment=seg, type=req.type, state=req.state))
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
                add_door(a, b, DoorRequest(to=b))
    ext_room, ext_req = exterior or (ids[0], DoorRequest(to="exterior"))
    if not add_door(ext_room, "exterior", ext_req):
        warnings.append(f"room {ext_room}: no exterior wall free for the entrance door")
    windows = _windows(rooms, rects, openings, rng, wall_height, warnings)
    out_rooms = [Room(id=r.id, type=r.type, polygon=rects[r.id].polygon()) for r in rooms]
    return FloorPlan(rooms=out_rooms, rects=rects, doors=doors, windows=windows, warnings=warnings)


def _windows(rooms: list[RoomRequest], rects: dict[str, Rect], openings: _Openings,
             rng: np.random.Generator, wall_height: float, warnings: list[str]) -> list[Window]:
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
                width = min(w.width, hi - lo - 2 * CORNER)
                if width < 0.3:
                    continue
                start = openings.place(e, lo, hi, width, rng, gap=0.1)
                if start is None:
                    continue
                if e.side != w.wall:
                    warnings.append(f"room {r.id}: wall {w.wall} is not exterior; window put on {e.side}")
                seg = (e.point(start), e.point(_snap(start + width, 0.001)))
                out.append(Window(id=f"w{len(out)}", room=r.id, segment=seg, sill=w.sill,
                                  height=round(height, 3), state=w.state))
                placed = True
                break
            if not placed:
                warnings.append(f"room {r.id}: no exterior wall free for a window; skipped")
    return out
