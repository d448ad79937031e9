"""Offline answers to the baselines' request kinds, from the payload alone (never ground truth).

Each handler implements its baseline's *strategy* with the same analyser the LogicEnvGen
handlers use:
- `cot_environments`: a flat reading of the description — a baseline situation (every factor at
  its first value, the case the text describes first) plus, for each factor, each other value
  one at a time, with no decision-tree nesting; the floor plan from `written_floor_plan` (the
  writer's own coarse geometry), object coordinates from `scene.guessed_layout`.
- `ifg_intents`: k intents sampled with `default_rng(request.seed)`, each factor's value drawn
  from a softmax over a prior that prefers the first-described value, sharpened by 1/temperature.
- `ifg_intent` (protocol 5): one such intent under the request's own seed, as literals.
- `ifg_environment`: one environment realising the intent, the same floor plan rule, coordinates
  from `scene.guessed_layout` with a temperature-scaled, seeded wall gap.
- `holodeck_scene`: the default room of the description — every role object in its typical
  place, plus furniture typical of each room type (catalog `rooms`), and spatial relations.
"""

from __future__ import annotations

import hashlib
from typing import Any

import numpy as np

from logicenveval.baselines.geometry import room_dims
from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.structured import literals_of
from logicenveval.model.rooms import room_type_of
from logicenveval.offline.analysis import Factor, analyse
from logicenveval.offline.handlers import handler
from logicenveval.offline.keyed import keyed, keyed_selection
from logicenveval.offline.realise import task_objects
from logicenveval.offline.scene_answers import AREA
from logicenveval.scene.guessed_layout import guess_coordinates

# (`AREA`, the typical floor area per room type, is the scene answers' table: one for both)
#: pairs that usually stand together (object category, anchor category)
COMPANIONS = {"dining_chair": "dining_table", "office_chair": "desk", "nightstand": "bed",
              "armchair": "coffee_table", "ottoman": "sofa", "bar_stool": "kitchen_island",
              "side_table": "sofa", "tv_stand": "sofa", "dryer": "washing_machine"}
#: the prior preference (logit) of a factor's first-described value over the others
FIRST_VALUE_LOGIT = 1.0


def _stable(*parts: object) -> int:
    return int.from_bytes(hashlib.sha256("\0".join(map(str, parts)).encode()).digest()[:4], "little")


def default_rooms(task: dict[str, Any]) -> list[dict[str, Any]]:
    """The brief's rooms in order, typical areas, a door between consecutive rooms, an exterior
    door in the first room and a window on the north wall of each room but hallways."""
    rooms = list(task["rooms"])
    out = []
    for i, r in enumerate(rooms):
        rtype = room_type_of(r)
        doors = [{"to": "exterior", "type": "door", "width": 0.9, "state": "closed"}] if i == 0 else []
        if i + 1 < len(rooms):
            doors.append({"to": rooms[i + 1], "type": "door", "width": 0.9, "state": "open"})
        out.append({"id": r, "type": rtype, "area_m2": AREA.get(rtype, 12.0),
                    "adjacent_to": [x for x in rooms[max(i - 1, 0):i + 2] if x != r], "doors": doors,
                    "windows": [] if rtype in ("Hallway", "Pantry", "Entryway") else
                    [{"wall": "n", "width": 1.2, "height": 1.2, "sill": 0.9, "state": "closed"}]})
    return out


def flat_situations(factors: list[Factor]) -> list[tuple[str, list[str]]]:
    """(description, facts) of a flat reading: all factors at their first value, then each other
    value of each factor one at a time."""
    base = {f.id: next(iter(f.values)) for f in factors}
    out = [("the situation as described first: " + ", ".join(f"{k}={v}" for k, v in base.items()),
            [f.values[base[f.id]] for f in factors])]
    for f in factors:
        for value in list(f.values)[1:]:
            facts = [g.values[value] if g.id == f.id else g.values[base[g.id]] for g in factors]
            out.append((f"as described first, but {f.question} -> {value}", facts))
    return out


def value_probabilities(n_values: int, temperature: float) -> np.ndarray:
    """Softmax over the prior logits (first value preferred) at `temperature` (0 = greedy)."""
    logits = np.zeros(n_values)
    logits[0] = FIRST_VALUE_LOGIT
    if temperature <= 0:
        p = np.zeros(n_values)
        p[0] = 1.0
        return p
    z = np.exp((logits - logits.max()) / temperature)
    return np.asarray(z / z.sum())


#: room types a writer thinks of as connecting the others
HUBS = ("Hallway", "Entryway")


