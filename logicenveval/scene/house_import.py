"""ProcTHOR / AI2-THOR house JSON (schema 1.0.0) → EnvSpec, so their scenes can be scored.

The layout read is that of ProcTHOR's generator and of the ProcTHOR-10K houses AI2-THOR ships
as test data (checked against both):

* `rooms[]`: `id` (`room|<n>`), `roomType`, `floorPolygon` of `{x, y, z}` points.
* `walls[]`: `id` = `wall|<room n or exterior>|x0|z0|x1|z1`, `polygon` whose first two points
  are the wall's ends (at floor or ceiling height) — a hole's x runs from `polygon[0]` toward
  `polygon[1]`.
* `doors[]` / `windows[]`: `room0`, `room1`, `wall0`, `wall1`, `holePolygon` = [min, max] in
  wall coordinates (x along the wall, y up), optional `openness`/`openable`; an exterior door
  has `room0 == room1` and a `wall|exterior|…` side.
* `objects[]`: `id`, `assetId`, `position` (bounding-box centre), `rotation` (degrees; y is
  yaw), states (`isOn`/`isToggled`, `openness`/`isOpen`, `isDirty`, `isFilledWithLiquid`,
  `isCooked`, `isSliced`, `isBroken`), `children` (objects spawned in or on this receptacle).
  ProcTHOR-10K houses carry no `objectType`: their ids name it (`CounterTop|2|0`,
  `Book|surface|2|0`, `HousePlant|2|2|0`); the current generator writes `2|0` and `small|2|3`.
* `metadata.schema` (`1.0.0`) and `metadata.agent.position`.

Mapping (docs/scene.md "Importing houses"): a room becomes `<snake roomType>` (`living_room`,
then `living_room_2`, …) so task room names resolve. An object's AI2-THOR type is its
`objectType`, else the prefix of its id, else the type the asset database gives its `assetId`
(ProcTHOR's with `--procthor-db`, else our recorded mapping), else words of the asset id
(`RoboTHOR_office_chair_volmar` → office chair); the type becomes a catalog category through the
one vocabulary (`domain.categories`: `resolve_type`, ties broken by the task's role categories,
every such choice reported). A type that names no category is kept as an obstacle (category =
the snake type) and listed. Sizes come from the house (`boundingBox` / `axisAlignedBoundingBox`
where present), else the asset database (ProcTHOR's real sizes with `--procthor-db`), else the
catalog's mid-range size; an obstacle of unknown size has none. A child sits inside a parent
that is a container without a surface, else on it. Every number must be finite, and the object
limit (`max_env_objects`) is checked while reading.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from shapely import STRtree
from shapely.geometry import LineString, Point, Polygon
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union

from logicenveval.domain.catalog import Catalog
from logicenveval.domain.categories import Resolution, snake, vocabulary
from logicenveval.domain.shapes import load_shapes
from logicenveval.envfiles import env_from_dict
from logicenveval.errors import EnvSpecError
from logicenveval.limits import limit, raise_hint
from logicenveval.model.envspec import EnvSpec
from logicenveval.scene.procthor import OBSTACLE_CLASSES, ProcthorDB, our_assets

SUPPORTED_SCHEMAS = ("1.0.0",)

_STATES = {"isOn": "toggled_on", "isToggled": "toggled_on", "isOpen": "open", "isDirty": "dirty",
           "isFilledWithLiquid": "filled", "isCooked": "cooked", "isSliced": "sliced",
           "isBroken": "broken"}
#: first id segments that are not object types (`small|2|3`, `Book|surface|2|0`)
_NOT_TYPES = frozenset({"small", "surface", "room", "wall", "door", "window", "exterior"})
#: asset-id words that name a collection, not a thing
_ASSET_NOISE = frozenset({"robothor", "thor", "v", "ai2"})
_LAYOUT = "see the ProcTHOR house layout in docs/scene.md (Importing houses)"


@dataclass
class ImportReport:
    env: EnvSpec
    unknown_types: dict[str, list[str]] = field(default_factory=dict)  # objectType -> object ids
    ambiguous_types: dict[str, list[str]] = field(default_factory=dict)  # type -> candidates
    chosen: dict[str, str] = field(default_factory=dict)  # ambiguous type -> category used
    warnings: list[str] = field(default_factory=list)
    #: where object types came from (objectType, id, asset database, asset id) -> count
    type_sources: dict[str, int] = field(default_factory=dict)
    #: where object sizes came from (house, asset database, catalog, none) -> count
    size_sources: dict[str, int] = field(default_factory=dict)
    #: object id -> where its size came from; object id -> obstacle class (OBSTACLE_CLASSES)
    size_of: dict[str, str] = field(default_factory=dict)
    obstacles: dict[str, str] = field(default_factory=dict)
    #: EnvSpec room id -> the house's room id
    room_sources: dict[str, str] = field(default_factory=dict)


def show(value: Any, limit_chars: int = 60) -> str:
    """`repr(value)` cut to a readable length for messages (ids may be a megabyte long)."""
    text = repr(value)
    return text if len(text) <= limit_chars else f"{text[:limit_chars - 12]}…({len(text)} chars)"


def _num(value: Any, where: str, default: float | None = None) -> float:
    """A finite number, or one precise error naming the field."""
    if value is None and default is not None:
        return default
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise EnvSpecError(f"expected a number, got {show(value)}", field=where, hint=_LAYOUT)
    if isinstance(value, int) and value.bit_length() > 63:  # float() of it: OverflowError
        raise EnvSpecError(f"an integer of {value.bit_length()} bits is out of range", field=where,
                           hint="coordinates, sizes and angles are finite numbers (metres, degrees)")
    if not math.isfinite(value):
        raise EnvSpecError(f"non-finite number {value}", field=where,
                           hint="coordinates, sizes and angles are finite numbers (metres, degrees)")
    return float(value)


def _xz(p: Any, where: str) -> tuple[float, float]:
    if not isinstance(p, dict) or "x" not in p or "z" not in p:
        raise EnvSpecError("expected a point {x, y, z}", field=where,
                           hint="ProcTHOR points are objects with x, y and z")
    return _num(p["x"], f"{where}.x"), _num(p["z"], f"{where}.z")


def _need(data: Any, key: str, where: str) -> Any:
    if not isinstance(data, dict):
        raise EnvSpecError(f"expected an object, got {show(data)}", field=where or None, hint=_LAYOUT)
    if key not in data:
        raise EnvSpecError(f"missing {key!r}", field=f"{where}.{key}" if where else key, hint=_LAYOUT)
    return data[key]


def _list(data: dict[str, Any], key: str, where: str, required: bool = False) -> list[Any]:
    value = _need(data, key, where) if required else data.get(key)
    if value is None and not required:
        return []
    if not isinstance(value, list):
        raise EnvSpecError(f"expected a list, got {show(value)}", field=f"{where}.{key}" if where else key,
                           hint=_LAYOUT)
    return value


def _ref(value: Any, where: str) -> str:
    """A room/wall/object reference: ProcTHOR ids are strings (numbers are accepted)."""
    if isinstance(value, bool) or not isinstance(value, str | int):
        raise EnvSpecError(f"expected an id (a string), got {show(value)}", field=where, hint=_LAYOUT)
    return str(value)


def _id_type(raw_id: str) -> str | None:
    """The object type a ProcTHOR id names: `CounterTop|2|0` -> CounterTop; `2|0`, `small|2|3` -> None."""
    head, sep, rest = raw_id.partition("|")
    if sep and rest and re.fullmatch(r"[A-Za-z][A-Za-z0-9]*", head) and head.lower() not in _NOT_TYPES:
        return head
    return None


def _asset_words(asset_id: str) -> list[str]:
    """Words of an asset id that may name a thing: `Countertop_L_4x4` -> [Countertop]."""
    words = [w for w in re.split(r"[_\-\s|]+", snake(asset_id)) if w]
    return [w for w in words if len(w) > 1 and not any(c.isdigit() for c in w) and w not in _ASSET_NOISE]


def _bbox(obj: dict[str, Any], where: str) -> tuple[float, float, float] | None:
    """The object's own size, where the house gives one (`boundingBox` {x,y,z} or {min,max};
    AI2-THOR metadata's `axisAlignedBoundingBox.size`)."""
    box = obj.get("boundingBox")
    here = f"{where}.boundingBox"
    if box is None and isinstance(obj.get("axisAlignedBoundingBox"), dict):
        box, here = obj["axisAlignedBoundingBox"].get("size"), f"{where}.axisAlignedBoundingBox.size"
    if box is None:
        return None
    if isinstance(box, dict) and "min" in box and "max" in box:
        lo, hi = box["min"], box["max"]
        if not isinstance(lo, dict) or not isinstance(hi, dict):
            raise EnvSpecError("min and max must be points {x, y, z}", field=here, hint=_LAYOUT)
        size = [_num(hi.get(k), f"{here}.max.{k}") - _num(lo.get(k), f"{here}.min.{k}") for k in "xyz"]
    elif isinstance(box, dict):
        size = [_num(box.get(k), f"{here}.{k}") for k in "xyz"]
    else:
        raise EnvSpecError(f"expected a size {{x, y, z}}, got {show(box)}", field=here, hint=_LAYOUT)
    if min(size) <= 0:
        raise EnvSpecError(f"size {tuple(size)} is not positive", field=here, hint="sizes are in metres, > 0")
    return (size[0], size[1], size[2])


