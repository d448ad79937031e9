"""Exporters: EnvSpec → ProcTHOR-style house JSON (AI2-THOR tooling) and → GLB (any 3D viewer).

House JSON follows ProcTHOR's schema 1.0.0 layout: `rooms` with `floorPolygon`, one `walls`
entry per room side and per stretch (a room edge is split wherever another room's edge starts or
ends, so a shared stretch is one wall on each side), `doors`/`windows` with `room0/room1`,
`wall0/wall1` and a `holePolygon` in wall coordinates (x along the wall from its first point, y
up), and flat `objects` with `assetId`, `objectType` (catalog `ai2thor_type`), `position` and
`rotation`; an object on or inside another is listed among that object's `children`.
AI2-THOR has no asset ids of ours, so `assetId` names the type and category; tools that need
real assets map it.
"""

from __future__ import annotations

import hashlib
import math
from typing import Any

from logicenveval.domain.catalog import Catalog
from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import EnvObject, EnvSpec

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


def _walls(env: EnvSpec) -> list[dict[str, Any]]:
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
                out.append({"id": _wall_id(rid, p0, p1), "roomId": rid, "material": {"name": "PaintedWall"},
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


def to_procthor(env: EnvSpec, catalog: Catalog) -> dict[str, Any]:
    """A ProcTHOR-style house dict for `env` (rooms, walls, doors, windows, objects, agent)."""
    walls = _walls(env)
    rooms = [{"id": r.id, "roomType": r.type, "floorPolygon": [_p(x, 0, z) for x, z in _poly(env, r.id)],
              "floorMaterial": {"name": "WoodFloor"}, "children": [], "ceilings": []} for r in env.rooms]
    doors = []
    for d in env.doors:
        if d.segment is None:
            continue
        r0, r1 = d.rooms
        if r0 == "exterior":
            r0, r1 = r1, r0
        w0, t0, t1 = _host(walls, r0, d.segment)
        w1, _, _ = _host(walls, r1, d.segment)
        doors.append({"id": d.id, "assetId": "Doorway_1" if d.type == "doorway" else "Doorframe_1",
                      "room0": r0, "room1": r1 if r1 != "exterior" else r0, "wall0": w0["id"], "wall1": w1["id"],
                      "holePolygon": [_p(t0, 0, 0), _p(t1, d.height, 0)],
                      "assetPosition": _p((t0 + t1) / 2, d.height / 2, 0),
                      "openable": d.type != "doorway", "openness": 1 if d.state == "open" else 0})
    windows = []
    for w in env.windows:
        if w.segment is None:
            continue
        w0, t0, t1 = _host(walls, w.room, w.segment)
        w1, _, _ = _host(walls, "exterior", w.segment)
        windows.append({"id": w.id, "assetId": "Window_1", "room0": w.room, "room1": w.room,
                        "wall0": w0["id"], "wall1": w1["id"],
                        "holePolygon": [_p(t0, w.sill, 0), _p(t1, w.sill + w.height, 0)],
                        "assetPosition": _p((t0 + t1) / 2, w.sill + w.height / 2, 0),
                        "openness": 1 if w.state == "open" else 0})
    by_parent: dict[str | None, list[EnvObject]] = {}
    for o in env.objects:
        parent = o.container or (o.support if o.support not in (None, "floor", "wall", "ceiling") else None)
        by_parent.setdefault(parent, []).append(o)

    def obj(o: EnvObject) -> dict[str, Any]:
        cat = catalog.get(o.category)
        otype = (cat.ai2thor_type if cat and cat.ai2thor_type else
                 "".join(p.capitalize() for p in o.category.split("_")))
        pos = o.position or (0.0, 0.0, 0.0)
        return {"id": o.id, "assetId": f"{otype}|{o.category}", "objectType": otype,
                "position": _p(*pos), "rotation": _p(0, o.yaw % 360, 0),
                "kinematic": not (cat.pickable if cat else False), "roomId": o.room,
                "openness": 1 if o.states.get("open") else 0, "isDirty": bool(o.states.get("dirty")),
                "isToggled": bool(o.states.get("toggled_on")), "size": list(o.size) if o.size else None,
                "children": [obj(c) for c in by_parent.get(o.id, [])]}

    agent: dict[str, Any] = {"horizon": 30, "standing": True, "rotation": _p(0, 0, 0)}
    if env.agent.position is not None:
        agent["position"] = _p(env.agent.position[0], 0.95, env.agent.position[1])
    return {"metadata": {"schema": "1.0.0", "agent": agent, "source": f"logicenveval:{env.env_id}"},
            "proceduralParameters": {"floorColliderThickness": 1.0, "lights": [], "reflections": [],
                                     "ceilingMaterial": {"name": "PureWhite"}, "skyboxId": "SkyAlbany"},
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


def to_glb(env: EnvSpec) -> bytes:
    """A GLB scene: floor slabs per room and one box per object, coloured by category."""
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