def written_floor_plan(task: dict[str, Any]) -> dict[str, list[dict[str, Any]]]:
    """The floor plan a writer without a solver puts down, in coordinates (as the paper's prompts
    have the LLM write vertex coordinates): the task's rooms as rectangles side by side along x in
    the order listed, each of its type's typical area A, `round(sqrt(1.25 A), 1)` wide and
    `round(A / width, 1)` deep; one room is the hub (a hallway or entryway if there is one, else
    the first room) and gets the entrance, centred on its south wall, and a door to every other
    room, centred on the hub's wall that faces that room — the writer connects rooms by what they
    are, not by where it drew them, so a door to a room that is not the hub's neighbour lands on a
    wall the two do not share; a window 1.2 m wide, sill 0.9 m, 1.2 m high, centred on the north
    wall of each room but hallways, pantries and entryways. Returns `rooms`, `doors`, `windows` in
    the `WrittenEnvironment` form."""
    names = list(task["rooms"])
    types = {r: room_type_of(r) for r in names}
    hub = next((r for r in names if types[r] in HUBS), names[0])
    rects: dict[str, tuple[float, float, float]] = {}  # room -> (x0, width, depth)
    x = 0.0
    for r in names:
        w, d = room_dims(AREA.get(types[r], 12.0))
        rects[r] = (round(x, 2), w, d)
        x += w
    hx, hw, hd = rects[hub]
    doors = [{"rooms": [hub, "exterior"], "segment": [[round(hx + hw / 2 - 0.45, 2), 0.0],
                                                      [round(hx + hw / 2 + 0.45, 2), 0.0]],
              "type": "door", "state": "closed"}]
    for r in names:
        if r == hub:
            continue
        wall_x = round(hx + hw, 2) if rects[r][0] > hx else hx
        doors.append({"rooms": [hub, r], "segment": [[wall_x, round(hd / 2 - 0.45, 2)], [wall_x, round(hd / 2 + 0.45, 2)]],
                      "type": "door", "state": "open"})
    windows = [{"room": r, "segment": [[round(x0 + w / 2 - 0.6, 2), d], [round(x0 + w / 2 + 0.6, 2), d]],
                "sill": 0.9, "height": 1.2, "state": "closed"}
               for r, (x0, w, d) in rects.items() if types[r] not in ("Hallway", "Pantry", "Entryway")]
    rooms = [{"id": r, "type": types[r], "polygon": [[x0, 0.0], [round(x0 + w, 2), 0.0], [round(x0 + w, 2), d], [x0, d]]}
             for r, (x0, w, d) in rects.items()]
    return {"rooms": rooms, "doors": doors, "windows": windows}


def door_stretches(plan: dict[str, list[dict[str, Any]]]) -> dict[str, dict[str, list[tuple[float, float]]]]:
    """Room → wall → stretches along the wall (room-relative) in front of a door the plan draws on
    that wall (door width plus its swing), which the writer keeps furniture off."""
    out: dict[str, dict[str, list[tuple[float, float]]]] = {}
    for room in plan["rooms"]:
        (x0, z0), (x1, _), (_, z1) = room["polygon"][0], room["polygon"][1], room["polygon"][2]
        walls = out.setdefault(room["id"], {})
        for d in plan["doors"]:
            (ax, az), (bx, bz) = d["segment"]
            width = max(abs(bx - ax), abs(bz - az))
            if az == bz and az in (z0, z1) and x0 <= min(ax, bx) and max(ax, bx) <= x1:
                wall, lo, hi = ("s" if az == z0 else "n"), min(ax, bx) - x0, max(ax, bx) - x0
            elif ax == bx and ax in (x0, x1) and z0 <= min(az, bz) and max(az, bz) <= z1:
                wall, lo, hi = ("w" if ax == x0 else "e"), min(az, bz) - z0, max(az, bz) - z0
            else:
                continue
            walls.setdefault(wall, []).append((lo - width, hi + width))
    return out


def _environment(task: dict[str, Any], situation: str, facts: list[str], catalog: Catalog,
                 rng: np.random.Generator | None, wall_gap: float) -> dict[str, Any]:
    plan = written_floor_plan(task)
    origin = {r["id"]: tuple(r["polygon"][0]) for r in plan["rooms"]}
    dims = {r["id"]: (r["polygon"][1][0] - r["polygon"][0][0], r["polygon"][2][1] - r["polygon"][0][1])
            for r in plan["rooms"]}
    objects = guess_coordinates(task_objects(task, facts, catalog), dims, catalog, rng=rng, wall_gap=wall_gap,
                                doors=door_stretches(plan))
    for o in objects:  # the writer's room-relative thinking, written in the plan's frame
        (ox, oz), (x, y, z) = origin[o["room"]], o["position"]
        o["position"] = (round(x + ox, 3), y, round(z + oz, 3))
    relations = [{"type": "on" if o["placement"].startswith("on:") else "inside",
                  "args": [o["id"], o["placement"].split(":", 1)[1]]}
                 for o in objects if o["placement"].startswith(("on:", "inside:"))]
    return {"situation": situation, **plan, "objects": [dict(o) for o in objects], "relations": relations}


