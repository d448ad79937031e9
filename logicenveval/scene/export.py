"""Exporters: EnvSpec → ProcTHOR house JSON (loadable by AI2-THOR) and → GLB (any 3D viewer).

House JSON follows ProcTHOR's schema 1.0.0 layout (its generation code: house.py, doors.py,
wall_objects.py) and the fields AI2-THOR reads (`ProceduralData.cs`: `HouseObject`,
`HouseMetadata.agentPoses`, `Door`, `Window`, `PolygonWall`, `RoomHierarchy`): `rooms` with `floorPolygon` and one of ProcTHOR's four `roomType`s, one
`walls` entry per room side and per stretch (a room edge is split wherever another room's edge
starts or ends, so a shared stretch is one wall on each side), `doors`/`windows` with
`room0/room1`, `wall0/wall1`, a real wall-hole `assetId` and its `holePolygon`/`assetPosition`
placed as ProcTHOR places them, and `objects` with a real `assetId`/`objectType` (our recorded
choice per category, `scene/procthor.py`), `position`, `rotation`, `room`, `openness`, `isOn`,
`isDirty`; an object on or inside another is listed among that object's `children`. What
AI2-THOR has no field for stays in `logicenveval*` side fields (original room type and
category, other state flags, size and hole-size differences to the chosen assets).
"""

from __future__ import annotations

import hashlib
import math
from typing import Any

from logicenveval.domain.catalog import Catalog
from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import EnvObject, EnvSpec
from logicenveval.scene.procthor import (
    AI2THOR_ROOM_TYPES,
    ROOM_TYPE_MAP,
    load_mapping,
    opening_asset,
)

Seg = tuple[tuple[float, float], tuple[float, float]]


def _p(x: float, y: float, z: float) -> dict[str, float]:
    return {"x": round(x, 4), "y": round(y, 4), "z": round(z, 4)}


def _poly(env: EnvSpec, rid: str) -> list[tuple[float, float]]:
    room = next(r for r in env.rooms if r.id == rid)
    if room.polygon is None:
        raise EnvSpecError(f"room {rid} has no polygon", field=f"rooms.{rid}.polygon",
                           hint="export only constructed environments (with geometry)")
    return [(float(x), float(z)) for x, z in room.polygon]


def _edges(poly: list[tuple[float, float]]) -> list[Seg]:
    return [(poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly))]


def _collinear_cuts(seg: Seg, others: list[Seg]) -> list[float]:
    (ax, az), (bx, bz) = seg
    length = math.dist(seg[0], seg[1])
    ux, uz = (bx - ax) / length, (bz - az) / length
    cuts = {0.0, length}
    for o in others:
        for px, pz in o:
            cross = (px - ax) * uz - (pz - az) * ux
            t = (px - ax) * ux + (pz - az) * uz
            if abs(cross) < 1e-6 and 1e-6 < t < length - 1e-6:
                cuts.add(round(t, 6))
    return sorted(cuts)


def _wall_id(rid: str, a: tuple[float, float], b: tuple[float, float]) -> str:
    return f"wall|{rid}|{a[0]:.2f}|{a[1]:.2f}|{b[0]:.2f}|{b[1]:.2f}"


def _walls(env: EnvSpec, material: str = "Drywall") -> list[dict[str, Any]]:
    all_edges = {r.id: _edges(_poly(env, r.id)) for r in env.rooms}
    out: list[dict[str, Any]] = []
    pieces: set[tuple[tuple[float, float], tuple[float, float]]] = set()
    for rid, segs in all_edges.items():
        others = [s for oid, ss in all_edges.items() if oid != rid for s in ss]
        for seg in segs:
            (ax, az), (bx, bz) = seg
            length = math.dist(seg[0], seg[1])
            cuts = _collinear_cuts(seg, others)
            for t0, t1 in zip(cuts, cuts[1:], strict=False):
                p0 = (round(ax + (bx - ax) * t0 / length, 4), round(az + (bz - az) * t0 / length, 4))
                p1 = (round(ax + (bx - ax) * t1 / length, 4), round(az + (bz - az) * t1 / length, 4))
                out.append({"id": _wall_id(rid, p0, p1), "roomId": rid, "material": {"name": material},
                            "polygon": [_p(p0[0], 0, p0[1]), _p(p1[0], 0, p1[1]),
                                        _p(p1[0], env.wall_height, p1[1]), _p(p0[0], env.wall_height, p0[1])]})
                pieces.add((p0, p1))
    for w in list(out):  # exterior side of every stretch no other room shares
        a = (w["polygon"][0]["x"], w["polygon"][0]["z"])
        b = (w["polygon"][1]["x"], w["polygon"][1]["z"])
        if (b, a) not in pieces:
            out.append({**w, "id": _wall_id("exterior", b, a), "roomId": "exterior",
                        "polygon": [_p(b[0], 0, b[1]), _p(a[0], 0, a[1]), _p(a[0], env.wall_height, a[1]),
                                    _p(b[0], env.wall_height, b[1])]})
    return out