class _Importer:
    def __init__(self, house: dict[str, Any], catalog: Catalog, role_categories: frozenset[str],
                 assets: ProcthorDB) -> None:
        self.house, self.catalog, self.assets = house, catalog, assets
        self.vocab = vocabulary(catalog)
        self.role_categories = role_categories
        self.chosen: dict[str, str] = {}
        self.unknown: dict[str, list[str]] = {}
        self.ambiguous: dict[str, list[str]] = {}
        self.type_sources: dict[str, int] = {}
        self.size_sources: dict[str, int] = {}
        self.size_of: dict[str, str] = {}  # object id -> where its size came from
        self.obstacles: dict[str, str] = {}  # object id -> its obstacle class (OBSTACLE_CLASSES)
        self.room_ids: dict[str, str] = {}
        self.room_where: dict[str, str] = {}
        self.polys: dict[str, Polygon] = {}
        self._tree: STRtree | None = None
        self._tree_ids: list[str] = []
        self.walls: dict[str, tuple[int, dict[str, Any]]] = {}
        self.objects: list[dict[str, Any]] = []
        self.used_ids: set[str] = set()
        self.next_suffix: dict[str, int] = {}
        self.max_objects = limit("max_env_objects")
        self.where = ""  # the part being read, for errors the precise checks do not name
        self.last_size_source = "none"

    def rooms(self) -> list[dict[str, Any]]:
        out = []
        counts: dict[str, int] = {}
        listed = _list(self.house, "rooms", "", required=True)
        # a house we exported names its rooms by our ids: keep them (ProcTHOR's are room|n)
        plain = {r["id"] for r in listed if isinstance(r, dict) and isinstance(r.get("id"), str)
                 and re.fullmatch(r"[a-z][a-z0-9_]*", r["id"])}
        taken: set[str] = set()
        for i, room in enumerate(listed):
            where = self.where = f"rooms[{i}]"
            raw = _ref(_need(room, "id", where), f"{where}.id")
            if raw in self.room_ids:
                raise EnvSpecError(f"room id {show(raw)} is used twice ({self.room_where[raw]} and "
                                   f"{where})", field=f"{where}.id", hint="give every room its own id")
            # our own room type where we exported it (a Study is a Bedroom to AI2-THOR)
            rtype = room.get("logicenvevalRoomType") or room.get("roomType") or "LivingRoom"
            if not isinstance(rtype, str):
                raise EnvSpecError(f"expected a room type, got {show(rtype)}", field=f"{where}.roomType",
                                   hint="Kitchen, LivingRoom, Bedroom or Bathroom")
            if raw in plain and raw not in taken:
                rid = raw
            else:
                base = snake(rtype) or "room"
                rid = ""
                while not rid or rid in plain or rid in taken:
                    counts[base] = counts.get(base, 0) + 1
                    rid = base if counts[base] == 1 else f"{base}_{counts[base]}"
            taken.add(rid)
            self.room_ids[raw], self.room_where[raw] = rid, where
            poly = [_xz(p, f"{where}.floorPolygon[{k}]")
                    for k, p in enumerate(_list(room, "floorPolygon", where, required=True))]
            if len(poly) < 3:
                raise EnvSpecError(f"a floor polygon needs 3 or more points, got {len(poly)}",
                                   field=f"{where}.floorPolygon", hint=_LAYOUT)
            self.polys[rid] = Polygon(poly)
            out.append({"id": rid, "type": rtype, "polygon": poly, "procthor_id": raw})
        if not out:
            raise EnvSpecError("the house has no rooms", field="rooms",
                               hint="a house needs at least one room with a floorPolygon")
        self._tree_ids = list(self.polys)
        self._tree = STRtree([self.polys[r] for r in self._tree_ids])
        return out

    def room_of(self, x: float, z: float) -> str:
        assert self._tree is not None
        pt = Point(x, z)
        inside = sorted(int(k) for k in self._tree.query(pt, predicate="covered_by"))
        if inside:
            return self._tree_ids[inside[0]]
        return self._tree_ids[int(self._tree.nearest(pt))]

    def _room(self, ref: Any, where: str) -> str:
        raw = _ref(ref, where)
        if raw not in self.room_ids:
            known = sorted(self.room_ids)
            raise EnvSpecError(f"{show(raw)} is not a room id", field=where,
                               hint=f"use one of {[show(k, 30) for k in known[:10]]}"
                               + (f" ({len(known)} rooms)" if len(known) > 10 else ""))
        return self.room_ids[raw]

    def read_walls(self) -> None:
        for i, w in enumerate(_list(self.house, "walls", "")):
            if isinstance(w, dict) and "id" in w:
                self.walls.setdefault(_ref(w["id"], f"walls[{i}].id"), (i, w))

    def _segment(self, hole: dict[str, Any], wall_ref: Any, where: str
                 ) -> tuple[tuple[tuple[float, float], tuple[float, float]], float, float]:
        found = self.walls.get(str(wall_ref)) if isinstance(wall_ref, str | int) else None
        poly = found[1].get("polygon") if found else None
        if found and isinstance(poly, list) and len(poly) >= 2:
            start = _xz(poly[0], f"walls[{found[0]}].polygon[0]")
            end = _xz(poly[1], f"walls[{found[0]}].polygon[1]")
        else:
            parts = _ref(wall_ref, f"{where}.wall0").split("|")
            try:
                x0, z0, x1, z1 = (float(v) for v in parts[-4:])
            except ValueError:
                raise EnvSpecError(f"wall {show(wall_ref)} is neither in `walls` nor an id with "
                                   "coordinates", field=f"{where}.wall0",
                                   hint="ProcTHOR wall ids are wall|<room>|x0|z0|x1|z1") from None
            if not all(math.isfinite(v) for v in (x0, z0, x1, z1)):
                raise EnvSpecError(f"wall {show(wall_ref)} has non-finite coordinates",
                                   field=f"{where}.wall0", hint="coordinates are finite numbers")
            start, end = (x0, z0), (x1, z1)
        hp = _list(hole, "holePolygon", where, required=True)
        if len(hp) < 2 or not all(isinstance(p, dict) for p in hp[:2]):
            raise EnvSpecError("expected two points [min, max]", field=f"{where}.holePolygon", hint=_LAYOUT)
        lo_x, lo_y = _num(hp[0].get("x"), f"{where}.holePolygon[0].x"), _num(hp[0].get("y"), f"{where}.holePolygon[0].y")
        hi_x, hi_y = _num(hp[1].get("x"), f"{where}.holePolygon[1].x"), _num(hp[1].get("y"), f"{where}.holePolygon[1].y")
        length = math.dist(start, end) or 1.0
        ux, uz = (end[0] - start[0]) / length, (end[1] - start[1]) / length
        ours = hole.get("logicenvevalOpening")  # a house we exported: our opening, not the asset's hole
        if isinstance(ours, dict) and "start" in ours and "width" in ours and "height" in ours:
            lo_x = _num(ours["start"], f"{where}.logicenvevalOpening.start")
            hi_x = lo_x + _num(ours["width"], f"{where}.logicenvevalOpening.width")
            hi_y = lo_y + _num(ours["height"], f"{where}.logicenvevalOpening.height")
            a = (round(start[0] + ux * lo_x, 4), round(start[1] + uz * lo_x, 4))  # as exported: 0.1 mm
            b = (round(start[0] + ux * hi_x, 4), round(start[1] + uz * hi_x, 4))
            return (a, b), lo_y, round(hi_y - lo_y, 4)
        a = (start[0] + ux * lo_x, start[1] + uz * lo_x)
        b = (start[0] + ux * hi_x, start[1] + uz * hi_x)
        return (a, b), lo_y, hi_y - lo_y

    def doors(self) -> list[dict[str, Any]]:
        out = []
        for i, d in enumerate(_list(self.house, "doors", "")):
            where = self.where = f"doors[{i}]"
            r0 = self._room(_need(d, "room0", where), f"{where}.room0")
            r1 = self._room(d.get("room1", d["room0"]), f"{where}.room1")
            sides = (str(d.get("wall0", "")), str(d.get("wall1", "")))
            exterior = r0 == r1 or any("exterior" in s for s in sides)
            seg, _, height = self._segment(d, d.get("wall0"), where)
            openness = _num(d.get("openness"), f"{where}.openness", 0.0)
            out.append({"id": _ident(str(d.get("id", f"door_{i}"))), "rooms": [r0, "exterior" if exterior else r1],
                        "segment": seg, "height": round(height, 4) or 2.1,
                        "type": d["logicenvevalDoorType"] if isinstance(d.get("logicenvevalDoorType"), str)
                        else "door" if d.get("openable", True) else "doorway",
                        "state": "open" if openness > 0 else "closed"})
        return out

    def openings(self, height: float) -> list[dict[str, Any]]:
        """Open boundaries: ProcTHOR joins two rooms without a door by giving both rooms' walls
        on their shared segment `"empty": true`. Each such pair becomes a door of type `open`
        spanning the segment (no leaf, so no swing area) that connects the two rooms."""
        sides: dict[tuple[tuple[float, float], tuple[float, float]], list[str]] = {}
        for wid, (i, w) in self.walls.items():
            if not isinstance(w, dict) or w.get("empty") is not True:
                continue
            self.where = f"walls[{i}]"
            poly = _list(w, "polygon", self.where, required=True)
            if len(poly) < 2:
                raise EnvSpecError("a wall polygon needs its two ends first", field=f"{self.where}.polygon",
                                   hint=_LAYOUT)
            ends = sorted((_xz(poly[0], f"{self.where}.polygon[0]"), _xz(poly[1], f"{self.where}.polygon[1]")))
            key = (ends[0], ends[1])
            ref = w.get("roomId", f"room|{wid.split('|')[1]}" if wid.count("|") >= 5 else None)
            if ref is None or str(ref) not in self.room_ids:
                continue  # an exterior or unknown side joins nothing
            room = self.room_ids[str(ref)]
            if room not in sides.setdefault(key, []):
                sides[key].append(room)
        out: list[dict[str, Any]] = []
        for (a, b), rooms in sorted(sides.items()):
            for r0, r1 in zip(rooms, rooms[1:], strict=False):
                out.append({"id": _ident(f"open_{r0}_{r1}_{len(out)}"), "rooms": [r0, r1], "segment": (a, b),
                            "height": round(height, 4), "type": "open", "state": "open"})
        return out

    def bare_boundaries(self, height: float) -> list[dict[str, Any]]:
        """Boundaries with no wall at all: two rooms whose floor polygons share a stretch that no
        wall of the house stands on (empty or not) have nothing between them there. Each such
        stretch (one per straight piece, at least `_MIN_OPENING` long) becomes a door of type
        `open` between the two rooms, as an `"empty": true` wall pair does (`openings`)."""
        walls = []
        for i, w in self.walls.values():
            poly = w.get("polygon") if isinstance(w, dict) else None
            if isinstance(poly, list) and len(poly) >= 2:
                walls.append(LineString([_xz(poly[0], f"walls[{i}].polygon[0]"),
                                         _xz(poly[1], f"walls[{i}].polygon[1]")]))
        out: list[dict[str, Any]] = []
        with np.errstate(all="ignore"):  # a mangled house's huge coordinates: no piece, no noise
            standing = unary_union(walls).buffer(_ON_WALL, cap_style="flat") if walls else None
            ids = sorted(self.polys)
            for k, r0 in enumerate(ids):
                for r1 in ids[k + 1:]:
                    shared = self.polys[r0].boundary.intersection(self.polys[r1].boundary)
                    bare = shared if standing is None else shared.difference(standing)
                    for a, b in _straight_pieces(bare):
                        out.append({"id": _ident(f"bare_{r0}_{r1}_{len(out)}"), "rooms": [r0, r1],
                                    "segment": (a, b), "height": round(height, 4), "type": "open",
                                    "state": "open"})
        return out

    def windows(self) -> list[dict[str, Any]]:
        out = []
        for i, w in enumerate(_list(self.house, "windows", "")):
            where = self.where = f"windows[{i}]"
            room = self._room(_need(w, "room0", where), f"{where}.room0")
            seg, sill, height = self._segment(w, w.get("wall0"), where)
            openness = _num(w.get("openness"), f"{where}.openness", 0.0)
            out.append({"id": _ident(str(w.get("id", f"window_{i}"))), "room": room, "segment": seg,
                        "sill": round(sill, 4), "height": round(height, 4),
                        "state": "open" if openness > 0 else "closed"})
        return out

    def object_type(self, obj: dict[str, Any], raw_id: str) -> tuple[Resolution | None, str, str]:
        """(resolution, the type read, where it came from) for one house object."""
        ours = obj.get("logicenvevalCategory")  # a house we exported ourselves
        if isinstance(ours, str) and ours in self.catalog:
            return self.vocab.resolve(ours), ours, "logicenvevalCategory"
        otype = obj.get("objectType")
        if isinstance(otype, str) and otype:
            return self.vocab.resolve_type(otype, self.role_categories), otype, "objectType"
        from_id = _id_type(raw_id)
        if from_id:
            return self.vocab.resolve_type(from_id, self.role_categories), from_id, "id"
        asset_id = obj.get("assetId")
        known = self.assets.assets.get(asset_id) if isinstance(asset_id, str) else None
        if known is not None:
            return self.vocab.resolve_type(known.object_type, self.role_categories), known.object_type, \
                "asset database"
        words = _asset_words(asset_id) if isinstance(asset_id, str) else []
        for n in range(len(words), 0, -1):  # the longest run of words that names a category
            for k in range(len(words) - n + 1):
                res = self.vocab.resolve(" ".join(words[k:k + n]), self.role_categories)
                if res.category is not None:
                    return res, "".join(w.title() for w in words[k:k + n]), "asset id"
        return None, "".join(w.title() for w in words) or "Unknown", "asset id"

    def category(self, obj: dict[str, Any], raw_id: str, oid: str) -> tuple[str, str]:
        res, otype, source = self.object_type(obj, raw_id)
        self.type_sources[source] = self.type_sources.get(source, 0) + 1
        if res is None or res.category is None:
            if otype in OBSTACLE_CLASSES:
                self.obstacles[oid] = OBSTACLE_CLASSES[otype][0]
            self.unknown.setdefault(otype, []).append(oid)
            return snake(otype) or "unknown", otype
        if res.ambiguous:
            self.ambiguous.setdefault(otype, list(res.candidates))
            self.chosen[otype] = res.category
        return res.category, otype

    def _size(self, obj: dict[str, Any], where: str, category: str) -> tuple[float, float, float] | None:
        size = _bbox(obj, where)
        source = "house"
        asset_id = obj.get("assetId")
        asset = self.assets.assets.get(asset_id) if isinstance(asset_id, str) else None
        cat = self.catalog.get(category)
        ours = obj.get("logicenvevalSizeDifference")  # a house we exported: asset minus our box
        if size is None and asset is not None and isinstance(ours, list) and len(ours) == 3:
            diff = [_num(v, f"{where}.logicenvevalSizeDifference[{k}]") for k, v in enumerate(ours)]
            exact = (asset.size[0] - diff[0], asset.size[1] - diff[1], asset.size[2] - diff[2])
            if min(exact) > 0:
                size = exact
        if size is None and asset is not None:
            source, size = "asset database", asset.size
        elif size is None and cat is not None:
            lo, hi = cat.size_min, cat.size_max
            source, size = "catalog", ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2)
        elif size is None:
            source = "none"
        self.size_sources[source] = self.size_sources.get(source, 0) + 1
        self.last_size_source = source
        return size

    def _unique(self, raw_id: str) -> str:
        """A readable, unique EnvSpec id; repeated ids get _2, _3, … (amortised constant time)."""
        base = _ident(raw_id)
        oid = base
        while oid in self.used_ids:
            k = self.next_suffix.get(base, 1) + 1
            self.next_suffix[base] = k
            oid = f"{base}_{k}"
        self.used_ids.add(oid)
        return oid

    def add_objects(self, roots: list[Any]) -> None:
        """Every object and child, depth first in file order (iterative: any nesting depth)."""
        stack: list[tuple[Any, str, dict[str, Any] | None]] = [
            (o, f"objects[{i}]", None) for i, o in reversed(list(enumerate(roots)))]
        while stack:
            obj, where, parent = stack.pop()
            entry = self.add_object(obj, where, parent)
            children = _list(obj, "children", where)
            stack += [(c, f"{where}.children[{j}]", entry) for j, c in reversed(list(enumerate(children)))]

    def add_object(self, obj: Any, where: str, parent: dict[str, Any] | None) -> dict[str, Any]:
        self.where = where
        if len(self.objects) >= self.max_objects:
            raise EnvSpecError(f"more than {self.max_objects} objects (counting children)", field=where,
                               hint=raise_hint("max_env_objects"))
        raw_id = _ref(_need(obj, "id", where), f"{where}.id")
        oid = self._unique(raw_id)
        pos = _need(obj, "position", where)
        x, z = _xz(pos, f"{where}.position")
        y = _num(pos.get("y"), f"{where}.position.y", 0.0)
        category, otype = self.category(obj, raw_id, oid)
        cat = self.catalog.get(category)
        states = {flag: bool(obj[key]) for key, flag in _STATES.items() if key in obj}
        if "openness" in obj:
            states["open"] = _num(obj["openness"], f"{where}.openness", 0.0) > 0
        ours = obj.get("logicenvevalStates")  # a house we exported: the states AI2-THOR has no key for
        if isinstance(ours, dict):
            states.update({str(k): v for k, v in ours.items() if isinstance(v, bool)})
        rot = obj.get("rotation")
        yaw = _num(rot.get("y"), f"{where}.rotation.y", 0.0) if isinstance(rot, dict) else 0.0
        entry: dict[str, Any] = {
            "id": oid, "category": category, "room": parent["room"] if parent else self.room_of(x, z),
            "position": (x, y, z), "yaw": yaw, "size": self._size(obj, where, category),
            "size_source": self.last_size_source,
            "states": states, "procthor_id": raw_id, "asset_id": obj.get("assetId"),
            "object_type": otype,
        }
        if parent is None:
            entry["support"] = "wall" if cat and cat.placement[0] == "wall" else "floor"
        else:
            pcat = self.catalog.get(parent["category"])
            if pcat is not None and pcat.container and not pcat.surface and not _on_rim(entry, parent):
                entry["support"], entry["container"] = None, parent["id"]
            else:
                entry["support"] = parent["id"]
        self.size_of[oid] = entry.pop("size_source")
        self.objects.append(entry)
        return entry

    def ceiling(self) -> float:
        ys = []
        for i, w in enumerate(_list(self.house, "walls", "")):
            poly = w.get("polygon") if isinstance(w, dict) else None
            for k, p in enumerate(poly if isinstance(poly, list) else []):
                if isinstance(p, dict) and "y" in p:
                    ys.append(_num(p["y"], f"walls[{i}].polygon[{k}].y"))
        top = max(ys, default=0.0)
        return top if top > 0 else 2.7

    def agent(self) -> dict[str, Any]:
        meta = self.house.get("metadata")
        agent = meta.get("agent") if isinstance(meta, dict) else None
        pos = agent.get("position") if isinstance(agent, dict) else None
        if not isinstance(pos, dict) or "x" not in pos or "z" not in pos:
            return {}
        x, z = _xz(pos, "metadata.agent.position")
        return {"room": self.room_of(x, z), "position": (x, z)}


