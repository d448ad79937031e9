"""Holodeck-like baseline: one scene from the description alone, placed by Holodeck's own solver.

Pipeline (Yang et al., 2024): floor plan → doors/windows → object selection → spatial relations
(one `holodeck_scene` request) → constraint solving with DFS grid placement (`holodeck_solver`).
No logical trajectory is asked for: the scene is the default room the description evokes, so
it covers few decision paths, but it is physically valid by construction.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from logicenveval.baselines.drafts import floor_plan
from logicenveval.baselines.geometry import RoomRect
from logicenveval.baselines.holodeck_solver import (
    DOOR_CLEARANCE,
    NEAR_GAP,
    Box,
    FloorItem,
    Pose,
    candidates,
    solve_floor,
    surface_spot,
    wall_spots,
)
from logicenveval.baselines.replies import HolodeckSceneReply, HolodeckSceneWire, dropped_relations
from logicenveval.domain.catalog import Catalog
from logicenveval.domain.shapes import load_shapes
from logicenveval.envfiles import env_from_dict
from logicenveval.errors import ConfigError, LogicEnvEvalError
from logicenveval.generators.base import (
    Attempt,
    GenerationContext,
    GenerationFailure,
    GenerationResult,
)
from logicenveval.generators.construction import placement_fields
from logicenveval.llm.ask import ask, protocol_of
from logicenveval.llm.replies import ObjectDraft, object_slots
from logicenveval.llm.scene_words import OTHER_ID, selection_words
from logicenveval.llm.vocab import Pattern, scene_vocabulary
from logicenveval.model.conditions import STATE_FLAGS
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import TaskBrief
from logicenveval.scene.guessed_layout import typical_size

WALL_OBJECT_Y = 1.6  # centre height of wall-mounted objects
WALL_HEIGHT = 2.7


class Holodeck:
    """Registered as `holodeck`; options tune the solver grid and search budget."""

    def __init__(self, *, name: str = "holodeck", grid: float = 0.25, max_nodes: int = 4000) -> None:
        if grid <= 0 or max_nodes < 1:
            raise ConfigError(f"grid must be > 0 and max_nodes >= 1, got {grid} and {max_nodes}",
                              field="holodeck.grid/max_nodes", hint="the defaults are grid=0.25, max_nodes=4000")
        self.name = name
        self.grid = grid
        self.max_nodes = max_nodes

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        """One attempt: the scene. It fails when the scene request or its layout fails, or when
        the solver left out an object the scene gave a task role: a scene without a task object
        it had to place is not the environment it set out to build (it stays in plan.json)."""
        payload = {"task": brief.model_dump(mode="json"), "categories": ctx.catalog.generator_categories()}
        env_id = f"{self.name}-00"
        ctx.plan_attempts(1)
        try:
            role_names = sorted(brief.roles)
            vocabulary = scene_vocabulary(brief.rooms, role_names, [
                *payload["categories"], *(r.category for r in brief.roles.values())], required_roles=role_names)
            if protocol_of(ctx.model) >= 3:  # the scene's objects keyed by role, as LogicEnvGen's
                vocabulary.update(selection_words(brief, role_names, ctx.catalog))
                # its relations name role objects as well as the others
                vocabulary["object_ids"] = Pattern(f"^({'|'.join([*map(re.escape, role_names), OTHER_ID])})$")
                # one relation per object it may list: its roles and at most MAX_OTHER_OBJECTS others
                vocabulary["relation_slots"] = object_slots(role_names)
                if protocol_of(ctx.model) >= 5:  # states keyed by the flags only (`SOME_KEYS`)
                    vocabulary["state_flags"] = list(STATE_FLAGS)
                wire = ask(ctx.model, "holodeck_scene", payload, HolodeckSceneWire, seed=ctx.seed,
                           vocabulary=vocabulary, quote=False)
                dropped = dropped_relations([(env_id, wire)])
                scene = wire.draft()
            else:
                dropped = {}
                scene = ask(ctx.model, "holodeck_scene", payload, HolodeckSceneReply, seed=ctx.seed,
                            vocabulary=vocabulary)
            env, log = build_scene(brief, scene, ctx.catalog, ctx.rng, env_id=env_id, generator=self.name,
                                   grid=self.grid, max_nodes=self.max_nodes)
        except LogicEnvEvalError as exc:
            return GenerationResult(
                failures=[GenerationFailure(stage="holodeck", message=str(exc), env_id=env_id)],
                attempts=[Attempt(id=env_id, stage="holodeck", reason=str(exc))])
        artifacts = {"scene": scene.model_dump(mode="json"), "layout": log, **dropped}
        roles = {o.id: o.role for o in scene.objects if o.role}
        failures = [GenerationFailure(stage="layout", env_id=env_id,
                                      message=f"role object {oid!r} could not be placed and was left out")
                    for oid in log["dropped"] if oid in roles]
        if failures:
            left_out = sorted({roles[oid] for oid in log["dropped"] if oid in roles})
            reason = f"the layout left out the object(s) of role(s) {left_out}"
            return GenerationResult(artifacts=artifacts, failures=failures,
                                    attempts=[Attempt(id=env_id, stage="layout", reason=reason)])
        return GenerationResult(envs=[env], artifacts=artifacts,
                                attempts=[Attempt(id=env_id, env_id=env_id)])


def _door_obstacles(rect: RoomRect, doors: list[dict[str, Any]]) -> list[Box]:
    """Clearance boxes in front of (and behind) each door on this room's walls, room coordinates."""
    out = []
    for d in doors:
        (ax, az), (bx, bz) = d["segment"]
        ax, bx = ax - rect.x0, bx - rect.x0
        if abs(ax - bx) < 1e-9 and (abs(ax) < 1e-6 or abs(ax - rect.width) < 1e-6):
            out.append(Box(ax, (az + bz) / 2, 2 * DOOR_CLEARANCE, abs(bz - az)))
        elif abs(az - bz) < 1e-9 and (abs(az) < 1e-6 or abs(az - rect.depth) < 1e-6) and -1e-6 <= ax <= rect.width:
            out.append(Box((ax + bx) / 2, az, abs(bx - ax), 2 * DOOR_CLEARANCE))
    return out