def _host(walls: list[dict[str, Any]], rid: str, seg: Seg) -> tuple[dict[str, Any], float, float]:
    """The wall of room `rid` holding `seg`, and the opening's offsets along it."""
    for w in walls:
        if w["roomId"] != rid:
            continue
        a = (w["polygon"][0]["x"], w["polygon"][0]["z"])
        b = (w["polygon"][1]["x"], w["polygon"][1]["z"])
        length = math.dist(a, b)
        ux, uz = (b[0] - a[0]) / length, (b[1] - a[1]) / length
        ts = []
        for px, pz in seg:
            if abs((px - a[0]) * uz - (pz - a[1]) * ux) > 1e-4:
                break
            ts.append((px - a[0]) * ux + (pz - a[1]) * uz)
        if len(ts) == 2 and min(ts) >= -1e-4 and max(ts) <= length + 1e-4:
            return w, min(ts), max(ts)
    raise EnvSpecError(f"opening {seg} lies on no wall of room {rid}", field="doors/windows",
                       hint="check the environment with `check-env` first")


#: our state flags that AI2-THOR house JSON names (ProcTHOR's object_states.py / objects.py);
#: `open` becomes `openness`, the others stay in `logicenvevalStates`
_AI2THOR_STATES = {"toggled_on": "isOn", "dirty": "isDirty"}


def _opening(walls: list[dict[str, Any]], rid: str, seg: Seg, mapping: dict[str, Any], kind: str,
             y0: float, height: float) -> tuple[dict[str, Any], dict[str, Any]]:
    """ProcTHOR's hole and asset placement (doors.py / wall_objects.py) of the mapping's asset
    closest in size, centred on our opening: (fields of the door/window, its host wall)."""
    wall, t0, t1 = _host(walls, rid, seg)
    asset_id, hole = opening_asset(mapping, kind, t1 - t0, height)
    asset_w, asset_h = mapping["openings"][kind][asset_id]["assetSize"]
    a = wall["polygon"][0]
    b = wall["polygon"][1]
    length = math.dist((a["x"], a["z"]), (b["x"], b["z"]))
    w, h = hole.size
    start = min(max((t0 + t1) / 2 - w / 2, 0.0), max(length - w, 0.0))
    ox, oy = hole.offset
    lo = _p(start - ox, y0, 0)
    hi = _p(start + w - ox, y0 + h - oy, 0)
    fields = {"assetId": asset_id, "holePolygon": [lo, hi],
              "assetPosition": _p(lo["x"] + ox + asset_w / 2, y0 + oy + asset_h / 2, 0),
              "logicenvevalOpening": {"width": round(t1 - t0, 4), "height": round(height, 4),
                                      "holeSizeDifference": [round(w - (t1 - t0), 4), round(h - height, 4)]}}
    return fields, wall


def _agent_xz(env: EnvSpec) -> tuple[float, float]:
    """The agent's floor position, else the centre of its room's polygon (AI2-THOR needs one)."""
    if env.agent.position is not None:
        return env.agent.position[0], env.agent.position[1]
    rid = next((r.id for r in env.rooms if r.id == env.agent.room), env.rooms[0].id)
    poly = _poly(env, rid)
    return sum(x for x, _ in poly) / len(poly), sum(z for _, z in poly) / len(poly)


