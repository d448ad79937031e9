"""Will AI2-THOR load this house? `check_house` verifies a ProcTHOR house JSON against ProcTHOR's
databases (or our recorded mapping): every object `assetId` is a real asset of its `objectType`,
every door/window asset has a wall hole, every material exists, the keys AI2-THOR reads are
there (`metadata.agentPoses`, room types, wall/room references) and state flags use AI2-THOR's
names. Problems are data (a typed report), not exceptions.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.scene.procthor import AI2THOR_ROOM_TYPES, ProcthorDB

#: our flag names and legacy spellings that AI2-THOR's house JSON does not read (its
#: `HouseObject` has `openness`, `isOn`, `isDirty`)
_FOREIGN_STATE_KEYS = ("isToggled", "toggled_on", "open", "dirty", "isOpen")
_REQUIRED = {
    "room": ("id", "roomType", "floorPolygon", "floorMaterial"),
    "wall": ("id", "roomId", "polygon", "material"),
    "door": ("id", "assetId", "room0", "room1", "wall0", "wall1", "holePolygon", "assetPosition",
             "openness"),
    "window": ("id", "assetId", "room0", "room1", "wall0", "wall1", "holePolygon", "assetPosition"),
    "object": ("id", "assetId", "objectType", "position", "rotation", "kinematic"),
}


class HouseProblem(BaseModel):
    model_config = ConfigDict(frozen=True)
    where: str  # JSON path, e.g. objects[3].children[0].assetId
    message: str


class HouseReport(BaseModel):
    model_config = ConfigDict(frozen=True)
    against: str  # which database was used
    problems: list[HouseProblem] = Field(default_factory=list)
    assets: int = 0  # asset ids checked (objects, doors, windows)
    unknown_ids: int = 0
    unknown_materials: int = 0

    @property
    def passed(self) -> bool:
        return not self.problems


def _objects(objs: list[Any], where: str) -> Iterator[tuple[str, dict[str, Any]]]:
    for i, o in enumerate(objs):
        here = f"{where}[{i}]"
        if isinstance(o, dict):
            yield here, o
            yield from _objects(o.get("children") or [], f"{here}.children")


def check_house(house: Any, db: ProcthorDB) -> HouseReport:
    """Every problem that would stop AI2-THOR from loading `house` as its ProcTHOR layout says."""
    problems: list[HouseProblem] = []
    counts = {"assets": 0, "unknown_ids": 0, "unknown_materials": 0}

    def bad(where: str, message: str) -> None:
        problems.append(HouseProblem(where=where, message=message))

    if not isinstance(house, dict):
        bad("$", "a house is a JSON object")
        return HouseReport(against=db.source, problems=problems)

    def items(key: str) -> list[tuple[str, dict[str, Any]]]:
        value = house.get(key)
        if not isinstance(value, list):
            bad(key, f"missing list {key!r}")
            return []
        return [(f"{key}[{i}]", v) for i, v in enumerate(value) if isinstance(v, dict)]

    def need(kind: str, where: str, entry: dict[str, Any]) -> None:
        for k in _REQUIRED[kind]:
            if k not in entry:
                bad(f"{where}.{k}", f"{kind} without {k!r}")

    def material(where: str, value: Any) -> None:
        name = value.get("name") if isinstance(value, dict) else value
        if name not in db.materials:
            counts["unknown_materials"] += 1
            bad(where, f"material {name!r} is not in the ProcTHOR material database")

    def asset(where: str, entry: dict[str, Any], hole: bool) -> None:
        aid = entry.get("assetId")
        counts["assets"] += 1
        known = db.assets.get(str(aid))
        if known is None:
            counts["unknown_ids"] += 1
            bad(f"{where}.assetId", f"{aid!r} is not a ProcTHOR asset id")
            return
        if "objectType" in entry and entry["objectType"] != known.object_type:
            bad(f"{where}.objectType", f"{aid} is a {known.object_type}, not {entry['objectType']}")
        if hole and str(aid).replace("Doorframe", "Doorway") not in db.holes:
            counts["unknown_ids"] += 1
            bad(f"{where}.assetId", f"{aid!r} has no ProcTHOR wall hole")

    meta = house.get("metadata")
    if not isinstance(meta, dict) or not isinstance(meta.get("agentPoses"), dict):
        bad("metadata.agentPoses", "missing the agent's starting poses")
    elif not all(isinstance(p, dict) and "position" in p for p in meta["agentPoses"].values()):
        bad("metadata.agentPoses", "every pose needs a position")
    room_ids = set()
    for where, r in items("rooms"):
        need("room", where, r)
        room_ids.add(r.get("id"))
        if r.get("roomType") not in AI2THOR_ROOM_TYPES:
            bad(f"{where}.roomType", f"{r.get('roomType')!r} is not one of {AI2THOR_ROOM_TYPES}")
        if "floorMaterial" in r:
            material(f"{where}.floorMaterial", r["floorMaterial"])
    wall_ids = set()
    for where, w in items("walls"):
        need("wall", where, w)
        wall_ids.add(w.get("id"))
        if "material" in w:
            material(f"{where}.material", w["material"])
        if w.get("roomId") not in room_ids and w.get("roomId") != "exterior":
            bad(f"{where}.roomId", f"{w.get('roomId')!r} is not a room")
    ceiling = (house.get("proceduralParameters") or {}).get("ceilingMaterial")
    if ceiling is not None:
        material("proceduralParameters.ceilingMaterial", ceiling)
    for kind in ("door", "window"):
        for where, d in items(f"{kind}s"):
            need(kind, where, d)
            asset(where, d, hole=True)
            for k in ("wall0", "wall1"):
                if k in d and d[k] not in wall_ids:
                    bad(f"{where}.{k}", f"{d[k]!r} is not a wall")
            for k in ("room0", "room1"):
                if k in d and d[k] not in room_ids:
                    bad(f"{where}.{k}", f"{d[k]!r} is not a room")
    if not isinstance(house.get("objects"), list):
        bad("objects", "missing list 'objects'")
    for where, o in _objects(house.get("objects") or [], "objects"):
        need("object", where, o)
        asset(where, o, hole=False)
        if "room" in o and o["room"] not in room_ids:
            bad(f"{where}.room", f"{o['room']!r} is not a room")
        for k in _FOREIGN_STATE_KEYS:
            if k in o:
                bad(f"{where}.{k}", f"AI2-THOR does not read {k!r} (isOn, isDirty, openness)")
    return HouseReport(against=db.source, problems=problems, **counts)