def _wall_blocked(rect: RoomRect, openings: list[tuple[float, float, float, float]], floor: dict[str, Pose],
                  heights: dict[str, float], y_low: float) -> dict[str, list[tuple[float, float]]]:
    """Intervals along each wall taken by doors/windows or by floor objects tall enough to hit a
    wall object hanging from `y_low` up."""
    blocked: dict[str, list[tuple[float, float]]] = {"n": [], "s": [], "w": [], "e": []}
    for ax, az, bx, bz in openings:
        ax, bx = ax - rect.x0, bx - rect.x0
        if abs(az - bz) < 1e-9:
            wall = "s" if abs(az) < 1e-6 else "n" if abs(az - rect.depth) < 1e-6 else ""
            span = (min(ax, bx), max(ax, bx))
        else:
            wall = "w" if abs(ax) < 1e-6 else "e" if abs(ax - rect.width) < 1e-6 else ""
            span = (min(az, bz), max(az, bz))
        if wall:
            blocked[wall].append(span)
    for oid, pose in floor.items():
        if heights[oid] < y_low:
            continue
        b = pose.box
        near = {"s": b.z - b.fz / 2 < 0.5, "n": b.z + b.fz / 2 > rect.depth - 0.5,
                "w": b.x - b.fx / 2 < 0.5, "e": b.x + b.fx / 2 > rect.width - 0.5}
        for wall, hit in near.items():
            if hit:
                blocked[wall].append((b.x - b.fx / 2, b.x + b.fx / 2) if wall in "ns" else (b.z - b.fz / 2, b.z + b.fz / 2))
    return blocked