def _on_rim(child: dict[str, Any], parent: dict[str, Any]) -> bool:
    """A child of a container whose shape holds objects only near its top (a rim: its lowest
    level above half its height, e.g. a sink) and whose bottom is at or above that level (the
    faucet on a sink) rests on it, not in it; a fridge's shelves do not make a rim."""
    if child["size"] is None or parent["size"] is None:
        return False
    shape = load_shapes().of(parent["category"])
    if shape is None or shape.levels[0][0] < 0.5:
        return False
    p_bottom = parent["position"][1] - parent["size"][1] / 2
    level = p_bottom + shape.levels[0][0] * parent["size"][1]
    return bool(child["position"][1] - child["size"][1] / 2 >= level - 0.02)


def _ident(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_]+", "_", text).strip("_")[:200] or "obj"


def import_house(house: dict[str, Any], *, task_id: str, env_id: str, catalog: Catalog,
                 source: str | None = None, role_categories: Iterable[str] = (),
                 assets: ProcthorDB | None = None) -> ImportReport:
    """Convert one house dict; bad structure raises `EnvSpecError` naming the field.

    `role_categories` (the task's role categories) break ties first when an AI2-THOR type fits
    several catalog categories. `assets` is the asset database that types and sizes asset ids
    (ProcTHOR's own, `load_procthor_db`; default: the assets of our recorded mapping).
    """
    if not isinstance(house, dict):
        raise EnvSpecError("a house is a JSON object", file=source, hint="pass a ProcTHOR house JSON")
    meta = house.get("metadata")
    schema = meta.get("schema") if isinstance(meta, dict) else None
    warnings = []
    if schema not in SUPPORTED_SCHEMAS:
        if schema is None:
            warnings.append("no metadata.schema: read as 1.0.0")
        else:
            raise EnvSpecError(f"house schema {show(schema)} is not supported", file=source,
                               field="metadata.schema",
                               hint="upgrade it to 1.0.0 with ProcTHOR's upgrade_house_version")
    imp = _Importer(house, catalog, frozenset(role_categories), assets or our_assets())
    try:
        rooms = imp.rooms()
        imp.read_walls()
        doors, windows = imp.doors(), imp.windows()
        imp.where = "objects"
        imp.add_objects(_list(house, "objects", ""))
        imp.where = "walls"
        height = imp.ceiling()
        doors += imp.openings(height)
        doors += imp.bare_boundaries(height)
        imp.where = "metadata.agent"
        agent = imp.agent()
    except EnvSpecError as exc:
        if exc.file is not None or source is None:
            raise
        raise EnvSpecError(exc.message, file=source, field=exc.field, hint=exc.hint) from None
    except (KeyError, TypeError, ValueError, AttributeError, IndexError, RecursionError) as exc:
        raise EnvSpecError(f"malformed house: {type(exc).__name__}: {show(str(exc), 200)}", file=source,
                           field=imp.where or None, hint=_LAYOUT) from None
    for otype, ids in sorted(imp.unknown.items()):
        shown = ids if len(ids) <= 5 else [*ids[:5], f"… ({len(ids) - 5} more)"]
        if otype in OBSTACLE_CLASSES:
            cls, why = OBSTACLE_CLASSES[otype]
            warnings.append(f"AI2-THOR type {otype} is a {cls} ({why}): kept as obstacle(s) {', '.join(shown)}")
        else:
            warnings.append(f"AI2-THOR type {otype} names no catalog category: kept as obstacle(s) "
                            f"{', '.join(shown)}")
    data = {"task_id": task_id, "generator": "procthor-import", "env_id": env_id,
            "wall_height": height, "rooms": rooms, "doors": doors, "windows": windows,
            "objects": imp.objects, "agent": agent, "source_schema": schema or "1.0.0"}
    env = env_from_dict(data, source=source)
    return ImportReport(env=env, unknown_types=imp.unknown, ambiguous_types=imp.ambiguous,
                        chosen=imp.chosen, warnings=warnings, type_sources=imp.type_sources,
                        size_sources=imp.size_sources, size_of=imp.size_of, obstacles=imp.obstacles,
                        room_sources={r["id"]: r["procthor_id"] for r in rooms})