@handler("cot_environments")
def cot_environments(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    catalog = load_catalog()
    task = payload["task"]
    factors = analyse(task, catalog).factors
    situations = flat_situations(factors)[: max(1, int(payload.get("n_environments") or 12))]
    reasoning = ("Uncertain factors: " + "; ".join(f"{f.question} ({'/'.join(f.values)})" for f in factors)
                 + ". One environment for the described case and one per alternative answer.")
    return {"reasoning": reasoning,
            "environments": [_environment(task, s, facts, catalog, None, 0.05) for s, facts in situations]}


@handler("ifg_intents")
def ifg_intents(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    catalog = load_catalog()
    factors = analyse(payload["task"], catalog).factors
    rng = np.random.default_rng(request.seed or 0)
    intents = []
    for _ in range(max(1, int(payload["k"]))):
        picks = {f.id: list(f.values)[int(rng.choice(len(f.values), p=value_probabilities(len(f.values),
                                                                                            request.temperature)))]
                 for f in factors}
        intents.append({"description": ", ".join(f"{k}={v}" for k, v in picks.items()) or "the described room",
                        "facts": [f.values[picks[f.id]] for f in factors]})
    return {"trajectories": intents}


@handler("ifg_intent")
def ifg_intent(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """One intent (protocol 5): the `ifg_intents` draw with k = 1 under this request's own
    seed, its facts as structured literals."""
    intent = ifg_intents({**payload, "k": 1}, request)["trajectories"][0]
    return {"description": intent["description"][:300],
            "facts": [lit for fact in intent["facts"] for lit in literals_of(fact)]}


@handler("ifg_environment")
def ifg_environment(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    catalog = load_catalog()
    rng = np.random.default_rng(request.seed or 0)
    env = _environment(payload["task"], "; ".join(payload["intent"]), list(payload["intent"]), catalog,
                       rng, 0.5 * request.temperature)
    return {"reasoning": "", "environments": [env]}


@handler("holodeck_scene")
def holodeck_scene(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    catalog = load_catalog()
    task = payload["task"]
    rooms = default_rooms(task)
    objects = task_objects(task, [], catalog)
    used = {o["category"] for o in objects}
    for room in rooms:
        rtype = room["type"]
        floor_like = sorted(n for n, c in catalog.categories.items()
                            if rtype in c.rooms and c.placement[0] == "floor" and not c.pickable and n not in used
                            and not c.default_states.get("dirty", False)
                            and c.size_min[0] * c.size_min[2] < room["area_m2"] / 8)
        wall_like = sorted(n for n, c in catalog.categories.items()
                           if rtype in c.rooms and c.placement[0] == "wall" and n not in used)
        start = _stable(task["id"], room["id"])
        picks = [floor_like[(start + 7 * k) % len(floor_like)] for k in range(min(3, len(floor_like)))]
        picks += [wall_like[start % len(wall_like)]] if wall_like else []
        for k, cat in enumerate(dict.fromkeys(picks)):
            objects.append({"id": f"{cat}_{room['id']}_{k}", "category": cat, "room": room["id"], "role": None,
                            "placement": catalog.categories[cat].placement[0], "attributes": {},
                            "states": dict(catalog.categories[cat].default_states)})
    relations = _relations(objects, catalog)
    if keyed(request):  # protocol 3: the same objects, keyed by role
        return {"rooms": rooms, **keyed_selection(objects), "relations": relations}
    return {"rooms": rooms, "objects": objects, "relations": relations}


def _relations(objects: list[dict[str, Any]], catalog: Catalog) -> list[dict[str, Any]]:
    """Holodeck's relation vocabulary: big furniture at the edge, companions near and facing their
    anchor, items on/in their holder, wall objects wall-mounted."""
    out: list[dict[str, Any]] = []
    for o in objects:
        cat = catalog.get(o["category"])
        p = o["placement"]
        if p.startswith(("on:", "inside:")):
            out.append({"type": p.split(":")[0], "args": [o["id"], p.split(":", 1)[1]]})
        elif p == "wall":
            out.append({"type": "wall_mounted", "args": [o["id"]]})
        elif cat is not None and not cat.pickable and max(cat.size_min[0], cat.size_min[2]) >= 0.6:
            out.append({"type": "edge", "args": [o["id"]]})
        anchor = COMPANIONS.get(o["category"])
        partner = next((q for q in objects if q["category"] == anchor and q["room"] == o["room"]), None)
        if partner is not None and p == "floor":
            out.append({"type": "near", "args": [o["id"], partner["id"]]})
            out.append({"type": "face_to", "args": [o["id"], partner["id"]]})
    return out