def build_scene(brief: TaskBrief, scene: HolodeckSceneReply, catalog: Catalog, rng: np.random.Generator, *,
                env_id: str, generator: str, grid: float = 0.25, max_nodes: int = 4000) -> tuple[EnvSpec, dict[str, Any]]:
    """Solve the layout of a scene reply and return the EnvSpec plus a log (dropped, relaxed)."""
    rects, doors, windows = floor_plan(list(scene.rooms))
    by_room = {r.id: r for r in rects}
    drafts = {o.id: o for o in scene.objects}
    room_of = {o.id: (o.room if o.room in by_room else rects[0].id) for o in scene.objects}
    sizes = {o.id: typical_size(o.category, catalog) for o in scene.objects}
    rel: dict[str, dict[str, list[str]]] = {o.id: {"edge": [], "near": [], "face_to": []} for o in scene.objects}
    for r in scene.relations:
        if r.args[0] in rel and r.type in ("edge", "near", "face_to"):
            rel[r.args[0]][r.type].append(r.args[-1])
    log: dict[str, Any] = {"dropped": [], "relaxed": []}
    placed: dict[str, dict[str, Any]] = {}
    floor_poses: dict[str, Pose] = {}
    for rect in rects:
        ids = [i for i, o in drafts.items() if room_of[i] == rect.id and placement_fields(o.placement)[0] == "floor"]
        items = [FloorItem(i, sizes[i], edge=bool(rel[i]["edge"]),
                           near=[n for n in rel[i]["near"] if room_of.get(n) == rect.id],
                           face_to=[n for n in rel[i]["face_to"] if room_of.get(n) == rect.id]) for i in ids]
        room_doors = [d for d in doors if rect.id in d["rooms"]]
        layout = solve_floor(items, rect.width, rect.depth, _door_obstacles(rect, room_doors), rng,
                             grid=grid, max_nodes=max_nodes)
        log["dropped"] += layout.dropped
        log["relaxed"] += layout.relaxed
        for oid, pose in layout.poses.items():
            floor_poses[oid] = pose
            placed[oid] = _record(drafts[oid], rect, pose.box, sizes[oid][1] / 2, sizes[oid], pose.yaw, "floor", None)
        _wall_objects(rect, drafts, room_of, sizes, room_doors, windows, layout.poses, placed, log)
    obstacles = {r.id: _door_obstacles(r, [d for d in doors if r.id in d["rooms"]]) for r in rects}
    _held_objects(drafts, by_room, sizes, placed, log, catalog, obstacles)
    env = env_from_dict({
        "task_id": brief.id, "generator": generator, "env_id": env_id, "claimed_trajectory": None,
        "wall_height": WALL_HEIGHT,
        "rooms": [{"id": r.id, "type": d.type, "polygon": r.polygon} for r, d in zip(rects, scene.rooms, strict=True)],
        "doors": doors, "windows": windows, "objects": [placed[i] for i in drafts if i in placed],
        "relations": _holding_relations(scene, placed, floor_poses),
        # only roles with a placed object: the others are bound by the judge (`domain.roles`)
        "roles": {o.role: o.id for o in reversed(scene.objects) if o.role in brief.roles and o.id in placed},
        "agent": {"room": brief.rooms[0] if brief.rooms[0] in by_room else rects[0].id},
    }, source=env_id)
    return env, log


def _record(o: ObjectDraft, rect: RoomRect, box: Box, y: float, size: tuple[float, float, float], yaw: float,
            support: str | None, container: str | None, *, absolute: bool = False) -> dict[str, Any]:
    x = box.x if absolute else box.x + rect.x0
    return {"id": o.id, "category": o.category, "room": rect.id, "position": [round(x, 4), round(y, 6), round(box.z, 4)],
            "size": list(size), "yaw": yaw, "support": support, "container": container,
            "attributes": dict(o.attributes), "states": dict(o.states)}


def _wall_objects(rect: RoomRect, drafts: dict[str, ObjectDraft], room_of: dict[str, str],
                  sizes: dict[str, tuple[float, float, float]], doors: list[dict[str, Any]],
                  windows: list[dict[str, Any]], floor: dict[str, Pose], placed: dict[str, dict[str, Any]],
                  log: dict[str, Any]) -> None:
    openings = [(*d["segment"][0], *d["segment"][1]) for d in doors]
    openings += [(*w["segment"][0], *w["segment"][1]) for w in windows if w["room"] == rect.id]
    heights = {i: sizes[i][1] for i in floor}
    hung: dict[str, list[tuple[float, float]]] = {"n": [], "s": [], "w": [], "e": []}
    for oid, o in drafts.items():
        where = placement_fields(o.placement)[0]
        if room_of[oid] != rect.id or where not in ("wall", "ceiling"):
            continue
        w, h, d = sizes[oid]
        if where == "ceiling":  # as Holodeck's ceiling objects (lights): at the room's centre, touching it
            box = Box(rect.width / 2, rect.depth / 2, w, d)
            placed[oid] = _record(o, rect, box, WALL_HEIGHT - h / 2, sizes[oid], 0.0, "ceiling", None)
            continue
        y = min(WALL_OBJECT_Y, WALL_HEIGHT - h / 2 - 0.1)
        blocked = _wall_blocked(rect, openings, floor, heights, y - h / 2)
        for wall_id, spans in hung.items():
            blocked[wall_id] += spans
        spots = wall_spots(rect.width, rect.depth, blocked, w)
        if not spots:
            log["dropped"].append(oid)
            continue
        wall, c = spots[0]
        yaw = {"s": 0.0, "n": 180.0, "w": 90.0, "e": 270.0}[wall]
        if wall in "ns":
            box = Box(c, d / 2 + 0.005 if wall == "s" else rect.depth - d / 2 - 0.005, w, d)
        else:
            box = Box(d / 2 + 0.005 if wall == "w" else rect.width - d / 2 - 0.005, c, d, w)
        placed[oid] = _record(o, rect, box, y, sizes[oid], yaw, "wall", None)
        hung[wall].append((c - w / 2 - 0.05, c + w / 2 + 0.05))


