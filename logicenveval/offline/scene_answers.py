"""Offline answers to LogicEnvGen's environment-construction request kinds.

Like an LLM, they see only the payload: the brief, the rooms, the situation facts and the
task objects the generator has already realised; they answer with household conventions (room
sizes by type, furniture typical of each room type from the catalog, relations such as "a
sofa against a wall", "a chair near its table").
"""

from __future__ import annotations

import hashlib
import math
import re
from typing import Any

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.llm.base import ChatRequest
from logicenveval.model.rooms import room_type_of
from logicenveval.offline.handlers import handler
from logicenveval.offline.keyed import keyed, keyed_selection
from logicenveval.offline.placement import described_placements
from logicenveval.offline.realise import task_objects
from logicenveval.scene.compat import can_hold

#: typical floor area (m²) per room type
AREA = {"LivingRoom": 22.0, "Kitchen": 13.0, "Bedroom": 15.0, "Bathroom": 7.0, "Study": 11.0,
        "Hallway": 9.0, "LaundryRoom": 8.0, "DiningRoom": 15.0, "KidsRoom": 13.0, "Garage": 20.0,
        "Balcony": 6.0, "Office": 12.0, "Pantry": 5.0, "Entryway": 7.0}
#: pairs that usually stand together (object category, anchor category)
COMPANIONS = {"dining_chair": "dining_table", "office_chair": "desk", "nightstand": "bed",
              "armchair": "coffee_table", "ottoman": "sofa", "bar_stool": "kitchen_island",
              "stool": "kitchen_counter", "side_table": "sofa", "tv_stand": "sofa",
              "changing_table": "crib", "dryer": "washing_machine"}
WALLS = ("n", "e", "s", "w")


def _stable(*parts: object) -> int:
    return int.from_bytes(hashlib.sha256("\0".join(map(str, parts)).encode()).digest()[:4], "little")


