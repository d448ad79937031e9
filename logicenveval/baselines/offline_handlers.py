"""Offline answers to the baselines' request kinds, from the payload alone (never ground truth).

Each handler implements its baseline's *strategy* with the same analyser the LogicEnvGen
handlers use:
- `cot_environments`: a flat reading of the description — a baseline situation (every factor at
  its first value, the case the text describes first) plus, for each factor, each other value
  one at a time, with no decision-tree nesting; coordinates from `heuristics`.
- `ifg_intents`: k intents sampled with `default_rng(request.seed)`, each factor's value drawn
  from a softmax over a prior that prefers the first-described value, sharpened by 1/temperature.
- `ifg_environment`: one environment realising the intent, coordinates from `heuristics` with a
  temperature-scaled, seeded wall gap.
- `holodeck_scene`: the default room of the description — every role object in its typical
  place, plus furniture typical of each room type (catalog `rooms`), and spatial relations.
"""

from __future__ import annotations

import hashlib
from typing import Any

import numpy as np

from logicenveval.baselines.drafts import floor_plan
from logicenveval.baselines.geometry import room_dims
from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.generators.realise import task_objects
from logicenveval.llm.analysis import Factor, analyse
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.offline import handler
from logicenveval.llm.replies import RoomDraft
from logicenveval.model.rooms import room_type_of
from logicenveval.scene.guessed_layout import guess_coordinates

#: typical floor area (m²) per room type
AREA = {"LivingRoom": 22.0, "Kitchen": 13.0, "Bedroom": 15.0, "Bathroom": 7.0, "Study": 11.0,
        "Hallway": 9.0, "LaundryRoom": 8.0, "DiningRoom": 15.0, "KidsRoom": 13.0, "Garage": 20.0,
        "Balcony": 6.0, "Office": 12.0, "Pantry": 5.0, "Entryway": 7.0}
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


def door_stretches(rooms: list[dict[str, Any]]) -> dict[str, dict[str, list[tuple[float, float]]]]:
    """Room → wall → stretches along the wall in front of a door (door width plus its swing)."""
    rects, doors, _ = floor_plan([RoomDraft.model_validate(r) for r in rooms])
    out: dict[str, dict[str, list[tuple[float, float]]]] = {r.id: {} for r in rects}
    for rect in rects:
        for d in doors:
            (ax, az), (bx, bz) = d["segment"]
            ax, bx = ax - rect.x0, bx - rect.x0
            width = max(abs(bx - ax), abs(bz - az))
            if az == bz and az in (0.0, rect.depth) and 0 <= min(ax, bx) <= rect.width:
                wall, lo, hi = ("s" if az == 0.0 else "n"), min(ax, bx), max(ax, bx)
            elif ax == bx and (abs(ax) < 1e-6 or abs(ax - rect.width) < 1e-6):
                wall, lo, hi = ("w" if abs(ax) < 1e-6 else "e"), min(az, bz), max(az, bz)
            else:
                continue
            out[rect.id].setdefault(wall, []).append((lo - width, hi + width))
    return out


def _environment(task: dict[str, Any], situation: str, facts: list[str], catalog: Catalog,
                 rng: np.random.Generator | None, wall_gap: float) -> dict[str, Any]:
    rooms = default_rooms(task)
    dims = {r["id"]: room_dims(r["area_m2"]) for r in rooms}
    objects = guess_coordinates(task_objects(task, facts, catalog), dims, catalog, rng=rng, wall_gap=wall_gap,
                                doors=door_stretches(rooms))
    relations = [{"type": "on" if o["placement"].startswith("on:") else "inside",
                  "args": [o["id"], o["placement"].split(":", 1)[1]]}
                 for o in objects if o["placement"].startswith(("on:", "inside:"))]
    return {"situation": situation, "rooms": rooms,
            "objects": [dict(o) for o in objects], "relations": relations}


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
    return {"rooms": rooms, "objects": objects, "relations": _relations(objects, catalog)}


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