def _held_objects(drafts: dict[str, ObjectDraft], by_room: dict[str, RoomRect],
                  sizes: dict[str, tuple[float, float, float]], placed: dict[str, dict[str, Any]],
                  log: dict[str, Any], catalog: Catalog, obstacles: dict[str, list[Box]]) -> None:
    """Small objects on a free spot of their support's top, or inside their container (the
    catalog's smallest size when the typical one does not fit; an item too big for its support
    goes on the room's largest other surface, else on the floor); holders first."""
    pending = [i for i, o in drafts.items() if i not in placed and i not in log["dropped"]]
    taken: dict[tuple[str, int], tuple[float, list[Box], float]] = {}
    for _ in range(len(pending) + 1):
        progress = False
        for oid in list(pending):
            support, container = placement_fields(drafts[oid].placement)
            holder = container or support
            if holder not in placed:
                if holder not in drafts or holder in log["dropped"]:
                    pending.remove(oid)
                    log["dropped"].append(oid)
                continue
            h = placed[holder]
            hx, hy, hz = h["position"]
            hfx, hfz = (h["size"][2], h["size"][0]) if h["yaw"] in (90.0, 270.0) else (h["size"][0], h["size"][2])
            cat = catalog.get(drafts[oid].category)
            variants = [sizes[oid]] + ([cat.size_min] if cat is not None and cat.size_min != sizes[oid] else [])
            if container:
                top = Box(hx, hz, hfx - 0.04, hfz - 0.04)
                base = hy - h["size"][1] / 2 + 0.02
            else:
                top, base = _surface(h)
            # a holder's inside and its top are two spaces (a towel on the vanity leaves its shelf free)
            box, size, base = _free_spot(f"{holder}/inside" if container else holder, top, variants, base,
                                         hy + h["size"][1] / 2 if container else None, taken)
            if box is None and not container:  # too big for its support: the largest other free surface
                for alt in _surfaces(placed, h["room"], holder, catalog):
                    a = placed[alt]
                    atop, abase = _surface(a)
                    box, size, base = _free_spot(alt, atop, variants, abase, None, taken)
                    if box is not None:
                        log["relaxed"].append(f"on:{oid}:{holder}->{alt}")
                        holder, h = alt, a
                        break
            pending.remove(oid)
            progress = True
            if box is None:  # fits on no surface: it lies on the floor of the room instead
                rect = by_room[h["room"]]
                floor_box = _floor_spot(rect, variants[0], placed, obstacles[rect.id])
                if floor_box is None:
                    log["dropped"].append(oid)
                else:
                    log["relaxed"].append(f"{drafts[oid].placement}:{oid}->floor")
                    placed[oid] = _record(drafts[oid], rect, floor_box, variants[0][1] / 2, variants[0], 0.0,
                                          "floor", None)
                continue
            rect = by_room[h["room"]]
            placed[oid] = {**_record(drafts[oid], rect, box, base + size[1] / 2, size, 0.0,
                                     None if container else holder, container, absolute=True),
                           "room": h["room"]}
        if not progress:
            break
    log["dropped"] += [i for i in pending if i not in log["dropped"]]