@handler("floor_plan")
def floor_plan(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """Rooms of the brief with typical areas, larger where the task's objects need it (`room_areas`);
    hallway-centred adjacency when there is a hallway."""
    rooms = list(payload["task"]["rooms"])
    types = {r: room_type_of(r) for r in rooms}
    areas = room_areas(payload["task"], load_catalog())
    hub = next((r for r in rooms if types[r] in ("Hallway", "Entryway")), rooms[0])
    out = []
    for i, r in enumerate(rooms):
        if len(rooms) == 1:
            adjacent: list[str] = []
        elif hub != rooms[0] or types[hub] in ("Hallway", "Entryway"):
            adjacent = [x for x in rooms if x != r] if r == hub else [hub]
        else:
            adjacent = [x for x in (rooms[i - 1] if i else None, rooms[i + 1] if i + 1 < len(rooms) else None) if x]
        doors = [{"to": other, "type": "door", "width": 0.9, "state": "open"} for other in adjacent
                 if rooms.index(other) > i]
        if r == hub:
            doors.append({"to": "exterior", "type": "door", "width": 0.95, "state": "closed"})
        out.append({
            "id": r, "type": types[r], "area_m2": areas[r], "adjacent_to": adjacent,
            "doors": doors,
            "windows": [] if types[r] in ("Hallway", "Pantry") else [
                {"wall": WALLS[_stable(payload["task"]["id"], r) % 4], "width": 1.2, "height": 1.2,
                 "sill": 0.9, "state": "closed"}],
            "floor_material": "tiles" if types[r] in ("Bathroom", "Kitchen", "LaundryRoom") else "wood",
            "wall_color": "white",
        })
    return {"rooms": out}


#: a room's floor area per square metre of furniture footprint; metres of wall per metre of
#: wall-mounted objects (doors and windows need their share)
FLOOR_PER_FOOTPRINT, WALL_PER_WIDTH, OPENINGS_M = 3.0, 2.0, 2.0


def room_areas(task: dict[str, Any], catalog: Catalog) -> dict[str, float]:
    """Whole square metres per room: the typical area of its type, or more when the task's objects
    that belong there (at their largest catalog sizes) need more floor or wall (a designer who has
    read the task sizes the rooms for what they must hold)."""
    floor, wall, taken = _needs(task, catalog)
    out = {}
    for r in task["rooms"]:
        need = max(FLOOR_PER_FOOTPRINT * floor[r], (taken[r] / 4) ** 2)
        out[r] = float(min(80, max(AREA.get(room_type_of(r), 12.0), math.ceil(need))))
    return out


def _needs(task: dict[str, Any], catalog: Catalog) -> tuple[dict[str, float], dict[str, float], dict[str, float]]:
    """Per room, what the task's furniture needs at its largest catalog sizes: the floor it covers
    (m²), the width of its wall-mounted objects (m) and the metres of wall it takes (twice the
    wall-mounted objects' and the openings' widths, plus the floor furniture against the walls)."""
    rooms = list(task["rooms"])
    floor = dict.fromkeys(rooms, 0.0)
    along = dict.fromkeys(rooms, 0.0)  # metres of wall the floor furniture stands against
    wall = dict.fromkeys(rooms, 0.0)
    for role in dict(task.get("roles") or {}).values():
        cat = catalog.get(role["category"])
        if cat is None or cat.pickable:
            continue
        room = next((r for r in rooms if room_type_of(r) in cat.rooms), rooms[0])
        if cat.placement[0] == "floor":
            floor[room] += cat.size_max[0] * cat.size_max[2]
            along[room] += cat.size_max[0]
        elif cat.placement[0] == "wall":
            wall[room] += cat.size_max[0]
    return floor, wall, {r: WALL_PER_WIDTH * (wall[r] + OPENINGS_M) + along[r] for r in rooms}


_TOO_BIG = re.compile(r"(\w+) \(\w+\) is larger than the top of (\w+)")
_NO_FIT = re.compile(r"the objects \[([^\]]*)\] do not fit (inside|on) (\w+)")


def feedback_facts(feedback: list[str], facts: list[str]) -> list[str]:
    """Placements the layout rejected, as facts that rule them out (unless the situation needs them)."""
    required = set(facts)
    out: list[str] = []
    for text in feedback:
        for obj, holder in _TOO_BIG.findall(text):
            out.append(f"not on({obj}, {holder})")
        for listed, how, holder in _NO_FIT.findall(text):
            names = [n.strip(" '\"") for n in listed.split(",")]
            pred = "inside" if how == "inside" else "on"
            out += [f"not {pred}({n}, {holder})" for n in names[1:]]
    return [f for f in out if f[4:] not in required]


def _task_objects(payload: dict[str, Any]) -> list[dict[str, Any]]:
    """One object per role, placed so that the situation facts (and the layout's feedback) hold
    and every object fits where it is put (the asset sizes, as a model that knows them would).
    A placement the situation requires or the description states ("the cloth lives in the
    vanity") is kept even when the estimate finds the holder crowded: the reader was told so."""
    catalog = load_catalog()
    facts = list(payload.get("facts") or [])
    facts += feedback_facts(list(payload.get("feedback") or []), facts)
    told = set(facts) | set(described_placements(payload["task"], catalog))
    banned: list[str] = []
    objects = task_objects(payload["task"], facts, catalog)
    for _ in range(len(objects)):
        new = [f for f in misfits(objects, catalog, frozenset(told)) if f not in banned and f[4:] not in told]
        if not new:
            break
        banned += new
        objects = task_objects(payload["task"], facts + banned, catalog)
    return objects


#: layout grid (m) and the share of a holder's smallest top that its items may fill together
GRID, FILL = 0.05, 0.8


def misfits(objects: list[dict[str, Any]], catalog: Catalog, told: frozenset[str] = frozenset()) -> list[str]:
    """Placements that cannot be laid out, as facts that rule them out: an item larger than its
    holder's largest top (or opening), or the items on one holder (or inside it: the layout packs
    the two apart), at the largest size the layout may draw for each, too many for its smallest top
    (the last listed goes elsewhere). An item `told` there (the situation needs it, the text states
    it: "the cardboard box is on the stool") that may fill the holder's top alone, even with the
    holder drawn at its largest, leaves room for nothing else: every other item there goes
    elsewhere, wherever it was listed (a towel stated on a shelving unit, which it never fills,
    moves nothing: the layout finds room beside it)."""
    by_id = {o["id"]: o for o in objects}
    out: list[str] = []
    #: filled cells per (holder, on|inside): the layout packs a holder's top and inside apart
    load: dict[tuple[str, str], float] = {}
    full: set[tuple[str, str]] = set()  # holders a told item fills alone
    for o in objects:
        how, _, holder = str(o["placement"]).partition(":")
        if how not in ("on", "inside") or holder not in by_id:
            continue
        item, host = catalog.get(o["category"]), catalog.get(by_id[holder]["category"])
        if item is None or host is None:
            continue
        pred = f"not {how}({o['id']}, {holder})"
        if not can_hold(item, host, how):
            # the layout's own test (`scene.compat`): the item's footprint against the holder's top
            # or opening, and on a top its volume too ("the broom on the coat hook": a broom's
            # footprint is narrow, but it is far bigger than a hook)
            out.append(pred)
            continue
        # the layout draws an item's size up to its holder's top, whatever else stands there
        top = [max(host.size_min[k], item.size_min[k]) for k in (0, 2)]
        cells = math.prod(math.ceil(min(item.size_max[k], t) / GRID) for k, t in zip((0, 2), top, strict=True))
        room = math.prod(math.floor(t / GRID) for t in top)
        if pred[4:] in told and math.prod(math.ceil(min(item.size_max[k], host.size_max[k]) / GRID) for k in (0, 2)) \
                > FILL * math.prod(math.floor(host.size_max[k] / GRID) for k in (0, 2)):
            full.add((holder, how))  # the item at its largest fills the holder even at the holder's largest
        if load.get((holder, how), 0.0) + cells > FILL * room and load.get((holder, how)):
            out.append(pred)
            continue
        load[(holder, how)] = load.get((holder, how), 0.0) + cells
    for o in objects:
        how, _, holder = str(o["placement"]).partition(":")
        pred = f"not {how}({o['id']}, {holder})"
        if (holder, how) in full and pred[4:] not in told and pred not in out:
            out.append(pred)
    return out


@handler("select_objects")
def select_objects(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """The task objects placed as the situation requires, plus furniture typical of each room."""
    catalog = load_catalog()
    objects = _task_objects(payload)
    used = {o["category"] for o in objects}
    _, hung, taken = _needs(payload["task"], catalog)
    for room in payload["rooms"]:
        rtype, area = room["type"], float(room.get("area_m2", 12.0))
        floor_like = sorted(
            name for name, c in catalog.categories.items()
            if rtype in c.rooms and c.placement[0] == "floor" and not c.pickable and name not in used
            and not c.default_states.get("dirty", False) and c.size_min[0] * c.size_min[2] < area / 8
        )
        wall_like = sorted(name for name, c in catalog.categories.items()
                           if rtype in c.rooms and c.placement[0] == "wall" and name not in used)
        n_floor = 1 if area < 10 else 2
        start = _stable(payload["task"]["id"], room["id"], request.seed)
        picks = [floor_like[(start + k * 7) % len(floor_like)] for k in range(min(n_floor, len(floor_like)))]
        if wall_like:
            picks.append(wall_like[start % len(wall_like)])
        if hung.get(room["id"]):
            picks = _spared(picks, 4 * math.sqrt(area) - taken[room["id"]], catalog)
        for k, cat in enumerate(dict.fromkeys(picks)):
            objects.append({
                "id": f"{cat}_{room['id']}_{k}", "category": cat, "room": room["id"], "role": None,
                "placement": catalog.categories[cat].placement[0], "attributes": {}, "states": {},
                "description": f"a {cat.replace('_', ' ')} typical of a {rtype}",
            })
    return keyed_selection(objects) if keyed(request) else {"objects": objects}


def _spared(picks: list[str], spare: float, catalog: Catalog) -> list[str]:
    """The added furniture of a room where a task object hangs on a wall, as far as the wall the
    task's own objects leave (`_needs`) allows: floor furniture stands against a wall and a wall
    object takes twice its width, while the layout can drop neither for a curtain or a mirror of
    the task that finds no free wall (a crib, a changing table, a dresser and a curtain fill a
    nursery's walls; a nightstand and a desk added beside them left the curtain no room)."""
    out = []
    for name in picks:
        cat = catalog.categories[name]
        cost = cat.size_max[0] * (WALL_PER_WIDTH if cat.placement[0] == "wall" else 1.0)
        if cost <= spare:
            out.append(name)
            spare -= cost
    return out


@handler("spatial_relations")
def spatial_relations(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """Household conventions: big furniture against walls, companions near their anchor."""
    catalog = load_catalog()
    objects = payload["objects"]
    by_cat: dict[str, list[dict[str, Any]]] = {}
    for o in objects:
        by_cat.setdefault(o["category"], []).append(o)
    relations = []
    for o in objects:
        cat = catalog.get(o["category"])
        if cat is None:
            continue
        if o["placement"] == "wall":
            relations.append({"type": "wall_mounted", "args": [o["id"]]})
        elif o["placement"] == "floor" and not cat.pickable and max(cat.size_min[0], cat.size_min[2]) >= 0.6:
            relations.append({"type": "edge", "args": [o["id"]]})
        anchor = COMPANIONS.get(o["category"])
        if anchor and o["placement"] == "floor":
            partner = next((p for p in by_cat.get(anchor, []) if p["room"] == o["room"]), None)
            if partner is not None:
                relations.append({"type": "near", "args": [o["id"], partner["id"]]})
    return {"relations": relations}


@handler("refine_relations")
def refine_relations(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """Drop the relations the compatibility checker named, keep the rest."""
    bad = {tuple(r["args"]) + (r["type"],) for r in payload.get("rejected") or []}
    return {"relations": [r for r in spatial_relations(payload, request)["relations"]
                          if tuple(r["args"]) + (r["type"],) not in bad]}


@handler("place_objects")
def place_objects(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """Coordinates written down without a solver (the no-CAS ablation), room by room.

    Uses the same guessing heuristic as the CoT/IFG offline handlers: furniture along the walls,
    items on their support's top; nothing checks collisions — the physics checker judges it.
    """
    from logicenveval.scene.guessed_layout import guess_coordinates

    catalog = load_catalog()
    dims: dict[str, tuple[float, float]] = {}
    origin: dict[str, tuple[float, float]] = {}
    for room in payload["rooms"]:
        xs = [p[0] for p in room["polygon"]]
        zs = [p[1] for p in room["polygon"]]
        origin[room["id"]] = (min(xs), min(zs))
        dims[room["id"]] = (max(xs) - min(xs), max(zs) - min(zs))
    placed = guess_coordinates([dict(o) for o in payload["objects"]], dims, catalog)
    for o in placed:
        ox, oz = origin.get(o["room"], (0.0, 0.0))
        x, y, z = o["position"]
        o["position"] = (round(x + ox, 3), round(y, 3), round(z + oz, 3))
    return {"objects": placed, "relations": list(payload.get("relations") or []),
            "openings": spread_openings(payload.get("openings") or [])}


def spread_openings(openings: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Doors and windows where a writer without a solver puts them: the k openings of one wall
    stretch centred at 1/(k+1), 2/(k+1), ... of it (no check that they keep apart)."""
    by_wall: dict[tuple[float, ...], list[dict[str, Any]]] = {}
    for op in openings:
        by_wall.setdefault((*op["wall_from"], *op["wall_to"]), []).append(op)
    out = []
    for (ax, az, bx, bz), ops in by_wall.items():
        length = max(abs(bx - ax), abs(bz - az))
        ux, uz = (bx - ax) / length, (bz - az) / length
        for i, op in enumerate(ops):
            mid = length * (i + 1) / (len(ops) + 1)
            ends = [(round(ax + ux * t, 2), round(az + uz * t, 2)) for t in (mid - op["width"] / 2,
                                                                         mid + op["width"] / 2)]
            out.append({"id": op["id"], "segment": ends})
    return out