def to_procthor(env: EnvSpec, catalog: Catalog, mapping: dict[str, Any] | None = None) -> dict[str, Any]:
    """A ProcTHOR house dict for `env` that AI2-THOR can load: real asset ids, wall holes and
    materials from `mapping` (default: benchmark_data/procthor_assets.json)."""
    m = mapping or load_mapping()
    mats = m["materials"]
    walls = _walls(env, mats["wall"])
    rooms = []
    for r in env.rooms:
        room = {"id": r.id, "roomType": r.type if r.type in AI2THOR_ROOM_TYPES else
                ROOM_TYPE_MAP.get(r.type, "LivingRoom"),
                "floorPolygon": [_p(x, 0, z) for x, z in _poly(env, r.id)],
                "floorMaterial": {"name": mats["floor"]}, "children": [], "ceilings": []}
        if room["roomType"] != r.type:
            room["logicenvevalRoomType"] = r.type
        rooms.append(room)
    doors = []
    for d in env.doors:
        if d.segment is None:
            continue
        r0, r1 = d.rooms
        if r0 == "exterior":
            r0, r1 = r1, r0
        kind = "doorway" if d.type == "doorway" else "door"
        fields, w0 = _opening(walls, r0, d.segment, m, kind, 0.0, d.height)
        w1, _, _ = _host(walls, r1, d.segment)
        doors.append({"id": d.id, **fields, "room0": r0, "room1": r1 if r1 != "exterior" else r0,
                      "wall0": w0["id"], "wall1": w1["id"],
                      "openable": d.type != "doorway" and r1 != "exterior",
                      "openness": 1 if d.state == "open" else 0})
    windows = []
    for w in env.windows:
        if w.segment is None:
            continue
        fields, w0 = _opening(walls, w.room, w.segment, m, "window", w.sill, w.height)
        w1, _, _ = _host(walls, "exterior", w.segment)
        windows.append({"id": w.id, **fields, "room0": w.room, "room1": w.room,
                        "wall0": w0["id"], "wall1": w1["id"], "openness": 1 if w.state == "open" else 0})
    by_parent: dict[str | None, list[EnvObject]] = {}
    for o in env.objects:
        parent = o.container or (o.support if o.support not in (None, "floor", "wall", "ceiling") else None)
        by_parent.setdefault(parent, []).append(o)

    def obj(o: EnvObject) -> dict[str, Any]:
        cat = catalog.get(o.category)
        chosen = m["categories"].get(o.category)
        if chosen is None:
            raise EnvSpecError(f"object {o.id}: category {o.category!r} has no ProcTHOR asset in "
                               "our mapping", field=f"objects.{o.id}.category",
                               hint="use a catalog category (benchmark_data/catalog.json)")
        pos = o.position or (0.0, 0.0, 0.0)
        out: dict[str, Any] = {
            "id": o.id, "assetId": chosen["assetId"], "objectType": chosen["objectType"],
            "position": _p(*pos), "rotation": _p(0, o.yaw % 360, 0),
            "kinematic": not (cat.pickable if cat else False), "room": o.room,
            "openness": 1 if o.states.get("open") else 0,
            **{key: bool(o.states.get(flag)) for flag, key in _AI2THOR_STATES.items()},
            "children": [obj(c) for c in by_parent.get(o.id, [])],
            "logicenvevalCategory": o.category,
            "logicenvevalStates": {k: v for k, v in sorted(o.states.items())
                                   if k not in _AI2THOR_STATES and k != "open"}}
        if o.size is not None:
            out["logicenvevalSizeDifference"] = [round(a - b, 4) for a, b in zip(chosen["size"], o.size, strict=True)]
        return out

    x, z = _agent_xz(env)
    agent: dict[str, Any] = {"horizon": 30, "standing": True, "rotation": _p(0, 0, 0),
                             "position": _p(x, 0.95, z)}
    return {"metadata": {"schema": "1.0.0", "agent": agent, "agentPoses": {"default": agent},
                         "source": f"logicenveval:{env.env_id}"},
            "proceduralParameters": {"floorColliderThickness": 1.0, "lights": [], "reflections": [],
                                     "ceilingMaterial": {"name": mats["ceiling"]}, "skyboxId": "SkyAlbany"},
            "rooms": rooms, "walls": walls, "doors": doors, "windows": windows,
            "objects": [obj(o) for o in by_parent.get(None, [])]}


def _colour(category: str) -> list[int]:
    h = hashlib.sha256(category.encode()).digest()
    return [60 + h[0] % 170, 60 + h[1] % 170, 60 + h[2] % 170, 255]


def _ear_clip(poly: list[tuple[float, float]]) -> list[tuple[int, int, int]]:
    """Triangles of a simple polygon (no triangulation engine needed)."""
    idx = list(range(len(poly)))
    area = sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
               for i in idx)
    if area < 0:
        idx.reverse()

    def cross(o: int, a: int, b: int) -> float:
        return ((poly[a][0] - poly[o][0]) * (poly[b][1] - poly[o][1])
                - (poly[a][1] - poly[o][1]) * (poly[b][0] - poly[o][0]))

    tris: list[tuple[int, int, int]] = []
    while len(idx) > 3:
        for k in range(len(idx)):
            a, b, c = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            if cross(a, b, c) <= 1e-12:
                continue
            if any(cross(a, b, p) >= 0 and cross(b, c, p) >= 0 and cross(c, a, p) >= 0
                   for p in idx if p not in (a, b, c)):
                continue
            tris.append((a, b, c))
            idx.pop(k)
            break
        else:  # degenerate (collinear) rest: stop
            break
    if len(idx) == 3:
        tris.append((idx[0], idx[1], idx[2]))
    return tris