def _floor_spot(rect: RoomRect, size: tuple[float, float, float], placed: dict[str, dict[str, Any]],
                obstacles: list[Box]) -> Box | None:
    """A free floor footprint (room coordinates) clear of floor objects and door swing areas."""
    taken = []
    for rec in placed.values():
        if rec["room"] == rect.id and rec["support"] == "floor":
            fx, fz = (rec["size"][2], rec["size"][0]) if rec["yaw"] in (90.0, 270.0) else (rec["size"][0], rec["size"][2])
            taken.append(Box(rec["position"][0] - rect.x0, rec["position"][2], fx, fz))
    for pose in candidates(FloorItem("item", size), rect.width, rect.depth, 0.1):
        if not any(pose.box.overlaps(t) for t in taken) and not any(pose.box.overlaps(o, 0.0) for o in obstacles):
            return pose.box
    return None


def _surfaces(placed: dict[str, dict[str, Any]], room: str, exclude: str, catalog: Catalog) -> list[str]:
    """Floor-standing surfaces of a room, largest top first."""
    out = []
    for oid, rec in placed.items():
        cat = catalog.get(rec["category"])
        if oid != exclude and rec["room"] == room and rec["support"] == "floor" and cat is not None and cat.surface:
            out.append((-rec["size"][0] * rec["size"][2], oid))
    return [oid for _, oid in sorted(out)]


def _surface(h: dict[str, Any]) -> tuple[Box, float]:
    """The area and height where things are put on a placed holder: its top, or for a seat (a
    sofa, an armchair, a bed) its seat in front of the back strip (domain.shapes: AI2-THOR's
    placement puts small objects on receptacle surfaces, as Holodeck does through it)."""
    (hx, hy, hz), (sx, sy, sz), yaw = h["position"], h["size"], h["yaw"]
    shape = load_shapes().of(h["category"])
    level, back = shape.surface() if shape is not None else (1.0, 0.0)
    shift = back * sz / 2
    fx, fz, dx, dz = {0.0: (sx, sz * (1 - back), 0.0, shift), 180.0: (sx, sz * (1 - back), 0.0, -shift),
                      90.0: (sz * (1 - back), sx, shift, 0.0), 270.0: (sz * (1 - back), sx, -shift, 0.0)
                      }.get(float(yaw) % 360, (sx, sz, 0.0, 0.0))
    return Box(hx + dx, hz + dz, fx, fz), hy - sy / 2 + level * sy


def _free_spot(holder: str, top: Box, variants: list[tuple[float, float, float]], base: float,
               ceiling: float | None, taken: dict[tuple[str, int], tuple[float, list[Box], float]]
               ) -> tuple[Box | None, tuple[float, float, float], float]:
    """A free footprint on the holder for the typical size, else the catalog's smallest variant
    (as Holodeck retrieves another asset); inside a container (`ceiling` = its rim) items may
    also lie in layers on the ones below, as clothes in a hamper do.
    Returns (box or None, size used, bottom height)."""
    for layer in range(3 if ceiling is not None else 1):
        if layer and (holder, layer - 1) not in taken:
            break
        below = taken.get((holder, layer - 1))
        layer_base, boxes, tallest = taken.get((holder, layer), (below[0] + below[2] if below else base, [], 0.0))
        for size in variants:
            if ceiling is not None and layer_base + size[1] > ceiling:
                continue
            box = surface_spot(top, size, boxes)
            if box is not None:
                taken[(holder, layer)] = (layer_base, [*boxes, box], max(tallest, size[1]))
                return box, size, layer_base
    return None, variants[0], base


def _holding_relations(scene: HolodeckSceneReply, placed: dict[str, dict[str, Any]],
                       floor: dict[str, Pose]) -> list[dict[str, Any]]:
    """The scene's relations that the solved layout satisfies (the rest were relaxed)."""
    out = []
    for r in scene.relations:
        if any(a not in placed for a in r.args):
            continue
        a = placed[r.args[0]]
        ok = False
        if r.type in ("on", "inside"):
            ok = a["support" if r.type == "on" else "container"] == r.args[1]
        elif r.type == "wall_mounted":
            ok = a["support"] == "wall"
        elif r.type == "edge":
            ok = r.args[0] in floor
        elif r.type == "near" and r.args[0] in floor and r.args[1] in floor and a["room"] == placed[r.args[1]]["room"]:
            ok = floor[r.args[0]].box.gap(floor[r.args[1]].box) <= NEAR_GAP - 0.05
        if ok:
            out.append({"type": r.type, "args": list(r.args)})
    return out
