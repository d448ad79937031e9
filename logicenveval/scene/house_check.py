"""Will AI2-THOR load this house? `check_house` verifies a ProcTHOR house JSON against ProcTHOR's
databases (or our recorded mapping): every object `assetId` is a real asset (of its `objectType`
when the house names one — ProcTHOR-10K houses do not), every door/window asset has a wall hole,
every material exists, the keys AI2-THOR reads are there (`metadata.agentPoses`, room types,
wall/room references, unique room and object ids), every number is finite, and state flags use AI2-THOR's
names. Problems are data (a typed report), not exceptions; a value of the wrong JSON type is a
problem at its path.

Against our mapping (no `--procthor-db`) an asset id the mapping does not hold is a *warning*:
the mapping only knows the ids our exporter chooses, so it cannot say the id is not ProcTHOR's.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.scene.house_import import show
from logicenveval.scene.procthor import AI2THOR_ROOM_TYPES, ProcthorDB

#: our flag names and legacy spellings that AI2-THOR's house JSON does not read (its
#: `HouseObject` has `openness`, `isOn`, `isDirty`)
_FOREIGN_STATE_KEYS = ("isToggled", "toggled_on", "open", "dirty", "isOpen")
_REQUIRED = {
    "room": ("id", "roomType", "floorPolygon", "floorMaterial"),
    "wall": ("id", "roomId", "polygon", "material"),
    "door": ("id", "assetId", "room0", "room1", "wall0", "wall1", "holePolygon", "assetPosition"),
    "window": ("id", "assetId", "room0", "room1", "wall0", "wall1", "holePolygon", "assetPosition"),
    "object": ("id", "assetId", "position", "rotation", "kinematic"),
}


class HouseProblem(BaseModel):
    model_config = ConfigDict(frozen=True)
    where: str  # JSON path, e.g. objects[3].children[0].assetId
    message: str


class HouseReport(BaseModel):
    model_config = ConfigDict(frozen=True)
    against: str  # which database was used
    problems: list[HouseProblem] = Field(default_factory=list)
    #: what the database used cannot decide (asset ids our mapping does not hold)
    warnings: list[HouseProblem] = Field(default_factory=list)
    assets: int = 0  # asset ids checked (objects, doors, windows)
    unknown_ids: int = 0
    unknown_materials: int = 0

    @property
    def passed(self) -> bool:
        return not self.problems


def _objects(objs: Any, where: str) -> Iterator[tuple[str, dict[str, Any]]]:
    """Every object and child with its JSON path, depth first in file order (any depth)."""
    stack = [(f"{where}[{i}]", o) for i, o in enumerate(objs)][::-1] if isinstance(objs, list) else []
    while stack:
        here, o = stack.pop()
        if not isinstance(o, dict):
            continue
        yield here, o
        kids = o.get("children")
        if isinstance(kids, list):
            stack += [(f"{here}.children[{j}]", c) for j, c in enumerate(kids)][::-1]


#: bits of the largest integer a house may hold (2**63: ids, counts; coordinates are far smaller)
MAX_INT_BITS = 63


def _non_finite(data: Any) -> Iterator[str]:
    """JSON paths of NaN and infinite numbers (AI2-THOR cannot place them; JSON has no NaN), and
    of integers too large for a float (JSON allows 400 digits; no coordinate is that large)."""
    stack: list[tuple[Any, str]] = [(data, "")]
    while stack:
        value, here = stack.pop()
        if (isinstance(value, float) and not math.isfinite(value)) or \
                (isinstance(value, int) and value.bit_length() > MAX_INT_BITS):
            yield here or "$"
        elif isinstance(value, dict):
            stack += [(v, f"{here}.{k}" if here else str(k)) for k, v in value.items()]
        elif isinstance(value, list):
            stack += [(v, f"{here}[{i}]") for i, v in enumerate(value)]


def _key(value: Any) -> str | None:
    """A reference as a dictionary key; None when it is not a string or number."""
    return str(value) if isinstance(value, str | int) and not isinstance(value, bool) else None


def check_house(house: Any, db: ProcthorDB, *, authoritative: bool = True) -> HouseReport:
    """Every problem that would stop AI2-THOR from loading `house` as its ProcTHOR layout says.

    `authoritative`: `db` is ProcTHOR's own database, so an asset id it lacks is a problem;
    otherwise (our mapping) it is a warning naming the mapping.
    """
    problems: list[HouseProblem] = []
    warnings: list[HouseProblem] = []
    counts = {"assets": 0, "unknown_ids": 0, "unknown_materials": 0}

    def bad(where: str, message: str) -> None:
        problems.append(HouseProblem(where=where, message=message))

    if not isinstance(house, dict):
        bad("$", "a house is a JSON object")
        return HouseReport(against=db.source, problems=problems)

    def items(key: str) -> list[tuple[str, dict[str, Any]]]:
        value = house.get(key)
        if not isinstance(value, list):
            bad(key, f"missing list {key!r}" if value is None else f"{key!r} is not a list")
            return []
        out = []
        for i, v in enumerate(value):
            if isinstance(v, dict):
                out.append((f"{key}[{i}]", v))
            else:
                bad(f"{key}[{i}]", f"expected an object, got {show(v)}")
        return out

    def unsure(where: str, what: str) -> None:
        warnings.append(HouseProblem(where=where, message=(
            f"{what} is not in {db.source}, which holds only the ids our exporter uses; "
            "check it against ProcTHOR's databases with --procthor-db")))

    def need(kind: str, where: str, entry: dict[str, Any]) -> None:
        for k in _REQUIRED[kind]:
            if k not in entry:
                bad(f"{where}.{k}", f"{kind} without {k!r}")

    def material(where: str, value: Any) -> None:
        name = value.get("name") if isinstance(value, dict) else value
        if not isinstance(name, str):
            bad(where, f"a material is {{\"name\": ...}} or a name, not {show(value)}")
        elif name not in db.materials:
            counts["unknown_materials"] += 1
            if authoritative:
                bad(where, f"material {show(name)} is not in the ProcTHOR material database")
            else:
                unsure(where, f"material {show(name)}")

    def asset(where: str, entry: dict[str, Any], hole: bool) -> None:
        aid = entry.get("assetId")
        if "assetId" not in entry:
            return  # reported by need()
        counts["assets"] += 1
        known = db.assets.get(aid) if isinstance(aid, str) else None
        if known is None:
            counts["unknown_ids"] += 1
            if not isinstance(aid, str):
                bad(f"{where}.assetId", f"an asset id is a string, not {show(aid)}")
            elif authoritative:
                bad(f"{where}.assetId", f"{show(aid)} is not a ProcTHOR asset id")
            else:
                unsure(f"{where}.assetId", f"asset id {show(aid)}")
            return
        otype = entry.get("objectType")
        if otype is not None and otype != known.object_type:
            bad(f"{where}.objectType", f"{aid} is a {known.object_type}, not {show(otype)}")
        if hole and known.asset_id.replace("Doorframe", "Doorway") not in db.holes:
            counts["unknown_ids"] += 1
            bad(f"{where}.assetId", f"{show(aid)} has no ProcTHOR wall hole")

    def refer(where: str, value: Any, known: set[str], what: str, extra: tuple[str, ...] = ()) -> None:
        key = _key(value)
        if key is None:
            bad(where, f"a {what} reference is a string, not {show(value)}")
        elif key not in known and key not in extra:
            bad(where, f"{show(value)} is not a {what}")

    meta = house.get("metadata")
    poses = meta.get("agentPoses") if isinstance(meta, dict) else None
    if not isinstance(poses, dict):
        bad("metadata.agentPoses", "missing the agent's starting poses")
    elif not all(isinstance(p, dict) and "position" in p for p in poses.values()):
        bad("metadata.agentPoses", "every pose needs a position")
    room_ids: dict[str, str] = {}
    for where, r in items("rooms"):
        need("room", where, r)
        rid = _key(r.get("id"))
        if "id" in r and rid is None:
            bad(f"{where}.id", f"a room id is a string, not {show(r.get('id'))}")
        elif rid is not None and rid in room_ids:
            bad(f"{where}.id", f"room id {show(rid)} is used twice ({room_ids[rid]} and {where})")
        elif rid is not None:
            room_ids[rid] = where
        if r.get("roomType") not in AI2THOR_ROOM_TYPES:
            bad(f"{where}.roomType", f"{show(r.get('roomType'))} is not one of {AI2THOR_ROOM_TYPES}")
        if "floorMaterial" in r:
            material(f"{where}.floorMaterial", r["floorMaterial"])
    rooms = set(room_ids)
    wall_ids: set[str] = set()
    for where, w in items("walls"):
        need("wall", where, w)
        wid = _key(w.get("id"))
        if wid is not None:
            wall_ids.add(wid)
        elif "id" in w:
            bad(f"{where}.id", f"a wall id is a string, not {show(w.get('id'))}")
        if "material" in w:
            material(f"{where}.material", w["material"])
        if "roomId" in w:
            refer(f"{where}.roomId", w["roomId"], rooms, "room", ("exterior",))
    params = house.get("proceduralParameters")
    if params is not None and not isinstance(params, dict):
        bad("proceduralParameters", f"expected an object, got {show(params)}")
    elif params is not None and params.get("ceilingMaterial") is not None:
        material("proceduralParameters.ceilingMaterial", params["ceilingMaterial"])
    for kind in ("door", "window"):
        for where, d in items(f"{kind}s"):
            need(kind, where, d)
            asset(where, d, hole=True)
            for k in ("wall0", "wall1"):
                if k in d:
                    refer(f"{where}.{k}", d[k], wall_ids, "wall")
            for k in ("room0", "room1"):
                if k in d:
                    refer(f"{where}.{k}", d[k], rooms, "room")
    if not isinstance(house.get("objects"), list):
        bad("objects", "missing list 'objects'")
    object_ids: dict[str, str] = {}
    for where, o in _objects(house.get("objects"), "objects"):
        need("object", where, o)
        oid = _key(o.get("id"))
        if oid is not None and oid in object_ids:
            bad(f"{where}.id", f"object id {show(oid)} is used twice ({object_ids[oid]} and {where})")
        elif oid is not None:
            object_ids[oid] = where
        asset(where, o, hole=False)
        if "room" in o:
            refer(f"{where}.room", o["room"], rooms, "room")
        for k in _FOREIGN_STATE_KEYS:
            if k in o:
                bad(f"{where}.{k}", f"AI2-THOR does not read {k!r} (isOn, isDirty, openness)")
    for where in sorted(_non_finite(house))[:50]:
        bad(where, "not a finite number (AI2-THOR cannot place NaN, infinity or a number of "
            "hundreds of digits)")
    return HouseReport(against=db.source, problems=problems, warnings=warnings, **counts)
