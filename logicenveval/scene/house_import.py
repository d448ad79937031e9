"""ProcTHOR / AI2-THOR house JSON (schema 1.0.0) → EnvSpec, so their scenes can be scored.

The layout read (checked against ProcTHOR's own generator and 0.0.1→1.0.0 upgrader):

* `rooms[]`: `id` (`room|<n>`), `roomType`, `floorPolygon` of `{x, y, z}` points.
* `walls[]`: `id` = `wall|<room n or exterior>|x0|z0|x1|z1`, `polygon` whose first two points
  are the wall's ends at floor height — a hole's x runs from `polygon[0]` toward `polygon[1]`.
* `doors[]` / `windows[]`: `room0`, `room1`, `wall0`, `wall1`, `holePolygon` = [min, max] in
  wall coordinates (x along the wall, y up), `openness`; an exterior door has `room0 == room1`
  and a `wall|exterior|…` side.
* `objects[]`: `id`, `assetId`, `position` (bounding-box centre), `rotation` (degrees; y is
  yaw), optional `objectType`, states (`isOn`/`isToggled`, `openness`/`isOpen`, `isDirty`,
  `isFilledWithLiquid`, `isCooked`, `isSliced`, `isBroken`), and `children` — objects spawned in
  or on this receptacle.
* `metadata.schema` (`1.0.0`) and `metadata.agent.position`.

Mapping: a room becomes `<snake roomType>` (`living_room`, then `living_room_2`, …) so task
room names resolve; an object's category is the catalog category whose `ai2thor_type` is its
`objectType` (or the type read from `assetId`, e.g. `Dining_Table_16_1` → `DiningTable`); when
a type fits several categories, the only one that is a role category of the task, else the one
whose name or synonym is the type (GarbageCan → trash_can, "garbage can"), else the first by
name — every such choice is reported; a type no category lists but that names a catalog category
(WallClock → wall_clock) is that category; a child sits inside a parent that is a container
without a surface, else on it. Unknown types are kept as obstacles (category = the snake type,
which the simulator treats as an immovable obstacle) and listed. Houses carry no sizes (those
live in AI2-THOR's asset database), so a known category gets its catalog mid-range size and an
unknown one none — PhyPR of an imported house therefore reflects these approximations.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from shapely.geometry import Point, Polygon

from logicenveval.domain.catalog import Catalog
from logicenveval.domain.roles import category_names
from logicenveval.envfiles import env_from_dict
from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import EnvSpec

SUPPORTED_SCHEMAS = ("1.0.0",)

_STATES = {"isOn": "toggled_on", "isToggled": "toggled_on", "isOpen": "open", "isDirty": "dirty",
           "isFilledWithLiquid": "filled", "isCooked": "cooked", "isSliced": "sliced",
           "isBroken": "broken"}


@dataclass
class ImportReport:
    env: EnvSpec
    unknown_types: dict[str, list[str]] = field(default_factory=dict)  # objectType -> object ids
    ambiguous_types: dict[str, list[str]] = field(default_factory=dict)  # type -> candidates
    chosen: dict[str, str] = field(default_factory=dict)  # ambiguous type -> category used
    warnings: list[str] = field(default_factory=list)


def _snake(name: str) -> str:
    spaced = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name)
    return re.sub(r"[^a-z0-9]+", "_", spaced.lower()).strip("_")


def _type_of(obj: dict[str, Any]) -> str:
    if isinstance(obj.get("objectType"), str) and obj["objectType"]:
        return str(obj["objectType"])
    words = [w for w in re.split(r"[_|]", str(obj.get("assetId", ""))) if w and not w.isdigit()]
    return "".join(w[:1].upper() + w[1:] for w in words) or "Unknown"


def _xz(p: Any, where: str) -> tuple[float, float]:
    try:
        x, z = float(p["x"]), float(p["z"])
    except (TypeError, KeyError, ValueError):
        raise EnvSpecError("expected a point {x, y, z}", field=where,
                           hint="ProcTHOR points are objects with x, y and z") from None
    if not (math.isfinite(x) and math.isfinite(z)):
        raise EnvSpecError(f"non-finite coordinate ({x}, {z})", field=where,
                           hint="coordinates are finite numbers in metres")
    return x, z


def _need(data: dict[str, Any], key: str, where: str) -> Any:
    if key not in data:
        raise EnvSpecError(f"missing {key!r}", field=f"{where}.{key}" if where else key,
                           hint="see the ProcTHOR house layout in docs/own-generator.md")
    return data[key]


class _Importer:
    def __init__(self, house: dict[str, Any], catalog: Catalog, source: str | None,
                 role_categories: frozenset[str]) -> None:
        self.house, self.catalog, self.source = house, catalog, source
        self.role_categories = role_categories
        self.chosen: dict[str, str] = {}
        self.by_type: dict[str, list[str]] = {}
        for name, cat in catalog.categories.items():
            if cat.ai2thor_type:
                self.by_type.setdefault(cat.ai2thor_type, []).append(name)
        self.unknown: dict[str, list[str]] = {}
        self.ambiguous: dict[str, list[str]] = {}
        self.warnings: list[str] = []
        self.room_ids: dict[str, str] = {}
        self.polys: dict[str, Polygon] = {}
        self.objects: list[dict[str, Any]] = []
        self.used_ids: set[str] = set()
        self.where = ""  # the part being read, for errors the precise checks do not name

    def rooms(self) -> list[dict[str, Any]]:
        out = []
        counts: dict[str, int] = {}
        for i, room in enumerate(_need(self.house, "rooms", "")):
            where = self.where = f"rooms[{i}]"
            rtype = str(room.get("roomType") or "LivingRoom")
            base = _snake(rtype)
            counts[base] = counts.get(base, 0) + 1
            rid = base if counts[base] == 1 else f"{base}_{counts[base]}"
            self.room_ids[str(_need(room, "id", where))] = rid
            poly = [_xz(p, f"{where}.floorPolygon[{k}]")
                    for k, p in enumerate(_need(room, "floorPolygon", where))]
            self.polys[rid] = Polygon(poly)
            out.append({"id": rid, "type": rtype, "polygon": poly, "procthor_id": room["id"]})
        if not out:
            raise EnvSpecError("the house has no rooms", file=self.source, field="rooms",
                               hint="a house needs at least one room with a floorPolygon")
        return out

    def room_of(self, x: float, z: float) -> str:
        pt = Point(x, z)
        inside = [rid for rid, poly in self.polys.items() if poly.covers(pt)]
        if inside:
            return inside[0]
        return min(self.polys, key=lambda rid: self.polys[rid].distance(pt))

    def _room(self, ref: Any, where: str) -> str:
        if ref not in self.room_ids:
            raise EnvSpecError(f"{ref!r} is not a room id", file=self.source, field=where,
                               hint=f"use one of {sorted(self.room_ids)}")
        return self.room_ids[ref]

    def _segment(self, hole: dict[str, Any], wall_ref: Any, where: str
                 ) -> tuple[tuple[tuple[float, float], tuple[float, float]], float, float]:
        walls = {w.get("id"): w for w in self.house.get("walls") or []}
        wall = walls.get(wall_ref)
        if wall is not None and len(wall.get("polygon") or []) >= 2:
            start = _xz(wall["polygon"][0], f"walls.{wall_ref}.polygon[0]")
            end = _xz(wall["polygon"][1], f"walls.{wall_ref}.polygon[1]")
        else:
            parts = str(wall_ref).split("|")
            try:
                x0, z0, x1, z1 = (float(v) for v in parts[-4:])
            except ValueError:
                raise EnvSpecError(f"wall {wall_ref!r} is neither in `walls` nor an id with "
                                   "coordinates", file=self.source, field=f"{where}.wall0",
                                   hint="ProcTHOR wall ids are wall|<room>|x0|z0|x1|z1") from None
            start, end = (x0, z0), (x1, z1)
        hp = _need(hole, "holePolygon", where)
        lo, hi = hp[0], hp[1]
        length = math.dist(start, end) or 1.0
        ux, uz = (end[0] - start[0]) / length, (end[1] - start[1]) / length
        a = (start[0] + ux * float(lo["x"]), start[1] + uz * float(lo["x"]))
        b = (start[0] + ux * float(hi["x"]), start[1] + uz * float(hi["x"]))
        return (a, b), float(lo["y"]), float(hi["y"]) - float(lo["y"])

    def doors(self) -> list[dict[str, Any]]:
        out = []
        for i, d in enumerate(self.house.get("doors") or []):
            where = self.where = f"doors[{i}]"
            r0 = self._room(_need(d, "room0", where), f"{where}.room0")
            r1 = self._room(d.get("room1", d["room0"]), f"{where}.room1")
            exterior = r0 == r1 or "exterior" in str(d.get("wall1", "")) or "exterior" in str(d.get("wall0", ""))
            seg, _, height = self._segment(d, d.get("wall0"), where)
            out.append({"id": _ident(str(d.get("id", f"door_{i}"))), "rooms": [r0, "exterior" if exterior else r1],
                        "segment": seg, "height": round(height, 4) or 2.1,
                        "type": "door" if d.get("openable", True) else "doorway",
                        "state": "open" if float(d.get("openness", 0) or 0) > 0 else "closed"})
        return out

    def windows(self) -> list[dict[str, Any]]:
        out = []
        for i, w in enumerate(self.house.get("windows") or []):
            where = self.where = f"windows[{i}]"
            room = self._room(_need(w, "room0", where), f"{where}.room0")
            seg, sill, height = self._segment(w, w.get("wall0"), where)
            out.append({"id": _ident(str(w.get("id", f"window_{i}"))), "room": room, "segment": seg,
                        "sill": round(sill, 4), "height": round(height, 4),
                        "state": "open" if float(w.get("openness", 0) or 0) > 0 else "closed"})
        return out

    def category(self, otype: str, oid: str) -> str:
        names = self.by_type.get(otype, [])
        if not names and _snake(otype) in self.catalog:
            return _snake(otype)  # a catalog category of that name, without an ai2thor_type
        if not names:
            self.unknown.setdefault(otype, []).append(oid)
            return _snake(otype) or "unknown"
        if len(names) == 1:
            return names[0]
        key = _snake(otype).replace("_", "")
        named = [n for n in names
                 if key in {x.replace("_", "") for x in category_names(n, self.catalog)}]
        roles = [n for n in names if n in self.role_categories]
        choice = ((roles if len(roles) == 1 else []) or named or sorted(names))[0]
        self.ambiguous.setdefault(otype, sorted(names))
        self.chosen[otype] = choice
        return choice

    def add_object(self, obj: dict[str, Any], where: str, parent: dict[str, Any] | None) -> None:
        self.where = where
        raw_id = str(_need(obj, "id", where))
        oid = _ident(raw_id)
        k = 1
        while oid in self.used_ids:
            k += 1
            oid = f"{_ident(raw_id)}_{k}"
        self.used_ids.add(oid)
        pos = _need(obj, "position", where)
        x, z = _xz(pos, f"{where}.position")
        y = float(pos.get("y", 0.0))
        otype = _type_of(obj)
        category = self.category(otype, oid)
        cat = self.catalog.get(category)
        states = {flag: bool(obj[key]) for key, flag in _STATES.items() if key in obj}
        if "openness" in obj:
            states["open"] = float(obj["openness"] or 0) > 0
        rot = obj.get("rotation") or {}
        entry: dict[str, Any] = {
            "id": oid, "category": category, "room": parent["room"] if parent else self.room_of(x, z),
            "position": (x, y, z), "yaw": float(rot.get("y", 0.0) or 0.0),
            "size": tuple((lo + hi) / 2 for lo, hi in zip(cat.size_min, cat.size_max, strict=True))
            if cat else None,
            "states": states, "procthor_id": raw_id, "asset_id": obj.get("assetId"),
            "object_type": otype,
        }
        if parent is None:
            entry["support"] = "wall" if cat and cat.placement[0] == "wall" else "floor"
        else:
            pcat = self.catalog.get(parent["category"])
            if pcat is not None and pcat.container and not pcat.surface:
                entry["support"], entry["container"] = None, parent["id"]
            else:
                entry["support"] = parent["id"]
        self.objects.append(entry)
        for j, child in enumerate(obj.get("children") or []):
            self.add_object(child, f"{where}.children[{j}]", entry)

    def agent(self) -> dict[str, Any]:
        pos = ((self.house.get("metadata") or {}).get("agent") or {}).get("position")
        if not isinstance(pos, dict) or "x" not in pos or "z" not in pos:
            return {}
        x, z = _xz(pos, "metadata.agent.position")
        return {"room": self.room_of(x, z), "position": (x, z)}


def _ident(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_]+", "_", text).strip("_") or "obj"


def import_house(house: dict[str, Any], *, task_id: str, env_id: str, catalog: Catalog,
                 source: str | None = None, role_categories: Iterable[str] = ()) -> ImportReport:
    """Convert one house dict; bad structure raises `EnvSpecError` naming the field.

    `role_categories` (the task's role categories) break ties first when an AI2-THOR type fits
    several catalog categories.
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
            raise EnvSpecError(f"house schema {schema!r} is not supported", file=source,
                               field="metadata.schema",
                               hint="upgrade it to 1.0.0 with ProcTHOR's upgrade_house_version")
    imp = _Importer(house, catalog, source, frozenset(role_categories))
    try:
        rooms = imp.rooms()
        doors, windows = imp.doors(), imp.windows()
        imp.where = "objects"
        for i, obj in enumerate(house.get("objects") or []):
            imp.add_object(obj, f"objects[{i}]", None)
        imp.where = "walls"
        ceiling = [float(p.get("y", 0)) for w in house.get("walls") or [] for p in w.get("polygon") or []]
        imp.where = "metadata.agent"
        agent = imp.agent()
    except EnvSpecError as exc:
        if exc.file is not None or source is None:
            raise
        raise EnvSpecError(exc.message, file=source, field=exc.field, hint=exc.hint) from None
    except (KeyError, TypeError, ValueError, AttributeError, IndexError, RecursionError) as exc:
        raise EnvSpecError(f"malformed house: {type(exc).__name__}: {exc}", file=source,
                           field=imp.where or None,
                           hint="compare the field with the ProcTHOR 1.0.0 layout "
                           "(docs/own-generator.md)") from None
    for otype, ids in sorted(imp.unknown.items()):
        warnings.append(f"unknown AI2-THOR type {otype} kept as obstacle(s): {', '.join(ids)}")
    height = max(ceiling) if ceiling and math.isfinite(max(ceiling)) and max(ceiling) > 0 else 2.7
    data = {"task_id": task_id, "generator": "procthor-import", "env_id": env_id,
            "wall_height": height, "rooms": rooms, "doors": doors, "windows": windows,
            "objects": imp.objects, "agent": agent, "source_schema": schema or "1.0.0"}
    env = env_from_dict(data, source=source)
    return ImportReport(env=env, unknown_types=imp.unknown, ambiguous_types=imp.ambiguous,
                        chosen=imp.chosen, warnings=warnings)


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