WALL_THICKNESS = 0.05
_WALL_COLOUR = [235, 232, 225, 255]


def _wall_pieces(env: EnvSpec) -> list[tuple[Seg, float, float]]:
    """Solid parts of the walls as (segment on the floor, bottom, top): every room edge once
    (a shared stretch only from one side), cut around the doors and windows on it."""
    done: set[tuple[tuple[float, float], tuple[float, float]]] = set()
    openings = [(d.segment, 0.0, d.height) for d in env.doors if d.segment is not None]
    openings += [(w.segment, w.sill, w.sill + w.height) for w in env.windows if w.segment is not None]
    pieces: list[tuple[Seg, float, float]] = []
    for w in _walls(env):
        if w["roomId"] == "exterior":
            continue
        a = (w["polygon"][0]["x"], w["polygon"][0]["z"])
        b = (w["polygon"][1]["x"], w["polygon"][1]["z"])
        if (b, a) in done:
            continue
        done.add((a, b))
        length = math.dist(a, b)
        ux, uz = (b[0] - a[0]) / length, (b[1] - a[1]) / length
        holes = []
        for seg, lo, hi in openings:
            ts = [(px - a[0]) * ux + (pz - a[1]) * uz for px, pz in seg]
            if all(abs((px - a[0]) * uz - (pz - a[1]) * ux) < 1e-4 for px, pz in seg) \
                    and min(ts) > -1e-4 and max(ts) < length + 1e-4:
                holes.append((max(min(ts), 0.0), min(max(ts), length), lo, hi))
        cuts = sorted({0.0, length, *(t for h in holes for t in h[:2])})

        for t0, t1 in zip(cuts, cuts[1:], strict=False):
            if t1 - t0 < 1e-4:
                continue
            mid = (t0 + t1) / 2
            gap = next(((lo, hi) for h0, h1, lo, hi in holes if h0 <= mid <= h1), None)
            spans = [(0.0, env.wall_height)] if gap is None else [(0.0, gap[0]), (gap[1], env.wall_height)]
            seg = ((a[0] + ux * t0, a[1] + uz * t0), (a[0] + ux * t1, a[1] + uz * t1))
            pieces += [(seg, y0, y1) for y0, y1 in spans if y1 - y0 > 1e-4]
    return pieces


def to_glb(env: EnvSpec) -> bytes:
    """A GLB scene: floor slabs per room, walls with door/window openings, and one box per
    object coloured by category."""
    import trimesh as _trimesh

    trimesh: Any = _trimesh  # trimesh is only partly typed
    scene = trimesh.Scene()
    for r in env.rooms:
        poly = _poly(env, r.id)
        tris = _ear_clip(poly)
        verts = [(x, 0.0, z) for x, z in poly]
        slab = trimesh.Trimesh(vertices=verts, faces=[(a, c, b) for a, b, c in tris], process=False)
        slab.visual.face_colors = [200, 200, 190, 255]
        scene.add_geometry(slab, node_name=f"floor_{r.id}")
    for i, ((p0, p1), y0, y1) in enumerate(_wall_pieces(env)):
        length = math.dist(p0, p1)
        box = trimesh.creation.box(extents=(length, y1 - y0, WALL_THICKNESS))
        tf = trimesh.transformations.rotation_matrix(-math.atan2(p1[1] - p0[1], p1[0] - p0[0]), [0, 1, 0])
        tf[:3, 3] = ((p0[0] + p1[0]) / 2, (y0 + y1) / 2, (p0[1] + p1[1]) / 2)
        box.apply_transform(tf)
        box.visual.face_colors = _WALL_COLOUR
        scene.add_geometry(box, node_name=f"wall_{i}")
    for o in env.objects:
        if o.position is None or o.size is None:
            continue
        box = trimesh.creation.box(extents=o.size)
        yaw = math.radians(o.yaw)
        tf = trimesh.transformations.rotation_matrix(yaw, [0, 1, 0])
        tf[:3, 3] = o.position
        box.apply_transform(tf)
        box.visual.face_colors = _colour(o.category)
        scene.add_geometry(box, node_name=o.id)
    data = scene.export(file_type="glb")
    return bytes(data)