def load_house(path: str | Path) -> dict[str, Any]:
    """Read an untrusted house JSON file (size-limited, UTF-8, one precise error per problem)."""
    from logicenveval.limits import parse_json, read_text

    text = read_text(path, what="house file", error=EnvSpecError, max_bytes="max_env_bytes",
                     hint="check the path")
    data = parse_json(text, file=str(path), error=EnvSpecError)
    if not isinstance(data, dict):
        raise EnvSpecError(f"a house is a JSON object, not {type(data).__name__}", file=str(path),
                           hint="export the house with AI2-THOR/ProcTHOR (schema 1.0.0)")
    return data


#: how far (m) a boundary point may be from a wall's line and still be under the wall
_ON_WALL = 0.01
#: the shortest stretch of bare boundary that counts as an opening (m): shorter ones are the
#: rounding of two polygons' corners, not a way through
_MIN_OPENING = 0.3


def _straight_pieces(geom: BaseGeometry) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The straight segments of at least `_MIN_OPENING` of a (multi)line geometry, as
    ((x, z), (x, z)) rounded to 0.1 mm; points and shorter pieces are left out."""
    lines = [g for g in getattr(geom, "geoms", [geom]) if isinstance(g, LineString)]
    out = []
    for line in lines:
        coords = list(line.coords)
        for (ax, az), (bx, bz) in zip(coords, coords[1:], strict=False):
            if math.hypot(bx - ax, bz - az) >= _MIN_OPENING:
                out.append(((round(ax, 4), round(az, 4)), (round(bx, 4), round(bz, 4))))
    return out
